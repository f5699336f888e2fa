//! The Voronoi JSON formats (public contracts, documented in README.md).
//!
//! Sites in: `{"points": [[x, y], ..], "curves": [[[x, y, bulge], ..], ..],
//! "regions": [[[x, y, bulge], ..], ..], "boundary": [[x, y, bulge], ..]}`,
//! every key optional (no `boundary`: the library chooses the frame).
//!
//! Diagram out: the axis JSON's nodes and edges (see
//! [`crate::plane::axis::json`]) restricted to the sites' diagram, nodes renumbered
//! to those the kept edges use, plus:
//!
//! ```text
//! {"frame": "auto"|"given", "complete": bool,
//!  "nodes": [{.., "frontier": bool}, ..],
//!  "edges": [{.., "separates": [SITE, SITE], "self": bool}, ..],
//!  "regions": [{"site": SITE, "edges": [[edge, forward], ..],
//!               "self_edges": [edge, ..], "unbounded": bool}, ..]}
//! SITE = {"point": i} | {"curve": i} | {"region": i} | "boundary"
//! ```
//!
//! Edge indices in `regions` refer to the `edges` array; a region lists
//! only edges that were kept, in walk order: an unbounded region's walk
//! facing the library's frame, and self-edges left out with
//! `--no-self-edges`, leave gaps (the walk is then not closed).
//! `frontier` marks a node where an edge runs on to infinity beyond the
//! library's frame. Edge `sites` number loops as the shape does: loop 0
//! is the frame, then the regions, curves and points in order; an element
//! on a curve's way back names the curve element it runs over and carries
//! `"side": "back"`.

use crate::io::json::read_sites as read_raw_sites;
use crate::io::json::written;
use crate::io::{ParseError, RawVertex};
use crate::kernel::Point;
use crate::plane::axis::json::{conic, node_kind, SiteOut, BATCH};
use crate::plane::voronoi::{SiteId, Sites, VoronoiDiagram};
use crate::shape::Vertex;
use serde::Serialize;
use serde_json::{json, Value};

fn vertices(raw: Vec<RawVertex>) -> Vec<Vertex> {
    raw.into_iter().map(Vertex::from).collect()
}

/// Reads a sites file: the sites and the caller's outer boundary, if any.
pub fn read_sites(text: &str) -> Result<(Sites, Option<Vec<Vertex>>), ParseError> {
    let raw = read_raw_sites(text)?;
    let sites = Sites {
        points: raw.points.iter().map(|&[x, y]| Point::new(x, y)).collect(),
        curves: raw.curves.into_iter().map(vertices).collect(),
        regions: raw.regions.into_iter().map(vertices).collect(),
    };
    Ok((sites, raw.boundary.map(vertices)))
}

/// The shape the diagnosis tools (`examples/axis_debug`,
/// `examples/leaf_replay`) and tests work on, from a shape file
/// (`{"loops": ...}`) or a sites file, which becomes the shape its diagram
/// is computed on first ([`crate::plane::voronoi::first_shape`]): curves and
/// points are holes of zero area, which a shape file cannot express.
#[doc(hidden)]
pub fn shape_or_sites(text: &str) -> Result<crate::shape::Shape2d, String> {
    use crate::shape::{Shape2d, ShapeOptions};
    if let Ok(shape) = Shape2d::from_json_str(text, &ShapeOptions::default()) {
        return Ok(shape);
    }
    let (sites, boundary) = read_sites(text).map_err(|e| e.to_string())?;
    let opts = crate::plane::voronoi::VoronoiOptions { boundary, ..Default::default() };
    crate::plane::voronoi::first_shape(&sites, &opts).map_err(|e| e.to_string())
}

/// A site as JSON.
pub fn site_id_json(s: SiteId) -> Value {
    match s {
        SiteId::Point(i) => json!({ "point": i }),
        SiteId::Curve(i) => json!({ "curve": i }),
        SiteId::Region(i) => json!({ "region": i }),
        SiteId::Frame => json!("boundary"),
    }
}

/// A diagram edge as written (sorted keys, as a `Value` map writes them).
#[derive(Serialize)]
struct EdgeOut {
    from: usize,
    kind: &'static str,
    samples: Vec<[f64; 3]>,
    #[serde(rename = "self")]
    self_edge: bool,
    separates: [Value; 2],
    sites: [SiteOut; 2],
    to: usize,
}

#[derive(Serialize)]
struct NodeOut {
    frontier: bool,
    kind: &'static str,
    r: f64,
    x: f64,
    y: f64,
}

#[derive(Serialize)]
struct RegionOut {
    edges: Vec<(usize, bool)>,
    self_edges: Vec<usize>,
    site: Value,
    unbounded: bool,
}

impl VoronoiDiagram {
    /// The diagram as JSON (format in the module docs), edges sampled to
    /// chordal tolerance `tol` (model units); self-edges kept when
    /// `self_edges`: [`write_json`](Self::write_json) into a string.
    pub fn to_json(&self, tol: f64, self_edges: bool) -> String {
        written(|w| self.write_json(tol, self_edges, w))
    }

    /// Writes the diagram as JSON (format in the module docs) to `out`, an
    /// edge at a time: memory stays a batch of samples besides the
    /// diagram (as one document the text of 2·10^4 points' diagram, 24 MB,
    /// took 0.66 GB). Buffer `out`; the errors are `out`'s.
    pub fn write_json(&self, tol: f64, self_edges: bool, mut out: impl std::io::Write) -> std::io::Result<()> {
        use rayon::prelude::*;
        let shape = self.shape();
        let kept = self.diagram_edges(self_edges);
        // Nodes numbered in the order the kept edges first use them.
        let mut node_index = vec![usize::MAX; self.axis.nodes.len()];
        let mut order = Vec::new();
        let mut edge_index = vec![usize::MAX; self.axis.edges.len()];
        for (k, &i) in kept.iter().enumerate() {
            edge_index[i] = k;
            let e = &self.axis.edges[i];
            for v in [e.from, e.to] {
                if node_index[v] == usize::MAX {
                    node_index[v] = order.len();
                    order.push(v);
                }
            }
        }
        write!(out, "{{\"complete\":{},\"edges\":[", self.complete)?;
        for (b, batch) in kept.chunks(BATCH).enumerate() {
            let samples: Vec<_> =
                batch.par_iter().map(|&i| self.axis.edges[i].sample(shape, &self.axis.nodes, tol)).collect();
            for (k, (&i, s)) in batch.iter().zip(samples).enumerate() {
                let (e, v) = (&self.axis.edges[i], &self.edges[i]);
                let edge = EdgeOut {
                    from: node_index[e.from],
                    kind: conic(e.kind),
                    samples: s.iter().map(|d| [d.center.x, d.center.y, d.radius]).collect(),
                    self_edge: v.self_edge,
                    separates: [site_id_json(v.sides[0]), site_id_json(v.sides[1])],
                    sites: [SiteOut::of(shape, e.sites[0]), SiteOut::of(shape, e.sites[1])],
                    to: node_index[e.to],
                };
                if b + k > 0 {
                    out.write_all(b",")?;
                }
                serde_json::to_writer(&mut out, &edge)?;
            }
        }
        let frame = if self.auto_frame { "auto" } else { "given" };
        write!(out, "],\"frame\":\"{frame}\",\"nodes\":[")?;
        for (k, &v) in order.iter().enumerate() {
            let n = &self.axis.nodes[v];
            let node = NodeOut {
                frontier: self.frontier[v],
                kind: node_kind(n.kind),
                r: n.radius,
                x: n.point.x,
                y: n.point.y,
            };
            if k > 0 {
                out.write_all(b",")?;
            }
            serde_json::to_writer(&mut out, &node)?;
        }
        out.write_all(b"],\"regions\":[")?;
        for (k, r) in self.regions.iter().enumerate() {
            let region = RegionOut {
                edges: r
                    .boundary
                    .iter()
                    .filter(|(i, _)| edge_index[*i] != usize::MAX)
                    .map(|&(i, fwd)| (edge_index[i], fwd))
                    .collect(),
                self_edges: r.self_edges.iter().map(|&i| edge_index[i]).filter(|&i| i != usize::MAX).collect(),
                site: site_id_json(r.site),
                unbounded: r.unbounded,
            };
            if k > 0 {
                out.write_all(b",")?;
            }
            serde_json::to_writer(&mut out, &region)?;
        }
        out.write_all(b"]}\n")?;
        out.flush()
    }
}
