//! Profiles out of drawings: the closed loops of a DXF or SVG drawing,
//! grouped into shapes by containment, and a report of everything left
//! out. Real drawings hold centre lines, leaders and symbol strokes beside
//! the parts, and often several parts: refusing the whole file for one open
//! line (as [`Shape2d::from_file`] does) refused 94 % of a real library.

use crate::io::{dxf, svg_path, Format, RawDrawing};
use crate::kernel::{BBox, FilteredKernel, Point};
use crate::shape::build::chain::{chain, Chained};
use crate::shape::build::import::{decode, drawing_parts, looks_json, read_bytes, svg_drawing};
use crate::shape::index::box_tree::BoxTree;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::ShapeError;
use crate::shape::model::options::ShapeOptions;
use crate::shape::shape2d::Shape2d;
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
}

/// Something of a drawing that is in none of its shapes.
#[derive(Debug, Clone, PartialEq)]
pub struct Ignored {
    /// What it is.
    pub kind: IgnoredKind,
    /// 1-based line (DXF) or byte offset (SVG) of its first entity.
    pub source: usize,
    /// A point of it (model units): an open chain's loose end, a shape's
    /// first vertex.
    pub position: Point,
    /// Why it was left out.
    pub reason: String,
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
    /// A copy of a loop drawn twice (the first is kept).
    DuplicateLoop,
    /// An outer loop with its holes that does not validate (loops that
    /// touch or cross, a loop drawn twice): the validation error says
    /// where.
    InvalidShape,
}

impl IgnoredKind {
    /// A short name for reports.
    pub fn name(self) -> &'static str {
        match self {
            IgnoredKind::OpenChain => "open chain",
            IgnoredKind::FlatLoop => "flat loop",
            IgnoredKind::DuplicateLoop => "duplicate loop",
            IgnoredKind::InvalidShape => "invalid shape",
        }
    }
}

/// The profiles of a parsed drawing: curve entities chained within the
/// chaining tolerance ([`ShapeOptions::chain_tolerance_for`] of the
/// drawing's extent), closed loops kept and grouped into shapes, open
/// chains and shapes that do not validate reported in
/// [`Drawing2d::ignored`]. Never fails: a drawing without a closed loop
/// gives no shapes.
pub fn profiles(d: &RawDrawing, opts: &ShapeOptions) -> Drawing2d {
    let parts = drawing_parts(d);
    let tol = opts.chain_tolerance_for(parts.diagonal);
    let mut loops = parts.loops;
    let mut ignored = Vec::new();
    let _ = chain(&parts.loose, tol, |found| {
        match found {
            Chained::Loop(l, ids) => loops.push((l, parts.sources[ids[0]])),
            Chained::Open { elements, gap, position } => ignored.push(Ignored {
                kind: IgnoredKind::OpenChain,
                source: parts.sources[elements[0]],
                position,
                reason: format!("{} entities end {gap:.3e} from any other free end", elements.len()),
                cause: None,
            }),
        }
        Ok::<(), ()>(())
    });
    let (flat, loops): (Vec<_>, Vec<_>) = loops.into_iter().partition(|(l, _)| l.signed_area() == 0.0);
    ignored.extend(flat.into_iter().map(|(l, source)| Ignored {
        kind: IgnoredKind::FlatLoop,
        source,
        position: l.vertices().first().map_or(Point::default(), |v| v.p),
        reason: "the loop encloses no area (entities drawn twice?)".into(),
        cause: None,
    }));
    let (loops, twice) = drop_duplicates(loops, tol);
    ignored.extend(twice);
    let mut shapes = Vec::new();
    for group in nest(loops) {
        let (source, position) = (group[0].1, group[0].0.vertices()[0].p);
        match Shape2d::from_loops(group.into_iter().map(|(l, _)| l).collect(), opts) {
            Ok(s) => shapes.push(s),
            Err(e) => ignored.push(Ignored {
                kind: IgnoredKind::InvalidShape,
                source,
                position,
                reason: e.to_string(),
                cause: Some(e),
            }),
        }
    }
    Drawing2d { shapes, ignored }
}

/// Points of a loop tested for lying inside another (element midpoints).
const PROBES: usize = 3;

/// `loops` sorted by decreasing enclosed area, without the copies of a
/// loop drawn twice (same area, box and vertices within `tol` of the
/// first's, in either direction), which are returned as ignored.
fn drop_duplicates(mut loops: Vec<(Loop, usize)>, tol: f64) -> (Vec<(Loop, usize)>, Vec<Ignored>) {
    loops.sort_by(|a, b| b.0.signed_area().abs().total_cmp(&a.0.signed_area().abs()));
    let same = |a: &Loop, b: &Loop| {
        let (ba, bb) = (a.bbox(), b.bbox());
        a.len() == b.len()
            && ba.min.dist(bb.min) <= tol
            && ba.max.dist(bb.max) <= tol
            && (a.signed_area().abs() - b.signed_area().abs()).abs() <= tol * (ba.width() + ba.height())
            && a.vertices().iter().all(|v| b.vertices().iter().any(|w| v.p.dist(w.p) <= tol))
    };
    let mut kept: Vec<(Loop, usize)> = Vec::with_capacity(loops.len());
    let mut twice = Vec::new();
    for (l, source) in loops {
        // Equal areas are neighbours in the order: look back while they are.
        let area = l.signed_area().abs();
        let first = kept
            .iter()
            .rev()
            .take_while(|(k, _)| k.signed_area().abs() - area <= tol * (k.bbox().width() + k.bbox().height()))
            .find(|(k, _)| same(k, &l));
        match first {
            Some(&(_, at)) => twice.push(Ignored {
                kind: IgnoredKind::DuplicateLoop,
                source,
                position: l.vertices()[0].p,
                reason: format!("drawn twice: the same loop as the one at line/byte {at}, which is kept"),
                cause: None,
            }),
            None => kept.push((l, source)),
        }
    }
    (kept, twice)
}

/// Groups loops (with their sources, by decreasing area) into shapes: each
/// loop's parent is the smallest larger loop around a point of it; a loop
/// at even depth is the outer loop of a shape, one at odd depth a hole of
/// its parent's shape. Groups are outer loop first, largest outer loop
/// first.
fn nest(loops: Vec<(Loop, usize)>) -> Vec<Vec<(Loop, usize)>> {
    let tree = BoxTree::new(loops.iter().map(|(l, _)| l.bbox()).collect());
    let k = FilteredKernel;
    // The group of each loop, and its depth.
    let mut group: Vec<usize> = Vec::with_capacity(loops.len());
    let mut depth: Vec<usize> = Vec::with_capacity(loops.len());
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, (l, _)) in loops.iter().enumerate() {
        // Points of the loop away from its vertices: one of them off a
        // loop that touches it (from inside or outside) decides.
        let probes: Vec<Point> = (0..l.len().min(PROBES)).map(|e| l.element(e).point_at(0.5)).collect();
        let mut parent = None;
        for &probe in &probes {
            tree.visit_overlapping(&BBox::of_points(probe, probe), |j| {
                if j < i && parent.is_none_or(|p| j > p) && loops[j].0.winding_number(&k, probe) != 0 {
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
    let mut slots: Vec<Option<(Loop, usize)>> = loops.into_iter().map(Some).collect();
    groups.into_iter().map(|g| g.into_iter().filter_map(|i| slots[i].take()).collect()).collect()
}

impl Drawing2d {
    /// Reads a drawing file: DXF and SVG through [`profiles`]; a medax JSON
    /// file is one shape, read as [`Shape2d::from_file`] does. The format
    /// comes from the extension or, failing that, from the content.
    ///
    /// # Errors
    ///
    /// The file cannot be read or parsed, or (JSON only) its shape does not
    /// validate; an SVG elliptical arc.
    pub fn from_file(path: impl AsRef<std::path::Path>, opts: &ShapeOptions) -> Result<Drawing2d, ShapeError> {
        let path = path.as_ref();
        let bytes = read_bytes(path)?;
        let hint = Format::from_path(path);
        if hint == Some(Format::Json) || (hint.is_none() && looks_json(&bytes)) {
            return Ok(Drawing2d { shapes: vec![Shape2d::from_file(path, opts)?], ignored: Vec::new() });
        }
        let (text, format) = decode(&bytes, hint);
        Drawing2d::from_str_as(&text, format, opts)
    }

    /// Reads drawing text in the given format (see
    /// [`from_file`](Self::from_file)).
    pub fn from_str_as(text: &str, format: Format, opts: &ShapeOptions) -> Result<Drawing2d, ShapeError> {
        opts.check()?;
        let raw = match format {
            Format::Json => {
                return Ok(Drawing2d { shapes: vec![Shape2d::from_json_str(text, opts)?], ignored: Vec::new() })
            }
            Format::Dxf => dxf::read_dxf(text)?,
            Format::Svg => svg_drawing(&svg_path::read_svg(text)?)?,
        };
        Ok(profiles(&raw, opts))
    }
}
