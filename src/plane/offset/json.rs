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

use crate::io::json::written;
use crate::plane::offset::layer::OffsetLayer;
use crate::shape::Vertex;
use serde::Serialize;
use serde_json::Value;

impl OffsetLayer {
    /// This layer as one entry of the `offsets` array (see the module docs).
    pub fn to_json_value(&self) -> Value {
        serde_json::to_value(LayerOut::of(self)).unwrap_or(Value::Null)
    }
}

/// The layers as offsets JSON (see the module docs), one line:
/// [`write_offsets_json`] into a string.
pub fn offsets_to_json(layers: &[OffsetLayer]) -> String {
    written(|w| write_offsets_json(layers, w))
}

/// Writes the layers as offsets JSON (see the module docs) to `out`,
/// straight from the layers (no intermediate document: the offsets of a
/// curve of 10^6 arcs at three distances are about 0.2 GB of text). Buffer
/// `out`; the errors are `out`'s.
pub fn write_offsets_json(layers: &[OffsetLayer], mut out: impl std::io::Write) -> std::io::Result<()> {
    let doc = DocOut { offsets: layers.iter().map(LayerOut::of).collect() };
    serde_json::to_writer(&mut out, &doc)?;
    out.write_all(b"\n")?;
    out.flush()
}

/// The document as written; keys in sorted order, as a `Value` map writes
/// them, so that the text is what the format always was.
#[derive(Serialize)]
struct DocOut<'a> {
    offsets: Vec<LayerOut<'a>>,
}

#[derive(Serialize)]
pub(crate) struct LayerOut<'a> {
    area: f64,
    distance: f64,
    loops: Vec<LoopOut<'a>>,
    regions: Vec<RegionOut<'a>>,
}

impl<'a> LayerOut<'a> {
    pub(crate) fn of(l: &'a OffsetLayer) -> LayerOut<'a> {
        LayerOut {
            area: l.area(),
            distance: l.distance,
            loops: l.loops.iter().map(|lp| LoopOut(&lp.vertices)).collect(),
            regions: l.regions.iter().map(|r| RegionOut { holes: &r.holes, outer: r.outer }).collect(),
        }
    }
}

#[derive(Serialize)]
struct RegionOut<'a> {
    holes: &'a [usize],
    outer: usize,
}

/// A loop as `[[x, y, bulge], ..]`, written vertex by vertex.
pub(crate) struct LoopOut<'a>(pub(crate) &'a [Vertex]);

impl Serialize for LoopOut<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0.iter().map(|v| [v.p.x, v.p.y, v.bulge]))
    }
}
