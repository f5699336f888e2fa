//! Maximal disks: the largest disk inside the shape that touches the
//! boundary at a given point (thesis 2.2.1, Algorithm 1 and Figure 2.2).
//!
//! The thesis grows the disk against every element in turn (O(n) per disk).
//! Here the disks tangent at one point are nested, so the maximal one is the
//! first contact of a growing disk, and a branch-and-bound search over a
//! hierarchy of boundary runs ([`ChainTree`]) finds it. Any maximal disk of
//! a subshape is a maximal disk of the whole shape (Observation 4), so the
//! divide step can ask this one index for every subshape.

use crate::kernel::direction::{Alignment, Heading};
use crate::kernel::fan::BoundSide;
use crate::kernel::growing_disk::GrowingDisk;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Orientation;
use crate::kernel::{AxisKernel, Contact, Disk, FilteredKernel, Point};
use crate::shape::{ChainTree, Element, ElementRef, JointKind, LoopKind, Shape2d};

/// Where a maximal disk touches the boundary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Footpoint {
    /// The element touched, indexed as in [`Shape2d::loops`] (normalised
    /// orientation).
    pub element: ElementRef,
    /// The touching point, model units.
    pub point: Point,
}

/// A maximal disk with its footpoints.
#[derive(Debug, Clone, PartialEq)]
pub struct MaxDisk {
    /// Centre, model units.
    pub center: Point,
    /// Radius, model units.
    pub radius: f64,
    /// Where the disk touches the boundary: every element whose own first
    /// contact with the growing disk comes within the contact tolerance
    /// ([`DiskFinder::contact_tolerance`]) of the disk's radius, at its
    /// point closest to the centre, merged where elements meet (a touch at
    /// a vertex is listed once). The first entry is the point the disk was
    /// grown from, the rest follow in loop and element order. Two or more
    /// for an ordinary disk, three or more at a branch point.
    pub footpoints: Vec<Footpoint>,
    /// The disk is the supporting circle of the arc it was grown from,
    /// which then touches it along its whole length: a leaf of the medial
    /// axis (thesis Observation 5).
    pub leaf_arc: bool,
}

/// Computes maximal disks of one shape; the run hierarchy is built once
/// (O(n)) and shared by every query. `Sync`: query from many threads.
/// Every construction and contact decision goes through the kernel `K`,
/// which the algorithms built on the finder reach through
/// [`DiskFinder::kernel`].
pub struct DiskFinder<'s, K: AxisKernel = FilteredKernel> {
    shape: &'s Shape2d,
    kernel: K,
    /// Runs of consecutive elements, for every query (whose points are
    /// mostly centres of maximal disks, where element boxes prune badly:
    /// on smooth boundaries the circle runs tangent to them, and among
    /// dense spikes a point lies in the boxes of a fiftieth of all
    /// elements).
    chains: ChainTree,
}

/// Disks tested per walk of the index in [`DiskFinder::any_intruder`]:
/// the final check's three (an edge's middle and the nodes it owns).
const WALK: usize = 4;

impl<'s> DiskFinder<'s> {
    /// Indexes the elements of `shape`, with the default kernel (exact
    /// signs, `f64` constructions).
    pub fn new(shape: &'s Shape2d) -> DiskFinder<'s> {
        DiskFinder::with_kernel(shape, FilteredKernel)
    }
}

impl<'s, K: AxisKernel> DiskFinder<'s, K> {
    /// Indexes the elements of `shape`; `kernel` answers every geometric
    /// question of the finder and of the algorithms that use it.
    pub fn with_kernel(shape: &'s Shape2d, kernel: K) -> DiskFinder<'s, K> {
        DiskFinder { shape, kernel, chains: ChainTree::new(shape.loops()) }
    }

    /// The kernel answering this finder's questions.
    pub fn kernel(&self) -> &K {
        &self.kernel
    }

    /// Contacts closer than this to the disk's circle count as footpoints:
    /// the shape's tolerance (by default 1e-9 × the bounding-box diagonal).
    pub fn contact_tolerance(&self) -> f64 {
        self.shape.tolerance()
    }

    /// The shape the finder indexes.
    pub fn shape(&self) -> &'s Shape2d {
        self.shape
    }

    /// The element nearest to `p` and its distance.
    pub fn nearest(&self, p: Point) -> Option<(ElementRef, f64)> {
        self.chains.nearest(self.shape.loops(), p)
    }

    /// An element reaching into the disk (`c`, `r`) by more than `tol`
    /// (model units), with its distance from `c`; `None` when the disk is
    /// empty within `tol`. Cheaper than [`nearest`](Self::nearest) for
    /// disks expected to be empty.
    pub fn intruder(&self, c: Point, r: f64, tol: f64) -> Option<(ElementRef, f64)> {
        self.chains.closer_than(self.shape.loops(), c, r - tol, |e| {
            self.kernel.element_contact(Disk::new(c, r), e, tol) == Contact::Overlapping
        })
    }

    /// [`intruder`](Self::intruder) for several disks (centre, radius),
    /// four of them per walk of the index: the index of a disk some
    /// element reaches into by more than `tol`, with the element and its
    /// distance.
    pub fn any_intruder(&self, disks: &[(Point, f64)], tol: f64) -> Option<(usize, ElementRef, f64)> {
        disks.chunks(WALK).enumerate().find_map(|(c, chunk)| {
            let mut shrunk = [(Point::default(), 0.0); WALK];
            for (s, &(p, r)) in shrunk.iter_mut().zip(chunk) {
                *s = (p, r - tol);
            }
            let hit = self.chains.any_closer_than(self.shape.loops(), &shrunk[..chunk.len()], |k, e| {
                self.kernel.element_contact(Disk::new(chunk[k].0, chunk[k].1), e, tol) == Contact::Overlapping
            });
            hit.map(|(k, r, d)| (c * WALK + k, r, d))
        })
    }

    /// Where the circle (`c`, `r`) of an empty disk touches the boundary:
    /// every element within the contact tolerance of it, at its point
    /// nearest to `c`, merged where elements meet; in loop and element order.
    pub fn touching(&self, c: Point, r: f64) -> Vec<Footpoint> {
        let tol = self.contact_tolerance();
        let mut near: Vec<(ElementRef, Point)> = Vec::new();
        let reach = Tolerance::new(tol).footpoint_search();
        self.chains.visit_within(c, r + reach, |er| {
            let e = self.shape.loops()[er.loop_index].element(er.element);
            let q = e.closest_point(c).1;
            if self.kernel.point_contact(Disk::new(c, r), q, tol) != Contact::Apart && self.faces(er, &e, q, c, r, tol)
            {
                near.push((er, q));
            }
        });
        near.sort_by_key(|&(er, _)| er);
        let out = apart(near.into_iter().map(|(element, point)| Footpoint { element, point }), tol);
        self.drop_clamped_ends(out, c)
    }

    /// Removes footpoints that are only an element's end point seen
    /// within the tolerance (the element's own closest point to the centre
    /// is clamped to its end) while the element beyond that smooth or
    /// convex vertex has the real tangency nearby: one contact, not two.
    /// At a reflex vertex the vertex itself is the contact and stays,
    /// unless the centre `c` lies outside the vertex's fan on the side of
    /// a neighbour with a contact of its own: that disk is tangent to the
    /// neighbour and passes the vertex within the tolerance, and a cut at
    /// the vertex too would leave the neighbour's last piece (where the
    /// axis changes from the neighbour to the vertex) in a sliver of its
    /// own.
    /// `feet` are in element order, one per element at most.
    fn drop_clamped_ends(&self, feet: Vec<Footpoint>, c: Point) -> Vec<Footpoint> {
        let tol = self.contact_tolerance();
        let keep: Vec<bool> = feet
            .iter()
            .map(|f| {
                let lp = &self.shape.loops()[f.element.loop_index];
                if lp.kind() == LoopKind::Point {
                    // No neighbour to hand the contact to.
                    return true;
                }
                let n = lp.len();
                let e = lp.element(f.element.element);
                let (vertex, other) = if f.point.dist(e.end()) <= tol {
                    ((f.element.element + 1) % n, (f.element.element + 1) % n)
                } else if f.point.dist(e.start()) <= tol {
                    (f.element.element, (f.element.element + n - 1) % n)
                } else {
                    return true;
                };
                // The neighbour touches too, at a point of its own inside.
                let v = lp.vertices()[vertex].p;
                let at_other = ElementRef { loop_index: f.element.loop_index, element: other };
                let neighbour_touches =
                    feet.binary_search_by(|g| g.element.cmp(&at_other)).is_ok_and(|i| feet[i].point.dist(v) > tol);
                if self.shape.joint(f.element.loop_index, vertex) == JointKind::Reflex {
                    let d = c - v;
                    let outside = if other == vertex {
                        // `f` ends its element; the neighbour starts at `v`.
                        self.kernel.turn(lp.element(other).start_tangent().perp(), d) == Orientation::Right
                    } else {
                        self.kernel.turn(lp.element(other).end_tangent().perp(), d) == Orientation::Left
                    };
                    return !(neighbour_touches && outside);
                }
                !neighbour_touches
            })
            .collect();
        feet.into_iter().zip(keep).filter(|(_, k)| *k).map(|(f, _)| f).collect()
    }

    /// [`seen_from_inside`], and on a curve site (whose two sides share
    /// their vertices) a touch at an element's end only where that end's
    /// vertex, on this side of the curve, faces the centre `c`: inside a
    /// reflex vertex's fan (within `tol`), on the inner side of a smooth
    /// one, never at a convex one (a disk larger than `tol` touches the
    /// elements there, not the corner). The other side's occurrence of the
    /// vertex is the footpoint.
    fn faces(&self, er: ElementRef, e: &Element, q: Point, c: Point, r: f64, tol: f64) -> bool {
        let lp = &self.shape.loops()[er.loop_index];
        if lp.kind() == LoopKind::Point {
            // Every direction is in a point's fan.
            return true;
        }
        if lp.kind() != LoopKind::Curve || r <= tol {
            return seen_from_inside(&self.kernel, e, q, c, r, tol);
        }
        let n = lp.len();
        let v = if q.dist(e.start()) <= tol {
            er.element
        } else if q.dist(e.end()) <= tol {
            (er.element + 1) % n
        } else {
            return self.kernel.heading(c - q, e.left_normal_at(q)) == Heading::Forward;
        };
        let m = c - lp.vertices()[v].p;
        match self.shape.joint(er.loop_index, v) {
            JointKind::Reflex => {
                let t_in = lp.element((v + n - 1) % n).end_tangent();
                let t_out = lp.element(v).start_tangent();
                self.kernel.vertex_fan_side(t_in, t_out, m, tol) == BoundSide::Within
            }
            JointKind::Smooth => self.kernel.heading(m, e.left_normal_at(q)) == Heading::Forward,
            JointKind::Convex => false,
        }
    }

    fn element(&self, r: ElementRef) -> Element {
        self.shape.loops()[r.loop_index].element(r.element)
    }

    /// The point at arc-length fraction `s` ∈ [0, 1] of element `at` and the
    /// unit normal there pointing into the shape (the interior is left of
    /// every loop). At `s` = 0 or 1 the normal is the element's own, not
    /// the neighbour's: at a reflex vertex it picks one disk of the fan.
    pub fn boundary_point(&self, at: ElementRef, s: f64) -> (Point, Point) {
        let e = self.shape.loops()[at.loop_index].element(at.element);
        let p = e.point_at(s.clamp(0.0, 1.0));
        (p, e.left_normal_at(p))
    }

    /// The maximal disk touching element `at` at arc-length fraction `s`
    /// (thesis Algorithm 1). Element ids in the result are as in
    /// [`Shape2d::loops`].
    ///
    /// At a convex corner (`s` = 0 or 1 there) the maximal disk is the
    /// corner itself: radius 0, touching both elements.
    pub fn max_disk(&self, at: ElementRef, s: f64) -> MaxDisk {
        let (p, n) = self.boundary_point(at, s);
        self.grow(at, s, p, n)
    }

    /// [`max_disk`](Self::max_disk) grown along the unit direction `n`
    /// instead of the element's own normal: at a reflex vertex (`s` = 0 or
    /// 1 there) any direction of the vertex's fan of normals picks one disk
    /// of the fan. `n` must point into the shape; at a point inside an
    /// element only the element's own normal (within rounding) makes sense.
    pub fn max_disk_toward(&self, at: ElementRef, s: f64, n: Point) -> MaxDisk {
        let (p, _) = self.boundary_point(at, s);
        self.grow(at, s, p, n)
    }

    fn grow(&self, at: ElementRef, s: f64, p: Point, n: Point) -> MaxDisk {
        let g = GrowingDisk { p, n };
        let lp = &self.shape.loops()[at.loop_index];
        // The vertex the disk grows from, with its joint and its other element.
        let vertex = match s {
            0.0 => Some((at.element, (at.element + lp.len() - 1) % lp.len())),
            1.0 => Some(((at.element + 1) % lp.len(), (at.element + 1) % lp.len())),
            _ => None,
        }
        .map(|(v, other)| (self.shape.joint(at.loop_index, v), ElementRef { element: other, ..at }));
        if let Some((JointKind::Convex, other)) = vertex {
            let footpoints = vec![Footpoint { element: at, point: p }, Footpoint { element: other, point: p }];
            return MaxDisk { center: p, radius: 0.0, footpoints, leaf_arc: false };
        }
        let shares_p = vertex.map(|(joint, other)| (other, joint == JointKind::Smooth));
        let tol = self.shape.tolerance();
        // Contacts at radii this small are the disk's own tangency point
        // seen through a neighbour sharing it; a genuine contact is at least
        // half the distance to another element, which validation keeps
        // above the tolerance.
        let t_min = Tolerance::new(tol).least_growth();
        // Grown along the element's own normal, the disk meets its own arc
        // again only as the arc's circle; grown along another direction of a
        // reflex vertex's fan (an augmenting disk at a curve site's end, where
        // the fan is half a turn), the arc is any other element.
        let own_element = lp.element(at.element);
        let along_normal = self.kernel.direction_match(own_element.left_normal_at(p), n, Tolerance::same_direction())
            == Alignment::Along;
        // The first contact of each element, as a key for the tree search.
        let contact = |er: ElementRef| {
            let e = self.element(er);
            let k = &self.kernel;
            if er == at {
                if along_normal {
                    own_contact(k, &g, &e)
                } else {
                    neighbour_touch(k, &g, &e, t_min, tol, false)
                }
            } else {
                match shares_p {
                    Some((other, smooth)) if other == er => neighbour_touch(k, &g, &e, t_min, tol, smooth),
                    _ => first_touch(k, &g, &e, t_min),
                }
            }
        };
        // Footpoints: every element whose own first contact comes within the
        // tolerance of the disk's. (Elements merely near the circle, like
        // the boundary running on from a smooth footpoint, are not contacts.)
        let near = self.chains.first_contacts(&g, tol, contact);
        let Some(&(_, radius)) = near.first() else {
            // Cannot happen inside a bounded shape; an infinite radius keeps
            // the answer honest rather than inventing one.
            let footpoints = vec![Footpoint { element: at, point: p }];
            return MaxDisk { center: p, radius: f64::INFINITY, footpoints, leaf_arc: false };
        };
        let center = g.center(radius);
        // The arc grown from is among the first contacts: the disk is its circle.
        let leaf_arc = along_normal && near.iter().any(|&(er, _)| er == at);
        let first = Footpoint { element: at, point: p };
        let others = near.iter().filter(|&&(er, _)| !(er == at && along_normal)).filter_map(|&(er, _)| {
            let e = self.element(er);
            let q = e.closest_point(center).1;
            self.faces(er, &e, q, center, radius, tol).then_some(Footpoint { element: er, point: q })
        });
        let mut found = apart(std::iter::once(first).chain(others), tol);
        found[1..].sort_by_key(|f| f.element);
        let mut footpoints = self.drop_clamped_ends(found, center);
        // The point grown from stays first, whatever the filter said.
        if footpoints.first() != Some(&first) {
            footpoints.retain(|f| *f != first);
            footpoints.insert(0, first);
        }
        MaxDisk { center, radius, footpoints, leaf_arc }
    }
}

/// The element the disk grows from touches it again only if it is an arc
/// curving towards the inside: at its own radius, where the disk becomes
/// its supporting circle.
fn own_contact(k: &impl AxisKernel, g: &GrowingDisk, e: &Element) -> Option<f64> {
    match e {
        Element::Arc(a) if k.heading(g.n, a.center - g.p) == Heading::Forward => Some(a.radius),
        _ => None,
    }
}

/// [`first_touch`] for the other element at the vertex the disk grows
/// from. Contacts within `tol` of that vertex are the vertex itself, seen
/// through rounding (near a smooth joint the tangency equations are 0/0),
/// and are ignored. At a smooth joint, an arc curving inwards more tightly
/// than the disk enters it right at the vertex once the disk outgrows the
/// arc's radius; at a reflex joint the element leaves the disk there and
/// can only come back through its far end or a tangency elsewhere.
fn neighbour_touch(
    k: &impl AxisKernel,
    g: &GrowingDisk,
    e: &Element,
    t_min: f64,
    tol: f64,
    smooth: bool,
) -> Option<f64> {
    let mut best = touches(k, g, e, t_min).filter(|&(_, q)| q.dist(g.p) > tol).map(|(t, _)| t).fold(None, min_some);
    if let (true, Element::Arc(a)) = (smooth, e) {
        if k.heading(g.n, a.center - g.p) == Heading::Forward {
            best = min_some(best, a.radius);
        }
    }
    best
}

fn min_some(best: Option<f64>, t: f64) -> Option<f64> {
    Some(best.map_or(t, |b| b.min(t)))
}

/// The first radius above `t_min` at which the growing disk touches `e`:
/// at an end point, or where its circle is tangent to the element's
/// supporting line or circle at a point of the element.
fn first_touch(k: &impl AxisKernel, g: &GrowingDisk, e: &Element, t_min: f64) -> Option<f64> {
    touches(k, g, e, t_min).map(|(t, _)| t).fold(None, min_some)
}

/// Every radius above `t_min` at which the growing disk's circle meets `e`
/// at an end point or is tangent to it at an inner point, with that point.
fn touches(k: &impl AxisKernel, g: &GrowingDisk, e: &Element, t_min: f64) -> impl Iterator<Item = (f64, Point)> {
    let mut out = [None; 4];
    out[0] = k.through_point(g, e.start()).map(|t| (t, e.start()));
    out[1] = k.through_point(g, e.end()).map(|t| (t, e.end()));
    match *e {
        Element::Segment(s) => {
            let d = s.b - s.a;
            for (slot, (t, q)) in
                out[2..].iter_mut().zip(k.tangent_to_line(g, s.a, d.perp().unit()).into_iter().flatten())
            {
                if (0.0..=1.0).contains(&(d.dot(q - s.a) / d.norm2())) {
                    *slot = Some((t, q));
                }
            }
        }
        Element::Arc(a) => {
            for (slot, (t, q)) in
                out[2..].iter_mut().zip(k.tangent_to_circle(g, a.center, a.radius).into_iter().flatten())
            {
                if a.spans_direction(q) {
                    *slot = Some((t, q));
                }
            }
        }
    }
    out.into_iter().flatten().filter(move |&(t, _)| t > t_min)
}

/// True when a disk centred at `c` (radius `r`) touches element `e` at its
/// point `q` from the element's interior side, or at one of its ends. A
/// contact inside an element from the other side reaches it through a
/// needle thinner than the tolerance, past the needle's other side, which
/// is the real contact.
fn seen_from_inside(k: &impl AxisKernel, e: &Element, q: Point, c: Point, r: f64, tol: f64) -> bool {
    r <= tol
        || q.dist(e.start()) <= tol
        || q.dist(e.end()) <= tol
        || k.heading(c - q, e.left_normal_at(q)) == Heading::Forward
}

/// The footpoints of `feet` (in order) that lie farther than `tol` from
/// every footpoint kept before them. A disk that hugs a long stretch of
/// boundary within the tolerance touches thousands of elements (a nearly
/// circular curve of 3·10^5 arcs), so kept points are found through a
/// grid of cells `tol` wide, not by comparing with each.
fn apart(feet: impl Iterator<Item = Footpoint>, tol: f64) -> Vec<Footpoint> {
    let mut out: Vec<Footpoint> = Vec::new();
    let mut grid: crate::util::fast_hash::FastMap<(i64, i64), Vec<usize>> = Default::default();
    let cell = |p: Point| ((p.x / tol).floor() as i64, (p.y / tol).floor() as i64);
    for f in feet {
        // Most disks have two or three contacts: compared one by one
        // until the grid pays (it was a fifth of the divide step's
        // allocations).
        if out.len() < GRID_FROM {
            if out.iter().all(|k| k.point.dist(f.point) > tol) {
                out.push(f);
                if out.len() == GRID_FROM {
                    for (k, g) in out.iter().enumerate() {
                        grid.entry(cell(g.point)).or_default().push(k);
                    }
                }
            }
            continue;
        }
        let (i, j) = cell(f.point);
        // Saturating: a huge coordinate over a tiny tolerance shares the
        // extreme cell, where the points are compared one by one.
        let taken = (i.saturating_sub(1)..=i.saturating_add(1))
            .flat_map(|a| (j.saturating_sub(1)..=j.saturating_add(1)).map(move |b| (a, b)))
            .filter_map(|k| grid.get(&k))
            .flatten()
            .any(|&k| out[k].point.dist(f.point) <= tol);
        if !taken {
            grid.entry((i, j)).or_default().push(out.len());
            out.push(f);
        }
    }
    out
}

/// Kept contacts from which [`apart`] finds close ones through its grid.
const GRID_FROM: usize = 16;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn apart_keeps_what_comparing_with_every_kept_point_keeps() {
        let mut rng = crate::util::mix::Mix(3);
        let tol = 1e-3;
        for round in 0..50 {
            // Clusters a few tolerances wide, so that many points fall
            // within the tolerance of an earlier one and many do not.
            let feet: Vec<Footpoint> = (0..200)
                .map(|i| {
                    let base = Point::new((i % 7) as f64, (round % 3) as f64 * 1e6);
                    let p = base + Point::new(rng.next() - 0.5, rng.next() - 0.5) * (8.0 * tol);
                    Footpoint { element: ElementRef { loop_index: 0, element: i }, point: p }
                })
                .collect();
            let mut want: Vec<Footpoint> = Vec::new();
            for f in &feet {
                if want.iter().all(|k| k.point.dist(f.point) > tol) {
                    want.push(*f);
                }
            }
            assert!(want.len() > 7 && want.len() < 200);
            assert_eq!(apart(feet.into_iter(), tol), want);
        }
    }
}
