//! The C API of solids: arrays, memory and files in, facts, components,
//! vertices and triangles out by the buffer protocol, typed errors with
//! the face, vertex and line in `mx_error_info`, and NULL arguments.

mod common;

use common::ffi::last_message;
use medax::ffi::*;
use medax::shape::mesh_samples::{cuboid, torus, union};
use medax::shape::{Mesh3d, MeshOptions};
use std::ffi::CString;
use std::ptr::{null, null_mut};

fn from_arrays(v: &[[f64; 3]], t: &[[u32; 3]]) -> (mx_status, *mut mx_mesh3d) {
    let xyz: Vec<f64> = v.iter().flatten().copied().collect();
    let abc: Vec<u32> = t.iter().flatten().copied().collect();
    let mut m = null_mut();
    let st = unsafe { mx_mesh3d_from_arrays(xyz.as_ptr(), xyz.len(), abc.as_ptr(), abc.len(), null(), &mut m) };
    (st, m)
}

fn info(m: *const mx_mesh3d) -> mx_mesh3d_info {
    let mut i = unsafe { std::mem::zeroed::<mx_mesh3d_info>() };
    assert_eq!(unsafe { mx_mesh3d_get_info(m, &mut i) }, mx_status::MX_OK);
    i
}

fn error_info() -> mx_error_info {
    let mut e = unsafe { std::mem::zeroed::<mx_error_info>() };
    assert_eq!(unsafe { mx_last_error_info(&mut e) }, mx_status::MX_OK);
    e
}

#[test]
fn a_solid_from_arrays_matches_the_rust_one() {
    let (tv, tt) = torus(3.0, 1.0, 24, 12);
    let torus_aside = (tv.iter().map(|p| [p[0] + 30.0, p[1], p[2]]).collect::<Vec<_>>(), tt);
    let soup = union(&[cuboid([0.0; 3], [10.0; 3]), cuboid([2.0; 3], [8.0; 3]), torus_aside]);
    let rust = Mesh3d::from_triangles(&soup.0, &soup.1, &MeshOptions::default()).unwrap();
    let (st, m) = from_arrays(&soup.0, &soup.1);
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let i = info(m);
    assert_eq!(
        (i.vertex_count, i.triangle_count, i.component_count),
        (rust.positions().len(), rust.triangles().len(), 3)
    );
    assert_eq!(i.volume, rust.volume());
    assert_eq!(i.components_reversed, 1);
    // The cavity: inside component 0, depth 1, negative volume, reversed.
    let mut c = unsafe { std::mem::zeroed::<mx_mesh3d_component>() };
    assert_eq!(unsafe { mx_mesh3d_get_component(m, 1, &mut c) }, mx_status::MX_OK);
    assert_eq!((c.has_parent, c.parent, c.depth, c.reversed), (1, 0, 1, 1));
    assert!(c.volume < 0.0);
    assert_eq!(unsafe { mx_mesh3d_get_component(m, 2, &mut c) }, mx_status::MX_OK);
    assert_eq!(c.genus, 1);
    assert_eq!(unsafe { mx_mesh3d_get_component(m, 3, &mut c) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
    // Buffers: size query, short buffer refused, fill.
    let mut n = 0;
    assert_eq!(unsafe { mx_mesh3d_vertices(m, null_mut(), 0, &mut n) }, mx_status::MX_OK);
    assert_eq!(n, i.vertex_count);
    let mut xyz = vec![7.0; 3 * n];
    assert_eq!(unsafe { mx_mesh3d_vertices(m, xyz.as_mut_ptr(), n - 1, &mut n) }, mx_status::MX_ERR_BUFFER_TOO_SMALL);
    assert!(xyz.iter().all(|&v| v == 7.0));
    assert_eq!(unsafe { mx_mesh3d_vertices(m, xyz.as_mut_ptr(), n, &mut n) }, mx_status::MX_OK);
    assert_eq!(xyz[..3], rust.positions()[0].to_array());
    let mut k = 0;
    assert_eq!(unsafe { mx_mesh3d_triangles(m, null_mut(), 0, &mut k) }, mx_status::MX_OK);
    let mut abc = vec![0u32; 3 * k];
    assert_eq!(unsafe { mx_mesh3d_triangles(m, abc.as_mut_ptr(), k, &mut k) }, mx_status::MX_OK);
    assert_eq!(abc[..3], rust.triangles()[0]);
    unsafe { mx_mesh3d_free(m) };
    unsafe { mx_mesh3d_free(null_mut()) };
}

#[test]
fn written_files_read_back_to_the_same_solid() {
    let (v, t) = torus(3.0, 1.0, 20, 10);
    let (_, m) = from_arrays(&v, &t);
    let dir = std::env::temp_dir();
    for (ext, format) in
        [("off", mx_format::MX_FORMAT_OFF), ("obj", mx_format::MX_FORMAT_OBJ), ("ply", mx_format::MX_FORMAT_PLY)]
    {
        let path = CString::new(dir.join(format!("medax-ffi-mesh.{ext}")).to_str().unwrap()).unwrap();
        assert_eq!(unsafe { mx_mesh3d_write(m, path.as_ptr(), format as u32) }, mx_status::MX_OK, "{}", last_message());
        let mut back = null_mut();
        let st = unsafe { mx_mesh3d_from_file(path.as_ptr(), mx_format::MX_FORMAT_AUTO as u32, null(), &mut back) };
        assert_eq!(st, mx_status::MX_OK, "{ext}: {}", last_message());
        let (a, b) = (info(m), info(back));
        assert_eq!((a.vertex_count, a.triangle_count, a.volume), (b.vertex_count, b.triangle_count, b.volume), "{ext}");
        unsafe { mx_mesh3d_free(back) };
    }
    // STL is not written; a 2D format is refused for a solid.
    let stl = CString::new(dir.join("medax-ffi-mesh.stl").to_str().unwrap()).unwrap();
    assert_eq!(unsafe { mx_mesh3d_write(m, stl.as_ptr(), 0) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    let mut none = null_mut();
    let st = unsafe { mx_mesh3d_from_file(stl.as_ptr(), mx_format::MX_FORMAT_DXF as u32, null(), &mut none) };
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("mx_shape2d_from_file"), "{}", last_message());
    unsafe { mx_mesh3d_free(m) };
}

#[test]
fn bad_solids_name_the_face_vertex_and_line() {
    // An OFF box with its last face missing: open, at the line of a face
    // along the open edge.
    let (v, t) = cuboid([0.0; 3], [1.0; 3]);
    let mut off = format!("OFF\n{} {} 0\n", v.len(), t.len() - 1);
    for p in &v {
        off += &format!("{} {} {}\n", p[0], p[1], p[2]);
    }
    for tri in &t[..t.len() - 1] {
        off += &format!("3 {} {} {}\n", tri[0], tri[1], tri[2]);
    }
    let mut m = std::ptr::NonNull::<mx_mesh3d>::dangling().as_ptr();
    let st = unsafe { mx_mesh3d_from_memory(off.as_ptr(), off.len(), mx_format::MX_FORMAT_OFF as u32, null(), &mut m) };
    assert_eq!(st, mx_status::MX_ERR_NOT_CLOSED, "{}", last_message());
    assert_eq!(m, std::ptr::NonNull::<mx_mesh3d>::dangling().as_ptr(), "out-param untouched on failure");
    let e = error_info();
    assert!(e.element >= 0 && e.line >= 11, "{e:?}");
    assert!(e.other_element >= 0);
    // NaN vertex: the vertex.
    let mut nan = v.clone();
    nan[3][2] = f64::NAN;
    assert_eq!(from_arrays(&nan, &t).0, mx_status::MX_ERR_NON_FINITE);
    assert_eq!(error_info().other_element, 3);
    // Two boxes sharing a corner: not a manifold, at that vertex.
    let bow = union(&[cuboid([0.0; 3], [1.0; 3]), cuboid([1.0; 3], [2.0; 3])]);
    assert_eq!(from_arrays(&bow.0, &bow.1).0, mx_status::MX_ERR_NOT_MANIFOLD);
    assert_eq!(error_info().other_element, 7);
    // Lengths not in threes, NULL arrays, bad options.
    let mut out = null_mut();
    let xyz = [0.0; 4];
    let st = unsafe { mx_mesh3d_from_arrays(xyz.as_ptr(), 4, null(), 0, null(), &mut out) };
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT);
    let st = unsafe { mx_mesh3d_from_arrays(null(), 3, null(), 0, null(), &mut out) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    let mut o = unsafe { std::mem::zeroed::<mx_mesh_options>() };
    assert_eq!(unsafe { mx_mesh_options_init(&mut o, std::mem::size_of::<mx_mesh_options>()) }, mx_status::MX_OK);
    o.weld_tolerance = -1.0;
    let xyz: Vec<f64> = v.iter().flatten().copied().collect();
    let abc: Vec<u32> = t.iter().flatten().copied().collect();
    let st = unsafe { mx_mesh3d_from_arrays(xyz.as_ptr(), xyz.len(), abc.as_ptr(), abc.len(), &o, &mut out) };
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(out.is_null());
    // Queries on NULL.
    let mut i = unsafe { std::mem::zeroed::<mx_mesh3d_info>() };
    assert_eq!(unsafe { mx_mesh3d_get_info(null(), &mut i) }, mx_status::MX_ERR_NULL_ARGUMENT);
}

/// Point queries through C on a box with a cavity: sides (exact, on the
/// surface included), closest points against the box's own geometry, the
/// largest cube ball at inside points (the L∞ distance to the nearest
/// face), batched equal to one by one, and errors.
#[test]
fn point_queries_side_closest_and_ball() {
    let soup = union(&[cuboid([0.0; 3], [10.0; 3]), cuboid([4.0; 3], [6.0; 3])]);
    let (_, m) = from_arrays(&soup.0, &soup.1);
    let mut cube = null_mut();
    assert_eq!(unsafe { mx_ball_cube(&mut cube) }, mx_status::MX_OK);
    let pts: [[f64; 3]; 4] = [[1.0, 2.0, 3.0], [5.0, 5.0, 5.0], [12.0, 5.0, 5.0], [0.0, 5.0, 5.0]];
    let sides =
        [mx_point_side::MX_INSIDE, mx_point_side::MX_OUTSIDE, mx_point_side::MX_OUTSIDE, mx_point_side::MX_ON_SURFACE];
    for (p, want) in pts.iter().zip(sides) {
        let mut s = mx_point_side::MX_ON_SURFACE;
        assert_eq!(unsafe { mx_mesh3d_side(m, p.as_ptr(), &mut s) }, mx_status::MX_OK);
        assert_eq!(s, want, "{p:?}");
    }
    let mut one = unsafe { std::mem::zeroed::<mx_point_query3>() };
    assert_eq!(unsafe { mx_mesh3d_query_point(m, cube, pts[0].as_ptr(), &mut one) }, mx_status::MX_OK);
    assert_eq!((one.distance, one.closest), (1.0, [0.0, 2.0, 3.0]));
    assert_eq!((one.has_ball, one.ball_radius), (1, 1.0));
    // Inside the material near the cavity: the cavity's face is nearest.
    let near_cavity = [3.5, 5.0, 5.0];
    assert_eq!(unsafe { mx_mesh3d_query_point(m, cube, near_cavity.as_ptr(), &mut one) }, mx_status::MX_OK);
    assert_eq!((one.distance, one.ball_radius, one.contact[0]), (0.5, 0.5, 4.0));
    // Batched: size query, short buffer, the same answers.
    let xyz: Vec<f64> = pts.iter().flatten().copied().collect();
    let mut n = 0;
    let st = unsafe { mx_mesh3d_query_points(m, cube, xyz.as_ptr(), xyz.len(), null_mut(), 0, &mut n) };
    assert_eq!((st, n), (mx_status::MX_OK, 4));
    let mut all = vec![unsafe { std::mem::zeroed::<mx_point_query3>() }; 4];
    let st = unsafe { mx_mesh3d_query_points(m, cube, xyz.as_ptr(), xyz.len(), all.as_mut_ptr(), 3, &mut n) };
    assert_eq!(st, mx_status::MX_ERR_BUFFER_TOO_SMALL);
    let st = unsafe { mx_mesh3d_query_points(m, cube, xyz.as_ptr(), xyz.len(), all.as_mut_ptr(), 4, &mut n) };
    assert_eq!(st, mx_status::MX_OK);
    for (i, p) in pts.iter().enumerate() {
        assert_eq!(unsafe { mx_mesh3d_query_point(m, cube, p.as_ptr(), &mut one) }, mx_status::MX_OK);
        assert_eq!(all[i], one, "{i}");
    }
    assert_eq!(all[1].has_ball, 0, "no ball at an outside point");
    // A plane ball is refused; NaN names the point.
    let mut square = null_mut();
    assert_eq!(unsafe { mx_ball_square(&mut square) }, mx_status::MX_OK);
    let st = unsafe { mx_mesh3d_query_point(m, square, pts[0].as_ptr(), &mut one) };
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT);
    let bad = [0.0, 0.0, 0.0, 1.0, f64::NAN, 1.0];
    let st = unsafe { mx_mesh3d_query_points(m, null(), bad.as_ptr(), 6, all.as_mut_ptr(), 4, &mut n) };
    assert_eq!(st, mx_status::MX_ERR_NON_FINITE);
    assert!(last_message().contains("point 1"), "{}", last_message());
    unsafe { mx_ball_free(cube) };
    unsafe { mx_ball_free(square) };
    unsafe { mx_mesh3d_free(m) };
}
