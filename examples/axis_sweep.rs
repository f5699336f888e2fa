//! Robustness sweep of the medial axis: how many of a fixed set of sample
//! shapes (random star polygons and biarc flowers of 100..2000 elements)
//! end in a reported numerical breakdown, for several leaf sizes of the
//! divide step. `cargo run --release --example axis_sweep`. Every axis that
//! is returned has passed the library's own tree and disk checks; the
//! oracle tests are in tests/axis.rs. Figures go to docs/PERFORMANCE.md.
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{samples, Shape2d, ShapeOptions};
fn main() {
    for lp in [3usize, 6, 12, 24, 32] {
        let mut fails = Vec::new();
        let mut total = 0;
        for seed in 0..6u64 {
            for n in [100usize, 300, 1000, 2000] {
                for (name, loops) in
                    [("star", samples::star_polygon(n, seed)), ("flower", samples::flower_arcs(n + seed as usize * 37))]
                {
                    let Ok(s) = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()) else { continue };
                    total += 1;
                    if let Err(e) = medial_axis(&s, &AxisOptions { leaf_parts: lp, ..AxisOptions::default() }) {
                        fails.push(format!("{name} {n} s{seed}: {e}"));
                    }
                }
            }
        }
        println!("leaf_parts {lp}: {} of {total} failed", fails.len());
        for f in fails.iter().take(4) {
            println!("   {f}");
        }
    }
}
