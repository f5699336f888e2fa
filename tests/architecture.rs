//! The layering of docs/ARCHITECTURE.md, checked on the sources: arrows
//! point down only, the files and folders of `src/plane` and `src/shape`
//! import each other without cycles, and files stay small. A refactor that breaks one of these rules
//! fails here rather than in a later reader's head.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// The file's code without its unit tests (a test may reach anywhere) and
/// without comments (a doc link is no dependency).
fn code_of(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let mut code = String::new();
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("#[cfg(test)]") {
            break;
        }
        if t.starts_with("//") {
            continue;
        }
        code.push_str(line);
        code.push('\n');
    }
    code
}

/// The module path of a source file: `src/plane/axis/mod.rs` is
/// `plane::axis`.
fn module_of(path: &Path) -> String {
    let rel = path.strip_prefix(src()).unwrap().with_extension("");
    let mut parts: Vec<String> = rel.iter().map(|s| s.to_string_lossy().into_owned()).collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts.join("::")
}

/// Every `crate::a::b::...`, `super::...` and `self::...` path in the code
/// of `module`, as the segments of its absolute path (without `crate`).
/// Relative paths are read as the file's own: an inline module (other than
/// the tests, which are cut) writes `crate::` paths.
fn crate_paths(module: &str, code: &str) -> Vec<Vec<String>> {
    let here: Vec<String> = module.split("::").filter(|s| !s.is_empty()).map(String::from).collect();
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(i) = ["crate::", "super::", "self::"].iter().filter_map(|k| code[at..].find(k)).min() {
        let start = at + i;
        at = start + 1;
        // Part of a longer name (`$crate::`, `my_super::`): no path.
        if code[..start].chars().next_back().is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '$') {
            continue;
        }
        let mut rest = &code[start..];
        let mut base: Vec<String> = Vec::new();
        if let Some(r) = rest.strip_prefix("crate::") {
            rest = r;
        } else if let Some(r) = rest.strip_prefix("self::") {
            base = here.clone();
            rest = r;
        } else {
            base = here.clone();
            while let Some(r) = rest.strip_prefix("super::") {
                base.pop();
                rest = r;
            }
        }
        let end = rest.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':')).unwrap_or(rest.len());
        let mut segs = base;
        segs.extend(rest[..end].split("::").filter(|s| !s.is_empty()).map(String::from));
        // A grouped import `crate::a::{b, c}` names each of b and c.
        if rest[end..].starts_with('{') {
            let close = rest[end..].find('}').map_or(rest.len(), |c| end + c);
            for item in rest[end + 1..close].split(',') {
                let item: String = item.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                if !item.is_empty() {
                    let mut s = segs.clone();
                    s.push(item);
                    out.push(s);
                }
            }
        }
        out.push(segs);
    }
    out
}

/// The layers below each top-level module: what it may use.
fn allowed(top: &str) -> Option<&'static [&'static str]> {
    Some(match top {
        "util" => &["util"],
        "io" => &["io", "util"],
        "kernel" => &["kernel", "io", "util"],
        "shape" => &["shape", "kernel", "io", "util"],
        "plane" => &["plane", "shape", "kernel", "io", "util"],
        // Chapter 3 beside chapter 2, not on it: it shares the shapes, the
        // ball and the kernel, never the Euclidean algorithms.
        "polymetric" => &["polymetric", "shape", "kernel", "io", "util"],
        "space" => &["space", "shape", "kernel", "io", "util"],
        "cam" => &["cam", "plane", "shape", "kernel", "io", "util"],
        _ => return None,
    })
}

#[test]
fn layers_use_only_the_layers_below() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut wrong = Vec::new();
    for f in &files {
        let module = module_of(f);
        let top = module.split("::").next().unwrap().to_string();
        let Some(ok) = allowed(&top) else { continue };
        for p in crate_paths(&module, &code_of(f)) {
            if let Some(first) = p.first() {
                if !ok.contains(&first.as_str()) {
                    wrong.push(format!("{module} uses crate::{}", p.join("::")));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "upward dependencies:\n{}", wrong.join("\n"));
}

/// Inside `plane`: the output graph knows nothing of the algorithm, the
/// algorithm nothing of its applications, and the applications
/// (Voronoi diagrams, offsets) nothing of each other.
#[test]
fn plane_capabilities_depend_downwards() {
    let rules: [(&str, &[&str]); 4] = [
        ("plane::axis", &["medial", "voronoi", "offset"]),
        ("plane::medial", &["voronoi", "offset"]),
        ("plane::voronoi", &["offset"]),
        ("plane::offset", &["voronoi"]),
    ];
    let mut files = Vec::new();
    rust_files(&src().join("plane"), &mut files);
    let mut wrong = Vec::new();
    for f in &files {
        let module = module_of(f);
        for (prefix, banned) in rules {
            if module == prefix || module.starts_with(&format!("{prefix}::")) {
                for p in crate_paths(&module, &code_of(f)) {
                    if p.len() > 1 && p[0] == "plane" && banned.contains(&p[1].as_str()) {
                        wrong.push(format!("{module} uses crate::{}", p.join("::")));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "dependencies against the grain:\n{}", wrong.join("\n"));
}

/// The import graph between the files under `src/<dir>`, each file's
/// module cut to its first `depth` segments (`usize::MAX`: the files; 2:
/// the folders and top files of `dir`). A module declaring its children
/// is no import, and `dir`'s own module only re-exports (its constants
/// import nothing).
fn import_graph(dir: &str, depth: usize) -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(&src().join(dir), &mut files);
    let cut = |m: &str| m.split("::").take(depth).collect::<Vec<_>>().join("::");
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(f)).collect();
    // The file a path lands in: its longest prefix that is a module.
    let file_of = |p: &[String]| -> Option<String> {
        (1..=p.len()).rev().map(|n| p[..n].join("::")).find(|m| modules.contains(m))
    };
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in &files {
        let module = module_of(f);
        let targets = edges.entry(cut(&module)).or_default();
        for p in crate_paths(&module, &code_of(f)) {
            if let Some(t) = file_of(&p) {
                if t != module && t != dir && cut(&t) != cut(&module) {
                    targets.insert(cut(&t));
                }
            }
        }
    }
    edges
}

/// The first import cycle of `edges`, if any (depth-first search for a
/// back edge).
fn find_cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(m.to_string(), 1);
        stack.push(m.to_string());
        for t in edges.get(m).into_iter().flatten() {
            match state.get(t.as_str()).copied().unwrap_or(0) {
                1 => {
                    let at = stack.iter().position(|s| s == t).unwrap();
                    let mut cycle = stack[at..].to_vec();
                    cycle.push(t.clone());
                    return Some(cycle);
                }
                0 => {
                    if let Some(c) = visit(t, edges, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(m.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for m in edges.keys() {
        if state.get(m.as_str()).copied().unwrap_or(0) == 0 {
            if let Some(c) = visit(m, edges, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

/// No import cycles under `src/<dir>`: between its files, nor between its
/// folders (and top files).
fn assert_no_import_cycles(dir: &str) {
    for depth in [usize::MAX, 2] {
        if let Some(c) = find_cycle(&import_graph(dir, depth)) {
            panic!("import cycle: {}", c.join(" -> "));
        }
    }
}

#[test]
fn plane_files_import_each_other_without_cycles() {
    assert_no_import_cycles("plane");
}

#[test]
fn shape_files_import_each_other_without_cycles() {
    assert_no_import_cycles("shape");
}

/// Files stay small enough to read whole. The ones still over the limit
/// are named here, each with its size today, so that none grows and a new
/// one cannot join them unnoticed.
#[test]
fn source_files_stay_small() {
    const LIMIT: usize = 600;
    let waived: &[(&str, usize)] = &[];
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut wrong = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(src()).unwrap().to_string_lossy().replace('\\', "/");
        let lines = std::fs::read_to_string(f).unwrap().lines().count();
        let limit = waived.iter().find(|w| w.0 == rel).map_or(LIMIT, |w| w.1);
        if lines > limit {
            wrong.push(format!("src/{rel}: {lines} lines (limit {limit})"));
        }
    }
    assert!(wrong.is_empty(), "files too long:\n{}", wrong.join("\n"));
}

/// Non-test code of the files under `dir`, each line with its file and
/// number.
fn code_lines(dir: &Path) -> Vec<(String, usize, String)> {
    let mut files = Vec::new();
    rust_files(dir, &mut files);
    let mut out = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(src()).unwrap().to_string_lossy().replace('\\', "/");
        for (i, line) in std::fs::read_to_string(f).unwrap().lines().enumerate() {
            let t = line.trim_start();
            if t.starts_with("#[cfg(test)]") {
                break;
            }
            if !t.starts_with("//") {
                out.push((rel.clone(), i + 1, line.to_string()));
            }
        }
    }
    out
}

/// The algorithms ask the kernel which side, which turn and which angle
/// (`AxisKernel` predicates, `kernel::fan`): no product of vectors
/// compared against zero or a tolerance, no `atan2` of their own, and the
/// sign helpers of `kernel::direction` reached through the kernel trait
/// (which an exact kernel overrides), not called directly.
#[test]
fn plane_asks_the_kernel_for_signs_and_angles() {
    let mut wrong = Vec::new();
    let free_sign_helpers = ["heading", "turn", "alignment", "direction_match", "vertex_fan_side"];
    for (file, n, line) in code_lines(&src().join("plane")) {
        let product = line.contains(".dot(") || line.contains(".cross(");
        let unarrowed = line.replace("=>", "").replace("->", "");
        let compared = unarrowed.contains('<') || unarrowed.contains('>') || unarrowed.contains("==");
        let helper = line.contains("direction::")
            && free_sign_helpers.iter().any(|h| {
                line.contains(&format!("direction::{h}("))
                    || line.contains(&format!(" {h},"))
                    || line.contains(&format!("{{{h},"))
                    || line.contains(&format!(" {h}}}"))
            });
        if line.contains("atan2") || (product && compared) || helper {
            wrong.push(format!("src/{file}:{n}: {}", line.trim()));
        }
    }
    assert!(wrong.is_empty(), "sign tests outside the kernel:\n{}", wrong.join("\n"));
}

/// Tolerances are asked of `kernel::tolerance::Tolerance` by name: no bare
/// `1e-N` and no `k * tol` in the algorithms.
#[test]
fn algorithms_name_their_tolerances() {
    // The public sampling floor is part of the API (a named constant that
    // callers read).
    let allowed = ["pub const MIN_RELATIVE_SAMPLE_TOLERANCE"];
    let mut wrong = Vec::new();
    for dir in ["plane", "cam"] {
        for (file, n, line) in code_lines(&src().join(dir)) {
            if allowed.iter().any(|a| line.contains(a)) {
                continue;
            }
            let bytes = line.as_bytes();
            let literal = (1..bytes.len().saturating_sub(2)).any(|i| {
                bytes[i] == b'e'
                    && bytes[i - 1].is_ascii_digit()
                    && bytes[i + 1] == b'-'
                    && bytes[i + 2].is_ascii_digit()
            });
            let multiple = ["* tol", "* self.tol", "* shape.tolerance()", "* tolerance"].iter().any(|m| {
                line.match_indices(m).any(|(i, _)| {
                    let before = line[..i].trim_end();
                    before.ends_with(|c: char| c.is_ascii_digit())
                })
            });
            if literal || multiple {
                wrong.push(format!("src/{file}:{n}: {}", line.trim()));
            }
        }
    }
    assert!(wrong.is_empty(), "unnamed tolerances:\n{}", wrong.join("\n"));
}
