//! The 3D medial axis through the C API (`mx_mesh3d_axis`, `mx_axis3d`):
//! the same vertices, triangles and sheets as the Rust axis, the buffer
//! protocol, progress and cancellation through the callback, and every
//! bad argument refused with the out-parameters left alone.

mod common;

use common::ffi::{c_solid, last_message};
use common::solids::l_prism;
use medax::ffi::*;
use medax::shape::{Ball3, Feature3, SurfacePart};
use medax::space::medial_axis_3d;
use std::ffi::{c_int, c_void};
use std::ptr::{null, null_mut};

fn turned_tetrahedron() -> *mut mx_ball {
    let (mut tetra, mut turned) = (null_mut(), null_mut());
    assert_eq!(unsafe { mx_ball_tetrahedron(&mut tetra) }, mx_status::MX_OK);
    let r = [0.2, 0.4, -0.3];
    assert_eq!(unsafe { mx_ball_rotated3(tetra, r.as_ptr(), &mut turned) }, mx_status::MX_OK);
    unsafe { mx_ball_free(tetra) };
    turned
}

/// Counts its calls in `*user`; cancels from the `limit`-th call on
/// (`user` points at `[calls, limit]`).
unsafe extern "C" fn counting(_fraction: f64, user: *mut c_void) -> c_int {
    let state = unsafe { &mut *(user as *mut [usize; 2]) };
    state[0] += 1;
    c_int::from(state[0] >= state[1])
}

#[test]
fn the_axis_of_an_l_prism_is_the_rust_axis() {
    let (rust, m) = c_solid(&l_prism(1.3, 1.0));
    let b = turned_tetrahedron();
    let mut axis = null_mut();
    assert_eq!(unsafe { mx_mesh3d_axis(m, b, null(), &mut axis) }, mx_status::MX_OK, "{}", last_message());
    let want = medial_axis_3d(&rust, &Ball3::tetrahedron().rotated([0.2, 0.4, -0.3]).unwrap()).unwrap();
    // Vertices: size query, a short buffer refused, then the copy.
    let mut n = 0;
    assert_eq!(unsafe { mx_axis3d_vertices(axis, null_mut(), 0, &mut n) }, mx_status::MX_OK);
    assert_eq!(n, want.vertices.len());
    let mut short = vec![-7.0; 4 * (n - 1)];
    let mut m2 = 99;
    let st = unsafe { mx_axis3d_vertices(axis, short.as_mut_ptr(), n - 1, &mut m2) };
    assert_eq!(st, mx_status::MX_ERR_BUFFER_TOO_SMALL);
    assert!(short.iter().all(|&x| x == -7.0));
    let mut xyzr = vec![0.0; 4 * n];
    assert_eq!(unsafe { mx_axis3d_vertices(axis, xyzr.as_mut_ptr(), n, &mut n) }, mx_status::MX_OK);
    assert_eq!(xyzr, want.vertices.iter().flatten().copied().collect::<Vec<_>>());
    let mut t = 0;
    assert_eq!(unsafe { mx_axis3d_triangles(axis, null_mut(), 0, &mut t) }, mx_status::MX_OK);
    let mut abc = vec![0u32; 3 * t];
    assert_eq!(unsafe { mx_axis3d_triangles(axis, abc.as_mut_ptr(), t, &mut t) }, mx_status::MX_OK);
    assert_eq!(abc, want.triangles.iter().flatten().copied().collect::<Vec<_>>());
    // Sheets: classes, jump flags and triangles as in Rust.
    let mut s = 0;
    assert_eq!(unsafe { mx_axis3d_sheet_count(axis, &mut s) }, mx_status::MX_OK);
    assert_eq!(s, want.sheets.len());
    let mut edge_edge = 0;
    for (i, ws) in want.sheets.iter().enumerate() {
        let mut sheet = std::mem::MaybeUninit::<mx_axis3d_sheet>::zeroed();
        assert_eq!(unsafe { mx_axis3d_get_sheet(axis, i, sheet.as_mut_ptr()) }, mx_status::MX_OK);
        let sheet = unsafe { sheet.assume_init() };
        assert_eq!((sheet.jump != 0, sheet.triangle_count), (ws.jump, ws.triangles.len()));
        for (c, w) in sheet.classes.iter().zip(&ws.classes) {
            let ball = match w.ball {
                Feature3::Vertex(v) => (mx_ball_part3::MX_BALL_VERTEX, v),
                Feature3::Edge(e) => (mx_ball_part3::MX_BALL_EDGE, e),
                Feature3::Facet(f) => (mx_ball_part3::MX_BALL_FACET, f),
            };
            assert_eq!((c.ball_part, c.ball_part_index), ball);
            match w.surface {
                SurfacePart::Face(f) => assert_eq!(c.surface_index, [f as usize; 2]),
                SurfacePart::Edge([a, b]) => {
                    assert_eq!(c.surface_index, [a as usize, b as usize]);
                    assert_eq!(c.kind, mx_contact3_kind::MX_CONTACT3_EE);
                    edge_edge += 1;
                }
                SurfacePart::Vertex(v) => assert_eq!(c.surface_index, [v as usize; 2]),
            }
        }
        let mut tris = vec![0u32; ws.triangles.len()];
        let mut k = 0;
        let st = unsafe { mx_axis3d_sheet_triangles(axis, i, tris.as_mut_ptr(), tris.len(), &mut k) };
        assert_eq!(st, mx_status::MX_OK);
        assert_eq!(tris, ws.triangles);
    }
    assert!(edge_edge > 0, "the prism's reflex edge gives EE sheets");
    // Out of range and NULL: refused, the out-parameter left alone.
    let mut sheet = std::mem::MaybeUninit::<mx_axis3d_sheet>::zeroed();
    assert_eq!(unsafe { mx_axis3d_get_sheet(axis, s, sheet.as_mut_ptr()) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
    let mut k = 5;
    assert_eq!(unsafe { mx_axis3d_sheet_count(null(), &mut k) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(k, 5);
    unsafe {
        mx_axis3d_free(axis);
        mx_axis3d_free(null_mut());
        mx_ball_free(b);
        mx_mesh3d_free(m);
    }
}

#[test]
fn progress_is_reported_and_a_nonzero_answer_cancels() {
    let (_, m) = c_solid(&l_prism(1.3, 1.0));
    let b = turned_tetrahedron();
    let mut o = std::mem::MaybeUninit::<mx_axis3d_options>::zeroed();
    let size = std::mem::size_of::<mx_axis3d_options>();
    assert_eq!(unsafe { mx_axis3d_options_init(o.as_mut_ptr(), size) }, mx_status::MX_OK);
    let mut o = unsafe { o.assume_init() };
    assert_eq!((o.struct_size, o.threads), (size, 0));
    // Cancelled at the first call: before any work.
    let mut state = [0usize, 1];
    o.progress = Some(counting);
    o.user = &mut state as *mut _ as *mut c_void;
    let sentinel = 0x10 as *mut mx_axis3d;
    let mut axis = sentinel;
    assert_eq!(unsafe { mx_mesh3d_axis(m, b, &o, &mut axis) }, mx_status::MX_ERR_CANCELLED);
    assert_eq!((axis, state[0]), (sentinel, 1));
    assert!(last_message().contains("cancelled"), "{}", last_message());
    // Cancelled at the second call, while it runs.
    state = [0, 2];
    o.user = &mut state as *mut _ as *mut c_void;
    assert_eq!(unsafe { mx_mesh3d_axis(m, b, &o, &mut axis) }, mx_status::MX_ERR_CANCELLED);
    assert_eq!(axis, sentinel);
    // Never cancelled: called at least at the start and the end, on two
    // threads of its own.
    state = [0, usize::MAX];
    o.user = &mut state as *mut _ as *mut c_void;
    o.threads = 2;
    assert_eq!(unsafe { mx_mesh3d_axis(m, b, &o, &mut axis) }, mx_status::MX_OK, "{}", last_message());
    assert!(state[0] >= 2 && axis != sentinel);
    unsafe { mx_axis3d_free(axis) };
    // Too many threads, a plane ball, NULL arguments: refused.
    o.threads = 1 << 20;
    o.progress = None;
    let mut axis = sentinel;
    assert_eq!(unsafe { mx_mesh3d_axis(m, b, &o, &mut axis) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    let mut square = null_mut();
    assert_eq!(unsafe { mx_ball_square(&mut square) }, mx_status::MX_OK);
    assert_eq!(unsafe { mx_mesh3d_axis(m, square, null(), &mut axis) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert_eq!(unsafe { mx_mesh3d_axis(null(), b, null(), &mut axis) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_mesh3d_axis(m, null(), null(), &mut axis) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_mesh3d_axis(m, b, null(), null_mut()) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(axis, sentinel);
    // The axis-aligned cube on the box-shaped prism: faces parallel to its
    // facets, outside general position, named.
    let mut cube = null_mut();
    assert_eq!(unsafe { mx_ball_cube(&mut cube) }, mx_status::MX_OK);
    let (_, plain) = c_solid(&l_prism(1.3, 0.0));
    assert_eq!(unsafe { mx_mesh3d_axis(plain, cube, null(), &mut axis) }, mx_status::MX_ERR_DEGENERATE);
    assert!(last_message().contains("parallel"), "{}", last_message());
    assert_eq!(axis, sentinel);
    unsafe {
        mx_ball_free(square);
        mx_ball_free(cube);
        mx_ball_free(b);
        mx_mesh3d_free(m);
        mx_mesh3d_free(plain);
    }
}
