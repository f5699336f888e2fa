//! V-carving: a V-bit of included angle α follows the medial axis at depth
//! r / tan(α/2) where r is the radius of the maximal disk (its flanks touch
//! both walls); where that would pass the maximum depth the bottom is flat
//! and bounded by the offset at the capped radius.

use super::CamError;
use crate::kernel::Point;
use crate::plane::{MedialAxis2d, OffsetLayer, Offsets};
use crate::shape::Shape2d;

/// Options for [`vcarve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VCarveOptions {
    /// Included angle of the V-bit, degrees, in (0, 180).
    pub angle_deg: f64,
    /// Maximum depth, model units, > 0 (infinite: no cap).
    pub max_depth: f64,
    /// Chordal tolerance for the sampled axis curves, model units (0: the
    /// shape's tolerance × 1000).
    pub tolerance: f64,
}

/// One tool path along the axis: points (x, y, depth), depth ≥ 0 measured
/// down from the surface.
#[derive(Debug, Clone, PartialEq)]
pub struct VCarvePath {
    /// (x, y, depth), model units.
    pub points: Vec<[f64; 3]>,
}

/// V-carve paths.
#[derive(Debug, Clone, PartialEq)]
pub struct VCarve {
    /// Paths along the axis, shallower than the maximum depth.
    pub paths: Vec<VCarvePath>,
    /// The radius where the depth is capped: max_depth · tan(α/2).
    pub flat_radius: f64,
    /// The offset rings at the capped radius, cut at the maximum depth
    /// (empty when the cap is never reached).
    pub flat: OffsetLayer,
}

/// V-carve paths of `shape` from its medial axis `axis`: every edge sampled
/// to the tolerance, cut where its radius passes the flat radius (on the
/// chord between samples, so within the tolerance of the curve), and
/// joined into long paths through nodes where only two pieces
/// meet.
pub fn vcarve(shape: &Shape2d, axis: &MedialAxis2d, opts: &VCarveOptions) -> Result<VCarve, CamError> {
    let a = opts.angle_deg;
    if !(a.is_finite() && a > 0.0 && a < 180.0) {
        return Err(CamError::BadOption { name: "angle_deg", value: a });
    }
    if opts.max_depth.is_nan() || opts.max_depth <= 0.0 {
        return Err(CamError::BadOption { name: "max_depth", value: opts.max_depth });
    }
    if !(opts.tolerance.is_finite() && opts.tolerance >= 0.0) {
        return Err(CamError::BadOption { name: "tolerance", value: opts.tolerance });
    }
    let slope = (0.5 * a.to_radians()).tan();
    let flat_radius = opts.max_depth * slope;
    let tol = if opts.tolerance > 0.0 { opts.tolerance } else { 1000.0 * shape.tolerance() };
    let sampled = axis.sampled(shape, tol);
    // Pieces of edges below the flat radius, as polylines of (point, radius).
    let mut pieces: Vec<Vec<(Point, f64)>> = Vec::new();
    for (edge, samples) in axis.edges.iter().zip(&sampled) {
        let mut cur: Vec<(Point, f64)> = Vec::new();
        // The radius is not linear between samples (between two points it
        // is hyperbolic along a straight edge): the cut is where the
        // distance to the edge's site reaches the flat radius on the chord.
        let cut = |p: Point, q: Point| {
            let (mut lo, mut hi) = (p, q);
            for _ in 0..60 {
                let m = lo.mid(hi);
                if edge.sites[0].distance(shape, m) <= flat_radius {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            (lo.mid(hi), flat_radius)
        };
        for w in samples.windows(2) {
            let ((p, r), (q, s)) = (w[0], w[1]);
            if cur.is_empty() && r <= flat_radius {
                cur.push((p, r));
            }
            match (r <= flat_radius, s <= flat_radius) {
                (true, true) => cur.push((q, s)),
                (true, false) => {
                    cur.push(cut(p, q));
                    pieces.push(std::mem::take(&mut cur));
                }
                (false, true) => {
                    cur.push(cut(q, p));
                    cur.push((q, s));
                }
                (false, false) => {}
            }
        }
        if cur.len() >= 2 {
            pieces.push(cur);
        }
    }
    let paths = chain(pieces, shape.tolerance())
        .into_iter()
        .map(|pl| VCarvePath { points: pl.iter().map(|&(p, r)| [p.x, p.y, r / slope]).collect() })
        .collect();
    let flat = if flat_radius < axis.nodes.iter().map(|n| n.radius).fold(0.0, f64::max) {
        Offsets::from_axis(shape, axis)?.layer(flat_radius)?
    } else {
        OffsetLayer::empty(flat_radius)
    };
    Ok(VCarve { paths, flat_radius, flat })
}

/// Joins polylines end to end where exactly two ends meet (within `tol`),
/// so the tool lifts only at branch points and leaves.
fn chain(pieces: Vec<Vec<(Point, f64)>>, tol: f64) -> Vec<Vec<(Point, f64)>> {
    use std::collections::HashMap;
    // Ends keyed by a grid cell of size tol; ends at one node share the
    // node's computed point, so an exact key is enough in practice and the
    // cell only absorbs rounding.
    let cell = |p: Point| {
        ((p.x / tol.max(f64::MIN_POSITIVE)).round() as i64, (p.y / tol.max(f64::MIN_POSITIVE)).round() as i64)
    };
    let mut at: HashMap<(i64, i64), Vec<(usize, bool)>> = HashMap::new();
    for (i, pl) in pieces.iter().enumerate() {
        at.entry(cell(pl[0].0)).or_default().push((i, false));
        at.entry(cell(pl[pl.len() - 1].0)).or_default().push((i, true));
    }
    let mut used = vec![false; pieces.len()];
    let mut out = Vec::new();
    let degree2 = |p: Point| at.get(&cell(p)).is_some_and(|v| v.len() == 2);
    // Start at ends that are not joints, then close any remaining cycles.
    let mut starts: Vec<usize> = (0..pieces.len()).filter(|&i| !degree2(pieces[i][0].0)).collect();
    starts.extend(0..pieces.len());
    for s in starts {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut path = pieces[s].clone();
        loop {
            let end = path[path.len() - 1].0;
            let Some(ends) = at.get(&cell(end)).filter(|v| v.len() == 2) else { break };
            let Some(&(j, at_end)) = ends.iter().find(|(j, _)| !used[*j]) else { break };
            used[j] = true;
            let mut next = pieces[j].clone();
            if at_end {
                next.reverse();
            }
            path.extend_from_slice(&next[1..]);
        }
        out.push(path);
    }
    out
}
