//! `medax info`: the validation report.

use super::{fail, ShapeArgs};
use medax::shape::{Drawing2d, IgnoredKind, Shape2d};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// Formats the report for a valid shape.
pub fn report(s: &Shape2d) -> String {
    let (segs, arcs) = s.element_counts();
    let [smooth, convex, reflex] = s.joint_counts();
    let bb = s.bbox();
    let mut out = String::new();
    out += &format!("valid shape: {} loop(s) (1 outer, {} hole(s))\n", s.loops().len(), s.holes().len());
    out += &format!("elements: {} ({segs} segments, {arcs} arcs)\n", s.element_count());
    out += &format!("joints: {convex} convex, {reflex} reflex, {smooth} smooth\n");
    out += &format!("area: {}\n", s.area());
    out += &format!("bounding box: [{}, {}] x [{}, {}]\n", bb.min.x, bb.max.x, bb.min.y, bb.max.y);
    out += &format!("tolerance: {:e}\n", s.tolerance());
    // The first few, and how many: a plate of 10^4 holes drawn the wrong
    // way round named every one.
    const NAMED: usize = 10;
    let reversed: Vec<usize> = (0..s.loops().len()).filter(|&l| s.was_reversed(l)).collect();
    if !reversed.is_empty() {
        let named: Vec<String> = reversed.iter().take(NAMED).map(|l| l.to_string()).collect();
        let more = if reversed.len() > NAMED { format!(" … ({} in all)", reversed.len()) } else { String::new() };
        out += &format!("reversed to normalise orientation: loop(s) {}{more}\n", named.join(", "));
    }
    if s.flattened_arcs() > 0 {
        out += &format!("nearly straight arcs stored as segments: {}\n", s.flattened_arcs());
    }
    out
}

pub fn run(args: &ShapeArgs, json: Option<&Path>) -> Result<(), ExitCode> {
    if super::mesh::is_mesh(&args.shape) {
        return super::mesh::run_info(&args.shape);
    }
    let t = Instant::now();
    let d = args.load_drawing().map_err(|e| fail(&args.shape, &e))?;
    if let Some(path) = json {
        super::write_file(path, &d.to_json())?;
        out!("wrote {}", path.display());
    }
    if d.shapes.is_empty() {
        put_ignored(&d);
        return Err(fail(&args.shape, &super::no_shape(&d, 0)));
    }
    let only = match args.pick {
        Some(super::Pick::One(k)) => Some(k),
        _ => None,
    };
    if d.shapes.len() == 1 && only.is_none_or(|k| k == 0) {
        super::put(&report(&d.shapes[0]));
    } else {
        out!("{} shapes (largest first; `--shape K` picks one for the other commands)", d.shapes.len());
        for (k, s) in d.shapes.iter().enumerate().filter(|(k, _)| only.is_none_or(|p| p == *k)) {
            out!("shape {k}:");
            for line in report(s).lines() {
                out!("  {line}");
            }
        }
    }
    put_ignored(&d);
    out!("read and validated in {:.3} s", t.elapsed().as_secs_f64());
    Ok(())
}

/// What the drawing held besides its shapes: a count per kind and the
/// first few of each.
fn put_ignored(d: &Drawing2d) {
    const SHOWN: usize = 5;
    for kind in [
        IgnoredKind::OpenChain,
        IgnoredKind::FlatLoop,
        IgnoredKind::DuplicateLoop,
        IgnoredKind::TouchingLoop,
        IgnoredKind::InvalidShape,
    ] {
        let all: Vec<_> = d.ignored.iter().filter(|i| i.kind == kind).collect();
        if all.is_empty() {
            continue;
        }
        out!("ignored: {} {}(s)", all.len(), kind.name());
        for i in all.iter().take(SHOWN) {
            let layer = if i.layer.is_empty() { String::new() } else { format!(", layer {}", i.layer) };
            let handles = if i.handles.is_empty() {
                String::new()
            } else {
                let hex: Vec<String> = i.handles.iter().map(|h| format!("{h:X}")).collect();
                format!(", handle {}", hex.join(" and "))
            };
            out!("  at line/byte {}{layer}{handles} near ({}, {}): {}", i.source, i.position.x, i.position.y, i.reason);
        }
        if all.len() > SHOWN {
            out!("  … and {} more", all.len() - SHOWN);
        }
    }
    if let Some(units) = d.units {
        out!("units: {units} (DXF $INSUNITS)");
    }
    if let Some((p, widest)) = d.gaps.first() {
        out!("gaps closed: {} (widest {widest:e} at ({}, {}))", d.gaps.len(), p.x, p.y);
    }
    if !d.touching.is_empty() {
        out!("touching shapes: {} pair(s), each kept", d.touching.len());
        for t in d.touching.iter().take(SHOWN) {
            let [a, b] = t.shapes;
            let [la, lb] = t.sources;
            out!(
                "  shapes {a} and {b} meet at ({}, {}): entities at line/byte {la} and {lb}{}",
                t.position.x,
                t.position.y,
                if t.handles == [0, 0] {
                    String::new()
                } else {
                    format!(" (handles {:X} and {:X})", t.handles[0], t.handles[1])
                }
            );
        }
        if d.touching.len() > SHOWN {
            out!("  … and {} more", d.touching.len() - SHOWN);
        }
    }
}
