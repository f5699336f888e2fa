//! Dense text-like outlines: a plate whose holes are letters drawn with a
//! round pen (the outlines an engraving font gives), packed in rows.

use crate::kernel::Point;
use crate::shape::model::bulge_loop::Vertex;
use crate::util::mix::Mix;

/// Steps per half turn when a letter's bowl is drawn as a polyline: fine
/// enough that its stroke outline has many short elements, coarse enough
/// that each step is longer than the pen's inner miter needs.
const BOWL_STEPS: usize = 12;

fn arc(c: (f64, f64), r: f64, from_deg: f64, to_deg: f64) -> Vec<(f64, f64)> {
    let steps = ((to_deg - from_deg).abs() / 180.0 * BOWL_STEPS as f64).ceil() as usize;
    (0..=steps)
        .map(|i| (from_deg + (to_deg - from_deg) * i as f64 / steps as f64).to_radians())
        .map(|a| (c.0 + r * a.cos(), c.1 + r * a.sin()))
        .collect()
}

fn join(parts: &[Vec<(f64, f64)>]) -> Vec<(f64, f64)> {
    parts.concat()
}

/// The pen paths of the letters, one path each (a hole is one loop), in a
/// cell of 0.7 × 1.1.
fn letters() -> Vec<Vec<(f64, f64)>> {
    vec![
        vec![(0.1, 1.1), (0.1, 0.1), (0.6, 0.1)],
        vec![(0.05, 1.1), (0.35, 0.1), (0.65, 1.1)],
        vec![(0.1, 0.1), (0.1, 1.1), (0.6, 0.1), (0.6, 1.1)],
        vec![(0.1, 1.1), (0.6, 1.1), (0.1, 0.1), (0.6, 0.1)],
        vec![(0.05, 0.1), (0.05, 1.1), (0.35, 0.5), (0.65, 1.1), (0.65, 0.1)],
        vec![(0.0, 1.1), (0.17, 0.1), (0.35, 0.8), (0.53, 0.1), (0.7, 1.1)],
        vec![(0.05, 1.1), (0.65, 1.1), (0.25, 0.1)],
        arc((0.4, 0.6), 0.45, 50.0, 310.0),
        join(&[vec![(0.1, 1.1)], arc((0.35, 0.4), 0.25, 180.0, 360.0), vec![(0.6, 1.1)]]),
        join(&[arc((0.35, 0.84), 0.23, 20.0, 270.0), arc((0.35, 0.38), 0.23, 90.0, -160.0)[1..].to_vec()]),
        join(&[vec![(0.5, 1.1)], arc((0.3, 0.35), 0.2, 0.0, -180.0)]),
        join(&[arc((0.35, 0.8), 0.25, 160.0, -30.0), vec![(0.08, 0.1), (0.62, 0.1)]]),
        join(&[arc((0.4, 0.6), 0.45, 40.0, 320.0), vec![(0.745, 0.55), (0.5, 0.55)]]),
    ]
}

/// One side of a round-pen stroke of half-width `w` along `path`, walked
/// forward on the left, then the round cap at the end: miter points where
/// the side is inside a turn, round joins where it is outside. Walking
/// this side, then the side of the reversed path, goes clockwise.
fn side(path: &[Point], w: f64) -> Vec<Vertex> {
    let left = |d: Point| Point::new(-d.y, d.x);
    let dirs: Vec<Point> = path.windows(2).map(|s| (s[1] - s[0]).unit()).collect();
    let mut out = vec![Vertex { p: path[0] + left(dirs[0]) * w, bulge: 0.0 }];
    for i in 1..path.len() - 1 {
        let (a, b) = (dirs[i - 1], dirs[i]);
        let turn = a.cross(b).atan2(a.dot(b));
        if turn < -1e-9 {
            out.push(Vertex { p: path[i] + left(a) * w, bulge: (turn / 4.0).tan() });
            out.push(Vertex { p: path[i] + left(b) * w, bulge: 0.0 });
        } else if turn > 1e-9 {
            let (na, nb) = (left(a), left(b));
            out.push(Vertex { p: path[i] + (na + nb) * (w / (1.0 + na.dot(nb))), bulge: 0.0 });
        }
    }
    let last = *dirs.last().expect("a path has a segment");
    out.push(Vertex { p: *path.last().expect("a path has points") + left(last) * w, bulge: -1.0 });
    out
}

/// A plate of about `n` elements: rows of letters (13 shapes drawn with a
/// round pen: straight strokes with sharp turns, bowls drawn as polylines
/// of short steps, round caps), each jittered in size, slant, rotation and
/// pen width, with gaps between neighbours of 0.06–0.2 letter heights.
/// Every letter is a hole of the plate; the outer loop is a rectangle.
pub fn text_plate(n: usize, seed: u64) -> Vec<Vec<Vertex>> {
    let shapes = letters();
    // About 32 elements per letter on average.
    let count = (n / 32).max(1);
    let cols = (count as f64).sqrt().ceil() as usize;
    let rows = count.div_ceil(cols);
    let (cell_w, cell_h) = (1.08, 1.35);
    let mut rng = Mix(seed ^ 0x7465_7874);
    let (width, height) = (cols as f64 * cell_w + 0.4, rows as f64 * cell_h + 0.4);
    let corner = |x: f64, y: f64| Vertex { p: Point::new(x, y), bulge: 0.0 };
    let mut loops = vec![vec![corner(0.0, 0.0), corner(width, 0.0), corner(width, height), corner(0.0, height)]];
    for k in 0..count {
        let (i, j) = (k % cols, k / cols);
        let shape = &shapes[rng.below(shapes.len())];
        let scale = 0.9 + 0.1 * rng.next();
        let slant = 0.1 * rng.next();
        let (s, c) = (0.04 * (rng.next() - 0.5)).sin_cos();
        let w = 0.055 + 0.02 * rng.next();
        let origin =
            Point::new(0.3 + i as f64 * cell_w + 0.02 * rng.next(), 0.25 + j as f64 * cell_h + 0.02 * rng.next());
        let path: Vec<Point> = shape
            .iter()
            .map(|&(x, y)| {
                let (x, y) = (scale * (x + slant * (y - 0.55)), scale * y);
                origin + Point::new(c * x - s * y, s * x + c * y)
            })
            .collect();
        let rev: Vec<Point> = path.iter().rev().copied().collect();
        let mut hole = side(&path, w);
        hole.extend(side(&rev, w));
        loops.push(hole);
    }
    loops
}
