//! The driver: seeds at the convex corners, rays traced to their next node
//! until every ray of every node is an edge, then pass-through nodes
//! merged and node kinds assigned.
//!
//! In general position every polygon has a corner the ball does not prune:
//! along the outer loop the edges' normals turn once round, so the vertex
//! of the ball that touches them changes at some convex vertex. Outside it
//! (a rectangle under the square ball prunes all four corners) and for any
//! part of the axis the corners do not reach, an edge that no axis edge
//! names as a side is *probed*: the ball touching its middle grows until
//! it touches elsewhere, a point of the axis, from which tracing goes on.

use super::error::BallAxisError;
use super::graph::{BallAxis, BallEdge, BallNode, BallNodeKind};
use super::node::{Node, Ray};
use super::problem::{ClassId, Problem};
use crate::kernel::exact_line::{HPoint, ILine, IVec};
use crate::kernel::BigInt;
use crate::shape::{Ball2, Shape2d};
use crate::util::fast_hash::FastMap;
use std::cmp::Ordering;

struct Tracer<'p, 'a> {
    pb: &'p Problem<'a>,
    nodes: Vec<Node>,
    cells: FastMap<(i64, i64), Vec<usize>>,
    cell: f64,
    edges: Vec<Traced>,
    /// `named[e]`: a traced edge has shape edge `e`'s class on a side.
    named: Vec<bool>,
    work: Vec<(usize, usize)>,
    /// Probe landing points: nodes in the middle of an axis edge, which a
    /// trace from the edge's far end would walk past (nothing happens
    /// there) and must stop at.
    landings: Vec<usize>,
}

/// A traced edge: nodes, side classes, the line it runs on.
struct Traced {
    from: usize,
    to: usize,
    left: ClassId,
    right: ClassId,
    carrier: ILine,
}

impl Tracer<'_, '_> {
    fn key(&self, x: f64, y: f64) -> (i64, i64) {
        ((x / self.cell).floor() as i64, (y / self.cell).floor() as i64)
    }

    fn find(&self, p: &HPoint) -> Option<usize> {
        let at = p.approx(self.pb.shape_units);
        let (cx, cy) = self.key(at.x, at.y);
        for dx in -1..=1 {
            for dy in -1..=1 {
                if let Some(ids) = self.cells.get(&(cx + dx, cy + dy)) {
                    if let Some(&i) = ids.iter().find(|&&i| self.nodes[i].p.same(p)) {
                        return Some(i);
                    }
                }
            }
        }
        None
    }

    fn insert(&mut self, node: Node) -> usize {
        let id = self.nodes.len();
        let key = self.key(node.at.x, node.at.y);
        self.cells.entry(key).or_default().push(id);
        for j in 0..node.rays.len() {
            self.work.push((id, j));
        }
        self.nodes.push(node);
        id
    }

    /// Traces every pending ray, in rounds: the rays pending at the start
    /// of a round are traced in parallel, the new nodes they reach are
    /// analysed in parallel, then the edges are recorded in the order the
    /// rays were taken (so the result does not depend on the threads). A
    /// ray whose partner (the ray back from its far end) was traced in the
    /// same round is dropped: the partner's edge is the same.
    fn run(&mut self, limit: usize) -> Result<(), BallAxisError> {
        use rayon::prelude::*;
        loop {
            let mut batch: Vec<(usize, usize)> = std::mem::take(&mut self.work);
            batch.retain(|&(id, j)| self.nodes[id].rays.get(j).is_some_and(|r| !r.traced));
            if batch.is_empty() {
                return Ok(());
            }
            let (pb, nodes) = (self.pb, &self.nodes);
            let reached: Vec<Result<(HPoint, ClassId), BallAxisError>> =
                batch.par_iter().map(|&(id, j)| pb.trace(&nodes[id], &nodes[id].rays[j])).collect();
            // Where each ray lands: an existing node or a new one (several
            // rays of a round can reach the same new node).
            let mut fresh: Vec<(HPoint, ClassId)> = Vec::new();
            let mut fresh_cells: FastMap<(i64, i64), Vec<usize>> = FastMap::default();
            let mut targets: Vec<usize> = Vec::with_capacity(batch.len());
            for (&(id, j), r) in batch.iter().zip(reached) {
                let (q, reference) = r?;
                let to = match self.landing_before(id, j, &q).or_else(|| self.find(&q)) {
                    Some(t) => t,
                    None => {
                        let at = q.approx(self.pb.shape_units);
                        let (cx, cy) = self.key(at.x, at.y);
                        let seen = (-1..=1)
                            .flat_map(|dx| (-1..=1).map(move |dy| (cx + dx, cy + dy)))
                            .filter_map(|c| fresh_cells.get(&c))
                            .flatten()
                            .copied()
                            .find(|&k| fresh[k].0.same(&q));
                        let k = seen.unwrap_or_else(|| {
                            fresh_cells.entry((cx, cy)).or_default().push(fresh.len());
                            fresh.push((q, reference));
                            fresh.len() - 1
                        });
                        self.nodes.len() + k
                    }
                };
                targets.push(to);
            }
            if self.nodes.len() + fresh.len() > limit {
                return Err(BallAxisError::Inconsistent {
                    at: self.nodes[batch[0].0].at,
                    what: "more nodes than the size bound O(n + r·k) allows",
                });
            }
            let analysed: Vec<Node> = fresh.into_par_iter().map(|(q, reference)| pb.analyse(q, reference)).collect();
            for node in analysed {
                self.insert(node);
            }
            for (&(id, j), to) in batch.iter().zip(targets) {
                // Traced from the far end this round (then possibly released).
                if self.nodes[id].rays.get(j).is_none_or(|r| r.traced) {
                    continue;
                }
                self.nodes[id].rays[j].traced = true;
                self.connect(id, j, to)?;
                self.release_if_done(id);
                self.release_if_done(to);
            }
        }
    }

    /// Drops the rays of node `id` once every one is an edge: they hold the
    /// node's largest exact data (a direction and a carrier line each),
    /// and nothing reads them after (a tenth of the memory at 10^5 edges).
    fn release_if_done(&mut self, id: usize) {
        let rays = &mut self.nodes[id].rays;
        if !rays.is_empty() && rays.iter().all(|r| r.traced) {
            *rays = Vec::new();
        }
    }

    /// Records the edge traced along ray `j` of node `id` to node `to`,
    /// marking the ray back from `to` as traced.
    fn connect(&mut self, id: usize, j: usize, to: usize) -> Result<(), BallAxisError> {
        let ray = &self.nodes[id].rays[j];
        let (dir, left, right, carrier) = (ray.dir.neg(), ray.left, ray.right, ray.carrier.clone());
        let back = self.nodes[to]
            .rays
            .iter()
            .position(|b| b.dir.cross_sign(&dir) == Ordering::Equal && b.dir.dot_sign(&dir) == Ordering::Greater);
        match back {
            Some(b) if !self.nodes[to].rays[b].traced => self.nodes[to].rays[b].traced = true,
            _ => {
                return Err(BallAxisError::Inconsistent {
                    at: self.nodes[to].at,
                    what: "an edge of the axis arrives where its node has no ray back",
                })
            }
        }
        for c in [left, right] {
            if let Some(x) = self.named.get_mut(c as usize) {
                *x = true;
            }
        }
        self.edges.push(Traced { from: id, to, left, right, carrier });
        Ok(())
    }

    /// The landing point nearest to node `id` strictly inside the segment
    /// its ray `j` traced to `q`, if any.
    fn landing_before(&self, id: usize, j: usize, q: &HPoint) -> Option<usize> {
        let (from, ray) = (&self.nodes[id].p, &self.nodes[id].rays[j]);
        let d = &ray.dir;
        self.landings
            .iter()
            .copied()
            .filter(|&l| {
                let p = &self.nodes[l].p;
                l != id
                    && ray.carrier.side(p) == Ordering::Equal
                    && from.along(p, d) == Ordering::Greater
                    && p.along(q, d) == Ordering::Greater
            })
            .min_by(|&a, &b| self.nodes[b].p.along(&self.nodes[a].p, d))
    }

    /// True when `q` lies on a traced edge (ends included).
    fn on_traced_edge(&self, q: &HPoint) -> bool {
        self.edges.iter().any(|e| {
            let (a, b) = (&self.nodes[e.from].p, &self.nodes[e.to].p);
            let d = e.carrier.direction();
            e.carrier.side(q) == Ordering::Equal
                && a.along(q, &d) != b.along(q, &d).reverse()
                && (a.along(q, &d) != Ordering::Greater || b.along(q, &d) != Ordering::Greater)
                && (a.along(q, &d) != Ordering::Less || b.along(q, &d) != Ordering::Less)
        })
    }

    /// Probes every edge no axis edge names as a side: the ball touching
    /// its middle, grown along the touching vertex (the middle of the
    /// touching ball edge for EE), reaches the axis; tracing goes on from
    /// there unless that point is already on the traced axis.
    fn probe_uncovered(&mut self, limit: usize) -> Result<(), BallAxisError> {
        let pb = self.pb;
        for e in 0..pb.edge_count() as u32 {
            // A bit per edge, not a scan of the traced edges: this loop
            // runs for every edge.
            if self.named[e as usize] || pb.degenerate[e as usize] {
                continue;
            }
            let (a, b) = pb.edge(e);
            let (a, b) = (pb.shape_units.vec(a), pb.shape_units.vec(b));
            let mid = HPoint::new(&a.x + &b.x, &a.y + &b.y, BigInt::from_i64(2));
            let ball = pb.ball_ints();
            let k = ball.len();
            let dir = match pb.classes[e as usize].ball {
                crate::shape::Feature::Vertex(i) => ball[i].neg(),
                crate::shape::Feature::Edge(i) => ball[i].add(&ball[(i + 1) % k]).neg(),
            };
            let n = IVec::new(dir.y.clone(), -&dir.x);
            let carrier = ILine::new(n.scale(&mid.w), -&(&(&n.x * &mid.x) + &(&n.y * &mid.y)));
            let at = mid.approx(pb.shape_units);
            let start = Node {
                p: mid,
                at,
                r: 0.0,
                corner: false,
                vv: false,
                tied: vec![e],
                touching: vec![e],
                rays: Vec::new(),
            };
            let ray = Ray { dir, carrier, left: e, right: e, along: vec![e], traced: true };
            let (q, reference) = pb.trace(&start, &ray)?;
            if self.find(&q).is_some() || self.on_traced_edge(&q) {
                continue;
            }
            if self.nodes.len() >= limit {
                return Err(BallAxisError::Inconsistent {
                    at,
                    what: "more nodes than the size bound O(n + r·k) allows",
                });
            }
            let node = pb.analyse(q, reference);
            let id = self.insert(node);
            self.landings.push(id);
            self.run(limit)?;
        }
        Ok(())
    }
}

/// The medial axis of a polygon (any number of holes) under the convex
/// polygon ball `ball` (thesis 3.1–3.2): the centres of maximal* balls,
/// exact.
///
/// Every node is the meeting point of two lines of the input (coordinates
/// rational in the input, computed with integers) and every decision is
/// exact, so the graph's combinatorics are right for any input; outside
/// general position the symbolic perturbation of [`super`] decides.
/// Positions and radii are rounded to `f64` only on output.
///
/// # Errors
///
/// [`BallAxisError::Arc`] for arcs (flatten them first),
/// [`BallAxisError::Inconsistent`] if the tracing breaks down (a bug).
pub fn medial_axis_with_ball(shape: &Shape2d, ball: &Ball2) -> Result<BallAxis, BallAxisError> {
    let pb = Problem::new(shape, ball)?;
    let n = pb.edge_count();
    let mut t = Tracer {
        pb: &pb,
        nodes: Vec::new(),
        cells: FastMap::default(),
        cell: (pb.diag * 1e-7).max(f64::MIN_POSITIVE),
        edges: Vec::new(),
        named: vec![false; n],
        work: Vec::new(),
        landings: Vec::new(),
    };
    let seeds: Vec<Node> = {
        use rayon::prelude::*;
        (0..n as u32)
            .into_par_iter()
            .filter(|&v| !pb.reflex[v as usize])
            .map(|v| pb.analyse(HPoint::at(&pb.shape_units.vec(pb.pts[v as usize])), v))
            .filter(|node| !node.rays.is_empty())
            .collect()
    };
    for node in seeds {
        t.insert(node);
    }
    let limit = 64 * (pb.classes.len() + 16);
    t.run(limit)?;
    t.probe_uncovered(limit)?;
    let (nodes, edges) = merge_pass_through(t.nodes, t.edges);
    Ok(finish(&pb, nodes, edges))
}

/// An edge after merging: (from, to, left class, right class).
type Link = (usize, usize, ClassId, ClassId);

/// Removes nodes of degree 2 whose two edges have the same two sides and
/// run on one line (a probe's landing point, a tie with a class that owns
/// nothing there): one edge replaces the two.
fn merge_pass_through(nodes: Vec<Node>, edges: Vec<Traced>) -> (Vec<Node>, Vec<Link>) {
    let mut edges: Vec<Option<Traced>> = edges.into_iter().map(Some).collect();
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); nodes.len()];
    for (i, e) in edges.iter().enumerate() {
        let e = e.as_ref().expect("all live");
        at[e.from].push(i);
        at[e.to].push(i);
    }
    let mut dead = vec![false; nodes.len()];
    for v in 0..nodes.len() {
        if nodes[v].corner || at[v].len() != 2 || at[v][0] == at[v][1] {
            continue;
        }
        let (i, j) = (at[v][0], at[v][1]);
        let (Some(e1), Some(e2)) = (&edges[i], &edges[j]) else { continue };
        // Orient e1 into v and e2 out of v.
        let into = |e: &Traced| if e.to == v { (e.from, e.left, e.right) } else { (e.to, e.right, e.left) };
        let out = |e: &Traced| if e.from == v { (e.to, e.left, e.right) } else { (e.from, e.right, e.left) };
        let (a, l1, r1) = into(e1);
        let (b, l2, r2) = out(e2);
        if (l1, r1) != (l2, r2) || a == b || !e1.carrier.n.cross(&e2.carrier.n).is_zero() {
            continue;
        }
        let carrier = e1.carrier.clone();
        edges[j] = None;
        edges[i] = Some(Traced { from: a, to: b, left: l1, right: r1, carrier });
        for end in [a, b] {
            for slot in at[end].iter_mut() {
                if *slot == j {
                    *slot = i;
                }
            }
        }
        dead[v] = true;
    }
    let mut new_id = vec![usize::MAX; nodes.len()];
    let mut kept = Vec::new();
    for (v, n) in nodes.into_iter().enumerate() {
        if !dead[v] {
            new_id[v] = kept.len();
            kept.push(n);
        }
    }
    let edges = edges.into_iter().flatten().map(|e| (new_id[e.from], new_id[e.to], e.left, e.right)).collect();
    (kept, edges)
}

fn finish(pb: &Problem, nodes: Vec<Node>, edges: Vec<Link>) -> BallAxis {
    let mut degree = vec![0usize; nodes.len()];
    for &(a, b, _, _) in &edges {
        degree[a] += 1;
        degree[b] += 1;
    }
    let out_nodes = nodes
        .iter()
        .zip(&degree)
        .map(|(nd, &deg)| {
            let kind = if nd.corner {
                BallNodeKind::Corner
            } else if deg >= 3 {
                BallNodeKind::Branch
            } else if deg == 1 {
                BallNodeKind::Leaf
            } else if nd.vv {
                BallNodeKind::PseudoBranch
            } else {
                BallNodeKind::Joint
            };
            BallNode { at: nd.at, r: nd.r, kind, contacts: nd.tied.iter().map(|&c| pb.classes[c as usize]).collect() }
        })
        .collect();
    let k = pb.ball.len();
    let out_edges = edges
        .into_iter()
        .map(|(a, b, l, r)| {
            let (left, right) = (pb.classes[l as usize], pb.classes[r as usize]);
            BallEdge { from: a, to: b, left, right, jump: left.ball_neighbours(&right, k) }
        })
        .collect();
    BallAxis { nodes: out_nodes, edges: out_edges, ball: pb.ball.clone(), offsets: pb.offsets.clone() }
}
