//! Turning loose elements into closed loops.
//!
//! Files such as DXF hold boundaries as unordered LINE and ARC entities whose
//! ends meet only up to the writer's rounding. Chaining links each element's
//! end to the nearest free end of another element within the chaining
//! tolerance (reversing that element when needed) and snaps the gap shut by
//! making the next element start exactly where the loop's vertex is.

use crate::kernel::Point;
use crate::shape::model::bulge_loop::{Loop, Vertex};
use crate::shape::model::error::{ElementRef, ShapeError};
use crate::shape::model::loose::LooseElement;
use std::collections::HashMap;

struct EndGrid {
    cell: f64,
    cells: HashMap<(i64, i64), Vec<(usize, bool)>>,
}

impl EndGrid {
    fn key(&self, p: Point) -> (i64, i64) {
        ((p.x / self.cell).floor() as i64, (p.y / self.cell).floor() as i64)
    }

    /// Nearest end of an unused element to `p`: (element, is_end, distance).
    /// Ends of used elements are dropped from the cells as they are met, and
    /// an exact match ends the search, so many ends at one point (a fan of
    /// triangles) cost amortised O(1) each instead of a rescan every time.
    fn nearest(&mut self, p: Point, elems: &[LooseElement], used: &[bool]) -> Option<(usize, bool, f64)> {
        let (kx, ky) = self.key(p);
        let mut best: Option<(usize, bool, f64)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                let Some(list) = self.cells.get_mut(&(kx.saturating_add(dx), ky.saturating_add(dy))) else {
                    continue;
                };
                let mut k = 0;
                while k < list.len() {
                    let (i, is_end) = list[k];
                    if used[i] {
                        list.swap_remove(k);
                        continue;
                    }
                    k += 1;
                    let q = if is_end { elems[i].b } else { elems[i].a };
                    let d = p.dist(q);
                    if best.is_none_or(|(_, _, bd)| d < bd) {
                        best = Some((i, is_end, d));
                        if d == 0.0 {
                            return best;
                        }
                    }
                }
            }
        }
        best
    }
}

/// Chains loose elements into closed loops; elements are used once each, in
/// whichever direction fits. Fails with [`ShapeError::NotClosed`] naming the
/// element (index in the partial loop, loop index = number of loops closed
/// before it) whose end finds no partner within `tol`.
pub fn chain_loops(elems: &[LooseElement], tol: f64) -> Result<Vec<Loop>, ShapeError> {
    // A cell of 2·tol keeps every partner within the 3×3 neighbourhood while
    // bounding how many unrelated ends share a cell.
    let cell = (2.0 * tol).max(f64::MIN_POSITIVE * 1e10);
    let mut grid = EndGrid { cell, cells: HashMap::with_capacity(2 * elems.len()) };
    for (i, e) in elems.iter().enumerate() {
        for (is_end, p) in [(false, e.a), (true, e.b)] {
            let k = grid.key(p);
            grid.cells.entry(k).or_default().push((i, is_end));
        }
    }
    let mut used = vec![false; elems.len()];
    let mut loops = Vec::new();
    for first in 0..elems.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let start = elems[first].a;
        let mut verts = vec![Vertex { p: start, bulge: elems[first].bulge }];
        let mut end = elems[first].b;
        loop {
            let next = grid.nearest(end, elems, &used);
            let closes = end.dist(start) <= tol;
            match next {
                Some((i, is_end, d)) if d <= tol && !(closes && d >= end.dist(start)) => {
                    used[i] = true;
                    let e = elems[i];
                    // Entering at its end means walking it backwards.
                    let (far, bulge) = if is_end { (e.a, -e.bulge) } else { (e.b, e.bulge) };
                    verts.push(Vertex { p: end, bulge });
                    end = far;
                }
                _ if closes => break,
                other => {
                    let gap = other.map_or(end.dist(start), |(_, _, d)| d.min(end.dist(start)));
                    return Err(ShapeError::NotClosed {
                        at: ElementRef { loop_index: loops.len(), element: verts.len() - 1 },
                        gap,
                        position: end,
                    });
                }
            }
        }
        loops.push(Loop::new(verts));
    }
    Ok(loops)
}

/// Puts the loop with the largest enclosed area first (the outer boundary),
/// keeping the others in their order: files do not say which loop is outer.
pub fn outer_first(mut loops: Vec<Loop>) -> Vec<Loop> {
    if let Some(imax) =
        (0..loops.len()).max_by(|&i, &j| loops[i].signed_area().abs().total_cmp(&loops[j].signed_area().abs()))
    {
        let outer = loops.remove(imax);
        loops.insert(0, outer);
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;

    fn le(ax: f64, ay: f64, bx: f64, by: f64, bulge: f64) -> LooseElement {
        LooseElement { a: Point::new(ax, ay), b: Point::new(bx, by), bulge }
    }

    #[test]
    fn chains_shuffled_and_reversed_elements_with_small_gaps() {
        let elems = [
            le(1.0, 0.0, 1.0, 1.0, 0.0),
            le(0.0, 1.0, 0.0, 0.0, 0.0),
            le(1.0, 1.0 + 1e-9, 0.0, 1.0, 0.5),
            le(1.0, 0.0, 0.0, 0.0, 0.0), // reversed
        ];
        let loops = chain_loops(&elems, 1e-6).unwrap();
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0].len(), 4);
        let total: f64 = loops[0].vertices.iter().map(|v| v.bulge.abs()).sum();
        assert_eq!(total, 0.5);
    }

    #[test]
    fn reports_the_dangling_end() {
        let elems = [le(0.0, 0.0, 1.0, 0.0, 0.0), le(1.0, 0.0, 1.0, 1.0, 0.0), le(1.0, 1.0, 0.0, 0.5, 0.0)];
        match chain_loops(&elems, 1e-6) {
            Err(ShapeError::NotClosed { at, position, gap }) => {
                assert_eq!(at, ElementRef { loop_index: 0, element: 2 });
                assert_eq!(position, Point::new(0.0, 0.5));
                assert!((gap - 0.5).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
    }
}
