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

/// Edges sampled and written per batch of this many: the samples of one
/// batch are all that is held besides the output (a whole axis of 10^6
/// edges as one `Value` tree took 16 GB).
const BATCH: usize = 4096;

impl MedialAxis2d {
    /// The axis as JSON, edges sampled to chordal tolerance `tol` (model
    /// units). Written an edge at a time (keys in sorted order, as a
    /// `serde_json::Value` map writes them), so memory stays about the
    /// size of the text.
    pub fn to_json(&self, shape: &Shape2d, tol: f64) -> String {
        use rayon::prelude::*;
        let mut out = String::from("{\"edges\":[");
        for (b, batch) in self.edges.chunks(BATCH).enumerate() {
            let samples: Vec<_> = batch.par_iter().map(|e| e.sample(shape, &self.nodes, tol)).collect();
            for (k, (e, s)) in batch.iter().zip(samples).enumerate() {
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
                if b + k > 0 {
                    out.push(',');
                }
                out.push_str(&serde_json::to_string(&v).unwrap_or_default());
            }
        }
        out.push_str("],\"nodes\":[");
        for (i, n) in self.nodes.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let v = json!({"x": n.point.x, "y": n.point.y, "r": n.radius, "kind": node_kind(n.kind)});
            out.push_str(&serde_json::to_string(&v).unwrap_or_default());
        }
        out.push_str("]}\n");
        out
    }
}

#[cfg(test)]
mod tests {
    use crate::plane::{medial_axis, AxisOptions};
    use crate::shape::{samples, Shape2d, ShapeOptions};

    #[test]
    fn batched_writing_gives_one_document_of_every_edge_and_node() {
        // More edges than one batch, so that batches join with commas.
        let shape = Shape2d::from_bulge_loops(samples::star_polygon(3000, 2), &ShapeOptions::default()).unwrap();
        let axis = medial_axis(&shape, &AxisOptions::default()).unwrap();
        assert!(axis.edges.len() > super::BATCH);
        let text = axis.to_json(&shape, 1e-3);
        assert!(text.ends_with("]}\n") && !text[..text.len() - 1].contains('\n'));
        let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        let (edges, nodes) = (doc["edges"].as_array().unwrap(), doc["nodes"].as_array().unwrap());
        assert_eq!((edges.len(), nodes.len()), (axis.edges.len(), axis.nodes.len()));
        for (e, v) in axis.edges.iter().zip(edges) {
            assert_eq!((v["from"].as_u64(), v["to"].as_u64()), (Some(e.from as u64), Some(e.to as u64)));
            assert!(v["samples"].as_array().unwrap().len() >= 2);
        }
        assert_eq!(nodes[7]["r"].as_f64(), Some(axis.nodes[7].radius));
    }
}
