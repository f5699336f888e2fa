//! The largest ball at a centre with its contacts decided exactly, from C
//! (`TriangleTree::exact_contacts`): every contact with the least ball
//! and surface features holding it, so the non-regular types too.

use super::ball::mx_ball;
use super::boundary::{fill_items, guard, slice};
use super::last_error::FfiError;
use super::mesh3d::mx_mesh3d;
use super::mesh3d_query::{kind_of, mx_contact3_kind, point_arg, solid_and_ball};
use super::status::mx_status;
use crate::kernel::Point3;
use crate::shape::{ExactContact, Feature3, SurfacePart};

/// Which feature of a space ball holds a contact.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_ball_part3 {
    /// A vertex (an index into `mx_ball_vertices`).
    MX_BALL_VERTEX = 0,
    /// An edge (its index in the ball's edge list, sorted by end vertices).
    MX_BALL_EDGE = 1,
    /// A facet (its index in the ball's facet list).
    MX_BALL_FACET = 2,
}

/// Which feature of a solid's surface holds a contact.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_surface_part3 {
    /// A vertex.
    MX_SURFACE_VERTEX = 0,
    /// The inside of an edge.
    MX_SURFACE_EDGE = 1,
    /// The inside of a triangle.
    MX_SURFACE_FACE = 2,
}

/// One contact of the largest ball at a centre (`mx_mesh3d_ball_contacts`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_contact3 {
    /// The ball's radius (the exact value rounded; the same in every
    /// contact of one call).
    pub radius: f64,
    /// The ball's centre (the point asked for the largest ball; for a
    /// maximal* ball `point − radius·ṽ`, the exact value rounded).
    pub centre: [f64; 3],
    /// The point of contact (the exact value rounded).
    pub point: [f64; 3],
    /// The contact type: VF, EE, FV or the non-regular VE, EV, VV.
    pub kind: mx_contact3_kind,
    /// The least feature of the ball holding the point.
    pub ball_part: mx_ball_part3,
    /// Its index (vertex, edge or facet of the ball).
    pub ball_part_index: usize,
    /// The least feature of the surface holding the point.
    pub surface_part: mx_surface_part3,
    /// Its vertices: a vertex twice, an edge's two ends (the lesser
    /// first), a face's first two corners (see `triangle`).
    pub surface_vertices: [usize; 2],
    /// A triangle holding the point (the least index among them).
    pub triangle: usize,
    /// 1 when the ball lies flat on a triangle holding the point (a ball
    /// edge or facet along it: the contact is a segment or polygon and the
    /// point one of its corners), else 0.
    pub flat: i32,
}

/// A ball feature as C sees it: its kind and index.
pub(super) fn ball_part_of(x: Feature3) -> (mx_ball_part3, usize) {
    match x {
        Feature3::Vertex(v) => (mx_ball_part3::MX_BALL_VERTEX, v),
        Feature3::Edge(e) => (mx_ball_part3::MX_BALL_EDGE, e),
        Feature3::Facet(f) => (mx_ball_part3::MX_BALL_FACET, f),
    }
}

fn to_c(x: &ExactContact, (radius, centre): (f64, Point3), corners: impl Fn(u32) -> [u32; 3]) -> mx_contact3 {
    let (ball_part, ball_part_index) = ball_part_of(x.ball);
    let (surface_part, surface_vertices) = match x.surface {
        SurfacePart::Vertex(v) => (mx_surface_part3::MX_SURFACE_VERTEX, [v as usize; 2]),
        SurfacePart::Edge([a, b]) => (mx_surface_part3::MX_SURFACE_EDGE, [a as usize, b as usize]),
        SurfacePart::Face(t) => {
            let c = corners(t);
            (mx_surface_part3::MX_SURFACE_FACE, [c[0] as usize, c[1] as usize])
        }
    };
    mx_contact3 {
        radius,
        centre: centre.to_array(),
        point: x.point.to_array(),
        kind: kind_of(x.kind),
        ball_part,
        ball_part_index,
        surface_part,
        surface_vertices,
        triangle: x.triangle as usize,
        flat: x.flat as i32,
    }
}

/// The largest ball `point + r·B` under `ball` (a space ball) that holds
/// no point of the surface inside (inside the solid: the largest ball
/// inside it there), with its radius and contacts decided exactly: every
/// contact with the least ball and surface features holding it, into
/// `contacts` of `capacity` entries, their number in `*count` (capacity
/// 0: a size query; a shorter buffer: `MX_ERR_BUFFER_TOO_SMALL`, nothing
/// written). About five times the time of `mx_mesh3d_query_point`'s
/// `f64` ball radius.
///
/// # Safety
/// `mesh` and `ball` NULL or live handles; `point` NULL or three readable
/// doubles; `contacts` NULL or `capacity` writable entries; `count` NULL
/// or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_ball_contacts(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    point: *const f64,
    contacts: *mut mx_contact3,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let (m, b) = unsafe { solid_and_ball(mesh, ball, count)? };
        // SAFETY: caller contract.
        let c = point_arg(unsafe { slice(point, 3, "point")? }, "`point`")?;
        let found = m.inner.tree().exact_contacts(c, &b.reach()).ok_or_else(|| {
            FfiError::new(mx_status::MX_ERR_NON_FINITE, "the point and the solid are too large for exact contacts")
        })?;
        let tris = m.inner.triangles();
        let out: Vec<mx_contact3> =
            found.contacts.iter().map(|x| to_c(x, (found.radius, c), |t| tris[t as usize])).collect();
        // SAFETY: caller contract (`contacts` holds `capacity` entries).
        unsafe { hand_out(out, contacts, capacity, count) }
    })
}

/// Writes `out` by the buffer protocol.
///
/// # Safety
/// `contacts` NULL or `capacity` writable entries; `count` writable.
unsafe fn hand_out(
    out: Vec<mx_contact3>,
    contacts: *mut mx_contact3,
    capacity: usize,
    count: *mut usize,
) -> Result<(), FfiError> {
    let n = out.len();
    // SAFETY: forwarded contract.
    unsafe {
        fill_items((contacts, "contacts"), (capacity, count), (n, 1), out, || {
            format!("{n} contacts, the buffer holds {capacity}")
        })
    }
}

/// The maximal* ball under `ball` (a space ball) whose vertex `vertex`
/// sits at the point `t0 + uv[0]·(t1 − t0) + uv[1]·(t2 − t0)` of triangle
/// `triangle` (taken exactly, on the triangle's plane), with its radius,
/// centre and the contacts that stop its growth decided exactly, into
/// `contacts` by the buffer protocol (as `mx_mesh3d_ball_contacts`). A
/// ball that does not grow (radius 0: the vertex's cone enters the
/// surface there) or grows without bound (outside the solid) has no
/// stopping contact: the call succeeds with count 0. Those radii (0 and
/// infinity) are decided exactly as well, also where the `f64`
/// `mx_mesh3d_maximal_ball` is lost in rounding (a plate thinner than
/// 10^-13 of the coordinates).
///
/// # Safety
/// `mesh` and `ball` NULL or live handles; `uv` NULL or two readable
/// doubles; `contacts` NULL or `capacity` writable entries; `count` NULL
/// or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_maximal_ball_contacts(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    triangle: usize,
    uv: *const f64,
    vertex: usize,
    contacts: *mut mx_contact3,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let (m, b) = unsafe { solid_and_ball(mesh, ball, count)? };
        // SAFETY: caller contract.
        let uv = unsafe { slice(uv, 2, "uv")? };
        if uv.iter().any(|v| !v.is_finite()) {
            return Err(FfiError::new(mx_status::MX_ERR_NON_FINITE, "`uv` has a NaN or infinite parameter"));
        }
        let tris = m.inner.triangles();
        if triangle >= tris.len() || vertex >= b.vertices().len() {
            let (nt, nv) = (tris.len(), b.vertices().len());
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("triangle {triangle} (of {nt}) or vertex {vertex} (of {nv}) is out of range"),
            ));
        }
        let corners = tris[triangle].map(|i| m.inner.positions()[i as usize]);
        let found = m.inner.tree().maximal_ball_exact_on(corners, (uv[0], uv[1]), vertex, &b.reach());
        let found = found.ok_or_else(|| {
            FfiError::new(mx_status::MX_ERR_NON_FINITE, "the point and the solid are too large for a ball's radius")
        })?;
        let out: Vec<mx_contact3> =
            found.opposite.iter().map(|x| to_c(x, (found.radius, found.centre), |t| tris[t as usize])).collect();
        // SAFETY: caller contract (`contacts` holds `capacity` entries).
        unsafe { hand_out(out, contacts, capacity, count) }
    })
}
