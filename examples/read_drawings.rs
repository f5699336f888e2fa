//! Reads every DXF and SVG drawing under a directory (or one file) through
//! profile extraction and reports files per second, how many gave a shape,
//! and what was ignored by kind: the import benchmark of issue 27.
//!
//! `cargo run --release --example read_drawings -- /usr/share/librecad`

use medax::shape::{Drawing2d, DrawingOptions, ShapeOptions};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

fn main() {
    let root = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "/usr/share/librecad".into()));
    let mut files = Vec::new();
    let mut dirs = vec![root.clone()];
    if root.is_file() {
        files.push(root);
        dirs.clear();
    }
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("a readable directory").flatten() {
            let p = entry.path();
            let drawing = p.extension().is_some_and(|e| e.eq_ignore_ascii_case("dxf") || e.eq_ignore_ascii_case("svg"));
            if p.is_dir() {
                dirs.push(p);
            } else if drawing {
                files.push(p);
            }
        }
    }
    files.sort();
    // Read once untimed, so that the timed pass reads from the page cache.
    let texts: Vec<Vec<u8>> = files.iter().map(|f| std::fs::read(f).expect("a readable file")).collect();
    let bytes: usize = texts.iter().map(Vec::len).sum();
    let (opts, select) = (ShapeOptions::default(), DrawingOptions::default());
    let t = Instant::now();
    let (mut with_shapes, mut shapes, mut errors, mut touching) = (0, 0, 0, 0);
    let mut ignored: BTreeMap<&'static str, usize> = BTreeMap::new();
    for f in &files {
        match Drawing2d::from_file(f, &opts, &select) {
            Ok(d) => {
                with_shapes += usize::from(!d.shapes.is_empty());
                shapes += d.shapes.len();
                touching += d.touching.len();
                for i in &d.ignored {
                    *ignored.entry(i.kind.name()).or_default() += 1;
                }
            }
            Err(_) => errors += 1,
        }
    }
    let secs = t.elapsed().as_secs_f64();
    println!(
        "{} files ({:.1} MB) in {secs:.3} s: {:.0} files/s, {:.1} MB/s",
        files.len(),
        bytes as f64 / 1e6,
        files.len() as f64 / secs,
        bytes as f64 / 1e6 / secs
    );
    println!("{with_shapes} files gave {shapes} shapes ({touching} pairs touching); {errors} could not be read");
    for (kind, n) in ignored {
        println!("  ignored {kind}: {n}");
    }
}
