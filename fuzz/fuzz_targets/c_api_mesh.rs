//! Solids through the C API: any bytes as a file of the format the first
//! byte picks (or guessed), and any numbers as vertex and triangle arrays
//! with an optional welding tolerance. Every call gives a status, never a
//! panic (MX_ERR_PANIC) or a crash; a solid that builds answers every query
//! consistently (counts, buffers, components). Its rays and intersection
//! tests take the fuzzed points (often the solid's own vertices) as
//! origins, directions, segments, triangles and boxes: failures leave the
//! outputs alone, the batch answers as one ray at a time, and the exact
//! tests agree with the exact sides (a point meets the surface exactly
//! when it lies on it; a segment from inside to outside meets it).
//! Largest and maximal* balls under a tetrahedron at the same points.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::ffi::*;
use std::ptr::{null, null_mut};

fn side(m: *const mx_mesh3d, p: &[f64; 3]) -> Option<mx_point_side> {
    let mut s = mx_point_side::MX_OUTSIDE;
    (unsafe { mx_mesh3d_side(m, p.as_ptr(), &mut s) } == mx_status::MX_OK).then_some(s)
}

fn queries(m: *const mx_mesh3d, points: &[[f64; 3]]) {
    let sentinel = mx_ray_hit3 { hit: 7, t: -1.0, point: [-1.0; 3], triangle: 9 };
    let mut rays = Vec::new();
    let mut single = Vec::new();
    for w in points.windows(2).take(16) {
        let (a, b) = (&w[0], &w[1]);
        let mut h = sentinel;
        let st = unsafe { mx_mesh3d_first_hit(m, a.as_ptr(), b.as_ptr(), &mut h) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st == mx_status::MX_OK {
            assert!(h.hit == 0 || (h.hit == 1 && h.t >= 0.0));
            rays.extend(a.iter().chain(b));
            single.push(h);
        } else {
            assert_eq!(h, sentinel);
        }
        let mut out = -1;
        let st = unsafe { mx_mesh3d_intersects_segment(m, a.as_ptr(), b.as_ptr(), &mut out) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st != mx_status::MX_OK {
            assert_eq!(out, -1);
            continue;
        }
        assert!(out == 0 || out == 1);
        let (sa, sb) = (side(m, a), side(m, b));
        if a == b {
            assert_eq!(out == 1, sa == Some(mx_point_side::MX_ON_SURFACE));
        }
        if let (Some(x), Some(y)) = (sa, sb) {
            if x != y || x == mx_point_side::MX_ON_SURFACE {
                assert_eq!(out, 1, "{a:?} {x:?} {b:?} {y:?}");
            }
        }
        let mut on = -1;
        let st = unsafe { mx_mesh3d_intersects_box(m, a.as_ptr(), a.as_ptr(), &mut on) };
        assert_eq!(st, mx_status::MX_OK);
        assert_eq!(on == 1, sa == Some(mx_point_side::MX_ON_SURFACE));
        let st = unsafe { mx_mesh3d_intersects_box(m, a.as_ptr(), b.as_ptr(), &mut on) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st == mx_status::MX_OK && out == 1 {
            // The box spanned by a segment holds all of it.
            assert_eq!(on, 1);
        }
    }
    for w in points.windows(3).take(16) {
        let nine: Vec<f64> = w.iter().flatten().copied().collect();
        let mut out = -1;
        let st = unsafe { mx_mesh3d_intersects_triangle(m, nine.as_ptr(), &mut out) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st != mx_status::MX_OK {
            assert_eq!(out, -1);
            continue;
        }
        // A triangle holds its edges.
        let mut edge = -1;
        assert_eq!(
            unsafe { mx_mesh3d_intersects_segment(m, w[0].as_ptr(), w[1].as_ptr(), &mut edge) },
            mx_status::MX_OK
        );
        assert!(edge == 0 || out == 1);
    }
    let n = rays.len() / 6;
    let mut hits = vec![sentinel; n];
    let mut count = 0;
    let st = unsafe { mx_mesh3d_first_hits(m, rays.as_ptr(), rays.len(), hits.as_mut_ptr(), n, &mut count) };
    if n > 0 {
        assert_eq!(st, mx_status::MX_OK);
        assert_eq!((count, &hits), (n, &single));
    }
}

fn check(m: *mut mx_mesh3d, points: &[[f64; 3]]) {
    let mut i = unsafe { std::mem::zeroed::<mx_mesh3d_info>() };
    assert_eq!(unsafe { mx_mesh3d_get_info(m, &mut i) }, mx_status::MX_OK);
    assert!(i.triangle_count >= 4 && i.vertex_count >= 4 && i.component_count >= 1);
    let mut n = 0;
    assert_eq!(unsafe { mx_mesh3d_triangles(m, null_mut(), 0, &mut n) }, mx_status::MX_OK);
    let mut abc = vec![0u32; 3 * n];
    assert_eq!(unsafe { mx_mesh3d_triangles(m, abc.as_mut_ptr(), n, &mut n) }, mx_status::MX_OK);
    assert!(abc.iter().all(|&v| (v as usize) < i.vertex_count));
    for c in 0..i.component_count {
        let mut comp = unsafe { std::mem::zeroed::<mx_mesh3d_component>() };
        assert_eq!(unsafe { mx_mesh3d_get_component(m, c, &mut comp) }, mx_status::MX_OK);
        assert!(comp.triangle_count >= 4);
    }
    queries(m, points);
    balls(m, points);
    unsafe { mx_mesh3d_free(m) };
}

/// Largest balls (in f64 and with exact contacts) and maximal* balls
/// under a tetrahedron at the fuzzed points
/// (often the solid's own vertices, so on the surface): a status, never a
/// panic; a largest ball's radius is finite and ≥ 0, a maximal* ball's
/// is ≥ 0 (infinite only without an opposite contact), and the batch
/// answers as one point at a time.
fn balls(m: *const mx_mesh3d, points: &[[f64; 3]]) {
    let mut tetra = null_mut();
    assert_eq!(unsafe { mx_ball_tetrahedron(&mut tetra) }, mx_status::MX_OK);
    let mut single = Vec::new();
    let (mut xyz, mut vs) = (Vec::new(), Vec::new());
    for (i, p) in points.iter().take(8).enumerate() {
        let mut q = unsafe { std::mem::zeroed::<mx_point_query3>() };
        let st = unsafe { mx_mesh3d_query_point(m, tetra, p.as_ptr(), &mut q) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st == mx_status::MX_OK && q.has_ball == 1 {
            assert!(q.ball_radius.is_finite() && q.ball_radius >= 0.0);
        }
        // Exact contacts: at least one, all at one radius, near the f64 one.
        let mut n = 0usize;
        let st = unsafe { mx_mesh3d_ball_contacts(m, tetra, p.as_ptr(), null_mut(), 0, &mut n) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st == mx_status::MX_OK {
            assert!(n >= 1);
            let mut cs = vec![unsafe { std::mem::zeroed::<mx_contact3>() }; n];
            let st = unsafe { mx_mesh3d_ball_contacts(m, tetra, p.as_ptr(), cs.as_mut_ptr(), n, &mut n) };
            assert_eq!(st, mx_status::MX_OK);
            assert!(cs.iter().all(|c| c.radius == cs[0].radius && c.radius >= 0.0));
            // The exact maximal* ball at a point of the first triangle.
            let mut k = 0usize;
            let uv = [0.25, 0.5];
            let st = unsafe { mx_mesh3d_maximal_ball_contacts(m, tetra, 0, uv.as_ptr(), i % 4, null_mut(), 0, &mut k) };
            assert_ne!(st, mx_status::MX_ERR_PANIC);
            if q.has_ball == 1 && q.ball_radius.is_finite() && q.ball_radius > 0.0 {
                let r = cs[0].radius;
                assert!((r - q.ball_radius).abs() <= 1e-6 * (r + 1.0) || !r.is_finite(), "{r} vs {}", q.ball_radius);
            }
        }
        let mut b = unsafe { std::mem::zeroed::<mx_maximal_ball3>() };
        let st = unsafe { mx_mesh3d_maximal_ball(m, tetra, p.as_ptr(), i % 5, &mut b) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st == mx_status::MX_OK {
            assert!(b.radius >= 0.0 && (b.radius.is_finite() || b.has_opposite == 0));
            if i % 5 < 4 {
                single.push(b);
                xyz.extend(p);
                vs.push(i % 5);
            }
        }
    }
    let mut out = vec![unsafe { std::mem::zeroed::<mx_maximal_ball3>() }; vs.len()];
    let mut count = 0;
    let st = unsafe {
        mx_mesh3d_maximal_balls(m, tetra, xyz.as_ptr(), xyz.len(), vs.as_ptr(), vs.len(), out.as_mut_ptr(), out.len(), &mut count)
    };
    if !vs.is_empty() {
        assert_eq!(st, mx_status::MX_OK);
        assert_eq!(count, vs.len());
        for (a, b) in out.iter().zip(&single) {
            assert!(a.radius == b.radius || (a.radius.is_nan() && b.radius.is_nan()));
        }
    }
    unsafe { mx_ball_free(tetra) };
}

fuzz_target!(|input: (u8, f64, Vec<[f64; 3]>, Vec<[u8; 3]>, &[u8])| {
    let (choice, tolerance, points, tris, data) = input;
    let format = [0u32, 4, 5, 6, 7, 1][usize::from(choice % 6)];
    let sentinel = 0x1 as *mut mx_mesh3d;
    let mut m = sentinel;
    let st = unsafe { mx_mesh3d_from_memory(data.as_ptr(), data.len(), format, null(), &mut m) };
    assert_ne!(st, mx_status::MX_ERR_PANIC);
    if st == mx_status::MX_OK {
        check(m, &points);
    } else {
        assert_eq!(m, sentinel);
    }
    let xyz: Vec<f64> = points.iter().flatten().copied().collect();
    let n = points.len().max(1);
    let abc: Vec<u32> = tris.iter().flatten().map(|&v| u32::from(v) % (n as u32 + 1)).collect();
    let mut o = unsafe { std::mem::zeroed::<mx_mesh_options>() };
    unsafe { mx_mesh_options_init(&mut o, std::mem::size_of::<mx_mesh_options>()) };
    o.weld_tolerance = if choice & 0x80 != 0 { tolerance } else { 0.0 };
    o.threads = 0; // a pool per call would leave its threads' TLS to the leak checker
    let mut m = sentinel;
    let st = unsafe { mx_mesh3d_from_arrays(xyz.as_ptr(), xyz.len(), abc.as_ptr(), abc.len(), &o, &mut m) };
    assert_ne!(st, mx_status::MX_ERR_PANIC);
    if st == mx_status::MX_OK {
        check(m, &points);
    } else {
        assert_eq!(m, sentinel);
    }
});
