//! The committed C header must be exactly what cbindgen generates from the
//! sources, and its version macros must match Cargo.toml.
//! Regenerate with `MEDAX_UPDATE_HEADER=1 cargo test --test header`.

mod common;

use common::c_header;
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
    for unknown in [-1, 22, 42, 98, 100] {
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

/// The rules of docs/C_API.md that a reader of the header can check:
/// what each function returns, the buffer protocol, one boolean type, kinds
/// as enums (a `uint32_t` only where the caller passes a kind in), counts
/// and indices as `size_t`, outputs last.
#[test]
fn every_declaration_follows_the_c_api_conventions() {
    let code = c_header::header_code();
    let mut bad = Vec::new();
    let kind_inputs = ["kind", "order", "format", "site_kind"];
    let sized = |name: &str| {
        name == "count"
            || name == "capacity"
            || name == "index"
            || name == "struct_size"
            || name.ends_with("_index")
            || name.ends_with("_count")
            || name.ends_with("_len")
    };
    let check_type = |owner: &str, ty: &str, name: &str, bad: &mut Vec<String>| {
        let base = ty.trim_start_matches("const ").trim_end_matches('*').trim();
        if base == "bool" || (base == "uint8_t" && !ty.starts_with("const uint8_t *")) {
            bad.push(format!("{owner} {name}: {ty} (booleans are int32_t; uint8_t only for input bytes)"));
        }
        // Arrays of uint32_t are triangles' vertex indices.
        if base == "uint32_t" && !kind_inputs.contains(&name) && !ty.ends_with('*') {
            bad.push(format!("{owner} {name}: uint32_t is for kinds the caller passes in and index arrays"));
        }
        // An index that may be absent (`mx_error_info`) is int64_t, −1 for none.
        if sized(name) && base != "size_t" && !(base == "int64_t" && name.ends_with("_index")) {
            bad.push(format!("{owner} {name}: {ty} (counts and indices are size_t)"));
        }
    };
    for p in c_header::prototypes(&code) {
        let n = p.name.as_str();
        let plain = n.ends_with("_free") && p.returns == "void"
            || matches!(
                (n, p.returns.as_str()),
                ("mx_status_str", "const char *")
                    | ("mx_version", "const char *")
                    | ("mx_version_number", "uint32_t")
                    | ("mx_last_error_length", "size_t")
                    | ("mx_last_error_message", "size_t")
                    | ("mx_clear_last_error", "void")
            );
        if !plain && p.returns != "enum mx_status" {
            bad.push(format!("{n} returns {} (fallible calls return enum mx_status)", p.returns));
        }
        for (ty, name) in &p.params {
            check_type(n, ty, name, &mut bad);
        }
        // Protocol 2: `..., T *buf, size_t capacity, size_t *count)`.
        if let Some(i) = p.params.iter().position(|(_, name)| name == "capacity") {
            let last = p.params.len() - 1;
            let before_is_buffer = i > 0 && p.params[i - 1].0.ends_with('*');
            if !(before_is_buffer && i + 1 == last && p.params[last] == ("size_t *".to_owned(), "count".to_owned())) {
                bad.push(format!("{n}: capacity must follow the buffer and precede the last `size_t *count`"));
            }
        }
        // Outputs come last; `_init(&o, sizeof o)` fills `o` of that size.
        if let Some(i) = p.params.iter().position(|(_, name)| name == "out") {
            let init =
                n.ends_with("_init") && p.params.len() == 2 && p.params[1] == ("size_t".to_owned(), "size".to_owned());
            if i + 1 != p.params.len() && !init {
                bad.push(format!("{n}: `out` is not the last parameter"));
            }
        }
        if p.params.iter().any(|(_, name)| name == "p" || name.is_empty()) {
            bad.push(format!("{n}: a parameter without a telling name"));
        }
    }
    for (s, fields) in c_header::structs(&code) {
        let body_start = code.find(&format!("typedef struct {s} {{")).unwrap();
        let body = &code[body_start..body_start + code[body_start..].find('}').unwrap()];
        for line in body.lines().skip(1).map(str::trim).filter(|l| l.ends_with(';') && !l.contains("(*")) {
            let decl = line.trim_end_matches(';').split('[').next().unwrap();
            let split = decl.rfind([' ', '*']).unwrap() + 1;
            check_type(&s, decl[..split].trim(), &decl[split..], &mut bad);
        }
        let options = s.ends_with("_options") || s == "mx_drawing_select";
        if options && fields.first().map(String::as_str) != Some("struct_size") {
            bad.push(format!("{s}: options structs start with struct_size"));
        }
    }
    assert!(bad.is_empty(), "include/medax.h breaks docs/C_API.md:\n{}", bad.join("\n"));
}
