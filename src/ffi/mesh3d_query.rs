//! Queries of a solid from C (issue 19): which side of the surface a point
//! lies on (exact), the closest surface point, and the largest ball
//! `c + r·B` at a centre under a space ball, one point or many at once.

use super::ball::mx_ball;
use super::boundary::{batch_room, check_out, fill_items, guard, slice};
use super::handles::{arg, query};
use super::last_error::FfiError;
use super::mesh3d::mx_mesh3d;
use super::status::mx_status;
use crate::kernel::Point3;
use crate::shape::{ContactKind3, Mesh3d, Reach};

/// Where a point lies relative to a solid.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_point_side {
    /// Outside the material (a cavity is outside).
    MX_OUTSIDE = 0,
    /// Inside the material.
    MX_INSIDE = 1,
    /// Exactly on the surface.
    MX_ON_SURFACE = 2,
}

/// The contact type of a ball touching a surface (thesis 3.1.2).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_contact3_kind {
    /// A vertex of the ball on a triangle's interior (VF).
    MX_CONTACT3_VF = 0,
    /// An edge of the ball on an edge of a triangle (EE).
    MX_CONTACT3_EE = 1,
    /// A vertex of the surface on a ball facet (FV; from the `f64` queries
    /// any point of the ball's boundary).
    MX_CONTACT3_FV = 2,
    /// A vertex of the ball on an edge of the surface (VE; exact queries).
    MX_CONTACT3_VE = 3,
    /// A vertex of the surface on an edge of the ball (EV; exact queries).
    MX_CONTACT3_EV = 4,
    /// A vertex of the ball on a vertex of the surface (VV; exact queries).
    MX_CONTACT3_VV = 5,
}

/// Everything `mx_mesh3d_query_points` tells about one point.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_point_query3 {
    /// Inside, outside or on the surface (exact).
    pub side: mx_point_side,
    /// Euclidean distance to the surface.
    pub distance: f64,
    /// The closest surface point.
    pub closest: [f64; 3],
    /// The triangle it lies on.
    pub closest_triangle: usize,
    /// 1 when the ball fields hold an answer (a ball was given and the
    /// point is inside), else 0.
    pub has_ball: i32,
    /// The largest r with `point + r·B` inside the solid.
    pub ball_radius: f64,
    /// Where that ball touches the surface.
    pub contact: [f64; 3],
    /// The triangle it touches.
    pub contact_triangle: usize,
    /// The contact's type.
    pub contact_kind: mx_contact3_kind,
}

fn point_of(xyz: &[f64]) -> Result<Point3, FfiError> {
    point_arg(xyz, "a point")
}

/// The point in `xyz` (three doubles; `what` in errors): finite, else
/// `MX_ERR_NON_FINITE`. Shared by the solid's point arguments.
pub(super) fn point_arg(xyz: &[f64], what: &str) -> Result<Point3, FfiError> {
    if xyz.iter().any(|v| !v.is_finite()) {
        return Err(FfiError::new(mx_status::MX_ERR_NON_FINITE, format!("{what} has a NaN or infinite coordinate")));
    }
    Ok(Point3::new(xyz[0], xyz[1], xyz[2]))
}

/// The prologue of a buffer query of a solid under a space ball: `count`
/// writable, `mesh` live, `ball` a live space ball.
///
/// # Safety
/// `mesh` and `ball` NULL or live handles.
pub(super) unsafe fn solid_and_ball<'a>(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    count: *mut usize,
) -> Result<(&'a mx_mesh3d, &'a crate::shape::Ball3), FfiError> {
    check_out(count, "count")?;
    // SAFETY: forwarded contract.
    let m = unsafe { arg(mesh)? };
    // SAFETY: forwarded contract.
    Ok((m, unsafe { arg(ball)? }.as_space()?))
}

pub(super) fn kind_of(k: ContactKind3) -> mx_contact3_kind {
    match k {
        ContactKind3::VertexFace => mx_contact3_kind::MX_CONTACT3_VF,
        ContactKind3::EdgeEdge => mx_contact3_kind::MX_CONTACT3_EE,
        ContactKind3::FaceVertex => mx_contact3_kind::MX_CONTACT3_FV,
        ContactKind3::VertexEdge => mx_contact3_kind::MX_CONTACT3_VE,
        ContactKind3::EdgeVertex => mx_contact3_kind::MX_CONTACT3_EV,
        ContactKind3::VertexVertex => mx_contact3_kind::MX_CONTACT3_VV,
    }
}

/// `ball` prepared once per call (for many points, once for all).
fn answer(m: &Mesh3d, ball: Option<&Reach<'_>>, p: Point3) -> mx_point_query3 {
    let side = match m.inside(p) {
        Some(true) => mx_point_side::MX_INSIDE,
        Some(false) => mx_point_side::MX_OUTSIDE,
        None => mx_point_side::MX_ON_SURFACE,
    };
    let closest = m.tree().closest_point(p).expect("a valid solid has triangles");
    let mut q = mx_point_query3 {
        side,
        distance: closest.squared_distance.sqrt(),
        closest: closest.point.to_array(),
        closest_triangle: closest.triangle as usize,
        has_ball: 0,
        ball_radius: 0.0,
        contact: [0.0; 3],
        contact_triangle: 0,
        contact_kind: mx_contact3_kind::MX_CONTACT3_FV,
    };
    if let (Some(b), mx_point_side::MX_INSIDE) = (ball, side) {
        let c = m.tree().ball_radius_with(p, b).expect("a valid solid has triangles");
        q.has_ball = 1;
        q.ball_radius = c.radius;
        q.contact = c.point.to_array();
        q.contact_triangle = c.triangle as usize;
        q.contact_kind = kind_of(c.kind);
    }
    q
}

/// Where `point` (three doubles) lies: inside, outside or on the surface,
/// decided exactly.
///
/// # Safety
/// `mesh` NULL or a live handle; `point` NULL or three readable doubles;
/// `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_side(
    mesh: *const mx_mesh3d,
    point: *const f64,
    out: *mut mx_point_side,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let p = point_of(slice(point, 3, "point")?)?;
            Ok(answer(&m.inner, None, p).side)
        })
    }
}

/// One point's answers (`mx_point_query3`): side, closest point and, with
/// `ball` (a space ball; NULL for none), the largest ball at the point.
///
/// # Safety
/// `mesh` NULL or a live handle; `ball` NULL or a live handle; `point`
/// NULL or three readable doubles; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_query_point(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    point: *const f64,
    out: *mut mx_point_query3,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        query(mesh, out, |m| {
            let b = if ball.is_null() { None } else { Some(arg(ball)?.as_space()?) };
            let p = point_of(slice(point, 3, "point")?)?;
            Ok(answer(&m.inner, b.map(|b| b.reach()).as_ref(), p))
        })
    }
}

/// The answers for `xyz_len / 3` points at once (in parallel), into
/// `answers` of `capacity` entries, their number in `*count` (capacity 0: a size
/// query; a shorter buffer: `MX_ERR_BUFFER_TOO_SMALL`, nothing written).
/// A NaN point fails the call naming it.
///
/// # Safety
/// `mesh` NULL or a live handle; `ball` NULL or a live handle; `xyz` NULL
/// (only when `xyz_len` is 0) or `xyz_len` readable doubles; `answers`
/// NULL or `capacity` writable entries; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_query_points(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    xyz: *const f64,
    xyz_len: usize,
    answers: *mut mx_point_query3,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        check_out(count, "count")?;
        // SAFETY: caller contract.
        let m = unsafe { arg(mesh)? };
        // SAFETY: caller contract.
        let b = if ball.is_null() { None } else { Some(unsafe { arg(ball)? }.as_space()?) };
        if xyz_len % 3 != 0 {
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("xyz_len = {xyz_len} is not a multiple of 3"),
            ));
        }
        // SAFETY: caller contract.
        let xyz = unsafe { slice(xyz, xyz_len, "xyz")? };
        let n = xyz_len / 3;
        // SAFETY: `count` checked non-NULL above.
        if !unsafe { batch_room(answers, (capacity, count), n, "points")? } {
            return Ok(());
        }
        let points = xyz
            .chunks_exact(3)
            .enumerate()
            .map(|(i, c)| {
                point_of(c).map_err(|_| {
                    FfiError::new(mx_status::MX_ERR_NON_FINITE, format!("point {i} has a NaN or infinite coordinate"))
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let reach = b.map(|b| b.reach());
        let found = m.inner.tree().batch_by(&points, |&p| p, |&p| answer(&m.inner, reach.as_ref(), p));
        // SAFETY: caller contract (`capacity` ≥ n writable entries).
        unsafe { fill_items((answers, "answers"), (capacity, count), (n, 1), found, String::new) }
    })
}
