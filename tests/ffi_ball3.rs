//! Space balls through the C API: presets, hulls of points and of a mesh
//! file's vertices, vertices by the buffer protocol, facets, the distance
//! (checked against the facet inequalities computed here), the mirror, and
//! the errors of bad balls and of a ball of the wrong dimension.

mod common;

use common::ffi::last_message;
use medax::ffi::*;
use std::ffi::CString;
use std::ptr::{null, null_mut};

fn make(f: unsafe extern "C" fn(*mut *mut mx_ball) -> mx_status) -> *mut mx_ball {
    let mut b = null_mut();
    assert_eq!(unsafe { f(&mut b) }, mx_status::MX_OK, "{}", last_message());
    b
}

fn vertices(b: *const mx_ball) -> Vec<[f64; 3]> {
    let (mut n, mut m) = (0, 0);
    assert_eq!(unsafe { mx_ball_vertices(b, null_mut(), 0, &mut n) }, mx_status::MX_OK);
    let mut xyz = vec![0.0; 3 * n];
    assert_eq!(unsafe { mx_ball_vertices(b, xyz.as_mut_ptr(), n, &mut m) }, mx_status::MX_OK);
    assert_eq!(m, n);
    xyz.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
}

fn distance(b: *const mx_ball, p: [f64; 3], q: [f64; 3]) -> f64 {
    let mut d = -1.0;
    assert_eq!(unsafe { mx_ball_distance3(b, p.as_ptr(), q.as_ptr(), &mut d) }, mx_status::MX_OK);
    d
}

#[test]
fn presets_and_their_distances() {
    let cube = make(mx_ball_cube);
    let mut dim = 0;
    assert_eq!(unsafe { mx_ball_dimension(cube, &mut dim) }, mx_status::MX_OK);
    assert_eq!(dim, 3);
    assert_eq!(vertices(cube).len(), 8);
    let mut f = 0;
    assert_eq!(unsafe { mx_ball_facet_count(cube, &mut f) }, mx_status::MX_OK);
    assert_eq!(f, 6);
    // L∞ and L1.
    assert_eq!(distance(cube, [1.0, 2.0, 3.0], [4.0, -3.0, 3.5]), 5.0);
    let octa = make(mx_ball_octahedron);
    assert_eq!(distance(octa, [1.0, 2.0, 3.0], [4.0, -3.0, 3.5]), 8.5);
    // The tetrahedron is not symmetric; its mirror swaps the directions.
    let tetra = make(mx_ball_tetrahedron);
    let mut sym = 9;
    assert_eq!(unsafe { mx_ball_is_symmetric(tetra, &mut sym) }, mx_status::MX_OK);
    assert_eq!(sym, 0);
    let mut mirror = null_mut();
    assert_eq!(unsafe { mx_ball_mirrored(tetra, &mut mirror) }, mx_status::MX_OK);
    let (p, q) = ([0.3, -0.2, 0.1], [1.0, 2.0, -0.5]);
    assert!((distance(mirror, p, q) - distance(tetra, q, p)).abs() < 1e-12);
    assert!((distance(tetra, p, q) - distance(tetra, q, p)).abs() > 1e-3);
    let mut geo = null_mut();
    assert_eq!(unsafe { mx_ball_geodesic(80, &mut geo) }, mx_status::MX_OK);
    assert_eq!(unsafe { mx_ball_facet_count(geo, &mut f) }, mx_status::MX_OK);
    assert_eq!(f, 80);
    // Geodesic corners lie on the unit sphere: the distance to a corner
    // direction at length 2 is 2.
    let v = vertices(geo)[5];
    assert!((distance(geo, [0.0; 3], [2.0 * v[0], 2.0 * v[1], 2.0 * v[2]]) - 2.0).abs() < 1e-12);
    for b in [cube, octa, tetra, mirror, geo] {
        unsafe { mx_ball_free(b) };
    }
}

/// The hull of a 3×3×3 grid around an off-centre origin: 8 corners, 6
/// facets; its distance agrees with the facet inequalities of the box
/// written here.
#[test]
fn hulls_of_points_and_of_a_mesh_file() {
    let mut xyz = Vec::new();
    for i in 0..3 {
        for j in 0..3 {
            for k in 0..3 {
                xyz.extend([i as f64 - 0.5, j as f64 - 0.7, k as f64 - 0.2]);
            }
        }
    }
    let mut b = null_mut();
    assert_eq!(
        unsafe { mx_ball_from_points3(xyz.as_ptr(), xyz.len(), &mut b) },
        mx_status::MX_OK,
        "{}",
        last_message()
    );
    assert_eq!(vertices(b).len(), 8);
    // The box [-0.5, 1.5] × [-0.7, 1.3] × [-0.2, 1.8]: the gauge of v is
    // the largest v_i / hi_i (v_i > 0) or v_i / lo_i (v_i < 0).
    let (lo, hi) = ([-0.5, -0.7, -0.2], [1.5, 1.3, 1.8]);
    let gauge = |v: [f64; 3]| (0..3).map(|i| if v[i] > 0.0 { v[i] / hi[i] } else { v[i] / lo[i] }).fold(0.0, f64::max);
    for v in [[1.0, 2.0, 3.0], [-1.0, 0.1, -0.1], [0.2, -4.0, 0.0]] {
        assert!((distance(b, [0.0; 3], v) - gauge(v)).abs() < 1e-12, "{v:?}");
    }
    // The same box from an OFF file's vertices.
    let corners: Vec<[f64; 3]> = xyz.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    let off = medax::io::mesh::write_off(&corners, &[[0, 1, 2]]);
    let path = std::env::temp_dir().join(format!("medax-ball3-{}.off", std::process::id()));
    std::fs::write(&path, off).unwrap();
    let c_path = CString::new(path.to_str().unwrap()).unwrap();
    let mut from_file = null_mut();
    assert_eq!(unsafe { mx_ball_from_file3(c_path.as_ptr(), 0, &mut from_file) }, mx_status::MX_OK);
    assert_eq!(vertices(from_file), vertices(b));
    unsafe { mx_ball_free(b) };
    unsafe { mx_ball_free(from_file) };
    std::fs::remove_file(&path).ok();
}

#[test]
fn bad_balls_and_wrong_dimensions_are_refused() {
    let mut out = std::ptr::NonNull::<mx_ball>::dangling().as_ptr();
    let sentinel = out;
    // Flat, origin outside, too few points, NaN, length not in threes.
    let flat = [1.0, 0.0, 0.0, -1.0, 1.0, 0.0, -1.0, -1.0, 0.0, 0.5, 0.5, 0.0];
    let outside = [1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 2.0];
    let three = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let nan = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, f64::NAN, -1.0, -1.0];
    for (xyz, what) in [(&flat[..], "flat"), (&outside[..], "origin"), (&three[..], "4"), (&nan[..], "NaN")] {
        let st = unsafe { mx_ball_from_points3(xyz.as_ptr(), xyz.len(), &mut out) };
        assert_eq!(st, mx_status::MX_ERR_INVALID_BALL, "{what}");
        assert_eq!(out, sentinel);
        assert!(!last_message().is_empty());
    }
    assert_eq!(unsafe { mx_ball_from_points3(flat.as_ptr(), 11, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    // A space ball where a plane ball is needed, and the other way round.
    let cube = make(mx_ball_cube);
    let square = make(mx_ball_square);
    let mut d = 0.0;
    let p = [0.0; 3];
    assert_eq!(unsafe { mx_ball_distance2(cube, p.as_ptr(), p.as_ptr(), &mut d) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("3D ball"), "{}", last_message());
    assert_eq!(
        unsafe { mx_ball_distance3(square, p.as_ptr(), p.as_ptr(), &mut d) },
        mx_status::MX_ERR_INVALID_ARGUMENT
    );
    let mut f = 0;
    assert_eq!(unsafe { mx_ball_facet_count(square, &mut f) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    let mut rotated = null_mut();
    assert_eq!(unsafe { mx_ball_rotated3(cube, null(), &mut rotated) }, mx_status::MX_ERR_NULL_ARGUMENT);
    let r = [0.0, 0.0, std::f64::consts::FRAC_PI_4];
    assert_eq!(unsafe { mx_ball_rotated3(cube, r.as_ptr(), &mut rotated) }, mx_status::MX_OK);
    // Turned 45° about z, the corner (1, −1, ·) moves to (√2, 0, ·): the
    // point (√2, 0, 0) lies on the turned cube's vertical edge.
    assert!((medax_distance(rotated, [2f64.sqrt(), 0.0, 0.0]) - 1.0).abs() < 1e-12);
    let shape_json = CString::new(r#"{"loops": [[[0, 0], [4, 0], [4, 2], [0, 2]]]}"#).unwrap();
    let mut s = null_mut();
    assert_eq!(unsafe { mx_shape2d_from_string(shape_json.as_ptr(), 1, null(), &mut s) }, mx_status::MX_OK);
    let mut a = null_mut();
    assert_eq!(unsafe { mx_axis_compute_with_ball(s, cube, null(), &mut a) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(a.is_null());
    for b in [cube, square, rotated] {
        unsafe { mx_ball_free(b) };
    }
    unsafe { mx_shape2d_free(s) };
}

fn medax_distance(b: *const mx_ball, q: [f64; 3]) -> f64 {
    distance(b, [0.0; 3], q)
}
