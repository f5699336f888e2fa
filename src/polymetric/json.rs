//! The axis JSON under a polygon ball: the Euclidean axis's contract
//! (README.md, "Axis JSON") with what a polygon ball adds.
//!
//! ```text
//! {"ball": {"vertices": [[x, y], ..]},
//!  "edges": [{"from": i, "to": j, "kind": "line", "jump": true|false,
//!             "sites": [{"loop": l, "element": k, "class": "VE"|"EE", "ball_vertex"|"ball_edge": b}
//!                      | {"loop": l, "vertex": v, "class": "EV", "ball_edge": b}, ..],
//!             "samples": [[x, y, r], [x, y, r]]}, ..],
//!  "nodes": [{"x": .., "y": .., "r": .., "kind": "branch"|"pseudo_branch"|"corner"|"joint"|"leaf"}, ..]}
//! ```
//!
//! Every edge is straight and the ball radius is affine along it, so its
//! two end samples are the whole edge. `sites[0]` is the class on the
//! left walking from `from` to `to`. Shape features use the caller's loop,
//! element and vertex numbering; ball features index `ball.vertices`
//! (counter-clockwise, as written here, whatever order the ball was given
//! in).

use super::classes::{ClassKind, ContactClass, ShapeFeature};
use super::graph::{BallAxis, BallNodeKind};
use crate::io::json::written;
use crate::shape::{Feature, Shape2d};
use serde::Serialize;

/// A node kind as written.
pub(crate) fn node_kind(k: BallNodeKind) -> &'static str {
    match k {
        BallNodeKind::Branch => "branch",
        BallNodeKind::PseudoBranch => "pseudo_branch",
        BallNodeKind::Corner => "corner",
        BallNodeKind::Joint => "joint",
        BallNodeKind::Leaf => "leaf",
    }
}

/// A contact class as written (sorted keys, as the Euclidean sites).
#[derive(Serialize)]
struct SiteOut {
    #[serde(skip_serializing_if = "Option::is_none")]
    ball_edge: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ball_vertex: Option<usize>,
    class: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    element: Option<usize>,
    #[serde(rename = "loop")]
    loop_index: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    vertex: Option<usize>,
}

#[derive(Serialize)]
struct EdgeOut {
    from: usize,
    jump: bool,
    kind: &'static str,
    samples: [[f64; 3]; 2],
    sites: [SiteOut; 2],
    to: usize,
}

#[derive(Serialize)]
struct NodeOut {
    kind: &'static str,
    r: f64,
    x: f64,
    y: f64,
}

impl BallAxis {
    /// A contact class in the caller's numbering.
    fn site_out(&self, shape: &Shape2d, c: &ContactClass) -> SiteOut {
        let (l, i) = self.locate(c.shape);
        let (element, vertex) = match c.shape {
            ShapeFeature::Edge(_) => (Some(shape.input_element_index(l, i)), None),
            ShapeFeature::Vertex(_) => (None, Some(shape.input_vertex_index(l, i))),
        };
        let (ball_vertex, ball_edge) = match c.ball {
            Feature::Vertex(b) => (Some(b), None),
            Feature::Edge(b) => (None, Some(b)),
        };
        let class = match c.kind {
            ClassKind::VE => "VE",
            ClassKind::EV => "EV",
            ClassKind::EE => "EE",
        };
        SiteOut { ball_edge, ball_vertex, class, element, loop_index: l, vertex }
    }

    /// The axis as JSON ([`write_json`](Self::write_json) into a string).
    pub fn to_json(&self, shape: &Shape2d) -> String {
        written(|w| self.write_json(shape, w))
    }

    /// Writes the axis as JSON to `out`, an edge at a time; `shape` is the
    /// one it was computed for (for the caller's numbering). Buffer `out`;
    /// the errors are `out`'s.
    pub fn write_json(&self, shape: &Shape2d, mut out: impl std::io::Write) -> std::io::Result<()> {
        out.write_all(b"{\"ball\":{\"vertices\":")?;
        let ball: Vec<[f64; 2]> = self.ball.vertices().iter().map(|p| [p.x, p.y]).collect();
        serde_json::to_writer(&mut out, &ball)?;
        out.write_all(b"},\"edges\":[")?;
        for (k, e) in self.edges.iter().enumerate() {
            let (a, b) = (&self.nodes[e.from], &self.nodes[e.to]);
            let v = EdgeOut {
                from: e.from,
                jump: e.jump,
                kind: "line",
                samples: [[a.at.x, a.at.y, a.r], [b.at.x, b.at.y, b.r]],
                sites: [self.site_out(shape, &e.left), self.site_out(shape, &e.right)],
                to: e.to,
            };
            if k > 0 {
                out.write_all(b",")?;
            }
            serde_json::to_writer(&mut out, &v)?;
        }
        out.write_all(b"],\"nodes\":[")?;
        for (i, n) in self.nodes.iter().enumerate() {
            if i > 0 {
                out.write_all(b",")?;
            }
            serde_json::to_writer(&mut out, &NodeOut { kind: node_kind(n.kind), r: n.r, x: n.at.x, y: n.at.y })?;
        }
        out.write_all(b"]}\n")?;
        out.flush()
    }
}
