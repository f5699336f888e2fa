//! Gives the shared library a SONAME (`libmedax.so.<major>`) so that binaries
//! linked against it keep working across minor releases and the installed
//! symlink chain `libmedax.so -> libmedax.so.<major> -> libmedax.so.<version>` resolves.

fn main() {
    let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "0".into());
    let target_os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os == "linux" {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libmedax.so.{major}");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
