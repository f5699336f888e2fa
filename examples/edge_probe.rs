//! Lists the edges of a glued axis that the final check would refuse,
//! with their length, kind and how far each checked disk strays:
//! `cargo run --release --features internals --example edge_probe -- SHAPE.json`.
use medax::kernel::tolerance::Tolerance;
use medax::plane::internals::{augment, decompose_in, final_check, glue, solve_leaves};
use medax::plane::{AxisOptions, DiskFinder};

fn main() {
    let path = std::env::args().nth(1).expect("a shape file");
    let text = std::fs::read_to_string(&path).expect("readable shape file");
    let shape = medax::plane::shape_or_sites(&text).expect("a valid shape file");
    let finder = DiskFinder::new(&shape);
    let aug = augment(&finder).expect("augmenting disks");
    let opts = AxisOptions::default();
    let mut d = decompose_in(&finder, &aug, opts.seed, opts.leaf_parts.max(3));
    let locals = solve_leaves(&finder, &mut d, opts.seed).expect("leaves solved");
    let axis = glue(&finder, &d.cuts, locals).expect("glued");
    let tau = shape.tolerance();
    let slack = Tolerance::new(tau).final_check();
    println!("tau {tau:e}, {} nodes, {} edges", axis.nodes.len(), axis.edges.len());
    println!("final check: {:?}", final_check(&finder, &axis));
    let deg = axis.degrees();
    for (i, e) in axis.edges.iter().enumerate() {
        let (a, b) = (&axis.nodes[e.from], &axis.nodes[e.to]);
        let mut bad = Vec::new();
        for s in [1.0 / 64.0, 0.5, 63.0 / 64.0] {
            let Some(dk) = e.eval(&shape, &axis.nodes, s) else {
                bad.push(format!("s={s}: no disk"));
                continue;
            };
            let miss: Vec<f64> = e.sites.iter().map(|p| (p.distance(&shape, dk.center) - dk.radius) / tau).collect();
            let intr = finder.intruder(dk.center, dk.radius, slack).map(|(_, depth)| depth / tau);
            if miss.iter().any(|m| m.abs() > 64.0) || (s == 0.5 && intr.is_some()) {
                let mid = (a.point + b.point) * 0.5;
                bad.push(format!(
                    "s={s}: miss {miss:.1?}τ intruder {intr:?} centre off chord-middle {:.1}τ radius {:.1}τ off mean",
                    dk.center.dist(mid) / tau,
                    (dk.radius - 0.5 * (a.radius + b.radius)) / tau
                ));
            }
        }
        if !bad.is_empty() {
            println!(
                "edge {i}: {}(deg {}, {:?}) -> {}(deg {}, {:?}) length {:.1}τ kind {:?} straight {} sites {:?} params {:?}",
                e.from, deg[e.from], a.kind, e.to, deg[e.to], b.kind, a.point.dist(b.point) / tau, e.kind, e.straight, e.sites, e.params
            );
            println!("    from {:?} r {:.12}, to {:?} r {:.12}", a.point, a.radius, b.point, b.radius);
            println!("    sites {:?} / {:?}", e.sites[0].site(&shape), e.sites[1].site(&shape));
            for l in bad {
                println!("    {l}");
            }
        }
    }
}
