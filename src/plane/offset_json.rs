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

use super::offset::OffsetLayer;
use crate::shape::Vertex;
use serde_json::{json, Value};

/// Closed bulge loops as `[[[x, y, bulge], ..], ..]`.
pub fn loops_json<'a>(loops: impl IntoIterator<Item = &'a [Vertex]>) -> Value {
    loops.into_iter().map(|l| l.iter().map(|v| [v.p.x, v.p.y, v.bulge]).collect::<Vec<_>>()).collect()
}

impl OffsetLayer {
    /// This layer as one entry of the `offsets` array (see the module docs).
    pub fn to_json_value(&self) -> Value {
        let regions: Vec<Value> = self.regions.iter().map(|r| json!({"outer": r.outer, "holes": r.holes})).collect();
        json!({
            "distance": self.distance,
            "area": self.area(),
            "loops": loops_json(self.loops.iter().map(|l| l.vertices.as_slice())),
            "regions": regions,
        })
    }
}

/// The layers as offsets JSON (see the module docs), one line.
pub fn offsets_to_json(layers: &[OffsetLayer]) -> String {
    let layers: Vec<Value> = layers.iter().map(OffsetLayer::to_json_value).collect();
    let mut out = serde_json::to_string(&json!({ "offsets": layers })).unwrap_or_default();
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;

    #[test]
    fn loop_numbers_read_back_bit_for_bit() {
        let v = |x: f64, y: f64, bulge: f64| Vertex { p: Point::new(x, y), bulge };
        let a = vec![v(0.1, 1.0 / 3.0, 0.0), v(2.0e-300, 7.25, -0.41421356237309503), v(1e9, -5.0, 1.7)];
        let b = vec![v(-1.0, 0.0, 1.0), v(1.0, 0.0, 1.0)];
        let text = serde_json::to_string(&loops_json([a.as_slice(), b.as_slice()])).unwrap();
        let back: Vec<Vec<[f64; 3]>> = serde_json::from_str(&text).unwrap();
        let flat = |l: &[Vertex]| l.iter().map(|v| [v.p.x, v.p.y, v.bulge]).collect::<Vec<_>>();
        assert_eq!(back, vec![flat(&a), flat(&b)]);
        assert_eq!(loops_json(std::iter::empty()), json!([]));
    }
}
