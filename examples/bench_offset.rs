//! Trimmed offsets, side by side with cavalier_contours on the same shapes
//! (issue 5's benchmark; `scripts/bench-offset`, figures in
//! docs/PERFORMANCE.md, "Offsets").
//!
//! For each shape: medax's medial axis, the offset preparation
//! (`Offsets::from_axis`), then 20 layers one after another (the first is
//! the 1-distance case); cavalier_contours' `parallel_offset` at the same
//! 20 distances (a single loop: `Polyline::parallel_offset_opt` with its
//! segment index built once; with holes: `Shape::parallel_offset`, the
//! shape's indexes built once). Totals for 1 and 20 distances include the
//! axis. Agreement per distance: the same numbers of outer loops and holes
//! and total areas within 1e-6 relative. Where they differ, cavalier's
//! loops are checked against the offset distance (vertices and element
//! midpoints, distance to the boundary by medax's nearest-element search):
//! off by more than 1e-6 × diagonal counts as "cavalier off" (its result is
//! wrong there), otherwise as a disagreement to look into.
//! cavalier is slow on star polygons (its slices grow quadratically): it
//! stops after `BENCH_OFFSET_BUDGET` seconds (default 60) per shape, and a
//! size it would need more than that for is skipped.
//! Growth exponents: least-squares slope of log time over log n, n ≥ 10^3.
//!
//! `cargo run --release --example bench_offset -- [threads] [max_n]`
//! (threads for medax's rayon pool, default 1: cavalier is sequential).

use cavalier_contours::polyline::{PlineCreation, PlineOffsetOptions, PlineSource, PlineSourceMut, Polyline};
use cavalier_contours::shape_algorithms::{Shape, ShapeOffsetOptions};
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions, DiskFinder, OffsetLayer, Offsets};
use medax::shape::{samples, Shape2d, ShapeOptions, Vertex};
use std::time::Instant;

const LAYERS: usize = 20;

fn slope(points: &[(f64, f64)]) -> f64 {
    let k = points.len() as f64;
    let (sx, sy) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| (a + x.ln(), b + y.ln()));
    let (mx, my) = (sx / k, sy / k);
    let num: f64 = points.iter().map(|&(x, y)| (x.ln() - mx) * (y.ln() - my)).sum();
    let den: f64 = points.iter().map(|&(x, _)| (x.ln() - mx).powi(2)).sum();
    num / den
}

fn to_pline(vs: &[Vertex]) -> Polyline<f64> {
    let mut p = Polyline::with_capacity(vs.len(), true);
    for x in vs {
        p.add(x.p.x, x.p.y, x.bulge);
    }
    p
}

/// (outer loops, holes, signed area) of cavalier's result.
fn summary(plines: &[&Polyline<f64>]) -> (usize, usize, f64) {
    let areas: Vec<f64> = plines.iter().map(|p| p.area()).collect();
    (areas.iter().filter(|&&a| a > 0.0).count(), areas.iter().filter(|&&a| a < 0.0).count(), areas.iter().sum())
}

fn medax_summary(l: &OffsetLayer) -> (usize, usize, f64) {
    (l.loops.iter().filter(|x| x.area > 0.0).count(), l.loops.iter().filter(|x| x.area < 0.0).count(), l.area())
}

/// The largest |dist(q, boundary) − d| over cavalier's vertices and
/// element midpoints.
fn cavalier_defect(finder: &DiskFinder, plines: &[&Polyline<f64>], d: f64) -> f64 {
    let mut worst = 0.0f64;
    for p in plines {
        for seg in p.iter_segments() {
            let (a, b) = (Point::new(seg.0.x, seg.0.y), Point::new(seg.1.x, seg.1.y));
            let half = (b - a) * 0.5;
            // An arc's midpoint: the chord's middle moved by the sagitta to
            // the chord's right (bulge > 0, counter-clockwise) or left.
            let mid = a + half + Point::new(half.y, -half.x) * seg.0.bulge;
            for q in [a, mid] {
                let dist = finder.nearest(q).map_or(f64::INFINITY, |(_, r)| r);
                worst = worst.max((dist - d.abs()).abs());
            }
        }
    }
    worst
}

#[derive(Default)]
struct Row {
    n: usize,
    edges: usize,
    axis: f64,
    prep: f64,
    first: f64,
    per_layer: f64,
    /// cavalier's offsets run (of `LAYERS`), first and mean times.
    cav_runs: usize,
    cav_first: f64,
    cav_per: f64,
    agree: usize,
    cav_off: usize,
    differ: usize,
    worst_rel: f64,
}

fn run(s: &Shape2d, pool: &rayon::ThreadPool, cavalier_budget: Option<f64>) -> Row {
    let t = Instant::now();
    let axis = pool.install(|| medial_axis(s, &AxisOptions::default())).expect("axis");
    let t_axis = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let off = Offsets::from_axis(s, &axis).expect("offsets");
    let t_prep = t.elapsed().as_secs_f64();
    let m = off.max_inner_distance();
    // From near the boundary to near the last loop, as pocketing does.
    let distances: Vec<f64> = (0..LAYERS).map(|i| m * (0.013 + 0.9 * i as f64 / LAYERS as f64)).collect();
    let mut times = Vec::new();
    let mut ours = Vec::new();
    for &d in &distances {
        let t = Instant::now();
        let layer = pool.install(|| off.layer(d)).expect("layer");
        times.push(t.elapsed().as_secs_f64());
        ours.push(medax_summary(&layer));
    }
    let mut row = Row {
        n: s.element_count(),
        edges: axis.edges.len(),
        axis: t_axis,
        prep: t_prep,
        first: times[0],
        per_layer: times.iter().sum::<f64>() / LAYERS as f64,
        ..Row::default()
    };
    let Some(budget) = cavalier_budget else { return row };
    // cavalier_contours at the same distances, until the budget is spent.
    let plines: Vec<Polyline<f64>> = s.loops().iter().map(|l| to_pline(l.vertices())).collect();
    let finder = DiskFinder::new(s);
    let diag = s.bbox().diagonal();
    let single = plines.len() == 1;
    let index = plines[0].create_approx_aabb_index();
    let shape = if single { None } else { Some(Shape::from_plines(plines.clone())) };
    let mut cav_times = Vec::new();
    for (&d, a) in distances.iter().zip(&ours) {
        if cav_times.iter().sum::<f64>() > budget {
            break;
        }
        let t = Instant::now();
        let out: Vec<Polyline<f64>> = match &shape {
            None => {
                plines[0].parallel_offset_opt(d, &PlineOffsetOptions { aabb_index: Some(&index), ..Default::default() })
            }
            Some(sh) => {
                let o = sh.parallel_offset(d, ShapeOffsetOptions::default());
                o.ccw_plines.into_iter().chain(o.cw_plines).map(|p| p.polyline).collect()
            }
        };
        cav_times.push(t.elapsed().as_secs_f64());
        let refs: Vec<&Polyline<f64>> = out.iter().collect();
        let b = summary(&refs);
        let rel = (a.2 - b.2).abs() / a.2.abs();
        if (a.0, a.1) == (b.0, b.1) && rel <= 1e-6 {
            row.agree += 1;
            row.worst_rel = row.worst_rel.max(rel);
        } else if cavalier_defect(&finder, &refs, d) > 1e-6 * diag {
            row.cav_off += 1;
        } else {
            row.differ += 1;
            eprintln!("n {}: at {d} medax {a:?} cavalier {b:?}", row.n);
        }
    }
    row.cav_runs = cav_times.len();
    row.cav_first = cav_times[0];
    row.cav_per = cav_times.iter().sum::<f64>() / cav_times.len() as f64;
    row
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let threads: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1);
    let max_n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("pool");
    type Gen = fn(usize) -> Vec<Vec<Vertex>>;
    let kinds: [(&str, Gen); 3] = [
        ("flower arcs", samples::flower_arcs),
        ("random holes", |n| samples::random_holes(((n as f64 / 6.0).sqrt().round() as usize).max(1), 1)),
        ("star polygon", |n| samples::star_polygon(n, 3)),
    ];
    println!("medax {threads} thread(s); {LAYERS} distances from 0.013 to 0.868 of the largest inscribed radius");
    println!();
    println!("| shape | n | axis edges | axis | prep | medax 1 | medax 20 | per layer | µs/edge/layer | cavalier 1 | cavalier 20 | cavalier/medax at 20 | break-even k | agree | cavalier off | other | max rel. diff (agreeing) |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let budget: f64 = std::env::var("BENCH_OFFSET_BUDGET").ok().and_then(|s| s.parse().ok()).unwrap_or(60.0);
    let mut growth = Vec::new();
    for (name, gen) in kinds {
        let (mut g_axis, mut g_layer, mut g_cav) = (Vec::new(), Vec::new(), Vec::new());
        let mut cav_next = Some(budget);
        for n in [100, 1_000, 10_000, 100_000].into_iter().filter(|&n| n <= max_n) {
            let s = Shape2d::from_bulge_loops(gen(n), &ShapeOptions::default()).expect("samples are valid");
            let r = run(&s, &pool, cav_next);
            let fixed = r.axis + r.prep;
            let one = fixed + r.first;
            let twenty = fixed + LAYERS as f64 * r.per_layer;
            let ms = |t: f64| format!("{:.1} ms", 1e3 * t);
            let cav = if r.cav_runs == 0 {
                ["—".to_string(), "—".into(), "—".into(), "—".into()]
            } else {
                let k = if r.cav_runs < LAYERS { format!(" ({} run)", r.cav_runs) } else { String::new() };
                // Distances from which medax's total is below cavalier's.
                let even = if r.cav_per > r.per_layer {
                    format!("{:.0}", (fixed / (r.cav_per - r.per_layer)).ceil().max(1.0))
                } else {
                    "never".into()
                };
                [
                    ms(r.cav_first),
                    format!("{}{k}", ms(LAYERS as f64 * r.cav_per)),
                    format!("{:.2}", LAYERS as f64 * r.cav_per / twenty),
                    even,
                ]
            };
            println!(
                "| {name} | {} | {} | {} | {} | {} | {} | {:.3} ms | {:.3} | {} | {} | {} | {} | {} | {} | {} | {:.1e} |",
                r.n,
                r.edges,
                ms(r.axis),
                ms(r.prep),
                ms(one),
                ms(twenty),
                1e3 * r.per_layer,
                1e6 * r.per_layer / r.edges as f64,
                cav[0],
                cav[1],
                cav[2],
                cav[3],
                r.agree,
                r.cav_off,
                r.differ,
                r.worst_rel
            );
            if r.n >= 900 {
                g_axis.push((r.n as f64, fixed));
                g_layer.push((r.n as f64, r.per_layer));
                if r.cav_runs > 0 {
                    g_cav.push((r.n as f64, r.cav_per));
                }
            }
            // The next size is 10 times larger: skip cavalier if that would
            // exceed the budget at its growth so far (at least linear).
            let factor = if g_cav.len() >= 2 { 10f64.powf(slope(&g_cav).max(1.0)) } else { 10.0 };
            if r.cav_runs == 0 || r.cav_per * factor * LAYERS as f64 > 4.0 * budget {
                cav_next = None;
            }
        }
        if g_axis.len() >= 2 {
            let c = if g_cav.len() >= 2 { format!("{:.2}", slope(&g_cav)) } else { "—".into() };
            growth.push((name, slope(&g_axis), slope(&g_layer), c));
        }
    }
    println!();
    println!("Growth exponents (n ≥ 10^3): shape: medax axis + prep, medax per layer, cavalier per offset");
    for (name, a, l, c) in growth {
        println!("* {name}: {a:.2}, {l:.2}, {c}");
    }
}
