//! `medax info`: the validation report.

use super::{fail, ShapeArgs};
use medax::shape::Shape2d;
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
    let reversed: Vec<String> = (0..s.loops().len()).filter(|&l| s.was_reversed(l)).map(|l| l.to_string()).collect();
    if !reversed.is_empty() {
        out += &format!("reversed to normalise orientation: loop(s) {}\n", reversed.join(", "));
    }
    if s.flattened_arcs() > 0 {
        out += &format!("nearly straight arcs stored as segments: {}\n", s.flattened_arcs());
    }
    out
}

pub fn run(args: &ShapeArgs) -> Result<(), ExitCode> {
    let t = Instant::now();
    let s = args.load().map_err(|e| fail(&args.shape, &e))?;
    super::put(&report(&s));
    out!("read and validated in {:.3} s", t.elapsed().as_secs_f64());
    Ok(())
}
