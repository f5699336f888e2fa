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
    match base_case::solve(&shape, &s, &cuts, shape.tolerance(), &finder) {
        Ok(local) => println!("solved: {} nodes, {} edges", local.nodes.len(), local.edges.len()),
        Err(e) => println!("failed: {e:?}"),
    }
}
