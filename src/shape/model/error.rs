//! Why a shape was rejected. Every variant names the loop and element it
//! found at fault, in the caller's own indexing (before medax normalises
//! orientation), and a position where one makes sense.

use crate::io::ParseError;
use crate::kernel::Point;
use std::fmt;

/// An element of a shape: loop `loop_index` (0 = outer boundary, 1.. = holes,
/// in input order) and element `element` within it (element `i` runs from
/// vertex `i` to vertex `i + 1`, cyclically).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct ElementRef {
    /// Loop index in input order.
    pub loop_index: usize,
    /// Element index within the loop, in input order.
    pub element: usize,
}

impl fmt::Display for ElementRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "loop {} element {}", self.loop_index, self.element)
    }
}

/// How an element is degenerate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Degeneracy {
    /// Start and end closer than the tolerance.
    ZeroLength,
    /// The boundary turns back on itself at the element's start vertex
    /// (turning angle within the angular tolerance of ±180°).
    Cusp,
    /// The whole loop encloses (almost) no area.
    ZeroArea,
}

/// A shape that could not be built, with the element at fault.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeError {
    /// A file or string could not be parsed.
    Parse(ParseError),
    /// A file could not be read.
    Io {
        /// The path as given.
        path: String,
        /// The operating system's message.
        message: String,
    },
    /// The input holds no loop at all.
    Empty,
    /// A drawing holds no closed profile that makes a valid shape; what
    /// it held instead is in [`Drawing2d::ignored`](crate::shape::Drawing2d::ignored).
    NoProfile {
        /// How many things the drawing held that are in no shape.
        ignored: usize,
        /// The first of them, for a person.
        first: String,
    },
    /// A loop has fewer elements than a closed boundary needs (two arcs, or
    /// three segments).
    TooFewElements {
        /// The loop.
        loop_index: usize,
        /// How many elements it has.
        count: usize,
    },
    /// A coordinate or bulge is NaN or infinite.
    NonFinite {
        /// The element whose start vertex or bulge is not finite.
        at: ElementRef,
    },
    /// A coordinate (of a vertex, or of an arc's extent, or an arc radius)
    /// lies outside ±[`MAX_COORDINATE`](crate::shape::MAX_COORDINATE), or the whole
    /// shape is smaller than [`MIN_EXTENT`](crate::shape::MIN_EXTENT) (then `value`
    /// is its diagonal and the element is loop 0 element 0).
    OutOfRange {
        /// The element.
        at: ElementRef,
        /// The offending value.
        value: f64,
    },
    /// Loose elements could not be chained into a closed loop: the end of
    /// `at` is `gap` away from the nearest free start.
    NotClosed {
        /// The element whose end has no successor (indexing of the chained loop).
        at: ElementRef,
        /// Distance to the nearest candidate, model units.
        gap: f64,
        /// The dangling end point.
        position: Point,
    },
    /// An element is degenerate.
    Degenerate {
        /// The element.
        at: ElementRef,
        /// How.
        kind: Degeneracy,
        /// Where.
        position: Point,
    },
    /// Two elements cross, touch or come closer than the tolerance (within
    /// one loop: a self-intersection; across loops: loops touching).
    Intersection {
        /// The first element (the smaller reference).
        first: ElementRef,
        /// The second element.
        second: ElementRef,
        /// A point where they meet or come closest.
        position: Point,
    },
    /// An arc given by centre and end points whose end points are not the
    /// same distance from the centre (beyond the chaining tolerance).
    InconsistentArc {
        /// The element.
        at: ElementRef,
        /// Difference of the two radii, model units.
        deviation: f64,
    },
    /// A hole does not lie inside the outer loop.
    HoleOutside {
        /// The hole's loop index.
        hole: usize,
        /// A point of the hole outside the outer loop.
        position: Point,
    },
    /// A hole lies inside another hole.
    HoleInsideHole {
        /// The inner hole's loop index.
        hole: usize,
        /// The enclosing hole's loop index.
        container: usize,
        /// A point of the inner hole.
        position: Point,
    },
    /// The input uses something medax does not handle (yet), e.g. a Bézier
    /// curve or an elliptical arc.
    Unsupported {
        /// What, and where in the input.
        what: String,
    },
    /// An argument is invalid (e.g. a negative tolerance, a loop length that
    /// does not match the data).
    InvalidArgument {
        /// What was wrong.
        what: String,
    },
}

impl ShapeError {
    /// The loop the error is about (the first one of an intersection), when
    /// it names one.
    pub fn loop_index(&self) -> Option<usize> {
        use ShapeError::*;
        match self {
            TooFewElements { loop_index, .. } => Some(*loop_index),
            NonFinite { at }
            | OutOfRange { at, .. }
            | NotClosed { at, .. }
            | Degenerate { at, .. }
            | InconsistentArc { at, .. } => Some(at.loop_index),
            Intersection { first, .. } => Some(first.loop_index),
            HoleOutside { hole, .. } | HoleInsideHole { hole, .. } => Some(*hole),
            Parse(_) | Io { .. } | Empty | NoProfile { .. } | Unsupported { .. } | InvalidArgument { .. } => None,
        }
    }

    /// The element the error is about (the first one of an intersection;
    /// element 0 of a loop when it names only the loop).
    pub fn element(&self) -> Option<ElementRef> {
        use ShapeError::*;
        match self {
            NonFinite { at }
            | OutOfRange { at, .. }
            | NotClosed { at, .. }
            | Degenerate { at, .. }
            | InconsistentArc { at, .. } => Some(*at),
            Intersection { first, .. } => Some(*first),
            _ => self.loop_index().map(|loop_index| ElementRef { loop_index, element: 0 }),
        }
    }
}

impl fmt::Display for ShapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use ShapeError::*;
        match self {
            Parse(e) => write!(f, "{e}"),
            Io { path, message } => write!(f, "cannot read {path}: {message}"),
            Empty => write!(f, "the shape has no loops"),
            NoProfile { ignored, first } => {
                write!(f, "no closed profile in the drawing; {ignored} thing(s) in no shape, the first: {first}")
            }
            TooFewElements { loop_index, count } => {
                write!(f, "loop {loop_index} has {count} element(s); a closed loop needs at least 2 arcs or 3 segments")
            }
            NonFinite { at } => write!(f, "{at}: a coordinate or the bulge is NaN or infinite"),
            OutOfRange { at, value } => {
                write!(
                    f,
                    "{at}: value {value:e} is outside the supported range (coordinates and radii within ±{:e}, shape extent at least {:e})",
                    crate::shape::MAX_COORDINATE,
                    crate::shape::MIN_EXTENT
                )
            }
            NotClosed { at, gap, position } => write!(
                f,
                "{at}: the boundary is not closed; the end at ({}, {}) is {gap:e} from the nearest element",
                position.x, position.y
            ),
            Degenerate { at, kind, position } => {
                let what = match kind {
                    Degeneracy::ZeroLength => "zero-length element",
                    Degeneracy::Cusp => "the boundary turns back on itself (cusp) at the start vertex",
                    Degeneracy::ZeroArea => "the loop encloses no area",
                };
                write!(f, "{at}: {what} at ({}, {})", position.x, position.y)
            }
            Intersection { first, second, position } => {
                write!(f, "{first} and {second} intersect or touch at ({}, {})", position.x, position.y)
            }
            InconsistentArc { at, deviation } => {
                write!(f, "{at}: the arc's end points differ in distance from its centre by {deviation:e}")
            }
            HoleOutside { hole, position } => write!(
                f,
                "loop {hole} (a hole) is not inside the outer loop 0; its point ({}, {}) is outside",
                position.x, position.y
            ),
            HoleInsideHole { hole, container, position } => {
                write!(f, "loop {hole} (a hole) lies inside hole {container}, at ({}, {})", position.x, position.y)
            }
            Unsupported { what } => write!(f, "unsupported input: {what}"),
            InvalidArgument { what } => write!(f, "invalid argument: {what}"),
        }
    }
}

impl std::error::Error for ShapeError {}

impl From<ParseError> for ShapeError {
    fn from(e: ParseError) -> Self {
        ShapeError::Parse(e)
    }
}
