//! Block references: the entities of a BLOCK placed where each INSERT
//! (or MINSERT array) puts them, nested blocks included, with scale,
//! rotation and mirroring.

use crate::io::{RawArc, RawCircle, RawDrawing, RawLine, RawPolyline, RawSkipped};
use std::collections::HashMap;

/// Block references deeper than this are reported, not expanded (a block
/// that refers to itself would never end).
const MAX_DEPTH: usize = 16;

/// Curves placed by all block references of one file at most: a MINSERT
/// of a million rows of a large block is reported beyond it, not expanded.
const MAX_PLACED: usize = 20_000_000;

/// An INSERT record: which block, and where, in the units of the block's
/// parent (the drawing, or the block holding the INSERT).
#[derive(Debug, Clone)]
pub(crate) struct Insert {
    pub name: String,
    pub at: [f64; 2],
    pub scale: [f64; 2],
    pub rotation_deg: f64,
    /// MINSERT array: columns, rows and their spacing (1, 1 for INSERT).
    pub columns: u32,
    pub rows: u32,
    pub spacing: [f64; 2],
    /// Extrusion (0, 0, −1): x of the placed entities is negated.
    pub mirror: bool,
    pub source: usize,
    pub layer: u32,
    /// Group 62 as written, resolved for top-level INSERTs.
    pub colour: i16,
    pub handle: u64,
}

/// The colour of entities that name none, or name "by block" outside a
/// block: 7 (white on dark screens, black on paper).
pub(crate) const DEFAULT_COLOUR: i16 = 7;

/// How colours as written (group 62) become colours 1–255.
pub(crate) struct Colours<'a> {
    /// Each layer's colour.
    pub layers: &'a [i16],
    /// The colour "by block" (0) stands for: that of the block reference.
    pub by_block: i16,
}

impl Colours<'_> {
    /// Colour `c` as written, of an entity on `layer`.
    pub fn of(&self, c: i16, layer: u32) -> i16 {
        match c {
            0 => self.by_block,
            256 => self.layers.get(layer as usize).copied().unwrap_or(DEFAULT_COLOUR),
            1..=255 => c,
            _ => DEFAULT_COLOUR,
        }
    }

    /// Resolves the colours of every entity of `d` (the drawing's own:
    /// block copies are resolved as they are placed).
    pub fn resolve_all(&self, d: &mut RawDrawing) {
        for l in &mut d.lines {
            l.colour = self.of(l.colour, l.layer);
        }
        for a in &mut d.arcs {
            a.colour = self.of(a.colour, a.layer);
        }
        for c in &mut d.circles {
            c.colour = self.of(c.colour, c.layer);
        }
        for p in &mut d.polylines {
            p.colour = self.of(p.colour, p.layer);
        }
        for e in &mut d.skipped {
            e.colour = self.of(e.colour, e.layer);
        }
    }
}

/// A BLOCK definition: its base point and what it holds.
#[derive(Debug, Clone, Default)]
pub(crate) struct Block {
    pub base: [f64; 2],
    pub drawing: RawDrawing,
    pub inserts: Vec<Insert>,
}

/// x ↦ m·x + t.
#[derive(Debug, Clone, Copy)]
struct Affine {
    m: [[f64; 2]; 2],
    t: [f64; 2],
}

impl Affine {
    const IDENTITY: Affine = Affine { m: [[1.0, 0.0], [0.0, 1.0]], t: [0.0, 0.0] };

    fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        [self.m[0][0] * p[0] + self.m[0][1] * p[1] + self.t[0], self.m[1][0] * p[0] + self.m[1][1] * p[1] + self.t[1]]
    }

    /// `self` after `inner`: x ↦ self(inner(x)).
    fn after(&self, inner: &Affine) -> Affine {
        let (a, b) = (&self.m, &inner.m);
        let m = [
            [a[0][0] * b[0][0] + a[0][1] * b[1][0], a[0][0] * b[0][1] + a[0][1] * b[1][1]],
            [a[1][0] * b[0][0] + a[1][1] * b[1][0], a[1][0] * b[0][1] + a[1][1] * b[1][1]],
        ];
        Affine { m, t: self.apply(inner.t) }
    }

    fn det(&self) -> f64 {
        self.m[0][0] * self.m[1][1] - self.m[0][1] * self.m[1][0]
    }

    /// The scale factor when the map is a similarity (circles stay
    /// circles), within a relative 1e-9.
    fn similarity(&self) -> Option<f64> {
        let [[a, b], [c, d]] = self.m;
        let (sx, sy) = (a.hypot(c), b.hypot(d));
        let ortho = a * b + c * d;
        ((sx - sy).abs() <= 1e-9 * sx.max(sy) && ortho.abs() <= 1e-9 * sx * sy && sx > 0.0).then_some(sx)
    }

    /// Where one copy of `ins` (array cell `col`, `row`) puts the points
    /// of a block with base point `base`.
    fn of_insert(ins: &Insert, base: [f64; 2], col: u32, row: u32) -> Affine {
        let (s, c) = ins.rotation_deg.to_radians().sin_cos();
        let rot = [[c, -s], [s, c]];
        let m = [
            [rot[0][0] * ins.scale[0], rot[0][1] * ins.scale[1]],
            [rot[1][0] * ins.scale[0], rot[1][1] * ins.scale[1]],
        ];
        let cell = [col as f64 * ins.spacing[0], row as f64 * ins.spacing[1]];
        let offset = [rot[0][0] * cell[0] + rot[0][1] * cell[1], rot[1][0] * cell[0] + rot[1][1] * cell[1]];
        let placed = Affine { m, t: [0.0, 0.0] };
        let b = placed.apply(base);
        let a = Affine { m, t: [ins.at[0] + offset[0] - b[0], ins.at[1] + offset[1] - b[1]] };
        if ins.mirror {
            Affine { m: [[-1.0, 0.0], [0.0, 1.0]], t: [0.0, 0.0] }.after(&a)
        } else {
            a
        }
    }
}

/// What expanding needs besides the blocks.
struct Placing<'a> {
    blocks: &'a HashMap<String, Block>,
    /// The layer index of "0": entities on it take their INSERT's layer.
    zero: Option<u32>,
    layer_colours: &'a [i16],
    placed: usize,
    /// The expansion limit was reached (and reported once).
    full: bool,
}

/// What a block reference hands down to what it places: the top-level
/// INSERT's line and handle (the thing a user can pick in a CAD program),
/// and its own layer and resolved colour.
#[derive(Clone, Copy)]
struct Placer {
    source: usize,
    handle: u64,
    layer: u32,
    colour: i16,
}

/// Adds to `out` the entities of the blocks `inserts` refer to, placed,
/// each with the INSERT's line and handle, layer 0 and colour "by block"
/// taking the INSERT's; a reference to a missing block, one nested too
/// deep, a curve that an uneven scale would turn into an ellipse and
/// everything beyond the expansion limit are added to `out.skipped`.
/// `inserts` have their colours resolved; `layer_colours` are the
/// layers' colours.
pub(crate) fn expand(out: &mut RawDrawing, inserts: &[Insert], blocks: &HashMap<String, Block>, layer_colours: &[i16]) {
    let zero = out.layers.iter().position(|l| l == "0").map(|i| i as u32);
    let mut p = Placing { blocks, zero, layer_colours, placed: 0, full: false };
    let mut path = Vec::new();
    for ins in inserts {
        let by = Placer { source: ins.source, handle: ins.handle, layer: ins.layer, colour: ins.colour };
        place(out, &mut p, ins, &Affine::IDENTITY, by, &mut path);
    }
}

fn place(out: &mut RawDrawing, p: &mut Placing, ins: &Insert, outer: &Affine, by: Placer, path: &mut Vec<String>) {
    let skip = |out: &mut RawDrawing, why: String| {
        out.skipped.push(RawSkipped {
            entity: why,
            layer: by.layer,
            colour: by.colour,
            handle: by.handle,
            position: Some(outer.apply(ins.at)),
            source: by.source,
        });
    };
    if p.full {
        return;
    }
    let Some(block) = p.blocks.get(&ins.name) else {
        return skip(out, format!("INSERT of block {} (no such block)", ins.name));
    };
    if path.len() >= MAX_DEPTH || path.contains(&ins.name) {
        return skip(out, format!("INSERT of block {} (nested too deep, or in itself)", ins.name));
    }
    path.push(ins.name.clone());
    let zero = p.zero;
    let of = |l: u32| if Some(l) == zero { by.layer } else { l };
    let colours = Colours { layers: p.layer_colours, by_block: by.colour };
    for col in 0..ins.columns {
        for row in 0..ins.rows {
            if p.placed >= MAX_PLACED || p.full {
                if !p.full {
                    p.full = true;
                    skip(
                        out,
                        format!(
                            "INSERT of block {} (beyond {MAX_PLACED} placed curves: the rest not placed)",
                            ins.name
                        ),
                    );
                }
                path.pop();
                return;
            }
            let a = outer.after(&Affine::of_insert(ins, block.base, col, row));
            // A cell counts even when its block is empty: an array of
            // nothing must end too.
            p.placed += copy(out, &block.drawing, &a, by, &of, &colours).max(1);
            for inner in &block.inserts {
                let layer = of(inner.layer);
                let inner_by = Placer { layer, colour: colours.of(inner.colour, layer), ..by };
                place(out, p, inner, &a, inner_by, path);
            }
        }
    }
    path.pop();
}

/// Copies the curves of `d` through `a` into `out`; returns how many.
fn copy(
    out: &mut RawDrawing,
    d: &RawDrawing,
    a: &Affine,
    by: Placer,
    of: &impl Fn(u32) -> u32,
    colours: &Colours,
) -> usize {
    let flip = a.det() < 0.0;
    let similar = a.similarity();
    let (source, handle) = (by.source, by.handle);
    let uneven = |out: &mut RawDrawing, what: &str, at: [f64; 2]| {
        let entity = format!("{what} in a block scaled unevenly (an ellipse)");
        let (layer, colour) = (by.layer, by.colour);
        out.skipped.push(RawSkipped { entity, layer, colour, handle, position: Some(a.apply(at)), source });
    };
    for l in &d.lines {
        let (layer, colour) = (of(l.layer), colours.of(l.colour, of(l.layer)));
        out.lines.push(RawLine { a: a.apply(l.a), b: a.apply(l.b), source, layer, colour, handle });
    }
    for pl in &d.polylines {
        if similar.is_none() && pl.vertices.iter().any(|v| v.bulge != 0.0) {
            uneven(out, "POLYLINE with arcs", pl.vertices.first().map_or([0.0, 0.0], |v| [v.x, v.y]));
            continue;
        }
        let vertices = pl
            .vertices
            .iter()
            .map(|v| {
                let [x, y] = a.apply([v.x, v.y]);
                crate::io::RawVertex { x, y, bulge: if flip { -v.bulge } else { v.bulge } }
            })
            .collect();
        let (layer, colour) = (of(pl.layer), colours.of(pl.colour, of(pl.layer)));
        out.polylines.push(RawPolyline { vertices, closed: pl.closed, source, layer, colour, handle });
    }
    for c in &d.circles {
        match similar {
            Some(s) => out.circles.push(RawCircle {
                center: a.apply(c.center),
                radius: c.radius * s,
                source,
                layer: of(c.layer),
                colour: colours.of(c.colour, of(c.layer)),
                handle,
            }),
            None => uneven(out, "CIRCLE", c.center),
        }
    }
    for arc in &d.arcs {
        let Some(s) = similar else {
            uneven(out, "ARC", arc.center);
            continue;
        };
        let on = |deg: f64| {
            let (sin, cos) = deg.to_radians().sin_cos();
            a.apply([arc.center[0] + arc.radius * cos, arc.center[1] + arc.radius * sin])
        };
        let center = a.apply(arc.center);
        let angle = |q: [f64; 2]| (q[1] - center[1]).atan2(q[0] - center[0]).to_degrees();
        let from = angle(on(arc.start_deg));
        // A whole circle drawn as an ARC stays whole (rounding would
        // leave it a hair short of or past 360°).
        let to =
            if (arc.end_deg - arc.start_deg).rem_euclid(360.0) == 0.0 { from + 360.0 } else { angle(on(arc.end_deg)) };
        // A mirror turns the arc round: counter-clockwise from the old end.
        let (start_deg, end_deg) = if flip { (to, from) } else { (from, to) };
        let (layer, colour) = (of(arc.layer), colours.of(arc.colour, of(arc.layer)));
        let radius = arc.radius * s;
        out.arcs.push(RawArc { center, radius, start_deg, end_deg, source, layer, colour, handle });
    }
    for e in &d.skipped {
        let mut e = e.clone();
        e.position = e.position.map(|q| a.apply(q));
        e.colour = colours.of(e.colour, of(e.layer));
        (e.source, e.layer, e.handle) = (source, of(e.layer), handle);
        out.skipped.push(e);
    }
    d.lines.len() + d.polylines.len() + d.circles.len() + d.arcs.len()
}
