//! Voronoi diagrams and outer offsets under a polygon ball through the C
//! ABI, called from Rust as a C caller would: labels, regions and nearest
//! sites checked against the gauge distance by brute force, the grown
//! rectangle's area by hand, NULL balls falling back to the Euclidean
//! calls, and errors writing nothing.

mod common;

use common::ffi::{ball, ball_vertices, gauge, last_message};
use medax::ffi::*;
use std::ptr::{null, null_mut};

fn shape(loops: &[&[(f64, f64)]]) -> *mut mx_shape2d {
    let xyb: Vec<f64> = loops.iter().flat_map(|l| l.iter().flat_map(|&(x, y)| [x, y, 0.0])).collect();
    let lens: Vec<usize> = loops.iter().map(|l| l.len()).collect();
    let mut s = null_mut();
    let st = unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), null(), &mut s) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    s
}

fn point_sites(xy: &[f64]) -> mx_sites {
    mx_sites {
        points_xy: xy.as_ptr(),
        point_count: xy.len() / 2,
        curves_xyb: null(),
        curves_xyb_len: 0,
        curve_lengths: null(),
        curve_count: 0,
        regions_xyb: null(),
        regions_xyb_len: 0,
        region_lengths: null(),
        region_count: 0,
        boundary_xyb: null(),
        boundary_count: 0,
    }
}

#[test]
fn points_under_a_hexagon_and_the_triangle() {
    // A jittered grid of points: general position.
    let mut xy = Vec::new();
    for i in 0..6 {
        for j in 0..5 {
            let f = (i * 7 + j * 13) as f64;
            xy.extend([i as f64 + 0.21 * (f * 0.37).sin(), j as f64 + 0.19 * (f * 0.71).cos()]);
        }
    }
    let pts: Vec<(f64, f64)> = xy.chunks_exact(2).map(|c| (c[0], c[1])).collect();
    let sites = point_sites(&xy);
    for spec in ["ngon:6:0.2", "triangle"] {
        let b = ball(spec);
        let v = ball_vertices(b);
        let mut vd = null_mut();
        let st = unsafe { mx_voronoi_compute_with_ball(&sites, b, null(), &mut vd) };
        assert_eq!(st, mx_status::MX_OK, "{spec}: {}", last_message());
        let mut info = mx_voronoi_info { auto_frame: 0, complete: 0, region_count: 0 };
        assert_eq!(unsafe { mx_voronoi_get_info(vd, &mut info) }, mx_status::MX_OK);
        assert_eq!((info.auto_frame, info.complete, info.region_count), (1, 1, pts.len()));
        // Every edge between two points: both at the node radius from its
        // ends (the gauge from the centre to the point), none nearer.
        let mut axis = null();
        assert_eq!(unsafe { mx_voronoi_axis(vd, &mut axis) }, mx_status::MX_OK);
        let mut n = 0;
        assert_eq!(unsafe { mx_axis_edge_count(axis, &mut n) }, mx_status::MX_OK);
        let mut between = 0;
        for i in 0..n {
            let site = mx_site { kind: mx_site_kind::MX_SITE_BOUNDARY, index: 0 };
            let mut ve = mx_voronoi_edge { sides: [site; 2], is_self: 0, in_diagram: 0 };
            assert_eq!(unsafe { mx_voronoi_get_edge(vd, i, &mut ve) }, mx_status::MX_OK);
            let mut e = mx_axis_edge {
                from: 0,
                to: 0,
                kind: mx_conic_kind::MX_CONIC_PARABOLA,
                sites: [mx_axis_site { loop_index: 0, index: 0, is_vertex: 0 }; 2],
            };
            assert_eq!(unsafe { mx_axis_get_edge(axis, i, &mut e) }, mx_status::MX_OK);
            if ve.in_diagram == 0 || ve.sides.iter().any(|s| s.kind != mx_site_kind::MX_SITE_POINT) {
                continue;
            }
            between += 1;
            for end in [e.from, e.to] {
                let mut node = mx_axis_node { x: 0.0, y: 0.0, r: 0.0, kind: mx_node_kind::MX_NODE_JOINT };
                assert_eq!(unsafe { mx_axis_get_node(axis, end, &mut node) }, mx_status::MX_OK);
                let d = |p: (f64, f64)| gauge(&v, (p.0 - node.x, p.1 - node.y));
                for s in ve.sides {
                    assert!((d(pts[s.index]) - node.r).abs() < 1e-9, "{spec}: edge {i} side {}", s.index);
                }
                let nearest = pts.iter().map(|&p| d(p)).fold(f64::INFINITY, f64::min);
                assert!(nearest > node.r - 1e-9, "{spec}: edge {i}: a point nearer than r {}", node.r);
            }
        }
        assert!(between >= pts.len(), "{spec}: only {between} edges between points");
        // Regions: one closed walk each.
        for k in 0..pts.len() {
            let mut r = mx_voronoi_region { walk_length: 0, walks: 0, self_edge_count: 0, unbounded: 0 };
            let st = unsafe { mx_voronoi_get_region(vd, mx_site_kind::MX_SITE_POINT as u32, k, &mut r) };
            assert_eq!(st, mx_status::MX_OK);
            assert_eq!(r.walks, 1, "{spec}: region of point {k}");
            assert!(r.walk_length >= 3);
        }
        // Nearest sites under the ball's distance, against the brute force.
        for q in 0..200 {
            let p = (-1.0 + 7.0 * ((q as f64) * 0.618).fract(), -1.0 + 6.0 * ((q as f64) * 0.414).fract());
            let mut ns = mx_nearest_site {
                site: mx_site { kind: mx_site_kind::MX_SITE_BOUNDARY, index: 0 },
                distance: 0.0,
                foot_x: 0.0,
                foot_y: 0.0,
            };
            assert_eq!(unsafe { mx_voronoi_nearest_site(vd, p.0, p.1, &mut ns) }, mx_status::MX_OK);
            let d = |s: (f64, f64)| gauge(&v, (s.0 - p.0, s.1 - p.1));
            let best = pts.iter().map(|&s| d(s)).fold(f64::INFINITY, f64::min);
            assert_eq!(ns.site.kind, mx_site_kind::MX_SITE_POINT);
            assert!((ns.distance - best).abs() < 1e-12, "{spec}: nearest to {p:?}: {} against {best}", ns.distance);
            assert!((d(pts[ns.site.index]) - best).abs() < 1e-12);
            assert_eq!((ns.foot_x, ns.foot_y), pts[ns.site.index]);
        }
        unsafe { mx_voronoi_free(vd) };
        unsafe { mx_ball_free(b) };
    }
}

#[test]
fn null_ball_is_the_euclidean_diagram_and_errors_write_nothing() {
    let xy = [0.0, 0.0, 3.0, 0.5, 1.0, 2.0];
    let sites = point_sites(&xy);
    let mut vd = null_mut();
    assert_eq!(unsafe { mx_voronoi_compute_with_ball(&sites, null(), null(), &mut vd) }, mx_status::MX_OK);
    let mut ns = mx_nearest_site {
        site: mx_site { kind: mx_site_kind::MX_SITE_BOUNDARY, index: 0 },
        distance: 0.0,
        foot_x: 0.0,
        foot_y: 0.0,
    };
    assert_eq!(unsafe { mx_voronoi_nearest_site(vd, 2.9, 0.0, &mut ns) }, mx_status::MX_OK);
    assert_eq!(ns.site.index, 1);
    assert!((ns.distance - (0.01f64 + 0.25).sqrt()).abs() < 1e-12);
    unsafe { mx_voronoi_free(vd) };
    let sq = ball("square");
    let sentinel = 0x5EE7 as *mut mx_voronoi;
    // No sites.
    let mut out = sentinel;
    let none = point_sites(&[]);
    assert_eq!(unsafe { mx_voronoi_compute_with_ball(&none, sq, null(), &mut out) }, mx_status::MX_ERR_EMPTY);
    assert_eq!(out, sentinel);
    // An arc in a curve site: unsupported under a ball, named.
    let curve = [0.0, 0.0, 0.5, 2.0, 0.0, 0.0];
    let lens = [2usize];
    let mut arcs = point_sites(&[]);
    arcs.curves_xyb = curve.as_ptr();
    arcs.curves_xyb_len = curve.len();
    arcs.curve_lengths = lens.as_ptr();
    arcs.curve_count = 1;
    assert_eq!(unsafe { mx_voronoi_compute_with_ball(&arcs, sq, null(), &mut out) }, mx_status::MX_ERR_UNSUPPORTED);
    assert_eq!(out, sentinel);
    assert!(last_message().contains("curve site 0"), "{}", last_message());
    // Non-finite points.
    let bad = [0.0, f64::NAN];
    assert_ne!(unsafe { mx_voronoi_compute_with_ball(&point_sites(&bad), sq, null(), &mut out) }, mx_status::MX_OK);
    assert_eq!(out, sentinel);
    unsafe { mx_ball_free(sq) };
}

fn layer_info(l: *const mx_offset_layer) -> mx_offset_layer_info {
    let mut info = std::mem::MaybeUninit::<mx_offset_layer_info>::zeroed();
    assert_eq!(unsafe { mx_offset_layer_get_info(l, info.as_mut_ptr()) }, mx_status::MX_OK);
    unsafe { info.assume_init() }
}

#[test]
fn outer_offsets_of_a_plate() {
    // A 6 × 2 rectangle with a 2 × 1 hole at (1, 0.5)–(3, 1.5).
    let s =
        shape(&[&[(0.0, 0.0), (6.0, 0.0), (6.0, 2.0), (0.0, 2.0)], &[(1.0, 0.5), (1.0, 1.5), (3.0, 1.5), (3.0, 0.5)]]);
    let sq = ball("square");
    // Under the square the grown rectangle is the 7 × 3 rectangle; the
    // hole shrinks to 1 × 0 and vanishes at 0.5: area 21 exactly.
    let mut l = null_mut();
    let st = unsafe { mx_shape2d_outer_offset_with_ball(s, sq, 0.5, &mut l) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let info = layer_info(l);
    assert_eq!(info.distance, -0.5);
    assert!((info.area - 21.0).abs() < 1e-9, "area {}", info.area);
    assert_eq!(info.loop_count, 1);
    unsafe { mx_offset_layer_free(l) };
    // At 0.25 the hole remains as 1.5 × 0.5 (clockwise): 6.5 × 2.5 − 0.75.
    let st = unsafe { mx_shape2d_outer_offset_with_ball(s, sq, 0.25, &mut l) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let info = layer_info(l);
    assert!((info.area - (6.5 * 2.5 - 0.75)).abs() < 1e-9, "area {}", info.area);
    assert_eq!((info.loop_count, info.region_count), (2, 1));
    unsafe { mx_offset_layer_free(l) };
    // NULL ball: the Euclidean outer offset, rounded corners: the
    // rectangle grown by 0.5 has area 12 + 2·0.5·8 + π·0.25; the hole's
    // Euclidean inner offset at 0.5 is empty.
    let st = unsafe { mx_shape2d_outer_offset_with_ball(s, null(), 0.5, &mut l) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let info = layer_info(l);
    let want = 12.0 + 8.0 + std::f64::consts::PI * 0.25;
    assert!((info.area - want).abs() < 1e-9, "area {} against {want}", info.area);
    unsafe { mx_offset_layer_free(l) };
    // Bad distances and handles write nothing.
    for d in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let mut l = 0x5EE7 as *mut mx_offset_layer;
        assert_eq!(unsafe { mx_shape2d_outer_offset_with_ball(s, sq, d, &mut l) }, mx_status::MX_ERR_INVALID_ARGUMENT);
        assert_eq!(l, 0x5EE7 as *mut mx_offset_layer);
    }
    let mut l = 0x5EE7 as *mut mx_offset_layer;
    assert_eq!(unsafe { mx_shape2d_outer_offset_with_ball(null(), sq, 1.0, &mut l) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(l, 0x5EE7 as *mut mx_offset_layer);
    // An arc under a ball: unsupported.
    let xyb = [0.0, 0.0, 0.0, 4.0, 0.0, 0.5, 4.0, 4.0, 0.0, 0.0, 4.0, 0.0];
    let mut arc = null_mut();
    assert_eq!(
        unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), 12, [4usize].as_ptr(), 1, null(), &mut arc) },
        mx_status::MX_OK
    );
    assert_eq!(unsafe { mx_shape2d_outer_offset_with_ball(arc, sq, 1.0, &mut l) }, mx_status::MX_ERR_UNSUPPORTED);
    assert_eq!(l, 0x5EE7 as *mut mx_offset_layer);
    unsafe { mx_shape2d_free(arc) };
    unsafe { mx_ball_free(sq) };
    unsafe { mx_shape2d_free(s) };
}
