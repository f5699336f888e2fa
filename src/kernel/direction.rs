//! Questions about directions (normals, tangents, vectors from a centre)
//! that the algorithms used to answer with a sign test of their own: on
//! which side of a normal a vector points, which way one direction turns
//! from another, and the angles that order directions round a fan.
//!
//! The directions asked about are themselves rounded constructions
//! (normals of elements, vectors between constructed points), so these
//! are `f64` evaluations: an exact sign of rounded inputs would not be
//! more right. They live here so that an exact kernel has one place to
//! change them, and so that `src/plane` holds no sign test of its own
//! (`tests/architecture.rs` checks it).

use super::fan::BoundSide;
use super::{Orientation, Point};

/// Where a vector points relative to a direction `n`: the sign of `n · v`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Heading {
    /// Into the half plane `n` points into (`n · v > 0`).
    Forward,
    /// Along the line perpendicular to `n` (`n · v = 0`, or not a number).
    Sideways,
    /// Into the other half plane (`n · v < 0`).
    Backward,
}

/// Where `v` points relative to the direction `n` (see [`Heading`]).
#[inline]
pub fn heading(n: Point, v: Point) -> Heading {
    let d = n.dot(v);
    if d > 0.0 {
        Heading::Forward
    } else if d < 0.0 {
        Heading::Backward
    } else {
        Heading::Sideways
    }
}

/// Which way direction `b` turns from direction `a`: [`Orientation::Left`]
/// counter-clockwise (`a × b > 0`), [`Orientation::Right`] clockwise,
/// [`Orientation::Collinear`] along or opposite it (or not a number).
#[inline]
pub fn turn(a: Point, b: Point) -> Orientation {
    super::orientation_of(a.cross(b))
}

/// How a vector lies along a direction, decided with a tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Alignment {
    /// Along the direction, within the tolerance.
    Along,
    /// Opposite the direction, within the tolerance.
    Against,
    /// Neither.
    Across,
}

/// How `v` lies along the unit direction `n`: within `tol` (the length of
/// `v`'s component across `n`, `v`'s units) of the line through `n`, on
/// `n`'s side (`Along`) or the other (`Against`).
#[inline]
pub fn alignment(n: Point, v: Point, tol: f64) -> Alignment {
    if n.cross(v).abs() > tol {
        return Alignment::Across;
    }
    match heading(n, v) {
        Heading::Forward => Alignment::Along,
        Heading::Backward => Alignment::Against,
        Heading::Sideways => Alignment::Across,
    }
}

/// How two unit directions `a` and `b` compare: one direction when their
/// dot product exceeds `1 − eps` (`Along`), opposite ones when it is
/// below `−(1 − eps)` (`Against`).
#[inline]
pub fn direction_match(a: Point, b: Point, eps: f64) -> Alignment {
    let d = a.dot(b);
    if d > 1.0 - eps {
        Alignment::Along
    } else if d < eps - 1.0 {
        Alignment::Against
    } else {
        Alignment::Across
    }
}

/// Whether the vector `m` from a vertex points into the vertex's fan of
/// normals, the directions between the left normals of the tangent
/// `t_in` arriving and `t_out` leaving (unit; a reflex vertex turns
/// clockwise from one to the other): not more than `tol` (`m`'s units)
/// behind the incoming tangent's normal line nor ahead of the outgoing
/// one's: [`BoundSide::Within`] the fan, or `Beyond` one of its bounds.
#[inline]
pub fn vertex_fan_side(t_in: Point, t_out: Point, m: Point, tol: f64) -> BoundSide {
    if m.dot(t_in) >= -tol && m.dot(t_out) <= tol {
        BoundSide::Within
    } else {
        BoundSide::Beyond
    }
}

/// The angle of direction `v` from the positive x axis, radians in
/// (−π, π] (0 for the zero vector).
#[inline]
pub fn angle_of(v: Point) -> f64 {
    v.y.atan2(v.x)
}

/// The signed angle from direction `a` to direction `b`, radians in
/// (−π, π]: positive counter-clockwise.
#[inline]
pub fn signed_angle(a: Point, b: Point) -> f64 {
    a.cross(b).atan2(a.dot(b))
}

/// The counter-clockwise angle from direction `a` to direction `b`,
/// radians in [0, 2π).
#[inline]
pub fn ccw_angle(a: Point, b: Point) -> f64 {
    signed_angle(a, b).rem_euclid(std::f64::consts::TAU)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headings_and_turns_read_the_signs() {
        let (e, n) = (Point::new(1.0, 0.0), Point::new(0.0, 1.0));
        assert_eq!(heading(e, Point::new(2.0, 5.0)), Heading::Forward);
        assert_eq!(heading(e, Point::new(0.0, 5.0)), Heading::Sideways);
        assert_eq!(heading(e, Point::new(-1.0, 5.0)), Heading::Backward);
        assert_eq!(turn(e, n), Orientation::Left);
        assert_eq!(turn(n, e), Orientation::Right);
        assert_eq!(turn(e, Point::new(-3.0, 0.0)), Orientation::Collinear);
    }

    #[test]
    fn angles() {
        let q = std::f64::consts::FRAC_PI_2;
        assert_eq!(angle_of(Point::new(0.0, 2.0)), q);
        assert_eq!(signed_angle(Point::new(0.0, 1.0), Point::new(1.0, 0.0)), -q);
        assert_eq!(ccw_angle(Point::new(0.0, 1.0), Point::new(1.0, 0.0)), 3.0 * q);
        assert_eq!(ccw_angle(Point::new(1.0, 0.0), Point::new(1.0, 0.0)), 0.0);
    }
}
