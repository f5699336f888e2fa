//! Maximal-disk queries: time per disk at random boundary points of sample
//! shapes of 10^3..10^6 elements, single-threaded, and the index build;
//! then the divide step (all cuts down to leaves) per element.
//! `cargo bench --bench maxdisk`. Figures go to docs/PERFORMANCE.md.

use medax::plane::internals::decompose;
use medax::plane::DiskFinder;
use medax::shape::{samples, ElementRef, Shape2d, ShapeOptions, Vertex};
use std::time::Instant;

fn main() {
    type Gen = fn(usize) -> Vec<Vec<Vertex>>;
    let kinds: [(&str, Gen); 3] = [
        ("flower arcs (C1)", samples::flower_arcs),
        ("star polygon", |n| samples::star_polygon(n, 1)),
        ("plate with holes", |n| samples::perforated_plate(((n as f64) / 2.0).sqrt().ceil() as usize)),
    ];
    println!("| shape | n | index build | µs per disk |");
    println!("|---|---:|---:|---:|");
    for (name, gen) in kinds {
        for n in [1_000, 10_000, 100_000, 1_000_000] {
            let s = Shape2d::from_bulge_loops(gen(n), &ShapeOptions::default()).expect("samples are valid");
            let t = Instant::now();
            let finder = DiskFinder::new(&s);
            let build = t.elapsed().as_secs_f64();
            let mut x = 0x9e37_79b9_7f4a_7c15u64;
            let queries = 20_000;
            let points: Vec<(ElementRef, f64)> = (0..queries)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    let l = (x % s.loops().len() as u64) as usize;
                    let e = ((x >> 20) % s.loops()[l].len() as u64) as usize;
                    (ElementRef { loop_index: l, element: e }, 0.1 + 0.8 * ((x >> 40) as f64 / (1u64 << 24) as f64))
                })
                .collect();
            let t = Instant::now();
            let mut sum = 0.0;
            for &(at, f) in &points {
                sum += finder.max_disk(at, f).radius;
            }
            let per = t.elapsed().as_secs_f64() * 1e6 / queries as f64;
            std::hint::black_box(sum);
            println!("| {name} | {} | {build:.3} s | {per:.2} |", s.element_count());
        }
    }
    println!();
    println!("| divide step | n | cuts | leaves | stuck | time | µs per element |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    // The divide step is not tuned yet (see PERFORMANCE.md): the star
    // stops at 10^4 to keep the run short.
    for (name, gen, sizes) in
        [(kinds[0].0, kinds[0].1, &[1_000, 10_000, 100_000][..]), (kinds[1].0, kinds[1].1, &[1_000, 10_000][..])]
    {
        for &n in sizes {
            let s = Shape2d::from_bulge_loops(gen(n), &ShapeOptions::default()).expect("samples are valid");
            let t = Instant::now();
            let d = decompose(&s, 1).expect("no holes");
            let dt = t.elapsed().as_secs_f64();
            let m = s.element_count();
            println!(
                "| {name} | {m} | {} | {} | {} | {dt:.3} s | {:.2} |",
                d.cuts.len(),
                d.leaves.len(),
                d.stuck.len(),
                dt * 1e6 / m as f64
            );
        }
    }
}
