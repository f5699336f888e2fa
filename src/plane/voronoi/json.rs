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
use crate::io::{ParseError, RawVertex};
use crate::kernel::Point;
use crate::plane::axis::json::{conic, node_kind, site_json};
use crate::plane::voronoi::{SiteId, Sites, VoronoiDiagram};
use crate::shape::Vertex;
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

impl VoronoiDiagram {
    /// The diagram as JSON (format in the module docs), edges sampled to
    /// chordal tolerance `tol` (model units); self-edges kept when
    /// `self_edges`.
    pub fn to_json(&self, tol: f64, self_edges: bool) -> String {
        let shape = self.shape();
        let kept = self.diagram_edges(self_edges);
        let mut node_index = vec![usize::MAX; self.axis.nodes.len()];
        let mut nodes = Vec::new();
        let mut number = |v: usize, nodes: &mut Vec<Value>| {
            if node_index[v] == usize::MAX {
                node_index[v] = nodes.len();
                let n = &self.axis.nodes[v];
                nodes.push(json!({"x": n.point.x, "y": n.point.y, "r": n.radius,
                    "kind": node_kind(n.kind), "frontier": self.frontier[v]}));
            }
            node_index[v]
        };
        let mut edge_index = vec![usize::MAX; self.axis.edges.len()];
        let mut edges = Vec::with_capacity(kept.len());
        for &i in &kept {
            let e = &self.axis.edges[i];
            let v = &self.edges[i];
            let (from, to) = (number(e.from, &mut nodes), number(e.to, &mut nodes));
            edge_index[i] = edges.len();
            let samples = e.sample(shape, &self.axis.nodes, tol);
            edges.push(json!({
                "from": from,
                "to": to,
                "kind": conic(e.kind),
                "sites": [site_json(shape, e.sites[0]), site_json(shape, e.sites[1])],
                "separates": [site_id_json(v.sides[0]), site_id_json(v.sides[1])],
                "self": v.self_edge,
                "samples": samples.iter().map(|d| [d.center.x, d.center.y, d.radius]).collect::<Vec<_>>(),
            }));
        }
        let regions: Vec<Value> = self
            .regions
            .iter()
            .map(|r| {
                let walk: Vec<Value> = r
                    .boundary
                    .iter()
                    .filter(|(i, _)| edge_index[*i] != usize::MAX)
                    .map(|&(i, fwd)| json!([edge_index[i], fwd]))
                    .collect();
                let selfs: Vec<usize> =
                    r.self_edges.iter().map(|&i| edge_index[i]).filter(|&i| i != usize::MAX).collect();
                json!({"site": site_id_json(r.site), "edges": walk, "self_edges": selfs, "unbounded": r.unbounded})
            })
            .collect();
        let frame = if self.auto_frame { "auto" } else { "given" };
        let doc =
            json!({"frame": frame, "complete": self.complete, "nodes": nodes, "edges": edges, "regions": regions});
        crate::io::json::to_line(&doc)
    }
}
