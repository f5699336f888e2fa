//! Gives the shared library a SONAME that changes exactly when the ABI may
//! break: `libmedax.so.<major>` from 1.0 on, `libmedax.so.0.<minor>` before
//! (a 0.x minor release may change the ABI, a patch release may not; see
//! docs/C_API.md "Versions"). The loader then refuses to pair a binary with
//! a library it was not built for, and the installed symlink chain
//! `libmedax.so -> <SONAME> -> libmedax.so.<version>` resolves. CMakeLists.txt
//! computes the same name.

fn main() {
    let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "0".into());
    let minor = std::env::var("CARGO_PKG_VERSION_MINOR").unwrap_or_else(|_| "0".into());
    let soname = if major == "0" { format!("libmedax.so.0.{minor}") } else { format!("libmedax.so.{major}") };
    let target_os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os == "linux" {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{soname}");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
