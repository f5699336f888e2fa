//! The axis JSON format (a public contract, documented in README.md):
//!
//! ```text
//! {"nodes": [{"x": .., "y": .., "r": .., "kind": "branch"|"corner"|"leaf"|"joint"}, ..],
//!  "edges": [{"from": i, "to": j, "kind": "line"|"parabola"|"ellipse"|"hyperbola",
//!             "sites": [{"loop": l, "element": k} | {"loop": l, "vertex": v}, ..],
//!             "samples": [[x, y, r], ..]}, ..]}
//! ```
//!
//! Sites use the caller's loop, element and vertex numbering (before
//! orientation was normalised). Samples run from `from` to `to`, start and
//! end at the nodes, and deviate from the true edge by at most the
//! tolerance passed to [`MedialAxis2d::to_json`].

use crate::kernel::bisector::ConicKind;
use crate::plane::axis::{MedialAxis2d, NodeKind, Primitive};
use crate::shape::Shape2d;
use serde_json::{json, Value};

pub(crate) fn node_kind(k: NodeKind) -> &'static str {
    match k {
        NodeKind::Branch => "branch",
        NodeKind::Corner => "corner",
        NodeKind::Leaf => "leaf",
        NodeKind::Joint => "joint",
    }
}

pub(crate) fn conic(k: ConicKind) -> &'static str {
    match k {
        ConicKind::Line => "line",
        ConicKind::Parabola => "parabola",
        ConicKind::Ellipse => "ellipse",
        ConicKind::Hyperbola => "hyperbola",
    }
}

/// A site in the caller's numbering.
pub fn site_json(shape: &Shape2d, p: Primitive) -> Value {
    match p {
        Primitive::Element(r) => {
            let e = shape.input_element_index(r.loop_index, r.element);
            if shape.on_way_back(r.loop_index, r.element) {
                json!({"loop": r.loop_index, "element": e, "side": "back"})
            } else {
                json!({"loop": r.loop_index, "element": e})
            }
        }
        Primitive::Vertex { loop_index, vertex } => {
            json!({"loop": loop_index, "vertex": shape.input_vertex_index(loop_index, vertex)})
        }
    }
}

impl MedialAxis2d {
    /// The axis as JSON, edges sampled to chordal tolerance `tol` (model units).
    pub fn to_json(&self, shape: &Shape2d, tol: f64) -> String {
        let nodes: Vec<Value> = self
            .nodes
            .iter()
            .map(|n| json!({"x": n.point.x, "y": n.point.y, "r": n.radius, "kind": node_kind(n.kind)}))
            .collect();
        let samples = self.sampled(shape, tol);
        let edges: Vec<Value> = self
            .edges
            .iter()
            .zip(samples)
            .map(|(e, s)| {
                let mut v = json!({
                    "from": e.from,
                    "to": e.to,
                    "kind": conic(e.kind),
                    "sites": [site_json(shape, e.sites[0]), site_json(shape, e.sites[1])],
                    "samples": s.iter().map(|d| [d.center.x, d.center.y, d.radius]).collect::<Vec<_>>(),
                });
                // Only where it holds: a straight segment standing for
                // the conic across a hugged band (see `AxisEdge::straight`).
                if e.straight {
                    v["straight"] = Value::Bool(true);
                }
                v
            })
            .collect();
        crate::io::json::to_line(&json!({"nodes": nodes, "edges": edges}))
    }
}
