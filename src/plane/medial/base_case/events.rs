//! Events: the disks known without search (ports, corners, joints, fan
//! ends, leaf arcs), each with its footpoints on the cycle.

use super::port::Port;
use super::sites::SiteRef;
use super::{BaseCaseError, Builder, EventKind, Key};
use crate::kernel::apollonius::Site;
use crate::kernel::direction::{Alignment, Heading};
use crate::kernel::growing_disk::GrowingDisk;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Crossing;
use crate::kernel::Disk;
use crate::kernel::SitePiece;
use crate::kernel::{AxisKernel, Contact, Point};
use crate::plane::axis::Primitive;
use crate::plane::medial::decompose::subshape::Cut;
use crate::shape::{JointKind, Shape2d};

/// An event of the base case: its index in the builder's events (and in
/// the local axis's nodes, which keep the events' order).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(super) struct EventRef(pub(super) usize);

impl std::ops::Index<EventRef> for Vec<Event> {
    type Output = Event;
    #[inline]
    fn index(&self, e: EventRef) -> &Event {
        &self[e.0]
    }
}

impl std::ops::IndexMut<EventRef> for Vec<Event> {
    #[inline]
    fn index_mut(&mut self, e: EventRef) -> &mut Event {
        &mut self[e.0]
    }
}

pub(super) struct Event {
    pub(super) center: Point,
    pub(super) radius: f64,
    pub(super) kind: EventKind,
    /// Footpoints in cycle order, distinct.
    pub(super) feet: Vec<Key>,
    /// Primitives the disk touches along their whole range (an arc and its
    /// own circle): pockets made only of these are empty.
    pub(super) whole: Vec<SiteRef>,
}

impl<K: AxisKernel> Builder<'_, K> {
    pub(super) fn k(&self) -> &K {
        self.finder.kernel()
    }

    /// True when the disk (`c`, `r`) is event `e`'s own (centres and radii
    /// within [`Tolerance::same_event`]): one event, not two.
    pub(super) fn same_disk(&self, e: &Event, c: Point, r: f64) -> bool {
        let near = self.tol.same_event();
        e.center.dist(c) <= near && (e.radius - r).abs() <= near
    }

    /// How the circle (`c`, `r`) meets site `i`'s piece, within `tol`.
    pub(super) fn contact(&self, i: SiteRef, c: Point, r: f64, tol: f64) -> Contact {
        let disk = Disk::new(c, r);
        self.clear_contact(i, disk, tol).unwrap_or_else(|| self.k().piece_contact(disk, &self.piece(i), tol))
    }

    /// How `disk` meets site `i` when its bounding disk or its distance
    /// without trigonometry decides it within `tol`; `None` near contact.
    fn clear_contact(&self, i: SiteRef, disk: Disk, tol: f64) -> Option<Contact> {
        let s = &self.sites[i];
        self.k().bound_contact(disk, s.bound, tol).or_else(|| self.k().quick_contact(disk, &self.piece(i), s.ends, tol))
    }

    /// True when the disk (`c`, `r`) crosses one of the auxiliary arcs.
    pub(super) fn leaves_subshape(&self, c: Point, r: f64) -> bool {
        self.aux.iter().any(|p| self.k().arc_crossing(&p.arc, Disk::new(c, r), self.tol.touch()) == Crossing::Crosses)
    }

    /// Every site the circle (`c`, `r`) touches within the tolerance.
    pub(super) fn touching(&self, c: Point, r: f64) -> (Vec<Key>, Vec<SiteRef>) {
        let mut feet = Vec::new();
        let mut whole = Vec::new();
        for i in self.site_refs() {
            if let Site::Circle { o, r: rc, outside: false } = self.sites[i].site {
                if c.dist(o) <= self.tol.touch() && (rc - r).abs() <= self.tol.touch() {
                    feet.push((i, self.key(i, self.sites[i].u0, r)));
                    feet.push((i, self.key(i, self.sites[i].u1, r)));
                    whole.push(i);
                    continue;
                }
            }
            let (disk, s) = (Disk::new(c, r), &self.sites[i]);
            if self.clear_contact(i, disk, self.touch).is_some() {
                continue;
            }
            let (contact, u) = self.k().piece_contact_at(disk, &self.piece(i), self.touch);
            if contact == Contact::Touching && self.faces_inside(i, c, u) {
                if let Site::Point(q) = self.sites[i].site {
                    // A disk through a reflex vertex from outside its fan
                    // (in this subshape) touches the element beside it.
                    let w = self.fraction(i, self.param(i, c, 0.0));
                    let slack = self.tol.fan_slack() / self.length(i, 0.0, 1.0, c.dist(q)).max(f64::MIN_POSITIVE);
                    if w < -slack || w > 1.0 + slack {
                        continue;
                    }
                }
                // Strictly inside a fan's or an arc's range the nearest
                // point's parameter is the tangency's (one angle, not two).
                let (lo, hi) = (s.u0.min(s.u1), s.u0.max(s.u1));
                let free = match s.site {
                    Site::Point(_) | Site::Circle { .. } if lo < u && u < hi => u,
                    _ => self.param(i, c, r),
                };
                let k = self.key_of_contact(i, u, free, r);
                // A touch at a reflex vertex belongs to the vertex's fan,
                // at the disk's direction, not to the element's end.
                if self.fan_owns(i, k) {
                    continue;
                }
                feet.push((i, k));
            }
        }
        // A contact at an element's clamped end, where the joined
        // neighbour has a contact of its own, is that neighbour's contact
        // seen within the tolerance (nearly concentric arcs smear one
        // contact over a range): one footpoint, not two.
        let n = self.n();
        let has = |j: SiteRef, feet: &[(SiteRef, Key)]| feet.iter().any(|&(s, k)| s == j && k.w > 0.0 && k.w < 1.0);
        let taken = |&(i, k): &(SiteRef, Key)| {
            let at_start = k.site == i && k.w == 0.0;
            let at_end = k.site != i || k.w == 1.0;
            let prev = i.prev(n);
            let next = i.next(n);
            let start_taken = at_start && self.sites[prev].joined_next && has(prev, &feet) && !has(i, &feet);
            let end_taken = at_end && self.sites[i].joined_next && has(next, &feet) && !has(i, &feet);
            start_taken || end_taken
        };
        let kept = feet.iter().filter(|f| !taken(f)).map(|&(_, k)| k).collect();
        (kept, whole)
    }

    /// Contacts of a constructed disk count as footpoints within this
    /// distance ([`Tolerance::constructed_touch`]); far from the origin,
    /// rounding of the coordinates themselves sets the floor.
    pub(super) fn touch_tol(shape: &Shape2d, tol: Tolerance) -> f64 {
        let bb = shape.bbox();
        let magnitude = bb.min.x.abs().max(bb.min.y.abs()).max(bb.max.x.abs()).max(bb.max.y.abs()) + bb.diagonal();
        tol.constructed_touch(magnitude)
    }

    /// True when key `k`, found on element site `i`, is an end of `i`
    /// where a reflex vertex's fan joins it.
    pub(super) fn fan_owns(&self, i: SiteRef, k: Key) -> bool {
        let n = self.n();
        let is_fan = |j: SiteRef| matches!(self.sites[j].prim, Primitive::Vertex { .. });
        if is_fan(i) {
            return false;
        }
        let prev = i.prev(n);
        // `k` may already be the next site's start (a joined end).
        let at_start = k.site == i && k.w == 0.0 && self.sites[prev].joined_next && is_fan(prev);
        let at_end = k.site == i.next(n) && k.w == 0.0 && k.site != i && is_fan(k.site);
        at_start || at_end
    }

    pub(super) fn add_event(
        &mut self,
        center: Point,
        radius: f64,
        kind: EventKind,
        mut feet: Vec<Key>,
        whole: Vec<SiteRef>,
    ) -> EventRef {
        // The same disk found twice (a joint disk that is also a branch
        // point or a leaf circle) is one event with all its footpoints.
        // The two auxiliary arcs of one augmenting disk (thesis 2.3.1) are
        // the two sides of a cycle cut open: two ends of this axis, glued
        // into one node only with the other subshapes.
        let twin = |e: &Event| matches!((e.kind, kind), (EventKind::Port(a), EventKind::Port(b)) if a == b);
        let same = self.events.iter().position(|e| self.same_disk(e, center, radius) && !twin(e));
        let id = EventRef(match same {
            Some(i) => {
                let e = &mut self.events[i];
                feet.append(&mut e.feet);
                e.whole.extend(whole);
                if matches!(kind, EventKind::Port(_)) {
                    e.kind = kind;
                }
                i
            }
            None => {
                self.events.push(Event { center, radius, kind, feet: Vec::new(), whole });
                self.events.len() - 1
            }
        });
        feet.sort_by(|a, b| self.pos(*a).total_cmp(&self.pos(*b)));
        feet.dedup_by(|a, b| a.site == b.site && (a.w - b.w).abs() <= Tolerance::same_fraction());
        let e = &mut self.events[id];
        e.feet = feet;
        e.whole.sort_unstable();
        e.whole.dedup();
        id
    }

    /// The maximal disk grown at the start of site `j` (a joint with the
    /// previous site), tangent with normal `nrm`; `own` are the sites whose
    /// supporting curve is tangent there (skipped, but an arc among them
    /// curving inwards caps the radius at its own).
    pub(super) fn grow(&self, p: Point, nrm: Point, own: &[SiteRef]) -> Option<Disk> {
        let g = GrowingDisk { p, n: nrm };
        let t_min = self.tol.least_growth();
        let mut best = f64::INFINITY;
        // The piece ends first (boundary points, always safe contacts, and
        // cheap): the smallest of them rules out most carriers below.
        for i in self.site_refs() {
            let s = &self.sites[i];
            if own.contains(&i) {
                if let Site::Circle { o, r, outside: false } = s.site {
                    if self.k().heading(nrm, o - p) == Heading::Forward {
                        best = best.min(r);
                    }
                }
                continue;
            }
            for q in s.ends {
                if q.dist(p) > self.tol.touch() {
                    if let Some(t) = self.k().through_point(&g, q).filter(|&t| t > t_min) {
                        best = best.min(t);
                    }
                }
            }
        }
        for i in self.site_refs() {
            let s = &self.sites[i];
            if own.contains(&i) || matches!(s.site, Site::Point(_)) {
                continue;
            }
            // The disks grown at `p` are nested: a site wholly outside the
            // smallest found so far cannot touch a smaller one.
            if best.is_finite()
                && self.k().bound_contact(Disk::new(g.center(best), best), s.bound, self.tol.touch())
                    == Some(Contact::Apart)
            {
                continue;
            }
            let (lo, hi) = (s.u0.min(s.u1), s.u0.max(s.u1));
            if let Some(t) = self.k().touch_site(&g, &s.site).filter(|&t| t > t_min && t < best) {
                let c = g.center(t);
                let slack = match s.site {
                    Site::Circle { r, .. } => self.tol.touch() / r,
                    _ => self.tol.touch(),
                };
                // An arc's sweep decided by signs where the direction is
                // clearly in or out (the slack is far above rounding).
                let in_range = self.piece(i).sweep_side(c, s.ends, slack).unwrap_or_else(|| {
                    let u = self.param(i, c, t);
                    u >= lo - slack && u <= hi + slack
                });
                if in_range && s.site.contact(c, t).dist(p) > self.tol.touch() {
                    best = best.min(t);
                }
            }
        }
        // A dividing disk tangent at `p` is the maximal disk there (its
        // other contacts may lie outside this subshape).
        for Port { arc, .. } in &self.aux {
            let v = arc.center - p;
            if (v.norm() - arc.radius).abs() <= self.tol.touch()
                && self.k().alignment(nrm, v, self.tol.touch()) == Alignment::Along
            {
                best = best.min(arc.radius);
            }
        }
        best.is_finite().then(|| Disk::new(g.center(best), best))
    }

    pub(super) fn collect_events(&mut self, cuts: &[Cut]) -> Result<(), BaseCaseError> {
        self.set_joint_normals();
        let n = self.n();
        // Ports: the auxiliary arcs, between the site before and after.
        for &Port { disk, site_after: next, .. } in &self.aux.clone() {
            let c = cuts[disk];
            let next = SiteRef(next % n);
            let feet = vec![Key::at(next.prev(n), 1.0), Key::at(next, 0.0)];
            self.add_event(c.center, c.radius, EventKind::Port(disk as u32), feet, Vec::new());
        }
        // Joints between consecutive sites.
        for i in self.site_refs() {
            if !self.sites[i].joined_next {
                continue;
            }
            let j = i.next(n);
            let (a, b) = (self.sites[i], self.sites[j]);
            let key = Key::at(j, 0.0);
            let p = self.point_of(j, b.u0);
            // The element whose normal the joint's disk grows along: the
            // one after the joint, or before it at the start of a fan.
            let grow_from = match (a.prim.element(), b.prim.element()) {
                (Some(_), Some(eb)) => {
                    if self.shape.joint(eb.loop_index, eb.element) == JointKind::Convex {
                        self.add_event(p, 0.0, EventKind::Corner, vec![key], Vec::new());
                        continue;
                    }
                    (eb, false)
                }
                (Some(ea), None) => (ea, true),
                (None, Some(eb)) => (eb, false),
                (None, None) => {
                    // Two pieces of one point site's fan: the maximal disk
                    // through the point in the direction where they meet.
                    if a.prim != b.prim {
                        continue;
                    }
                    let Site::Point(q) = b.site else { continue };
                    let nrm = Point::new(b.u0.cos(), b.u0.sin());
                    let (c, r) = self.grow(q, nrm, &[i, j]).ok_or(BaseCaseError::NoDisk(q))?.parts();
                    let (feet, whole) = self.touching(c, r);
                    let feet = self.one_per_hug(c, r, feet, &[key], &whole);
                    self.add_event(c, r, EventKind::Joint, feet, whole);
                    continue;
                }
            };
            let (er, at_end) = grow_from;
            let nrm = self.sites[j].joint_normal.unwrap_or_else(|| {
                let e = self.shape.loops()[er.loop_index].element(er.element);
                if at_end { e.end_tangent() } else { e.start_tangent() }.perp()
            });
            let (c, r) = self.grow(p, nrm, &[i, j]).ok_or(BaseCaseError::NoDisk(p))?.parts();
            let (feet, whole) = self.touching(c, r);
            let feet = self.one_per_hug(c, r, feet, &[key], &whole);
            self.add_event(c, r, EventKind::Joint, feet, whole);
        }
        // Arcs whose own circle is the maximal disk at their middle.
        for i in self.site_refs() {
            let Site::Circle { o, r, outside: false } = self.sites[i].site else { continue };
            let um = 0.5 * (self.sites[i].u0 + self.sites[i].u1);
            let (p, nrm) = crate::kernel::bisector::footpoint(&self.sites[i].site, um);
            if let Some(Disk { radius: t, .. }) = self.grow(p, nrm, &[i]) {
                if (t - r).abs() <= self.tol.touch() && !self.leaves_subshape(o, r) {
                    let (feet, whole) = self.touching(o, r);
                    let feet = self.one_per_hug(o, r, feet, &[], &whole);
                    self.add_event(o, r, EventKind::Leaf, feet, whole);
                }
            }
        }
        Ok(())
    }

    /// True when site `i` between fractions `w0` and `w1` stays within the
    /// tolerance of the circle (`c`, `r`): a footpoint smeared by rounding
    /// into two (a disk through a vertex just beside its tangency point).
    pub(super) fn hugs(&self, i: SiteRef, w0: f64, w1: f64, c: Point, r: f64) -> bool {
        if let Site::Point(_) = self.sites[i].site {
            // A disk through the vertex touches it in one direction only;
            // the rest of the fan is real boundary for the axis.
            return false;
        }
        let (u0, u1) = (self.u_at(i, w0), self.u_at(i, w1));
        let piece = SitePiece { u0, u1, ..self.piece(i) };
        let ends = [self.point_of(i, u0), self.point_of(i, u1)];
        self.k().piece_hugs(Disk::new(c, r), &piece, ends, self.tol.hug())
    }
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{rectangle, shape, with_events};
    use super::*;

    #[test]
    fn a_rectangles_events_are_its_four_corners() {
        with_events(&rectangle(), |b| {
            assert_eq!(b.events.len(), 4);
            assert!(b.events.iter().all(|e| e.kind == EventKind::Corner && e.radius == 0.0 && e.feet.len() == 1));
        });
    }

    #[test]
    fn a_smooth_joint_grows_the_maximal_disk_there() {
        // A stadium: two half circles of radius 1 joined to two segments.
        let stadium = shape(&[(0.0, 0.0, 0.0), (2.0, 0.0, 1.0), (2.0, 2.0, 0.0), (0.0, 2.0, 1.0)]);
        with_events(&stadium, |b| {
            let joints: Vec<&Event> = b.events.iter().filter(|e| e.kind == EventKind::Joint).collect();
            // The disk at both joints of a half circle is its circle: one
            // event with two footpoints at each end.
            assert_eq!(joints.len(), 2);
            for e in joints {
                assert_eq!(e.feet.len(), 2);
                // The disk of radius 1 centred on the stadium's spine.
                assert!((e.radius - 1.0).abs() < 1e-12 && (e.center.y - 1.0).abs() < 1e-12, "{:?}", e.center);
                assert!(e.center.x.abs() < 1e-12 || (e.center.x - 2.0).abs() < 1e-12);
            }
        });
    }

    #[test]
    fn touching_finds_every_site_a_disk_meets() {
        with_events(&rectangle(), |b| {
            // The disk of radius 1 at (1, 1) touches the bottom, top and left.
            let (feet, whole) = b.touching(Point::new(1.0, 1.0), 1.0);
            let mut sites: Vec<usize> = feet.iter().map(|k| k.site.0).collect();
            sites.sort_unstable();
            assert_eq!(sites, vec![0, 2, 3]);
            assert!(whole.is_empty());
        });
    }
}
