//! An auxiliary arc of a subshape (part of a dividing disk's circle), and
//! whether another disk crosses it, which would take that disk out of the
//! subshape.

use crate::kernel::direction::ccw_angle;
use crate::kernel::Point;

/// An auxiliary arc where a subshape meets a dividing disk: a port through
/// which its axis leaves for the neighbouring subshape.
#[derive(Debug, Clone, Copy)]
pub(super) struct Port {
    /// The dividing disk (index into the divide step's cuts).
    pub(super) disk: usize,
    /// Index of the site after the arc in the cycle (may equal the number
    /// of sites: wrap it).
    pub(super) site_after: usize,
    /// The arc itself.
    pub(super) arc: AuxArc,
}

/// An auxiliary arc: counter-clockwise around `c` from `a` to `b`.
#[derive(Debug, Clone, Copy)]
pub(super) struct AuxArc {
    pub(super) c: Point,
    pub(super) r: f64,
    pub(super) a: Point,
    pub(super) b: Point,
}

impl AuxArc {
    /// True when the circle (`o`, `rho`) passes through the arc's inside
    /// (by more than `tol`): such a disk leaves the subshape.
    pub(super) fn crossed_by(&self, o: Point, rho: f64, tol: f64) -> bool {
        let d = o.dist(self.c);
        if d + self.r <= rho + tol {
            // The arc's whole disk inside the circle: the circle reaches
            // past the arc, unless it is the arc's own circle.
            return rho > self.r + tol;
        }
        if d >= rho + self.r - tol || d + rho <= self.r + tol {
            return false;
        }
        // The two intersection points of the circles.
        let x = (d * d + self.r * self.r - rho * rho) / (2.0 * d);
        let h = (self.r * self.r - x * x).max(0.0).sqrt();
        let u = (o - self.c) * (1.0 / d);
        let base = self.c + u * x;
        let (va, vb) = (self.a - self.c, self.b - self.c);
        let sweep = ccw_angle(va, vb);
        [base + u.perp() * h, base - u.perp() * h].into_iter().any(|q| {
            let vq = q - self.c;
            let at = ccw_angle(va, vq);
            // Strictly inside the arc, away from its ends by the tolerance.
            at * self.r > tol && (sweep - at) * self.r > tol
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The upper half of the unit circle, counter-clockwise from (1, 0).
    fn upper() -> AuxArc {
        AuxArc { c: Point::new(0.0, 0.0), r: 1.0, a: Point::new(1.0, 0.0), b: Point::new(-1.0, 0.0) }
    }

    #[test]
    fn a_circle_through_the_arc_crosses_it() {
        assert!(upper().crossed_by(Point::new(0.0, 1.0), 0.5, 1e-9));
    }

    #[test]
    fn a_circle_through_the_other_half_does_not() {
        assert!(!upper().crossed_by(Point::new(0.0, -1.0), 0.5, 1e-9));
    }

    #[test]
    fn the_arcs_own_circle_and_circles_inside_it_do_not() {
        assert!(!upper().crossed_by(Point::new(0.0, 0.0), 1.0, 1e-9));
        assert!(!upper().crossed_by(Point::new(0.0, 0.2), 0.5, 1e-9));
    }

    #[test]
    fn a_circle_round_the_whole_disk_reaches_past_the_arc() {
        assert!(upper().crossed_by(Point::new(0.0, 0.0), 1.5, 1e-9));
    }

    #[test]
    fn touching_the_arc_within_the_tolerance_is_no_crossing() {
        // Tangent from outside at the top, and meeting only the arc's ends.
        assert!(!upper().crossed_by(Point::new(0.0, 2.0), 1.0, 1e-9));
        assert!(!upper().crossed_by(Point::new(2.0, 0.0), 1.0, 1e-9));
    }
}
