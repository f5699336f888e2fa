//! `mx_ball`: the unit ball that defines a distance (thesis chapter 3):
//! plane balls (convex polygons, this file) and space balls (convex
//! polytopes, `ball3.rs`) in one handle, told apart by `mx_ball_dimension`.

use super::boundary::{c_str, fill_items, slice};
use super::handles::{arg, create, free, query, Handle};
use super::last_error::FfiError;
use super::status::mx_status;
use crate::kernel::Point;
use crate::shape::{Ball2, Ball3};
use std::ffi::c_char;

/// A unit ball: a convex polygon (plane) or polytope (space) holding the
/// origin strictly inside. Immutable; may be shared between threads.
pub struct mx_ball {
    pub(crate) inner: BallKind,
}

/// The ball of one dimension or the other.
pub(crate) enum BallKind {
    Plane(Ball2),
    Space(Ball3),
}

impl mx_ball {
    pub(crate) fn plane(b: Ball2) -> mx_ball {
        mx_ball { inner: BallKind::Plane(b) }
    }

    pub(crate) fn space(b: Ball3) -> mx_ball {
        mx_ball { inner: BallKind::Space(b) }
    }

    /// The plane ball, or the error a space ball gets where a plane
    /// ball is needed.
    pub(crate) fn as_plane(&self) -> Result<&Ball2, FfiError> {
        match &self.inner {
            BallKind::Plane(b) => Ok(b),
            BallKind::Space(_) => Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                "ball: a 3D ball (polytope) where a plane ball (polygon) is needed",
            )),
        }
    }

    /// The space ball, or the error a plane ball gets where a space ball
    /// is needed.
    pub(crate) fn as_space(&self) -> Result<&Ball3, FfiError> {
        match &self.inner {
            BallKind::Space(b) => Ok(b),
            BallKind::Plane(_) => Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                "ball: a plane ball (polygon) where a 3D ball (polytope) is needed",
            )),
        }
    }
}

impl Handle for mx_ball {
    const ARG: &'static str = "ball";
    type Ownership = super::handles::Boxed;
}

/// A plane ball from `count` vertices `xy` (x0, y0, x1, y1, …, either
/// orientation, unitless). A polygon that is not a ball (fewer than 3
/// vertices, NaN, a repeated or collinear vertex, not convex, the origin
/// not strictly inside) gives `MX_ERR_INVALID_BALL`, the vertex in
/// `mx_last_error_info`'s `element`.
///
/// # Safety
/// `xy` NULL (only when `count` is 0) or `2 * count` readable doubles;
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_from_vertices2(xy: *const f64, count: usize, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let xy = slice(xy, count.saturating_mul(2), "xy")?;
            let vertices: Vec<Point> = xy.chunks_exact(2).map(|c| Point::new(c[0], c[1])).collect();
            Ok(mx_ball::plane(Ball2::new(&vertices)?))
        })
    }
}

/// The ball a NUL-terminated UTF-8 description names: `square`,
/// `diamond`, `triangle`, `ngon:K[:DEGREES]`, or ball JSON `{"vertices":
/// [[x, y], ...]}` (as the command line's `--ball`). JSON that does not
/// parse gives `MX_ERR_PARSE` with its line and column, a description that
/// names no ball `MX_ERR_INVALID_ARGUMENT`, a polygon that is no ball
/// `MX_ERR_INVALID_BALL`.
///
/// # Safety
/// `text` NULL or NUL-terminated; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_parse(text: *const c_char, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let text = c_str(text, "text")?;
            Ok(mx_ball::plane(Ball2::parse(text)?))
        })
    }
}

/// The regular polygon of `k` vertices (3 to 100 000) on the unit circle,
/// the first at angle `rotation` radians (`MX_ERR_INVALID_ARGUMENT`
/// otherwise).
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_regular(k: usize, rotation: f64, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::plane(Ball2::regular(k, rotation)?))) }
}

/// The square [−1, 1]²: the L∞ distance.
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_square(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::plane(Ball2::square()))) }
}

/// The diamond |x| + |y| ≤ 1: the L1 distance.
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_diamond(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::plane(Ball2::diamond()))) }
}

/// The equilateral triangle of circumradius 1, a vertex straight up: the
/// simplest ball that is not symmetric.
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_triangle(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::plane(Ball2::triangle()))) }
}

/// A new ball, the mirror image −B of `ball`: distances under it run the
/// other way (δ_{−B}(p, q) = δ_B(q, p)).
///
/// # Safety
/// `ball` NULL or a live handle; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_mirrored(ball: *const mx_ball, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            Ok(match &arg(ball)?.inner {
                BallKind::Plane(b) => mx_ball::plane(b.mirrored()),
                BallKind::Space(b) => mx_ball::space(b.mirrored()),
            })
        })
    }
}

/// Frees a ball; NULL is fine.
///
/// # Safety
/// `ball` NULL or a live handle, not used afterwards.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_free(ball: *mut mx_ball) {
    // SAFETY: forwarded contract.
    unsafe { free(ball) }
}

/// The ball's dimension: 2 (a polygon) or 3 (a polytope).
///
/// # Safety
/// `ball` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_dimension(ball: *const mx_ball, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(ball, out, |b| {
            Ok(match b.inner {
                BallKind::Plane(_) => 2,
                BallKind::Space(_) => 3,
            })
        })
    }
}

/// The number of vertices.
///
/// # Safety
/// `ball` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_vertex_count(ball: *const mx_ball, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(ball, out, |b| {
            Ok(match &b.inner {
                BallKind::Plane(b) => b.len(),
                BallKind::Space(b) => b.vertices().len(),
            })
        })
    }
}

/// Copies the vertices into `xy` of `capacity` vertices and writes their
/// number to `*count`: a plane ball's counter-clockwise as x0, y0, x1, y1,
/// …; a space ball's as x0, y0, z0, … (`mx_ball_dimension` numbers each).
/// Size query: `capacity` 0 (`xy` may be NULL) writes only `*count`; a
/// shorter buffer gives `MX_ERR_BUFFER_TOO_SMALL` with nothing written.
///
/// # Safety
/// `ball` NULL or a live handle; `xy` NULL or `dimension * capacity`
/// writable doubles; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_vertices(
    ball: *const mx_ball,
    xy: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    super::boundary::guard(|| {
        // SAFETY: caller contract.
        let b = unsafe { arg(ball)? };
        let (n, dim, coords): (usize, usize, Vec<f64>) = match &b.inner {
            BallKind::Plane(b) => (b.len(), 2, b.vertices().iter().flat_map(|v| [v.x, v.y]).collect()),
            BallKind::Space(b) => (b.vertices().len(), 3, b.vertices().iter().flat_map(|v| v.to_array()).collect()),
        };
        // SAFETY: caller contract.
        unsafe {
            fill_items((xy, "xy"), (capacity, count), (n, dim), coords, || {
                format!("the ball has {n} vertices, the buffer room for {capacity}")
            })
        }
    })
}

/// δ_B(from, to): the least r with `to` in `from + r·B` (model units; not
/// symmetric unless the ball is).
///
/// # Safety
/// `ball` NULL or a live handle; `from`, `to` NULL or two readable doubles;
/// `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_distance2(
    ball: *const mx_ball,
    from: *const f64,
    to: *const f64,
    out: *mut f64,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(ball, out, |b| {
            let (from, to) = (slice(from, 2, "from")?, slice(to, 2, "to")?);
            if from.iter().chain(to).any(|v| !v.is_finite()) {
                return Err(FfiError::new(mx_status::MX_ERR_NON_FINITE, "a point has a NaN or infinite coordinate"));
            }
            Ok(b.as_plane()?.distance(Point::new(from[0], from[1]), Point::new(to[0], to[1])))
        })
    }
}

/// 1 when the ball is symmetric (−B = B exactly: δ_B is then a metric),
/// else 0.
///
/// # Safety
/// `ball` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_is_symmetric(ball: *const mx_ball, out: *mut i32) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(ball, out, |b| {
            Ok(i32::from(match &b.inner {
                BallKind::Plane(b) => b.is_symmetric(),
                BallKind::Space(b) => b.is_symmetric(),
            }))
        })
    }
}
