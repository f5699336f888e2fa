//! What a space ball prepares once for least-gauge questions
//! (`reach3.rs`), kept in the ball itself so that a query about one point
//! does not pay for it again: data only (no use of the ball's type, so the
//! ball can hold it).

use std::sync::OnceLock;

/// Neighbour lists in one flat array: item `i`'s are
/// `items[start[i]..start[i + 1]]`.
#[derive(Debug, Clone)]
pub(super) struct Neighbours {
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Neighbours {
    /// From the pairs that are neighbours (each pair once).
    pub(super) fn of(n: usize, pairs: impl Iterator<Item = (usize, usize)> + Clone) -> Neighbours {
        let mut start = vec![0u32; n + 1];
        for (a, b) in pairs.clone() {
            start[a + 1] += 1;
            start[b + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut items = vec![0u32; start[n] as usize];
        for (a, b) in pairs {
            items[fill[a] as usize] = b as u32;
            fill[a] += 1;
            items[fill[b] as usize] = a as u32;
            fill[b] += 1;
        }
        Neighbours { start, items }
    }

    pub(super) fn of_item(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        self.items[self.start[i] as usize..self.start[i + 1] as usize].iter().map(|&j| j as usize)
    }
}

/// For a grid of directions (the cube's faces cut into cells), the facet
/// whose cone holds the cell's centre and the vertex farthest toward it:
/// a climb started there takes a step or none.
#[derive(Debug, Clone)]
pub(super) struct DirectionTable {
    pub(super) facets: Vec<u32>,
    pub(super) vertices: Vec<u32>,
}

/// The ball's graphs, the direction table and the box bounds' factors.
#[derive(Debug, Clone)]
pub(super) struct Prepared {
    pub(super) facet_graph: Neighbours,
    pub(super) vertex_graph: Neighbours,
    /// Climbs' starts by direction (balls of many facets only).
    pub(super) table: Option<DirectionTable>,
    /// Few facets: boxes are bounded by every facet plane.
    pub(super) few: bool,
    /// 1 / circumradius: `γ_B(x) ≥ |x| / R`.
    pub(super) inv_radius: f64,
    /// Per axis 1 / (the ball's largest coordinate) and 1 / (minus its
    /// least): B lies in its bounding box, whose gauge is below B's.
    pub(super) up: [f64; 3],
    pub(super) down: [f64; 3],
}

/// The ball's [`Prepared`], made on first use. A cache: it takes no part
/// in comparing balls, and a clone starts empty.
#[derive(Default)]
pub(super) struct PreparedCell(pub(super) OnceLock<Box<Prepared>>);

impl Clone for PreparedCell {
    fn clone(&self) -> Self {
        PreparedCell::default()
    }
}

impl PartialEq for PreparedCell {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for PreparedCell {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.get().is_some() { "prepared" } else { "not prepared" })
    }
}
