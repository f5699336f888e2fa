//! Welding: vertices at the same place become one. STL stores every facet's
//! corners on their own, and OBJ groups repeat their vertices, so a solid's
//! topology (which faces share an edge) exists only after equal positions
//! are merged. With a tolerance, vertices closer than it merge too
//! (transitively: a chain of close vertices becomes one), which closes the
//! cracks of files written with rounded coordinates; the count is reported.

use crate::kernel::Point3;
use crate::util::fast_hash::FastMap;

/// The welded vertices and how the input maps onto them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Welded {
    /// The distinct positions (the first input vertex of each group).
    pub positions: Vec<Point3>,
    /// Input vertex → welded vertex.
    pub map: Vec<u32>,
    /// Welded vertex → the first input vertex it stands for.
    pub first_input: Vec<u32>,
    /// Input vertices merged into an earlier one.
    pub merged: usize,
}

/// Bit patterns of a position with −0 read as +0, so that equal
/// coordinates hash equally.
fn key(p: Point3) -> [u64; 3] {
    p.to_array().map(|c| (c + 0.0).to_bits())
}

/// Merges vertices at equal positions, and with `tolerance > 0` those
/// closer than it (Euclidean). Positions are finite.
pub(crate) fn weld(input: &[Point3], tolerance: f64) -> Welded {
    let mut parent: Vec<u32> = (0..input.len() as u32).collect();
    // Below the coordinates' resolution only equal points are that close;
    // above the extent everything merges anyway. Either way the grid would
    // put everything in a few cells and compare all pairs.
    let extent = crate::kernel::BBox3::of(input.iter().copied());
    let scale = extent.min.to_array().iter().chain(&extent.max.to_array()).fold(0.0f64, |m, v| m.max(v.abs()));
    let tolerance = if tolerance > 0.0 { tolerance.min(extent.diagonal() * 2.0) } else { 0.0 };
    if tolerance > scale * f64::EPSILON * 4.0 && tolerance.is_finite() {
        close_pairs(input, tolerance, &mut parent);
    } else {
        let mut seen: FastMap<[u64; 3], u32> = FastMap::default();
        seen.reserve(input.len());
        for (i, &p) in input.iter().enumerate() {
            let first = *seen.entry(key(p)).or_insert(i as u32);
            parent[i] = first;
        }
    }
    let mut map = vec![0u32; input.len()];
    let mut positions = Vec::new();
    let mut first_input = Vec::new();
    let mut id_of_root: FastMap<u32, u32> = FastMap::default();
    for (i, slot) in map.iter_mut().enumerate() {
        let r = find(&mut parent, i as u32);
        *slot = *id_of_root.entry(r).or_insert_with(|| {
            positions.push(input[r as usize]);
            first_input.push(r);
            (positions.len() - 1) as u32
        });
    }
    let merged = input.len() - positions.len();
    Welded { positions, map, first_input, merged }
}

fn find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let up = parent[parent[i as usize] as usize];
        parent[i as usize] = up;
        i = up;
    }
    i
}

/// Unions every pair closer than `tolerance`, found in a grid of cells of
/// that size (a pair lies in the same or a neighbouring cell). The root of
/// a group is its smallest input index, so the kept position is the
/// first one the file gave.
fn close_pairs(input: &[Point3], tolerance: f64, parent: &mut [u32]) {
    let cell = |p: Point3| p.to_array().map(|c| (c / tolerance).floor() as i64);
    let mut grid: FastMap<[i64; 3], Vec<u32>> = FastMap::default();
    for (i, &p) in input.iter().enumerate() {
        grid.entry(cell(p)).or_default().push(i as u32);
    }
    let t2 = tolerance * tolerance;
    for (i, &p) in input.iter().enumerate() {
        let c = cell(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(others) = grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) else { continue };
                    for &j in others {
                        if (j as usize) < i && (input[j as usize] - p).norm2() <= t2 {
                            let (a, b) = (find(parent, i as u32), find(parent, j));
                            let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                            parent[hi as usize] = lo;
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    #[test]
    fn equal_positions_merge_and_the_first_is_kept() {
        let w = weld(&[p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(-0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)], 0.0);
        assert_eq!(w.positions.len(), 2);
        assert_eq!(w.map, [0, 1, 0, 1]);
        assert_eq!(w.first_input, [0, 1]);
        assert_eq!(w.merged, 2);
    }

    #[test]
    fn a_tolerance_merges_close_chains() {
        let input = [p(0.0, 0.0, 0.0), p(0.9e-3, 0.0, 0.0), p(1.8e-3, 0.0, 0.0), p(5.0, 0.0, 0.0)];
        let w = weld(&input, 1e-3);
        assert_eq!(w.map, [0, 0, 0, 1]);
        assert_eq!(w.positions[0], input[0]);
        assert_eq!(weld(&input, 0.0).merged, 0);
    }
}
