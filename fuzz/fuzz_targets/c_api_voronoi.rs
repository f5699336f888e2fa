//! The C entry point for Voronoi sites with arbitrary arrays and lengths
//! (points, curves, regions, an optional boundary; lengths taken from the
//! arrays so the pointers stay valid): statuses only, never a panic
//! (MX_ERR_PANIC) or a crash; the out-param is written only on success,
//! and every region of a computed diagram is one closed walk. Under no
//! ball or one of three (`mx_voronoi_compute_with_ball`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::ffi::*;

fuzz_target!(|input: (Vec<i8>, Vec<i8>, Vec<u8>, Vec<i8>, Vec<u8>, bool, u8)| {
    let (points, curves, curve_lens, regions, region_lens, framed, which) = input;
    let mut ball: *mut mx_ball = std::ptr::null_mut();
    let made = match which % 4 {
        0 => mx_status::MX_OK,
        1 => unsafe { mx_ball_square(&mut ball) },
        2 => unsafe { mx_ball_triangle(&mut ball) },
        _ => unsafe { mx_ball_regular(6, 0.2, &mut ball) },
    };
    assert_eq!(made, mx_status::MX_OK);
    let coords = |v: &[i8]| v.iter().take(96).map(|&c| c as f64).collect::<Vec<f64>>();
    let (points, curves, regions) = (coords(&points), coords(&curves), coords(&regions));
    let lens = |l: &[u8]| l.iter().take(6).map(|&n| n as usize % 6).collect::<Vec<usize>>();
    let (curve_lens, region_lens) = (lens(&curve_lens), lens(&region_lens));
    let frame = [-300.0, -300.0, 0.0, 300.0, -300.0, 0.0, 300.0, 300.0, 0.0, -300.0, 300.0, 0.0];
    let sites = mx_sites {
        points_xy: points.as_ptr(),
        point_count: points.len() / 2,
        curves_xyb: curves.as_ptr(),
        curves_xyb_len: curves.len(),
        curve_lengths: curve_lens.as_ptr(),
        curve_count: curve_lens.len(),
        regions_xyb: regions.as_ptr(),
        regions_xyb_len: regions.len(),
        region_lengths: region_lens.as_ptr(),
        region_count: region_lens.len(),
        boundary_xyb: if framed { frame.as_ptr() } else { std::ptr::null() },
        boundary_count: if framed { 4 } else { 0 },
    };
    let sentinel = 0x5EE7 as *mut mx_voronoi;
    let mut out = sentinel;
    let status = unsafe { mx_voronoi_compute_with_ball(&sites, ball, std::ptr::null(), &mut out) };
    assert_ne!(status, mx_status::MX_ERR_PANIC);
    if status != mx_status::MX_OK {
        assert_eq!(out, sentinel);
        assert!(mx_last_error_length() > 0);
        unsafe { mx_ball_free(ball) };
        return;
    }
    let mut info = mx_voronoi_info { auto_frame: 0, complete: 0, region_count: 0 };
    assert_eq!(unsafe { mx_voronoi_get_info(out, &mut info) }, mx_status::MX_OK);
    let kinds = [(0u32, points.len() / 2), (1, curve_lens.len()), (2, region_lens.len())];
    for (kind, count) in kinds {
        for i in 0..count {
            let mut r = mx_voronoi_region { walk_length: 0, walks: 0, self_edge_count: 0, unbounded: 0 };
            assert_eq!(unsafe { mx_voronoi_get_region(out, kind, i, &mut r) }, mx_status::MX_OK);
            assert!(r.walks <= 1, "site kind {kind} index {i}: {} walks", r.walks);
        }
    }
    let mut near = mx_nearest_site {
        site: mx_site { kind: mx_site_kind::MX_SITE_BOUNDARY, index: 0 },
        distance: 0.0,
        foot_x: 0.0,
        foot_y: 0.0,
    };
    let st = unsafe { mx_voronoi_nearest_site(out, 1.5, -2.5, &mut near) };
    assert!(st == mx_status::MX_OK && near.distance >= 0.0, "{st:?}");
    unsafe { mx_voronoi_free(out) };
    unsafe { mx_ball_free(ball) };
});
