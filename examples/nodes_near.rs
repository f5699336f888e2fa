//! Prints the axis nodes near a point: `-- SHAPE.json X Y [RADIUS]`.
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("readable shape file");
    let shape = Shape2d::from_json_str(&text, &ShapeOptions::default()).expect("valid shape file");
    let p = Point::new(args[2].parse().expect("x"), args[3].parse().expect("y"));
    let within: f64 = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(0.05);
    let axis = medial_axis(&shape, &AxisOptions::default()).expect("axis");
    for (i, n) in axis.nodes.iter().enumerate().filter(|(_, n)| n.point.dist(p) < within) {
        println!("node {i}: {:?} r {} {:?}, {:e} away", n.point, n.radius, n.kind, n.point.dist(p));
        for e in axis.edges.iter().filter(|e| e.from == i || e.to == i) {
            let defects: Vec<f64> = e.sites.iter().map(|s| s.distance(&shape, n.point) - n.radius).collect();
            println!("   edge {} -> {} {:?} sites {:?} defects {defects:?}", e.from, e.to, e.kind, e.sites);
            if std::env::var("MEDAX_SITES").is_ok() {
                for s in &e.sites {
                    let (l, i) = (&shape.loops()[s.loop_index()], s.index());
                    match *s {
                        medax::plane::Primitive::Vertex { .. } => println!("      vertex {i}: {:?}", l.vertices()[i].p),
                        medax::plane::Primitive::Element { .. } => {
                            let el = l.element(i);
                            println!("      element {i}: {:?} -> {:?}", el.start(), el.end())
                        }
                    }
                }
            }
        }
    }
}
