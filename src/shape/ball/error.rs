//! Why a ball is refused.

use crate::io::ParseError;
use std::fmt;

/// A polygon that is not a unit ball: each names the vertex (an index
/// into the vertices as given) at fault.
#[derive(Debug, Clone, PartialEq)]
pub enum BallError {
    /// Fewer than three vertices.
    TooFewVertices {
        /// How many were given.
        count: usize,
    },
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// The vertex.
        vertex: usize,
    },
    /// A vertex repeats the one before it.
    Repeated {
        /// The vertex.
        vertex: usize,
    },
    /// A vertex lies on the line through its two neighbours (the polygon
    /// must be strictly convex: drop the vertex).
    Collinear {
        /// The vertex.
        vertex: usize,
    },
    /// The polygon turns the other way at this vertex, or winds round more
    /// than once: it is not convex.
    NotConvex {
        /// The vertex.
        vertex: usize,
    },
    /// The origin is on the edge from this vertex to the next, or outside
    /// the polygon beyond it: the ball must hold the origin strictly inside.
    OriginNotInside {
        /// The edge's first vertex.
        vertex: usize,
        /// True when the origin lies on the edge, false when beyond it.
        on_edge: bool,
    },
    /// The ball is too thin for `f64` distances (the origin within 1e-12
    /// of the ball's size from the edge that starts at this vertex), or
    /// this vertex's coordinates are outside ±1e100 or, unless zero,
    /// below 1e-100 in magnitude.
    IllConditioned {
        /// The vertex.
        vertex: usize,
    },
    /// A ball file that does not parse, or a ball description that names
    /// no ball.
    Parse(ParseError),
    /// A preset's parameter is out of range (a regular k-gon with k < 3 or
    /// k > 100 000, a non-finite rotation).
    InvalidArgument {
        /// What was wrong.
        what: String,
    },
    /// A space ball ([`Ball3`](super::Ball3)) needs at least four points.
    TooFewPoints {
        /// How many were given.
        count: usize,
    },
    /// A space ball's point has a NaN or infinite coordinate.
    NonFinitePoint {
        /// The point, as an index into the points given.
        point: usize,
    },
    /// All the points of a space ball lie on one plane (or one line, or
    /// are one point): their hull has no volume.
    Flat,
    /// The origin lies on facet `facet` of a space ball's hull, or outside
    /// the hull beyond that facet: it must be strictly inside.
    OriginNotInsideHull {
        /// The facet, as an index into the hull's facets.
        facet: usize,
        /// True when the origin lies on the facet's plane, false when
        /// beyond it.
        on_facet: bool,
    },
    /// The origin lies within 1e-12 of a space ball's size from the plane
    /// of this facet: `f64` distances divided by that height would carry
    /// no useful digits.
    ThinFacet {
        /// The facet.
        facet: usize,
    },
}

impl BallError {
    /// The vertex at fault, where the error names one.
    pub fn vertex(&self) -> Option<usize> {
        match *self {
            BallError::NonFinite { vertex }
            | BallError::NonFinitePoint { point: vertex }
            | BallError::Repeated { vertex }
            | BallError::Collinear { vertex }
            | BallError::NotConvex { vertex }
            | BallError::OriginNotInside { vertex, .. }
            | BallError::IllConditioned { vertex } => Some(vertex),
            BallError::TooFewVertices { .. } | BallError::InvalidArgument { .. } | BallError::Parse(_) => None,
            BallError::TooFewPoints { .. }
            | BallError::Flat
            | BallError::OriginNotInsideHull { .. }
            | BallError::ThinFacet { .. } => None,
        }
    }
}

impl fmt::Display for BallError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BallError::TooFewVertices { count } => {
                write!(f, "a ball needs at least 3 vertices, {count} given")
            }
            BallError::NonFinite { vertex } => write!(f, "ball vertex {vertex} has a NaN or infinite coordinate"),
            BallError::Repeated { vertex } => write!(f, "ball vertex {vertex} repeats the vertex before it"),
            BallError::Collinear { vertex } => {
                write!(f, "ball vertex {vertex} lies on the line through its neighbours (drop it)")
            }
            BallError::NotConvex { vertex } => write!(f, "the ball is not convex at vertex {vertex}"),
            BallError::OriginNotInside { vertex, on_edge: true } => {
                write!(f, "the origin lies on the ball's edge from vertex {vertex}; it must be strictly inside")
            }
            BallError::OriginNotInside { vertex, on_edge: false } => write!(
                f,
                "the origin lies outside the ball, beyond its edge from vertex {vertex}; it must be strictly inside"
            ),
            BallError::IllConditioned { vertex } => write!(
                f,
                "the ball is too thin or out of scale at vertex {vertex}: the origin lies within 1e-12 of the \
                 ball's size from its edge there, or a coordinate is beyond 1e100 or below 1e-100"
            ),
            BallError::InvalidArgument { what } => write!(f, "invalid ball: {what}"),
            BallError::Parse(e) => write!(f, "{e}"),
            BallError::TooFewPoints { count } => {
                write!(f, "a space ball needs at least 4 points, {count} given")
            }
            BallError::NonFinitePoint { point } => {
                write!(f, "ball point {point} has a NaN or infinite coordinate")
            }
            BallError::Flat => write!(f, "the ball's points all lie on one plane: their hull has no volume"),
            BallError::OriginNotInsideHull { facet, on_facet: true } => {
                write!(f, "the origin lies on facet {facet} of the ball; it must be strictly inside")
            }
            BallError::OriginNotInsideHull { facet, on_facet: false } => {
                write!(f, "the origin lies outside the ball, beyond its facet {facet}; it must be strictly inside")
            }
            BallError::ThinFacet { facet } => write!(
                f,
                "the ball is too thin at facet {facet}: the origin lies within 1e-12 of the ball's size from its plane"
            ),
        }
    }
}

impl std::error::Error for BallError {}
