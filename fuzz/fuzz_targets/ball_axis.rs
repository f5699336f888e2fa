//! Random polygons on a small integer grid (collinear edges, reflex
//! vertices in line, edges parallel to ball edges: far from general
//! position) under random polygon balls: the axis under the ball or a
//! typed error, never a panic; an axis returned is sound (every node's
//! radius is the brute-force gauge distance to the boundary); its offsets
//! at two distances exist and lie at their distance, and its JSON and SVG
//! are written.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::kernel::Point;
use medax::polymetric::medial_axis_with_ball;
use medax::shape::{Ball2, Shape2d, ShapeOptions, Vertex};

fuzz_target!(|input: (Vec<(i8, i8)>, Vec<(i8, i8)>)| {
    let (poly, ball) = input;
    if poly.len() < 3 || poly.len() > 40 || ball.len() > 12 {
        return;
    }
    let grid = |(x, y): (i8, i8)| Point::new(f64::from(x) / 4.0, f64::from(y) / 4.0);
    let Ok(ball) = Ball2::new(&ball.iter().map(|&v| grid(v)).collect::<Vec<_>>()) else { return };
    let loop_: Vec<Vertex> = poly.iter().map(|&v| Vertex { p: grid(v), bulge: 0.0 }).collect();
    let Ok(shape) = Shape2d::from_bulge_loops(vec![loop_], &ShapeOptions::default()) else { return };
    let Ok(axis) = medial_axis_with_ball(&shape, &ball) else { return };
    let mut edges = Vec::new();
    for l in shape.loops() {
        let v = l.vertices();
        for i in 0..v.len() {
            edges.push((v[i].p, v[(i + 1) % v.len()].p));
        }
    }
    // The gauge is 1/inradius-Lipschitz: rounding the node's position by ε
    // changes its distance by up to ε/inradius.
    let inradius = ball.inradius();
    let tol = 1e-9 * shape.bbox().diagonal() / inradius.min(1.0);
    for n in &axis.nodes {
        let d = edges.iter().map(|&(a, b)| ball.distance_to_segment(n.at, a, b)).fold(f64::INFINITY, f64::min);
        assert!((d - n.r).abs() <= tol, "node {:?}: radius {} distance {d}", n.at, n.r);
    }
    let rmax = axis.nodes.iter().map(|n| n.r).fold(0.0, f64::max);
    for f in [0.3, 0.7] {
        let d = f * rmax;
        let layer = axis.offset(&shape, d).expect("offsets of an axis that was computed");
        for lp in &layer.loops {
            for &p in &lp.points {
                let got = edges.iter().map(|&(a, b)| ball.distance_to_segment(p, a, b)).fold(f64::INFINITY, f64::min);
                assert!((got - d).abs() <= 4.0 * tol, "offset at {d}: {p:?} at {got}");
            }
        }
    }
    let _ = (axis.to_json(&shape), axis.to_svg(&shape, 300.0));
});
