//! The medial axis under a polygon ball as a graph of straight edges.

use super::classes::{ContactClass, ShapeFeature};
use crate::kernel::Point;
use crate::shape::Ball2;

/// What a node of the axis is (thesis 3.1.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BallNodeKind {
    /// Three or more edges: a ball with three or more contacts.
    Branch,
    /// Two edges, and a ball vertex sits on a shape vertex (a VV contact):
    /// where a pruned convex corner or a reflex vertex's class change meets
    /// the axis (Definition 3.2.1).
    PseudoBranch,
    /// A convex corner of the shape (radius 0).
    Corner,
    /// Two edges, a contact class changes without a VV contact.
    Joint,
    /// One edge ending away from the boundary (not expected for polygons).
    Leaf,
}

/// A node: its centre, the ball radius there, its kind and the classes in
/// contact.
#[derive(Debug, Clone, PartialEq)]
pub struct BallNode {
    /// Centre, model units (rounded from the exact rational point).
    pub at: Point,
    /// The radius r of the maximal* ball `at + r·B` (model units per ball unit).
    pub r: f64,
    /// Branch, pseudo-branch, corner, joint or leaf.
    pub kind: BallNodeKind,
    /// Every contact class of the ball here.
    pub contacts: Vec<ContactClass>,
}

/// A straight edge between two nodes, with the contact classes on its two
/// sides (left and right walking from `from` to `to`).
#[derive(Debug, Clone, PartialEq)]
pub struct BallEdge {
    /// Start node (index into [`BallAxis::nodes`]).
    pub from: usize,
    /// End node.
    pub to: usize,
    /// The class owning the side on the left, walking from `from` to `to`.
    pub left: ContactClass,
    /// The class on the right.
    pub right: ContactClass,
    /// The two classes neighbour on ∂B (a jump edge, Observation 10): the
    /// maximal* balls on it are not maximal inscribed.
    pub jump: bool,
}

/// The medial axis of a polygon under a polygon ball (thesis 3.2):
/// the centres of maximal* balls (Definition 3.1.5), straight edges
/// between nodes whose coordinates were computed exactly.
#[derive(Debug, Clone)]
pub struct BallAxis {
    /// Nodes.
    pub nodes: Vec<BallNode>,
    /// Straight edges.
    pub edges: Vec<BallEdge>,
    /// The ball it was computed for.
    pub ball: Ball2,
    /// Loop `l` holds the global vertices and edges `offsets[l]..offsets[l + 1]`.
    pub(crate) offsets: Vec<usize>,
}

impl BallAxis {
    /// `(loop, index)` of a shape feature in the shape's normalised loops
    /// (outer counter-clockwise, holes clockwise; [`crate::shape::Shape2d::loops`]).
    pub fn locate(&self, f: ShapeFeature) -> (usize, usize) {
        let g = match f {
            ShapeFeature::Edge(i) | ShapeFeature::Vertex(i) => i as usize,
        };
        let l = self.offsets.partition_point(|&o| o <= g) - 1;
        (l, g - self.offsets[l])
    }

    /// Counts of nodes by kind: (branch, pseudo-branch, corner, joint, leaf).
    pub fn kind_counts(&self) -> [usize; 5] {
        let mut c = [0; 5];
        for n in &self.nodes {
            c[n.kind as usize] += 1;
        }
        c
    }

    /// Number of jump edges.
    pub fn jump_count(&self) -> usize {
        self.edges.iter().filter(|e| e.jump).count()
    }
}
