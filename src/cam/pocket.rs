//! Pocketing: offset rings at ρ_k = r + k·s for a tool of radius r and a
//! stepover s, until nothing is left, as a tree in machining order, with the
//! area the tool leaves uncut.

use super::uncut::band_regions;
use super::CamError;
use crate::plane::{OffsetLoop, Offsets};
use crate::shape::Vertex;

/// In which order the rings of a pocket are machined.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PocketOrder {
    /// Every ring after the rings inside it (children first): the tool
    /// starts at the centre of each pocket and works outwards, so the last
    /// pass is the finishing pass along the wall.
    #[default]
    InsideOut,
    /// Every ring before the rings inside it: from the wall inwards.
    OutsideIn,
}

/// Options for [`pocket`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PocketOptions {
    /// Tool radius r, model units, > 0: the first ring is the offset at r.
    pub tool_radius: f64,
    /// Stepover s between rings, model units, > 0 (usually at most 2r).
    pub stepover: f64,
    /// Machining order of [`Pocket::order`].
    pub order: PocketOrder,
    /// At most this many levels; beyond it the pocket is cut short (a guard
    /// against a tiny stepover), default 100 000.
    pub max_levels: usize,
}

impl PocketOptions {
    /// Options for tool radius `r` and stepover `s`, inside-out.
    pub fn new(tool_radius: f64, stepover: f64) -> PocketOptions {
        PocketOptions { tool_radius, stepover, order: PocketOrder::InsideOut, max_levels: 100_000 }
    }

    /// Checks every option's range: the tool radius and the stepover
    /// finite and > 0, at least one level. [`pocket`] calls it first.
    pub fn check(&self) -> Result<(), CamError> {
        const POSITIVE: &str = "a finite number > 0";
        let positive = |name, value: f64| {
            if value.is_finite() && value > 0.0 {
                Ok(())
            } else {
                Err(CamError::BadOption { name, value, expected: POSITIVE })
            }
        };
        positive("tool_radius", self.tool_radius)?;
        positive("stepover", self.stepover)?;
        if self.max_levels == 0 {
            return Err(CamError::BadOption { name: "max_levels", value: 0.0, expected: "at least 1" });
        }
        Ok(())
    }
}

/// One ring: the boundary of one connected region of the offset at one
/// level, which the tool centre follows.
#[derive(Debug, Clone, PartialEq)]
pub struct PocketRing {
    /// Level k (0 for the ring at the tool radius).
    pub level: usize,
    /// Offset distance ρ_k = r + k·s, model units.
    pub distance: f64,
    /// The outer loop first (counter-clockwise), then its holes (clockwise).
    pub loops: Vec<OffsetLoop>,
    /// The ring of level k − 1 that encloses this one.
    pub parent: Option<usize>,
    /// The rings of level k + 1 inside this one.
    pub children: Vec<usize>,
}

/// Why some material stays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UncutKind {
    /// Between rings: the stepover left a cusp the tool did not reach.
    Scallop,
    /// Along the wall: corners and necks narrower than the tool.
    Wall,
}

/// A region the tool does not cut: an outer loop and its holes.
#[derive(Debug, Clone, PartialEq)]
pub struct UncutRegion {
    /// Why it is left.
    pub kind: UncutKind,
    /// Outer loop first (counter-clockwise), then holes (clockwise).
    pub loops: Vec<Vec<Vertex>>,
    /// Area, square model units.
    pub area: f64,
}

/// The rings of a pocket.
#[derive(Debug, Clone, PartialEq)]
pub struct Pocket {
    /// Every ring, level by level.
    pub rings: Vec<PocketRing>,
    /// Indices into `rings` in machining order.
    pub order: Vec<usize>,
    /// The area left uncut.
    pub uncut: Vec<UncutRegion>,
    /// Whether [`PocketOptions::max_levels`] cut the pocket short.
    pub truncated: bool,
}

impl Pocket {
    /// The total area left uncut, square model units (0, not −0, when
    /// nothing is left).
    pub fn uncut_area(&self) -> f64 {
        self.uncut.iter().fold(0.0, |a, u| a + u.area)
    }

    /// Number of levels: the deepest ring's level + 1 (0 without rings).
    pub fn level_count(&self) -> usize {
        self.rings.iter().map(|r| r.level + 1).max().unwrap_or(0)
    }
}

/// The pocket of the prepared shape for the options: the offsets at
/// r, r + s, r + 2s, … while anything is left, each connected region of
/// each level one ring, nested under the ring of the level before that
/// encloses it (found on the medial axis, not by geometry: a region's
/// anchor piece of axis lies in exactly one region of every shallower
/// level).
pub fn pocket(offsets: &Offsets, opts: &PocketOptions) -> Result<Pocket, CamError> {
    opts.check()?;
    let deepest = offsets.max_inner_distance();
    let mut distances = Vec::new();
    while distances.len() < opts.max_levels {
        let d = opts.tool_radius + distances.len() as f64 * opts.stepover;
        if d >= deepest {
            break;
        }
        distances.push(d);
    }
    let truncated = opts.tool_radius + distances.len() as f64 * opts.stepover < deepest;
    let layers = offsets.layers(&distances)?;
    let mut rings: Vec<PocketRing> = Vec::new();
    // First ring of each level, to turn a layer's region index into a ring.
    let mut level_start = Vec::with_capacity(layers.len());
    for (k, layer) in layers.iter().enumerate() {
        level_start.push(rings.len());
        for r in 0..layer.regions.len() {
            let loops = layer.region_loops(r);
            let parent = if k == 0 {
                None
            } else {
                let up = layers[k - 1].region_enclosing(layer, r).ok_or(CamError::Offset(
                    crate::plane::OffsetError::Topology {
                        distance: layer.distance,
                        what: "a ring has no enclosing ring",
                    },
                ))?;
                Some(level_start[k - 1] + up)
            };
            rings.push(PocketRing { level: k, distance: layer.distance, loops, parent, children: Vec::new() });
        }
    }
    for i in 0..rings.len() {
        if let Some(p) = rings[i].parent {
            rings[p].children.push(i);
        }
    }
    let order = machining_order(&rings, opts.order);
    let uncut = uncut_regions(offsets, opts, &distances, deepest)?;
    Ok(Pocket { rings, order, uncut, truncated })
}

/// The wall's uncut band, the scallops between rings (only when the
/// stepover exceeds the tool radius) and what is left inside the last ring.
fn uncut_regions(
    offsets: &Offsets,
    opts: &PocketOptions,
    distances: &[f64],
    deepest: f64,
) -> Result<Vec<UncutRegion>, CamError> {
    let (r, tol) = (opts.tool_radius, offsets.tolerance());
    let trimmer = &offsets.inner;
    let mut out = band_regions(trimmer, 0.0, r, r, UncutKind::Wall, tol)?;
    if opts.stepover > r {
        for w in distances.windows(2) {
            out.extend(band_regions(trimmer, w[0] + r, w[1], r, UncutKind::Scallop, tol)?);
        }
    }
    if let Some(&last) = distances.last() {
        if last + r < deepest {
            let layer = offsets.layer(last + r)?;
            for r in 0..layer.regions.len() {
                let loops = layer.region_loops(r);
                let area = loops.iter().map(|l| l.area).sum();
                let loops = loops.into_iter().map(|l| l.vertices).collect();
                out.push(UncutRegion { kind: UncutKind::Scallop, loops, area });
            }
        }
    }
    Ok(out)
}

/// Depth-first over the ring tree from the level-0 rings: children before
/// their parent (inside-out) or after it (outside-in).
fn machining_order(rings: &[PocketRing], order: PocketOrder) -> Vec<usize> {
    let mut out = Vec::with_capacity(rings.len());
    // (ring, children done) on an explicit stack: trees can be deep.
    let mut stack: Vec<(usize, bool)> =
        rings.iter().enumerate().rev().filter(|(_, r)| r.parent.is_none()).map(|(i, _)| (i, false)).collect();
    while let Some((i, expanded)) = stack.pop() {
        if expanded {
            out.push(i);
            continue;
        }
        if order == PocketOrder::OutsideIn {
            out.push(i);
        } else {
            stack.push((i, true));
        }
        stack.extend(rings[i].children.iter().rev().map(|&c| (c, false)));
    }
    out
}
