//! Following a ray of the axis to its next node.
//!
//! Along a ray the ball's centre moves on a line and its radius is affine,
//! so the ray ends at the first of two kinds of event: a class tied along
//! it stops being valid (its contact reaches the end of its feature: a
//! joint, a corner when the radius reaches 0), or the ball starts touching
//! an edge it did not touch (a branch point). Both are the meeting point
//! of the ray's line with another input-level line, so the next node is
//! exact and of bounded size however long the walk.
//!
//! The second kind is searched in `f64` first: a best-first walk of the
//! edge box tree for the earliest contact (a box is reached no earlier than
//! the Euclidean disk around the ball reaches it), then every class whose
//! `f64` contact comes within a margin (10^-7 of the shape's diagonal) of
//! the earliest is decided exactly; when the exact test rejects them all
//! (the margin admits classes whose contact lies just behind the start),
//! the search resumes without them. Edges the ball touches at the start
//! are left out: the ball meets a closed edge during one interval of the
//! walk (both are convex), so an edge it leaves never comes back, and one
//! it keeps touching changes class only through the first kind of event.

use super::classes::ApproxClass;
use super::error::BallAxisError;
use super::node::{radius_num, tie_line, valid_at, Node, Ray};
use super::problem::{ClassId, Problem};
use crate::kernel::exact_line::{HPoint, IVec};
use crate::kernel::{BBox, Point};
use std::cmp::Ordering;
use std::ops::ControlFlow;

/// The ray's start in `f64`: position, unit direction, radius and its slope.
struct Walk {
    at: Point,
    dir: Point,
    r: f64,
    slope: f64,
    eps: f64,
}

impl Walk {
    /// When the ball touches this class's contact, approximately (with the
    /// filter's margins on the generous side), or `None`.
    fn contact_time(&self, c: &ApproxClass) -> Option<f64> {
        let d0 = c.radius(self.at) - self.r;
        let rate = c.slope(self.dir) - self.slope;
        let scale = c.slope(self.dir).abs() + self.slope.abs() + 1e-300;
        let t = if rate.abs() <= 1e-12 * scale {
            // Equal slopes: touching from where the class becomes valid.
            if d0.abs() > self.eps {
                return None;
            }
            let mut t: f64 = 0.0;
            for (g, g0) in &c.valid[..c.n_valid] {
                let (v0, dv) = (g.dot(self.at) + g0, g.dot(self.dir));
                if v0 < -self.eps {
                    if dv <= 0.0 {
                        return None;
                    }
                    t = t.max(-v0 / dv);
                }
            }
            t
        } else {
            -d0 / rate
        };
        if t < -self.eps {
            return None;
        }
        let q = self.at + self.dir * t;
        (c.validity(q) >= -self.eps).then_some(t.max(0.0))
    }

    /// A lower bound on when the ball can reach the box (`None`: never):
    /// the later of the times the circumscribed disk and the ball's own
    /// box (`extent`, ball units) can reach it. The box bound is the
    /// tight one for balls that fill their box (the square exactly); each
    /// of its four separations is affine in the time, and all four must
    /// have closed for the boxes to meet.
    fn box_bound(&self, reach: f64, extent: &[f64; 4], b: &BBox) -> Option<f64> {
        let gap = b.distance_to(self.at) - self.r * reach * (1.0 + 1e-9) - self.eps;
        if gap <= 0.0 {
            return Some(0.0);
        }
        let speed = 1.0 + self.slope * reach * (1.0 + 1e-9);
        let mut t = if speed > 0.0 { gap / speed } else { return None };
        let grow = 1e-9 * self.r.abs() + self.eps;
        // (separation at t = 0, its rate): box beyond the ball's right,
        // left, top and bottom sides.
        let seps = [
            (b.min.x - self.at.x - self.r * extent[1], -self.dir.x - self.slope * extent[1]),
            (self.at.x + self.r * extent[0] - b.max.x, self.dir.x + self.slope * extent[0]),
            (b.min.y - self.at.y - self.r * extent[3], -self.dir.y - self.slope * extent[3]),
            (self.at.y + self.r * extent[2] - b.max.y, self.dir.y + self.slope * extent[2]),
        ];
        for (s0, s1) in seps {
            let s0 = s0 - grow;
            if s0 > 0.0 {
                if s1 >= 0.0 {
                    return None;
                }
                t = t.max(s0 / -s1 * (1.0 - 1e-12));
            }
        }
        Some(t)
    }

    /// The box around the ball at time `t`.
    fn ball_box(&self, reach: f64, t: f64) -> BBox {
        let c = self.at + self.dir * t;
        let rad = (self.r + self.slope * t).max(0.0) * reach * (1.0 + 1e-9) + self.eps;
        BBox::of_points(c, c).inflate(rad)
    }
}

impl Problem<'_> {
    /// Follows `ray` from `node` to the next node: its exact position and a
    /// class tied there (whose radius is the node's).
    pub(crate) fn trace(&self, node: &Node, ray: &Ray) -> Result<(HPoint, ClassId), BallAxisError> {
        let reference = ray.along[0];
        let re = self.exact(reference);
        let d = &ray.dir;
        let mut best: Option<HPoint> = None;
        let offer = |q: HPoint, best: &mut Option<HPoint>| {
            if node.p.along(&q, d) != Ordering::Greater {
                return;
            }
            if best.as_ref().is_none_or(|b| b.along(&q, d) == Ordering::Less) {
                *best = Some(q);
            }
        };
        // Validity ends of the classes along the ray.
        for &c in &ray.along {
            let ex = if c == reference { re.clone() } else { self.exact(c) };
            for g in &ex.valid {
                if g.n.dot(d).signum() == Ordering::Less {
                    if let Some(q) = ray.carrier.meet(g) {
                        offer(q, &mut best);
                    }
                }
            }
        }
        let unit = d.approx().unit();
        let ra = self.approx(reference);
        let walk =
            Walk { at: node.at, dir: unit, r: node.r, slope: ra.slope(unit), eps: 1e-7 * self.diag + 1e-9 * node.r };
        let t_first = best.as_ref().map_or(f64::INFINITY, |b| (b.approx(self.shape_units) - node.at).dot(unit));
        // New contacts: the earliest in f64, then all near it exactly. The
        // f64 times carry margins, so the earliest can be a false alarm
        // that the exact test rejects (typically a class tied within the
        // margin at the start, whose contact lies just behind it): such
        // classes are set aside and the search resumes, or a real contact
        // beyond the window would be missed and the ball would walk
        // through it.
        let excluded = |e: u32| node.touching.binary_search(&e).is_ok();
        let mut rejected: Vec<ClassId> = Vec::new();
        loop {
            let contact = |c: ClassId| -> Option<f64> {
                if rejected.contains(&c) {
                    return None;
                }
                walk.contact_time(&self.approx(c))
            };
            let key = |e: usize, _: &BBox| -> Option<(f64, ClassId)> {
                if excluded(e as u32) {
                    return None;
                }
                self.classes_of_edge(e as u32).filter_map(|c| contact(c).map(|t| (t, c))).reduce(|a, b| {
                    if b.0 < a.0 {
                        b
                    } else {
                        a
                    }
                })
            };
            let found = self.tree.min_by_bound(
                // A contact later than the validity end found exactly would
                // be dropped below: boxes beyond it are never opened (most
                // rays end at a joint, long before the next contact).
                |b| {
                    walk.box_bound(self.reach, &self.extent, b)
                        .filter(|&t| t <= t_first + 2.0 * walk.eps)
                        .map(|t| (t, 0))
                },
                key,
            );
            let Some((_, (t, first))) = found else { break };
            if t > t_first + 2.0 * walk.eps {
                break;
            }
            let limit = t + 2.0 * walk.eps;
            let window = walk.ball_box(self.reach, 0.0).union(&walk.ball_box(self.reach, limit));
            // The earliest's own class always, so that every round without
            // a contact sets at least one class aside and the loop ends.
            let mut near: Vec<ClassId> = vec![first];
            self.tree.visit_overlapping(&window, |e| {
                if !excluded(e as u32) {
                    near.extend(self.classes_of_edge(e as u32).filter(|&c| contact(c).is_some_and(|tc| tc <= limit)));
                }
                ControlFlow::<()>::Continue(())
            });
            near.sort_unstable();
            near.dedup();
            let mut hit = false;
            for c in near {
                match self.contact_on_ray(node, ray, &re, c) {
                    Some(q) => {
                        offer(q, &mut best);
                        hit = true;
                    }
                    None => rejected.push(c),
                }
            }
            if hit {
                break;
            }
        }
        match best {
            Some(q) => Ok((q, reference)),
            None => Err(BallAxisError::Inconsistent { at: node.at, what: "a ray of the axis leaves the shape" }),
        }
    }

    /// Where, exactly, the ball walking along `ray` first touches class
    /// `c`'s contact, if ahead.
    fn contact_on_ray(
        &self,
        node: &Node,
        ray: &Ray,
        re: &crate::polymetric::classes::ExactClass,
        c: ClassId,
    ) -> Option<HPoint> {
        let ex = self.exact(c);
        let d: &IVec = &ray.dir;
        let q = match tie_line(re, &ex).and_then(|t| ray.carrier.meet(&t)) {
            Some(q) => q,
            None => {
                // Parallel: equal along the whole line, or never.
                if &radius_num(&ex, &node.p) * &re.h != &radius_num(re, &node.p) * &ex.h {
                    return None;
                }
                let mut entry: Option<HPoint> = None;
                for g in &ex.valid {
                    if g.side(&node.p) == Ordering::Less {
                        if g.n.dot(d).signum() != Ordering::Greater {
                            return None;
                        }
                        let q = ray.carrier.meet(g)?;
                        if entry.as_ref().is_none_or(|e| e.along(&q, d) == Ordering::Greater) {
                            entry = Some(q);
                        }
                    }
                }
                entry?
            }
        };
        (node.p.along(&q, d) == Ordering::Greater && valid_at(&ex, &q)).then_some(q)
    }
}
