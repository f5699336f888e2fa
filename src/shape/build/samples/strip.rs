//! A long, nearly straight band: the medial axis runs its whole length,
//! and every maximal disk touches two arcs of huge radius.

use super::biarc_loop;
use crate::kernel::Point;
use crate::shape::model::bulge_loop::Vertex;
use crate::util::mix::Mix;
use std::f64::consts::TAU;

/// A band of width about 1 and length `n / 20`, its two long sides
/// smooth random curves y = spread·f(x) and y = 1 + spread·g(x) (sums of
/// six sines of wavelengths 2–200 and normal amplitudes), each drawn by
/// biarcs through samples 0.2 apart (about `n / 2` arcs per side), the
/// ends closed by the half circles the biarcs make when they turn back.
/// With `spread` = 10^-3 the arcs have radii of 100 and more: nearly
/// straight.
pub fn nearly_straight_strip(n: usize, seed: u64, spread: f64) -> Vec<Vec<Vertex>> {
    let mut rng = Mix(seed ^ 0x0073_7472_6970);
    let mut wave = || {
        let mut terms = Vec::new();
        for _ in 0..6 {
            let (u, v) = (1.0 - rng.next(), rng.next());
            let amp = spread * (-2.0 * u.ln()).sqrt() * (TAU * v).cos();
            let freq = TAU / (2.0 * 100f64.powf(rng.next()));
            terms.push((amp, freq, TAU * rng.next()));
        }
        terms
    };
    let (low, high) = (wave(), wave());
    let eval = |terms: &[(f64, f64, f64)], x: f64| -> (f64, f64) {
        terms.iter().fold((0.0, 0.0), |(y, dy), &(a, f, p)| (y + a * (f * x + p).sin(), dy + a * f * (f * x + p).cos()))
    };
    let m = (n / 4).max(4);
    let step = 0.2;
    let mut samples = Vec::with_capacity(2 * m);
    for i in 0..m {
        let x = i as f64 * step;
        let (y, dy) = eval(&low, x);
        samples.push((Point::new(x, y), Point::new(1.0, dy).unit()));
    }
    for i in (0..m).rev() {
        let x = i as f64 * step;
        let (y, dy) = eval(&high, x);
        samples.push((Point::new(x, 1.0 + y), Point::new(-1.0, -dy).unit()));
    }
    vec![biarc_loop(&samples)]
}
