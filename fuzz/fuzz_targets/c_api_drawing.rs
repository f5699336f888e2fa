//! Drawings through the C API: any bytes (read as DXF, SVG or JSON by the
//! first byte's choice) with a selection made from the input, every report
//! queried and the JSON written. Statuses only, never a panic
//! (MX_ERR_PANIC) or a crash; out-params untouched on failure.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::ffi::*;
use std::ffi::CString;

fuzz_target!(|input: (u8, Vec<String>, Vec<i16>, &[u8])| {
    let (choice, layers, colours, data) = input;
    let format = [mx_format::MX_FORMAT_AUTO, mx_format::MX_FORMAT_DXF, mx_format::MX_FORMAT_SVG, mx_format::MX_FORMAT_JSON]
        [usize::from(choice % 4)] as u32;
    let names: Vec<CString> = layers.iter().filter_map(|l| CString::new(l.as_str()).ok()).collect();
    let pointers: Vec<*const std::ffi::c_char> = names.iter().map(|n| n.as_ptr()).collect();
    let select = mx_drawing_select {
        struct_size: std::mem::size_of::<mx_drawing_select>(),
        layers: pointers.as_ptr(),
        layer_count: pointers.len(),
        colours: colours.as_ptr(),
        colour_count: colours.len(),
        keep_duplicates: i32::from(choice & 4 != 0),
    };
    let sentinel = 0x1 as *mut mx_drawing;
    let mut d = sentinel;
    let status = unsafe { mx_drawing_from_memory(data.as_ptr(), data.len(), format, std::ptr::null(), &select, &mut d) };
    assert_ne!(status, mx_status::MX_ERR_PANIC);
    if status != mx_status::MX_OK {
        assert_eq!(d, sentinel);
        assert!(mx_last_error_length() > 0);
        return;
    }
    let (mut shapes, mut ignored, mut warnings) = (0usize, 0usize, 0usize);
    unsafe {
        assert_eq!(mx_drawing_shape_count(d, &mut shapes), mx_status::MX_OK);
        assert_eq!(mx_drawing_ignored_count(d, &mut ignored), mx_status::MX_OK);
        assert_eq!(mx_drawing_warning_count(d, &mut warnings), mx_status::MX_OK);
        for k in 0..shapes {
            let mut s: *mut mx_shape2d = std::ptr::null_mut();
            assert_eq!(mx_drawing_shape(d, k, &mut s), mx_status::MX_OK);
            let mut area = 0.0;
            assert_eq!(mx_shape2d_area(s, &mut area), mx_status::MX_OK);
            assert!(area > 0.0);
            mx_shape2d_free(s);
        }
        for k in 0..ignored {
            // The kinds have no zero value: an all-zero struct is no valid
            // Rust value, so the library writes into uninitialised memory.
            let mut i = std::mem::MaybeUninit::<mx_ignored>::uninit();
            assert_eq!(mx_drawing_get_ignored(d, k, i.as_mut_ptr()), mx_status::MX_OK);
            let i = i.assume_init();
            assert!(!i.layer.is_null() && !i.reason.is_null());
        }
        for k in 0..warnings {
            let mut w = std::mem::MaybeUninit::<mx_warning>::uninit();
            assert_eq!(mx_drawing_get_warning(d, k, w.as_mut_ptr()), mx_status::MX_OK);
            let w = w.assume_init();
            assert!(w.shapes[0] < shapes.max(1) && w.shapes[1] < shapes.max(1));
        }
        let mut w = std::mem::MaybeUninit::<mx_warning>::uninit();
        assert_eq!(mx_drawing_get_warning(d, warnings, w.as_mut_ptr()), mx_status::MX_ERR_INDEX_OUT_OF_RANGE);
        let path = CString::new("/dev/null").unwrap();
        assert_eq!(mx_drawing_write_json(d, path.as_ptr()), mx_status::MX_OK);
        mx_drawing_free(d);
    }
});
