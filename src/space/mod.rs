//! Chapter 3 in space: the medial axis of triangulated solids under
//! polyhedral unit balls, by contact arrangements (thesis 3.3; issue 20).
//! Built on the solids, the space balls and their exact ball queries of
//! `shape` (the core shared with the plane's `polymetric`).
//!
//! * [`classes`]: the contact classes a solid and a ball can form (which
//!   ball feature can touch which surface feature of an inscribed ball),
//!   decided exactly from the normal cones.

pub mod classes;

pub use classes::{contact_classes, ContactClass, ContactClasses};
