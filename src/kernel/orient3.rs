//! Exact predicates of space for triangulated solids: the side of a point
//! relative to the plane of three points, and collinearity of three points.
//! Validation (degenerate facets, self-intersections) and inside tests
//! stand on them, and a wrong sign there turns a valid solid into an error
//! or lets a crossing through, so they are exact: an `f64` determinant with
//! Shewchuk's error bound first, big integers behind it (as in
//! `kernel::exact_int`: every finite `f64` is an integer in units of the
//! smallest exponent among the inputs, and the determinant is homogeneous,
//! so scaling leaves its sign alone).

use super::bigint::{decompose, BigInt};
use super::{FilteredKernel, Kernel, Orientation, Point, Point3};
use std::cmp::Ordering;

/// Where a point lies relative to the oriented plane through `a, b, c`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlaneSide {
    /// On the side `(b − a) × (c − a)` points to (`a, b, c` counter-clockwise
    /// seen from the point).
    Above,
    /// On the plane (or the three points are collinear).
    On,
    /// On the other side.
    Below,
}

const EPS: f64 = f64::EPSILON * 0.5;
// Shewchuk (1997), the non-adaptive stage of orient3d.
const ORIENT3_ERRBOUND: f64 = (7.0 + 56.0 * EPS) * EPS;

fn side_of(ord: Ordering) -> PlaneSide {
    match ord {
        Ordering::Greater => PlaneSide::Above,
        Ordering::Equal => PlaneSide::On,
        Ordering::Less => PlaneSide::Below,
    }
}

/// Exact side of `d` relative to the plane through `a, b, c`:
/// the sign of `((b − a) × (c − a)) · (d − a)`.
pub fn plane_side(a: Point3, b: Point3, c: Point3, d: Point3) -> PlaneSide {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let bc = bd.y * cd.z - bd.z * cd.y;
    let ca = cd.y * ad.z - cd.z * ad.y;
    let ab = ad.y * bd.z - ad.z * bd.y;
    let det = ad.x * bc + bd.x * ca + cd.x * ab;
    let permanent = ((bd.y * cd.z).abs() + (bd.z * cd.y).abs()) * ad.x.abs()
        + ((cd.y * ad.z).abs() + (cd.z * ad.y).abs()) * bd.x.abs()
        + ((ad.y * bd.z).abs() + (ad.z * bd.y).abs()) * cd.x.abs();
    // The bound holds only without overflow or underflow in the terms.
    if det.abs() > ORIENT3_ERRBOUND * permanent && permanent.is_finite() && permanent > f64::MIN_POSITIVE * 1e40 {
        // det = (a − d) · ((b − d) × (c − d)) = −((b − a) × (c − a)) · (d − a).
        return side_of(0.0f64.total_cmp(&det));
    }
    exact_plane_side(a, b, c, d)
}

/// The coordinates as integers, all scaled by the same power of two.
fn scaled<const N: usize>(values: [f64; N]) -> [BigInt; N] {
    let parts = values.map(decompose);
    let e0 = parts.iter().filter(|p| p.1 != 0).map(|p| p.2).min().unwrap_or(0);
    parts.map(
        |(negative, m, e)| if m == 0 { BigInt::default() } else { BigInt::from_shifted(negative, m, (e - e0) as u32) },
    )
}

fn exact_plane_side(a: Point3, b: Point3, c: Point3, d: Point3) -> PlaneSide {
    let [ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz] =
        scaled([a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z]);
    let (ux, uy, uz) = (&bx - &ax, &by - &ay, &bz - &az);
    let (vx, vy, vz) = (&cx - &ax, &cy - &ay, &cz - &az);
    let (wx, wy, wz) = (&dx - &ax, &dy - &ay, &dz - &az);
    let nx = &(&uy * &vz) - &(&uz * &vy);
    let ny = &(&uz * &vx) - &(&ux * &vz);
    let nz = &(&ux * &vy) - &(&uy * &vx);
    let det = &(&(&nx * &wx) + &(&ny * &wy)) + &(&nz * &wz);
    side_of(det.signum())
}

/// Exactly whether `a, b, c` lie on one line (two or three of them equal
/// included): the cross product `(b − a) × (c − a)` is zero exactly when
/// its three components, the orientations of the projections onto the
/// coordinate planes, all vanish.
pub fn collinear3(a: Point3, b: Point3, c: Point3) -> bool {
    let k = FilteredKernel;
    let proj = |p: Point3, i: usize| match i {
        0 => Point::new(p.y, p.z),
        1 => Point::new(p.z, p.x),
        _ => Point::new(p.x, p.y),
    };
    (0..3).all(|i| k.orientation(proj(a, i), proj(b, i), proj(c, i)) == Orientation::Collinear)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    #[test]
    fn sides_of_the_unit_triangle() {
        let (a, b, c) = (p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0));
        assert_eq!(plane_side(a, b, c, p(0.2, 0.2, 1.0)), PlaneSide::Above);
        assert_eq!(plane_side(a, b, c, p(0.2, 0.2, -1e-300)), PlaneSide::Below);
        assert_eq!(plane_side(a, b, c, p(5.0, -3.0, 0.0)), PlaneSide::On);
        assert_eq!(plane_side(b, a, c, p(0.2, 0.2, 1.0)), PlaneSide::Below);
    }

    /// Points on a slanted plane x + y + z = 1 (exactly representable
    /// sums): the filter cannot decide, the exact path says On; a nudge of
    /// one ulp is decided by its sign.
    #[test]
    fn near_degenerate_signs_are_exact() {
        let (a, b, c) = (p(0.5, 0.25, 0.25), p(0.125, 0.5, 0.375), p(0.75, 0.0, 0.25));
        let d = p(0.0625, 0.4375, 0.5);
        assert_eq!(plane_side(a, b, c, d), PlaneSide::On);
        let up = p(0.0625, 0.4375, f64::from_bits(0.5f64.to_bits() + 1));
        let down = p(0.0625, 0.4375, f64::from_bits(0.5f64.to_bits() - 1));
        let s_up = plane_side(a, b, c, up);
        assert_ne!(s_up, PlaneSide::On);
        assert_eq!(
            plane_side(a, b, c, down),
            if s_up == PlaneSide::Above { PlaneSide::Below } else { PlaneSide::Above }
        );
        // Against the exact path directly, on random-ish large/small mixes.
        for k in 0..200 {
            let f = |i: u32| ((k * 7919 + i * 104729) % 1000) as f64 * 1e-3 - 0.5;
            let q =
                [p(f(1), f(2), f(3)), p(f(4) * 1e8, f(5), f(6)), p(f(7), f(8) * 1e-8, f(9)), p(f(10), f(11), f(12))];
            assert_eq!(plane_side(q[0], q[1], q[2], q[3]), exact_plane_side(q[0], q[1], q[2], q[3]), "{k}");
        }
    }

    #[test]
    fn collinearity_is_exact() {
        assert!(collinear3(p(0.0, 0.0, 0.0), p(1.0, 1.0, 1.0), p(3.0, 3.0, 3.0)));
        assert!(collinear3(p(1.0, 2.0, 3.0), p(1.0, 2.0, 3.0), p(7.0, -1.0, 0.5)));
        assert!(!collinear3(p(0.0, 0.0, 0.0), p(1.0, 1.0, 1.0), p(3.0, 3.0, f64::from_bits(3.0f64.to_bits() + 1))));
    }
}
