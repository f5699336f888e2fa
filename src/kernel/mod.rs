//! The geometric kernel: number types, predicates and constructions.
//!
//! Algorithms never compute a sign themselves; they ask a [`Kernel`]. A
//! predicate answers a geometric question with an enum ([`Orientation`],
//! [`CircleSide`]); a construction (in [`construct`]) builds new geometry and
//! is always rounded to `f64`. Two kernels exist now:
//!
//! * [`FloatKernel`]: plain `f64` evaluation. Fast; its answers can be wrong
//!   for nearly degenerate input, which its name makes visible.
//! * [`FilteredKernel`]: the same `f64` evaluation guarded by a forward error
//!   bound (Shewchuk's static filter); only when the bound cannot certify the
//!   sign is the predicate recomputed exactly, with integers in pure Rust
//!   (`exact_int`: no system library needed). Its answers are exact for every
//!   finite `f64` input. With the `gmp` feature the fallback is evaluated
//!   with GMP rationals instead (`exact`); the answers are the same (a test
//!   cross-checks the two), only the dependency differs.
//!
//! The medial-axis algorithms ask more than signs: [`AxisKernel`] (in
//! [`axis_kernel`]) adds the constructions and tolerance decisions they
//! need, with `f64` provided methods, and both kernels implement it.
//!
//! This mirrors the CGAL traits design (predicates separate from
//! constructions, filtered = interval first, exact on doubt) without the
//! template parameters.

pub mod apollonius;
pub mod axis_kernel;
mod bbox;
// Always built: the exact lines of the polygon-ball axis use it with or
// without `gmp` (the predicates' fallback only without it).
pub(crate) mod bigint;
pub mod bisector;
mod circle_arc;
pub mod construct;
pub mod direction;
mod disk;
pub mod element;
#[cfg(feature = "gmp")]
mod exact;
#[cfg(any(test, not(feature = "gmp")))]
mod exact_int;
pub(crate) mod exact_line;
pub(crate) mod exact_space;
pub mod fan;
pub mod growing_disk;
mod limbs;
pub mod orient3;
mod point;
mod point3;
mod site_piece;
pub mod tolerance;
pub mod tri_tri;
pub(crate) mod xfloat;

pub use axis_kernel::{AxisKernel, CarrierSide, Contact};
pub use bbox::BBox;
pub(crate) use bigint::BigInt;
pub use circle_arc::{CircleArc, Crossing};
pub use disk::Disk;
pub use point::Point;
pub use point3::{BBox3, Point3};
pub use site_piece::SitePiece;

// The exact fallback of `FilteredKernel`: both evaluations are exact, so the
// choice changes no answer; GMP only when the caller opted into it.
#[cfg(feature = "gmp")]
use exact as fallback;
#[cfg(not(feature = "gmp"))]
use exact_int as fallback;

/// Where a point lies relative to a directed line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Strictly to the left (counter-clockwise turn).
    Left,
    /// On the line (collinear).
    Collinear,
    /// Strictly to the right (clockwise turn).
    Right,
}

/// Where a point lies relative to the circle through three points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CircleSide {
    /// Strictly inside the circle.
    Inside,
    /// On the circle.
    On,
    /// Strictly outside the circle.
    Outside,
}

/// The predicates an algorithm may ask. Implementations differ in how exact
/// their answers are, never in what question they answer.
pub trait Kernel: Send + Sync {
    /// Orientation of `r` relative to the directed line `p → q`.
    fn orientation(&self, p: Point, q: Point, r: Point) -> Orientation;

    /// Side of `d` relative to the circle through `a`, `b`, `c`, which must be
    /// in counter-clockwise order (for clockwise order the answer flips).
    fn circle_side(&self, a: Point, b: Point, c: Point, d: Point) -> CircleSide;

    /// Orientation of the direction `r → s` relative to the direction
    /// `p → q`: the sign of the cross product (q − p) × (s − r), `Left`
    /// when positive. With `r = p` it is [`orientation`](Self::orientation);
    /// with `r` the origin and `s = (−n.y, n.x)` it compares `p` and `q`
    /// along `n` (`Left`: `q` lies further). Exact by default (as
    /// [`FilteredKernel`] decides it).
    fn cross_sign(&self, p: Point, q: Point, r: Point, s: Point) -> Orientation {
        FilteredKernel.cross_sign(p, q, r, s)
    }
}

/// Plain `f64` predicates: exact signs are *not* guaranteed near degeneracy.
#[derive(Debug, Clone, Copy, Default)]
pub struct FloatKernel;

/// `f64` predicates certified by an error bound, falling back to exact big
/// integer arithmetic (GMP rationals with the `gmp` feature) when the bound
/// cannot decide. Exact for all finite `f64` inputs (no overflow or
/// underflow limits).
#[derive(Debug, Clone, Copy, Default)]
pub struct FilteredKernel;

fn orient_det(p: Point, q: Point, r: Point) -> (f64, f64) {
    let l = (p.x - r.x) * (q.y - r.y);
    let rr = (p.y - r.y) * (q.x - r.x);
    (l - rr, l.abs() + rr.abs())
}

fn cross_det(p: Point, q: Point, r: Point, s: Point) -> (f64, f64) {
    let l = (q.x - p.x) * (s.y - r.y);
    let rr = (q.y - p.y) * (s.x - r.x);
    (l - rr, l.abs() + rr.abs())
}

fn incircle_det(a: Point, b: Point, c: Point, d: Point) -> (f64, f64) {
    let (adx, ady) = (a.x - d.x, a.y - d.y);
    let (bdx, bdy) = (b.x - d.x, b.y - d.y);
    let (cdx, cdy) = (c.x - d.x, c.y - d.y);
    let alift = adx * adx + ady * ady;
    let blift = bdx * bdx + bdy * bdy;
    let clift = cdx * cdx + cdy * cdy;
    let bc = bdx * cdy - cdx * bdy;
    let ca = cdx * ady - adx * cdy;
    let ab = adx * bdy - bdx * ady;
    let det = alift * bc + blift * ca + clift * ab;
    let permanent = ((bdx * cdy).abs() + (cdx * bdy).abs()) * alift
        + ((cdx * ady).abs() + (adx * cdy).abs()) * blift
        + ((adx * bdy).abs() + (bdx * ady).abs()) * clift;
    (det, permanent)
}

/// The orientation a determinant's sign stands for (positive: left).
pub(crate) fn orientation_of(det: f64) -> Orientation {
    if det > 0.0 {
        Orientation::Left
    } else if det < 0.0 {
        Orientation::Right
    } else {
        Orientation::Collinear
    }
}

fn circle_side_of(det: f64) -> CircleSide {
    if det > 0.0 {
        CircleSide::Inside
    } else if det < 0.0 {
        CircleSide::Outside
    } else {
        CircleSide::On
    }
}

const EPS: f64 = f64::EPSILON * 0.5;
// Shewchuk, "Adaptive precision floating-point arithmetic and fast robust
// geometric predicates" (1997): bounds for the first, non-adaptive stage.
const ORIENT_ERRBOUND: f64 = (3.0 + 16.0 * EPS) * EPS;
const INCIRCLE_ERRBOUND: f64 = (10.0 + 96.0 * EPS) * EPS;

impl Kernel for FloatKernel {
    fn orientation(&self, p: Point, q: Point, r: Point) -> Orientation {
        orientation_of(orient_det(p, q, r).0)
    }

    fn circle_side(&self, a: Point, b: Point, c: Point, d: Point) -> CircleSide {
        circle_side_of(incircle_det(a, b, c, d).0)
    }

    fn cross_sign(&self, p: Point, q: Point, r: Point, s: Point) -> Orientation {
        orientation_of(cross_det(p, q, r, s).0)
    }
}

impl Kernel for FilteredKernel {
    fn orientation(&self, p: Point, q: Point, r: Point) -> Orientation {
        let (det, sum) = orient_det(p, q, r);
        // The bound is only valid when no intermediate overflowed or
        // underflowed to a subnormal; the exact path has no such limits.
        if det.abs() > ORIENT_ERRBOUND * sum && sum.is_finite() && sum > f64::MIN_POSITIVE * 1e20 {
            return orientation_of(det);
        }
        fallback::orientation(p, q, r)
    }

    fn circle_side(&self, a: Point, b: Point, c: Point, d: Point) -> CircleSide {
        let (det, permanent) = incircle_det(a, b, c, d);
        if det.abs() > INCIRCLE_ERRBOUND * permanent && permanent.is_finite() && permanent > f64::MIN_POSITIVE * 1e40 {
            return circle_side_of(det);
        }
        fallback::circle_side(a, b, c, d)
    }

    fn cross_sign(&self, p: Point, q: Point, r: Point, s: Point) -> Orientation {
        // Two differences, two products, one difference: the terms of
        // the orientation determinant, so its bound holds.
        let (det, sum) = cross_det(p, q, r, s);
        if det.abs() > ORIENT_ERRBOUND * sum && sum.is_finite() && sum > f64::MIN_POSITIVE * 1e20 {
            return orientation_of(det);
        }
        fallback::cross_sign(p, q, r, s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filtered_orientation_is_exact_on_near_collinear_points() {
        // Kettner et al., "Classroom examples of robustness problems in
        // geometric computations": p near (0.5, 0.5) moved by ulps, q and r
        // on the diagonal. Plain f64 gets many signs wrong here.
        let k = FilteredKernel;
        let q = Point::new(12.0, 12.0);
        let r = Point::new(24.0, 24.0);
        let u = f64::EPSILON / 2.0;
        let mut disagreements_float = 0;
        for i in 0..256 {
            for j in 0..256 {
                let p = Point::new(0.5 + i as f64 * u, 0.5 + j as f64 * u);
                let exact = exact_int::orientation(p, q, r);
                assert_eq!(k.orientation(p, q, r), exact, "at {i},{j}");
                if FloatKernel.orientation(p, q, r) != exact {
                    disagreements_float += 1;
                }
            }
        }
        // The test set is only meaningful if plain floats fail on it.
        assert!(disagreements_float > 0);
    }

    #[test]
    fn circle_side_of_cocircular_points_is_on() {
        let k = FilteredKernel;
        let a = Point::new(1.0, 0.0);
        let b = Point::new(0.0, 1.0);
        let c = Point::new(-1.0, 0.0);
        assert_eq!(k.circle_side(a, b, c, Point::new(0.0, -1.0)), CircleSide::On);
        assert_eq!(k.circle_side(a, b, c, Point::new(0.0, 0.0)), CircleSide::Inside);
        assert_eq!(k.circle_side(a, b, c, Point::new(2.0, 0.0)), CircleSide::Outside);
        assert_eq!(k.circle_side(a, b, c, Point::new(0.6, 0.8)), exact_int::circle_side(a, b, c, Point::new(0.6, 0.8)));
    }
}
