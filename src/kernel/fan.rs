//! Fans of directions: the normals round a reflex vertex, a curve's end
//! (half a turn) or a point site (a whole turn).

use super::Point;

/// The clockwise angle from direction `a` to direction `b`, radians in
/// [0, 2π): the order of directions round a fan of normals, whatever its
/// width. Neither direction needs unit length; a zero direction gives an
/// arbitrary but finite angle.
pub fn cw_angle(a: Point, b: Point) -> f64 {
    (a.y.atan2(a.x) - b.y.atan2(b.x)).rem_euclid(std::f64::consts::TAU)
}

#[cfg(test)]
mod tests {
    use super::*;

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
