//! Rays and intersection tests of a solid's surface from C (issue 19):
//! the first hit of a ray (`f64`), one or many at once, and whether a
//! closed segment, triangle or box meets the surface (exact).

use super::boundary::{batch_room, check_out, fill_items, guard, slice};
use super::handles::{arg, query};
use super::last_error::FfiError;
use super::mesh3d::mx_mesh3d;
use super::mesh3d_query::point_arg;
use super::status::mx_status;
use crate::kernel::{BBox3, Point3};
use crate::shape::Hit;

/// Where a ray first meets a solid's surface
/// (`mx_mesh3d_first_hit`, `mx_mesh3d_first_hits`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_ray_hit3 {
    /// 1 when the ray meets the surface, else 0 (then `t`, `point` and
    /// `triangle` are 0).
    pub hit: i32,
    /// Ray parameter, ≥ 0: the point is `origin + t·direction` (a distance
    /// only for a unit direction).
    pub t: f64,
    /// The point hit.
    pub point: [f64; 3],
    /// The triangle hit (as numbered by `mx_mesh3d_triangles`); where the
    /// ray passes through an edge or a corner, one of the triangles there.
    pub triangle: usize,
}

impl mx_ray_hit3 {
    fn of(h: Option<Hit>) -> mx_ray_hit3 {
        match h {
            Some(h) => mx_ray_hit3 { hit: 1, t: h.t, point: h.point.to_array(), triangle: h.triangle as usize },
            None => mx_ray_hit3 { hit: 0, t: 0.0, point: [0.0; 3], triangle: 0 },
        }
    }
}

/// A direction (`what` in errors): not zero.
fn nonzero(d: Point3, what: &str) -> Result<Point3, FfiError> {
    if d == Point3::new(0.0, 0.0, 0.0) {
        return Err(FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("{what} is zero")));
    }
    Ok(d)
}

/// Where the ray `origin + t·direction`, `t ≥ 0`, first meets the surface
/// (edges and corners included), computed in `f64`; `out->hit` is 0 when
/// it misses. A NaN or infinite number gives `MX_ERR_NON_FINITE`, a zero
/// direction `MX_ERR_INVALID_ARGUMENT`.
///
/// # Safety
/// `mesh` NULL or a live handle; `origin` and `direction` NULL or three
/// readable doubles each; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_first_hit(
    mesh: *const mx_mesh3d,
    origin: *const f64,
    direction: *const f64,
    out: *mut mx_ray_hit3,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let o = point_arg(slice(origin, 3, "origin")?, "`origin`")?;
            let d = nonzero(point_arg(slice(direction, 3, "direction")?, "`direction`")?, "`direction`")?;
            Ok(mx_ray_hit3::of(m.inner.tree().first_hit(o, d)))
        })
    }
}

/// The first hits of `rays_len / 6` rays at once (in parallel), each
/// given by six numbers: origin x, y, z and direction x, y, z. Into `hits`
/// of `capacity` entries, their number in `*count` (capacity 0: a size
/// query; a shorter buffer: `MX_ERR_BUFFER_TOO_SMALL`, nothing written).
/// A NaN or infinite number (`MX_ERR_NON_FINITE`) or a zero direction
/// (`MX_ERR_INVALID_ARGUMENT`) fails the call naming the ray.
///
/// # Safety
/// `mesh` NULL or a live handle; `rays` NULL (only when `rays_len` is 0)
/// or `rays_len` readable doubles; `hits` NULL or `capacity` writable
/// entries; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_first_hits(
    mesh: *const mx_mesh3d,
    rays: *const f64,
    rays_len: usize,
    hits: *mut mx_ray_hit3,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        check_out(count, "count")?;
        // SAFETY: caller contract.
        let m = unsafe { arg(mesh)? };
        if rays_len % 6 != 0 {
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("rays_len = {rays_len} is not a multiple of 6 (origin and direction per ray)"),
            ));
        }
        // SAFETY: caller contract.
        let rays = unsafe { slice(rays, rays_len, "rays")? };
        let n = rays_len / 6;
        // SAFETY: `count` checked non-NULL above.
        if !unsafe { batch_room(hits, (capacity, count), n, "rays")? } {
            return Ok(());
        }
        let rays = rays
            .chunks_exact(6)
            .enumerate()
            .map(|(i, six)| {
                let what = format!("ray {i}");
                Ok((
                    point_arg(&six[..3], &what)?,
                    nonzero(point_arg(&six[3..], &what)?, &format!("{what}: the direction"))?,
                ))
            })
            .collect::<Result<Vec<_>, FfiError>>()?;
        let found = m.inner.tree().first_hits(&rays).into_iter().map(mx_ray_hit3::of);
        // SAFETY: caller contract (`capacity` ≥ n writable entries).
        unsafe { fill_items((hits, "hits"), (capacity, count), (n, 1), found, String::new) }
    })
}

/// Whether the closed segment from `a` to `b` (three doubles each) meets
/// the surface, exactly (touching counts; `a` = `b` asks about a point):
/// `*out` 1 or 0. A NaN or infinite number gives `MX_ERR_NON_FINITE`.
///
/// # Safety
/// `mesh` NULL or a live handle; `a` and `b` NULL or three readable
/// doubles each; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_intersects_segment(
    mesh: *const mx_mesh3d,
    a: *const f64,
    b: *const f64,
    out: *mut i32,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let a = point_arg(slice(a, 3, "a")?, "`a`")?;
            let b = point_arg(slice(b, 3, "b")?, "`b`")?;
            Ok(i32::from(m.inner.tree().intersects_segment(a, b)))
        })
    }
}

/// Whether the closed triangle with corners `xyz9` (x, y, z of each of
/// three corners) meets the surface, exactly (touching counts): `*out` 1
/// or 0. Corners on one line ask about the segment they span, three equal
/// corners about a point. A NaN or infinite number gives
/// `MX_ERR_NON_FINITE`.
///
/// # Safety
/// `mesh` NULL or a live handle; `xyz9` NULL or nine readable doubles;
/// `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_intersects_triangle(
    mesh: *const mx_mesh3d,
    xyz9: *const f64,
    out: *mut i32,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let xyz = slice(xyz9, 9, "xyz9")?;
            let c = |i: usize| point_arg(&xyz[3 * i..3 * i + 3], &format!("`xyz9` corner {i}"));
            Ok(i32::from(m.inner.tree().intersects_triangle([c(0)?, c(1)?, c(2)?])))
        })
    }
}

/// Whether the closed axis-aligned box from `min` to `max` (three doubles
/// each, `min[k] ≤ max[k]`; equal bounds make a flat box) meets the
/// surface, exactly (touching counts): `*out` 1 or 0. A NaN or infinite
/// number gives `MX_ERR_NON_FINITE`, `min[k] > max[k]`
/// `MX_ERR_INVALID_ARGUMENT`.
///
/// # Safety
/// `mesh` NULL or a live handle; `min` and `max` NULL or three readable
/// doubles each; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_intersects_box(
    mesh: *const mx_mesh3d,
    min: *const f64,
    max: *const f64,
    out: *mut i32,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let lo = point_arg(slice(min, 3, "min")?, "`min`")?;
            let hi = point_arg(slice(max, 3, "max")?, "`max`")?;
            if let Some(k) = (0..3).find(|&k| lo.coord(k) > hi.coord(k)) {
                return Err(FfiError::new(
                    mx_status::MX_ERR_INVALID_ARGUMENT,
                    format!("min[{k}] = {} exceeds max[{k}] = {}", lo.coord(k), hi.coord(k)),
                ));
            }
            Ok(i32::from(m.inner.tree().intersects_box(&BBox3 { min: lo, max: hi })))
        })
    }
}
