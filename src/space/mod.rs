//! Chapter 3 in space: the medial axis of triangulated solids under
//! polyhedral unit balls, by contact arrangements (thesis 3.3; issue 20).
//! Built on the solids, the space balls and their exact ball queries of
//! `shape` (the core shared with the plane's `polymetric`).
//!
//! * [`classes`]: the contact classes a solid and a ball can form (which
//!   ball feature can touch which surface feature of an inscribed ball),
//!   decided exactly from the normal cones.
//! * [`radius`]: the radius at which a maximal* ball anchored at a point
//!   of a contact domain reaches a given class: affine in the point, on
//!   the convex region where that contact holds.
//! * [`along`]: the contact arrangement of a VF class along a segment of
//!   its domain (the opposite classes piece by piece, and where they
//!   change: ties, handovers, flat continuations, jumps).
//! * [`arrangement`]: the contact arrangement of a VF class, its face cut
//!   by projection lines into cells of one opposite class each.
//! * [`axis`]: the medial axis of a convex solid assembled from its faces'
//!   arrangements, a triangle mesh of sheets with radii.

pub mod along;
pub mod arrangement;
pub mod axis;
pub mod classes;
pub mod radius;

pub use along::{opposite_along, Along, AlongChange, AlongError, AlongPiece, ChangeKind, Opposite};
pub use arrangement::{face_arrangement, Cell, FaceArrangement};
pub use axis::{medial_axis_3d, Axis3, Axis3Error, Sheet3};
pub use classes::{contact_classes, ContactClass, ContactClasses};
pub use radius::{radius_fn, Affine3, RadiusFn};
