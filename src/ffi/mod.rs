//! The C ABI. Thin by design: convert C arguments, validate them, call the
//! Rust API, convert the result. No geometry lives here.
//!
//! Conventions (every export follows them):
//! * fallible functions return [`mx_status`]; `MX_OK` = 0;
//! * out-parameters are written only on success;
//! * failures record a thread-local message and [`mx_error_info`];
//! * no panic crosses the boundary (it becomes `MX_ERR_PANIC`);
//! * `_free(NULL)` is a no-op; const handles may be shared between threads.
//!
//! This is the only module allowed `unsafe` code.

#![allow(non_camel_case_types, reason = "C names: the `mx_` prefix and snake_case, as in include/medax.h")]

mod axis;
mod axis3d;
mod ball;
mod ball3;
mod ball_axis;
mod ball_voronoi;
mod boundary;
mod drawing;
mod drawing_report;
mod handles;
mod last_error;
mod mesh3d;
mod mesh3d_contacts;
mod mesh3d_maximal;
mod mesh3d_query;
mod mesh3d_ray;
mod offset;
mod pocket;
mod shape2d;
mod shape_kinds;
mod status;
mod vcarve;
mod version;
mod voronoi;

pub use axis::*;
pub use axis3d::*;
pub use ball::*;
pub use ball3::*;
pub use ball_axis::*;
pub use ball_voronoi::mx_voronoi_compute_with_ball;
pub use drawing::*;
pub use drawing_report::*;
pub use last_error::*;
pub use mesh3d::*;
pub use mesh3d_contacts::*;
pub use mesh3d_maximal::*;
pub use mesh3d_query::*;
pub use mesh3d_ray::*;
pub use offset::*;
pub use pocket::*;
pub use shape2d::*;
pub use shape_kinds::*;
pub use status::*;
pub use vcarve::*;
pub use version::*;
pub use voronoi::*;
