//! The medial axis through the C ABI, called from Rust as a C caller would:
//! known axes (a rectangle, an L), sampled disks checked against a
//! brute-force boundary distance in the caller's numbering, NULL and range
//! handling, options, cancellation, holes, size queries.

use medax::ffi::*;
use std::ffi::{c_int, c_void, CStr};
use std::ptr::{null, null_mut};

/// A pointer value medax never returns, to prove failing calls leave
/// out-params alone.
const SENTINEL: *mut mx_axis = 0x5EE7 as *mut mx_axis;

fn shape(loops: &[&[(f64, f64)]]) -> *mut mx_shape2d {
    let xyb: Vec<f64> = loops.iter().flat_map(|l| l.iter().flat_map(|&(x, y)| [x, y, 0.0])).collect();
    let lens: Vec<usize> = loops.iter().map(|l| l.len()).collect();
    let mut s = null_mut();
    let st = unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), null(), &mut s) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    s
}

fn last_message() -> String {
    let n = unsafe { mx_last_error_message(null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; n.max(1)];
    unsafe { mx_last_error_message(buf.as_mut_ptr(), buf.len()) };
    unsafe { CStr::from_ptr(buf.as_ptr()) }.to_string_lossy().into_owned()
}

fn compute(s: *const mx_shape2d, opts: *const mx_axis_options) -> *mut mx_axis {
    let mut a = null_mut();
    let st = unsafe { mx_axis_compute(s, opts, &mut a) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    assert!(!a.is_null());
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

fn edges(a: *const mx_axis) -> Vec<mx_axis_edge> {
    let mut n = 0;
    assert_eq!(unsafe { mx_axis_edge_count(a, &mut n) }, mx_status::MX_OK);
    let site = mx_axis_site { loop_index: 9, index: 9, is_vertex: 9 };
    (0..n)
        .map(|i| {
            let mut e = mx_axis_edge { from: 0, to: 0, kind: mx_conic_kind::MX_CONIC_LINE, sites: [site; 2] };
            assert_eq!(unsafe { mx_axis_get_edge(a, i, &mut e) }, mx_status::MX_OK);
            e
        })
        .collect()
}

/// Samples of edge `i` as (x, y, r), by a size query and a fill.
fn samples(a: *const mx_axis, i: usize, tol: f64) -> Vec<[f64; 3]> {
    let mut n = 0;
    assert_eq!(unsafe { mx_axis_edge_sample(a, i, tol, null_mut(), 0, &mut n) }, mx_status::MX_OK);
    assert!(n >= 2);
    let mut buf = vec![f64::NAN; 3 * n];
    let mut m = 0;
    let st = unsafe { mx_axis_edge_sample(a, i, tol, buf.as_mut_ptr(), n, &mut m) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    assert_eq!(m, n);
    buf.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
}

fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// Brute-force distance from `p` to a polygon's boundary.
fn boundary_distance(poly: &[(f64, f64)], p: (f64, f64)) -> f64 {
    (0..poly.len()).map(|k| segment_distance(p, poly[k], poly[(k + 1) % poly.len()])).fold(f64::INFINITY, f64::min)
}

/// Distance from `p` to a site, read in the caller's numbering of `poly`.
fn site_distance(poly: &[(f64, f64)], s: &mx_axis_site, p: (f64, f64)) -> f64 {
    assert_eq!(s.loop_index, 0);
    assert!(s.index < poly.len());
    let v = poly[s.index];
    if s.is_vertex == 1 {
        (p.0 - v.0).hypot(p.1 - v.1)
    } else {
        assert_eq!(s.is_vertex, 0);
        segment_distance(p, v, poly[(s.index + 1) % poly.len()])
    }
}

/// Every sample is a disk of its radius touching the boundary and both of
/// its edge's sites; the ends are the edge's nodes.
fn check_disks(poly: &[(f64, f64)], a: *const mx_axis) -> usize {
    let (ns, es) = (nodes(a), edges(a));
    let mut count = 0;
    for (i, e) in es.iter().enumerate() {
        let s = samples(a, i, 1e-6);
        let (first, last) = (s[0], s[s.len() - 1]);
        assert_eq!(first, [ns[e.from].x, ns[e.from].y, ns[e.from].r]);
        assert_eq!(last, [ns[e.to].x, ns[e.to].y, ns[e.to].r]);
        for [x, y, r] in s {
            let d = boundary_distance(poly, (x, y));
            assert!((d - r).abs() <= 1e-9, "edge {i}: sample ({x}, {y}) radius {r}, boundary distance {d}");
            for site in &e.sites {
                let d = site_distance(poly, site, (x, y));
                assert!((d - r).abs() <= 1e-9, "edge {i}: site {site:?} at distance {d}, radius {r}");
            }
            count += 1;
        }
    }
    count
}

const RECT: [(f64, f64); 4] = [(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (0.0, 2.0)];

#[test]
fn rectangle_axis() {
    let s = shape(&[&RECT]);
    let a = compute(s, null());
    let ns = nodes(a);
    assert_eq!(ns.len(), 6);
    let mut branches: Vec<_> = ns.iter().filter(|n| n.kind == mx_node_kind::MX_NODE_BRANCH).collect();
    branches.sort_by(|p, q| p.x.total_cmp(&q.x));
    assert_eq!(branches.len(), 2);
    for (b, x) in branches.iter().zip([1.0, 3.0]) {
        assert!((b.x - x).abs() < 1e-9 && (b.y - 1.0).abs() < 1e-9 && (b.r - 1.0).abs() < 1e-9, "{b:?}");
    }
    let corners: Vec<_> = ns.iter().filter(|n| n.kind == mx_node_kind::MX_NODE_CORNER).collect();
    assert_eq!(corners.len(), 4);
    for c in corners {
        assert!(RECT.contains(&(c.x, c.y)) && c.r == 0.0, "{c:?}");
    }
    let es = edges(a);
    assert_eq!(es.len(), 5);
    assert!(es.iter().all(|e| e.kind == mx_conic_kind::MX_CONIC_LINE && e.from < 6 && e.to < 6));
    assert!(es.iter().all(|e| e.sites.iter().all(|s| s.is_vertex == 0)));
    assert!(check_disks(&RECT, a) >= 10);
    unsafe { mx_axis_free(a) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn sites_use_the_callers_numbering() {
    // An L given clockwise: stored reversed, one reflex vertex, input vertex 3 at (1, 1).
    let l = [(0.0, 0.0), (0.0, 3.0), (1.0, 3.0), (1.0, 1.0), (3.0, 1.0), (3.0, 0.0)];
    let s = shape(&[&l]);
    let mut rev = 0;
    assert_eq!(unsafe { mx_shape2d_loop_reversed(s, 0, &mut rev) }, mx_status::MX_OK);
    assert_eq!(rev, 1);
    let a = compute(s, null());
    let es = edges(a);
    let vertex_sites: Vec<_> = es.iter().flat_map(|e| e.sites).filter(|s| s.is_vertex == 1).collect();
    assert!(!vertex_sites.is_empty());
    assert!(vertex_sites.iter().all(|s| s.index == 3), "{vertex_sites:?}");
    assert!(es.iter().any(|e| e.kind == mx_conic_kind::MX_CONIC_PARABOLA));
    check_disks(&l, a);
    unsafe { mx_axis_free(a) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn axis_outlives_its_shape_and_threads_do_not_change_it() {
    let star: Vec<(f64, f64)> = (0..40)
        .map(|k| {
            let t = std::f64::consts::TAU * (k as f64 + 0.5 * ((k * 7 % 5) as f64 / 5.0)) / 40.0;
            let r = if k % 2 == 0 { 10.0 } else { 6.0 + (k % 3) as f64 };
            (r * t.cos(), r * t.sin())
        })
        .collect();
    let s = shape(&[&star]);
    let mut o = unsafe { std::mem::zeroed::<mx_axis_options>() };
    assert_eq!(unsafe { mx_axis_options_init(&mut o, std::mem::size_of_val(&o)) }, mx_status::MX_OK);
    assert_eq!(o.struct_size, std::mem::size_of::<mx_axis_options>());
    assert_eq!(o.threads, 0);
    assert!(o.progress.is_none() && o.user.is_null());
    let a0 = compute(s, &o);
    o.threads = 1;
    let a1 = compute(s, &o);
    o.threads = 3;
    let a3 = compute(s, &o);
    unsafe { mx_shape2d_free(s) };
    let (n0, e0) = (nodes(a0), edges(a0));
    for a in [a1, a3] {
        assert_eq!(nodes(a), n0);
        assert_eq!(edges(a), e0);
    }
    assert!(n0.iter().any(|n| n.kind == mx_node_kind::MX_NODE_BRANCH));
    check_disks(&star, a3);
    for a in [a0, a1, a3] {
        unsafe { mx_axis_free(a) };
    }
}

#[test]
fn null_and_range_errors_write_nothing() {
    use mx_status::*;
    let s = shape(&[&RECT]);
    let mut out = SENTINEL;
    assert_eq!(unsafe { mx_axis_compute(null(), null(), &mut out) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(out, SENTINEL);
    assert_eq!(unsafe { mx_axis_compute(s, null(), null_mut()) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(
        unsafe { mx_axis_options_init(null_mut(), std::mem::size_of::<mx_axis_options>()) },
        MX_ERR_NULL_ARGUMENT
    );
    let a = compute(s, null());
    let mut n = 77;
    assert_eq!(unsafe { mx_axis_node_count(null(), &mut n) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_axis_edge_count(null(), &mut n) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_axis_node_count(a, null_mut()) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_axis_edge_count(a, null_mut()) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(n, 77);
    let mut node = mx_axis_node { x: 7.0, y: 7.0, r: 7.0, kind: mx_node_kind::MX_NODE_LEAF };
    let before = node;
    assert_eq!(unsafe { mx_axis_get_node(a, 6, &mut node) }, MX_ERR_INDEX_OUT_OF_RANGE);
    assert!(last_message().contains("node index 6"), "{}", last_message());
    assert_eq!(unsafe { mx_axis_get_node(null(), 0, &mut node) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_axis_get_node(a, 0, null_mut()) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(node, before);
    let site = mx_axis_site { loop_index: 7, index: 7, is_vertex: 7 };
    let mut e = mx_axis_edge { from: 7, to: 7, kind: mx_conic_kind::MX_CONIC_ELLIPSE, sites: [site; 2] };
    let before = e;
    assert_eq!(unsafe { mx_axis_get_edge(a, 5, &mut e) }, MX_ERR_INDEX_OUT_OF_RANGE);
    assert_eq!(unsafe { mx_axis_get_edge(null(), 0, &mut e) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_axis_get_edge(a, 0, null_mut()) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(e, before);
    // Sampling: range, NULLs, bad tolerances, short buffers (capacity in
    // samples: 10 for 30 doubles).
    let mut buf = [7.0; 30];
    let mut count = 77;
    let sample = |i: usize, tol: f64, p: *mut f64, cap: usize, c: *mut usize| unsafe {
        mx_axis_edge_sample(a, i, tol, p, cap, c)
    };
    assert_eq!(sample(5, 1e-3, buf.as_mut_ptr(), 10, &mut count), MX_ERR_INDEX_OUT_OF_RANGE);
    assert_eq!(unsafe { mx_axis_edge_sample(null(), 0, 1e-3, buf.as_mut_ptr(), 10, &mut count) }, MX_ERR_NULL_ARGUMENT);
    assert_eq!(sample(0, 1e-3, buf.as_mut_ptr(), 10, null_mut()), MX_ERR_NULL_ARGUMENT);
    assert_eq!(sample(0, 1e-3, null_mut(), 10, &mut count), MX_ERR_NULL_ARGUMENT);
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e-15] {
        assert_eq!(sample(0, tol, buf.as_mut_ptr(), 10, &mut count), MX_ERR_INVALID_ARGUMENT, "{tol}");
    }
    assert_eq!(sample(0, 1e-3, buf.as_mut_ptr(), 1, &mut count), MX_ERR_BUFFER_TOO_SMALL);
    assert!(last_message().contains("has 2 samples, the buffer room for 1"), "{}", last_message());
    assert_eq!(count, 77);
    assert_eq!(buf, [7.0; 30]);
    // Size query with a buffer and capacity 0 writes only the count.
    assert_eq!(sample(0, 1e-3, buf.as_mut_ptr(), 0, &mut count), MX_OK);
    assert_eq!(count, 2);
    assert_eq!(buf, [7.0; 30]);
    assert_eq!(sample(0, 1e-3, buf.as_mut_ptr(), 2, &mut count), MX_OK);
    assert!(buf[6..].iter().all(|&v| v == 7.0));
    unsafe { mx_axis_free(a) };
    unsafe { mx_axis_free(null_mut()) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn bad_options() {
    let s = shape(&[&RECT]);
    let mut o = unsafe { std::mem::zeroed::<mx_axis_options>() };
    unsafe { mx_axis_options_init(&mut o, std::mem::size_of_val(&o)) };
    let mut out = SENTINEL;
    o.threads = MX_AXIS_MAX_THREADS + 1;
    assert_eq!(unsafe { mx_axis_compute(s, &o, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    o.threads = 0;
    o.struct_size = 8;
    assert_eq!(unsafe { mx_axis_compute(s, &o, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("mx_axis_options_init"), "{}", last_message());
    assert_eq!(out, SENTINEL);
    unsafe { mx_shape2d_free(s) };
}

/// Records every fraction reported and cancels when asked to.
struct Progress {
    seen: Vec<f64>,
    cancel_at: f64,
}

unsafe extern "C" fn on_progress(fraction: f64, user: *mut c_void) -> c_int {
    let p = unsafe { &mut *user.cast::<Progress>() };
    p.seen.push(fraction);
    c_int::from(fraction >= p.cancel_at)
}

#[test]
fn progress_and_cancel() {
    let s = shape(&[&RECT]);
    let mut o = unsafe { std::mem::zeroed::<mx_axis_options>() };
    unsafe { mx_axis_options_init(&mut o, std::mem::size_of_val(&o)) };
    let mut p = Progress { seen: vec![], cancel_at: 0.0 };
    o.progress = Some(on_progress);
    o.user = (&mut p as *mut Progress).cast();
    let mut out = SENTINEL;
    assert_eq!(unsafe { mx_axis_compute(s, &o, &mut out) }, mx_status::MX_ERR_CANCELLED);
    assert_eq!(out, SENTINEL);
    assert!(last_message().contains("cancelled"), "{}", last_message());
    assert_eq!(p.seen, [0.0]);
    // Not cancelled: 0 then 1; cancelling at 1 is too late and ignored.
    for cancel_at in [2.0, 1.0] {
        p = Progress { seen: vec![], cancel_at };
        o.user = (&mut p as *mut Progress).cast();
        let a = compute(s, &o);
        assert_eq!(p.seen, [0.0, 1.0]);
        unsafe { mx_axis_free(a) };
    }
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn holes_give_one_cycle_each_with_sites_in_the_callers_numbering() {
    // The hole is given counter-clockwise: the library turns it round, and
    // the sites must still name the caller's vertices and segments.
    let hole = [(1.0, 0.5), (3.0, 0.5), (3.0, 1.5), (1.0, 1.5)];
    let loops: [&[(f64, f64)]; 2] = [&RECT, &hole];
    let s = shape(&loops);
    let a = compute(s, null());
    let (ns, es) = (nodes(a), edges(a));
    // Connected with one independent cycle.
    assert_eq!(es.len(), ns.len(), "{} nodes, {} edges", ns.len(), es.len());
    let mut on_hole = 0;
    for (i, e) in es.iter().enumerate() {
        for [x, y, r] in samples(a, i, 1e-6) {
            let d = loops.iter().map(|l| boundary_distance(l, (x, y))).fold(f64::INFINITY, f64::min);
            assert!((d - r).abs() <= 1e-9, "edge {i}: ({x}, {y}) radius {r}, boundary {d}");
            for site in &e.sites {
                let poly = loops[site.loop_index];
                let v = poly[site.index];
                let ds = if site.is_vertex == 1 {
                    (x - v.0).hypot(y - v.1)
                } else {
                    segment_distance((x, y), v, poly[(site.index + 1) % poly.len()])
                };
                assert!((ds - r).abs() <= 1e-9, "edge {i}: site {site:?} at {ds}, radius {r}");
            }
        }
        on_hole += e.sites.iter().filter(|t| t.loop_index == 1).count();
    }
    assert!(on_hole >= 4, "every side of the hole faces the axis");
    unsafe { mx_axis_free(a) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn new_statuses_have_texts() {
    for (s, v) in [(mx_status::MX_ERR_CANCELLED, 8), (mx_status::MX_ERR_NUMERICAL, 9)] {
        assert_eq!(s as i32, v);
        let t = unsafe { CStr::from_ptr(mx_status_str(v)) }.to_str().unwrap();
        assert_ne!(t, "unknown status");
    }
}
