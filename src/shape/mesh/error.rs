//! Why a solid was rejected. Every variant names the vertex, face or edge
//! at fault in the caller's own indexing (vertices and faces as the file or
//! the arrays gave them, before welding and triangulation) and, for faces,
//! where in the file they came from.

use crate::io::mesh::MeshParseError;
use std::fmt;

/// Where a face came from: a 1-based line of a text file, or its record
/// number in a binary file or in the caller's arrays.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct FaceRef {
    /// The face's index in input order (0-based).
    pub face: usize,
    /// Its 1-based line in a text file; 0 where there is none.
    pub line: usize,
}

impl fmt::Display for FaceRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "face {}", self.face)?;
        if self.line > 0 {
            write!(f, " (line {})", self.line)?;
        }
        Ok(())
    }
}

/// A solid that could not be built, with what is at fault.
#[derive(Debug, Clone, PartialEq)]
pub enum MeshError {
    /// The file could not be parsed.
    Parse(MeshParseError),
    /// A file could not be read.
    Io {
        /// The path as given.
        path: String,
        /// The operating system's message.
        message: String,
    },
    /// No face at all.
    Empty,
    /// A vertex coordinate is NaN or infinite.
    NonFinite {
        /// The vertex, input index.
        vertex: usize,
    },
    /// A vertex lies outside ±[`crate::shape::MAX_COORDINATE`].
    TooLarge {
        /// The vertex, input index.
        vertex: usize,
    },
    /// A face names a vertex that does not exist (arrays from the caller).
    IndexOutOfRange {
        /// The face.
        face: FaceRef,
        /// The index it holds.
        index: u64,
        /// How many vertices there are.
        vertex_count: usize,
    },
    /// A face of fewer than three distinct vertices, or whose vertices lie
    /// on one line (exactly): it encloses no area.
    DegenerateFace {
        /// The face.
        face: FaceRef,
    },
    /// An edge with one face only: the surface has a hole there and bounds
    /// no solid.
    OpenEdge {
        /// Its two vertices (input indices).
        edge: [usize; 2],
        /// The one face along it.
        face: FaceRef,
    },
    /// An edge shared by more than two faces.
    NonManifoldEdge {
        /// Its two vertices (input indices).
        edge: [usize; 2],
        /// How many faces share it.
        faces: usize,
        /// One of them.
        face: FaceRef,
    },
    /// A vertex whose faces form more than one fan (two solids touching at
    /// a point, or a surface pinched there).
    NonManifoldVertex {
        /// The vertex (input index).
        vertex: usize,
        /// How many separate fans meet there.
        fans: usize,
    },
    /// No orientation of the faces is consistent (a Möbius-like surface).
    NonOrientable {
        /// A face where the orientations conflict.
        face: FaceRef,
    },
    /// Two faces cross or touch away from the edges and vertices they
    /// share (within one component, or two components meeting).
    SelfIntersection {
        /// The two faces.
        faces: [FaceRef; 2],
    },
    /// A closed surface that encloses no volume.
    FlatComponent {
        /// The component (in [`super::Mesh3d::components`] order).
        component: usize,
        /// One of its faces.
        face: FaceRef,
    },
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshError::Parse(e) => write!(f, "{e}"),
            MeshError::Io { path, message } => write!(f, "cannot read {path}: {message}"),
            MeshError::Empty => write!(f, "the mesh has no face"),
            MeshError::NonFinite { vertex } => write!(f, "vertex {vertex} has a NaN or infinite coordinate"),
            MeshError::TooLarge { vertex } => {
                write!(f, "vertex {vertex} lies outside ±{:e} model units", crate::shape::MAX_COORDINATE)
            }
            MeshError::IndexOutOfRange { face, index, vertex_count } => {
                write!(f, "{face} names vertex {index}, but there are {vertex_count} vertices")
            }
            MeshError::DegenerateFace { face } => {
                write!(f, "{face} encloses no area (repeated vertices, or all on one line)")
            }
            MeshError::OpenEdge { edge, face } => write!(
                f,
                "the edge from vertex {} to vertex {} has only {face} along it: the surface is open there",
                edge[0], edge[1]
            ),
            MeshError::NonManifoldEdge { edge, faces, face } => write!(
                f,
                "the edge from vertex {} to vertex {} is shared by {faces} faces ({face} among them): not a manifold",
                edge[0], edge[1]
            ),
            MeshError::NonManifoldVertex { vertex, fans } => {
                write!(f, "vertex {vertex} joins {fans} separate fans of faces: not a manifold")
            }
            MeshError::NonOrientable { face } => {
                write!(f, "the faces cannot be oriented consistently (conflict at {face})")
            }
            MeshError::SelfIntersection { faces } => {
                write!(f, "{} and {} cross or touch: the surface intersects itself", faces[0], faces[1])
            }
            MeshError::FlatComponent { component, face } => {
                write!(f, "component {component} ({face} among its faces) encloses no volume")
            }
        }
    }
}

impl std::error::Error for MeshError {}

impl From<MeshParseError> for MeshError {
    fn from(e: MeshParseError) -> Self {
        MeshError::Parse(e)
    }
}
