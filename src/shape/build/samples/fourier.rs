//! Smooth random closed curves: radial Fourier series interpolated by
//! biarcs, alone or with holes of the same kind.

use super::biarc_loop;
use crate::kernel::Point;
use crate::shape::model::bulge_loop::Vertex;
use crate::util::mix::Mix;
use std::f64::consts::TAU;

/// r(θ) = 1 + scale·Σ_{k=1..7} a_k cos(kθ + φ_k), scaled so that r ≥ 0.2
/// (star-shaped about the origin, hence simple) and r ≤ 1.8.
struct Series {
    terms: Vec<(f64, f64, f64)>,
    scale: f64,
}

impl Series {
    fn random(rng: &mut Mix, spread: f64) -> Series {
        let mut gauss = || {
            // Box–Muller; 1 − u keeps the logarithm finite.
            let (u, v) = (1.0 - rng.next(), rng.next());
            (-2.0 * u.ln()).sqrt() * (TAU * v).cos()
        };
        let mut terms: Vec<(f64, f64, f64)> = (1..=7).map(|k| (k as f64, gauss() * spread / k as f64, 0.0)).collect();
        for t in terms.iter_mut() {
            t.2 = TAU * rng.next();
        }
        // The lowest radius bounds how far the series may reach below 1.
        let reach: f64 = terms.iter().map(|t| t.1.abs()).sum();
        let scale = if reach > 0.8 { 0.8 / reach } else { 1.0 };
        Series { terms, scale }
    }

    fn radius(&self, t: f64) -> f64 {
        1.0 + self.scale * self.terms.iter().map(|&(k, a, phi)| a * (k * t + phi).cos()).sum::<f64>()
    }

    fn slope(&self, t: f64) -> f64 {
        -self.scale * self.terms.iter().map(|&(k, a, phi)| a * k * (k * t + phi).sin()).sum::<f64>()
    }

    /// The biarc loop through `m` uniform angles, scaled by `size` about
    /// `centre`; counter-clockwise (`ccw`) or clockwise.
    fn loop_of(&self, m: usize, centre: Point, size: f64, ccw: bool) -> Vec<Vertex> {
        let mut samples: Vec<(Point, Point)> = (0..m)
            .map(|i| TAU * i as f64 / m as f64)
            .map(|t| {
                let (r, dr) = (self.radius(t), self.slope(t));
                let (s, c) = t.sin_cos();
                let tangent = Point::new(dr * c - r * s, dr * s + r * c).unit();
                (centre + Point::new(r * c, r * s) * size, tangent)
            })
            .collect();
        if !ccw {
            samples.reverse();
            for s in samples.iter_mut() {
                s.1 = s.1 * -1.0;
            }
        }
        biarc_loop(&samples)
    }
}

/// A smooth random closed curve of `n` arcs (n rounded up to even): the
/// radial Fourier series r(θ) = 1 + Σ_{k=1..7} a_k cos(kθ + φ_k) with a_k
/// normal of deviation 0.35/k and φ_k uniform (scaled down, if need be, so
/// that r ≥ 0.2: star-shaped about the origin, hence simple), sampled at
/// `n/2` uniform angles and interpolated by biarcs with the curve's exact
/// tangents. Every joint is tangent-continuous up to rounding. The family
/// issue 17 found breaking down at 10^5 arcs.
pub fn fourier_biarcs(n: usize, seed: u64) -> Vec<Vec<Vertex>> {
    fourier_curve(n, seed, 0.35)
}

/// [`fourier_biarcs`] with coefficients of deviation `spread / k`: 0.35
/// gives lobes, 10^-3 a nearly circular curve whose medial axis is a small
/// tree near the centre, reached by disks that all but osculate long
/// stretches of the boundary.
pub fn fourier_curve(n: usize, seed: u64, spread: f64) -> Vec<Vec<Vertex>> {
    let series = Series::random(&mut Mix(seed), spread);
    vec![series.loop_of(n.max(8).div_ceil(2), Point::new(0.0, 0.0), 1.0, true)]
}

/// A [`fourier_biarcs`] curve with `holes` holes of the same kind (each its
/// own random series, shrunk and placed at random where it keeps a gap of
/// at least a third of its size to the outer curve and to every other
/// hole): about `n` arcs in all, half on the outer curve and half shared
/// among the holes (at least 8 each, so a request of many holes and few
/// arcs gives more than `n`). Holes that find no room after many
/// tries are left out, so a crowded request gives fewer. The second family
/// issue 17 found breaking down (40 holes, 5·10^5 arcs).
pub fn fourier_with_holes(n: usize, holes: usize, seed: u64) -> Vec<Vec<Vertex>> {
    let mut rng = Mix(seed ^ 0x686f_6c65_7321);
    let outer = Series::random(&mut rng, 0.35);
    // A polygon fine enough to place holes against: the series has no
    // frequency above 7, so 4096 chords stay within 10^-4 of the curve.
    const PROBE: usize = 4096;
    let rim: Vec<Point> = (0..PROBE)
        .map(|i| TAU * i as f64 / PROBE as f64)
        .map(|t| Point::new(t.cos(), t.sin()) * outer.radius(t))
        .collect();
    let inside = |c: Point, reach: f64| {
        let t = c.y.atan2(c.x);
        c.norm() < outer.radius(t) && rim.iter().all(|q| (*q - c).norm() > reach)
    };
    // Hole sizes follow the room the curve offers: r ≥ 0.2 everywhere.
    let size = 0.5 / (holes.max(1) as f64).sqrt();
    let mut placed: Vec<(Point, f64)> = Vec::new();
    let mut tries = 0;
    while placed.len() < holes && tries < 1000 * holes.max(1) {
        tries += 1;
        let s = size * (0.5 + 0.5 * rng.next());
        // Each hole's series reaches at most 1.8 s from its centre.
        let reach = 1.8 * s;
        let c = Point::new(2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0) * 1.8;
        if inside(c, reach + s / 3.0) && placed.iter().all(|&(q, rq)| (q - c).norm() > reach + rq + s / 3.0) {
            placed.push((c, reach));
        }
    }
    let per_hole = if placed.is_empty() { 0 } else { (n / 2 / placed.len()).max(8) };
    // Many holes of at least 8 arcs each may take more than `n`: the outer
    // curve keeps at least half (fewer arcs would stray from the series
    // the holes were placed against).
    let outer_arcs = n.saturating_sub(per_hole * placed.len()).max(n / 2).max(8);
    let mut loops = vec![outer.loop_of(outer_arcs.div_ceil(2), Point::new(0.0, 0.0), 1.0, true)];
    for &(c, reach) in &placed {
        let series = Series::random(&mut rng, 0.35);
        loops.push(series.loop_of(per_hole.div_ceil(2), c, reach / 1.8, false));
    }
    loops
}
