//! A small reader of `include/medax.h` for the tests that check the C API
//! (the ABI description, the naming and type conventions): comments
//! stripped, then function prototypes, enums and struct bodies by the
//! layout cbindgen writes.

use std::path::PathBuf;

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The header without comments, one declaration per line where it matters.
pub fn header_code() -> String {
    let text = std::fs::read_to_string(root().join("include/medax.h")).expect("include/medax.h");
    let mut out = String::with_capacity(text.len());
    let mut rest = text.as_str();
    while let Some(i) = rest.find("/*") {
        out.push_str(&rest[..i]);
        let end = rest[i..].find("*/").expect("closed comment") + i + 2;
        rest = &rest[end..];
    }
    out.push_str(rest);
    out.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n")
}

pub fn squash(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ").replace("( ", "(").replace(" )", ")")
}

/// `function <prototype>` for every function declared in the header: a
/// declaration starts at column 0 (not a typedef, not inside a struct or
/// enum body) and ends at `;`.
pub fn functions(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_body = false;
    let mut current: Option<String> = None;
    for line in code.lines() {
        if line.starts_with("typedef") && line.contains('{') {
            in_body = true;
        }
        if in_body {
            in_body = !line.starts_with('}');
            continue;
        }
        if current.is_none()
            && !line.starts_with([' ', '#', '}', '\t'])
            && line.contains('(')
            && !line.starts_with("typedef")
        {
            current = Some(String::new());
        }
        if let Some(c) = current.as_mut() {
            c.push(' ');
            c.push_str(line.trim());
            if line.trim_end().ends_with(';') {
                out.push(format!("function {}", squash(c)));
                current = None;
            }
        }
    }
    out
}

/// (enum name, [(constant, value)]) with implicit values filled in.
pub fn enums(code: &str) -> Vec<(String, Vec<(String, i64)>)> {
    let mut out = Vec::new();
    for part in code.split("typedef enum ").skip(1) {
        let name = part.split_whitespace().next().unwrap().to_owned();
        let body = &part[part.find('{').unwrap() + 1..part.find('}').unwrap()];
        let mut next = 0i64;
        let mut values = Vec::new();
        for item in body.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let (c, v) = match item.split_once('=') {
                Some((c, v)) => (c.trim(), v.trim().parse::<i64>().unwrap_or_else(|_| panic!("{name}: {item}"))),
                None => (item, next),
            };
            values.push((c.to_owned(), v));
            next = v + 1;
        }
        out.push((name, values));
    }
    out
}

/// (struct name, [field names]) of every struct with a body.
pub fn structs(code: &str) -> Vec<(String, Vec<String>)> {
    let mut out = Vec::new();
    for part in code.split("typedef struct ").skip(1) {
        let name = part.split_whitespace().next().unwrap().to_owned();
        let (Some(open), Some(semi)) = (part.find('{'), part.find(';')) else { continue };
        if semi < open {
            continue; // an opaque handle: `typedef struct mx_axis mx_axis;`
        }
        let body = &part[open + 1..part.find('}').unwrap()];
        let fields = body
            .split(';')
            .map(str::trim)
            .filter(|f| !f.is_empty())
            .map(|f| {
                let f = f.split('[').next().unwrap();
                // `type name` or a function pointer `ret (*name)(args)`.
                let f = f.rsplit("(*").next().unwrap().split(')').next().unwrap();
                f.split(|c: char| !(c.is_alphanumeric() || c == '_')).rfind(|w| !w.is_empty()).unwrap().to_owned()
            })
            .collect();
        out.push((name, fields));
    }
    out
}

/// One declared function: its return type, name and `(type, name)`
/// parameters, read from a `function` line of [`functions`].
pub struct Prototype {
    pub returns: String,
    pub name: String,
    pub params: Vec<(String, String)>,
}

pub fn prototypes(code: &str) -> Vec<Prototype> {
    functions(code)
        .iter()
        .map(|line| {
            let decl = line.trim_start_matches("function ").trim_end_matches(';');
            let open = decl.find('(').unwrap();
            let head = &decl[..open];
            let split = head.rfind([' ', '*']).unwrap() + 1;
            let (returns, name) = (head[..split].trim().to_owned(), head[split..].to_owned());
            let args = &decl[open + 1..decl.rfind(')').unwrap()];
            let params = if args.trim() == "void" {
                Vec::new()
            } else {
                args.split(',')
                    .map(|p| {
                        let p = p.trim();
                        let split = p.rfind([' ', '*']).unwrap() + 1;
                        (p[..split].trim().to_owned(), p[split..].to_owned())
                    })
                    .collect()
            };
            Prototype { returns, name, params }
        })
        .collect()
}
