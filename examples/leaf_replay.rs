//! Solves one leaf written by `axis_debug` (`MEDAX_DUMP=DIR`) on its own:
//! `cargo run --release --example leaf_replay -- star|flower|holes|plate|SHAPE.json N SEED LEAF.txt`.
//! Rebuilds the sample shape (or the shape of a shape or Voronoi sites file), reads the leaf's pieces and dividing disks
//! (exact bits, `plane::leaf_text`) and prints the base case's result, so a
//! breakdown found in a large decomposition can be traced in seconds.
use medax::plane::internals::{base_case, leaf_text};
use medax::plane::DiskFinder;
use medax::shape::{samples, Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 5 {
        eprintln!("usage: leaf_replay star|flower|holes|plate|SHAPE.json N SEED LEAF.txt");
        std::process::exit(2);
    }
    let n: usize = args[2].parse().expect("element count");
    let seed: u64 = args[3].parse().expect("star seed");
    let shape = if args[1].ends_with(".json") {
        let text = std::fs::read_to_string(&args[1]).expect("readable shape file");
        medax::plane::shape_or_sites(&text).expect("a valid shape or sites file")
    } else {
        let loops = match args[1].as_str() {
            "flower" => samples::flower_arcs(n),
            "holes" => samples::random_holes(n, seed),
            "plate" => samples::perforated_plate(n),
            _ => samples::star_polygon(n, seed),
        };
        Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid sample")
    };
    let finder = DiskFinder::new(&shape);
    let text = std::fs::read_to_string(&args[4]).expect("readable leaf");
    let (s, cuts) = leaf_text::read_leaf(&shape, &text).unwrap_or_else(|e| panic!("{e}"));
    // How far each chain element strays from each dividing disk's circle,
    // and its own radius: a leaf whose chains all hug every disk within a
    // few tolerances is one where footpoint order is rounding.
    let disks: Vec<_> = s
        .pieces
        .iter()
        .filter_map(|p| match *p {
            medax::plane::Piece::Aux { disk } => Some(cuts[disk]),
            _ => None,
        })
        .collect();
    println!("tolerance {:e}", shape.tolerance());
    for (from, to) in s.chains() {
        let lp = &shape.loops()[from.loop_index];
        let n = lp.len();
        let mut e = from.element;
        loop {
            let (lo, hi) = (if e == from.element { from.t } else { 0.0 }, if e == to.element { to.t } else { 1.0 });
            let el = lp.element(e);
            let radius = match el {
                medax::shape::Element::Arc(a) => a.radius,
                medax::shape::Element::Segment(_) => f64::INFINITY,
            };
            let devs: Vec<String> =
                disks.iter().map(|c| format!("{:.2e}", el.circle_deviation(lo, hi, c.center, c.radius))).collect();
            println!("  element {e} [{lo:.3}, {hi:.3}] radius {radius:.6} deviation {}", devs.join(" "));
            if e == to.element {
                break;
            }
            e = (e + 1) % n;
        }
    }
    for c in &disks {
        println!("  disk {:?} {:.9}", c.center, c.radius);
    }
    match base_case::solve(&shape, &s, &cuts, shape.tolerance(), &finder) {
        Ok(local) => println!("solved: {} nodes, {} edges", local.nodes.len(), local.edges.len()),
        Err(e) => println!("failed: {e:?}"),
    }
}
