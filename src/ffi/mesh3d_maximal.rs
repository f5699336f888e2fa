//! Maximal* balls of a solid from C (issue 19, thesis 3.3.2.2): the
//! largest ball `c + r·B` whose vertex `ṽ` sits at a given point, grown
//! about that point until it touches the surface elsewhere; one point or
//! many at once.

use super::ball::mx_ball;
use super::boundary::{batch_room, fill_items, guard, slice};
use super::handles::{arg, query};
use super::last_error::FfiError;
use super::mesh3d::mx_mesh3d;
use super::mesh3d_query::{kind_of, mx_contact3_kind, point_arg, solid_and_ball};
use super::status::mx_status;
use crate::kernel::Point3;
use crate::shape::{Ball3, MaximalBall, Mesh3d, Reach};

/// A maximal* ball (`mx_mesh3d_maximal_ball`): `centre + radius·B`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_maximal_ball3 {
    /// Its radius: 0 when the vertex's cone straddles the surface at the
    /// point, `INFINITY` when the ball grows without bound (outside the
    /// solid).
    pub radius: f64,
    /// Its centre, `point − radius·ṽ` (the point itself when unbounded).
    pub centre: [f64; 3],
    /// 1 when a contact stopped its growth (the fields below), 0 when
    /// unbounded.
    pub has_opposite: i32,
    /// The triangle of that contact.
    pub opposite_triangle: usize,
    /// Where the ball touches it.
    pub opposite_point: [f64; 3],
    /// The contact's type.
    pub opposite_kind: mx_contact3_kind,
}

fn vertex_in(ball: &Ball3, vertex: usize, what: &str) -> Result<(), FfiError> {
    if vertex >= ball.vertices().len() {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("{what} = {vertex}: the ball has {} vertices", ball.vertices().len()),
        ));
    }
    Ok(())
}

fn to_c(b: MaximalBall) -> mx_maximal_ball3 {
    let mut out = mx_maximal_ball3 {
        radius: b.radius,
        centre: b.centre.to_array(),
        has_opposite: 0,
        opposite_triangle: 0,
        opposite_point: [0.0; 3],
        opposite_kind: mx_contact3_kind::MX_CONTACT3_FV,
    };
    if let Some(o) = b.opposite {
        out.has_opposite = 1;
        out.opposite_triangle = o.triangle as usize;
        out.opposite_point = o.point.to_array();
        out.opposite_kind = kind_of(o.kind);
    }
    out
}

/// The ball for a checked vertex; `None` only when coordinates are so
/// large that the first ball's radius overflows.
fn maximal(m: &Mesh3d, reach: &Reach<'_>, p: Point3, vertex: usize) -> Result<mx_maximal_ball3, FfiError> {
    m.tree().maximal_ball_with(p, vertex, reach).map(to_c).ok_or_else(|| {
        FfiError::new(
            mx_status::MX_ERR_NON_FINITE,
            "the point and the solid are too large for a ball's radius (overflow)",
        )
    })
}

/// The maximal* ball under `ball` (a space ball) whose vertex `vertex`
/// (an index into `mx_ball_vertices`) sits at `point` (three doubles,
/// usually a surface point): the ball grows about `point` until it
/// touches the surface elsewhere. It lies on the side of the surface the
/// vertex points to.
///
/// # Safety
/// `mesh` and `ball` NULL or live handles; `point` NULL or three readable
/// doubles; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_maximal_ball(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    point: *const f64,
    vertex: usize,
    out: *mut mx_maximal_ball3,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let b = arg(ball)?.as_space()?;
            let p = point_arg(slice(point, 3, "point")?, "`point`")?;
            vertex_in(b, vertex, "vertex")?;
            maximal(&m.inner, &b.reach(), p, vertex)
        })
    }
}

/// Maximal* balls for `xyz_len / 3` points at once (in parallel), point
/// `i` with ball vertex `vertices[i]` (`vertices_len` = the number of
/// points), into `balls` of `capacity` entries, their number in `*count`
/// (capacity 0: a size query, which checks only the lengths; a shorter
/// buffer: `MX_ERR_BUFFER_TOO_SMALL`, nothing written). A NaN point or a
/// vertex out of range fails the call naming it.
///
/// # Safety
/// `mesh` and `ball` NULL or live handles; `xyz` NULL (only when
/// `xyz_len` is 0) or `xyz_len` readable doubles; `vertices` likewise with
/// `vertices_len` entries; `balls` NULL or `capacity` writable entries;
/// `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_maximal_balls(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    xyz: *const f64,
    xyz_len: usize,
    vertices: *const usize,
    vertices_len: usize,
    balls: *mut mx_maximal_ball3,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let (m, b) = unsafe { solid_and_ball(mesh, ball, count)? };
        if xyz_len % 3 != 0 || vertices_len != xyz_len / 3 {
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("xyz_len = {xyz_len} and vertices_len = {vertices_len}: want 3 numbers and 1 vertex per point"),
            ));
        }
        // SAFETY: caller contract.
        let (xyz, vertices) = unsafe { (slice(xyz, xyz_len, "xyz")?, slice(vertices, vertices_len, "vertices")?) };
        let n = vertices_len;
        // SAFETY: `count` checked non-NULL above.
        if !unsafe { batch_room(balls, (capacity, count), n, "points")? } {
            return Ok(());
        }
        let mut asked = Vec::with_capacity(n);
        for (i, (c, &v)) in xyz.chunks_exact(3).zip(vertices).enumerate() {
            let p = point_arg(c, &format!("point {i}"))?;
            vertex_in(b, v, &format!("vertices[{i}]"))?;
            asked.push((p, v));
        }
        let reach = b.reach();
        let found = m.inner.tree().batch_by(&asked, |a| a.0, |&(p, v)| maximal(&m.inner, &reach, p, v));
        let found = found.into_iter().collect::<Result<Vec<_>, _>>()?;
        // SAFETY: caller contract (`capacity` ≥ n writable entries).
        unsafe { fill_items((balls, "balls"), (capacity, count), (n, 1), found, String::new) }
    })
}
