//! Design-study probe: a jittered grid of point sites (and optionally
//! segment sites) in a square; decomposition counts and axis time.
use medax::kernel::Point;
use medax::plane::internals::augment;
use medax::plane::internals::decompose_in;
use medax::plane::{medial_axis, AxisOptions, DiskFinder};
use medax::shape::{Shape2d, ShapeOptions, Vertex};

fn main() {
    let cells: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(20);
    let segs = std::env::args().nth(2).is_some_and(|a| a == "segments");
    let sq = vec![(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
        .into_iter()
        .map(|(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 })
        .collect();
    let mut x = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let side = 10.0 / cells as f64;
    let (mut pts, mut curves) = (Vec::new(), Vec::new());
    for i in 0..cells {
        for j in 0..cells {
            let jitter = std::env::var("JITTER").ok().and_then(|j| j.parse::<f64>().ok()).unwrap_or(0.8);
            let mut p = || {
                Point::new(
                    (i as f64 + 0.5 + jitter * (rnd() - 0.5)) * side,
                    (j as f64 + 0.5 + jitter * (rnd() - 0.5)) * side,
                )
            };
            if segs {
                let (a, b) = (p(), p());
                curves.push(vec![Vertex { p: a, bulge: 0.0 }, Vertex { p: b, bulge: 0.0 }]);
            } else {
                pts.push(p());
            }
        }
    }
    let s = Shape2d::from_sites(vec![sq], curves, pts, &ShapeOptions::default()).unwrap();
    let f = DiskFinder::new(&s);
    let aug = augment(&f).unwrap();
    let d = decompose_in(&f, &aug, 0x006d_6564_6178, 32);
    println!("sites {} cuts {} leaves {} stuck {}", cells * cells, d.cuts.len(), d.leaves.len(), d.stuck.len());
    let t = std::time::Instant::now();
    let axis = medial_axis(&s, &AxisOptions::default()).unwrap();
    println!("axis: {} nodes {} edges in {:.3} s", axis.nodes.len(), axis.edges.len(), t.elapsed().as_secs_f64());
}
