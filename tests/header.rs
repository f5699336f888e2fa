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

fn header() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/medax.h")).expect("include/medax.h")
}

/// Every value of the header's `enum mx_status` has its own description
/// (a status added without one reads "unknown status").
#[test]
fn every_status_in_the_header_has_a_string() {
    let text = header();
    let start = text.find("enum mx_status {").expect("enum mx_status in the header");
    let body = &text[start..start + text[start..].find("} mx_status;").expect("end of the enum")];
    let mut seen = std::collections::HashSet::new();
    let mut count = 0;
    for line in body.lines() {
        let Some((name, value)) = line.trim().trim_end_matches(',').split_once(" = ") else { continue };
        let v: i32 = value.parse().unwrap_or_else(|_| panic!("{name} = {value}"));
        let s = unsafe { std::ffi::CStr::from_ptr(medax::ffi::mx_status_str(v)) }.to_str().unwrap().to_owned();
        assert_ne!(s, "unknown status", "{name} = {v} has no description");
        assert!(seen.insert(s.clone()), "{name}: description {s:?} is not its own");
        count += 1;
    }
    assert!(count >= 22, "only {count} statuses read from the header");
    for unknown in [-1, 21, 42, 98, 100] {
        let s = unsafe { std::ffi::CStr::from_ptr(medax::ffi::mx_status_str(unknown)) }.to_str().unwrap();
        assert_eq!(s, "unknown status", "{unknown}");
    }
}

/// Every name the header exports is prefixed: `mx_` functions and types,
/// `MX_` and `MEDAX_` macros and constants.
#[test]
fn every_exported_name_is_prefixed() {
    let text = header();
    let mut bad = Vec::new();
    for line in text.lines() {
        let t = line.trim_start();
        let name = if let Some(rest) = t.strip_prefix("typedef ").filter(|r| r.contains("(*")) {
            // A function pointer type: `typedef int (*name)(args);`.
            rest.split("(*").nth(1).and_then(|r| r.split(')').next())
        } else if let Some(rest) = t.strip_prefix("#define ") {
            rest.split_whitespace().next()
        } else if let Some(rest) = t.strip_prefix("typedef struct ") {
            rest.split_whitespace().next()
        } else if let Some(rest) = t.strip_prefix("typedef enum ") {
            rest.split_whitespace().next()
        } else if let Some(rest) = t.strip_prefix("struct ").filter(|r| r.ends_with('{')) {
            rest.split_whitespace().next()
        } else if let Some(rest) = t.strip_prefix("enum ").filter(|r| r.ends_with('{')) {
            rest.split_whitespace().next()
        } else if t.contains('(') && !t.starts_with('*') && !t.starts_with("//") && !line.starts_with(' ') {
            // A declaration at the start of a line: `type name(args...`.
            t.split('(').next().and_then(|head| head.split_whitespace().last()).map(|n| n.trim_start_matches('*'))
        } else {
            None
        };
        if let Some(n) = name {
            let n = n.trim_end_matches(';');
            if !(n.starts_with("mx_") || n.starts_with("MX_") || n.starts_with("MEDAX_")) {
                bad.push(n.to_owned());
            }
        }
    }
    assert!(bad.is_empty(), "unprefixed names in include/medax.h: {bad:?}");
}
