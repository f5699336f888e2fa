//! Points, vectors and boxes of space, in model units, for triangulated
//! solids (thesis chapter 3 in 3D).

use std::ops::{Add, Mul, Neg, Sub};

/// A point or a vector in space. Coordinates are `f64` in model units.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Point3 {
    /// x coordinate.
    pub x: f64,
    /// y coordinate.
    pub y: f64,
    /// z coordinate.
    pub z: f64,
}

impl Point3 {
    /// The point `(x, y, z)`.
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Self { x, y, z }
    }

    /// From an array `[x, y, z]`.
    pub const fn from_array(a: [f64; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// As an array `[x, y, z]`.
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    /// Dot product, as vectors.
    pub fn dot(self, o: Point3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product, as vectors (right-handed).
    pub fn cross(self, o: Point3) -> Point3 {
        Point3::new(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }

    /// Euclidean length, as a vector.
    pub fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// Squared length, as a vector.
    pub fn norm2(self) -> f64 {
        self.dot(self)
    }

    /// Euclidean distance to `o`.
    pub fn dist(self, o: Point3) -> f64 {
        (self - o).norm()
    }

    /// Coordinate `axis` (0 = x, 1 = y, 2 = z).
    pub fn coord(self, axis: usize) -> f64 {
        match axis {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }

    /// True when all three coordinates are finite.
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl Add for Point3 {
    type Output = Point3;
    fn add(self, o: Point3) -> Point3 {
        Point3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl Sub for Point3 {
    type Output = Point3;
    fn sub(self, o: Point3) -> Point3 {
        Point3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Mul<f64> for Point3 {
    type Output = Point3;
    fn mul(self, k: f64) -> Point3 {
        Point3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl Neg for Point3 {
    type Output = Point3;
    fn neg(self) -> Point3 {
        Point3::new(-self.x, -self.y, -self.z)
    }
}

/// An axis-aligned box of space; empty until a point is added.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BBox3 {
    /// Smallest corner.
    pub min: Point3,
    /// Largest corner.
    pub max: Point3,
}

impl Default for BBox3 {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl BBox3 {
    /// The box holding nothing (`min` > `max`).
    pub const EMPTY: BBox3 = BBox3 {
        min: Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY),
        max: Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY),
    };

    /// The smallest box holding `points`.
    pub fn of(points: impl IntoIterator<Item = Point3>) -> BBox3 {
        points.into_iter().fold(BBox3::EMPTY, |b, p| b.with(p))
    }

    /// This box grown to hold `p`.
    pub fn with(self, p: Point3) -> BBox3 {
        BBox3 {
            min: Point3::new(self.min.x.min(p.x), self.min.y.min(p.y), self.min.z.min(p.z)),
            max: Point3::new(self.max.x.max(p.x), self.max.y.max(p.y), self.max.z.max(p.z)),
        }
    }

    /// The smallest box holding both.
    pub fn union(self, o: BBox3) -> BBox3 {
        self.with(o.min).with(o.max)
    }

    /// True when no point was added.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x
    }

    /// Length of the diagonal (0 for an empty box).
    pub fn diagonal(&self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            (self.max - self.min).norm()
        }
    }

    /// True when the boxes share a point (closed boxes).
    pub fn overlaps(&self, o: &BBox3) -> bool {
        self.min.x <= o.max.x
            && o.min.x <= self.max.x
            && self.min.y <= o.max.y
            && o.min.y <= self.max.y
            && self.min.z <= o.max.z
            && o.min.z <= self.max.z
    }

    /// True when `o` lies inside this box (closed).
    pub fn contains_box(&self, o: &BBox3) -> bool {
        self.min.x <= o.min.x
            && self.min.y <= o.min.y
            && self.min.z <= o.min.z
            && o.max.x <= self.max.x
            && o.max.y <= self.max.y
            && o.max.z <= self.max.z
    }

    /// The centre.
    pub fn center(&self) -> Point3 {
        (self.min + self.max) * 0.5
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_is_right_handed_and_boxes_grow() {
        let (x, y) = (Point3::new(1.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0));
        assert_eq!(x.cross(y), Point3::new(0.0, 0.0, 1.0));
        let b = BBox3::of([Point3::new(0.0, 1.0, 2.0), Point3::new(-1.0, 3.0, 2.5)]);
        assert_eq!(b.min, Point3::new(-1.0, 1.0, 2.0));
        assert_eq!(b.max, Point3::new(0.0, 3.0, 2.5));
        assert!(BBox3::EMPTY.is_empty() && !b.is_empty());
        assert!(b.overlaps(&BBox3::of([Point3::new(0.0, 3.0, 2.5)])));
        assert!(!b.overlaps(&BBox3::of([Point3::new(0.1, 3.0, 2.5)])));
    }
}
