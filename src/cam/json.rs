//! The pocket and V-carve JSON formats (public contracts, documented in
//! README.md):
//!
//! ```text
//! pocket:  {"rings": [{"level": k, "distance": d, "loops": LOOPS,
//!                      "parent": i | null, "children": [j, ..]}, ..],
//!           "order": [i, ..], "truncated": bool,
//!           "uncut": [{"kind": "scallop" | "wall", "area": a, "loops": LOOPS}, ..]}
//! v-carve: {"angle_deg": a, "max_depth": h | null, "flat_radius": r,
//!           "paths": [[[x, y, depth], ..], ..],
//!           "flat": {"distance": r, "area": a, "loops": LOOPS, "regions": [..]}}
//! LOOPS = [[[x, y, bulge], ..], ..]   (closed; outer counter-clockwise, holes clockwise)
//! ```
//!
//! Ring indices (`parent`, `children`, `order`) index `rings`; a ring's
//! outer loop comes first, then its holes. `order` is the machining order.
//! V-carve depths are measured down from the surface (≥ 0); `max_depth` is
//! null when uncapped; `flat` is the offsets JSON entry of the flat bottom's
//! rings (see [`crate::plane::offset_json`]), cut at `max_depth`.

use super::pocket::{Pocket, UncutKind};
use super::vcarve::VCarve;
use crate::io::json::{loops_json, to_line};
use serde_json::{json, Value};

impl Pocket {
    /// The pocket as JSON (see the module docs).
    pub fn to_json(&self) -> String {
        let rings: Vec<Value> = self
            .rings
            .iter()
            .map(|r| {
                json!({
                    "level": r.level,
                    "distance": r.distance,
                    "loops": loops_json(&r.loops),
                    "parent": r.parent,
                    "children": r.children,
                })
            })
            .collect();
        let uncut: Vec<Value> = self
            .uncut
            .iter()
            .map(|u| {
                let kind = match u.kind {
                    UncutKind::Scallop => "scallop",
                    UncutKind::Wall => "wall",
                };
                json!({"kind": kind, "area": u.area, "loops": loops_json(&u.loops)})
            })
            .collect();
        to_line(&json!({"rings": rings, "order": self.order, "truncated": self.truncated, "uncut": uncut}))
    }
}

impl VCarve {
    /// The V-carve paths as JSON (see the module docs).
    pub fn to_json(&self) -> String {
        let paths: Vec<&[[f64; 3]]> = self.paths.iter().map(|p| p.points.as_slice()).collect();
        to_line(&json!({
            "angle_deg": self.opts.angle_deg,
            "max_depth": self.opts.max_depth,
            "flat_radius": self.flat_radius(),
            "paths": paths,
            "flat": self.flat.to_json_value(),
        }))
    }
}
