//! Offsets, pockets and V-carves through the C ABI, called from Rust as a
//! C caller would: results equal to the Rust API's, borrowed arrays laid
//! out as documented, typed statuses for NULL and bad values with the
//! out-params left alone, cancellation, `_free(NULL)`.

mod common;

use common::offset_oracle::{loop_samples, Loops};
use medax::cam::{pocket, vcarve, PocketOptions, PocketOrder, UncutKind, VCarveOptions};
use medax::ffi::*;
use medax::plane::{medial_axis, AxisOptions, OffsetLayer, OffsetOptions, Offsets};
use medax::shape::{Shape2d, ShapeOptions, Vertex};
use std::ffi::{c_int, c_void, CStr};
use std::ptr::{null, null_mut};

fn last_message() -> String {
    let n = unsafe { mx_last_error_message(null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; n.max(1)];
    unsafe { mx_last_error_message(buf.as_mut_ptr(), buf.len()) };
    unsafe { CStr::from_ptr(buf.as_ptr()) }.to_string_lossy().into_owned()
}

/// A 4 × 4 square with a 2 × 2 hole, and a round notch in its right side:
/// rings round the hole, arcs in the loops.
const XYB: [f64; 27] = [
    0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 4.0, 1.5, -1.0, 4.0, 2.5, 0.0, 4.0, 4.0, 0.0, 0.0, 4.0, 0.0, // outer
    1.0, 1.0, 0.0, 1.0, 3.0, 0.0, 3.0, 3.0, 0.0, // hole (first three corners)
];
const HOLE_LAST: [f64; 3] = [3.0, 1.0, 0.0];

fn input() -> (Vec<f64>, Vec<usize>) {
    let mut xyb = XYB.to_vec();
    xyb.extend(HOLE_LAST);
    (xyb, vec![6, 4])
}

fn c_shape() -> *mut mx_shape2d {
    let (xyb, lens) = input();
    let mut s = null_mut();
    let st = unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), null(), &mut s) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    s
}

fn rust_shape() -> Shape2d {
    let (xyb, lens) = input();
    let mut it = xyb.chunks_exact(3).map(|c| Vertex { p: medax::kernel::Point::new(c[0], c[1]), bulge: c[2] });
    let loops = lens.iter().map(|&n| it.by_ref().take(n).collect()).collect();
    Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap()
}

fn triples(l: &[Vertex]) -> Vec<f64> {
    l.iter().flat_map(|v| [v.p.x, v.p.y, v.bulge]).collect()
}

unsafe fn array<'a, T>(p: *const T, n: usize) -> &'a [T] {
    if n == 0 {
        assert!(p.is_null(), "empty arrays are NULL");
        &[]
    } else {
        unsafe { std::slice::from_raw_parts(p, n) }
    }
}

/// Loops from a borrowed `mx_bulge_loops`, as triples per loop.
unsafe fn loops_of(b: &mx_bulge_loops) -> Vec<Vec<f64>> {
    let (xyb, lens) = unsafe { (array(b.xyb, b.xyb_len), array(b.lengths, b.count)) };
    assert_eq!(3 * lens.iter().sum::<usize>(), xyb.len());
    let mut at = 0;
    lens.iter()
        .map(|&n| {
            at += 3 * n;
            xyb[at - 3 * n..at].to_vec()
        })
        .collect()
}

/// A C layer equals the Rust layer: info, every loop (all at once and one
/// by one), every region; and out-of-range indices leave `out` alone.
fn check_layer(c: *const mx_offset_layer, rust: &OffsetLayer) {
    let mut info = mx_offset_layer_info { distance: 0.0, area: 0.0, loop_count: 0, region_count: 0 };
    assert_eq!(unsafe { mx_offset_layer_get_info(c, &mut info) }, mx_status::MX_OK);
    assert_eq!(info.distance, rust.distance);
    assert_eq!(info.area, rust.area());
    assert_eq!((info.loop_count, info.region_count), (rust.loops.len(), rust.regions.len()));
    let mut all = mx_bulge_loops { xyb: null(), xyb_len: 0, lengths: null(), count: 0 };
    assert_eq!(unsafe { mx_offset_layer_loops(c, &mut all) }, mx_status::MX_OK);
    let expected: Vec<Vec<f64>> = rust.loops.iter().map(|l| triples(&l.vertices)).collect();
    assert_eq!(unsafe { loops_of(&all) }, expected);
    for (i, l) in rust.loops.iter().enumerate() {
        let mut one = mx_offset_loop { xyb: null(), vertex_count: 0, area: 0.0, region: 9, is_hole: 9 };
        assert_eq!(unsafe { mx_offset_layer_get_loop(c, i, &mut one) }, mx_status::MX_OK);
        assert_eq!(unsafe { array(one.xyb, 3 * one.vertex_count) }, expected[i].as_slice());
        assert_eq!((one.area, one.region, one.is_hole), (l.area, l.region, i32::from(l.is_hole())));
    }
    for (i, r) in rust.regions.iter().enumerate() {
        let mut c_r = mx_offset_region { outer: 99, holes: null(), hole_count: 0 };
        assert_eq!(unsafe { mx_offset_layer_get_region(c, i, &mut c_r) }, mx_status::MX_OK);
        assert_eq!(c_r.outer, r.outer);
        assert_eq!(unsafe { array(c_r.holes, c_r.hole_count) }, r.holes.as_slice());
    }
    let mut untouched = mx_offset_loop { xyb: null(), vertex_count: 7, area: 0.0, region: 0, is_hole: 0 };
    let past = rust.loops.len();
    assert_eq!(unsafe { mx_offset_layer_get_loop(c, past, &mut untouched) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
    assert_eq!(untouched.vertex_count, 7);
    let mut region = mx_offset_region { outer: 5, holes: null(), hole_count: 0 };
    let past = rust.regions.len();
    assert_eq!(unsafe { mx_offset_layer_get_region(c, past, &mut region) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
    assert_eq!(region.outer, 5);
}

fn offset_options() -> mx_offset_options {
    let mut o = unsafe { std::mem::zeroed::<mx_offset_options>() };
    assert_eq!(unsafe { mx_offset_options_init(&mut o, std::mem::size_of_val(&o)) }, mx_status::MX_OK);
    o
}

#[test]
fn offsets_agree_with_the_rust_api() {
    let shape = c_shape();
    let mut o = offset_options();
    o.outer_reach = 1.0;
    let mut offsets = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(shape, &o, &mut offsets) }, mx_status::MX_OK, "{}", last_message());
    // The handle owns what it needs: the shape may go first.
    unsafe { mx_shape2d_free(shape) };
    let opts = OffsetOptions { axis: AxisOptions { seed: o.seed, ..AxisOptions::default() }, outer_reach: 1.0 };
    let rust = Offsets::new(&rust_shape(), &opts).unwrap();
    let mut max = 0.0;
    assert_eq!(unsafe { mx_offsets_max_inner_distance(offsets, &mut max) }, mx_status::MX_OK);
    assert_eq!(max, rust.max_inner_distance());
    // Inside, outside, at the boundary and past everything.
    let distances = [0.25, -0.5, 0.0, -1.0, 0.45, 5.0];
    let mut layers = [null_mut(); 6];
    assert_eq!(
        unsafe { mx_offsets_layers(offsets, distances.as_ptr(), distances.len(), layers.as_mut_ptr()) },
        mx_status::MX_OK,
        "{}",
        last_message()
    );
    for (&d, &layer) in distances.iter().zip(&layers) {
        check_layer(layer, &rust.layer(d).unwrap());
        let mut one = null_mut();
        assert_eq!(unsafe { mx_offsets_layer(offsets, d, &mut one) }, mx_status::MX_OK);
        check_layer(one, &rust.layer(d).unwrap());
        unsafe { mx_offset_layer_free(one) };
    }
    let mut info = mx_offset_layer_info { distance: 0.0, area: 0.0, loop_count: 9, region_count: 9 };
    assert_eq!(unsafe { mx_offset_layer_get_info(layers[5], &mut info) }, mx_status::MX_OK);
    assert_eq!((info.loop_count, info.region_count), (0, 0), "nothing is left past the largest disk");
    for layer in layers {
        unsafe { mx_offset_layer_free(layer) };
    }
    unsafe { mx_offsets_free(offsets) };
}

/// A C axis computed with `mx_axis_options`' defaults, for the shape of
/// [`c_shape`].
fn c_axis() -> *mut mx_axis {
    let shape = c_shape();
    let mut axis = null_mut();
    assert_eq!(unsafe { mx_axis_compute(shape, null(), &mut axis) }, mx_status::MX_OK, "{}", last_message());
    unsafe { mx_shape2d_free(shape) };
    axis
}

#[test]
fn offsets_from_an_axis_agree_with_the_rust_api() {
    let axis = c_axis();
    let mut o = offset_options();
    o.outer_reach = 1.0;
    let mut offsets = null_mut();
    assert_eq!(unsafe { mx_offsets_from_axis(axis, &o, &mut offsets) }, mx_status::MX_OK, "{}", last_message());
    // The handle owns what it needs: the axis may go first.
    unsafe { mx_axis_free(axis) };
    let shape = rust_shape();
    let rust_axis = medial_axis(&shape, &AxisOptions::default()).unwrap();
    let opts = OffsetOptions { axis: AxisOptions { seed: o.seed, ..AxisOptions::default() }, outer_reach: 1.0 };
    let rust = Offsets::from_axis(&shape, &rust_axis).unwrap().with_outer(&shape, &opts).unwrap();
    for d in [0.25, -0.5, 0.0, 5.0] {
        let mut one = null_mut();
        assert_eq!(unsafe { mx_offsets_layer(offsets, d, &mut one) }, mx_status::MX_OK, "{}", last_message());
        check_layer(one, &rust.layer(d).unwrap());
        unsafe { mx_offset_layer_free(one) };
    }
    unsafe { mx_offsets_free(offsets) };

    let sentinel = 0x5EE7 as *mut mx_offsets;
    let mut out = sentinel;
    let axis = c_axis();
    o.outer_reach = -1.0;
    assert_eq!(unsafe { mx_offsets_from_axis(axis, &o, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("outer_reach"), "{}", last_message());
    o.outer_reach = 1.0;
    let mut calls = 0usize;
    o.progress = Some(cancel);
    o.user = &mut calls as *mut usize as *mut c_void;
    assert_eq!(unsafe { mx_offsets_from_axis(axis, &o, &mut out) }, mx_status::MX_ERR_CANCELLED);
    assert_eq!(calls, 1);
    assert_eq!(unsafe { mx_offsets_from_axis(null(), null(), &mut out) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(out, sentinel);
    assert_eq!(unsafe { mx_offsets_from_axis(axis, null(), null_mut()) }, mx_status::MX_ERR_NULL_ARGUMENT);
    unsafe { mx_axis_free(axis) };
}

unsafe extern "C" fn cancel(_fraction: f64, calls: *mut c_void) -> c_int {
    unsafe { *(calls as *mut usize) += 1 };
    1
}

#[test]
fn offsets_refuse_bad_values_and_leave_out_params_alone() {
    let shape = c_shape();
    let sentinel = 0x5EE7 as *mut mx_offsets;
    let mut out = sentinel;
    let mut o = offset_options();
    for reach in [-1.0, f64::NAN, f64::INFINITY] {
        o.outer_reach = reach;
        assert_eq!(unsafe { mx_offsets_compute(shape, &o, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
        assert!(last_message().contains("outer_reach"), "{}", last_message());
    }
    o.outer_reach = 0.0;
    o.threads = 1 << 20;
    assert_eq!(unsafe { mx_offsets_compute(shape, &o, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("threads") && !last_message().contains("outer_reach"), "{}", last_message());
    o.threads = 0;
    o.struct_size = 4;
    assert_eq!(unsafe { mx_offsets_compute(shape, &o, &mut out) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    o = offset_options();
    let mut calls = 0usize;
    o.progress = Some(cancel);
    o.user = &mut calls as *mut usize as *mut c_void;
    assert_eq!(unsafe { mx_offsets_compute(shape, &o, &mut out) }, mx_status::MX_ERR_CANCELLED);
    assert_eq!(calls, 1);
    assert_eq!(unsafe { mx_offsets_compute(null(), null(), &mut out) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(out, sentinel);
    assert_eq!(unsafe { mx_offsets_compute(shape, null(), null_mut()) }, mx_status::MX_ERR_NULL_ARGUMENT);

    // Inner offsets only: outer distances and non-finite ones are refused.
    let mut offsets = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(shape, null(), &mut offsets) }, mx_status::MX_OK);
    let layer_sentinel = 0x5EE7 as *mut mx_offset_layer;
    let mut layer = layer_sentinel;
    for d in [-0.1, f64::NAN, f64::INFINITY] {
        assert_eq!(unsafe { mx_offsets_layer(offsets, d, &mut layer) }, mx_status::MX_ERR_INVALID_ARGUMENT, "{d}");
        assert!(last_message().contains("distance"), "{}", last_message());
    }
    assert_eq!(layer, layer_sentinel);
    let ds = [0.1, -0.1];
    let mut layers = [layer_sentinel; 2];
    assert_eq!(
        unsafe { mx_offsets_layers(offsets, ds.as_ptr(), 2, layers.as_mut_ptr()) },
        mx_status::MX_ERR_INVALID_ARGUMENT
    );
    assert_eq!(layers, [layer_sentinel; 2], "all or nothing");
    assert_eq!(unsafe { mx_offsets_layers(offsets, null(), 2, layers.as_mut_ptr()) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_offsets_layer(null(), 0.1, &mut layer) }, mx_status::MX_ERR_NULL_ARGUMENT);
    let mut info = mx_offset_layer_info { distance: 0.0, area: 0.0, loop_count: 0, region_count: 0 };
    assert_eq!(unsafe { mx_offset_layer_get_info(null(), &mut info) }, mx_status::MX_ERR_NULL_ARGUMENT);
    unsafe {
        mx_offsets_free(offsets);
        mx_offsets_free(null_mut());
        mx_offset_layer_free(null_mut());
        mx_shape2d_free(shape);
    }
}

fn pocket_options(r: f64, s: f64) -> mx_pocket_options {
    let mut o = unsafe { std::mem::zeroed::<mx_pocket_options>() };
    assert_eq!(unsafe { mx_pocket_options_init(&mut o, std::mem::size_of_val(&o)) }, mx_status::MX_OK);
    o.tool_radius = r;
    o.stepover = s;
    o
}

#[test]
fn pockets_agree_with_the_rust_api() {
    let shape = c_shape();
    let mut offsets = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(shape, null(), &mut offsets) }, mx_status::MX_OK);
    let rust_offsets = Offsets::new(&rust_shape(), &OffsetOptions::default()).unwrap();
    for order in [mx_pocket_order::MX_POCKET_INSIDE_OUT, mx_pocket_order::MX_POCKET_OUTSIDE_IN] {
        let o = mx_pocket_options { order: order as u32, ..pocket_options(0.1, 0.15) };
        let mut p = null_mut();
        assert_eq!(unsafe { mx_pocket_compute(offsets, &o, &mut p) }, mx_status::MX_OK, "{}", last_message());
        let rust_order = if order == mx_pocket_order::MX_POCKET_INSIDE_OUT {
            PocketOrder::InsideOut
        } else {
            PocketOrder::OutsideIn
        };
        let rust =
            pocket(&rust_offsets, &PocketOptions { order: rust_order, ..PocketOptions::new(0.1, 0.15) }).unwrap();
        let mut info = unsafe { std::mem::zeroed::<mx_pocket_info>() };
        assert_eq!(unsafe { mx_pocket_get_info(p, &mut info) }, mx_status::MX_OK);
        assert_eq!((info.ring_count, info.uncut_count), (rust.rings.len(), rust.uncut.len()));
        assert_eq!(info.truncated, i32::from(rust.truncated));
        assert_eq!(info.level_count, rust.level_count());
        assert!(info.ring_count >= 3);
        assert_eq!(unsafe { array(info.order, info.ring_count) }, rust.order.as_slice());
        for (i, r) in rust.rings.iter().enumerate() {
            let mut c = unsafe { std::mem::zeroed::<mx_pocket_ring>() };
            assert_eq!(unsafe { mx_pocket_get_ring(p, i, &mut c) }, mx_status::MX_OK);
            assert_eq!((c.level, c.distance), (r.level, r.distance));
            assert_eq!(c.has_parent == 1, r.parent.is_some());
            if let Some(parent) = r.parent {
                assert_eq!(c.parent, parent);
            }
            assert_eq!(unsafe { array(c.children, c.child_count) }, r.children.as_slice());
            let loops: Vec<Vec<f64>> = r.loops.iter().map(|l| triples(&l.vertices)).collect();
            assert_eq!(unsafe { loops_of(&c.loops) }, loops);
        }
        for (i, u) in rust.uncut.iter().enumerate() {
            let mut c = unsafe { std::mem::zeroed::<mx_uncut_region>() };
            assert_eq!(unsafe { mx_pocket_get_uncut(p, i, &mut c) }, mx_status::MX_OK);
            let kind = if u.kind == UncutKind::Scallop {
                mx_uncut_kind::MX_UNCUT_SCALLOP
            } else {
                mx_uncut_kind::MX_UNCUT_WALL
            };
            assert_eq!((c.kind, c.area), (kind, u.area));
            let loops: Vec<Vec<f64>> = u.loops.iter().map(|l| triples(l)).collect();
            assert_eq!(unsafe { loops_of(&c.loops) }, loops);
        }
        let mut ring = unsafe { std::mem::zeroed::<mx_pocket_ring>() };
        ring.level = 77;
        let past = rust.rings.len();
        assert_eq!(unsafe { mx_pocket_get_ring(p, past, &mut ring) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
        assert_eq!(ring.level, 77);
        unsafe { mx_pocket_free(p) };
    }
    unsafe {
        mx_offsets_free(offsets);
        mx_shape2d_free(shape);
    }
}

#[test]
fn pockets_refuse_bad_options_by_name() {
    let shape = c_shape();
    let mut offsets = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(shape, null(), &mut offsets) }, mx_status::MX_OK);
    let sentinel = 0x5EE7 as *mut mx_pocket;
    let mut p = sentinel;
    let cases = [
        (pocket_options(0.0, 0.1), "tool_radius"),
        (pocket_options(-1.0, 0.1), "tool_radius"),
        (pocket_options(f64::NAN, 0.1), "tool_radius"),
        (pocket_options(0.1, 0.0), "stepover"),
        (pocket_options(0.1, f64::INFINITY), "stepover"),
        (mx_pocket_options { order: 7, ..pocket_options(0.1, 0.1) }, "order"),
        (mx_pocket_options { struct_size: 1, ..pocket_options(0.1, 0.1) }, "struct_size"),
    ];
    for (o, named) in cases {
        assert_eq!(unsafe { mx_pocket_compute(offsets, &o, &mut p) }, mx_status::MX_ERR_INVALID_ARGUMENT, "{named}");
        assert!(last_message().contains(named), "{named}: {}", last_message());
    }
    assert_eq!(unsafe { mx_pocket_compute(offsets, null(), &mut p) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert_eq!(
        unsafe { mx_pocket_compute(null(), &pocket_options(0.1, 0.1), &mut p) },
        mx_status::MX_ERR_NULL_ARGUMENT
    );
    assert_eq!(p, sentinel);
    let mut info = unsafe { std::mem::zeroed::<mx_pocket_info>() };
    assert_eq!(unsafe { mx_pocket_get_info(null(), &mut info) }, mx_status::MX_ERR_NULL_ARGUMENT);
    unsafe {
        mx_pocket_free(null_mut());
        mx_offsets_free(offsets);
        mx_shape2d_free(shape);
    }
}

fn vcarve_options(angle_deg: f64, max_depth: f64) -> mx_vcarve_options {
    let mut o = unsafe { std::mem::zeroed::<mx_vcarve_options>() };
    assert_eq!(unsafe { mx_vcarve_options_init(&mut o, std::mem::size_of_val(&o)) }, mx_status::MX_OK);
    assert_eq!((o.angle_deg, o.max_depth), (90.0, f64::INFINITY));
    o.angle_deg = angle_deg;
    o.max_depth = max_depth;
    o
}

#[test]
fn vcarves_agree_with_the_rust_api() {
    let c_axis = c_axis();
    let rust_shape = rust_shape();
    let axis = medial_axis(&rust_shape, &AxisOptions::default()).unwrap();
    for (angle, depth) in [(90.0, 0.3), (60.0, f64::INFINITY)] {
        let o = vcarve_options(angle, depth);
        let mut v = null_mut();
        assert_eq!(unsafe { mx_vcarve_compute(c_axis, &o, &mut v) }, mx_status::MX_OK, "{}", last_message());
        let rust =
            vcarve(&rust_shape, &axis, &VCarveOptions { angle_deg: angle, max_depth: depth, tolerance: 0.0 }).unwrap();
        let mut info = mx_vcarve_info { path_count: 0, flat_radius: 0.0, flat_loop_count: 9 };
        assert_eq!(unsafe { mx_vcarve_get_info(v, &mut info) }, mx_status::MX_OK);
        assert_eq!((info.path_count, info.flat_radius), (rust.paths.len(), rust.flat_radius()));
        assert_eq!(info.flat_loop_count, rust.flat.loops.len());
        assert!(info.path_count > 0);
        for (i, path) in rust.paths.iter().enumerate() {
            let mut c = mx_vcarve_path { xyd: null(), point_count: 0 };
            assert_eq!(unsafe { mx_vcarve_get_path(v, i, &mut c) }, mx_status::MX_OK);
            let flat: Vec<f64> = path.points.iter().flatten().copied().collect();
            assert_eq!(unsafe { array(c.xyd, 3 * c.point_count) }, flat.as_slice());
        }
        let mut c = mx_vcarve_path { xyd: null(), point_count: 5 };
        let past = rust.paths.len();
        assert_eq!(unsafe { mx_vcarve_get_path(v, past, &mut c) }, mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
        assert_eq!(c.point_count, 5);
        let mut flat: *const mx_offset_layer = null();
        assert_eq!(unsafe { mx_vcarve_flat(v, &mut flat) }, mx_status::MX_OK);
        check_layer(flat, &rust.flat);
        if depth.is_finite() {
            // The corridors round the hole are 1 wide: a 90° bit reaches
            // 0.5 in them, so the cap at 0.3 makes a flat bottom.
            assert!(!rust.flat.loops.is_empty());
        } else {
            assert!(rust.flat.loops.is_empty());
        }
        unsafe { mx_vcarve_free(v) };
    }
    unsafe { mx_axis_free(c_axis) };
}

#[test]
fn vcarves_refuse_bad_options_by_name() {
    let axis = c_axis();
    let sentinel = 0x5EE7 as *mut mx_vcarve;
    let mut v = sentinel;
    let cases = [
        (vcarve_options(0.0, 1.0), "angle"),
        (vcarve_options(180.0, 1.0), "angle"),
        (vcarve_options(f64::NAN, 1.0), "angle"),
        (vcarve_options(90.0, 0.0), "max_depth"),
        (vcarve_options(90.0, f64::NAN), "max_depth"),
        (mx_vcarve_options { tolerance: -1.0, ..vcarve_options(90.0, 1.0) }, "tolerance"),
        (mx_vcarve_options { struct_size: 1, ..vcarve_options(90.0, 1.0) }, "struct_size"),
    ];
    for (o, named) in cases {
        assert_eq!(unsafe { mx_vcarve_compute(axis, &o, &mut v) }, mx_status::MX_ERR_INVALID_ARGUMENT, "{named}");
        assert!(last_message().contains(named), "{named}: {}", last_message());
    }
    assert_eq!(unsafe { mx_vcarve_compute(null(), null(), &mut v) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(unsafe { mx_vcarve_compute(axis, null(), null_mut()) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert_eq!(v, sentinel);
    let mut flat: *const mx_offset_layer = null();
    assert_eq!(unsafe { mx_vcarve_flat(null(), &mut flat) }, mx_status::MX_ERR_NULL_ARGUMENT);
    assert!(flat.is_null());
    unsafe {
        mx_vcarve_free(null_mut());
        mx_axis_free(axis);
    }
}

/// The C offsets of a smooth curve where disks hug stretches of nearly
/// concentric arcs, read back as a C caller would and checked at points
/// along every element against the oracle's distance to the boundary
/// (the loop there once swung round a whole circle).
#[test]
fn c_offsets_of_a_smooth_curve_lie_at_their_distance() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/offset_gross_blob_1030.json");
    let rust = Shape2d::from_json_str(&std::fs::read_to_string(path).unwrap(), &ShapeOptions::default()).unwrap();
    let xyb: Vec<f64> = rust.loops().iter().flat_map(|l| triples(l.vertices())).collect();
    let lens: Vec<usize> = rust.loops().iter().map(|l| l.len()).collect();
    let mut shape = null_mut();
    let st = unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), null(), &mut shape) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let mut offsets = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(shape, &offset_options(), &mut offsets) }, mx_status::MX_OK);
    let wall = Loops::of_shape(&rust);
    let diag = rust.bbox().diagonal();
    for d in [0.0223, 0.186041, 0.5] {
        let mut layer = null_mut();
        assert_eq!(unsafe { mx_offsets_layer(offsets, d, &mut layer) }, mx_status::MX_OK);
        let mut all = mx_bulge_loops { xyb: null(), xyb_len: 0, lengths: null(), count: 0 };
        assert_eq!(unsafe { mx_offset_layer_loops(layer, &mut all) }, mx_status::MX_OK);
        let loops = unsafe { loops_of(&all) };
        assert!(!loops.is_empty());
        for l in loops {
            let vs: Vec<Vertex> =
                l.chunks_exact(3).map(|c| Vertex { p: medax::kernel::Point::new(c[0], c[1]), bulge: c[2] }).collect();
            for (q, _) in loop_samples(&vs, 5) {
                let dist = wall.dist(q);
                assert!((dist - d).abs() <= 1e-9 * diag, "offset {d}: point {q:?} at distance {dist}");
            }
        }
        unsafe { mx_offset_layer_free(layer) };
    }
    unsafe { mx_offsets_free(offsets) };
    unsafe { mx_shape2d_free(shape) };
}
