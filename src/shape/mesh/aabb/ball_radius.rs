//! The largest ball `c + r·B` inside a solid at a given centre (thesis
//! 3.3.2.2: the polytope distance from `c` to the surface): the least
//! gauge `γ_B(q − c)` over the surface's points `q`, with the triangle and
//! point where the grown ball first touches.
//!
//! The search descends the tree nearest box first, "nearest" measured by a
//! lower bound of the gauge over the box ([`Reach`]: the ball's
//! circumsphere, its bounding box and, for balls of few facets, each
//! facet plane at the box corner it picks), and skips every box and
//! triangle whose bound cannot beat the best radius so far. Measuring the
//! boxes by the gauge itself rather than by Euclidean distance matters
//! for a pointed ball: a tetrahedron reaches three times farther toward
//! its vertices than toward its facets, and a Euclidean bound would open
//! every triangle within that larger sphere. Each triangle that survives
//! is measured by [`Reach::triangle`].

use super::TriangleTree;
use crate::kernel::Point3;
pub use crate::shape::ball::ContactKind3;
use crate::shape::ball::{Ball3, Reach, ReachHint};

/// The largest ball at a centre and where it touches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallContact {
    /// The radius: `c + radius·B` touches the surface and holds no point
    /// of it inside.
    pub radius: f64,
    /// The triangle touched (index in the tree's input).
    pub triangle: u32,
    /// The point of contact.
    pub point: Point3,
    /// The contact's kind.
    pub kind: ContactKind3,
}

impl TriangleTree {
    /// The largest ball `c + r·B` whose interior holds no point of the
    /// surface, and where it touches (`None` for an empty tree). For `c`
    /// inside a solid this is the largest ball inside it at `c`.
    pub fn ball_radius(&self, c: Point3, ball: &Ball3) -> Option<BallContact> {
        self.ball_radius_with(c, &ball.reach())
    }

    /// [`ball_radius`](Self::ball_radius) with the ball prepared once
    /// ([`Ball3::reach`]) for many questions.
    pub fn ball_radius_with(&self, c: Point3, reach: &Reach<'_>) -> Option<BallContact> {
        self.ball_radius_at(c, reach).map(|(contact, _)| contact)
    }

    /// [`ball_radius`](Self::ball_radius) with the tree position of the
    /// triangle touched.
    pub(super) fn ball_radius_at(&self, c: Point3, reach: &Reach<'_>) -> Option<(BallContact, usize)> {
        let root = self.nodes.first()?;
        let mut hint = ReachHint::default();
        let mut at_k = 0;
        let mut best: Option<BallContact> = None;
        let beats = |lb: f64, best: &Option<BallContact>| best.is_none_or(|b| lb < b.radius);
        let mut stack = [(0u32, 0.0f64); 64];
        stack[0] = (0, reach.over_box(&root.bbox, c));
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (at, lb) = stack[top];
            if !beats(lb, &best) {
                continue;
            }
            let node = &self.nodes[at as usize];
            if node.is_leaf() {
                for k in node.range() {
                    let corners = self.corners(k);
                    if !beats(
                        reach.over_triangle(corners, c, best.map_or(f64::INFINITY, |b| b.radius), &mut hint),
                        &best,
                    ) {
                        continue;
                    }
                    let r = reach.triangle(c, corners, &mut hint);
                    if beats(r.radius, &best) {
                        best =
                            Some(BallContact { radius: r.radius, triangle: self.ids[k], point: r.point, kind: r.kind });
                        at_k = k;
                    }
                }
                continue;
            }
            let (left, right) = (at + 1, node.index);
            let dl = reach.over_box(&self.nodes[left as usize].bbox, c);
            let dr = reach.over_box(&self.nodes[right as usize].bbox, c);
            // The nearer child goes on top, to be searched first.
            let (near, far) = if dl <= dr { ((left, dl), (right, dr)) } else { ((right, dr), (left, dl)) };
            stack[top] = far;
            stack[top + 1] = near;
            top += 2;
        }
        best.map(|b| (b, at_k))
    }

    /// [`TriangleTree::ball_radius`] for many centres, in parallel (in an
    /// order of the centres that keeps the tree in cache).
    pub fn ball_radii(&self, centres: &[Point3], ball: &Ball3) -> Vec<Option<BallContact>> {
        let reach = ball.reach();
        self.batch(centres, |c| self.ball_radius_with(c, &reach))
    }
}
