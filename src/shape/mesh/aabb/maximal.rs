//! Maximal* balls (thesis 3.3.2.2): the largest ball `c + r·B` inside the
//! solid whose copy of a chosen ball vertex `ṽ` sits at a given point `p`
//! (a point of a contact class's contact plane, usually of the surface).
//! The balls `p + r·(B − ṽ)` grow about `p` and are nested, so there is a
//! largest radius before one pokes through the surface.
//!
//! The thesis's iterative shrinking, on the largest-ball query: start
//! with a ball too large for the solid; while the largest ball at its
//! centre is smaller than it (some triangle pokes into it), shrink about
//! `p` to the radius at which that triangle first enters; the radius
//! strictly decreases and each step ends at a triangle's entry, so a few
//! steps reach the ball no triangle enters, the maximal* ball. A
//! triangle's entry radius is where `g(s) = reach(T, p − s·ṽ) − s` turns
//! negative; `g` is continuous and piecewise linear and crosses once
//! (nested balls), so regula falsi lands on it in a few steps.
//!
//! Its contacts, all the triangles the final ball touches, come from
//! [`TriangleTree::ball_contacts`].

use super::{BallContact, TriangleTree};
use crate::kernel::Point3;
use crate::shape::ball::{Ball3, Reach, ReachHint, TriangleReach};

/// A maximal* ball: `centre + radius·B`, its vertex `ṽ` at the point asked.
#[derive(Debug, Clone, PartialEq)]
pub struct MaximalBall {
    /// Its radius (0: the ball vertex points out of the solid at `p`).
    pub radius: f64,
    /// Its centre `p − radius·ṽ`.
    pub centre: Point3,
    /// The contact that stopped its growth (the thesis's opposite
    /// contact): where the next larger ball would poke through. `None`
    /// when nothing does: outside the solid a ball may grow without bound
    /// (then `radius` is infinite and `centre` is the point asked).
    pub opposite: Option<BallContact>,
}

/// Relative gap within which a larger ball counts as touching, not
/// poking: the rounding of a gauge, with room.
const TOUCH: f64 = 1e-12;

/// How far a computed gauge from the centre `p − s·ṽ` may be off, beyond
/// the relative [`TOUCH`]: the centre and the corners carry rounding of
/// their own size (`ε·|coordinate|`), which a thin part far from the origin
/// makes large against `s`, and a gauge multiplies it by at most
/// 1 / inradius.
struct Slack {
    /// ε-scaled size of the coordinates in play, over the inradius.
    base: f64,
    /// The same for the part that grows with the radius.
    per_radius: f64,
}

impl Slack {
    fn new(p: Point3, b: &crate::kernel::BBox3, ball: &Ball3) -> Slack {
        let size = |q: Point3| q.x.abs().max(q.y.abs()).max(q.z.abs());
        let k = 64.0 * f64::EPSILON / ball.inradius();
        Slack { base: k * size(p).max(size(b.min)).max(size(b.max)), per_radius: k * ball.circumradius() }
    }

    /// Whether a least gauge `got` from the centre of the ball of radius
    /// `s` means a triangle enters that ball.
    fn pokes(&self, got: f64, s: f64) -> bool {
        got < s * (1.0 - TOUCH) - self.base - self.per_radius * s
    }
}

impl TriangleTree {
    /// The maximal* ball with ball vertex `vertex` at `p` (`None` for an
    /// empty tree, a vertex index out of range, or coordinates so large
    /// that the first ball's radius overflows). For `p` on the surface
    /// the ball lies on the side the vertex's cone points to: in the
    /// solid, in a cavity or outside (where it may be unbounded); a cone
    /// that straddles the surface gives radius 0.
    pub fn maximal_ball(&self, p: Point3, vertex: usize, ball: &Ball3) -> Option<MaximalBall> {
        self.maximal_ball_with(p, vertex, &ball.reach())
    }

    /// [`maximal_ball`](Self::maximal_ball) for many points, point `i` with
    /// ball vertex `asked[i].1`, in parallel (in Z-order of the points).
    pub fn maximal_balls(&self, asked: &[(Point3, usize)], ball: &Ball3) -> Vec<Option<MaximalBall>> {
        let reach = ball.reach();
        self.batch_by(asked, |a| a.0, |&(p, v)| self.maximal_ball_with(p, v, &reach))
    }

    /// [`maximal_ball`](Self::maximal_ball) with the ball prepared once.
    pub fn maximal_ball_with(&self, p: Point3, vertex: usize, reach: &Reach<'_>) -> Option<MaximalBall> {
        let ball = reach.ball();
        let v = *ball.vertices().get(vertex)?;
        let b = self.bbox();
        let slack = Slack::new(p, &b, ball);
        let mut r = self.unbounded_radius(p, v, ball)?;
        // The first ball: when the ray from p through the centres
        // (direction −ṽ) meets the surface at the centre of ball s₀, every
        // larger ball holds that point inside, so the answer is below s₀
        // and shrinking from there takes a few local steps; the ball the
        // size of the solid (huge for a round ball, whose margin is small)
        // costs a search over much of the surface. The ray starts a hair
        // off p, past p's own face.
        let lead = (1e-9 * size_of(p)).max(1e-300) / v.norm();
        let near = self.first_hit(p - v * lead, -v).and_then(|hit| {
            let s0 = (hit.t + lead) * (1.0 + 1e-9);
            let at = self.ball_radius_at(p - v * s0, reach)?;
            (s0 < r && slack.pokes(at.0.radius, s0)).then_some((s0, at))
        });
        let first = match near {
            Some((s0, at)) => {
                r = s0;
                at
            }
            None => {
                let at = self.ball_radius_at(p - v * r, reach)?;
                if !slack.pokes(at.0.radius, r) {
                    return Some(MaximalBall { radius: f64::INFINITY, centre: p, opposite: None });
                }
                at
            }
        };
        // Each step shrinks to the entry radius of a triangle that poked,
        // which pokes no more; balls are nested, so a triangle that stops
        // poking never pokes again, and the steps are at most the
        // triangles (the bound only guards against a bug).
        let (mut hit, mut k) = first;
        for _ in 0..=self.len() {
            let t = self.corners(k);
            r = entry_radius(reach, p, v, t, r);
            if r <= 4.0 * slack.base {
                // Within rounding of 0: the cone straddles the surface.
                r = 0.0;
            }
            let centre = p - v * r;
            let touch = reach.triangle(centre, t, &mut ReachHint::default());
            let opposite = BallContact { radius: r, triangle: hit.triangle, point: touch.point, kind: touch.kind };
            if r == 0.0 {
                return Some(MaximalBall { radius: 0.0, centre: p, opposite: Some(opposite) });
            }
            (hit, k) = self.ball_radius_at(centre, reach)?;
            if !slack.pokes(hit.radius, r) {
                return Some(MaximalBall { radius: r, centre, opposite: Some(opposite) });
            }
        }
        None
    }

    /// A radius beyond which the balls `p + s·(B − ṽ)` gain no point of
    /// the tree's box: the ball of that radius holds every point of the
    /// vertex's cone about `p` within `far` of `p` (it holds `q` when every
    /// facet not through `ṽ` has `row·(q − p) ≤ s·(1 − row·ṽ)`, and
    /// `row·(q − p) ≤ far / inradius`), with a factor 2 for rounding. So a
    /// ball that large that no triangle enters is never stopped: it grows
    /// without bound (outside the solid). `None` when it overflows.
    pub(super) fn unbounded_radius(&self, p: Point3, v: Point3, ball: &Ball3) -> Option<f64> {
        let b = self.bbox();
        let far = (b.max - b.min).norm().max((p - b.min).norm()).max((p - b.max).norm());
        let rows = ball.gauge_rows();
        let margin = rows.iter().map(|a| 1.0 - a.dot(v)).filter(|&m| m > 1e-9).fold(f64::INFINITY, f64::min);
        let r = 2.0 * far / (ball.inradius() * margin.min(1.0));
        r.is_finite().then_some(r)
    }

    /// Every triangle the ball `c + r·B` touches within a relative `tol`
    /// (its least gauge from `c` at most `r·(1 + tol)`), with where.
    pub fn ball_contacts(&self, c: Point3, r: f64, ball: &Ball3, tol: f64) -> Vec<BallContact> {
        let reach = ball.reach();
        let mut out: Vec<BallContact> = self
            .near_triangles(c, r * (1.0 + tol), &reach)
            .into_iter()
            .map(|(k, got)| BallContact { radius: got.radius, triangle: self.ids[k], point: got.point, kind: got.kind })
            .collect();
        out.sort_by_key(|c| c.triangle);
        out
    }

    /// The tree positions of the triangles whose least gauge from `c` is at
    /// most `limit`, with where they reach it.
    pub(super) fn near_triangles(&self, c: Point3, limit: f64, reach: &Reach<'_>) -> Vec<(usize, TriangleReach)> {
        let mut hint = ReachHint::default();
        let mut out = Vec::new();
        let _ = self.visit(
            |b| reach.over_box(b, c) <= limit,
            |k| {
                let t = self.corners(k);
                if reach.over_triangle(t, c, f64::INFINITY, &mut hint) <= limit {
                    let got = reach.triangle(c, t, &mut hint);
                    if got.radius <= limit {
                        out.push((k, got));
                    }
                }
                std::ops::ControlFlow::Continue(())
            },
        );
        out
    }
}

fn size_of(q: Point3) -> f64 {
    q.x.abs().max(q.y.abs()).max(q.z.abs())
}

/// The radius below `hi` at which triangle `t` first enters the ball
/// `p − s·v + s·B` as `s` grows: the last `s` with
/// `g(s) = reach(t, p − s·v) − s ≥ 0`, given that `t` pokes at `hi` by
/// more than the [`Slack`] (`g(0) ≥ 0`: a gauge). No slack in `g`, so the
/// answer is the crossing itself: a triangle through `p` that only touches
/// there (its `g` zero up to rounding at every radius) never gets here,
/// as the caller asks only about triangles that poke beyond rounding, and
/// one through `p` that pokes does so at every radius (near `p` the balls
/// are one cone), so its answer is 0. Regula falsi with the Illinois
/// halving keeps a bracket that shrinks on both sides; `g` is piecewise
/// linear, so a step on the final piece lands on the root.
fn entry_radius(reach: &Reach<'_>, p: Point3, v: Point3, t: [Point3; 3], hi: f64) -> f64 {
    let mut hint = ReachHint::default();
    let mut g = |s: f64| reach.triangle(p - v * s, t, &mut hint).radius - s;
    let (mut lo, mut hi) = (0.0f64, hi);
    let (mut g_lo, mut g_hi) = (g(lo), g(hi));
    if g_lo < 0.0 {
        return 0.0;
    }
    let mut side = 0;
    for _ in 0..200 {
        if hi - lo <= 4.0 * f64::EPSILON * hi {
            break;
        }
        let mut s = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
        if !(s > lo && s < hi) {
            s = 0.5 * (lo + hi);
        }
        let gs = g(s);
        if gs >= 0.0 {
            (lo, g_lo) = (s, gs);
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            (hi, g_hi) = (s, gs);
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
        if gs == 0.0 {
            break;
        }
    }
    lo
}
