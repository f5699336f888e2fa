//! Solids through the C API: any bytes as a file of the format the first
//! byte picks (or guessed), and any numbers as vertex and triangle arrays
//! with an optional welding tolerance. Every call gives a status, never a
//! panic (MX_ERR_PANIC) or a crash; a solid that builds answers every query
//! consistently (counts, buffers, components).
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::ffi::*;
use std::ptr::{null, null_mut};

fn check(m: *mut mx_mesh3d) {
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
    unsafe { mx_mesh3d_free(m) };
}

fuzz_target!(|input: (u8, f64, Vec<[f64; 3]>, Vec<[u8; 3]>, &[u8])| {
    let (choice, tolerance, points, tris, data) = input;
    let format = [0u32, 4, 5, 6, 7, 1][usize::from(choice % 6)];
    let sentinel = 0x1 as *mut mx_mesh3d;
    let mut m = sentinel;
    let st = unsafe { mx_mesh3d_from_memory(data.as_ptr(), data.len(), format, null(), &mut m) };
    assert_ne!(st, mx_status::MX_ERR_PANIC);
    if st == mx_status::MX_OK {
        check(m);
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
        check(m);
    } else {
        assert_eq!(m, sentinel);
    }
});
