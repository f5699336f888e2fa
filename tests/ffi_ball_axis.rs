//! The medial axis and offsets under a polygon ball through the C ABI,
//! called from Rust as a C caller would: the axis of a rectangle under the
//! square by hand, contact classes and jump flags, every node's ball
//! checked by brute force, offsets under the ball, and the errors (arcs,
//! a Euclidean axis asked for contacts, a ball axis given to the
//! Euclidean-only calls, bad distances) writing nothing.

mod common;

use common::ffi::{ball, ball_vertices, gauge, last_message};
use medax::ffi::*;
use std::ptr::{null, null_mut};

fn shape(loops: &[&[(f64, f64, f64)]]) -> *mut mx_shape2d {
    let xyb: Vec<f64> = loops.iter().flat_map(|l| l.iter().flat_map(|&(x, y, b)| [x, y, b])).collect();
    let lens: Vec<usize> = loops.iter().map(|l| l.len()).collect();
    let mut s = null_mut();
    let st = unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), null(), &mut s) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    s
}

fn with_ball(s: *const mx_shape2d, b: *const mx_ball) -> *mut mx_axis {
    let mut a = null_mut();
    let st = unsafe { mx_axis_compute_with_ball(s, b, null(), &mut a) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    a
}

fn nodes(a: *const mx_axis) -> Vec<mx_axis_node> {
    let mut n = 0;
    assert_eq!(unsafe { mx_axis_node_count(a, &mut n) }, mx_status::MX_OK);
    (0..n)
        .map(|i| {
            let mut node = mx_axis_node { x: 0.0, y: 0.0, r: 0.0, kind: mx_node_kind::MX_NODE_JOINT };
            assert_eq!(unsafe { mx_axis_get_node(a, i, &mut node) }, mx_status::MX_OK);
            node
        })
        .collect()
}

fn edges(a: *const mx_axis) -> Vec<(mx_axis_edge, mx_axis_contacts)> {
    let mut n = 0;
    assert_eq!(unsafe { mx_axis_edge_count(a, &mut n) }, mx_status::MX_OK);
    let site = mx_axis_site { loop_index: 9, index: 9, is_vertex: 9 };
    (0..n)
        .map(|i| {
            let mut e = mx_axis_edge { from: 0, to: 0, kind: mx_conic_kind::MX_CONIC_PARABOLA, sites: [site; 2] };
            assert_eq!(unsafe { mx_axis_get_edge(a, i, &mut e) }, mx_status::MX_OK);
            let mut c = mx_axis_contacts { kind: [mx_contact_kind::MX_CONTACT_EE; 2], ball_feature: [99; 2], jump: 7 };
            assert_eq!(unsafe { mx_axis_edge_contacts(a, i, &mut c) }, mx_status::MX_OK);
            (e, c)
        })
        .collect()
}

/// The largest ball at `c` inside a polygon: the least gauge to points of
/// its edges, each edge sampled densely (the oracle shares nothing with
/// the library).
fn brute_radius(poly: &[(f64, f64)], v: &[(f64, f64)], c: (f64, f64)) -> f64 {
    let mut best = f64::INFINITY;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        for k in 0..=4000 {
            let t = k as f64 / 4000.0;
            let p = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
            best = best.min(gauge(v, (p.0 - c.0, p.1 - c.1)));
        }
    }
    best
}

#[test]
fn a_rectangle_under_the_square() {
    let s = shape(&[&[(0.0, 0.0, 0.0), (6.0, 0.0, 0.0), (6.0, 2.0, 0.0), (0.0, 2.0, 0.0)]]);
    let sq = ball("square");
    let a = with_ball(s, sq);
    // The square fits every corner: one edge from (1, 1) to (5, 1), r = 1.
    let ns = nodes(a);
    let es = edges(a);
    assert_eq!(es.len(), 1);
    let (e, c) = es[0];
    assert_eq!(e.kind, mx_conic_kind::MX_CONIC_LINE);
    let mut ends = [(ns[e.from].x, ns[e.from].y, ns[e.from].r), (ns[e.to].x, ns[e.to].y, ns[e.to].r)];
    ends.sort_by(|p, q| p.0.total_cmp(&q.0));
    assert_eq!(ends, [(1.0, 1.0, 1.0), (5.0, 1.0, 1.0)]);
    // Its sides lie along the long edges (0: bottom, 2: top), EE contacts.
    let mut sides = [e.sites[0].index, e.sites[1].index];
    sides.sort();
    assert_eq!(sides, [0, 2]);
    assert_eq!(c.kind, [mx_contact_kind::MX_CONTACT_EE; 2]);
    assert_eq!(c.jump, 0);
    // Samples are the two ends.
    let mut n = 0;
    assert_eq!(unsafe { mx_axis_edge_sample(a, 0, 1e-3, null_mut(), 0, &mut n) }, mx_status::MX_OK);
    assert_eq!(n, 2);
    // The offset at 0.5 is the rectangle [0.5, 5.5] × [0.5, 1.5].
    let mut layer = null_mut();
    assert_eq!(unsafe { mx_axis_offset_layer(a, 0.5, &mut layer) }, mx_status::MX_OK, "{}", last_message());
    let mut info = std::mem::MaybeUninit::<mx_offset_layer_info>::zeroed();
    assert_eq!(unsafe { mx_offset_layer_get_info(layer, info.as_mut_ptr()) }, mx_status::MX_OK);
    let info = unsafe { info.assume_init() };
    assert_eq!(info.loop_count, 1);
    assert!((info.area - 5.0).abs() < 1e-12, "area {}", info.area);
    unsafe { mx_offset_layer_free(layer) };
    unsafe { mx_axis_free(a) };
    unsafe { mx_ball_free(sq) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn every_node_is_the_centre_of_a_ball_that_fits_and_touches() {
    // A star-like polygon under a hexagon and the (asymmetric) triangle.
    let poly: Vec<(f64, f64)> = (0..14)
        .map(|i| {
            let t = i as f64 * std::f64::consts::TAU / 14.0;
            let r = if i % 2 == 0 { 1.0 } else { 0.55 + 0.03 * i as f64 };
            (r * t.cos(), r * t.sin())
        })
        .collect();
    let loop_: Vec<(f64, f64, f64)> = poly.iter().map(|&(x, y)| (x, y, 0.0)).collect();
    let s = shape(&[&loop_]);
    for spec in ["ngon:6:10", "triangle"] {
        let b = ball(spec);
        let v = ball_vertices(b);
        let a = with_ball(s, b);
        let ns = nodes(a);
        assert!(ns.iter().any(|n| n.kind == mx_node_kind::MX_NODE_BRANCH));
        for n in &ns {
            let r = brute_radius(&poly, &v, (n.x, n.y));
            assert!((r - n.r).abs() < 1e-3, "{spec}: node ({}, {}) r {} against {r}", n.x, n.y, n.r);
        }
        for (e, c) in edges(a) {
            assert!(e.from < ns.len() && e.to < ns.len());
            for k in 0..2 {
                // A shape vertex is touched by a ball edge (EV), a shape
                // edge by a ball vertex or a parallel edge.
                assert!(c.ball_feature[k] < v.len());
                assert_eq!(e.sites[k].is_vertex == 1, c.kind[k] == mx_contact_kind::MX_CONTACT_EV);
            }
            assert!(c.jump == 0 || c.jump == 1);
        }
        unsafe { mx_axis_free(a) };
        unsafe { mx_ball_free(b) };
    }
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn errors_write_nothing() {
    let sentinel = 0x5EE7 as *mut mx_axis;
    // An arc: unsupported under a ball, with its loop and element.
    let s = shape(&[&[(0.0, 0.0, 0.0), (4.0, 0.0, 0.5), (4.0, 4.0, 0.0), (0.0, 4.0, 0.0)]]);
    let sq = ball("square");
    let mut a = sentinel;
    assert_eq!(unsafe { mx_axis_compute_with_ball(s, sq, null(), &mut a) }, mx_status::MX_ERR_UNSUPPORTED);
    assert_eq!(a, sentinel);
    let mut info = std::mem::MaybeUninit::<mx_error_info>::zeroed();
    assert_eq!(unsafe { mx_last_error_info(info.as_mut_ptr()) }, mx_status::MX_OK);
    let info = unsafe { info.assume_init() };
    assert_eq!((info.loop_index, info.element), (0, 1));
    // NULL ball: the Euclidean axis, which has no contact classes and
    // whose offsets match mx_axis_offset_layer's.
    let mut e = null_mut();
    assert_eq!(unsafe { mx_axis_compute_with_ball(s, null(), null(), &mut e) }, mx_status::MX_OK);
    let mut c = mx_axis_contacts { kind: [mx_contact_kind::MX_CONTACT_VE; 2], ball_feature: [5; 2], jump: 3 };
    assert_eq!(unsafe { mx_axis_edge_contacts(e, 0, &mut c) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert_eq!(c.ball_feature, [5; 2]);
    let mut layer = null_mut();
    assert_eq!(unsafe { mx_axis_offset_layer(e, 0.5, &mut layer) }, mx_status::MX_OK);
    unsafe { mx_offset_layer_free(layer) };
    for d in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let mut l = 0x5EE7 as *mut mx_offset_layer;
        assert_eq!(unsafe { mx_axis_offset_layer(e, d, &mut l) }, mx_status::MX_ERR_INVALID_ARGUMENT);
        assert_eq!(l, 0x5EE7 as *mut mx_offset_layer);
    }
    unsafe { mx_axis_free(e) };
    // A ball axis refused by the Euclidean-only calls.
    let p = shape(&[&[(0.0, 0.0, 0.0), (4.0, 0.0, 0.0), (4.0, 4.0, 0.0), (0.0, 4.0, 0.0)]]);
    let a = with_ball(p, sq);
    let mut o = null_mut();
    assert_eq!(unsafe { mx_offsets_from_axis(a, null(), &mut o) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(o.is_null());
    assert!(last_message().contains("polygon ball"), "{}", last_message());
    let mut c = mx_axis_contacts { kind: [mx_contact_kind::MX_CONTACT_VE; 2], ball_feature: [0; 2], jump: 0 };
    assert_eq!(unsafe { mx_axis_edge_contacts(a, 1_000_000, &mut c) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
    unsafe { mx_axis_free(a) };
    unsafe { mx_ball_free(sq) };
    unsafe { mx_shape2d_free(s) };
    unsafe { mx_shape2d_free(p) };
}
