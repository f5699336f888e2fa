//! Constructions on the disk that grows from a boundary point into a shape.
//!
//! The disk is tangent at `p` to a boundary element whose inward unit normal
//! there is `n`: centre `p + t·n`, radius `t`, for `t > 0`. These disks are
//! nested (each contains the smaller ones), so for any closed set there is a
//! first `t` at which the disk touches it, and the maximal disk at `p` is
//! the first touch over the whole boundary (thesis 2.2.1, Figure 2.2).
//!
//! Every function returns contact radii `t`; callers decide which contacts
//! count (inside an element's span, beyond a minimum radius). Relative
//! rounding error is a few ulps of the input magnitudes except where the
//! problem is ill-conditioned: a line nearly parallel to the tangent at `p`
//! or a circle nearly through `p` with a nearly tangent normal, where `t`
//! grows without bound.

use super::Point;

/// The disk `p + t·n`, radius `t`; `n` must be a unit vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GrowingDisk {
    /// The tangency point on the boundary.
    pub p: Point,
    /// Unit normal at `p`, pointing into the shape.
    pub n: Point,
}

impl GrowingDisk {
    /// Centre of the disk of radius `t`.
    pub fn center(&self, t: f64) -> Point {
        self.p + self.n * t
    }

    /// Radius at which the disk's circle passes through `q`:
    /// `|p − q|² / (2 n·(q − p))`; `None` when `q` lies on or behind the
    /// tangent line at `p` (the disk never reaches it).
    pub fn through_point(&self, q: Point) -> Option<f64> {
        let d = q - self.p;
        let along = self.n.dot(d);
        (along > 0.0).then(|| d.norm2() / (2.0 * along)).filter(|t| t.is_finite())
    }

    /// Radii at which the disk's circle is tangent to the line through `a`
    /// with unit normal `m`, with the tangency point (the foot of the
    /// centre): up to two, one per side of the line.
    pub fn tangent_to_line(&self, a: Point, m: Point) -> impl Iterator<Item = (f64, Point)> + '_ {
        // Signed distance of the centre, m·(p − a) + t·m·n, equals ±t.
        let (s0, k) = (m.dot(self.p - a), m.dot(self.n));
        [1.0, -1.0].into_iter().filter_map(move |side| {
            let t = s0 / (side - k);
            (t.is_finite() && t > 0.0).then(|| {
                let c = self.center(t);
                (t, c - m * (m.dot(c - a)))
            })
        })
    }

    /// Radii at which the disk's circle is tangent to the circle (`o`, `r`),
    /// externally or internally, with the tangency point: up to two.
    pub fn tangent_to_circle(&self, o: Point, r: f64) -> impl Iterator<Item = (f64, Point)> + '_ {
        let w = self.p - o;
        let wl = w.norm();
        // |w + t·n| = |t + s·r| for s = ±1:
        // t = (r² − |w|²) / (2 (n·w − s·r)), numerator factored for accuracy.
        let num = (r - wl) * (r + wl);
        let nw = self.n.dot(w);
        [1.0, -1.0].into_iter().filter_map(move |s| {
            let t = num / (2.0 * (nw - s * r));
            if !(t.is_finite() && t > 0.0) {
                return None;
            }
            let c = self.center(t);
            let v = c - o;
            let vl = v.norm();
            if vl == 0.0 {
                // Concentric: the disk is the circle itself (t = r) and
                // touches all of it; report the point opposite `p`.
                return Some((t, o - w));
            }
            // External tangency, or this disk inside the circle: the circle
            // point towards the centre. The circle inside this disk: the
            // point away from it.
            let toward = s > 0.0 || t < r;
            let q = if toward { o + v * (r / vl) } else { o - v * (r / vl) };
            Some((t, q))
        })
    }

    /// The radius at which the disk first meets the closed box
    /// [`min`, `max`], slightly lowered so that rounding never makes it
    /// exceed the first contact with anything inside the box: 0 when the
    /// box holds `p`, `None` when the disk never reaches it. The box is
    /// convex, so the first contact is at a corner or where the circle is
    /// tangent to a side.
    pub fn box_bound(&self, min: Point, max: Point) -> Option<f64> {
        self.box_bound_below(min, max, f64::INFINITY)
    }

    /// [`box_bound`](Self::box_bound), or a cheaper lower bound when that
    /// one already reaches `cutoff` (the box's circumscribed circle is met
    /// no earlier than the box).
    pub fn box_bound_below(&self, min: Point, max: Point, cutoff: f64) -> Option<f64> {
        let p = self.p;
        if min.x <= p.x && p.x <= max.x && min.y <= p.y && p.y <= max.y {
            return Some(0.0);
        }
        if cutoff.is_finite() {
            // First contact with the circle (m, ρ) around the box:
            // |t·n − w| = t + ρ with w = m − p, so t = (|w|² − ρ²) / (2 (ρ + n·w)).
            let (m, rho) = (min.mid(max), 0.5 * min.dist(max));
            let w = m - p;
            let den = 2.0 * (rho + self.n.dot(w));
            let num = (w.norm() - rho) * (w.norm() + rho);
            if num > 0.0 {
                if den <= 0.0 {
                    // The circle, hence the box, lies beyond every disk.
                    return None;
                }
                let t = num / den * (1.0 - 1e-12);
                if t >= cutoff {
                    return Some(t);
                }
            }
        }
        // The first contact is the box point nearest the centre, so it lies
        // on a side whose outer half-plane holds the centre; a disk through
        // `p` reaching that side before anything else has `p` there too.
        // Sides facing away from `p`, and corners between two of them,
        // are never first.
        let (left, right) = (p.x < min.x, p.x > max.x);
        let (below, above) = (p.y < min.y, p.y > max.y);
        let mut best = f64::INFINITY;
        for (q, faces) in [
            (min, left || below),
            (Point::new(max.x, min.y), right || below),
            (max, right || above),
            (Point::new(min.x, max.y), left || above),
        ] {
            if let Some(t) = self.through_point(q).filter(|_| faces) {
                best = best.min(t);
            }
        }
        // Sides x = const (normal ±x) and y = const (normal ±y).
        for (x, m, lo, hi, vertical, faces) in [
            (min, Point::new(1.0, 0.0), min.y, max.y, true, left),
            (max, Point::new(1.0, 0.0), min.y, max.y, true, right),
            (min, Point::new(0.0, 1.0), min.x, max.x, false, below),
            (max, Point::new(0.0, 1.0), min.x, max.x, false, above),
        ] {
            if !faces {
                continue;
            }
            for (t, foot) in self.tangent_to_line(x, m) {
                let along = if vertical { foot.y } else { foot.x };
                if lo <= along && along <= hi {
                    best = best.min(t);
                }
            }
        }
        best.is_finite().then_some(best * (1.0 - 1e-12))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn contacts_with_points_lines_and_circles() {
        // Growing upwards from the origin.
        let g = GrowingDisk { p: Point::new(0.0, 0.0), n: Point::new(0.0, 1.0) };
        // The circle through (1, 1): centre (0, 1), radius 1.
        assert!(close(g.through_point(Point::new(1.0, 1.0)).unwrap(), 1.0));
        assert_eq!(g.through_point(Point::new(1.0, -1.0)), None);
        // The line y = 4 (normal pointing down): touched at t = 2, foot (0, 4).
        let ts: Vec<_> = g.tangent_to_line(Point::new(5.0, 4.0), Point::new(0.0, -1.0)).collect();
        assert_eq!(ts.len(), 1);
        assert!(close(ts[0].0, 2.0) && ts[0].1.dist(Point::new(0.0, 4.0)) < 1e-12);
        // A slanted line x = 3: touched at t = 3, foot (3, 3).
        let ts: Vec<_> = g.tangent_to_line(Point::new(3.0, -7.0), Point::new(1.0, 0.0)).collect();
        assert!(ts.iter().any(|&(t, q)| close(t, 3.0) && q.dist(Point::new(3.0, 3.0)) < 1e-12));
        // Circle centre (0, 5) radius 1: external contact at t = 2 (point (0, 4)),
        // and the disk of radius 3 centred (0, 3) contains it, touching at (0, 6).
        let ts: Vec<_> = g.tangent_to_circle(Point::new(0.0, 5.0), 1.0).collect();
        assert!(ts.iter().any(|&(t, q)| close(t, 2.0) && q.dist(Point::new(0.0, 4.0)) < 1e-12));
        assert!(ts.iter().any(|&(t, q)| close(t, 3.0) && q.dist(Point::new(0.0, 6.0)) < 1e-12));
        // A circle around p: the disk grows inside it to radius (R + d)/2.
        let ts: Vec<_> = g.tangent_to_circle(Point::new(0.0, 1.0), 3.0).collect();
        assert!(ts.iter().any(|&(t, q)| close(t, 2.0) && q.dist(Point::new(0.0, 4.0)) < 1e-12));
    }

    #[test]
    fn every_reported_contact_is_a_tangency() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::SmallRng::seed_from_u64(17);
        let mut rnd = || rng.gen_range(-10.0..10.0);
        let mut seen = 0;
        for _ in 0..2000 {
            let n = Point::new(rnd(), rnd()).unit();
            let g = GrowingDisk { p: Point::new(rnd(), rnd()), n };
            let (o, r) = (Point::new(rnd(), rnd()), rnd().abs() + 0.1);
            for (t, q) in g.tangent_to_circle(o, r) {
                let c = g.center(t);
                // q on both circles, and the circles tangent at q.
                assert!((q.dist(o) - r).abs() < 1e-9 && (q.dist(c) - t).abs() < 1e-9 * (1.0 + t));
                assert!((q - o).cross(q - c).abs() < 1e-7 * (1.0 + t) * r);
                seen += 1;
            }
            let m = Point::new(rnd(), rnd()).unit();
            let a = Point::new(rnd(), rnd());
            for (t, q) in g.tangent_to_line(a, m) {
                assert!(m.dot(q - a).abs() < 1e-9 * (1.0 + t) && (q.dist(g.center(t)) - t).abs() < 1e-9 * (1.0 + t));
                seen += 1;
            }
        }
        assert!(seen > 2000, "{seen}");
    }

    #[test]
    fn box_bound_is_the_first_contact() {
        let g = GrowingDisk { p: Point::new(0.0, 0.0), n: Point::new(0.6, 0.8) };
        for &(min, max) in &[
            (Point::new(2.0, 2.0), Point::new(3.0, 3.0)),
            (Point::new(-5.0, 1.0), Point::new(-4.0, 9.0)),
            (Point::new(-1.0, -1.0), Point::new(1.0, 1.0)),
        ] {
            let bound = g.box_bound(min, max).unwrap();
            // The true first contact, by bisection on the distance to the box.
            let dist = |t: f64| {
                let c = g.center(t);
                let dx = (min.x - c.x).max(c.x - max.x).max(0.0);
                let dy = (min.y - c.y).max(c.y - max.y).max(0.0);
                dx.hypot(dy) - t
            };
            let (mut lo, mut hi) = (0.0, 100.0);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if dist(mid) <= 0.0 {
                    hi = mid
                } else {
                    lo = mid
                }
            }
            assert!(bound <= hi + 1e-12 && bound >= lo - 1e-9, "{bound} vs [{lo}, {hi}]");
        }
        for cutoff in [0.0, 1.0, 1e9] {
            // The circle bound, where it is used, never exceeds the exact one.
            let exact = g.box_bound(Point::new(2.0, 2.0), Point::new(3.0, 3.0)).unwrap();
            let quick = g.box_bound_below(Point::new(2.0, 2.0), Point::new(3.0, 3.0), cutoff).unwrap();
            assert!(quick <= exact && (quick == exact || quick >= cutoff), "{quick} {exact} {cutoff}");
        }
        // Behind the tangent line: never met.
        let up = GrowingDisk { p: Point::new(0.0, 0.0), n: Point::new(0.0, 1.0) };
        assert_eq!(up.box_bound(Point::new(-1.0, -3.0), Point::new(1.0, -2.0)), None);
        // Exact, not just a bound: a box whose lower side is y = 4 is met at t = 2.
        let t = up.box_bound(Point::new(-1.0, 4.0), Point::new(1.0, 5.0)).unwrap();
        assert!((t - 2.0).abs() < 1e-11, "{t}");
    }
}
