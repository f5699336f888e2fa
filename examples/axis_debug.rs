//! Diagnoses a medial-axis breakdown: decomposes a sample shape as
//! `medial_axis` does and solves every leaf on its own, printing each
//! leaf that fails with its pieces and dividing disks (and, for a chain
//! cut off by one disk, how far each element strays from that disk).
//! `cargo run --release --example axis_debug -- star|flower N [SEED]`.
use medax::plane::base_case;
use medax::plane::divide::decompose_in;
use medax::plane::maxdisk::DiskFinder;
use medax::plane::subshape::Piece;
use medax::plane::AxisOptions;
use medax::shape::{samples, Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let loops = match args.get(1).map(String::as_str) {
        Some("flower") => samples::flower_arcs(n),
        _ => samples::star_polygon(n, 1),
    };
    let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid sample");
    let finder = DiskFinder::new(&shape);
    let opts = AxisOptions::default();
    let seed: u64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(opts.seed);
    let d = decompose_in(&finder, seed, opts.leaf_parts);
    println!("{} cuts, {} leaves, {} stuck", d.cuts.len(), d.leaves.len(), d.stuck.len());
    for (i, s) in d.leaves.iter().chain(d.stuck.iter()).enumerate() {
        if let Err(e) = base_case::solve(&shape, s, &d.cuts, shape.tolerance(), &finder) {
            println!("leaf {i} ({} pieces): {e:?}", s.pieces.len());
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
