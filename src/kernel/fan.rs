//! Fans of directions: the normals round a reflex vertex, a curve's end
//! (half a turn) or a point site (a whole turn).

use super::Point;

/// The clockwise angle from direction `a` to direction `b`, radians in
/// [0, 2π): the order of directions round a fan of normals, whatever its
/// width. Neither direction needs unit length; a zero direction gives an
/// arbitrary but finite angle.
#[inline]
pub fn cw_angle(a: Point, b: Point) -> f64 {
    (a.y.atan2(a.x) - b.y.atan2(b.x)).rem_euclid(std::f64::consts::TAU)
}

/// A fan of directions, clockwise from a start direction through a width
/// of up to a whole turn: the normals at a reflex vertex (less than a half
/// turn), at a curve site's end (a half turn) or round a point site (a
/// whole turn), or the part of one that a subshape holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fan {
    start: Point,
    width: f64,
}

/// Which end of a fan a bounding direction stands at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FanEnd {
    /// The start: the fan runs clockwise away from it.
    Start,
    /// The end: the fan runs anticlockwise away from it.
    End,
}

/// Where a direction lies relative to a direction that bounds a fan at one
/// of its ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BoundSide {
    /// On the fan's side of the bound, or along it within the slack.
    Within,
    /// On the far side: outside the fan there.
    Beyond,
}

impl Fan {
    /// The fan clockwise from direction `start` to direction `end`.
    #[inline]
    pub fn clockwise(start: Point, end: Point) -> Fan {
        Fan { start, width: cw_angle(start, end) }
    }

    /// The fan clockwise from `start` to `end`, or the whole turn from
    /// `start` when the two are one direction within `min_width` radians
    /// (a point between the two arcs of one disk).
    #[inline]
    pub fn clockwise_or_whole(start: Point, end: Point, min_width: f64) -> Fan {
        let fan = Fan::clockwise(start, end);
        if fan.width <= min_width {
            Fan::whole_turn(start)
        } else {
            fan
        }
    }

    /// The whole turn of directions, starting at `start`.
    #[inline]
    pub fn whole_turn(start: Point) -> Fan {
        Fan { start, width: std::f64::consts::TAU }
    }

    /// The start direction.
    #[inline]
    pub fn start(&self) -> Point {
        self.start
    }

    /// The width, radians in [0, 2π].
    #[inline]
    pub fn width(&self) -> f64 {
        self.width
    }

    /// How far clockwise from the start direction `d` lies, radians in
    /// [0, 2π).
    #[inline]
    pub fn offset_of(&self, d: Point) -> f64 {
        cw_angle(self.start, d)
    }

    /// Whether direction `d` lies in the fan, its ends widened by `slack`
    /// radians on either side.
    #[inline]
    pub fn contains(&self, d: Point, slack: f64) -> bool {
        let x = self.offset_of(d);
        x <= self.width + slack || x >= std::f64::consts::TAU - slack
    }

    /// How far clockwise from the start direction `d` lies, radians, with
    /// the gap outside the fan cut in its middle: a direction just before
    /// the start reads as a small negative offset, one just past the end
    /// as a little more than the width. A direction a hair outside either
    /// end thus stays on that end's side, whichever of two neighbouring
    /// fans (sharing the end up to rounding) it is measured in.
    #[inline]
    pub fn signed_offset_of(&self, d: Point) -> f64 {
        let x = self.offset_of(d);
        if x > self.width && std::f64::consts::TAU - x < x - self.width {
            x - std::f64::consts::TAU
        } else {
            x
        }
    }

    /// Whether direction `m` lies on this fan's side of `bound`, a unit
    /// direction standing at the fan's `end` (the two may differ by
    /// rounding), with `slack` radians of play. Both directions unit.
    ///
    /// The side of `bound` decides, except where `m` is opposite it: at a
    /// curve's end a fan is a half turn (thesis 2.3, zero-area holes), so
    /// a disk tangent to one side there is opposite a bound tangent to the
    /// other and the side is rounding. Such an `m` is within only when the
    /// fan is itself a half turn (its other end opposite `bound` too); a
    /// fan narrower than a half turn whose ends rounding swapped reads as
    /// nearly a whole turn and holds no such direction.
    #[inline]
    pub fn bound_side(&self, bound: Point, end: FanEnd, m: Point, slack: f64) -> BoundSide {
        let cross = match end {
            FanEnd::Start => bound.cross(m),
            FanEnd::End => -bound.cross(m),
        };
        let opposite = bound.dot(m) < 0.0;
        let within = if cross.abs() > slack || !opposite {
            cross <= slack
        } else {
            (std::f64::consts::PI - slack..1.5 * std::f64::consts::PI).contains(&self.width)
        };
        if within {
            BoundSide::Within
        } else {
            BoundSide::Beyond
        }
    }

    /// The direction `fraction` (0 to 1) of the way through the fan, with
    /// the start direction's length.
    #[inline]
    pub fn direction_at(&self, fraction: f64) -> Point {
        let (s, c) = (-self.width * fraction).sin_cos();
        Point::new(c * self.start.x - s * self.start.y, s * self.start.x + c * self.start.y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bound_sides_and_the_half_turn() {
        let (east, south, west, north) =
            (Point::new(1.0, 0.0), Point::new(0.0, -1.0), Point::new(-1.0, 0.0), Point::new(0.0, 1.0));
        let slack = 1e-7;
        // A quarter fan from east clockwise to south.
        let quarter = Fan::clockwise(east, south);
        let se = Point::new(1.0, -1.0).unit();
        assert_eq!(quarter.bound_side(east, FanEnd::Start, se, slack), BoundSide::Within);
        assert_eq!(quarter.bound_side(east, FanEnd::Start, north, slack), BoundSide::Beyond);
        assert_eq!(quarter.bound_side(south, FanEnd::End, se, slack), BoundSide::Within);
        assert_eq!(quarter.bound_side(south, FanEnd::End, west, slack), BoundSide::Beyond);
        // Along the bound within the slack counts as within.
        let hair = Point::new(1.0, 1e-9).unit();
        assert_eq!(quarter.bound_side(east, FanEnd::Start, hair, slack), BoundSide::Within);
        // Opposite the bound: within only a half-turn fan.
        let half = Fan::clockwise(north, south);
        assert_eq!(half.bound_side(north, FanEnd::Start, south, slack), BoundSide::Within);
        assert_eq!(quarter.bound_side(east, FanEnd::Start, west, slack), BoundSide::Beyond);
        // A narrow fan whose ends rounding swapped (nearly a whole turn)
        // holds no direction opposite its bound.
        let swapped = Fan::clockwise(Point::new(1.0, -1e-12).unit(), east);
        assert_eq!(swapped.bound_side(east, FanEnd::Start, west, slack), BoundSide::Beyond);
    }

    #[test]
    fn fans_of_any_width() {
        let (east, south) = (Point::new(1.0, 0.0), Point::new(0.0, -1.0));
        let quarter = Fan::clockwise(east, south);
        assert!((quarter.width() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert!(quarter.direction_at(1.0).dist(south) < 1e-15);
        let whole = Fan::clockwise_or_whole(east, east, 1e-7);
        assert_eq!(whole.width(), std::f64::consts::TAU);
        assert!(whole.direction_at(0.5).dist(Point::new(-1.0, 0.0)) < 1e-15);
        assert!((whole.offset_of(Point::new(0.0, 1.0)) - 1.5 * std::f64::consts::PI).abs() < 1e-15);
        let north = Point::new(0.0, 1.0);
        assert!(quarter.contains(Point::new(1.0, -1.0), 0.0) && !quarter.contains(north, 0.1));
        assert!(quarter.contains(Point::new(1.0, 1e-9), 1e-8));
        // Just before the start: negative; just past the end: past the width.
        assert!((quarter.signed_offset_of(Point::new(1.0, 1e-3)) + 1e-3).abs() < 1e-9);
        assert!(quarter.signed_offset_of(Point::new(-1e-3, -1.0)) > quarter.width());
    }

    #[test]
    fn clockwise_angles_cover_the_whole_turn() {
        let east = Point::new(1.0, 0.0);
        let q = std::f64::consts::FRAC_PI_2;
        assert_eq!(cw_angle(east, east), 0.0);
        assert!((cw_angle(east, Point::new(0.0, -1.0)) - q).abs() < 1e-15);
        assert!((cw_angle(east, Point::new(0.0, 1.0)) - 3.0 * q).abs() < 1e-15);
        assert!((cw_angle(Point::new(0.0, 2.0), east) - q).abs() < 1e-15);
    }
}
