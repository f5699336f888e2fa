//! Version of the library, at compile time (macros) and at run time.

use std::ffi::c_char;

/// Major version of the medax headers (the SONAME is `libmedax.so.<major>`).
pub const MEDAX_VERSION_MAJOR: u32 = 0;
/// Minor version of the medax headers.
pub const MEDAX_VERSION_MINOR: u32 = 3;
/// Patch version of the medax headers.
pub const MEDAX_VERSION_PATCH: u32 = 0;

/// The version of the loaded library as a static NUL-terminated string
/// `"MAJOR.MINOR.PATCH"`. Compare with the `MEDAX_VERSION_*` macros to detect
/// a header/library mismatch. Never NULL; do not free.
#[no_mangle]
pub extern "C" fn mx_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// The version of the loaded library as `major * 10000 + minor * 100 + patch`.
#[no_mangle]
pub extern "C" fn mx_version_number() -> u32 {
    let p = |s: &str| s.parse::<u32>().unwrap_or(0);
    p(env!("CARGO_PKG_VERSION_MAJOR")) * 10000
        + p(env!("CARGO_PKG_VERSION_MINOR")) * 100
        + p(env!("CARGO_PKG_VERSION_PATCH"))
}
