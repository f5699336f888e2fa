//! Arcs of circles that are not boundary elements: the auxiliary arcs where
//! a subshape meets a dividing disk (thesis Def. 2.2.1), and whether a disk
//! crosses one.

use super::direction::ccw_angle;
use super::{Disk, Point};

/// An arc of the circle (`center`, `radius`), counter-clockwise from the
/// point `from` to the point `to` (both on the circle), model units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircleArc {
    /// The circle's centre.
    pub center: Point,
    /// The circle's radius, > 0.
    pub radius: f64,
    /// Where the arc starts.
    pub from: Point,
    /// Where the arc ends.
    pub to: Point,
}

/// Whether a disk's circle passes through an arc.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Crossing {
    /// Through the arc's inside, away from its ends by more than the
    /// tolerance, or round the arc's whole disk.
    Crosses,
    /// Not through it (outside, inside, tangent or through its ends only,
    /// within the tolerance; or the arc's own circle).
    Clear,
}

/// [`Crossing`] of `disk`'s circle with `arc`, tolerance `tol` (model
/// units), in `f64`: the two circles' intersection points, each placed on
/// the arc by its counter-clockwise angle from the start.
pub fn arc_crossing(arc: &CircleArc, disk: Disk, tol: f64) -> Crossing {
    let (o, rho) = (disk.center, disk.radius);
    let (c, r) = (arc.center, arc.radius);
    let d = o.dist(c);
    let crosses = if d + r <= rho + tol {
        // The arc's whole disk inside the circle: the circle reaches past
        // the arc, unless it is the arc's own circle.
        rho > r + tol
    } else if d >= rho + r - tol || d + rho <= r + tol {
        false
    } else {
        let x = (d * d + r * r - rho * rho) / (2.0 * d);
        let h = (r * r - x * x).max(0.0).sqrt();
        let u = (o - c) * (1.0 / d);
        let base = c + u * x;
        let (va, vb) = (arc.from - c, arc.to - c);
        let sweep = ccw_angle(va, vb);
        [base + u.perp() * h, base - u.perp() * h].into_iter().any(|q| {
            let at = ccw_angle(va, q - c);
            // Strictly inside the arc, away from its ends by the tolerance.
            at * r > tol && (sweep - at) * r > tol
        })
    };
    if crosses {
        Crossing::Crosses
    } else {
        Crossing::Clear
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{AxisKernel, Disk, FilteredKernel};

    fn crosses(arc: CircleArc, o: Point, rho: f64, tol: f64) -> bool {
        FilteredKernel.arc_crossing(&arc, Disk::new(o, rho), tol) == Crossing::Crosses
    }

    /// The upper half of the unit circle, counter-clockwise from (1, 0).
    fn upper() -> CircleArc {
        CircleArc { center: Point::new(0.0, 0.0), radius: 1.0, from: Point::new(1.0, 0.0), to: Point::new(-1.0, 0.0) }
    }

    #[test]
    fn a_circle_through_the_arc_crosses_it() {
        assert!(crosses(upper(), Point::new(0.0, 1.0), 0.5, 1e-9));
    }

    #[test]
    fn a_circle_through_the_other_half_does_not() {
        assert!(!crosses(upper(), Point::new(0.0, -1.0), 0.5, 1e-9));
    }

    #[test]
    fn the_arcs_own_circle_and_circles_inside_it_do_not() {
        assert!(!crosses(upper(), Point::new(0.0, 0.0), 1.0, 1e-9));
        assert!(!crosses(upper(), Point::new(0.0, 0.2), 0.5, 1e-9));
    }

    #[test]
    fn a_circle_round_the_whole_disk_reaches_past_the_arc() {
        assert!(crosses(upper(), Point::new(0.0, 0.0), 1.5, 1e-9));
    }

    #[test]
    fn touching_the_arc_within_the_tolerance_is_no_crossing() {
        // Tangent from outside at the top, and meeting only the arc's ends.
        assert!(!crosses(upper(), Point::new(0.0, 2.0), 1.0, 1e-9));
        assert!(!crosses(upper(), Point::new(2.0, 0.0), 1.0, 1e-9));
    }
}
