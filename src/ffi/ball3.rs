//! `mx_ball` in space: convex polytopes as unit balls (thesis 3.1,
//! Definition 3.1.4), from points (their convex hull, exact), a mesh file's
//! vertices, or presets; their facets and the distance they define.

use super::ball::mx_ball;
use super::boundary::{c_str, slice};
use super::handles::{arg, create, query};
use super::last_error::FfiError;
use super::status::mx_status;
use crate::io::mesh::{read_mesh, MeshFormat};
use crate::kernel::Point3;
use crate::shape::Ball3;
use std::ffi::c_char;

/// A space ball: the convex hull of `xyz_len / 3` points `xyz` (x, y, z
/// each), which must hold the origin strictly inside (its own coordinates
/// are kept: the origin is where the caller put it, so the distance may be
/// a quasi-metric). Points inside the hull or on its boundary but not at a
/// corner are dropped. Fewer than 4 points, a NaN, all points on one plane
/// or the origin on or outside the hull give `MX_ERR_INVALID_BALL`.
///
/// # Safety
/// `xyz` NULL (only when `xyz_len` is 0) or `xyz_len` readable doubles;
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_from_points3(xyz: *const f64, xyz_len: usize, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            if xyz_len % 3 != 0 {
                return Err(FfiError::new(
                    mx_status::MX_ERR_INVALID_ARGUMENT,
                    format!("xyz_len = {xyz_len} is not a multiple of 3"),
                ));
            }
            let xyz = slice(xyz, xyz_len, "xyz")?;
            let points: Vec<Point3> = xyz.chunks_exact(3).map(|c| Point3::new(c[0], c[1], c[2])).collect();
            Ok(mx_ball::space(Ball3::from_points(&points)?))
        })
    }
}

/// A space ball: the convex hull of the vertices of a mesh file (OBJ, OFF,
/// STL, PLY; `format` an `mx_format`, `MX_FORMAT_AUTO` by extension), as
/// `mx_ball_from_points3`. The file's faces are not used.
///
/// # Safety
/// `path` NULL or NUL-terminated UTF-8; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_from_file3(path: *const c_char, format: u32, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let path = std::path::Path::new(c_str(path, "path")?);
            let format = super::shape_kinds::mesh_format_of(format)?.or_else(|| MeshFormat::from_path(path));
            let bytes = std::fs::read(path)
                .map_err(|e| FfiError::new(mx_status::MX_ERR_IO, format!("cannot read {}: {e}", path.display())))?;
            let raw = read_mesh(&bytes, format)
                .map_err(|e| FfiError::new(mx_status::MX_ERR_PARSE, format!("{}: {e}", path.display())))?;
            let points: Vec<Point3> = raw.positions.iter().map(|&p| Point3::from_array(p)).collect();
            Ok(mx_ball::space(Ball3::from_points(&points)?))
        })
    }
}

/// The regular tetrahedron with corners at alternate corners of [−1, 1]³.
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_tetrahedron(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::space(Ball3::tetrahedron()))) }
}

/// The cube [−1, 1]³ (the L∞ distance).
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_cube(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::space(Ball3::cube()))) }
}

/// The octahedron with corners ±1 on the axes (the L1 distance).
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_octahedron(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::space(Ball3::octahedron()))) }
}

/// The regular icosahedron with corners (0, ±1, ±φ) and their cyclic
/// permutations.
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_icosahedron(out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::space(Ball3::icosahedron()))) }
}

/// A geodesic sphere: the icosahedron subdivided into at least `facets`
/// triangles (20·4^k, k ≤ 5), its corners on the unit sphere; a polytope
/// approaching the Euclidean ball.
///
/// # Safety
/// `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_geodesic(facets: usize, out: *mut *mut mx_ball) -> mx_status {
    // SAFETY: caller contract.
    unsafe { create(out, || Ok(mx_ball::space(Ball3::geodesic(facets)?))) }
}

/// A new space ball: `ball` turned about the axis `rotation` (three
/// doubles: its direction is the axis, its length the angle in radians,
/// counter-clockwise looking down the axis).
///
/// # Safety
/// `ball` NULL or a live handle; `rotation` NULL or three readable
/// doubles; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_rotated3(
    ball: *const mx_ball,
    rotation: *const f64,
    out: *mut *mut mx_ball,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let b = arg(ball)?.as_space()?;
            let r = slice(rotation, 3, "rotation")?;
            Ok(mx_ball::space(b.rotated([r[0], r[1], r[2]])?))
        })
    }
}

/// The number of facets of a space ball (coplanar triangles of the hull
/// are one facet).
///
/// # Safety
/// `ball` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_facet_count(ball: *const mx_ball, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(ball, out, |b| Ok(b.as_space()?.facets().len())) }
}

/// δ_B(from, to) in space: the least r with `to` in `from + r·B` (model
/// units; not symmetric unless the ball is).
///
/// # Safety
/// `ball` NULL or a live handle; `from`, `to` NULL or three readable
/// doubles; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_distance3(
    ball: *const mx_ball,
    from: *const f64,
    to: *const f64,
    out: *mut f64,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(ball, out, |b| {
            let b = b.as_space()?;
            let (from, to) = (slice(from, 3, "from")?, slice(to, 3, "to")?);
            if from.iter().chain(to).any(|v| !v.is_finite()) {
                return Err(FfiError::new(mx_status::MX_ERR_NON_FINITE, "a point has a NaN or infinite coordinate"));
            }
            Ok(b.distance(Point3::new(from[0], from[1], from[2]), Point3::new(to[0], to[1], to[2])))
        })
    }
}
