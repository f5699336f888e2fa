//! Contact arrangements of VF classes (`medax::space::face_arrangement`):
//! the cells must cover the face, each cell's class must be the one the
//! exact maximal* ball finds at random points inside it, and its radius
//! function must give the radius of a brute-force oracle that shares
//! nothing with the library (`common::maximal_oracle`).

mod common;

use common::maximal_oracle::{accepted, balls, oracle_radius, planes, solids, vf_anchor};
use medax::space::face_arrangement;
use medax::space::Opposite;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn area(d: &[(f64, f64)]) -> f64 {
    (0..d.len()).map(|k| d[k].0 * d[(k + 1) % d.len()].1 - d[(k + 1) % d.len()].0 * d[k].1).sum::<f64>() / 2.0
}

/// How far inside convex polygon `d` (counter-clockwise) the point lies:
/// the least signed distance to its sides' lines.
fn depth(d: &[(f64, f64)], (a, b): (f64, f64)) -> f64 {
    (0..d.len())
        .map(|k| {
            let (p, q) = (d[k], d[(k + 1) % d.len()]);
            let (ex, ey) = (q.0 - p.0, q.1 - p.1);
            (ex * (b - p.1) - ey * (a - p.0)) / (ex * ex + ey * ey).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn cells_cover_the_face_and_hold_the_classes_and_radii_found_inside_them() {
    let mut rng = SmallRng::seed_from_u64(56);
    let (mut faces, mut cells, mut probes, mut refused, mut multi) = (0, 0, 0, 0, 0);
    for (solid, m) in solids() {
        let diag = m.bbox().diagonal();
        for (name, ball) in balls() {
            let reach = ball.reach();
            let pl = planes(&ball);
            for _ in 0..4 {
                let face = rng.gen_range(0..m.triangles().len());
                let corners = m.triangles()[face].map(|i| m.positions()[i as usize]);
                let anchor = vf_anchor(&m, &ball, face);
                let what = format!("{solid}, {name}, face {face}, vertex {anchor}");
                let Some(got) = accepted(face_arrangement(&m, &reach, face as u32, anchor), &what, &mut refused) else {
                    continue;
                };
                faces += 1;
                cells += got.cells.len();
                let classes: std::collections::BTreeSet<Opposite> = got.cells.iter().map(|c| c.opposite).collect();
                multi += usize::from(classes.len() > 1);
                let total: f64 = got.cells.iter().map(|c| area(&c.polygon)).sum();
                assert!((total - 0.5).abs() < 1e-5, "{what}: cells cover {total} of 0.5");
                let at =
                    |(a, b): (f64, f64)| corners[0] + (corners[1] - corners[0]) * a + (corners[2] - corners[0]) * b;
                for cell in &got.cells {
                    assert!(area(&cell.polygon) > 0.0, "{what}: a cell turns clockwise or is empty");
                    let n = cell.polygon.len() as f64;
                    let g = cell.polygon.iter().fold((0.0, 0.0), |s, &(a, b)| (s.0 + a / n, s.1 + b / n));
                    let want = oracle_radius(&m, &ball, &pl, face, anchor, at(g));
                    let r = cell.radius.at(at(g));
                    assert!(
                        (r - want).abs() <= 1e-9 * diag,
                        "{what}: cell {:?}: radius {r}, oracle {want}",
                        cell.opposite
                    );
                }
                // Random points: the class found there is the cell's.
                for _ in 0..24 {
                    let (u, w) = (rng.gen_range(0.0..1.0f64), rng.gen_range(0.0..1.0f64));
                    let q = if u + w <= 1.0 { (u, w) } else { (1.0 - u, 1.0 - w) };
                    let Some(cell) = got.cells.iter().find(|c| depth(&c.polygon, q) > 1e-7) else { continue };
                    let found = m.tree().maximal_ball_exact_on(corners, q, anchor, &reach).unwrap();
                    let [c] = found.opposite.as_slice() else { panic!("{what}: several contacts at {q:?}") };
                    assert_eq!((c.ball, c.surface), (cell.opposite.ball, cell.opposite.surface), "{what}: at {q:?}");
                    probes += 1;
                }
            }
        }
    }
    eprintln!("{faces} faces, {cells} cells, {multi} with several classes, {probes} probes, {refused} refused");
    assert!(faces >= 50 && refused * 10 <= faces, "{faces} faces, {refused} refused");
    assert!(multi >= 15 && probes >= 800, "{multi} faces with several classes, {probes} probes");
}
