//! The frame Γ the library chooses around Voronoi sites (thesis 2.3:
//! "the outer curve Γ can always be chosen in a way such that each vertex
//! of V(S \ {Γ}) is also a vertex of V(S)").
//!
//! Γ is a circle around the sites. It keeps every Voronoi vertex of the
//! sites exactly when the edges that reach it are the edges that run to
//! infinity without Γ, and those are known beforehand: one per bridge of
//! the sites' convex hull (a hull edge that does not run along a site:
//! between two sites, or across a concavity of one site, which gives an
//! unbounded self-edge). A vertex beyond Γ shows as a pair of sites meeting
//! Γ that no bridge joins, so Γ grows until the two multisets agree.

use crate::kernel::{BBox, FilteredKernel, Kernel, Orientation, Point};
use crate::plane::voronoi::diagram::VoronoiDiagram;
use crate::shape::{Element, Loop, Vertex, MAX_COORDINATE};
use crate::shape::{SiteId, Sites};

/// The first frame's radius in sites' diagonals. Disks near the frame
/// have radii of its size, and constructing the ones that touch two sites
/// and the frame where the sites' bisectors meet it nearly parallel (the
/// nearly collinear runs of a hull) loses about radius × 2^-52 × their
/// condition to rounding, against a tolerance of 1e-9 sites' diagonals:
/// frames of 256 to 4096 diagonals broke down on random points, 64 did
/// not (docs/PERFORMANCE.md, stop 13). Farther vertices make it grow.
const FIRST_RADIUS: f64 = 64.0;
/// The radius tried when the first frame breaks down, in sites'
/// diagonals: collinear points or segments, whose bisectors are exactly
/// parallel where they meet the frame, have no far vertices, and a small
/// frame keeps those disks apart (a frame of 4096 diagonals broke down on
/// 30 collinear points).
const SMALL_RADIUS: f64 = 4.0;
/// How many times the frame grows before the diagram is returned as
/// incomplete, and by how much each time: up to 64 × 16^3 = 2^18 sites'
/// diagonals. A larger frame that breaks down leaves the diagram of the
/// last one that did not, marked incomplete.
const GROWTHS: u32 = 3;
const FACTOR: f64 = 16.0;

/// Arcs of sites are sampled at this angular step (radians) for the hull:
/// the hull only decides which sites are on it, and at least one interior
/// sample per arc keeps a concave arc's ends from looking adjacent.
const ARC_STEP: f64 = std::f64::consts::PI / 64.0;

/// The frame loop: a counter-clockwise circle (two half arcs).
pub(crate) fn frame_loop(center: Point, radius: f64) -> Vec<Vertex> {
    vec![
        Vertex { p: center + Point::new(radius, 0.0), bulge: 1.0 },
        Vertex { p: center - Point::new(radius, 0.0), bulge: 1.0 },
    ]
}

/// The frame's size and the bridges it must reproduce.
pub(crate) struct FrameCheck {
    center: Point,
    radius: f64,
    /// The sites' diagonal (or a unit for sites at one place).
    scale: f64,
    /// The largest radius whose circle keeps within ±`MAX_COORDINATE`.
    room: f64,
    growths: u32,
    /// The first frame broke down and the frames start small again.
    small: bool,
    /// Site pairs of the hull's bridges, each pair sorted, the list
    /// sorted: of the hull through points on the arcs, and of the hull
    /// through their tangent polygons' corners.
    bridges: [Vec<(SiteId, SiteId)>; 2],
    /// The radius whose frame broke down, never tried again.
    failed: Option<f64>,
}

/// A hull sample: the point, its site, its index along the site's
/// samples, how many samples the site has, and whether they close up (a
/// region) or not (a curve, a point).
#[derive(Debug, Clone, Copy)]
struct Sample {
    p: Point,
    site: SiteId,
    index: usize,
    /// Where the site's samples start in the list of all samples.
    start: usize,
    count: usize,
    closed: bool,
}

impl FrameCheck {
    /// The first frame for `sites` within `bbox`: a circle
    /// [`FIRST_RADIUS`] × `scale` (the sites' diagonal) in radius around
    /// the box's centre, or as large as the coordinate range allows.
    pub(crate) fn new(sites: &Sites, bbox: BBox, scale: f64, tol: f64) -> FrameCheck {
        // Arcs are sampled on them (the chords' hull lies inside the true
        // one) and at the corners of their tangent polygons (outside it):
        // a site within a sagitta of the hull is on one hull and not the
        // other, and only agreeing with both counts.
        let bridges = [false, true].map(|outer| {
            let mut samples = Vec::new();
            let mut add = |site: SiteId, pts: Vec<Point>, closed: bool| {
                let (count, start) = (pts.len(), samples.len());
                samples.extend(pts.into_iter().enumerate().map(|(index, p)| Sample {
                    p,
                    site,
                    index,
                    start,
                    count,
                    closed,
                }));
            };
            for (i, r) in sites.regions.iter().enumerate() {
                // As the shape stores it (a closing vertex repeating the
                // first is no vertex).
                add(SiteId::Region(i), loop_samples(&Loop::closed(r.clone()), outer), true);
            }
            for (i, c) in sites.curves.iter().enumerate() {
                add(SiteId::Curve(i), chain_samples(c, outer), false);
            }
            for (i, &p) in sites.points.iter().enumerate() {
                add(SiteId::Point(i), vec![p], false);
            }
            let mut b = hull_bridges(&samples, tol);
            b.sort();
            b
        });
        let center = bbox.min.mid(bbox.max);
        let room = (MAX_COORDINATE - center.x.abs().max(center.y.abs())).max(0.0);
        let radius = (FIRST_RADIUS * scale).min(room);
        FrameCheck { center, radius, scale, room, growths: 0, small: false, failed: None, bridges }
    }

    /// Centre of the frame circle, model units.
    pub(crate) fn center(&self) -> Point {
        self.center
    }

    /// Radius of the frame circle, model units.
    pub(crate) fn radius(&self) -> f64 {
        self.radius
    }

    /// After a breakdown with no diagram yet: the small frame first, then
    /// growing as usual; false when nothing is left to try.
    pub(crate) fn after_breakdown(&mut self) -> bool {
        self.failed.get_or_insert(self.radius);
        if self.small {
            return self.grow();
        }
        self.small = true;
        self.growths = 0;
        self.radius = (SMALL_RADIUS * self.scale).min(self.room);
        true
    }

    /// Grows the frame, past the radius that broke down (the same frame
    /// gives the same disks and breaks down again); false when it has
    /// reached its limit.
    pub(crate) fn grow(&mut self) -> bool {
        loop {
            if self.growths == GROWTHS || self.radius * FACTOR > self.room {
                return false;
            }
            self.growths += 1;
            self.radius *= FACTOR;
            if self.failed != Some(self.radius) {
                return true;
            }
        }
    }

    /// True when the edges between sites that reach the frame pair the
    /// same sites as the hull's bridges.
    pub(crate) fn accepts(&self, vd: &VoronoiDiagram) -> bool {
        let mut reaching = Vec::new();
        for (e, v) in vd.axis.edges.iter().zip(&vd.edges) {
            if v.sides.contains(&SiteId::Frame) {
                continue;
            }
            let [a, b] = v.sides;
            let pair = (a.min(b), a.max(b));
            for n in [e.from, e.to] {
                if vd.frontier[n] {
                    reaching.push(pair);
                }
            }
        }
        reaching.sort();
        self.bridges.iter().all(|b| *b == reaching)
    }
}

/// Points along a loop in order: its vertices and, on every arc, interior
/// points at most [`ARC_STEP`] apart in angle (at least one), on the arc
/// or, when `outer`, at the corners of its tangent polygon.
fn loop_samples(l: &Loop, outer: bool) -> Vec<Point> {
    let mut out = Vec::with_capacity(l.len());
    for (v, e) in l.vertices().iter().zip(l.elements()) {
        out.push(v.p);
        arc_inside(&e, outer, &mut out);
    }
    out
}

/// [`loop_samples`] of an open chain, its last vertex included.
fn chain_samples(c: &[Vertex], outer: bool) -> Vec<Point> {
    let mut out = Vec::with_capacity(c.len());
    for w in c.windows(2) {
        out.push(w[0].p);
        arc_inside(&Element::from_bulge(w[0].p, w[1].p, w[0].bulge), outer, &mut out);
    }
    out.extend(c.last().map(|v| v.p));
    out
}

/// Interior samples of an arc at most [`ARC_STEP`] apart (none for a
/// segment): points on it, or when `outer` the corners of the tangent
/// polygon through those points and the ends (each outside the arc, on
/// its convex side, so their hull holds it).
fn arc_inside(e: &Element, outer: bool, out: &mut Vec<Point>) {
    let Element::Arc(a) = e else { return };
    let steps = ((a.sweep().abs() / ARC_STEP).ceil() as usize).max(2);
    let at = |f: f64| e.point_at(f);
    if !outer {
        out.extend((1..steps).map(|k| at(k as f64 / steps as f64)));
        return;
    }
    // Corner between samples k and k + 1: on the bisecting ray from the
    // centre at radius r / cos(half the step).
    let half = 0.5 * a.sweep().abs() / steps as f64;
    let reach = a.radius / half.cos();
    out.extend((0..steps).map(|k| {
        let mid = at((k as f64 + 0.5) / steps as f64);
        a.center + (mid - a.center).unit() * reach
    }));
}

/// The site pairs of the convex hull's bridges: consecutive hull points
/// not next to each other along one site (within `tol`, model units). Collinear points on the hull are
/// kept (each is the end of an unbounded edge), with exact orientations.
fn hull_bridges(samples: &[Sample], tol: f64) -> Vec<(SiteId, SiteId)> {
    let mut pts = samples.to_vec();
    pts.sort_by(|a, b| a.p.x.total_cmp(&b.p.x).then(a.p.y.total_cmp(&b.p.y)));
    pts.dedup_by(|a, b| a.p == b.p);
    if pts.len() < 2 {
        return Vec::new();
    }
    let k = FilteredKernel;
    let mut hull: Vec<Sample> = Vec::with_capacity(2 * pts.len());
    let chain = |it: &mut dyn Iterator<Item = &Sample>, hull: &mut Vec<Sample>| {
        let base = hull.len();
        for s in it {
            while hull.len() >= base + 2
                && k.orientation(hull[hull.len() - 2].p, hull[hull.len() - 1].p, s.p) == Orientation::Right
            {
                hull.pop();
            }
            hull.push(*s);
        }
        hull.pop();
    };
    chain(&mut pts.iter(), &mut hull);
    chain(&mut pts.iter().rev(), &mut hull);
    // Two hull points of one site run along it when every sample between
    // them, one way or the other round the site, lies within `tol` of the
    // hull edge: samples a rounding off the hull (a vertex between two
    // tangent-polygon corners) are no concavity.
    let along = |a: &Sample, b: &Sample| {
        if a.site != b.site {
            return false;
        }
        let base = a.start;
        let (u, v) = (a.p, b.p);
        let off = |i: usize| {
            let q = samples[base + i].p;
            let d = v - u;
            let len = d.norm();
            if len > 0.0 {
                d.cross(q - u).abs() / len
            } else {
                q.dist(u)
            }
        };
        let clear = |from: usize, to: usize, step: usize| {
            let mut i = from;
            loop {
                i = (i + step) % a.count;
                if i == to {
                    return true;
                }
                if off(i) > tol {
                    return false;
                }
            }
        };
        if a.closed {
            clear(a.index, b.index, 1) || clear(a.index, b.index, a.count - 1)
        } else {
            let (lo, hi) = (a.index.min(b.index), a.index.max(b.index));
            clear(lo, hi, 1)
        }
    };
    let n = hull.len();
    (0..n)
        .map(|i| (hull[i], hull[(i + 1) % n]))
        .filter(|(a, b)| !along(a, b))
        .map(|(a, b)| (a.site.min(b.site), a.site.max(b.site)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(x: f64, y: f64, site: usize) -> Sample {
        Sample { p: Point::new(x, y), site: SiteId::Region(site), index: 0, start: site, count: 1, closed: true }
    }

    #[test]
    fn bridges_of_points_in_convex_and_collinear_position() {
        // A triangle of three single-sample sites: three bridges.
        let tri = hull_bridges(&[sample(0.0, 0.0, 0), sample(1.0, 0.0, 1), sample(0.3, 1.0, 2)], 1e-9);
        assert_eq!(tri.len(), 3);
        // Three collinear sites: the hull walks there and back, four bridges.
        let line = hull_bridges(&[sample(0.0, 0.0, 0), sample(1.0, 0.0, 1), sample(2.0, 0.0, 2)], 1e-9);
        assert_eq!(line.len(), 4);
        // A site inside the triangle of three others is on no bridge.
        let inner =
            hull_bridges(&[sample(0.0, 0.0, 0), sample(4.0, 0.0, 1), sample(2.0, 4.0, 2), sample(2.0, 1.0, 3)], 1e-9);
        assert!(inner.iter().all(|&(a, b)| a != SiteId::Region(3) && b != SiteId::Region(3)));
        assert_eq!(inner.len(), 3);
    }

    #[test]
    fn after_a_breakdown_the_failed_radius_is_not_tried_again() {
        let sites = Sites { points: vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0)], ..Sites::default() };
        let bbox = BBox { min: Point::new(0.0, 0.0), max: Point::new(1.0, 0.0) };
        let mut f = FrameCheck::new(&sites, bbox, 1.0, 1e-9);
        let mut radii = vec![f.radius()];
        assert!(f.after_breakdown());
        radii.push(f.radius());
        while f.grow() {
            radii.push(f.radius());
        }
        assert_eq!(radii[..2], [FIRST_RADIUS, SMALL_RADIUS]);
        assert_eq!(radii.iter().filter(|&&r| r == FIRST_RADIUS).count(), 1, "{radii:?}");
        assert!(radii.windows(2).skip(1).all(|w| w[1] > w[0]), "{radii:?}");
        // A second breakdown goes on growing from where it is.
        let before = f.radius();
        assert!(!f.after_breakdown() || f.radius() > before);
    }

    #[test]
    fn a_concavity_on_the_hull_is_a_self_bridge() {
        // A U-shaped region: the hull bridges its mouth.
        let u = [(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)];
        let count = u.len();
        let pts: Vec<Sample> = u
            .iter()
            .enumerate()
            .map(|(index, &(x, y))| Sample {
                p: Point::new(x, y),
                site: SiteId::Region(0),
                index,
                start: 0,
                count,
                closed: true,
            })
            .collect();
        assert_eq!(hull_bridges(&pts, 1e-9), vec![(SiteId::Region(0), SiteId::Region(0))]);
    }
}
