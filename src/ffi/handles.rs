//! Handles whose capabilities arrive with later issues: 3D meshes and unit
//! balls (the metric). They exist now so that the ABI and ownership rules
//! are fixed from the start; only `_free` is available. (`mx_axis` lives in
//! `axis.rs`.)

/// A triangulated solid (3D medial axis, thesis chapter 3). Opaque.
#[allow(non_camel_case_types)]
pub struct mx_mesh3d {
    _private: (),
}

/// A convex unit ball defining the metric (Euclidean disk or a polygon /
/// polytope, thesis chapter 3). Opaque.
#[allow(non_camel_case_types)]
pub struct mx_ball {
    _private: (),
}

/// Releases a `mx_mesh3d`. NULL is a no-op.
///
/// # Safety
/// `p` must be NULL or a handle returned by medax and not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_free(p: *mut mx_mesh3d) {
    if !p.is_null() {
        // SAFETY: per the contract, `p` came from Box::into_raw.
        drop(unsafe { Box::from_raw(p) });
    }
}

/// Releases a `mx_ball`. NULL is a no-op.
///
/// # Safety
/// `p` must be NULL or a handle returned by medax and not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_ball_free(p: *mut mx_ball) {
    if !p.is_null() {
        // SAFETY: per the contract, `p` came from Box::into_raw.
        drop(unsafe { Box::from_raw(p) });
    }
}
