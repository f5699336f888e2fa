//! The slow tier: the medial axis at 10^5, 3·10^5 and 10^6 elements on
//! generated families (smooth random Fourier curves with ten seeds, alone
//! and with holes of their kind, nearly circular curves, random star
//! polygons, flowers, plates of random holes, plates of letters, nearly
//! straight bands), each checked by the sampled oracle of
//! `common::oracle` (every axis sample's radius is its distance to the
//! boundary; the maximal disk at random boundary points is centred on the
//! axis or, where disks hug the boundary within the tolerance, lies within
//! 64τ inside a disk of the axis; the graph is a tree with one cycle per
//! hole; distances on a thousand edges and nodes of each axis, spread
//! over it). Ignored by default (minutes in a release
//! build): `cargo test --release --test scale_sweep -- --ignored`.

mod common;

use common::oracle::check_strided;
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{samples, Shape2d, ShapeOptions, Vertex};

/// Distances agree within this many 1e-9 of the diagonal (the default
/// tolerance τ), where the corpus tests ask for one: at 10^5 arcs and
/// more, neighbouring arcs differ from a disk by less than τ over a joint
/// node's contacts, and a joint node's disk was measured to overlap one
/// of them by up to 1.4τ (Fourier seed 10 at 10^5; the library's own
/// final check allows 64τ).
const SLACK: f64 = 4.0;

/// Boundary probes of the completeness check per shape.
const PROBES: usize = 300;

/// About this many edges and nodes get the brute-force soundness check
/// (the library checks every one itself before it returns an axis).
const CHECKED: usize = 1000;

fn sweep(name: &str, loops: Vec<Vec<Vertex>>) {
    check_shape(name, &Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid sample"));
}

fn check_shape(name: &str, shape: &Shape2d) {
    let axis = medial_axis(shape, &AxisOptions::default())
        .unwrap_or_else(|e| panic!("{name} ({} elements): {e}", shape.element_count()));
    let stride = axis.edges.len().div_ceil(CHECKED);
    let report = check_strided(shape, &axis, PROBES, 7, stride, SLACK);
    eprintln!(
        "{name}: {} elements, {} nodes, {} samples checked, {} of {PROBES} probes nested (up to {:.1e} off the axis)",
        shape.element_count(),
        axis.nodes.len(),
        report.samples,
        report.nested.0,
        report.nested.1
    );
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn fourier_curves_of_ten_seeds_at_1e5_and_3e5() {
    for seed in 1..=10 {
        sweep(&format!("fourier 1e5 seed {seed}"), samples::fourier_biarcs(100_000, seed));
    }
    for seed in 1..=2 {
        sweep(&format!("fourier 3e5 seed {seed}"), samples::fourier_biarcs(300_000, seed));
    }
    // 10^6 arcs: `a_million_elements`.
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn nearly_circular_curves() {
    for seed in 1..=2 {
        sweep(&format!("near circle 1e5 seed {seed}"), samples::fourier_curve(100_000, seed, 1e-3));
    }
    // Broke down until 49a2761: every disk near the centre hugs about a
    // hundred arcs within the tolerance (see base_case/hug_runs.rs).
    sweep("near circle 3e5", samples::fourier_curve(300_000, 3, 1e-3));
    // Found on fresh seeds after balanced cuts landed: their largest disks
    // broke a base case here; the retry divides with plain random cuts.
    sweep("near circle 1e5 seed 5", samples::fourier_curve(100_000, 5, 1e-3));
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn inputs_that_broke_down_until_stop_33() {
    // "the axis fell apart into pieces" before; computes since stop 33.
    sweep("within 1e-5 of a circle 5e4", samples::fourier_curve(50_000, 1, 1e-5));
    // "no branch point in a pocket" after three decompositions before.
    sweep("random holes 450x450 seed 3", samples::random_holes(450, 3));
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn inputs_that_broke_down_until_stop_34() {
    // Fresh seeds, "no branch point in a pocket" until stop 34: arcs
    // shorter than the √(τ·r) to which contacts along them are placed (a
    // smooth joint's disk, a branch point past a chain's end), and a
    // branch point between lines anchored 5·10^4 away.
    sweep("fourier 3e5 seed 11", samples::fourier_biarcs(300_000, 11));
    sweep("slanted comb 3e5", samples::slanted_comb(75_000, 37_500.0));
    sweep("fourier 1e6 with 40 holes seed 13", samples::fourier_with_holes(1_000_000, 40, 13));
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn nearly_circular_inputs_that_broke_down() {
    // Curves within 10^-4 and 10^-5 of a circle: "the axis fell apart
    // into pieces" after three decompositions until stop 37 (a leaf
    // between dividing disks a few tolerances apart named them by one
    // node, which gluing did not know), then cycles of two copies of one
    // stretch. (Seed 1 at 10^5 and 2·10^5 and a curve within 10^-4 at
    // 3·10^5 passed once too: 4 min of checking, near the centre every
    // disk reaches across the whole grid.)
    sweep("within 1e-5 of a circle 1e5 seed 2", samples::fourier_curve(100_000, 2, 1e-5));
    sweep("within 1e-7 of a circle 1e4 seed 1", samples::fourier_curve(10_000, 1, 1e-7));
    // "An edge's disks are not maximal" until stop 38: short hyperbolas
    // between arcs of nearly one circle whose middle disk strayed 80–210τ
    // off the chord and across the boundary, and edges from a leaf arc's
    // centre to a joint between that arc and itself.
    sweep("within 1e-6 of a circle 1e5 seed 2", samples::fourier_curve(100_000, 2, 1e-6));
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn nearly_circular_curves_of_a_million_arcs() {
    // Seed 4 fell apart into pieces until stop 34 (a cut 4τ from its twin,
    // which had merged into a disk just over 64τ away, stayed a node of
    // its own). Until stop 38, seed 6 reported "an edge's disks are not
    // maximal" (the spoke out to the curvature centre of one short tight
    // arc, whose footpoints barely move along it, evaluated by a footpoint
    // parameter) and seed 3 "no branch point in a pocket" (a leaf of that
    // spoke and two central disks, all hugging its chains); seed 9 too (a
    // hyperbola between arcs of nearly tangent circles whose middle
    // footpoint parameter gave a disk far off the edge). The oracle
    // passed on seeds 3, 4, 6 and 9 once (`MEDAX_SWEEP_FILES`, 10–16 min of
    // checking each: every disk near the centre reaches across the whole
    // grid); here the library's own final check (a tree whose node and
    // edge disks are maximal and touch their primitives) and the tree's
    // counts.
    for seed in [3, 4, 6, 9] {
        let loops = samples::fourier_curve(1_000_000, seed, 1e-3);
        let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
        let axis =
            medial_axis(&shape, &AxisOptions::default()).unwrap_or_else(|e| panic!("near circle 1e6 seed {seed}: {e}"));
        assert_eq!(axis.edges.len() + 1, axis.nodes.len());
        assert!(axis.nodes.len() > 600_000, "seed {seed}: {} nodes", axis.nodes.len());
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn star_polygons_and_flowers_at_1e5_and_3e5() {
    for seed in 1..=2 {
        sweep(&format!("star 1e5 seed {seed}"), samples::star_polygon(100_000, seed));
    }
    sweep("star 3e5", samples::star_polygon(300_000, 3));
    for n in [100_000, 300_000] {
        sweep(&format!("flower {n}"), samples::flower_arcs(n));
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn plates_of_random_holes() {
    // About 5 elements per hole: 10^5 and 3·10^5 elements (9·10^5 in
    // `inputs_that_broke_down_until_stop_33`).
    for (k, seed) in [(140, 1), (245, 2)] {
        sweep(&format!("random holes {k}x{k} seed {seed}"), samples::random_holes(k, seed));
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn fourier_curves_with_holes_of_their_kind() {
    // The second family issue 17 found breaking down: 40 holes, 5·10^5
    // arcs in all.
    for (n, seed) in [(100_000, 1), (300_000, 2), (500_000, 3)] {
        sweep(&format!("fourier {n} with 40 holes seed {seed}"), samples::fourier_with_holes(n, 40, seed));
    }
    sweep("fourier 3e5 with 400 holes", samples::fourier_with_holes(300_000, 400, 4));
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn dense_text_like_outlines() {
    for (n, seed) in [(100_000, 1), (300_000, 2)] {
        sweep(&format!("text {n} seed {seed}"), samples::text_plate(n, seed));
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn nearly_straight_long_bands() {
    // Sides within 10^-3, 10^-5 and exactly 0 of straight lines: arcs of
    // radius 100 and more, then 10^4 and more, then plain segments.
    for (n, spread) in [(100_000, 1e-3), (300_000, 1e-3), (300_000, 1e-5), (100_000, 0.0)] {
        sweep(&format!("strip {n} spread {spread}"), samples::nearly_straight_strip(n, 1, spread));
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn a_million_elements() {
    sweep("fourier 1e6 seed 1", samples::fourier_biarcs(1_000_000, 1));
    sweep("fourier 1e6 with 40 holes", samples::fourier_with_holes(1_000_000, 40, 1));
    sweep("text 1e6", samples::text_plate(1_000_000, 1));
    sweep("strip 1e6", samples::nearly_straight_strip(1_000_000, 1, 1e-3));
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn a_flower_of_a_million_arcs() {
    sweep("flower 1e6", samples::flower_arcs(1_000_000));
    // A random star of 10^6 vertices computes (14.8 s, docs/PERFORMANCE.md)
    // but is not checked here: the oracle's grids bucket every item by its
    // box, and the star's long radial sides and spines cover about 10^5
    // cells each at that size (killed at 24 GB).
}

/// The same oracle on shape files named in `MEDAX_SWEEP_FILES` (spaces
/// between; `examples/write_sample` writes fresh seeds of every family):
/// `MEDAX_SWEEP_FILES="a.json b.json" cargo test --release --test
/// scale_sweep -- --ignored shape_files`. Nothing without it.
#[test]
#[ignore = "a tool for fresh inputs: set MEDAX_SWEEP_FILES"]
fn shape_files_from_the_environment() {
    let files = std::env::var("MEDAX_SWEEP_FILES").unwrap_or_default();
    for path in files.split_whitespace() {
        let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let shape = Shape2d::from_json_str(&text, &ShapeOptions::default()).unwrap_or_else(|e| panic!("{path}: {e}"));
        check_shape(path, &shape);
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn offsets_of_smooth_curves_at_1e4_to_3e5_arcs() {
    // "A whole element is skipped that is no leaf arc" until stop 38 (10^5
    // seeds 1, 2): bands whose axis is the straight edge between two
    // hugging disks name one element of each chain, and the offsets' side
    // cycle accepted only leaf arcs between the sides at a node. Until
    // stop 40 (3·10^5 seeds 35, 44, 46, the same message or "two axis edge
    // sides lead to the same successor"): spikes of a few τ off the spine
    // at a hugged tip, whose sides were out of boundary order. Until issue
    // 46: offset arcs following one element's circle past its end where a
    // disk hugs a stretch of nearly concentric arcs, which only points
    // along the arcs show. Checked by the offset oracle's brute-force
    // distances (tests/common/offset_oracle.rs) at points along every
    // element of every loop.
    use common::offset_oracle::{Elem, Loops};
    use medax::plane::{OffsetOptions, Offsets};
    let families: Vec<(String, Vec<Vec<Vertex>>)> = vec![
        ("fourier 1e5 seed 1".into(), samples::fourier_biarcs(100_000, 1)),
        ("fourier 1e5 seed 2".into(), samples::fourier_biarcs(100_000, 2)),
        ("fourier 3e5 seed 35".into(), samples::fourier_biarcs(300_000, 35)),
        ("fourier 3e5 seed 44".into(), samples::fourier_biarcs(300_000, 44)),
        ("fourier 3e5 seed 46".into(), samples::fourier_biarcs(300_000, 46)),
        ("fourier 1e5 with 40 holes seed 3".into(), samples::fourier_with_holes(100_000, 40, 3)),
        ("fourier 1e4 with 5 holes seed 4".into(), samples::fourier_with_holes(10_000, 5, 4)),
        ("within 1e-3 of a circle 1e4 seed 5".into(), samples::fourier_curve(10_000, 5, 1e-3)),
        ("within 1e-3 of a circle 1e4 seed 6".into(), samples::fourier_curve(10_000, 6, 1e-3)),
    ];
    for (name, loops) in families {
        let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid sample");
        let offsets = Offsets::new(&shape, &OffsetOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let truth = Loops::of_shape(&shape);
        let tol = SLACK * 1e-9 * shape.bbox().diagonal();
        let mut area = f64::INFINITY;
        let mut points = 0;
        for fraction in [0.001, 0.01, 0.05, 0.3, 0.8] {
            let rho = fraction * offsets.max_inner_distance();
            let layer = offsets.layer(rho).unwrap_or_else(|e| panic!("{name}: layer {rho}: {e}"));
            assert!(!layer.loops.is_empty(), "{name}: nothing at {rho}");
            // About 2000 elements per layer, spread over every loop, each
            // at its start and three points along it.
            let count: usize = layer.loops.iter().map(|l| l.vertices.len()).sum();
            let step = (count / 2000).max(1);
            for l in &layer.loops {
                let n = l.vertices.len();
                for i in (0..n).step_by(step) {
                    let (a, b) = (l.vertices[i], l.vertices[(i + 1) % n]);
                    let e = Elem::new(a.p, b.p, a.bulge);
                    for q in [0.0, 0.25, 0.5, 0.75].map(|t| e.at(t)) {
                        let d = truth.dist(q);
                        assert!((d - rho).abs() <= tol, "{name}: {q:?} lies {d} from the boundary, not {rho}");
                        points += 1;
                    }
                }
            }
            let a: f64 = layer.loops.iter().map(|l| l.area).sum();
            assert!(a > 0.0 && a < area, "{name}: area {a} at {rho} after {area}");
            area = a;
        }
        println!("{name}: offsets at five distances checked at {points} points");
    }
}
