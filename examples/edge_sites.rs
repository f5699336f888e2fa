//! How often an axis edge names an element its disks do not touch there:
//! for every edge side on an element, the footpoint at each end (from the
//! edge's parameters) against the element itself. Prints the count of
//! such sides and the worst distance, as a fraction of the diagonal.
//! `cargo run --release --example edge_sites -- SHAPE.json...`
use medax::kernel::bisector::footpoint;
use medax::plane::{medial_axis, AxisOptions, Primitive};

fn main() {
    for path in std::env::args().skip(1) {
        let text = std::fs::read_to_string(&path).expect("readable shape file");
        let shape = medax::plane::shape_or_sites(&text).expect("a valid shape file");
        let axis = medial_axis(&shape, &AxisOptions::default()).expect("axis");
        let diag = shape.bbox().diagonal();
        let (mut off, mut sides, mut worst, mut gap) = (0usize, 0usize, 0f64, 0f64);
        for e in &axis.edges {
            for k in 0..2 {
                let p = e.sites[k];
                let Primitive::Element { .. } = p else { continue };
                let el = shape.loops()[p.loop_index()].element(p.index());
                let site = p.site(&shape);
                sides += 1;
                let d = [e.params[k].0, e.params[k].1]
                    .iter()
                    .map(|&u| el.closest_point(footpoint(&site, u).0).0)
                    .fold(0.0, f64::max);
                if d > 1e-9 * diag {
                    off += 1;
                    if std::env::var_os("MEDAX_EDGE_DETAIL").is_some() {
                        let (a, b) = (&axis.nodes[e.from], &axis.nodes[e.to]);
                        println!(
                            "  {p:?} side {k}: {:.1e} off; straight {}, {:?}, nodes {:?} r {} / {:?} r {}, params {:?}",
                            d / diag,
                            e.straight,
                            e.kind,
                            a.kind,
                            a.radius,
                            b.kind,
                            b.radius,
                            e.params
                        );
                    }
                }
                worst = worst.max(d / diag);
                // How far the element itself is from touching the disks at
                // the edge's ends: zero when the name is honest.
                for n in [e.from, e.to] {
                    let node = &axis.nodes[n];
                    gap = gap.max((el.closest_point(node.point).0 - node.radius).abs() / diag);
                }
            }
        }
        println!("{path}: {off} of {sides} element sides leave their element, worst {worst:.1e} of the diagonal; the elements miss their end disks by at most {gap:.1e}");
    }
}
