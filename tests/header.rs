//! The committed C header must be exactly what cbindgen generates from the
//! sources, and its version macros must match Cargo.toml.
//! Regenerate with `MEDAX_UPDATE_HEADER=1 cargo test --test header`.

use std::path::Path;

fn generate() -> String {
    let dir = env!("CARGO_MANIFEST_DIR");
    let config = cbindgen::Config::from_file(Path::new(dir).join("cbindgen.toml")).expect("cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen failed to read the crate");
    let mut out = Vec::new();
    bindings.write(&mut out);
    String::from_utf8(out).expect("header is UTF-8")
}

#[test]
fn header_is_fresh() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/medax.h");
    let fresh = generate();
    if std::env::var_os("MEDAX_UPDATE_HEADER").is_some() {
        std::fs::write(&path, &fresh).expect("write include/medax.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/medax.h is stale: run `MEDAX_UPDATE_HEADER=1 cargo test --test header` and commit it"
    );
}

#[test]
fn version_macros_match_cargo_toml() {
    let v = |s: &str| s.parse::<u32>().unwrap();
    assert_eq!(medax::ffi::MEDAX_VERSION_MAJOR, v(env!("CARGO_PKG_VERSION_MAJOR")));
    assert_eq!(medax::ffi::MEDAX_VERSION_MINOR, v(env!("CARGO_PKG_VERSION_MINOR")));
    assert_eq!(medax::ffi::MEDAX_VERSION_PATCH, v(env!("CARGO_PKG_VERSION_PATCH")));
    let s = unsafe { std::ffi::CStr::from_ptr(medax::ffi::mx_version()) };
    assert_eq!(s.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
    let header = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/medax.h")).unwrap();
    assert!(header.contains(&format!("#define MEDAX_VERSION_MAJOR {}", env!("CARGO_PKG_VERSION_MAJOR"))));
}
