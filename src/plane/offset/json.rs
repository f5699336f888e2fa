//! The offsets JSON format (a public contract, documented in README.md):
//!
//! ```text
//! {"offsets": [{"distance": d, "area": a,
//!               "loops": [[[x, y, bulge], ..], ..],
//!               "regions": [{"outer": i, "holes": [j, ..]}, ..]}, ..]}
//! ```
//!
//! One entry per distance, in the order asked for (negative distances are
//! outer offsets). Each loop is a closed bulge loop as in the shape JSON
//! (element `i` runs from vertex `i` to vertex `i + 1`, the last back to
//! the first), outer loops counter-clockwise and holes clockwise; `area` is
//! the offset region's area; `regions` index `loops`: each connected part
//! of the offset region is an outer loop and its holes. Numbers are written
//! in shortest round-trip form: reading them back gives the same `f64`s.

use crate::io::json::{loops_json, to_line};
use crate::plane::offset::layer::OffsetLayer;
use serde_json::{json, Value};

impl OffsetLayer {
    /// This layer as one entry of the `offsets` array (see the module docs).
    pub fn to_json_value(&self) -> Value {
        let regions: Vec<Value> = self.regions.iter().map(|r| json!({"outer": r.outer, "holes": r.holes})).collect();
        json!({
            "distance": self.distance,
            "area": self.area(),
            "loops": loops_json(&self.loops),
            "regions": regions,
        })
    }
}

/// The layers as offsets JSON (see the module docs), one line.
pub fn offsets_to_json(layers: &[OffsetLayer]) -> String {
    let layers: Vec<Value> = layers.iter().map(OffsetLayer::to_json_value).collect();
    to_line(&json!({ "offsets": layers }))
}
