//! Diagnoses a medial-axis breakdown: decomposes a sample shape as
//! `medial_axis` does and solves every leaf on its own, printing each
//! leaf that fails with its pieces and dividing disks (and, for a chain
//! cut off by one disk, how far each element strays from that disk).
//! `cargo run --release --example axis_debug -- star|flower N [SEED]` or
//! `-- plate K [SEED]` or `-- SHAPE.json 0 [SEED]` (a shape file, or a Voronoi sites file: the
//! shape its diagram is computed on first, frame or boundary with the sites as holes); `MEDAX_NEAR=x,y` lists the dividing disks near a point;
//! `MEDAX_DUMP=DIR` writes each failing leaf for `examples/leaf_replay`;
//! `MEDAX_PLAIN=1` decomposes as the retries after a breakdown do.
use medax::kernel::Disk;
use medax::plane::internals::augment;
use medax::plane::internals::base_case;
use medax::plane::internals::{decompose_in, decompose_plain_in};
use medax::plane::AxisOptions;
use medax::plane::DiskFinder;
use medax::plane::Piece;
use medax::shape::{samples, Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let shape = match args.get(1).map(String::as_str) {
        Some(path) if path.ends_with(".json") => {
            let text = std::fs::read_to_string(path).expect("readable shape file");
            medax::plane::shape_or_sites(&text).expect("a valid shape or sites file")
        }
        kind => {
            let loops = match kind {
                Some("flower") => samples::flower_arcs(n),
                Some("plate") => samples::perforated_plate(n),
                Some("holes") => samples::random_holes(n, 1),
                _ => samples::star_polygon(n, 1),
            };
            Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid sample")
        }
    };
    let finder = DiskFinder::new(&shape);
    let opts = AxisOptions::default();
    let seed: u64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(opts.seed);
    let aug = augment(&finder).expect("augmenting disks");
    // MEDAX_PLAIN: the decomposition of `medial_axis`'s retries (first
    // dividing disk, no balanced cuts); their seeds are SEED and
    // SEED + 0x9e3779b97f4a7c15.
    let d = if std::env::var_os("MEDAX_PLAIN").is_some() {
        decompose_plain_in(&finder, &aug, seed, opts.leaf_parts)
    } else {
        decompose_in(&finder, &aug, seed, opts.leaf_parts)
    };
    println!("{} cuts, {} leaves, {} stuck", d.cuts.len(), d.leaves.len(), d.stuck.len());
    if std::env::var("MEDAX_CORNERS").is_ok() || std::env::var("MEDAX_CHECK").is_ok() {
        glued_corners(&shape, &finder, seed);
    }
    if let Some(v) = std::env::var("MEDAX_VERTEX").ok().and_then(|s| s.parse::<usize>().ok()) {
        let n = shape.loops()[0].len();
        for (i, s) in d.leaves.iter().chain(d.stuck.iter()).enumerate() {
            for (from, to) in s.chains() {
                let parts = medax::plane::internals::ChainParts::new(&shape, from, to);
                if parts.iter().any(|(e, _, _)| e == v || e == (v + n - 1) % n) {
                    println!("leaf {i}: {:?}", s.pieces);
                }
            }
        }
    }
    // MEDAX_NEAR=x,y: the dividing disks near a point of interest.
    if let Some((x, y)) = std::env::var("MEDAX_NEAR").ok().and_then(|v| {
        let (a, b) = v.split_once(',')?;
        Some((a.parse::<f64>().ok()?, b.parse::<f64>().ok()?))
    }) {
        let p = medax::kernel::Point::new(x, y);
        for (i, c) in d.cuts.iter().enumerate().filter(|(_, c)| c.center.dist(p) < 1e-2) {
            println!("cut {i}: {c:?}, {:e} from the point", c.center.dist(p));
        }
    }
    for (i, s) in d.leaves.iter().chain(d.stuck.iter()).enumerate() {
        let solved = base_case::solve(&shape, s, &d.cuts, shape.tolerance(), &finder);
        if let Ok(local) = &solved {
            // Convex corners inside the leaf's chains must be corner nodes.
            let convex = convex_inside(&shape, s);
            let corners = local.nodes.iter().filter(|n| n.kind == base_case::EventKind::Corner).count();
            if corners != convex {
                println!("leaf {i} ({} pieces): {corners} corner nodes for {convex} convex vertices", s.pieces.len());
                for p in &s.pieces {
                    println!("   {p:?}");
                }
            }
        }
        if let (Err(_), true) = (&solved, std::env::var("MEDAX_REFINE").is_ok()) {
            // Divide the failed leaf again as `solve_leaves` does and check
            // the corners of the new leaves.
            let mut more = medax::plane::internals::Decomposition { cuts: d.cuts.clone(), ..Default::default() };
            let size = medax::plane::internals::leaf_size(&shape, s);
            medax::plane::internals::divide_into(
                &finder,
                &mut more,
                vec![s.clone()],
                seed ^ 1,
                (size / 2).max(3).min(size.saturating_sub(1)),
            );
            for (k, t) in more.leaves.iter().chain(more.stuck.iter()).enumerate() {
                let convex = convex_inside(&shape, t);
                match base_case::solve(&shape, t, &more.cuts, shape.tolerance(), &finder) {
                    Ok(local) => {
                        let corners = local.nodes.iter().filter(|n| n.kind == base_case::EventKind::Corner).count();
                        if corners != convex {
                            println!("  refined {k}: {corners} corners for {convex} convex: {:?}", t.pieces);
                        }
                    }
                    Err(e) => println!("  refined {k}: {e:?}"),
                }
            }
        }
        if let Err(e) = solved {
            println!("leaf {i} ({} pieces): {e:?}", s.pieces.len());
            if let Ok(dir) = std::env::var("MEDAX_DUMP") {
                let text = medax::plane::internals::write_leaf(s, &d.cuts);
                std::fs::write(format!("{dir}/leaf_{i}.txt"), text).expect("writable dump directory");
            }
            if let (true, Some(Piece::Chain { from, to }), Some(Piece::Aux { disk })) =
                (s.pieces.len() == 2, s.pieces.first(), s.pieces.get(1))
            {
                dump_chain(&shape, from.element, to.element, d.cuts[*disk].center, d.cuts[*disk].radius);
            }
            for p in &s.pieces {
                match p {
                    Piece::Aux { disk } => println!("   aux {:?}", d.cuts[*disk]),
                    Piece::Chain { from, to } => {
                        println!("   chain {:?} {:?} -> {:?} {:?}", from, from.point(&shape), to, to.point(&shape))
                    }
                }
            }
        }
    }
}

/// Prints the elements of a chain with their circles, against a disk.
/// Convex vertices strictly inside the chains of a subshape.
fn convex_inside(shape: &Shape2d, s: &medax::plane::Subshape) -> usize {
    let mut convex = 0;
    for (from, to) in s.chains() {
        let parts: Vec<_> = medax::plane::internals::ChainParts::new(shape, from, to).iter().collect();
        convex += parts
            .windows(2)
            .filter(|w| shape.joint(from.loop_index, w[1].0) == medax::shape::JointKind::Convex)
            .count();
    }
    convex
}

/// Solves and glues like `medial_axis` (one decomposition) and prints the
/// convex vertices that got no corner node, with the nodes near them.
fn glued_corners(shape: &Shape2d, finder: &DiskFinder, seed: u64) {
    let aug = augment(finder).expect("augmenting disks");
    let mut d = decompose_in(finder, &aug, seed, AxisOptions::default().leaf_parts);
    let subshapes: Vec<_> = d.leaves.iter().chain(d.stuck.iter()).cloned().collect();
    let locals = match medax::plane::internals::solve_leaves(finder, &mut d, seed) {
        Ok(l) => l,
        Err(e) => return println!("solve_leaves: {e}"),
    };
    for (k, local) in locals.iter().enumerate() {
        for (n, kind) in local.nodes.iter().zip(local.events) {
            if n.radius <= shape.tolerance() && *kind != base_case::EventKind::Corner {
                println!("local {k}: tiny non-corner node {n:?}");
            }
        }
    }
    let axis = match medax::plane::internals::glue(finder, &d.cuts, locals.clone()) {
        Ok(a) => a,
        Err(e) => return println!("glue: {e}"),
    };
    if std::env::var("MEDAX_CHECK").is_ok() {
        // The final check of `medial_axis` on edge disks, with the leaves
        // that made each failing edge (dumped with MEDAX_DUMP).
        let slack = 64.0 * shape.tolerance();
        let mut shown = 0;
        for (ei, e) in axis.edges.iter().enumerate() {
            for s in [1.0 / 64.0, 0.5, 63.0 / 64.0] {
                let Some(Disk { center: c, radius: r }) = e.eval(shape, &axis.nodes, s) else {
                    shown += 1;
                    let (a, b) = (&axis.nodes[e.from], &axis.nodes[e.to]);
                    println!("edge {ei} at {s}: no disk; {a:?} -> {b:?}, kind {:?}, sites {:?}", e.kind, e.sites);
                    for (k, local) in locals.iter().enumerate() {
                        if local.nodes.iter().any(|n| n.point.dist(a.point) < 1e-9 || n.point.dist(b.point) < 1e-9) {
                            println!("   from leaf {k} ({} nodes)", local.nodes.len());
                        }
                    }
                    continue;
                };
                let intruder = finder.intruder(c, r, slack);
                let apart: Vec<f64> = e.sites.iter().map(|p| p.distance(shape, c) - r).collect();
                if intruder.is_none() && apart.iter().all(|d| d.abs() <= slack) {
                    continue;
                }
                shown += 1;
                if shown > 6 {
                    break;
                }
                let (a, b) = (&axis.nodes[e.from], &axis.nodes[e.to]);
                println!("edge {ei} at {s}: disk {c:?} r {r}, intruder {intruder:?}, primitive defects {apart:?}");
                println!("   {:?} -> {:?}, sites {:?}", a, b, e.sites);
                for (k, local) in locals.iter().enumerate() {
                    if local.nodes.iter().any(|n| n.point.dist(a.point) < 1e-9 || n.point.dist(b.point) < 1e-9) {
                        println!("   from leaf {k} ({} nodes)", local.nodes.len());
                        if let Ok(dir) = std::env::var("MEDAX_DUMP") {
                            if let Some(sub) = subshapes.get(k) {
                                let text = medax::plane::internals::write_leaf(sub, &d.cuts);
                                std::fs::write(format!("{dir}/glued_{k}.txt"), text).expect("writable dump directory");
                            }
                        }
                    }
                }
            }
        }
        println!("{shown} failing edge checks");
    }
    if std::env::var("MEDAX_CORNERS").is_err() {
        return;
    }
    let lp = &shape.loops()[0];
    for v in 0..lp.len() {
        let p = lp.vertices()[v].p;
        if shape.joint(0, v) != medax::shape::JointKind::Convex {
            continue;
        }
        let near: Vec<_> = axis.nodes.iter().filter(|n| n.point.dist(p) < 1e-6).collect();
        if !near.iter().any(|n| n.kind == medax::plane::NodeKind::Corner) {
            println!("vertex {v} at {p:?}: nodes near {near:?}");
            for (k, sub) in d.leaves.iter().chain(d.stuck.iter()).enumerate() {
                let touches = sub.chains().any(|(a, b)| [a, b].iter().any(|q| q.point(shape).dist(p) < 1e-6));
                if touches {
                    println!("   leaf {k}: {:?}", sub.pieces);
                    println!("      nodes {:?}", locals.get(k).nodes);
                }
            }
            for (k, local) in locals.iter().enumerate() {
                for n in local.nodes.iter().filter(|n| n.point.dist(p) < 1e-6) {
                    println!("   local {k}: {n:?}");
                }
            }
        }
    }
}

fn dump_chain(shape: &Shape2d, from: usize, to: usize, c: medax::kernel::Point, r: f64) {
    let lp = &shape.loops()[0];
    for i in from..=to {
        let e = lp.element(i);
        match e {
            medax::shape::Element::Arc(a) => println!(
                "   {i}: arc r {:.9} centre dist from disk centre {:.3e}, start dist-to-circle {:.3e}, ccw {}",
                a.radius,
                a.center.dist(c),
                e.start().dist(c) - r,
                a.is_ccw()
            ),
            _ => println!("   {i}: segment start dist-to-circle {:.3e}", e.start().dist(c) - r),
        }
    }
}
