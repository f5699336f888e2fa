//! Voronoi diagrams through the C ABI, called from Rust as a C caller
//! would: labels against distances computed here from the input arrays,
//! region walks that close, nearest sites, size queries, errors that leave
//! out-params alone, cancellation and NULL handling.

use medax::ffi::*;
use std::ffi::{c_int, c_void, CStr};
use std::ptr::{null, null_mut};

const SENTINEL: *mut mx_voronoi = 0x5EE7 as *mut mx_voronoi;

fn last_message() -> String {
    let n = unsafe { mx_last_error_message(null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; n.max(1)];
    unsafe { mx_last_error_message(buf.as_mut_ptr(), buf.len()) };
    unsafe { CStr::from_ptr(buf.as_ptr()) }.to_string_lossy().into_owned()
}

/// Square regions of side 1 with these lower-left corners.
struct Input {
    xyb: Vec<f64>,
    lens: Vec<usize>,
    corners: Vec<(f64, f64)>,
}

fn squares(corners: &[(f64, f64)]) -> Input {
    let mut xyb = Vec::new();
    for &(x, y) in corners {
        for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            xyb.extend([x + dx, y + dy, 0.0]);
        }
    }
    Input { xyb, lens: vec![4; corners.len()], corners: corners.to_vec() }
}

fn sites_of(i: &Input) -> mx_sites {
    mx_sites {
        points_xy: null(),
        point_count: 0,
        curves_xyb: null(),
        curves_xyb_len: 0,
        curve_lengths: null(),
        curve_count: 0,
        regions_xyb: i.xyb.as_ptr(),
        regions_xyb_len: i.xyb.len(),
        region_lengths: i.lens.as_ptr(),
        region_count: i.lens.len(),
        boundary_xyb: null(),
        boundary_count: 0,
    }
}

/// Distance from (x, y) to the unit square at `c`.
fn square_distance(c: (f64, f64), x: f64, y: f64) -> f64 {
    let dx = (c.0 - x).max(x - c.0 - 1.0).max(0.0);
    let dy = (c.1 - y).max(y - c.1 - 1.0).max(0.0);
    dx.hypot(dy)
}

#[test]
fn squares_through_the_c_abi() {
    let input = squares(&[(0.0, 0.0), (3.0, 0.0), (1.5, 2.5), (1.4, 0.9)]);
    let sites = sites_of(&input);
    let mut vd = null_mut();
    assert_eq!(unsafe { mx_voronoi_compute(&sites, null(), &mut vd) }, mx_status::MX_OK, "{}", last_message());
    let mut info = mx_voronoi_info { auto_frame: 0, complete: 0, region_count: 0 };
    assert_eq!(unsafe { mx_voronoi_get_info(vd, &mut info) }, mx_status::MX_OK);
    assert_eq!((info.auto_frame, info.complete, info.region_count), (1, 1, 4));
    let mut axis: *const mx_axis = null();
    assert_eq!(unsafe { mx_voronoi_axis(vd, &mut axis) }, mx_status::MX_OK);
    let mut n_edges = 0;
    assert_eq!(unsafe { mx_axis_edge_count(axis, &mut n_edges) }, mx_status::MX_OK);
    let mut between = 0;
    for i in 0..n_edges {
        let blank = mx_site { kind: mx_site_kind::MX_SITE_POINT, index: 99 };
        let mut e = mx_voronoi_edge { sides: [blank; 2], is_self: 7, in_diagram: 7 };
        assert_eq!(unsafe { mx_voronoi_get_edge(vd, i, &mut e) }, mx_status::MX_OK);
        let frame = e.sides.iter().any(|s| s.kind == mx_site_kind::MX_SITE_BOUNDARY);
        assert_eq!(e.in_diagram, i32::from(!frame));
        assert_eq!(e.is_self, 0, "convex sites have no self-edges");
        if frame {
            continue;
        }
        between += 1;
        // Every sample is as far from both sites as its radius.
        let mut count = 0;
        assert_eq!(unsafe { mx_axis_edge_sample(axis, i, 1e-4, null_mut(), 0, &mut count) }, mx_status::MX_OK);
        let mut xyr = vec![0.0; 3 * count];
        assert_eq!(
            unsafe { mx_axis_edge_sample(axis, i, 1e-4, xyr.as_mut_ptr(), count, &mut count) },
            mx_status::MX_OK
        );
        for s in xyr.chunks_exact(3) {
            for side in e.sides {
                assert_eq!(side.kind, mx_site_kind::MX_SITE_REGION);
                let d = square_distance(input.corners[side.index], s[0], s[1]);
                assert!((d - s[2]).abs() < 1e-9, "edge {i}: {d} vs {}", s[2]);
            }
        }
    }
    assert!(between >= 5);
    // The square in the middle of the other three has a bounded region
    // whose walk closes.
    let mut r = mx_voronoi_region { walk_length: 0, walks: 0, self_edge_count: 9, unbounded: 9 };
    let region = mx_site_kind::MX_SITE_REGION as u32;
    assert_eq!(unsafe { mx_voronoi_get_region(vd, region, 3, &mut r) }, mx_status::MX_OK);
    assert_eq!((r.walks, r.self_edge_count, r.unbounded), (1, 0, 0));
    let mut count = 0;
    assert_eq!(
        unsafe { mx_voronoi_region_walk(vd, region, 3, null_mut(), null_mut(), 0, &mut count) },
        mx_status::MX_OK
    );
    assert_eq!(count, r.walk_length);
    let (mut edges, mut fwd) = (vec![0usize; count], vec![0i32; count]);
    let mut small = 0;
    assert_eq!(
        unsafe { mx_voronoi_region_walk(vd, region, 3, edges.as_mut_ptr(), fwd.as_mut_ptr(), count - 1, &mut small) },
        mx_status::MX_ERR_BUFFER_TOO_SMALL
    );
    assert_eq!(small, 0, "untouched on failure");
    assert_eq!(
        unsafe { mx_voronoi_region_walk(vd, region, 3, edges.as_mut_ptr(), fwd.as_mut_ptr(), count, &mut count) },
        mx_status::MX_OK
    );
    let ends = |k: usize| {
        let mut e = mx_axis_edge {
            from: 0,
            to: 0,
            kind: mx_conic_kind::MX_CONIC_LINE,
            sites: [mx_axis_site { loop_index: 0, index: 0, is_vertex: 0 }; 2],
        };
        assert_eq!(unsafe { mx_axis_get_edge(axis, edges[k], &mut e) }, mx_status::MX_OK);
        if fwd[k] == 1 {
            (e.from, e.to)
        } else {
            (e.to, e.from)
        }
    };
    for k in 0..count {
        assert_eq!(ends(k).1, ends((k + 1) % count).0, "the walk closes");
    }
    // Nearest sites.
    let mut near = mx_nearest_site {
        site: mx_site { kind: mx_site_kind::MX_SITE_POINT, index: 9 },
        distance: -1.0,
        foot_x: 0.0,
        foot_y: 0.0,
    };
    assert_eq!(unsafe { mx_voronoi_nearest_site(vd, 5.0, 0.5, &mut near) }, mx_status::MX_OK);
    assert_eq!((near.site.kind, near.site.index), (mx_site_kind::MX_SITE_REGION, 1));
    assert!((near.distance - 1.0).abs() < 1e-12 && (near.foot_x - 4.0).abs() < 1e-12);
    let before = near;
    assert_eq!(unsafe { mx_voronoi_nearest_site(vd, f64::NAN, 0.5, &mut near) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert_eq!(near, before);
    // Out-of-range and invalid arguments.
    assert_eq!(unsafe { mx_voronoi_get_region(vd, region, 4, &mut r) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
    assert_eq!(unsafe { mx_voronoi_get_region(vd, 17, 0, &mut r) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    let mut frontier = 5;
    assert_eq!(
        unsafe { mx_voronoi_node_frontier(vd, usize::MAX, &mut frontier) },
        mx_status::MX_ERR_INDEX_OUT_OF_RANGE
    );
    assert_eq!(frontier, 5);
    unsafe { mx_voronoi_free(vd) };
    unsafe { mx_voronoi_free(null_mut()) };
}

#[test]
fn bad_sites_leave_the_out_param_alone() {
    let mut vd = SENTINEL;
    let empty = squares(&[]);
    assert_eq!(unsafe { mx_voronoi_compute(&sites_of(&empty), null(), &mut vd) }, mx_status::MX_ERR_EMPTY);
    let overlapping = squares(&[(0.0, 0.0), (0.5, 0.5)]);
    assert_eq!(unsafe { mx_voronoi_compute(&sites_of(&overlapping), null(), &mut vd) }, mx_status::MX_ERR_INTERSECTION);
    assert!(last_message().contains("region site"), "{}", last_message());
    let mut wrong_len = squares(&[(0.0, 0.0)]);
    wrong_len.lens[0] = 5;
    assert_eq!(
        unsafe { mx_voronoi_compute(&sites_of(&wrong_len), null(), &mut vd) },
        mx_status::MX_ERR_INVALID_ARGUMENT
    );
    // A point inside a region site: the point is named.
    let pts = [0.5, 0.5];
    let inside = squares(&[(0.0, 0.0)]);
    let point_in = mx_sites { points_xy: pts.as_ptr(), point_count: 1, ..sites_of(&inside) };
    assert_eq!(unsafe { mx_voronoi_compute(&point_in, null(), &mut vd) }, mx_status::MX_ERR_HOLE_INSIDE_HOLE);
    assert!(last_message().contains("point site 0"), "{}", last_message());
    assert_eq!(unsafe { mx_voronoi_compute(null(), null(), &mut vd) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(vd, SENTINEL);
    let ok = squares(&[(0.0, 0.0), (2.0, 0.0)]);
    assert_eq!(unsafe { mx_voronoi_compute(&sites_of(&ok), null(), null_mut()) }, mx_status::MX_ERR_NULL_ARGUMENT);
}

unsafe extern "C" fn cancel(_fraction: f64, calls: *mut c_void) -> c_int {
    unsafe { *(calls as *mut usize) += 1 };
    1
}

#[test]
fn options_boundary_and_cancellation() {
    let input = squares(&[(0.0, 0.0), (2.0, 0.0)]);
    let mut o = unsafe { std::mem::zeroed::<mx_voronoi_options>() };
    assert_eq!(unsafe { mx_voronoi_options_init(&mut o, std::mem::size_of_val(&o)) }, mx_status::MX_OK);
    let mut calls = 0usize;
    o.progress = Some(cancel);
    o.user = &mut calls as *mut usize as *mut c_void;
    let mut vd = SENTINEL;
    assert_eq!(unsafe { mx_voronoi_compute(&sites_of(&input), &o, &mut vd) }, mx_status::MX_ERR_CANCELLED);
    assert_eq!((calls, vd), (1, SENTINEL));
    o.progress = None;
    o.threads = 2;
    o.tolerance = -1.0;
    assert_eq!(unsafe { mx_voronoi_compute(&sites_of(&input), &o, &mut vd) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    o.tolerance = 0.0;
    // A caller's boundary is a site: edges facing it are in the diagram.
    let frame = [-2.0, -2.0, 0.0, 5.0, -2.0, 0.0, 5.0, 3.0, 0.0, -2.0, 3.0, 0.0];
    let with_frame = mx_sites { boundary_xyb: frame.as_ptr(), boundary_count: 4, ..sites_of(&input) };
    assert_eq!(unsafe { mx_voronoi_compute(&with_frame, &o, &mut vd) }, mx_status::MX_OK, "{}", last_message());
    let mut info = mx_voronoi_info { auto_frame: 9, complete: 9, region_count: 0 };
    assert_eq!(unsafe { mx_voronoi_get_info(vd, &mut info) }, mx_status::MX_OK);
    assert_eq!((info.auto_frame, info.complete, info.region_count), (0, 1, 3));
    let mut r = mx_voronoi_region { walk_length: 0, walks: 0, self_edge_count: 0, unbounded: 9 };
    assert_eq!(
        unsafe { mx_voronoi_get_region(vd, mx_site_kind::MX_SITE_BOUNDARY as u32, 0, &mut r) },
        mx_status::MX_OK
    );
    assert_eq!((r.walks, r.unbounded), (1, 0));
    unsafe { mx_voronoi_free(vd) };
}

#[test]
fn points_and_a_curve_through_the_c_abi() {
    // Three points and an L-shaped polyline: labels name the kinds, the
    // nearest site of a point near the L is the curve, and every site has
    // one closed walk.
    let pts = [0.0, 0.0, 4.0, 0.0, 2.0, 3.0];
    let curve = [5.0, 2.0, 0.0, 6.0, 2.0, 0.0, 6.0, 3.0, 0.0];
    let lens = [3usize];
    let sites = mx_sites {
        points_xy: pts.as_ptr(),
        point_count: 3,
        curves_xyb: curve.as_ptr(),
        curves_xyb_len: curve.len(),
        curve_lengths: lens.as_ptr(),
        curve_count: 1,
        regions_xyb: null(),
        regions_xyb_len: 0,
        region_lengths: null(),
        region_count: 0,
        boundary_xyb: null(),
        boundary_count: 0,
    };
    let mut vd = null_mut();
    assert_eq!(unsafe { mx_voronoi_compute(&sites, null(), &mut vd) }, mx_status::MX_OK, "{}", last_message());
    let mut near = mx_nearest_site {
        site: mx_site { kind: mx_site_kind::MX_SITE_POINT, index: 9 },
        distance: 0.0,
        foot_x: 0.0,
        foot_y: 0.0,
    };
    assert_eq!(unsafe { mx_voronoi_nearest_site(vd, 6.5, 2.5, &mut near) }, mx_status::MX_OK);
    assert_eq!((near.site.kind, near.site.index), (mx_site_kind::MX_SITE_CURVE, 0));
    assert!((near.distance - 0.5).abs() < 1e-12);
    assert_eq!(unsafe { mx_voronoi_nearest_site(vd, 2.0, 2.6, &mut near) }, mx_status::MX_OK);
    assert_eq!((near.site.kind, near.site.index), (mx_site_kind::MX_SITE_POINT, 2));
    for (kind, index) in
        [(mx_site_kind::MX_SITE_POINT, 0), (mx_site_kind::MX_SITE_POINT, 2), (mx_site_kind::MX_SITE_CURVE, 0)]
    {
        let mut r = mx_voronoi_region { walk_length: 0, walks: 0, self_edge_count: 0, unbounded: 0 };
        assert_eq!(unsafe { mx_voronoi_get_region(vd, kind as u32, index, &mut r) }, mx_status::MX_OK);
        assert_eq!(r.walks, 1);
    }
    let mut r = mx_voronoi_region { walk_length: 0, walks: 0, self_edge_count: 0, unbounded: 0 };
    assert_eq!(unsafe { mx_voronoi_get_region(vd, mx_site_kind::MX_SITE_CURVE as u32, 0, &mut r) }, mx_status::MX_OK);
    assert!(r.self_edge_count >= 1, "the L's convex side has a self-edge");
    unsafe { mx_voronoi_free(vd) };
}
