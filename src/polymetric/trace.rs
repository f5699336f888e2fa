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
//! chain tree for the earliest contact (a run of edges is reached no
//! earlier than the disk around the ball reaches its capsule, nor the
//! ball's box its box or oriented box), then every class whose
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
use crate::kernel::Point;
use crate::shape::index::chain_tree::RunBounds;
use crate::shape::model::error::ElementRef;
use std::cmp::Ordering;

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

    /// A lower bound on when the ball can reach a run of edges (`None`:
    /// never): the latest of the times the circumscribed disk can reach
    /// the run's capsule, the ball's own box (`extent`, ball units) its
    /// box, and the disk's box (in the run's frame) its oriented box. The
    /// box bound is the tight one for balls that fill their box (the
    /// square exactly), the other two among long thin spikes.
    fn run_bound(&self, reach: f64, extent: &[f64; 4], run: RunBounds) -> Option<f64> {
        let gap = run.distance_to(self.at) - self.r * reach * (1.0 + 1e-9) - self.eps;
        let speed = 1.0 + self.slope * reach * (1.0 + 1e-9);
        let mut t = match (gap <= 0.0, speed > 0.0) {
            (true, _) => 0.0,
            (false, true) => gap / speed,
            (false, false) => return None,
        };
        let bb = run.bbox();
        t = t.max(self.box_bound(self.at, self.dir, extent, bb.min, bb.max)?);
        let (u, lo, hi) = run.oriented();
        let frame = |p: Point| Point::new(u.dot(p), u.perp().dot(p));
        let disk = [-reach, reach, -reach, reach];
        Some(t.max(self.box_bound(frame(self.at), frame(self.dir), &disk, lo, hi)?))
    }

    /// When the ball's box (`extent` around the centre `at + dir·t`,
    /// scaled by the radius) can first meet the box [`lo`, `hi`], all in
    /// one frame (`None`: never). Each of the four separations is affine
    /// in the time, and all four must have closed for the boxes to meet.
    fn box_bound(&self, at: Point, dir: Point, extent: &[f64; 4], lo: Point, hi: Point) -> Option<f64> {
        let grow = 1e-9 * self.r.abs() + self.eps;
        // (separation at t = 0, its rate): box beyond the ball's right,
        // left, top and bottom sides.
        let seps = [
            (lo.x - at.x - self.r * extent[1], -dir.x - self.slope * extent[1]),
            (at.x + self.r * extent[0] - hi.x, dir.x + self.slope * extent[0]),
            (lo.y - at.y - self.r * extent[3], -dir.y - self.slope * extent[3]),
            (at.y + self.r * extent[2] - hi.y, dir.y + self.slope * extent[2]),
        ];
        let mut t: f64 = 0.0;
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
            let ex = self.exact(c);
            for g in &ex.valid {
                if g.n.dot_sign(d) == Ordering::Less {
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
            let key = |r: ElementRef| -> Option<f64> {
                let e = self.edge_of(r);
                if excluded(e) {
                    return None;
                }
                self.classes_of_edge(e).filter_map(contact).reduce(f64::min)
            };
            // A contact later than the validity end found exactly would
            // be dropped below: runs beyond it are never opened (most
            // rays end at a joint, long before the next contact).
            let found = self.chain.first_by_bound(
                t_first + 2.0 * walk.eps,
                2.0 * walk.eps,
                |run, _| walk.run_bound(self.reach, &self.extent, run),
                key,
            );
            let Some(&(_, t)) = found.first() else { break };
            let limit = t + 2.0 * walk.eps;
            // Every class of the edges found whose contact comes within
            // the margin; the earliest's own class among them, so that
            // every round without a contact sets at least one class aside
            // and the loop ends.
            let mut near: Vec<ClassId> = Vec::new();
            for &(r, _) in &found {
                near.extend(
                    self.classes_of_edge(self.edge_of(r)).filter(|&c| contact(c).is_some_and(|tc| tc <= limit)),
                );
            }
            near.sort_unstable();
            near.dedup();
            let mut hit = false;
            for c in near {
                match self.contact_on_ray(node, ray, re, c) {
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
        let q = match tie_line(re, ex).and_then(|t| ray.carrier.meet(&t)) {
            Some(q) => q,
            None => {
                // Parallel: equal along the whole line, or never.
                if &radius_num(ex, &node.p) * &re.h != &radius_num(re, &node.p) * &ex.h {
                    return None;
                }
                let mut entry: Option<HPoint> = None;
                for g in &ex.valid {
                    if g.side(&node.p) == Ordering::Less {
                        if g.n.dot_sign(d) != Ordering::Greater {
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
        (node.p.along(&q, d) == Ordering::Greater && valid_at(ex, &q)).then_some(q)
    }
}
