//! V-carving: a V-bit of included angle α follows the medial axis at depth
//! r / tan(α/2) where r is the radius of the maximal disk (its flanks touch
//! both walls); where that would pass the maximum depth the bottom is flat
//! and bounded by the offset at the capped radius.

use super::CamError;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::{Disk, Point};
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

impl VCarveOptions {
    /// Checks every option's range: the angle in (0, 180), the maximum
    /// depth > 0 (infinite: no cap), the tolerance finite and ≥ 0.
    /// [`vcarve`] calls it first.
    pub fn check(&self) -> Result<(), CamError> {
        let a = self.angle_deg;
        if !(a.is_finite() && a > 0.0 && a < 180.0) {
            return Err(CamError::BadOption {
                name: "angle_deg",
                value: a,
                expected: "between 0 and 180 degrees (exclusive)",
            });
        }
        if self.max_depth.is_nan() || self.max_depth <= 0.0 {
            return Err(CamError::BadOption {
                name: "max_depth",
                value: self.max_depth,
                expected: "> 0 (infinite: no cap)",
            });
        }
        if !(self.tolerance.is_finite() && self.tolerance >= 0.0) {
            return Err(CamError::BadOption {
                name: "tolerance",
                value: self.tolerance,
                expected: "a finite number >= 0",
            });
        }
        Ok(())
    }
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
    /// The options the paths were computed with.
    pub opts: VCarveOptions,
    /// Paths along the axis, shallower than the maximum depth.
    pub paths: Vec<VCarvePath>,
    /// The offset rings at the capped radius (its distance), cut at the
    /// maximum depth (empty when the cap is never reached).
    pub flat: OffsetLayer,
}

impl VCarve {
    /// The radius where the depth is capped: max_depth · tan(α/2)
    /// (infinite without a cap).
    pub fn flat_radius(&self) -> f64 {
        self.flat.distance
    }

    /// The largest depth along the paths (0 without paths).
    pub fn deepest(&self) -> f64 {
        self.paths.iter().flat_map(|p| &p.points).map(|p| p[2]).fold(0.0, f64::max)
    }
}

/// V-carve paths of `shape` from its medial axis `axis`: every edge sampled
/// to the tolerance, cut where its radius passes the flat radius (on the
/// chord between samples, so within the tolerance of the curve), and
/// joined into long paths through nodes where only two pieces
/// meet.
pub fn vcarve(shape: &Shape2d, axis: &MedialAxis2d, opts: &VCarveOptions) -> Result<VCarve, CamError> {
    opts.check()?;
    let slope = (0.5 * opts.angle_deg.to_radians()).tan();
    let flat_radius = opts.max_depth * slope;
    let tol = if opts.tolerance > 0.0 { opts.tolerance } else { Tolerance::new(shape.tolerance()).vcarve_sampling() };
    let sampled = axis.sampled(shape, tol);
    // Pieces of edges below the flat radius, as polylines of maximal
    // disks, with the nodes they start and end at (none at a cut).
    let mut pieces: Vec<Piece> = Vec::new();
    for (edge, samples) in axis.edges.iter().zip(&sampled) {
        let mut start = Some(edge.from);
        let mut cur: Vec<Disk> = Vec::new();
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
            Disk::new(lo.mid(hi), flat_radius)
        };
        for w in samples.windows(2) {
            let (Disk { center: p, radius: r }, Disk { center: q, radius: s }) = (w[0], w[1]);
            if cur.is_empty() && r <= flat_radius {
                cur.push(w[0]);
            }
            match (r <= flat_radius, s <= flat_radius) {
                (true, true) => cur.push(w[1]),
                (true, false) => {
                    cur.push(cut(p, q));
                    pieces.push(Piece { points: std::mem::take(&mut cur), ends: [start, None] });
                    start = None;
                }
                (false, true) => {
                    cur.push(cut(q, p));
                    cur.push(w[1]);
                }
                (false, false) => {}
            }
        }
        if cur.len() >= 2 {
            pieces.push(Piece { points: cur, ends: [start, Some(edge.to)] });
        }
    }
    let paths = chain(pieces)
        .into_iter()
        .map(|pl| VCarvePath { points: pl.iter().map(|d| [d.center.x, d.center.y, d.radius / slope]).collect() })
        .collect();
    // Without a cap there is no flat bottom: no offsets to prepare.
    let offsets = if flat_radius.is_finite() { Some(Offsets::from_axis(shape, axis)?) } else { None };
    let flat = match offsets {
        Some(o) if flat_radius < o.max_inner_distance() => o.layer(flat_radius)?,
        _ => OffsetLayer::empty(flat_radius),
    };
    Ok(VCarve { opts: *opts, paths, flat })
}

/// A polyline of maximal disks along one edge and the axis nodes at its
/// ends (`None` where it was cut at the flat radius).
struct Piece {
    points: Vec<Disk>,
    ends: [Option<usize>; 2],
}

/// Joins pieces end to end at nodes where exactly two of them meet, so the
/// tool lifts only at branch points, leaves and the flat radius.
fn chain(pieces: Vec<Piece>) -> Vec<Vec<Disk>> {
    use std::collections::HashMap;
    let mut at: HashMap<usize, Vec<(usize, bool)>> = HashMap::new();
    for (i, pc) in pieces.iter().enumerate() {
        for (end, node) in pc.ends.iter().enumerate() {
            if let Some(n) = node {
                at.entry(*n).or_default().push((i, end == 1));
            }
        }
    }
    let joint = |node: Option<usize>| node.and_then(|n| at.get(&n)).filter(|v| v.len() == 2);
    let mut used = vec![false; pieces.len()];
    let mut out = Vec::new();
    // Start at ends that are not joints, then close any remaining cycles.
    let mut starts: Vec<usize> = (0..pieces.len()).filter(|&i| joint(pieces[i].ends[0]).is_none()).collect();
    starts.extend(0..pieces.len());
    for s in starts {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut path = pieces[s].points.clone();
        let mut end = pieces[s].ends[1];
        while let Some(&(j, at_end)) = joint(end).and_then(|v| v.iter().find(|(j, _)| !used[*j])) {
            used[j] = true;
            let mut next = pieces[j].points.clone();
            if at_end {
                next.reverse();
            }
            path.extend_from_slice(&next[1..]);
            end = pieces[j].ends[usize::from(!at_end)];
        }
        out.push(path);
    }
    out
}
