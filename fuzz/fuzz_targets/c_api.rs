//! The C entry point for bulge loops with arbitrary lengths and numbers:
//! statuses only, never a panic (MX_ERR_PANIC) or a crash.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::ffi::*;

fuzz_target!(|input: (Vec<f64>, Vec<u8>)| {
    let (xyb, lens) = input;
    let lens: Vec<usize> = lens.iter().map(|&l| l as usize % 16).collect();
    let mut out: *mut mx_shape2d = std::ptr::null_mut();
    let status = unsafe {
        mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), lens.as_ptr(), lens.len(), std::ptr::null(), &mut out)
    };
    assert_ne!(status, mx_status::MX_ERR_PANIC);
    if status == mx_status::MX_OK {
        let mut area = 0.0;
        assert_eq!(unsafe { mx_shape2d_area(out, &mut area) }, mx_status::MX_OK);
        unsafe { mx_shape2d_free(out) };
    } else {
        assert!(out.is_null());
        assert!(mx_last_error_length() > 0);
    }
});
