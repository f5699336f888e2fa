//! Callers built against the 0.1 header keep working: every options struct
//! is passed as 0.1 laid it out (a frozen copy of its fields, `struct_size`
//! its 0.1 `sizeof`, on 64-bit targets the literal sizes the library
//! checks against), and every field of that layout, the last one included,
//! must be read. A `struct_size` one byte short of it is rejected.

use medax::ffi::*;
use std::ffi::{c_int, c_void, CStr};
use std::mem::size_of;
use std::ptr::{null, null_mut};

/// The 0.1 layouts, as a caller compiled against the 0.1 header holds them.
#[repr(C)]
struct ShapeOptionsV01 {
    struct_size: usize,
    tolerance: f64,
    relative_tolerance: f64,
    angle_tolerance: f64,
    flatten_sagitta: f64,
    chain_tolerance: f64,
    max_radius_ratio: f64,
}

#[repr(C)]
struct AxisOptionsV01 {
    struct_size: usize,
    seed: u64,
    threads: usize,
    progress: mx_progress_fn,
    user: *mut c_void,
}

#[repr(C)]
struct OffsetOptionsV01 {
    struct_size: usize,
    seed: u64,
    threads: usize,
    outer_reach: f64,
    progress: mx_progress_fn,
    user: *mut c_void,
}

#[repr(C)]
struct PocketOptionsV01 {
    struct_size: usize,
    tool_radius: f64,
    stepover: f64,
    order: u32,
    max_levels: usize,
}

#[repr(C)]
struct VCarveOptionsV01 {
    struct_size: usize,
    angle_deg: f64,
    max_depth: f64,
    tolerance: f64,
}

#[repr(C)]
struct VoronoiOptionsV01 {
    struct_size: usize,
    seed: u64,
    threads: usize,
    tolerance: f64,
    progress: mx_progress_fn,
    user: *mut c_void,
}

// The sizes the 0.1 library was built with on 64-bit targets.
#[cfg(target_pointer_width = "64")]
const _: () = assert!(
    size_of::<ShapeOptionsV01>() == 56
        && size_of::<AxisOptionsV01>() == 40
        && size_of::<OffsetOptionsV01>() == 48
        && size_of::<PocketOptionsV01>() == 40
        && size_of::<VCarveOptionsV01>() == 32
        && size_of::<VoronoiOptionsV01>() == 48
);

fn last_message() -> String {
    let n = unsafe { mx_last_error_message(null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; n.max(1)];
    unsafe { mx_last_error_message(buf.as_mut_ptr(), buf.len()) };
    unsafe { CStr::from_ptr(buf.as_ptr()) }.to_string_lossy().into_owned()
}

/// Counts progress reports; never cancels.
unsafe extern "C" fn count(_fraction: f64, calls: *mut c_void) -> c_int {
    unsafe { *calls.cast::<usize>() += 1 };
    0
}

/// Boxed, so that nothing past the 0.1 struct is valid memory to read
/// (a read past it shows under valgrind and sanitizers).
fn old<T>(v: T) -> Box<T> {
    Box::new(v)
}

/// The 0.1 struct as the current type, as an old caller's pointer reaches
/// the library.
fn as_current<T, U>(v: &T) -> *const U {
    (v as *const T).cast()
}

/// A 4 × 2 rectangle.
fn rectangle(options: *const mx_shape_options) -> (mx_status, *mut mx_shape2d) {
    let xyb = [0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 4.0, 2.0, 0.0, 0.0, 2.0, 0.0];
    let mut s = null_mut();
    let st = unsafe { mx_shape2d_from_bulges(xyb.as_ptr(), xyb.len(), [4usize].as_ptr(), 1, options, &mut s) };
    (st, s)
}

#[test]
fn shape_threads_are_checked_and_leave_the_shape_as_it_is() {
    let mut o: mx_shape_options = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { mx_shape_options_init(&mut o, std::mem::size_of_val(&o)) }, mx_status::MX_OK);
    assert_eq!(o.threads, 0);
    let mut tol = [0.0; 2];
    for (i, threads) in [0, 1].into_iter().enumerate() {
        let (st, s) = rectangle(&mx_shape_options { threads, ..o });
        assert_eq!(st, mx_status::MX_OK, "{}", last_message());
        assert_eq!(unsafe { mx_shape2d_tolerance(s, &mut tol[i]) }, mx_status::MX_OK);
        unsafe { mx_shape2d_free(s) };
    }
    assert_eq!(tol[0], tol[1]);
    let (st, s) = rectangle(&mx_shape_options { threads: MX_AXIS_MAX_THREADS + 1, ..o });
    assert_eq!((st, s), (mx_status::MX_ERR_INVALID_ARGUMENT, null_mut()));
    assert!(last_message().contains("mx_shape_options.threads"), "{}", last_message());
}

#[test]
fn shape_options_of_0_1() {
    let o = old(ShapeOptionsV01 {
        struct_size: size_of::<ShapeOptionsV01>(),
        tolerance: 1e-6,
        relative_tolerance: 1e-9,
        angle_tolerance: 1e-6,
        flatten_sagitta: -1.0,
        chain_tolerance: 0.0,
        max_radius_ratio: -1.0,
    });
    // The last 0.1 field is read: a negative ratio is refused.
    let (st, _) = rectangle(as_current(&*o));
    assert_eq!(st, mx_status::MX_ERR_INVALID_ARGUMENT, "{}", last_message());
    let o = old(ShapeOptionsV01 { max_radius_ratio: 1e6, ..*o });
    let (st, s) = rectangle(as_current(&*o));
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    let mut tol = 0.0;
    assert_eq!(unsafe { mx_shape2d_tolerance(s, &mut tol) }, mx_status::MX_OK);
    assert_eq!(tol, 1e-6);
    let short = old(ShapeOptionsV01 { struct_size: size_of::<ShapeOptionsV01>() - 1, ..*o });
    assert_eq!(rectangle(as_current(&*short)).0, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("mx_shape_options.struct_size"), "{}", last_message());
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn axis_options_of_0_1() {
    let (_, s) = rectangle(null());
    let mut calls = 0usize;
    let o = old(AxisOptionsV01 {
        struct_size: size_of::<AxisOptionsV01>(),
        seed: 7,
        threads: 1,
        progress: Some(count),
        user: (&mut calls as *mut usize).cast(),
    });
    let mut a = null_mut();
    assert_eq!(unsafe { mx_axis_compute(s, as_current(&*o), &mut a) }, mx_status::MX_OK, "{}", last_message());
    assert_eq!(calls, 2, "progress and user (the last 0.1 fields) are read");
    let short = old(AxisOptionsV01 { struct_size: size_of::<AxisOptionsV01>() - 1, ..*o });
    let mut b = null_mut();
    assert_eq!(unsafe { mx_axis_compute(s, as_current(&*short), &mut b) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(b.is_null());

    // V-carve from that axis: the last 0.1 field (tolerance) is read.
    let v = old(VCarveOptionsV01 {
        struct_size: size_of::<VCarveOptionsV01>(),
        angle_deg: 60.0,
        max_depth: 0.5,
        tolerance: -1.0,
    });
    let mut vc = null_mut();
    assert_eq!(unsafe { mx_vcarve_compute(a, as_current(&*v), &mut vc) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    assert!(last_message().contains("tolerance"), "{}", last_message());
    let v = old(VCarveOptionsV01 { tolerance: 0.0, ..*v });
    assert_eq!(unsafe { mx_vcarve_compute(a, as_current(&*v), &mut vc) }, mx_status::MX_OK, "{}", last_message());
    let mut info = mx_vcarve_info { path_count: 0, flat_radius: 0.0, flat_loop_count: 0 };
    assert_eq!(unsafe { mx_vcarve_get_info(vc, &mut info) }, mx_status::MX_OK);
    assert!((info.flat_radius - 0.5 * 30f64.to_radians().tan()).abs() < 1e-12, "{}", info.flat_radius);
    let short = old(VCarveOptionsV01 { struct_size: size_of::<VCarveOptionsV01>() - 1, ..*v });
    let mut vc2 = null_mut();
    assert_eq!(unsafe { mx_vcarve_compute(a, as_current(&*short), &mut vc2) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    unsafe { mx_vcarve_free(vc) };
    unsafe { mx_axis_free(a) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn offset_and_pocket_options_of_0_1() {
    let (_, s) = rectangle(null());
    let mut calls = 0usize;
    let o = old(OffsetOptionsV01 {
        struct_size: size_of::<OffsetOptionsV01>(),
        seed: 7,
        threads: 1,
        outer_reach: 1.0,
        progress: Some(count),
        user: (&mut calls as *mut usize).cast(),
    });
    let mut off = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(s, as_current(&*o), &mut off) }, mx_status::MX_OK, "{}", last_message());
    assert_eq!(calls, 2, "progress and user (the last 0.1 fields) are read");
    let mut outer = null_mut();
    assert_eq!(unsafe { mx_offsets_layer(off, -0.5, &mut outer) }, mx_status::MX_OK, "outer_reach is read");
    let short = old(OffsetOptionsV01 { struct_size: size_of::<OffsetOptionsV01>() - 1, ..*o });
    let mut off2 = null_mut();
    assert_eq!(unsafe { mx_offsets_compute(s, as_current(&*short), &mut off2) }, mx_status::MX_ERR_INVALID_ARGUMENT);

    let p = old(PocketOptionsV01 {
        struct_size: size_of::<PocketOptionsV01>(),
        tool_radius: 0.1,
        stepover: 0.1,
        order: mx_pocket_order::MX_POCKET_OUTSIDE_IN as u32,
        max_levels: 2,
    });
    let mut pk = null_mut();
    assert_eq!(unsafe { mx_pocket_compute(off, as_current(&*p), &mut pk) }, mx_status::MX_OK, "{}", last_message());
    let mut info = unsafe { std::mem::zeroed::<mx_pocket_info>() };
    assert_eq!(unsafe { mx_pocket_get_info(pk, &mut info) }, mx_status::MX_OK);
    assert_eq!((info.level_count, info.truncated), (2, 1), "max_levels (the last 0.1 field) is read");
    let short = old(PocketOptionsV01 { struct_size: size_of::<PocketOptionsV01>() - 1, ..*p });
    let mut pk2 = null_mut();
    assert_eq!(unsafe { mx_pocket_compute(off, as_current(&*short), &mut pk2) }, mx_status::MX_ERR_INVALID_ARGUMENT);
    unsafe { mx_pocket_free(pk) };
    unsafe { mx_offset_layer_free(outer) };
    unsafe { mx_offsets_free(off) };
    unsafe { mx_shape2d_free(s) };
}

#[test]
fn voronoi_options_of_0_1() {
    let pts = [0.0, 0.0, 3.0, 0.0, 1.0, 2.0];
    let sites = mx_sites {
        points_xy: pts.as_ptr(),
        point_count: 3,
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
    };
    let mut calls = 0usize;
    let o = old(VoronoiOptionsV01 {
        struct_size: size_of::<VoronoiOptionsV01>(),
        seed: 7,
        threads: 1,
        tolerance: 0.0,
        progress: Some(count),
        user: (&mut calls as *mut usize).cast(),
    });
    let mut vd = null_mut();
    assert_eq!(unsafe { mx_voronoi_compute(&sites, as_current(&*o), &mut vd) }, mx_status::MX_OK, "{}", last_message());
    assert_eq!(calls, 2, "progress and user (the last 0.1 fields) are read");
    let short = old(VoronoiOptionsV01 { struct_size: size_of::<VoronoiOptionsV01>() - 1, ..*o });
    let mut vd2 = null_mut();
    assert_eq!(
        unsafe { mx_voronoi_compute(&sites, as_current(&*short), &mut vd2) },
        mx_status::MX_ERR_INVALID_ARGUMENT
    );
    unsafe { mx_voronoi_free(vd) };
}

/// Writes into a buffer of `size` bytes followed by guard bytes; returns
/// the status, the `struct_size` written and whether the guard held.
fn guarded<T>(size: usize, fill: unsafe extern "C" fn(*mut T) -> mx_status) -> (mx_status, usize, bool) {
    // u64 words: aligned for every options struct.
    let mut buf = vec![0xABAB_ABAB_ABAB_ABABu64; (size + 64).div_ceil(8)];
    let st = unsafe { fill(buf.as_mut_ptr().cast()) };
    let bytes: Vec<u8> = buf.iter().flat_map(|w| w.to_ne_bytes()).collect();
    (st, buf[0] as usize, bytes[size..].iter().all(|&b| b == 0xAB))
}

fn guarded_init<T>(size: usize, init: unsafe extern "C" fn(*mut T, usize) -> mx_status) -> (mx_status, usize, bool) {
    let mut buf = vec![0xABAB_ABAB_ABAB_ABABu64; (size + 64).div_ceil(8)];
    let st = unsafe { init(buf.as_mut_ptr().cast(), size) };
    let bytes: Vec<u8> = buf.iter().flat_map(|w| w.to_ne_bytes()).collect();
    (st, buf[0] as usize, bytes[size..].iter().all(|&b| b == 0xAB))
}

#[test]
fn defaults_never_write_past_the_callers_struct() {
    // (first release's end of fields, today's size, _default, _init) per
    // options struct; a 0.1 caller's struct is at least the first size.
    macro_rules! check {
        ($t:ty, $v1:expr, $default:ident, $init:ident) => {{
            let (v1, now) = ($v1, size_of::<$t>());
            // The 0.1 export: the 0.1 fields only.
            assert_eq!(guarded::<$t>(v1, $default), (mx_status::MX_OK, v1, true), stringify!($default));
            // The size-aware one: an old size, today's size, a larger one.
            assert_eq!(guarded_init::<$t>(v1, $init), (mx_status::MX_OK, v1, true), stringify!($init));
            assert_eq!(guarded_init::<$t>(now, $init), (mx_status::MX_OK, now, true), stringify!($init));
            assert_eq!(guarded_init::<$t>(now + 24, $init), (mx_status::MX_OK, now, true), stringify!($init));
            // Too small for any release: refused, nothing written.
            let (st, written, guard) = guarded_init::<$t>(v1 - 1, $init);
            assert_eq!((st, written, guard), (mx_status::MX_ERR_INVALID_ARGUMENT, 0xABAB_ABAB_ABAB_ABAB, true));
            assert!(last_message().contains("sizeof"), "{}", last_message());
        }};
    }
    check!(mx_shape_options, 56, mx_shape_options_default, mx_shape_options_init);
    check!(mx_axis_options, 40, mx_axis_options_default, mx_axis_options_init);
    check!(mx_offset_options, 48, mx_offset_options_default, mx_offset_options_init);
    check!(mx_pocket_options, 40, mx_pocket_options_default, mx_pocket_options_init);
    check!(mx_vcarve_options, 32, mx_vcarve_options_default, mx_vcarve_options_init);
    check!(mx_voronoi_options, 48, mx_voronoi_options_default, mx_voronoi_options_init);
    check!(mx_drawing_select, 44, mx_drawing_select_default, mx_drawing_select_init);
    // What a 0.1 caller's _default gives is accepted as it is.
    let mut o: ShapeOptionsV01 = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { mx_shape_options_default((&mut o as *mut ShapeOptionsV01).cast()) }, mx_status::MX_OK);
    let (st, s) = rectangle(as_current(&o));
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    unsafe { mx_shape2d_free(s) };
}
