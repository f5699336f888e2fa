//! Closed loops out of a drawing's loose curves, as cycles of the graph
//! whose vertices are the curves' end points (ends within the chaining
//! tolerance are one vertex) and whose edges are the curves.
//!
//! Following each curve to the nearest free end ([`chain`](super::chain))
//! walks into whatever meets a profile at one of its corners (the leads of
//! an electronic symbol, a centre line ending on an outline) and loses the
//! profile. Here curves with a loose end are stripped first, repeatedly,
//! which leaves exactly the curves that lie on cycles or between them; the
//! rest is walked into cycles, straight on at a junction.

use crate::kernel::element::Element;
use crate::kernel::Point;
use crate::shape::model::bulge_loop::{Loop, Vertex};
use crate::shape::model::loose::LooseElement;
use crate::util::fast_hash::FastMap;

/// The side of the cells that join curve ends, in chaining tolerances.
const CELL: f64 = 16.0;

/// What [`profile_loops`] found.
#[derive(Debug, Default)]
pub(crate) struct Profiles {
    /// Closed loops, each with the indices of its curves in loop order.
    pub loops: Vec<(Loop, Vec<usize>)>,
    /// Connected runs of curves in no loop (each index once), each with a
    /// point of it: a loose end where it has one.
    pub open: Vec<(Vec<usize>, Point)>,
    /// Vertices of the loops where curve ends that did not meet exactly
    /// were joined, and the widest gap joined there (model units).
    pub gaps: Vec<(Point, f64)>,
}

/// The graph: vertex positions, and each curve's two end vertices.
struct Graph {
    points: Vec<Point>,
    /// The farthest end joined into each vertex.
    widest: Vec<f64>,
    ends: Vec<[usize; 2]>,
    /// Curves at each vertex (a curve from a vertex to itself twice).
    at: Vec<Vec<usize>>,
}

impl Graph {
    fn new(elems: &[LooseElement], tol: f64) -> Graph {
        // Cells of `CELL` tolerances: a point within `tol` of a vertex
        // lies in the vertex's cell or in a neighbour it is within `tol`
        // of, and most points are near no cell side (one lookup).
        let cell = (CELL * tol).max(f64::MIN_POSITIVE * 1e10);
        let key = |p: Point| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
        // The neighbouring cells (-1, 0, 1 per axis) a point may reach.
        let reach = |x: f64, k: i64| {
            let f = x / cell - k as f64;
            (if f * cell < tol { -1 } else { 0 })..=(if (1.0 - f) * cell < tol { 1 } else { 0 })
        };
        let mut cells: FastMap<(i64, i64), Vec<usize>> = FastMap::default();
        let mut points: Vec<Point> = Vec::new();
        let mut widest: Vec<f64> = Vec::new();
        let mut vertex = |p: Point| {
            let (kx, ky) = key(p);
            let near = reach(p.x, kx)
                .flat_map(|dx| reach(p.y, ky).map(move |dy| (kx.saturating_add(dx), ky.saturating_add(dy))))
                .filter_map(|k| cells.get(&k))
                .flatten()
                .copied()
                .map(|v| (points[v].dist(p), v))
                .filter(|&(d, _)| d <= tol)
                .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            match near {
                Some((d, v)) => {
                    widest[v] = widest[v].max(d);
                    v
                }
                None => {
                    points.push(p);
                    widest.push(0.0);
                    cells.entry((kx, ky)).or_default().push(points.len() - 1);
                    points.len() - 1
                }
            }
        };
        let ends: Vec<[usize; 2]> = elems.iter().map(|e| [vertex(e.a), vertex(e.b)]).collect();
        let mut at = vec![Vec::new(); points.len()];
        for (i, &[u, v]) in ends.iter().enumerate() {
            at[u].push(i);
            at[v].push(i);
        }
        Graph { points, widest, ends, at }
    }

    /// The other end of curve `e` from vertex `v`.
    fn other(&self, e: usize, v: usize) -> usize {
        let [a, b] = self.ends[e];
        if a == v {
            b
        } else {
            a
        }
    }
}

/// Which curves are still to be walked, and how many meet at each vertex.
struct Live<'g> {
    g: &'g Graph,
    live: Vec<bool>,
    degree: Vec<usize>,
    /// Curves stripped as (parts of) dangling runs.
    stripped: Vec<bool>,
}

impl<'g> Live<'g> {
    fn new(g: &'g Graph, live: Vec<bool>) -> Live<'g> {
        let degree = g.at.iter().map(|es| es.iter().filter(|&&e| live[e]).count()).collect();
        let stripped = vec![false; live.len()];
        Live { g, live, degree, stripped }
    }

    fn take(&mut self, e: usize) {
        self.live[e] = false;
        for v in self.g.ends[e] {
            self.degree[v] -= 1;
        }
    }

    fn give(&mut self, e: usize) {
        self.live[e] = true;
        for v in self.g.ends[e] {
            self.degree[v] += 1;
        }
    }

    /// Strips, from the vertices `todo` on, every vertex's one live curve
    /// while it has one: what hangs off the rest by a loose end.
    fn strip(&mut self, mut todo: Vec<usize>) {
        while let Some(v) = todo.pop() {
            if self.degree[v] != 1 {
                continue;
            }
            let Some(&e) = self.g.at[v].iter().find(|&&e| self.live[e]) else { continue };
            self.take(e);
            self.stripped[e] = true;
            todo.push(self.g.other(e, v));
        }
    }
}

/// The closed loops of `elems` (ends within `tol` joined) and the curves
/// in none, every curve in exactly one of the two.
pub(crate) fn profile_loops(elems: &[LooseElement], tol: f64) -> Profiles {
    let g = Graph::new(elems, tol);
    let mut live = vec![true; elems.len()];
    // A curve from a vertex to itself (its ends within the tolerance: a
    // dot, or an arc the tolerance closes; a whole circle drawn as one arc
    // is read as a circle before it gets here) closes no loop of its own.
    let mut out = Profiles::default();
    for (i, &[u, v]) in g.ends.iter().enumerate() {
        if u == v {
            live[i] = false;
            out.open.push((vec![i], g.points[u]));
        }
    }
    let mut state = Live::new(&g, live);
    // Strip loose ends: a vertex with one live curve loses it, and so on.
    state.strip((0..g.points.len()).collect());
    walk_cycles(elems, &g, &mut state, &mut out);
    let Live { live, stripped, .. } = state;
    // The stripped curves and those no cycle took, by connected runs.
    let mut left: Vec<bool> = (0..elems.len()).map(|i| stripped[i] || live[i]).collect();
    for first in 0..elems.len() {
        if !left[first] {
            continue;
        }
        left[first] = false;
        let mut run = vec![first];
        let mut k = 0;
        while k < run.len() {
            for v in g.ends[run[k]] {
                for &e in &g.at[v] {
                    if left[e] {
                        left[e] = false;
                        run.push(e);
                    }
                }
            }
            k += 1;
        }
        // A loose end of the run if it has one: a vertex no other curve meets.
        let end = run.iter().flat_map(|&e| g.ends[e]).find(|&v| g.at[v].len() == 1).unwrap_or(g.ends[run[0]][0]);
        out.open.push((run, g.points[end]));
    }
    out
}

/// Walks the live curves into cycles: from a vertex along unused curves,
/// straight on where several continue, until the walk meets a vertex of
/// its own path again (the curves since then are a loop) or stops at a
/// vertex whose other curves the loops took: the walk's curves are given
/// back, and what now hangs off the rest by that vertex is stripped.
fn walk_cycles(elems: &[LooseElement], g: &Graph, state: &mut Live, out: &mut Profiles) {
    let element = |e: usize| Element::from_bulge(elems[e].a, elems[e].b, elems[e].bulge);
    // Direction of travel leaving vertex `v` along curve `e` (arriving at
    // `v` along `e` is the opposite).
    let leaving = |e: usize, v: usize| {
        let el = element(e);
        if g.ends[e][0] == v {
            el.start_tangent()
        } else {
            -el.end_tangent()
        }
    };
    let mut on_path: FastMap<usize, usize> = FastMap::default();
    for first in 0..elems.len() {
        if !state.live[first] {
            continue;
        }
        // The path: vertices, and the curve taken from each.
        let mut path: Vec<(usize, usize)> = Vec::new();
        on_path.clear();
        let (mut v, mut e) = (g.ends[first][0], first);
        let end = loop {
            state.take(e);
            on_path.insert(v, path.len());
            path.push((v, e));
            let w = g.other(e, v);
            if let Some(&k) = on_path.get(&w) {
                let cycle: Vec<(usize, usize)> = path.drain(k..).collect();
                for &(u, _) in &cycle {
                    on_path.remove(&u);
                }
                out.gaps.extend(
                    cycle.iter().filter(|&&(u, _)| g.widest[u] > 0.0).map(|&(u, _)| (g.points[u], g.widest[u])),
                );
                out.loops.push(loop_of(elems, g, &cycle));
            }
            let heading = -leaving(e, w);
            let next = g.at[w]
                .iter()
                .copied()
                .filter(|&c| state.live[c])
                .max_by(|&a, &b| heading.dot(leaving(a, w)).total_cmp(&heading.dot(leaving(b, w))).then(b.cmp(&a)));
            match next {
                Some(c) => (v, e) = (w, c),
                None => break w,
            }
        };
        for &(_, e) in &path {
            state.give(e);
        }
        if !path.is_empty() {
            state.strip(vec![end]);
        }
    }
}

/// The loop of a cycle of (vertex, curve leaving it): each curve from its
/// vertex, its bulge negated where it is walked backwards.
fn loop_of(elems: &[LooseElement], g: &Graph, cycle: &[(usize, usize)]) -> (Loop, Vec<usize>) {
    let vertices = cycle
        .iter()
        .map(|&(v, e)| {
            let bulge = if g.ends[e][0] == v { elems[e].bulge } else { -elems[e].bulge };
            Vertex { p: g.points[v], bulge }
        })
        .collect();
    (Loop::new(vertices), cycle.iter().map(|&(_, e)| e).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(a: (f64, f64), b: (f64, f64)) -> LooseElement {
        LooseElement { a: Point::new(a.0, a.1), b: Point::new(b.0, b.1), bulge: 0.0 }
    }

    #[test]
    fn leads_at_the_corners_of_a_triangle_leave_the_triangle() {
        // An amplifier symbol: a triangle, two input leads ending on its
        // left side's ends, an output lead at its tip, drawn lead first.
        let elems = [
            seg((-1.0, 1.0), (0.0, 1.0)),
            seg((0.0, 1.0), (0.0, -1.0)),
            seg((-1.0, -1.0), (0.0, -1.0)),
            seg((0.0, -1.0), (2.0, 0.0)),
            seg((2.0, 0.0), (3.0, 0.0)),
            seg((2.0, 0.0), (0.0, 1.0)),
        ];
        let p = profile_loops(&elems, 1e-9);
        assert_eq!(p.loops.len(), 1);
        let mut ids = p.loops[0].1.clone();
        ids.sort_unstable();
        assert_eq!(ids, [1, 3, 5]);
        assert!((p.loops[0].0.signed_area().abs() - 2.0).abs() < 1e-12);
        let mut open: Vec<usize> = p.open.iter().flat_map(|(r, _)| r.clone()).collect();
        open.sort_unstable();
        assert_eq!(open, [0, 2, 4]);
    }

    #[test]
    fn a_rectangle_with_a_diagonal_keeps_its_outline() {
        let elems = [
            seg((0.0, 0.0), (2.0, 0.0)),
            seg((2.0, 0.0), (2.0, 1.0)),
            seg((2.0, 1.0), (0.0, 1.0)),
            seg((0.0, 1.0), (0.0, 0.0)),
            seg((0.0, 0.0), (2.0, 1.0)),
        ];
        let p = profile_loops(&elems, 1e-9);
        assert_eq!(p.loops.len(), 1);
        assert!((p.loops[0].0.signed_area().abs() - 2.0).abs() < 1e-12);
        assert_eq!(p.open.len(), 1);
        assert_eq!(p.open[0].0, [4]);
    }

    #[test]
    fn reversed_curves_and_small_gaps_close() {
        let elems = [
            LooseElement { a: Point::new(0.0, 0.0), b: Point::new(1.0, 0.0), bulge: 0.0 },
            LooseElement { a: Point::new(1.0, 1.0), b: Point::new(1.0, 1e-10), bulge: -0.3 },
            seg((0.0, 1.0), (1.0, 1.0)),
            seg((0.0, 1.0), (0.0, 0.0)),
        ];
        let p = profile_loops(&elems, 1e-9);
        assert_eq!(p.loops.len(), 1);
        assert!(p.open.is_empty());
        // Every curve once; the reversed arc's bulge turned round.
        let l = &p.loops[0].0;
        assert_eq!(l.len(), 4);
        let bulges: f64 = l.vertices().iter().map(|v| v.bulge.abs()).sum();
        assert_eq!(bulges, 0.3);
    }
}
