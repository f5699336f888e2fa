//! Maximal* balls of a solid through the C API: closed forms in a box
//! with a cavity (a ball in the material, one in the cavity, one outside
//! and unbounded), the same answers as the Rust tree one by one and in a
//! batch, the buffer protocol, and every bad argument refused with the
//! out-parameters left alone.

mod common;

use common::ffi::{c_solid, last_message};
use medax::ffi::*;
use medax::kernel::Point3;
use medax::shape::mesh_samples::{cuboid, union};
use medax::shape::{Ball3, Mesh3d};
use std::ptr::{null, null_mut};

/// A box 0..10 with a cavity 3..7 (the cavity's triangles turned inward).
fn solid() -> (Mesh3d, *mut mx_mesh3d) {
    let inner = cuboid([3.0; 3], [7.0; 3]);
    let soup = union(&[cuboid([0.0; 3], [10.0; 3]), (inner.0, inner.1.iter().map(|t| [t[0], t[2], t[1]]).collect())]);
    c_solid(&soup)
}

const SENTINEL: mx_maximal_ball3 = mx_maximal_ball3 {
    radius: -1.0,
    centre: [-1.0; 3],
    has_opposite: 7,
    opposite_triangle: 99,
    opposite_point: [-1.0; 3],
    opposite_kind: mx_contact3_kind::MX_CONTACT3_EE,
};

fn one(m: *const mx_mesh3d, b: *const mx_ball, p: [f64; 3], v: usize) -> (mx_status, mx_maximal_ball3) {
    let mut out = SENTINEL;
    let st = unsafe { mx_mesh3d_maximal_ball(m, b, p.as_ptr(), v, &mut out) };
    (st, out)
}

#[test]
fn maximal_balls_in_a_box_with_a_cavity() {
    let (rust, m) = solid();
    let mut cube = null_mut();
    assert_eq!(unsafe { mx_ball_cube(&mut cube) }, mx_status::MX_OK);
    let cube_rs = Ball3::cube();
    // The cube's vertex (−1, −1, −1) at a point p of the bottom face
    // z = 0: the balls p + r·(B − v) = [1.5, 1.5 + 2r]² × [0, 2r] grow up
    // into the material until they meet the cavity's bottom z = 3, at
    // r = 1.5 (centre (3, 3, 1.5)), touching it over a square.
    let down = cube_rs.vertices().iter().position(|w| w.x < 0.0 && w.y < 0.0 && w.z < 0.0).unwrap();
    let (st, b) = one(m, cube, [1.5, 1.5, 0.0], down);
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    assert!(b.radius == 1.5 && b.centre == [3.0, 3.0, 1.5] && b.has_opposite == 1, "{b:?}");
    assert_eq!(b.opposite_point[2], 3.0, "{b:?}");
    // The opposite vertex (+1, +1, +1) at the same point points out of
    // the box: the ball is outside and grows without bound.
    let up = cube_rs.vertices().iter().position(|w| w.x > 0.0 && w.y > 0.0 && w.z > 0.0).unwrap();
    let (_, b) = one(m, cube, [1.5, 1.5, 0.0], up);
    assert!(b.radius.is_infinite() && b.has_opposite == 0 && b.centre == [1.5, 1.5, 0.0], "{b:?}");
    // From the cavity's bottom face z = 3 at (5, 5, 3): [5, 5 + 2r]² ×
    // [3, 3 + 2r] in the cavity, stopped by its walls x = 7 and y = 7.
    let (_, b) = one(m, cube, [5.0, 5.0, 3.0], down);
    assert!(b.radius == 1.0 && b.centre == [6.0, 6.0, 4.0], "{b:?}");
    // A batch agrees with one by one and with the Rust tree.
    let asked: Vec<([f64; 3], usize)> =
        (0..40).map(|i| ([0.25 + 0.23 * i as f64, 9.5 - 0.2 * i as f64, 0.0], i % 8)).collect();
    let xyz: Vec<f64> = asked.iter().flat_map(|a| a.0).collect();
    let vs: Vec<usize> = asked.iter().map(|a| a.1).collect();
    let mut count = 0;
    let st = unsafe {
        mx_mesh3d_maximal_balls(m, cube, xyz.as_ptr(), xyz.len(), vs.as_ptr(), vs.len(), null_mut(), 0, &mut count)
    };
    assert_eq!((st, count), (mx_status::MX_OK, 40));
    let mut out = vec![SENTINEL; 40];
    let st = unsafe {
        mx_mesh3d_maximal_balls(
            m,
            cube,
            xyz.as_ptr(),
            xyz.len(),
            vs.as_ptr(),
            vs.len(),
            out.as_mut_ptr(),
            39,
            &mut count,
        )
    };
    assert_eq!(st, mx_status::MX_ERR_BUFFER_TOO_SMALL);
    assert!(out.iter().all(|b| *b == SENTINEL));
    let st = unsafe {
        mx_mesh3d_maximal_balls(
            m,
            cube,
            xyz.as_ptr(),
            xyz.len(),
            vs.as_ptr(),
            vs.len(),
            out.as_mut_ptr(),
            40,
            &mut count,
        )
    };
    assert_eq!(st, mx_status::MX_OK);
    let rust_balls = rust
        .tree()
        .maximal_balls(&asked.iter().map(|&(p, v)| (Point3::from_array(p), v)).collect::<Vec<_>>(), &cube_rs);
    for ((a, got), want) in asked.iter().zip(&out).zip(rust_balls) {
        assert_eq!(*got, one(m, cube, a.0, a.1).1);
        let want = want.unwrap();
        assert_eq!((got.radius, got.centre), (want.radius, want.centre.to_array()));
    }
    unsafe { mx_ball_free(cube) };
    unsafe { mx_mesh3d_free(m) };
}

#[test]
fn bad_arguments_are_refused_and_nothing_is_written() {
    let (_, m) = solid();
    let mut tetra = null_mut();
    assert_eq!(unsafe { mx_ball_tetrahedron(&mut tetra) }, mx_status::MX_OK);
    let mut square = null_mut();
    assert_eq!(unsafe { mx_ball_square(&mut square) }, mx_status::MX_OK);
    let p = [5.0, 5.0, 0.0];
    let cases: [(mx_status, (mx_status, mx_maximal_ball3)); 5] = [
        (mx_status::MX_ERR_NULL_ARGUMENT, one(null(), tetra, p, 0)),
        (mx_status::MX_ERR_NULL_ARGUMENT, one(m, null(), p, 0)),
        (mx_status::MX_ERR_NON_FINITE, one(m, tetra, [f64::NAN, 0.0, 0.0], 0)),
        (mx_status::MX_ERR_INVALID_ARGUMENT, one(m, tetra, p, 4)),
        (mx_status::MX_ERR_INVALID_ARGUMENT, one(m, square, p, 0)),
    ];
    for (i, (want, (st, out))) in cases.into_iter().enumerate() {
        assert_eq!(st, want, "case {i}: {}", last_message());
        assert_eq!(out, SENTINEL, "case {i}");
    }
    assert!(last_message().contains("space ball") || !last_message().is_empty());
    let st = unsafe { mx_mesh3d_maximal_ball(m, tetra, p.as_ptr(), 0, null_mut()) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    // Batches: lengths that disagree, a vertex out of range named by index.
    let xyz = [1.0, 1.0, 0.0, 2.0, 2.0, 0.0];
    let (mut out, mut count) = ([SENTINEL; 2], 0);
    let st = unsafe {
        mx_mesh3d_maximal_balls(m, tetra, xyz.as_ptr(), 6, [0usize].as_ptr(), 1, out.as_mut_ptr(), 2, &mut count)
    };
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT);
    let st = unsafe {
        mx_mesh3d_maximal_balls(m, tetra, xyz.as_ptr(), 6, [0usize, 9].as_ptr(), 2, out.as_mut_ptr(), 2, &mut count)
    };
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("vertices[1]"), "{}", last_message());
    assert!(out.iter().all(|b| *b == SENTINEL) && count == 0);
    unsafe { mx_ball_free(tetra) };
    unsafe { mx_ball_free(square) };
    unsafe { mx_mesh3d_free(m) };
}
