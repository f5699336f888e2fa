//! Exact contacts of the largest ball through the C API
//! (`mx_mesh3d_ball_contacts`): closed forms in a box (an octahedron at
//! the centre touches all six faces; near a face its vertex lands on the
//! face's diagonal, a VE contact), a cube lying flat, the same answers as
//! the Rust tree, the buffer protocol, and bad arguments refused with the
//! buffer and count left alone.

mod common;

use common::ffi::{c_solid, last_message};
use medax::ffi::*;
use medax::kernel::Point3;
use medax::shape::mesh_samples::cuboid;
use medax::shape::{Ball3, Mesh3d};
use std::ptr::{null, null_mut};

fn solid() -> (Mesh3d, *mut mx_mesh3d) {
    let soup = cuboid([0.0; 3], [10.0; 3]);
    c_solid(&soup)
}

const BLANK: mx_contact3 = mx_contact3 {
    radius: -1.0,
    centre: [-1.0; 3],
    point: [-1.0; 3],
    kind: mx_contact3_kind::MX_CONTACT3_FV,
    ball_part: mx_ball_part3::MX_BALL_FACET,
    ball_part_index: 99,
    surface_part: mx_surface_part3::MX_SURFACE_FACE,
    surface_vertices: [99; 2],
    triangle: 99,
    flat: 7,
};

fn contacts(m: *const mx_mesh3d, b: *const mx_ball, p: [f64; 3]) -> Vec<mx_contact3> {
    let mut n = 0usize;
    let st = unsafe { mx_mesh3d_ball_contacts(m, b, p.as_ptr(), null_mut(), 0, &mut n) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let mut buf = vec![BLANK; n];
    let mut got = 0usize;
    let st = unsafe { mx_mesh3d_ball_contacts(m, b, p.as_ptr(), buf.as_mut_ptr(), n, &mut got) };
    assert_eq!((st, got), (mx_status::MX_OK, n), "{}", last_message());
    buf
}

#[test]
fn contacts_in_a_box_match_closed_forms_and_the_rust_tree() {
    let (rust, m) = solid();
    let (mut octa, mut cube) = (null_mut(), null_mut());
    assert_eq!(unsafe { mx_ball_octahedron(&mut octa) }, mx_status::MX_OK);
    assert_eq!(unsafe { mx_ball_cube(&mut cube) }, mx_status::MX_OK);
    // At the centre the octahedron's six vertices touch the six faces at
    // their centres, which lie on the faces' diagonals: six VE contacts
    // or VF, as the triangulation has it, each at distance 5.
    let at_centre = contacts(m, octa, [5.0; 3]);
    assert_eq!(at_centre.len(), 6, "{at_centre:?}");
    for x in &at_centre {
        assert_eq!(x.radius, 5.0);
        assert_eq!(x.ball_part, mx_ball_part3::MX_BALL_VERTEX);
        assert!(x.point.iter().filter(|&&v| v == 0.0 || v == 10.0).count() == 1 && x.flat == 0, "{x:?}");
    }
    // Off the diagonal: one VF contact on the face x = 0 at (0, 3, 6).
    let near = contacts(m, octa, [2.0, 3.0, 6.0]);
    assert_eq!(near.len(), 1, "{near:?}");
    let x = near[0];
    assert!(x.radius == 2.0 && x.point == [0.0, 3.0, 6.0], "{x:?}");
    assert_eq!((x.kind, x.surface_part), (mx_contact3_kind::MX_CONTACT3_VF, mx_surface_part3::MX_SURFACE_FACE));
    // The cube ball lies flat on the faces: at (2, 5, 5) its facet x = −1
    // lies on the face x = 0 over a square, reported by its corners.
    let flat = contacts(m, cube, [2.0, 5.0, 5.0]);
    assert!(flat.len() >= 4 && flat.iter().all(|x| x.flat == 1 && x.radius == 2.0 && x.point[0] == 0.0), "{flat:?}");
    // Every answer equals the Rust tree's.
    let balls = [(octa, Ball3::octahedron()), (cube, Ball3::cube())];
    for (cb, rb) in &balls {
        for p in [[5.0; 3], [2.0, 3.0, 6.0], [2.0, 5.0, 5.0], [1.25, 7.5, 3.0], [9.0, 9.5, 0.5]] {
            let want = rust.tree().exact_contacts(Point3::new(p[0], p[1], p[2]), &rb.reach()).unwrap();
            let got = contacts(m, *cb, p);
            assert_eq!(got.len(), want.contacts.len());
            for (g, w) in got.iter().zip(&want.contacts) {
                assert!(g.radius == want.radius && g.point == w.point.to_array() && g.triangle == w.triangle as usize);
            }
        }
    }
    unsafe {
        mx_ball_free(octa);
        mx_ball_free(cube);
        mx_mesh3d_free(m);
    }
}

/// A cube ball grown from its vertex (−1, −1, −1) at a point of the box's
/// floor: it slides along the floor (a wall of the vertex's cone, which
/// never stops it) and stops flat against the nearer of the walls
/// x = 10, y = 10, at radius (10 − max(x, y)) / 2.
#[test]
fn maximal_balls_on_the_floor_stop_flat_at_the_nearer_wall() {
    let (rust, m) = solid();
    let mut cube = null_mut();
    assert_eq!(unsafe { mx_ball_cube(&mut cube) }, mx_status::MX_OK);
    let ball = Ball3::cube();
    let down = ball.vertices().iter().position(|w| w.x < 0.0 && w.y < 0.0 && w.z < 0.0).unwrap();
    let floor: Vec<usize> = (0..rust.triangles().len())
        .filter(|&k| rust.triangles()[k].iter().all(|&i| rust.positions()[i as usize].z == 0.0))
        .collect();
    assert_eq!(floor.len(), 2);
    for &k in &floor {
        let uv = [0.25, 0.25];
        let [a, b, c] = rust.triangles()[k].map(|i| rust.positions()[i as usize]);
        let p = a + (b - a) * uv[0] + (c - a) * uv[1];
        let want = (10.0 - p.x.max(p.y)) / 2.0;
        let (mut n, mut got) = (0usize, 0usize);
        let call = |buf: *mut mx_contact3, cap: usize, count: &mut usize| unsafe {
            mx_mesh3d_maximal_ball_contacts(m, cube, k, uv.as_ptr(), down, buf, cap, count)
        };
        assert_eq!(call(null_mut(), 0, &mut n), mx_status::MX_OK, "{}", last_message());
        let mut buf = vec![BLANK; n];
        assert_eq!(call(buf.as_mut_ptr(), n, &mut got), mx_status::MX_OK);
        assert!(n >= 2 && got == n, "{n} contacts");
        let rs = rust.tree().maximal_ball_exact_on([a, b, c], (0.25, 0.25), down, &ball.reach()).unwrap();
        for x in &buf {
            assert_eq!(x.radius, want, "{x:?}");
            assert_eq!(x.centre, [p.x + want, p.y + want, want]);
            assert_eq!(x.flat, 1, "{x:?}");
            assert!(x.point[0] == 10.0 || x.point[1] == 10.0, "{x:?}");
        }
        assert_eq!(rs.opposite.len(), n);
    }
    // Out of range and NaN are refused.
    let mut n = 7usize;
    let uv = [0.25, 0.25];
    let st = unsafe { mx_mesh3d_maximal_ball_contacts(m, cube, 99, uv.as_ptr(), down, null_mut(), 0, &mut n) };
    assert_eq!((st, n), (mx_status::MX_ERR_INVALID_ARGUMENT, 7));
    let bad = [f64::NAN, 0.0];
    let st = unsafe { mx_mesh3d_maximal_ball_contacts(m, cube, floor[0], bad.as_ptr(), down, null_mut(), 0, &mut n) };
    assert_eq!((st, n), (mx_status::MX_ERR_NON_FINITE, 7));
    unsafe {
        mx_ball_free(cube);
        mx_mesh3d_free(m);
    }
}

#[test]
fn bad_arguments_leave_the_outputs_alone() {
    let (_, m) = solid();
    let (mut octa, mut square) = (null_mut(), null_mut());
    assert_eq!(unsafe { mx_ball_octahedron(&mut octa) }, mx_status::MX_OK);
    assert_eq!(unsafe { mx_ball_square(&mut square) }, mx_status::MX_OK);
    let p = [5.0, 5.0, 5.0];
    let call = |m: *const mx_mesh3d, b: *const mx_ball, p: *const f64, cap: usize, count: bool| {
        let mut buf = [BLANK; 2];
        let mut n = 77usize;
        let count_ptr = if count { &mut n as *mut usize } else { null_mut() };
        let st = unsafe { mx_mesh3d_ball_contacts(m, b, p, buf.as_mut_ptr(), cap, count_ptr) };
        (st, n, buf)
    };
    let cases = [
        (mx_status::MX_ERR_NULL_ARGUMENT, call(null(), octa, p.as_ptr(), 2, true)),
        (mx_status::MX_ERR_NULL_ARGUMENT, call(m, null(), p.as_ptr(), 2, true)),
        (mx_status::MX_ERR_NULL_ARGUMENT, call(m, octa, null(), 2, true)),
        (mx_status::MX_ERR_NULL_ARGUMENT, call(m, octa, p.as_ptr(), 2, false)),
        (mx_status::MX_ERR_NON_FINITE, call(m, octa, [f64::NAN, 0.0, 0.0].as_ptr(), 2, true)),
        (mx_status::MX_ERR_INVALID_ARGUMENT, call(m, square, p.as_ptr(), 2, true)),
        // Six contacts do not fit in two.
        (mx_status::MX_ERR_BUFFER_TOO_SMALL, call(m, octa, p.as_ptr(), 2, true)),
    ];
    for (want, (st, n, buf)) in cases {
        assert_eq!(st, want, "{}", last_message());
        assert!(!last_message().is_empty());
        assert_eq!(n, 77, "count written on failure");
        assert!(buf.iter().all(|x| *x == BLANK), "buffer written on failure");
    }
    unsafe {
        mx_ball_free(octa);
        mx_ball_free(square);
        mx_mesh3d_free(m);
    }
}
