//! Rays and intersection tests of a solid through the C API: answers
//! (against the Rust tree and closed forms on a box with a cavity), the
//! batched buffer protocol, NULL arguments, NaN and zero directions, with
//! out-parameters left alone on every failure.

mod common;

use common::ffi::{c_solid, last_message};
use medax::ffi::*;
use medax::kernel::{BBox3, Point3};
use medax::shape::mesh_samples::{cuboid, torus, union};
use medax::shape::Mesh3d;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::ptr::{null, null_mut};

/// A box 0..10 with a cavity 3..7, and a torus beside it around (30, 0, 0).
fn solid() -> (Mesh3d, *mut mx_mesh3d) {
    let (tv, tt) = torus(3.0, 1.0, 24, 12);
    let torus_aside = (tv.iter().map(|p| [p[0] + 30.0, p[1], p[2]]).collect::<Vec<_>>(), tt);
    let soup = union(&[cuboid([0.0; 3], [10.0; 3]), cuboid([3.0; 3], [7.0; 3]), torus_aside]);
    c_solid(&soup)
}

const SENTINEL: mx_ray_hit3 = mx_ray_hit3 { hit: 7, t: -1.0, point: [-1.0; 3], triangle: 99 };

fn first_hit(m: *const mx_mesh3d, o: [f64; 3], d: [f64; 3]) -> (mx_status, mx_ray_hit3) {
    let mut h = SENTINEL;
    let st = unsafe { mx_mesh3d_first_hit(m, o.as_ptr(), d.as_ptr(), &mut h) };
    (st, h)
}

#[test]
fn first_hits_answer_as_the_tree_and_the_box() {
    let (rust, m) = solid();
    // Up through the bottom face, from inside the material to the
    // cavity, from inside the cavity, and past everything.
    let (st, h) = first_hit(m, [5.0, 5.0, -20.0], [0.0, 0.0, 2.0]);
    assert_eq!(st, mx_status::MX_OK);
    assert_eq!((h.hit, h.t, h.point), (1, 10.0, [5.0, 5.0, 0.0]));
    let t = rust.triangles()[h.triangle].map(|v| rust.positions()[v as usize]);
    assert!(t.iter().all(|p| p.z == 0.0), "{t:?}");
    assert_eq!(first_hit(m, [5.0, 5.0, 1.0], [0.0, 0.0, 1.0]).1.point, [5.0, 5.0, 3.0]);
    assert_eq!(first_hit(m, [5.0, 5.0, 5.0], [0.0, 0.0, -4.0]).1.t, 0.5);
    let (st, h) = first_hit(m, [5.0, 5.0, 20.0], [0.0, 0.0, 1.0]);
    assert_eq!((st, h), (mx_status::MX_OK, mx_ray_hit3 { hit: 0, t: 0.0, point: [0.0; 3], triangle: 0 }));
    // Many rays at once: the same answers as one by one and as the tree.
    let mut rng = SmallRng::seed_from_u64(4);
    let mut rays = Vec::new();
    for _ in 0..500 {
        let mut at = |lo: f64, hi: f64| [rng.gen_range(lo..hi), rng.gen_range(-5.0..15.0), rng.gen_range(-5.0..15.0)];
        let (o, toward) = (at(-5.0, 40.0), at(0.0, 35.0));
        rays.extend(o);
        rays.extend([0, 1, 2].map(|k| toward[k] - o[k]));
    }
    let n = rays.len() / 6;
    let mut count = 0;
    let st = unsafe { mx_mesh3d_first_hits(m, rays.as_ptr(), rays.len(), null_mut(), 0, &mut count) };
    assert_eq!((st, count), (mx_status::MX_OK, n));
    let mut hits = vec![SENTINEL; n];
    let st = unsafe { mx_mesh3d_first_hits(m, rays.as_ptr(), rays.len(), hits.as_mut_ptr(), n - 1, &mut count) };
    assert_eq!(st, mx_status::MX_ERR_BUFFER_TOO_SMALL);
    assert!(hits.iter().all(|h| *h == SENTINEL) && count == n);
    count = 0;
    let st = unsafe { mx_mesh3d_first_hits(m, rays.as_ptr(), rays.len(), hits.as_mut_ptr(), n, &mut count) };
    assert_eq!((st, count), (mx_status::MX_OK, n));
    let mut met = 0;
    for (six, h) in rays.chunks_exact(6).zip(&hits) {
        let (o, d) = ([six[0], six[1], six[2]], [six[3], six[4], six[5]]);
        assert_eq!(first_hit(m, o, d).1, *h);
        let rust_hit = rust.tree().first_hit(Point3::from_array(o), Point3::from_array(d));
        assert_eq!(h.hit == 1, rust_hit.is_some());
        if let Some(r) = rust_hit {
            assert_eq!((h.t, h.point, h.triangle), (r.t, r.point.to_array(), r.triangle as usize));
            met += 1;
        }
    }
    assert!(met > 50 && met < n, "{met}");
    // No rays: a size query and a fill of nothing.
    assert_eq!(unsafe { mx_mesh3d_first_hits(m, null(), 0, null_mut(), 0, &mut count) }, mx_status::MX_OK);
    assert_eq!(count, 0);
    unsafe { mx_mesh3d_free(m) };
}

#[test]
fn intersection_tests_answer_exactly() {
    let (rust, m) = solid();
    let seg = |a: [f64; 3], b: [f64; 3]| {
        let mut out = -1;
        assert_eq!(unsafe { mx_mesh3d_intersects_segment(m, a.as_ptr(), b.as_ptr(), &mut out) }, mx_status::MX_OK);
        out
    };
    let tri = |c: [f64; 9]| {
        let mut out = -1;
        assert_eq!(unsafe { mx_mesh3d_intersects_triangle(m, c.as_ptr(), &mut out) }, mx_status::MX_OK);
        out
    };
    let boxed = |lo: [f64; 3], hi: [f64; 3]| {
        let mut out = -1;
        assert_eq!(unsafe { mx_mesh3d_intersects_box(m, lo.as_ptr(), hi.as_ptr(), &mut out) }, mx_status::MX_OK);
        out
    };
    let above = f64::from_bits(10f64.to_bits() + 1);
    // Segments: through a face, ending exactly on one, one ulp short,
    // inside the material, inside the cavity, a point on the surface.
    assert_eq!(seg([5.0, 5.0, 20.0], [5.0, 5.0, 8.0]), 1);
    assert_eq!(seg([5.0, 5.0, 20.0], [5.0, 5.0, 10.0]), 1);
    assert_eq!(seg([5.0, 5.0, 20.0], [5.0, 5.0, above]), 0);
    assert_eq!(seg([1.0, 1.0, 1.0], [9.0, 1.0, 9.0]), 0);
    assert_eq!(seg([4.0, 4.0, 4.0], [6.0, 6.0, 6.0]), 0);
    assert_eq!(seg([3.0, 5.0, 5.0], [3.0, 5.0, 5.0]), 1);
    // Triangles: across the cavity's wall, in the cavity, flat on a
    // face, degenerate (a segment, a point) on and off the surface.
    assert_eq!(tri([5.0, 5.0, 5.0, 8.0, 5.0, 5.0, 5.0, 6.0, 5.0]), 1);
    assert_eq!(tri([4.0, 4.0, 4.0, 6.0, 4.0, 4.0, 4.0, 6.0, 6.0]), 0);
    assert_eq!(tri([-1.0, -1.0, 10.0, 1.0, -1.0, 10.0, -1.0, 1.0, 10.0]), 1);
    assert_eq!(tri([-1.0, -1.0, above, 1.0, -1.0, above, -1.0, 1.0, above]), 0);
    assert_eq!(tri([5.0, 5.0, 20.0, 5.0, 5.0, 10.0, 5.0, 5.0, 15.0]), 1);
    assert_eq!(tri([5.0, 5.0, 20.0, 5.0, 5.0, above, 5.0, 5.0, 15.0]), 0);
    assert_eq!(tri([7.0, 5.0, 5.0, 7.0, 5.0, 5.0, 7.0, 5.0, 5.0]), 1);
    // Boxes: touching a face, a corner, flat, around the cavity only.
    assert_eq!(boxed([10.0, 2.0, 2.0], [12.0, 3.0, 3.0]), 1);
    assert_eq!(boxed([above, 2.0, 2.0], [12.0, 3.0, 3.0]), 0);
    assert_eq!(boxed([10.0, 10.0, 10.0], [11.0, 11.0, 11.0]), 1);
    assert_eq!(boxed([-5.0, -5.0, 10.0], [20.0, 20.0, 10.0]), 1);
    assert_eq!(boxed([3.5, 3.5, 3.5], [6.5, 6.5, 6.5]), 0);
    assert_eq!(boxed([2.5, 3.5, 3.5], [6.5, 6.5, 6.5]), 1);
    // The torus beside: its hole is empty, its tube is not.
    assert_eq!(boxed([29.5, -0.5, -0.5], [30.5, 0.5, 0.5]), 0);
    assert_eq!(boxed([29.5, -0.5, -0.5], [32.5, 0.5, 0.5]), 1);
    let b = BBox3 { min: Point3::new(29.5, -0.5, -0.5), max: Point3::new(32.5, 0.5, 0.5) };
    assert!(rust.tree().intersects_box(&b));
    unsafe { mx_mesh3d_free(m) };
}

#[test]
fn bad_arguments_fail_and_leave_the_outputs() {
    let (_, m) = solid();
    let (o, d, nan) = ([5.0, 5.0, -20.0], [0.0, 0.0, 1.0], [0.0, f64::NAN, 0.0]);
    let mut h = SENTINEL;
    // NULL handle, NULL out, NULL inputs.
    let st = unsafe { mx_mesh3d_first_hit(null(), o.as_ptr(), d.as_ptr(), &mut h) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    assert!(last_message().contains("mesh"), "{}", last_message());
    assert_eq!(unsafe { mx_mesh3d_first_hit(m, o.as_ptr(), d.as_ptr(), null_mut()) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_mesh3d_first_hit(m, null(), d.as_ptr(), &mut h) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert!(last_message().contains("origin"), "{}", last_message());
    // NaN and infinite numbers, named; a zero direction.
    assert_eq!(first_hit(m, nan, d), (mx_status::MX_ERR_NON_FINITE, SENTINEL));
    assert!(last_message().contains("`origin`"), "{}", last_message());
    assert_eq!(first_hit(m, o, [f64::INFINITY, 0.0, 0.0]), (mx_status::MX_ERR_NON_FINITE, SENTINEL));
    assert!(last_message().contains("`direction`"), "{}", last_message());
    assert_eq!(first_hit(m, o, [0.0, -0.0, 0.0]), (mx_status::MX_ERR_INVALID_ARGUMENT, SENTINEL));
    assert!(last_message().contains("`direction` is zero"), "{}", last_message());
    // The batch: NaN and zero directions name the ray; a length that is
    // no multiple of 6; NULL count, rays and hits.
    let mut rays = vec![5.0, 5.0, -20.0, 0.0, 0.0, 1.0, 1.0, 2.0, 3.0, 0.0, 0.0, 0.0];
    let mut hits = [SENTINEL; 2];
    let mut count = 77;
    let batch = |rays: &[f64], hits: &mut [mx_ray_hit3], count: &mut usize| unsafe {
        mx_mesh3d_first_hits(m, rays.as_ptr(), rays.len(), hits.as_mut_ptr(), hits.len(), count)
    };
    assert_eq!(batch(&rays, &mut hits, &mut count), mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("ray 1: the direction is zero"), "{}", last_message());
    rays[9] = f64::NAN;
    assert_eq!(batch(&rays, &mut hits, &mut count), mx_status::MX_ERR_NON_FINITE);
    assert!(last_message().contains("ray 1 has a NaN"), "{}", last_message());
    assert_eq!(batch(&rays[..7], &mut hits, &mut count), mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(hits.iter().all(|h| *h == SENTINEL) && count == 77);
    let st = unsafe { mx_mesh3d_first_hits(m, rays.as_ptr(), 6, hits.as_mut_ptr(), 2, null_mut()) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    let st = unsafe { mx_mesh3d_first_hits(m, null(), 6, hits.as_mut_ptr(), 2, &mut count) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    let st = unsafe { mx_mesh3d_first_hits(m, rays.as_ptr(), 6, null_mut(), 2, &mut count) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    let st = unsafe { mx_mesh3d_first_hits(null(), rays.as_ptr(), 6, hits.as_mut_ptr(), 2, &mut count) };
    assert_eq!(st, mx_status::MX_ERR_NULL_ARGUMENT);
    assert!(count == 77 && hits.iter().all(|h| *h == SENTINEL));
    // The tests: NULL, NaN, a box with min > max.
    let mut out = -5;
    let (a, b) = ([0.0; 3], [1.0; 3]);
    assert_eq!(
        unsafe { mx_mesh3d_intersects_segment(null(), a.as_ptr(), b.as_ptr(), &mut out) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(
        unsafe { mx_mesh3d_intersects_segment(m, a.as_ptr(), null(), &mut out) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(
        unsafe { mx_mesh3d_intersects_segment(m, a.as_ptr(), b.as_ptr(), null_mut()) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(
        unsafe { mx_mesh3d_intersects_segment(m, nan.as_ptr(), b.as_ptr(), &mut out) },
        mx_status::MX_ERR_NON_FINITE
    );
    assert!(last_message().contains("`a`"), "{}", last_message());
    let mut nine = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    nine[7] = f64::NEG_INFINITY;
    assert_eq!(unsafe { mx_mesh3d_intersects_triangle(m, nine.as_ptr(), &mut out) }, mx_status::MX_ERR_NON_FINITE);
    assert!(last_message().contains("`xyz9` corner 2"), "{}", last_message());
    assert_eq!(unsafe { mx_mesh3d_intersects_triangle(m, null(), &mut out) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(
        unsafe { mx_mesh3d_intersects_triangle(null(), nine.as_ptr(), &mut out) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(
        unsafe { mx_mesh3d_intersects_box(m, b.as_ptr(), a.as_ptr(), &mut out) },
        mx_status::MX_ERR_INVALID_ARGUMENT
    );
    assert!(last_message().contains("min[0] = 1 exceeds max[0] = 0"), "{}", last_message());
    assert_eq!(
        unsafe { mx_mesh3d_intersects_box(m, a.as_ptr(), nan.as_ptr(), &mut out) },
        mx_status::MX_ERR_NON_FINITE
    );
    assert!(last_message().contains("`max`"), "{}", last_message());
    assert_eq!(
        unsafe { mx_mesh3d_intersects_box(m, a.as_ptr(), b.as_ptr(), null_mut()) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(
        unsafe { mx_mesh3d_intersects_box(null(), a.as_ptr(), b.as_ptr(), &mut out) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(out, -5);
    unsafe { mx_mesh3d_free(m) };
}
