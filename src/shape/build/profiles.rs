//! Profiles out of drawings: the closed loops of a DXF or SVG drawing,
//! grouped into shapes by containment, and a report of everything left
//! out. Real drawings hold centre lines, leaders and symbol strokes beside
//! the parts, and often several parts: refusing the whole file for one open
//! line (as [`Shape2d::from_file`] does) refused 94 % of a real library.

use crate::io::RawDrawing;
use crate::kernel::{BBox, FilteredKernel, Point};
use crate::shape::build::import::{drawing_parts, Origin, Traced};
use crate::shape::build::profile_graph::profile_loops;
use crate::shape::build::touching::touching_shapes;
pub use crate::shape::build::touching::Touching;
use crate::shape::index::box_tree::BoxTree;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::{ElementRef, ShapeError};
use crate::shape::model::options::ShapeOptions;
use crate::shape::shape2d::Shape2d;
use crate::util::fast_hash::FastMap;
use rayon::prelude::*;
use std::ops::ControlFlow;

/// The shapes a drawing holds and what was left out of them.
#[derive(Debug, Clone)]
pub struct Drawing2d {
    /// One shape per outer loop, with the loops directly inside it as
    /// holes; a loop inside a hole is the outer loop of a shape of its
    /// own. Largest enclosed area first.
    pub shapes: Vec<Shape2d>,
    /// Everything of the drawing in no shape, in the order found.
    pub ignored: Vec<Ignored>,
    /// Where the loops' curves did not meet within the validation
    /// tolerance ([`ShapeOptions::tolerance_for`]) but within the chaining
    /// tolerance, and were joined: the joint and the gap closed (model
    /// units), widest first.
    pub gaps: Vec<(Point, f64)>,
    /// Shapes whose boundaries touch or cross: two parts sharing an edge,
    /// an island touching the hole it lies in. Both are kept (each is
    /// valid on its own); a machining plan may want them merged or apart.
    pub touching: Vec<Touching>,
    /// The unit the drawing says its coordinates are in (DXF `$INSUNITS`),
    /// by name: "millimetre", "inch"…; `None` where it does not say, or
    /// says "unitless".
    pub units: Option<&'static str>,
}

/// The name of a DXF `$INSUNITS` code; `None` for 0 (unitless) and codes
/// DXF does not define.
pub fn unit_name(code: i64) -> Option<&'static str> {
    const NAMES: [&str; 21] = [
        "",
        "inch",
        "foot",
        "mile",
        "millimetre",
        "centimetre",
        "metre",
        "kilometre",
        "microinch",
        "mil",
        "yard",
        "ångström",
        "nanometre",
        "micrometre",
        "decimetre",
        "decametre",
        "hectometre",
        "gigametre",
        "astronomical unit",
        "light year",
        "parsec",
    ];
    usize::try_from(code).ok().and_then(|k| NAMES.get(k)).copied().filter(|n| !n.is_empty())
}

/// Something of a drawing that is in none of its shapes.
#[derive(Debug, Clone, PartialEq)]
pub struct Ignored {
    /// What it is.
    pub kind: IgnoredKind,
    /// 1-based line (DXF) or byte offset (SVG) of its first entity.
    pub source: usize,
    /// That entity's layer ("" in formats without layers).
    pub layer: String,
    /// A point of it (model units): an open chain's loose end, a shape's
    /// first vertex.
    pub position: Point,
    /// Why it was left out.
    pub reason: String,
    /// The DXF handles (group 5) of the entities at fault, or of the block
    /// references that placed them: its first entity, then for a
    /// [`IgnoredKind::DuplicateLoop`] the entity of the copy kept, for a
    /// [`IgnoredKind::TouchingLoop`] or an [`IgnoredKind::InvalidShape`]
    /// whose loops meet the entity met. Empty where the file has none.
    pub handles: Vec<u64>,
    /// For an [`IgnoredKind::InvalidShape`], the validation error.
    pub cause: Option<ShapeError>,
}

/// The kinds of [`Ignored`] things.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IgnoredKind {
    /// Curve entities that chain into no closed loop (centre lines,
    /// leaders, strokes of symbols, or a profile with a gap wider than the
    /// chaining tolerance).
    OpenChain,
    /// A closed loop that encloses no area.
    FlatLoop,
    /// A copy of a loop drawn twice (the first is kept; see
    /// [`DrawingOptions::keep_duplicates`]).
    DuplicateLoop,
    /// A loop inside a shape's outer loop that touches or crosses another
    /// of its loops: left out, the shape kept without it.
    TouchingLoop,
    /// An entity that is not a curve medax reads (text, dimension, hatch,
    /// point, block reference, spline, ellipse…): its type is the reason.
    Entity,
    /// The curves of a layer the selection leaves out, one report per
    /// layer with their count.
    OtherLayer,
    /// An outer loop with its holes that does not validate (the outer
    /// loop crosses itself, or an element is degenerate): the validation
    /// error says where.
    InvalidShape,
}

impl IgnoredKind {
    /// A short name for reports.
    pub fn name(self) -> &'static str {
        match self {
            IgnoredKind::OpenChain => "open chain",
            IgnoredKind::Entity => "entity",
            IgnoredKind::OtherLayer => "other layer",
            IgnoredKind::FlatLoop => "flat loop",
            IgnoredKind::DuplicateLoop => "duplicate loop",
            IgnoredKind::TouchingLoop => "touching loop",
            IgnoredKind::InvalidShape => "invalid shape",
        }
    }
}

/// What to take out of a drawing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DrawingOptions {
    /// Take the curves of these layers only (DXF group 8; "0" for entities
    /// without one); empty: every layer.
    pub layers: Vec<String>,
    /// Take the curves of these colours only: AutoCAD colour indices
    /// 1–255 (DXF group 62, "by layer" and "by block" resolved; 7 where
    /// nothing says); empty: every colour.
    pub colours: Vec<i16>,
    /// Keep both copies of a loop drawn twice rather than merging them
    /// into one: they then meet, and are reported as touching loops or
    /// touching shapes, as drawn.
    pub keep_duplicates: bool,
}

/// The things left out of a drawing, as they are found.
struct Report<'a> {
    /// The drawing's layer names.
    layers: &'a [String],
    out: Vec<Ignored>,
}

impl Report<'_> {
    fn push(&mut self, kind: IgnoredKind, at: Origin, position: Point, reason: String, cause: Option<ShapeError>) {
        self.push_pair(kind, [at, Origin::default()], position, reason, cause);
    }

    /// An ignored thing whose first entity is `at[0]` and which meets or
    /// copies `at[1]` (default where none).
    fn push_pair(
        &mut self,
        kind: IgnoredKind,
        at: [Origin; 2],
        position: Point,
        reason: String,
        cause: Option<ShapeError>,
    ) {
        let layer = self.layers.get(at[0].layer as usize).cloned().unwrap_or_default();
        let mut handles = vec![at[0].handle, at[1].handle];
        while handles.last() == Some(&0) {
            handles.pop();
        }
        self.out.push(Ignored { kind, source: at[0].source, layer, position, reason, cause, handles });
    }
}

/// The profiles of a parsed drawing: curve entities of the selected
/// layers chained within the chaining tolerance
/// ([`ShapeOptions::chain_tolerance_for`] of their extent), closed loops
/// kept and grouped into shapes; open chains, other entities, other
/// layers and shapes that do not validate reported in
/// [`Drawing2d::ignored`]. Never fails: a drawing without a closed loop
/// gives no shapes.
pub fn profiles(d: &RawDrawing, opts: &ShapeOptions, select: &DrawingOptions) -> Drawing2d {
    let taken: Vec<bool> =
        d.layers.iter().map(|name| select.layers.is_empty() || select.layers.iter().any(|l| l == name)).collect();
    let take = |layer: u32, colour: i16| {
        taken.get(layer as usize).copied().unwrap_or(select.layers.is_empty())
            && (select.colours.is_empty() || select.colours.contains(&colour))
    };
    let mut report = Report { layers: &d.layers, out: Vec::new() };
    for e in d.skipped.iter().filter(|e| take(e.layer, e.colour)) {
        let at = Origin { source: e.source, layer: e.layer, handle: e.handle };
        let position = e.position.map_or(Point::default(), |[x, y]| Point::new(x, y));
        report.push(IgnoredKind::Entity, at, position, format!("{} is not a curve medax reads", e.entity), None);
    }
    left_out(d, &take, &mut report);
    let parts = drawing_parts(d, take);
    let tol = opts.chain_tolerance_for(parts.diagonal);
    let mut loops: Vec<Traced> = parts.loops.into_iter().map(|(l, at)| Traced { l, from: vec![at] }).collect();
    let found = profile_loops(&parts.loose, tol);
    let mut gaps: Vec<(Point, f64)> =
        found.gaps.into_iter().filter(|&(_, d)| d > opts.tolerance_for(parts.diagonal)).collect();
    gaps.sort_by(|a, b| b.1.total_cmp(&a.1));
    loops.extend(
        found.loops.into_iter().map(|(l, ids)| Traced { l, from: ids.iter().map(|&i| parts.origins[i]).collect() }),
    );
    for (run, position) in found.open {
        let first = run.iter().map(|&i| parts.origins[i]).min_by_key(|o| o.source).unwrap_or_default();
        let reason = format!("{} entities that close no loop", run.len());
        report.push(IgnoredKind::OpenChain, first, position, reason, None);
    }
    let (flat, loops): (Vec<_>, Vec<_>) = loops.into_iter().partition(|t| t.l.signed_area() == 0.0);
    for t in flat {
        let position = t.l.vertices().first().map_or(Point::default(), |v| v.p);
        let reason = "the loop encloses no area in sum (it crosses itself, or its entities are drawn twice)";
        report.push(IgnoredKind::FlatLoop, t.origin(0), position, reason.into(), None);
    }
    let loops = drop_duplicates(loops, tol, !select.keep_duplicates, &mut report);
    // Shapes validate independently; in parallel, a drawing of thousands
    // of small parts does not pay the thread pool's hand-off per shape.
    let layers = report.layers;
    let checked: Vec<_> = nest(loops, tol)
        .into_par_iter()
        .map(|group| {
            let mut local = Report { layers, out: Vec::new() };
            (validate(group, opts, &mut local), local.out)
        })
        .collect();
    let mut shapes = Vec::new();
    let mut traced = Vec::new();
    for (valid, ignored) in checked {
        report.out.extend(ignored);
        if let Some((shape, from)) = valid {
            shapes.push(shape);
            traced.push(from);
        }
    }
    let touching = touching_shapes(&shapes, &traced);
    Drawing2d { shapes, ignored: report.out, gaps, touching, units: d.units.and_then(unit_name) }
}

/// One report per layer of the curves `take` leaves out (by layer or by
/// colour), with their count.
fn left_out(d: &RawDrawing, take: &impl Fn(u32, i16) -> bool, report: &mut Report) {
    let mut count: Vec<(usize, Origin, Point)> = vec![(0, Origin::default(), Point::default()); d.layers.len()];
    let at = |layer: u32, source: usize, handle: u64| Origin { source, layer, handle };
    let curves = d.lines.iter().map(|l| (at(l.layer, l.source, l.handle), l.colour, l.a));
    let curves = curves.chain(d.arcs.iter().map(|a| (at(a.layer, a.source, a.handle), a.colour, a.center)));
    let curves = curves.chain(d.circles.iter().map(|c| (at(c.layer, c.source, c.handle), c.colour, c.center)));
    let curves = curves.chain(d.polylines.iter().map(|p| {
        let first = p.vertices.first().map_or([0.0, 0.0], |v| [v.x, v.y]);
        (at(p.layer, p.source, p.handle), p.colour, first)
    }));
    for (origin, _, [x, y]) in curves.filter(|c| !take(c.0.layer, c.1)) {
        if let Some(c) = count.get_mut(origin.layer as usize) {
            if c.0 == 0 {
                (c.1, c.2) = (origin, Point::new(x, y));
            }
            c.0 += 1;
        }
    }
    for (name, (n, at, position)) in d.layers.iter().zip(count) {
        if n > 0 {
            let reason = format!("{n} curve(s) on layer {name} not selected (by layer or colour)");
            report.push(IgnoredKind::OtherLayer, at, position, reason, None);
        }
    }
}

/// The shape of a group (outer loop first) and its loops' origins, without
/// the holes that touch or cross another of its loops (each reported,
/// with the validation error and both entities); `None` with the group
/// reported when the outer loop itself is at fault or the error is
/// another.
fn validate(mut group: Vec<Traced>, opts: &ShapeOptions, report: &mut Report) -> Option<(Shape2d, Vec<Traced>)> {
    loop {
        let loops = group.iter().map(|t| t.l.clone()).collect();
        let e = match Shape2d::from_loops(loops, opts) {
            Ok(s) => return Some((s, group)),
            Err(e) => e,
        };
        // The later of two loops that meet (the smaller: holes follow
        // their outer loop by decreasing area), unless that is the outer.
        let (culprit, at) = match e {
            ShapeError::Intersection { first, second, .. } => {
                let (a, b) = if first.loop_index >= second.loop_index { (first, second) } else { (second, first) };
                let origin = |r: ElementRef| group[r.loop_index].origin(r.element);
                (a.loop_index, [origin(a), origin(b)])
            }
            _ => {
                let r = e.element().unwrap_or_default();
                (0, [group.get(r.loop_index).map_or(Origin::default(), |t| t.origin(r.element)), Origin::default()])
            }
        };
        let t = if culprit == 0 { group.swap_remove(0) } else { group.remove(culprit) };
        let kind = if culprit == 0 { IgnoredKind::InvalidShape } else { IgnoredKind::TouchingLoop };
        report.push_pair(kind, at, t.l.vertices()[0].p, e.to_string(), Some(e));
        if culprit == 0 {
            return None;
        }
    }
}

/// Points of a loop tested for lying inside another (element midpoints).
const PROBES: usize = 3;

/// `loops` sorted by decreasing enclosed area, without the copies of a
/// loop drawn twice (the same vertices within `tol`, in either direction
/// and from any start, and the same area), which are reported; with them
/// when `merge` is false.
fn drop_duplicates(mut loops: Vec<Traced>, tol: f64, merge: bool, report: &mut Report) -> Vec<Traced> {
    loops.sort_by(|a, b| b.l.signed_area().abs().total_cmp(&a.l.signed_area().abs()));
    if !merge {
        return loops;
    }
    // Kept loops by the cell of their box's lower corner: a copy's corner
    // lies within `tol`, in that cell or a neighbour.
    let cell = tol.max(f64::MIN_POSITIVE * 1e10);
    let key = |p: Point| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut cells: FastMap<(i64, i64), Vec<usize>> = FastMap::default();
    let mut kept: Vec<(Traced, f64)> = Vec::with_capacity(loops.len());
    for t in loops {
        let (bb, area) = (t.l.bbox(), t.l.signed_area().abs());
        let (kx, ky) = key(bb.min);
        let first = (-1..=1)
            .flat_map(|dx| (-1..=1).map(move |dy| (kx.saturating_add(dx), ky.saturating_add(dy))))
            .filter_map(|k| cells.get(&k))
            .flatten()
            .copied()
            .find(|&k| {
                let (other, other_area) = &kept[k];
                (other_area - area).abs() <= tol * (bb.width() + bb.height()) && same_cycle(&other.l, &t.l, tol)
            });
        match first {
            Some(k) => {
                let other = kept[k].0.origin(0);
                let reason =
                    format!("drawn twice: the same loop as the one at line/byte {}, which is kept", other.source);
                report.push_pair(IgnoredKind::DuplicateLoop, [t.origin(0), other], t.l.vertices()[0].p, reason, None);
            }
            None => {
                cells.entry((kx, ky)).or_default().push(kept.len());
                kept.push((t, area));
            }
        }
    }
    kept.into_iter().map(|(t, _)| t).collect()
}

/// True when `b` has the vertices of `a` within `tol`, in the same cyclic
/// order either way round.
fn same_cycle(a: &Loop, b: &Loop, tol: f64) -> bool {
    let (va, vb) = (a.vertices(), b.vertices());
    let n = va.len();
    n == vb.len()
        && (0..n).filter(|&j| vb[j].p.dist(va[0].p) <= tol).any(|j| {
            (0..n).all(|i| vb[(j + i) % n].p.dist(va[i].p) <= tol)
                || (0..n).all(|i| vb[(j + n - i) % n].p.dist(va[i].p) <= tol)
        })
}

/// Groups loops (with their sources, by decreasing area) into shapes: each
/// loop's parent is the smallest larger loop around a point of it, taken
/// just inside the loop (off its boundary by more than the chaining
/// tolerance `tol`, so that a neighbour sharing an edge is not taken for
/// a loop around it); a loop
/// at even depth is the outer loop of a shape, one at odd depth a hole of
/// its parent's shape. Groups are outer loop first, largest outer loop
/// first.
fn nest(loops: Vec<Traced>, tol: f64) -> Vec<Vec<Traced>> {
    let tree = BoxTree::new(loops.iter().map(|t| t.l.bbox()).collect());
    let k = FilteredKernel;
    // The group of each loop, and its depth.
    let mut group: Vec<usize> = Vec::with_capacity(loops.len());
    let mut depth: Vec<usize> = Vec::with_capacity(loops.len());
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, Traced { l, .. }) in loops.iter().enumerate() {
        // Points of the loop away from its vertices: one of them off a
        // loop that touches it (from inside or outside) decides.
        // An arc's tangent at its midpoint is parallel to its chord: the
        // chord's left normal points inside a counter-clockwise loop.
        let inward = if l.signed_area() > 0.0 { 1.0 } else { -1.0 };
        let probes: Vec<Point> = (0..l.len().min(PROBES))
            .map(|e| {
                let el = l.element(e);
                let chord = el.end() - el.start();
                let length = chord.norm();
                let depth = (1e-4 * length).max(4.0 * tol).min(0.25 * length);
                el.point_at(0.5) + Point::new(-chord.y, chord.x) * (inward * depth / length.max(f64::MIN_POSITIVE))
            })
            .collect();
        let mut parent = None;
        for &probe in &probes {
            tree.visit_overlapping(&BBox::of_points(probe, probe), |j| {
                if j < i && parent.is_none_or(|p| j > p) && loops[j].l.winding_number(&k, probe) != 0 {
                    parent = Some(j);
                }
                ControlFlow::<()>::Continue(())
            });
        }
        match parent {
            Some(p) if depth[p] % 2 == 0 => {
                depth.push(depth[p] + 1);
                group.push(group[p]);
                groups[group[p]].push(i);
            }
            p => {
                depth.push(p.map_or(0, |p| depth[p] + 1));
                group.push(groups.len());
                groups.push(vec![i]);
            }
        }
    }
    let mut slots: Vec<Option<Traced>> = loops.into_iter().map(Some).collect();
    groups.into_iter().map(|g| g.into_iter().filter_map(|i| slots[i].take()).collect()).collect()
}
