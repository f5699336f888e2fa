//! Any text through `Ball2::parse`, and any polygon as a unit ball: a ball or a typed error naming a vertex in
//! range, never a panic. A ball accepted holds its invariants: every vertex
//! at gauge 1, the gauge non-negative and below 1 strictly inside, the
//! features found in range.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::kernel::Point;
use medax::shape::{Ball2, Feature};

fuzz_target!(|input: (Vec<(f64, f64)>, (f64, f64), (f64, f64), String)| {
    let (xy, (px, py), (qx, qy), text) = input;
    // Names and ball JSON: a ball or an error, never a panic.
    let _ = Ball2::parse(&text);
    let vertices: Vec<Point> = xy.iter().map(|&(x, y)| Point::new(x, y)).collect();
    let ball = match Ball2::new(&vertices) {
        Ok(b) => b,
        Err(e) => {
            let vertex = e.vertex().unwrap_or(0);
            assert!(vertex < vertices.len().max(1));
            return;
        }
    };
    let n = ball.len();
    for v in ball.vertices() {
        assert!((ball.gauge(*v) - 1.0).abs() < 1e-3, "{v:?}: {}", ball.gauge(*v));
    }
    let (p, q) = (Point::new(px, py), Point::new(qx, qy));
    if p.x.is_finite() && p.y.is_finite() && q.x.is_finite() && q.y.is_finite() {
        assert!(ball.distance(p, q) >= 0.0 || ball.distance(p, q).is_nan());
        let in_range = |f: Feature| match f {
            Feature::Vertex(i) | Feature::Edge(i) => i < n,
        };
        if p != Point::new(0.0, 0.0) {
            assert!(in_range(ball.support(p)));
        }
        if p != q {
            assert!(in_range(ball.towards(p, q)));
            assert!(in_range(ball.touching_edge(p, q)));
        }
    }
});
