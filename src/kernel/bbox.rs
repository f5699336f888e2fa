//! Axis-aligned bounding boxes.

use super::Point;

/// An axis-aligned box `[min.x, max.x] × [min.y, max.y]` in model units.
/// The empty box has `min > max` and contains nothing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BBox {
    /// Lower-left corner.
    pub min: Point,
    /// Upper-right corner.
    pub max: Point,
}

impl Default for BBox {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl BBox {
    /// The box that contains nothing; the identity of [`BBox::union`].
    pub const EMPTY: BBox =
        BBox { min: Point::new(f64::INFINITY, f64::INFINITY), max: Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY) };

    /// The smallest box containing both points.
    pub fn of_points(a: Point, b: Point) -> BBox {
        BBox { min: Point::new(a.x.min(b.x), a.y.min(b.y)), max: Point::new(a.x.max(b.x), a.y.max(b.y)) }
    }

    /// True when the box contains nothing.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y
    }

    /// Grows the box to contain `p`.
    pub fn add_point(&mut self, p: Point) {
        self.min.x = self.min.x.min(p.x);
        self.min.y = self.min.y.min(p.y);
        self.max.x = self.max.x.max(p.x);
        self.max.y = self.max.y.max(p.y);
    }

    /// The smallest box containing both boxes.
    pub fn union(&self, o: &BBox) -> BBox {
        BBox {
            min: Point::new(self.min.x.min(o.min.x), self.min.y.min(o.min.y)),
            max: Point::new(self.max.x.max(o.max.x), self.max.y.max(o.max.y)),
        }
    }

    /// The box grown by `d` on every side.
    pub fn inflate(&self, d: f64) -> BBox {
        BBox { min: Point::new(self.min.x - d, self.min.y - d), max: Point::new(self.max.x + d, self.max.y + d) }
    }

    /// Euclidean distance from `p` to the closed box (0 inside).
    pub fn distance_to(&self, p: Point) -> f64 {
        self.distance2_to(p).sqrt()
    }

    /// Squared distance from `p` to the box (0 inside), model units².
    pub fn distance2_to(&self, p: Point) -> f64 {
        let dx = (self.min.x - p.x).max(p.x - self.max.x).max(0.0);
        let dy = (self.min.y - p.y).max(p.y - self.max.y).max(0.0);
        dx * dx + dy * dy
    }

    /// True when the closed boxes share at least one point.
    pub fn overlaps(&self, o: &BBox) -> bool {
        self.min.x <= o.max.x && o.min.x <= self.max.x && self.min.y <= o.max.y && o.min.y <= self.max.y
    }

    /// True when `p` lies in the closed box.
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }

    /// Length of the diagonal; 0 for the empty box.
    pub fn diagonal(&self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            (self.max - self.min).norm()
        }
    }

    /// The centre point.
    pub fn center(&self) -> Point {
        self.min.mid(self.max)
    }

    /// Width (x extent).
    pub fn width(&self) -> f64 {
        self.max.x - self.min.x
    }

    /// Height (y extent).
    pub fn height(&self) -> f64 {
        self.max.y - self.min.y
    }
}
