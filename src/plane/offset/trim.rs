//! The trimming walk of thesis 2.4.3 for one axis.
//!
//! A state is one side of one monotonic piece of an edge. Walking the side cycle,
//! a side whose radius stays above ρ contributes its whole offset; a side
//! whose radius falls to ρ contributes its offset up to the disk of radius
//! ρ, and the walk turns over to the other side of the same piece there
//! (where the offset loop crosses the axis at a convex corner of Ω^ρ).
//! Every state has exactly one way in (its radius at the start is above ρ,
//! or it is entered at the crossing), so the walks are disjoint closed
//! loops. The components of Ω^ρ are those of the axis where the radius
//! exceeds ρ (Ω^ρ retracts onto it), found by union–find.

use crate::kernel::Point;
use crate::plane::axis::{own_end_pair, AxisEdge, MedialAxis2d, Primitive};
use crate::plane::offset::layer::{OffsetError, OffsetLayer, OffsetLoop, OffsetRegion};
use crate::plane::offset::prim::OffsetPrim;
use crate::plane::offset::profile::EdgeProfile;
use crate::plane::offset::side_cycle::SideCycle;
use crate::shape::{ElementRef, Loop, Shape2d, Vertex};
use std::collections::HashMap;

/// One axis prepared for offsets at any distance.
#[derive(Debug, Clone)]
pub(crate) struct Trimmer {
    profiles: Vec<EdgeProfile>,
    /// `sub_base[e]`: index of edge e's first piece among all pieces.
    sub_base: Vec<u32>,
    /// (from, to) node of each edge.
    ends: Vec<[u32; 2]>,
    sides: Result<SideCycle, &'static str>,
    /// The leaf arcs' primitives and start angles, by (loop, element).
    arcs: HashMap<(u32, u32), (OffsetPrim, f64)>,
    /// A shape whose axis is one leaf (a disk): its loop, centre and radius.
    disk: Option<(Loop, Point, f64)>,
    nodes: usize,
    max_radius: f64,
}

/// How the walk enters a state.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Entry {
    /// At the start of the piece's side (its radius there lies in the
    /// band).
    Start,
    /// At the disk of the band's lower radius, coming over from the other
    /// side.
    Low(Point, [f64; 2]),
    /// At the disk of the band's upper radius, coming over from the other
    /// side.
    High(Point, [f64; 2]),
}

/// A piece of an offset loop on one primitive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Run {
    pub prim: OffsetPrim,
    pub start: Point,
    pub advance: f64,
}

/// A piece of the boundary of a band {lo < dist < ·, radius of the
/// maximal disk at the footpoint < hi}.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum BandPiece {
    /// The offset at the lower radius along one primitive.
    Run(Run),
    /// Across the edge along the two footpoint normals of the disk of the
    /// upper radius (centre `centre`), from the offset point on one side to
    /// the other's.
    Turn { centre: Point, from: Point, to: Point },
}

/// A closed band loop and its component (union–find root).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BandLoop {
    pub pieces: Vec<BandPiece>,
    pub component: usize,
}

/// The axis's edges with the footpoint parameters of every element side
/// inside the element's own range, and at the element's end where the
/// side cycle turns onto another primitive (at its start where it turns
/// onto it from another).
///
/// A disk that hugs a stretch of nearly concentric arcs (a tip or the
/// inside of a nearly circular curve: centres 10^-4 apart where the disk
/// is known to 10^-7) touches each of them within the tolerance, and the
/// axis may name one element for the whole stretch, or give a parameter
/// from the direction of its centre, which is rounding there. Emitted as
/// is, the offset would follow that element's circle past its end. The
/// footpoint can never leave its element, and where the footpoint passes
/// from one primitive to the next at a node, the node's disk touches the
/// boundary between the two footpoints (a joint, a leaf arc, a stretch it
/// hugs, emitted whole as the side cycle's gaps), so the element's end is
/// a footpoint of that disk. Where the parameters are well conditioned
/// this changes them by rounding only. Reflex vertices keep theirs: a
/// fan's direction from a disk's centre is well conditioned whenever the
/// disk is larger than the tolerance.
fn element_params(shape: &Shape2d, axis: &MedialAxis2d, sides: &SideCycle) -> Vec<AxisEdge> {
    let mut edges = axis.edges.clone();
    for e in &mut edges {
        for k in 0..2 {
            let (p, (u0, u1)) = (e.sites[k], e.params[k]);
            e.params[k] = (p.clamp_param(shape, u0), p.clamp_param(shape, u1));
        }
    }
    for h in 0..2 * axis.edges.len() {
        let hn = sides.next[h] as usize;
        let (p, q) = (axis.edges[h / 2].sites[h % 2], axis.edges[hn / 2].sites[hn % 2]);
        if p == q {
            continue;
        }
        // Half-edge 2e + 1 runs from `from` to `to` on side 1, 2e the other
        // way on side 0: `.1` is where side 1 ends, `.0` where side 0 ends.
        if let Some((_, end)) = p.element_params(shape) {
            let slot = &mut edges[h / 2].params[h % 2];
            *(if h % 2 == 1 { &mut slot.1 } else { &mut slot.0 }) = end;
        }
        if let Some((start, _)) = q.element_params(shape) {
            let slot = &mut edges[hn / 2].params[hn % 2];
            *(if hn % 2 == 1 { &mut slot.0 } else { &mut slot.1 }) = start;
        }
    }
    edges
}

/// Whether a piece of edge with end radii `r0`, `r1` (monotonic between)
/// reaches into the open band (`lo`, `hi`).
fn in_band(r0: f64, r1: f64, lo: f64, hi: f64) -> bool {
    r0.max(r1) > lo && r0.min(r1) < hi
}

impl Trimmer {
    /// The trimmer of `axis`, the medial axis of `shape`.
    pub(crate) fn new(shape: &Shape2d, axis: &MedialAxis2d) -> Trimmer {
        let sides = SideCycle::new(shape, axis);
        let edges = match &sides {
            Ok(t) => element_params(shape, axis, t),
            Err(_) => axis.edges.clone(),
        };
        let profiles: Vec<EdgeProfile> = edges
            .iter()
            .map(|e| {
                let prims = [OffsetPrim::new(shape, e.sites[0]), OffsetPrim::new(shape, e.sites[1])];
                let own_end = own_end_pair(shape, e.sites[0], e.sites[1]);
                let r_max = axis.nodes[e.from].radius.max(axis.nodes[e.to].radius);
                EdgeProfile::new(e, &axis.nodes, prims, own_end, e.driver(shape, r_max))
            })
            .collect();
        let mut sub_base = Vec::with_capacity(profiles.len() + 1);
        let mut total = 0u32;
        for p in &profiles {
            sub_base.push(total);
            total += (p.breaks.len() - 1) as u32;
        }
        sub_base.push(total);
        let mut arcs = HashMap::new();
        if let Ok(t) = &sides {
            for h in 0..2 * axis.edges.len() {
                for &(l, e) in t.gaps(h) {
                    let r = ElementRef { loop_index: l as usize, element: e as usize };
                    arcs.entry((l, e)).or_insert_with(|| {
                        let prim = OffsetPrim::new(shape, Primitive::of_element(r));
                        (prim, prim.param_of(shape.loops()[r.loop_index].vertices()[r.element].p))
                    });
                }
            }
        }
        // The largest disk may lie inside an edge (a D shape's one edge runs
        // between two corners): its inner extrema are breaks.
        let max_radius = axis
            .nodes
            .iter()
            .map(|n| n.radius)
            .chain(profiles.iter().flat_map(|p| p.breaks.iter().map(|b| b.radius)))
            .fold(0.0, f64::max);
        let disk = (axis.edges.is_empty() && axis.nodes.len() == 1 && shape.loops().len() == 1)
            .then(|| (shape.loops()[0].clone(), axis.nodes[0].point, axis.nodes[0].radius));
        Trimmer {
            profiles,
            sub_base,
            ends: axis.edges.iter().map(|e| [e.from as u32, e.to as u32]).collect(),
            sides,
            arcs,
            disk,
            nodes: axis.nodes.len(),
            max_radius,
        }
    }

    /// Whether the axis's edge sides form the side cycle round the boundary.
    pub(crate) fn check(&self) -> Result<(), &'static str> {
        self.sides.as_ref().map(|_| ()).map_err(|e| *e)
    }

    /// The radius of the largest inscribed disk, model units.
    pub(crate) fn max_radius(&self) -> f64 {
        self.max_radius
    }

    fn pieces(&self, e: usize) -> usize {
        self.profiles[e].breaks.len() - 1
    }

    /// Union–find id of break `i` of edge `e`: its node at the ends, after
    /// the nodes for inner breaks.
    fn break_id(&self, e: usize, i: usize) -> usize {
        let m = self.pieces(e);
        if i == 0 {
            self.ends[e][0] as usize
        } else if i == m {
            self.ends[e][1] as usize
        } else {
            self.nodes + self.sub_base[e] as usize - e + i - 1
        }
    }

    /// Union–find id of piece `j` of edge `e`.
    fn piece_id(&self, e: usize, j: usize) -> usize {
        let total = *self.sub_base.last().unwrap_or(&0) as usize;
        self.nodes + (total - self.profiles.len()) + self.sub_base[e] as usize + j
    }

    /// The offset at distance `rho` ≥ 0; pieces shorter than `tol` are
    /// dropped.
    pub(crate) fn layer(&self, rho: f64, tol: f64) -> Result<OffsetLayer, OffsetError> {
        Ok(self.layer_sources(rho, tol)?.0)
    }

    /// [`Trimmer::layer`] and, for each loop, the lowest index of the shape
    /// loops it runs along.
    pub(crate) fn layer_sources(&self, rho: f64, tol: f64) -> Result<(OffsetLayer, Vec<u32>), OffsetError> {
        if let Some((lp, centre, radius)) = &self.disk {
            let layer = disk_layer(lp, *centre, *radius, rho);
            let sources = vec![0; layer.loops.len()];
            return Ok((layer, sources));
        }
        let (band, mut uf) = self.band_loops(rho, f64::INFINITY)?;
        let mut loops: Vec<(OffsetLoop, usize, usize)> = Vec::new();
        let mut sources = Vec::new();
        for (bl, piece) in band {
            let runs: Vec<Run> = bl
                .pieces
                .iter()
                .filter_map(|p| match p {
                    BandPiece::Run(r) => Some(*r),
                    BandPiece::Turn { .. } => None,
                })
                .collect();
            let source = runs.iter().map(|r| r.prim.loop_index).min().unwrap_or(0);
            if let Some(vertices) = close_runs(runs, rho, tol) {
                let area = Loop::new(vertices.clone()).signed_area();
                loops.push((OffsetLoop { vertices, area, region: 0 }, bl.component, piece));
                sources.push(source);
            }
        }
        Ok((self.regions(loops, &mut uf, rho)?, sources))
    }

    /// Every closed loop bounding the band of points at distance above `lo`
    /// whose footpoint's maximal disk has a radius below `hi` (`hi` infinite:
    /// the inner offset at `lo`), with the piece of axis it started from,
    /// and the union–find over the axis in the band.
    pub(crate) fn band_loops(&self, lo: f64, hi: f64) -> Result<(Vec<(BandLoop, usize)>, UnionFind), OffsetError> {
        let topology = |what| OffsetError::Topology { distance: lo, what };
        let sides = self.sides.as_ref().map_err(|w| topology(w))?;
        let total = *self.sub_base.last().unwrap_or(&0) as usize;
        let mut uf = UnionFind::new(self.nodes + 2 * total - self.profiles.len());
        for (e, p) in self.profiles.iter().enumerate() {
            for j in 0..p.breaks.len() - 1 {
                if !in_band(p.breaks[j].radius, p.breaks[j + 1].radius, lo, hi) {
                    continue;
                }
                for i in [j, j + 1] {
                    let r = p.breaks[i].radius;
                    if r > lo && r < hi {
                        uf.union(self.piece_id(e, j), self.break_id(e, i));
                    }
                }
            }
        }
        let mut visited = vec![false; 2 * total];
        let mut out = Vec::new();
        for (e, p) in self.profiles.iter().enumerate() {
            for j in 0..p.breaks.len() - 1 {
                if !in_band(p.breaks[j].radius, p.breaks[j + 1].radius, lo, hi) {
                    continue;
                }
                for k in 0..2 {
                    if visited[2 * (self.sub_base[e] as usize + j) + k] {
                        continue;
                    }
                    let pieces = self.walk(sides, (e, j, k), (lo, hi), &mut visited).map_err(topology)?;
                    let component = uf.find(self.piece_id(e, j));
                    out.push((BandLoop { pieces, component }, self.sub_base[e] as usize + j));
                }
            }
        }
        Ok((out, uf))
    }

    /// Walks one closed loop of the band (`lo`, `hi`) from state (edge,
    /// piece, side).
    fn walk(
        &self,
        sides: &SideCycle,
        start: (usize, usize, usize),
        (lo, hi): (f64, f64),
        visited: &mut [bool],
    ) -> Result<Vec<BandPiece>, &'static str> {
        let (mut e, mut j, mut k) = start;
        let first = {
            let p = &self.profiles[e];
            let r_in = p.breaks[if k == 1 { j } else { j + 1 }].radius;
            if r_in <= lo {
                let (c, u) = p.crossing(j, lo);
                Entry::Low(c, u)
            } else if r_in >= hi {
                let (c, u) = p.crossing(j, hi);
                Entry::High(c, u)
            } else {
                Entry::Start
            }
        };
        let mut entry = first;
        let mut out = Vec::new();
        let limit = visited.len() + 2;
        for _ in 0..limit {
            visited[2 * (self.sub_base[e] as usize + j) + k] = true;
            let p = &self.profiles[e];
            let (bi, bo) = if k == 1 { (j, j + 1) } else { (j + 1, j) };
            let prim = p.prims[k];
            let (start_point, u0) = match entry {
                Entry::Start => (prim.point_at(p.breaks[bi].u[k], lo), p.breaks[bi].u[k]),
                Entry::Low(c, u) => (c, u[k]),
                Entry::High(_, u) => (prim.point_at(u[k], lo), u[k]),
            };
            let r_out = p.breaks[bo].radius;
            let run = |u1: f64| BandPiece::Run(Run { prim, start: start_point, advance: prim.advance(u0, u1) });
            if r_out <= lo {
                let (c, u) = p.crossing(j, lo);
                out.push(run(u[k]));
                entry = Entry::Low(c, u);
                k = 1 - k;
            } else if r_out >= hi {
                let (c, u) = p.crossing(j, hi);
                out.push(run(u[k]));
                let (from, to) = (prim.point_at(u[k], lo), p.prims[1 - k].point_at(u[1 - k], lo));
                out.push(BandPiece::Turn { centre: c, from, to });
                entry = Entry::High(c, u);
                k = 1 - k;
            } else {
                out.push(run(p.breaks[bo].u[k]));
                entry = Entry::Start;
                if k == 1 && j + 1 < self.pieces(e) {
                    j += 1;
                } else if k == 0 && j > 0 {
                    j -= 1;
                } else {
                    let h = 2 * e + k;
                    for gap in sides.gaps(h) {
                        let (arc, u) = self.arcs[gap];
                        out.push(BandPiece::Run(Run { prim: arc, start: arc.point_at(u, lo), advance: arc.bound }));
                    }
                    let hn = sides.next[h] as usize;
                    (e, k) = (hn / 2, hn % 2);
                    j = if k == 1 { 0 } else { self.pieces(e) - 1 };
                }
            }
            if (e, j, k) == start {
                let same = matches!(
                    (entry, first),
                    (Entry::Start, Entry::Start)
                        | (Entry::Low(..), Entry::Low(..))
                        | (Entry::High(..), Entry::High(..))
                );
                if !same {
                    return Err("the walk came back to its start another way");
                }
                return Ok(out);
            }
        }
        Err("the walk did not close")
    }

    /// Groups the loops by component, outer loop first.
    fn regions(
        &self,
        loops: Vec<(OffsetLoop, usize, usize)>,
        uf: &mut UnionFind,
        rho: f64,
    ) -> Result<OffsetLayer, OffsetError> {
        let mut index: HashMap<usize, usize> = HashMap::new();
        let mut regions: Vec<OffsetRegion> = Vec::new();
        let mut anchors = Vec::new();
        let mut out = Vec::with_capacity(loops.len());
        for (li, (mut lp, root, piece)) in loops.into_iter().enumerate() {
            let r = *index.entry(root).or_insert_with(|| {
                regions.push(OffsetRegion { outer: usize::MAX, holes: Vec::new() });
                anchors.push(piece);
                regions.len() - 1
            });
            lp.region = r;
            if lp.area > 0.0 {
                if regions[r].outer != usize::MAX {
                    return Err(OffsetError::Topology { distance: rho, what: "a region has two outer loops" });
                }
                regions[r].outer = li;
            } else {
                regions[r].holes.push(li);
            }
            out.push(lp);
        }
        if regions.iter().any(|r| r.outer == usize::MAX) {
            return Err(OffsetError::Topology { distance: rho, what: "a region has no outer loop" });
        }
        let mut piece_region = vec![u32::MAX; *self.sub_base.last().unwrap_or(&0) as usize];
        for (e, p) in self.profiles.iter().enumerate() {
            for j in 0..p.breaks.len() - 1 {
                if p.breaks[j].radius.max(p.breaks[j + 1].radius) > rho {
                    if let Some(&r) = index.get(&uf.find(self.piece_id(e, j))) {
                        piece_region[self.sub_base[e] as usize + j] = r as u32;
                    }
                }
            }
        }
        Ok(OffsetLayer { distance: rho, loops: out, regions, anchors, piece_region })
    }
}

/// A disk's offset: its loop scaled about the centre (bulges keep their
/// sweep).
fn disk_layer(lp: &Loop, centre: Point, radius: f64, rho: f64) -> OffsetLayer {
    let mut layer = OffsetLayer {
        distance: rho,
        loops: Vec::new(),
        regions: Vec::new(),
        anchors: Vec::new(),
        piece_region: Vec::new(),
    };
    if rho < radius {
        let s = (radius - rho) / radius;
        let vertices: Vec<Vertex> =
            lp.vertices().iter().map(|v| Vertex { p: centre + (v.p - centre) * s, bulge: v.bulge }).collect();
        let area = Loop::new(vertices.clone()).signed_area();
        layer.loops.push(OffsetLoop { vertices, area, region: 0 });
        layer.regions.push(OffsetRegion { outer: 0, holes: Vec::new() });
        layer.anchors.push(usize::MAX);
    }
    layer
}

/// Merges consecutive runs on one primitive, drops runs shorter than `tol`
/// and returns the loop's vertices (`None` if nothing longer is left).
fn close_runs(mut runs: Vec<Run>, rho: f64, tol: f64) -> Option<Vec<Vertex>> {
    let same = |a: &Run, b: &Run| a.prim.loop_index == b.prim.loop_index && a.prim.pos == b.prim.pos;
    let mut merged: Vec<Run> = Vec::with_capacity(runs.len());
    for r in runs.drain(..) {
        match merged.last_mut() {
            Some(last) if same(last, &r) => last.advance += r.advance,
            _ => merged.push(r),
        }
    }
    if merged.len() > 1 && same(&merged[0], merged.last()?) {
        let last = merged.pop()?;
        merged[0].start = last.start;
        merged[0].advance += last.advance;
    }
    let vertices: Vec<Vertex> = merged
        .iter()
        .filter(|r| r.prim.length(r.advance, rho) > tol)
        .map(|r| Vertex { p: r.start, bulge: r.prim.bulge(r.advance) })
        .collect();
    (vertices.len() >= 2).then_some(vertices)
}

/// Union–find with path halving.
pub(crate) struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    fn new(n: usize) -> UnionFind {
        UnionFind { parent: (0..n as u32).collect() }
    }

    pub(crate) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] as usize != x {
            let g = self.parent[self.parent[x] as usize];
            self.parent[x] = g;
            x = g as usize;
        }
        x
    }

    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.parent[ra.max(rb)] = ra.min(rb) as u32;
        }
    }
}
