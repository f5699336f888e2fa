//! The C entry points for offsets, pockets and V-carves on arbitrary small
//! shapes (integer coordinates, bulges in steps of 1/16) with arbitrary
//! distances and options: statuses only, never a panic (MX_ERR_PANIC) or a
//! crash; out-params (offsets, pockets, V-carves) written only on success; borrowed arrays consistent
//! with their counts; a pocket's order visits every ring once.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::ffi::*;

#[derive(Debug, arbitrary::Arbitrary)]
struct Input {
    coords: Vec<(i8, i8, i8)>,
    lens: Vec<u8>,
    reach: u8,
    distances: Vec<i8>,
    pocket: (i8, i8, bool),
    vcarve: (u8, i8),
}

/// Every loop and region of a layer, read back.
fn read_layer(layer: *const mx_offset_layer) {
    let mut info = mx_offset_layer_info { distance: 0.0, area: 0.0, loop_count: 0, region_count: 0 };
    assert_eq!(unsafe { mx_offset_layer_get_info(layer, &mut info) }, mx_status::MX_OK);
    let mut all = mx_bulge_loops { xyb: std::ptr::null(), xyb_len: 0, lengths: std::ptr::null(), count: 0 };
    assert_eq!(unsafe { mx_offset_layer_loops(layer, &mut all) }, mx_status::MX_OK);
    assert_eq!(all.count, info.loop_count);
    let lens = if all.count == 0 { &[][..] } else { unsafe { std::slice::from_raw_parts(all.lengths, all.count) } };
    assert_eq!(3 * lens.iter().sum::<usize>(), all.xyb_len);
    for i in 0..info.loop_count {
        let mut l = mx_offset_loop { xyb: std::ptr::null(), vertex_count: 0, area: 0.0, region: 0, is_hole: 0 };
        assert_eq!(unsafe { mx_offset_layer_get_loop(layer, i, &mut l) }, mx_status::MX_OK);
        assert_eq!(l.vertex_count, lens[i]);
        assert!(l.region < info.region_count);
    }
    for r in 0..info.region_count {
        let mut reg = mx_offset_region { outer: 0, holes: std::ptr::null(), hole_count: 0 };
        assert_eq!(unsafe { mx_offset_layer_get_region(layer, r, &mut reg) }, mx_status::MX_OK);
        assert!(reg.outer < info.loop_count);
    }
}

fuzz_target!(|input: Input| {
    let xyb: Vec<f64> =
        input.coords.iter().take(24).flat_map(|&(x, y, b)| [x as f64, y as f64, b as f64 / 16.0]).collect();
    let lens: Vec<usize> = input.lens.iter().take(4).map(|&n| n as usize % 12).collect();
    let mut shape = std::ptr::null_mut();
    let st = unsafe {
        mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), std::ptr::null(), &mut shape)
    };
    if st != mx_status::MX_OK {
        return;
    }
    let mut o = unsafe { std::mem::zeroed::<mx_offset_options>() };
    assert_eq!(unsafe { mx_offset_options_default(&mut o) }, mx_status::MX_OK);
    o.outer_reach = input.reach as f64 / 8.0;
    // Offsets from the shape, or (odd reach) from its axis, which the
    // V-carve follows.
    let mut axis = std::ptr::null_mut();
    let st = unsafe { mx_axis_compute(shape, std::ptr::null(), &mut axis) };
    assert_ne!(st, mx_status::MX_ERR_PANIC);
    let sentinel = 0x5EE7 as *mut mx_offsets;
    let mut offsets = sentinel;
    let st = if input.reach % 2 == 1 && !axis.is_null() {
        unsafe { mx_offsets_from_axis(axis, &o, &mut offsets) }
    } else {
        unsafe { mx_offsets_compute(shape, &o, &mut offsets) }
    };
    assert_ne!(st, mx_status::MX_ERR_PANIC);
    if st == mx_status::MX_OK {
        for &d in input.distances.iter().take(4) {
            let no_layer = 0x5EE7 as *mut mx_offset_layer;
            let mut layer = no_layer;
            let st = unsafe { mx_offsets_layer(offsets, d as f64 / 8.0, &mut layer) };
            assert_ne!(st, mx_status::MX_ERR_PANIC);
            if st == mx_status::MX_OK {
                read_layer(layer);
                unsafe { mx_offset_layer_free(layer) };
            } else {
                assert_eq!(layer, no_layer);
            }
        }
        let mut po = unsafe { std::mem::zeroed::<mx_pocket_options>() };
        assert_eq!(unsafe { mx_pocket_options_default(&mut po) }, mx_status::MX_OK);
        po.tool_radius = input.pocket.0 as f64 / 16.0;
        po.stepover = input.pocket.1 as f64 / 16.0;
        po.order = input.pocket.2 as u32;
        po.max_levels = 64;
        let no_pocket = 0x5EE7 as *mut mx_pocket;
        let mut p = no_pocket;
        let st = unsafe { mx_pocket_compute(offsets, &po, &mut p) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st != mx_status::MX_OK {
            assert_eq!(p, no_pocket);
        } else {
            let mut info = unsafe { std::mem::zeroed::<mx_pocket_info>() };
            assert_eq!(unsafe { mx_pocket_get_info(p, &mut info) }, mx_status::MX_OK);
            let order =
                if info.ring_count == 0 { &[][..] } else { unsafe { std::slice::from_raw_parts(info.order, info.ring_count) } };
            let mut seen = vec![false; info.ring_count];
            for &i in order {
                assert!(!std::mem::replace(&mut seen[i], true), "ring {i} twice in the order");
            }
            unsafe { mx_pocket_free(p) };
        }
        unsafe { mx_offsets_free(offsets) };
    } else {
        assert_eq!(offsets, sentinel);
    }
    let mut vo = unsafe { std::mem::zeroed::<mx_vcarve_options>() };
    assert_eq!(unsafe { mx_vcarve_options_default(&mut vo) }, mx_status::MX_OK);
    vo.angle_deg = input.vcarve.0 as f64;
    vo.max_depth = input.vcarve.1 as f64 / 8.0;
    if !axis.is_null() {
        let no_vcarve = 0x5EE7 as *mut mx_vcarve;
        let mut v = no_vcarve;
        let st = unsafe { mx_vcarve_compute(axis, &vo, &mut v) };
        assert_ne!(st, mx_status::MX_ERR_PANIC);
        if st != mx_status::MX_OK {
            assert_eq!(v, no_vcarve);
        } else {
            let mut flat: *const mx_offset_layer = std::ptr::null();
            assert_eq!(unsafe { mx_vcarve_flat(v, &mut flat) }, mx_status::MX_OK);
            read_layer(flat);
            unsafe { mx_vcarve_free(v) };
        }
        unsafe { mx_axis_free(axis) };
    }
    unsafe { mx_shape2d_free(shape) };
});
