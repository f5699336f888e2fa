use medax::kernel::Point;
use medax::plane::augment::augment;
use medax::plane::conquer::{glue, solve_leaves};
use medax::plane::divide::decompose_in;
use medax::plane::{DiskFinder, Primitive};
use medax::shape::{Shape2d, ShapeOptions, Vertex};

fn main() {
    let sq = vec![(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
        .into_iter()
        .map(|(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 })
        .collect();
    let s = Shape2d::from_sites(vec![sq], vec![], vec![Point::new(4.0, 5.5)], &ShapeOptions::default()).unwrap();
    let f = DiskFinder::new(&s);
    let aug = augment(&f).unwrap();
    println!("cuts {:?}\nboundary {:?}", aug.cuts, aug.boundary);
    let mut d = decompose_in(&f, &aug, 0x006d_6564_6178, 32);
    println!("leaves {} stuck {}", d.leaves.len(), d.stuck.len());
    for l in &d.leaves { println!("leaf {:?}", l.pieces); }
    let locals = solve_leaves(&f, &mut d, 0x006d_6564_6178).unwrap();
    for l in &locals {
        for n in &l.nodes { println!("  node {:?}", n); }
        for e in &l.edges { println!("  edge {:?}", e); }
    }
    let axis = glue(&f, &d.cuts, &locals).unwrap();
    for e in &axis.edges {
        let bad = [1.0 / 64.0, 0.5, 63.0 / 64.0].iter().any(|&t| match e.eval(&s, &axis.nodes, t) {
            Some((c, r)) => e.sites.iter().any(|p| (p.distance(&s, c) - r).abs() > 1e-6) || f.nearest(c).map_or(true, |(_, d)| d < r - 1e-6),
            None => true,
        });
        if bad || e.sites.iter().any(|p| matches!(p, Primitive::Vertex { .. })) {
            println!("{} edge {:?} from {:?} to {:?}", if bad { "BAD" } else { "ok " }, e, axis.nodes[e.from], axis.nodes[e.to]);
        }
    }
}
