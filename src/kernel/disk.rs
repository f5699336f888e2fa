//! Disks: the medial axis's nodes and samples, the divide step's cuts, the
//! constructions' answers.

use super::Point;

/// A closed disk, model units: centre and radius (≥ 0; 0 at a convex
/// corner).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Disk {
    /// Centre.
    pub center: Point,
    /// Radius, ≥ 0.
    pub radius: f64,
}

impl Disk {
    /// The disk of radius `radius` around `center`.
    #[inline]
    pub fn new(center: Point, radius: f64) -> Disk {
        Disk { center, radius }
    }

    /// Whether this disk and `other` are one disk within `tol` (model
    /// units): centres and radii each within `tol`.
    #[inline]
    pub fn same_as(&self, other: &Disk, tol: f64) -> bool {
        self.center.dist(other.center) <= tol && (self.radius - other.radius).abs() <= tol
    }

    /// Centre and radius, in that order.
    #[inline]
    pub fn parts(self) -> (Point, f64) {
        (self.center, self.radius)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_disk_within_the_tolerance() {
        let d = Disk::new(Point::new(1.0, 2.0), 3.0);
        assert!(d.same_as(&Disk::new(Point::new(1.0, 2.0 + 1e-10), 3.0 - 1e-10), 1e-9));
        assert!(!d.same_as(&Disk::new(Point::new(1.0, 2.0), 3.1), 1e-9));
        assert_eq!(d.parts(), (Point::new(1.0, 2.0), 3.0));
    }
}
