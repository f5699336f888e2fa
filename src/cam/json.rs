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
//! rings (see `plane::offsets_to_json`), cut at `max_depth`.

use super::pocket::{Pocket, UncutKind};
use super::vcarve::VCarve;
use crate::io::json::written;
use crate::plane::offset::json::{LayerOut, LoopOut};
use serde::Serialize;

/// The pocket document as written: keys in sorted order, as a
/// `serde_json::Value` map writes them, so the text is what the format
/// always was.
#[derive(Serialize)]
struct PocketOut<'a> {
    order: &'a [usize],
    rings: Vec<RingOut<'a>>,
    truncated: bool,
    uncut: Vec<UncutOut<'a>>,
}

#[derive(Serialize)]
struct RingOut<'a> {
    children: &'a [usize],
    distance: f64,
    level: usize,
    loops: Vec<LoopOut<'a>>,
    parent: Option<usize>,
}

#[derive(Serialize)]
struct UncutOut<'a> {
    area: f64,
    kind: &'static str,
    loops: Vec<LoopOut<'a>>,
}

#[derive(Serialize)]
struct VCarveOut<'a> {
    angle_deg: f64,
    flat: LayerOut<'a>,
    flat_radius: f64,
    max_depth: f64,
    paths: Vec<&'a [[f64; 3]]>,
}

impl Pocket {
    /// The pocket as JSON (see the module docs).
    pub fn to_json(&self) -> String {
        written(|w| self.write_json(w))
    }

    /// Writes the pocket as JSON (see the module docs) to `out`, straight
    /// from the rings (a pocket of a curve of 10^5 arcs at 123 levels is
    /// 0.58 GB of text: built as one document it took 3.5 GB and 17 s).
    /// Buffer `out`; the errors are `out`'s.
    pub fn write_json(&self, mut out: impl std::io::Write) -> std::io::Result<()> {
        let doc = PocketOut {
            order: &self.order,
            rings: self
                .rings
                .iter()
                .map(|r| RingOut {
                    children: &r.children,
                    distance: r.distance,
                    level: r.level,
                    loops: r.loops.iter().map(|l| LoopOut(&l.vertices)).collect(),
                    parent: r.parent,
                })
                .collect(),
            truncated: self.truncated,
            uncut: self
                .uncut
                .iter()
                .map(|u| UncutOut {
                    area: u.area,
                    kind: match u.kind {
                        UncutKind::Scallop => "scallop",
                        UncutKind::Wall => "wall",
                    },
                    loops: u.loops.iter().map(|l| LoopOut(l)).collect(),
                })
                .collect(),
        };
        serde_json::to_writer(&mut out, &doc)?;
        out.write_all(b"\n")?;
        out.flush()
    }
}

impl VCarve {
    /// The V-carve paths as JSON (see the module docs).
    pub fn to_json(&self) -> String {
        written(|w| self.write_json(w))
    }

    /// Writes the V-carve paths as JSON (see the module docs) to `out`,
    /// straight from the paths. Buffer `out`; the errors are `out`'s.
    pub fn write_json(&self, mut out: impl std::io::Write) -> std::io::Result<()> {
        let doc = VCarveOut {
            angle_deg: self.opts.angle_deg,
            flat: LayerOut::of(&self.flat),
            flat_radius: self.flat_radius(),
            max_depth: self.opts.max_depth,
            paths: self.paths.iter().map(|p| p.points.as_slice()).collect(),
        };
        serde_json::to_writer(&mut out, &doc)?;
        out.write_all(b"\n")?;
        out.flush()
    }
}
