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

use crate::io::json::written;
use crate::kernel::bisector::ConicKind;
use crate::plane::axis::{MedialAxis2d, NodeKind, Primitive};
use crate::shape::Shape2d;
use serde::Serialize;
use serde_json::Value;

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

/// A site in the caller's numbering (the `sites` entries of the axis
/// JSON, as a value).
pub fn site_json(shape: &Shape2d, p: Primitive) -> Value {
    serde_json::to_value(SiteOut::of(shape, p)).unwrap_or(Value::Null)
}

/// Edges sampled and written per batch of this many: the samples of one
/// batch are all that is held besides the output (a whole axis of 10^6
/// edges as one `Value` tree took 16 GB).
pub(crate) const BATCH: usize = 4096;

/// A site as written: keys in sorted order, as a `Value` map writes them.
#[derive(Serialize)]
pub(crate) struct SiteOut {
    #[serde(skip_serializing_if = "Option::is_none")]
    element: Option<usize>,
    #[serde(rename = "loop")]
    loop_index: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    side: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    vertex: Option<usize>,
}

impl SiteOut {
    pub(crate) fn of(shape: &Shape2d, p: Primitive) -> SiteOut {
        let (loop_index, i) = (p.loop_index(), p.index());
        match p {
            Primitive::Element { .. } => SiteOut {
                element: Some(shape.input_element_index(loop_index, i)),
                loop_index,
                side: shape.on_way_back(loop_index, i).then_some("back"),
                vertex: None,
            },
            Primitive::Vertex { .. } => {
                SiteOut { element: None, loop_index, side: None, vertex: Some(shape.input_vertex_index(loop_index, i)) }
            }
        }
    }
}

/// An edge as written (sorted keys; `straight` only where it holds: a
/// straight segment standing for the conic across a hugged band, see
/// `AxisEdge::straight`).
#[derive(Serialize)]
struct EdgeOut {
    from: usize,
    kind: &'static str,
    samples: Vec<[f64; 3]>,
    sites: [SiteOut; 2],
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    straight: bool,
    to: usize,
}

/// A node as written (sorted keys).
#[derive(Serialize)]
struct NodeOut {
    kind: &'static str,
    r: f64,
    x: f64,
    y: f64,
}

impl MedialAxis2d {
    /// The axis as JSON, edges sampled to chordal tolerance `tol` (model
    /// units): [`write_json`](Self::write_json) into a string.
    pub fn to_json(&self, shape: &Shape2d, tol: f64) -> String {
        written(|w| self.write_json(shape, tol, w))
    }

    /// Writes the axis as JSON to `out`, edges sampled to chordal
    /// tolerance `tol` (model units), an edge at a time: memory stays a
    /// batch of samples whatever the axis's size (the text of an axis of
    /// 10^6 arcs is about 0.75 GB). Buffer `out` (a `BufWriter` for a
    /// file); the errors are `out`'s.
    pub fn write_json(&self, shape: &Shape2d, tol: f64, mut out: impl std::io::Write) -> std::io::Result<()> {
        use rayon::prelude::*;
        out.write_all(b"{\"edges\":[")?;
        for (b, batch) in self.edges.chunks(BATCH).enumerate() {
            let samples: Vec<_> = batch.par_iter().map(|e| e.sample(shape, &self.nodes, tol)).collect();
            for (k, (e, s)) in batch.iter().zip(samples).enumerate() {
                let v = EdgeOut {
                    from: e.from,
                    kind: conic(e.kind),
                    samples: s.iter().map(|d| [d.center.x, d.center.y, d.radius]).collect(),
                    sites: [SiteOut::of(shape, e.sites[0]), SiteOut::of(shape, e.sites[1])],
                    straight: e.straight,
                    to: e.to,
                };
                if b + k > 0 {
                    out.write_all(b",")?;
                }
                serde_json::to_writer(&mut out, &v)?;
            }
        }
        out.write_all(b"],\"nodes\":[")?;
        for (i, n) in self.nodes.iter().enumerate() {
            if i > 0 {
                out.write_all(b",")?;
            }
            let v = NodeOut { kind: node_kind(n.kind), r: n.radius, x: n.point.x, y: n.point.y };
            serde_json::to_writer(&mut out, &v)?;
        }
        out.write_all(b"]}\n")?;
        out.flush()
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
        // Streamed text is what a `Value` tree of the same document writes
        // (sorted keys, shortest round-trip numbers): the format did not
        // change when the writer stopped building the tree.
        assert_eq!(text, crate::io::json::to_line(&doc));
    }
}
