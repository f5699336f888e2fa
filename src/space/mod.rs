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
//! * [`domain`]: a contact domain's plane, with coordinates in which its
//!   points are taken exactly.
//! * [`along`]: the contact arrangement along a segment of a contact
//!   domain (the opposite classes piece by piece, and where they
//!   change: ties, handovers, flat continuations, jumps).
//! * [`arrangement`]: the contact arrangement of a convex region of a
//!   domain (a VF class's face), cut by projection lines into cells of one
//!   opposite class each.
//! * [`edge_domain`]: the contact domain of an EE class (between its
//!   reflex edge and the VE balls' polygonal line) and its arrangement.
//! * [`corner_domain`]: the contact domain of an FV class (a ball facet
//!   on a vertex, between its sides and the EV balls' polygonal line) and
//!   its arrangement.
//! * [`draw`]: an SVG picture of an axis over its solid's outline.
//! * [`axis`]: the medial axis of a solid assembled from its domains'
//!   arrangements, a triangle mesh of sheets with radii.

pub mod along;
pub mod arrangement;
pub mod axis;
pub mod classes;
pub mod corner_domain;
pub mod domain;
pub mod draw;
pub mod edge_domain;
pub mod radius;

pub use along::{opposite_along, opposite_along_in, Along, AlongChange, AlongError, AlongPiece, ChangeKind, Opposite};
pub use arrangement::{domain_arrangement, face_arrangement, Cell, FaceArrangement};
pub use axis::{medial_axis_3d, medial_axis_3d_watched, Axis3, Axis3Error, Sheet3, Watch};
pub use classes::{contact_classes, ContactClass, ContactClasses};
pub use corner_domain::{corner_arrangement, CornerArrangement, CornerSector};
pub use domain::{DomainPlane, Line2};
pub use draw::{axis3d_svg, radius_rgb};
pub use edge_domain::{edge_arrangement, EdgeArrangement};
pub use radius::{radius_fn, Affine3, RadiusFn};
