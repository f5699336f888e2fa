//! The branch point of a pocket: the empty Apollonius disk touching the
//! pocket's two sides and a third site in between.

use super::events::EventRef;
use super::sites::SiteRef;
use super::{Builder, Key};
use crate::kernel::apollonius::Site;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Contact, Point};

/// A branch point found in a pocket: its disk, its three contacts as
/// footpoints, and the same contacts before coinciding ones were pulled
/// apart.
pub(super) struct Branch {
    pub(super) center: Point,
    pub(super) radius: f64,
    pub(super) contacts: [Key; 3],
    pub(super) snapped: [Key; 3],
}

/// The part of the cycle between two consecutive footpoints of one event,
/// walked into from both ends.
#[derive(Debug, Clone, Copy)]
pub(super) struct Pocket {
    /// The event whose disk bounds the pocket.
    pub(super) event: EventRef,
    /// The footpoint the pocket starts at.
    pub(super) start: Key,
    /// Its length along the cycle (offsets; a whole turn for an event
    /// with one footpoint).
    pub(super) span: f64,
    /// The site just after the start and the one just before the end.
    pub(super) first_site: SiteRef,
    pub(super) last_site: SiteRef,
}

/// A disk tangent to the pocket's two sides and a third site, before the
/// emptiness test.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    /// Offset of its contact on the pocket's first site: the candidates are
    /// tried in this order.
    first_offset: f64,
    third: SiteRef,
    center: Point,
    radius: f64,
}

impl<K: AxisKernel> Builder<'_, K> {
    /// The branch point in `pocket`: an empty disk other than its event's
    /// own, touching the pocket's first site before offset `x1` (where the
    /// first other event's footpoint was met), its last site after offset
    /// `y2` (the last one met) and a third site in between. The one
    /// touching the first site first wins.
    pub(super) fn branch(&self, pocket: &Pocket, x1: f64, y2: f64) -> Option<Branch> {
        let Pocket { event: d, start: a, span, first_site: s1, last_site: s2 } = *pocket;
        // The pocket's own disk touches its two sites at the pocket's ends
        // (and a third site there, at a vertex): it would merge back into
        // event `d` and the pocket be walked again, for ever. But a branch
        // point within rounding of `d` (where the boundary nearly follows
        // the disks' circles, events lie a few tolerances apart) touches a
        // third site inside the pocket that `d` does not: merged into `d`,
        // it splits the pocket.
        let is_own = |c: Point, r: f64, t: SiteRef| {
            let own = &self.events[d];
            self.same_disk(own, c, r) && {
                let w = self.fraction(t, self.param(t, c, r));
                own.feet.iter().any(|k| k.site == t) || w <= 0.0 || w >= 1.0
            }
        };
        // Candidates that touch the three sites within their ranges, in
        // the pocket, by where they touch `s1`; the first empty one wins.
        // (Emptiness costs O(n) each, so it is tested last and in order.)
        let mut candidates: Vec<Candidate> = Vec::new();
        for t in self.site_refs() {
            if t == s1 || t == s2 {
                continue;
            }
            // The third contact lies between offsets x1 and y2, give or
            // take the slack: skip sites wholly outside. A contact at a
            // site's end may be keyed as the next site's start, one further
            // on; a site that holds `a` or whose end wraps round stays.
            let (o_start, o_end) = (self.offset(a, Key::at(t, 0.0)), self.offset(a, Key::at(t, 1.0)));
            let whole = o_start <= o_end && o_end + 1.0 < 2.0 * self.n() as f64;
            let cap = Tolerance::branch_contact_slack_cap();
            if whole && (o_end + 1.0 < x1 - cap || o_start > y2 + cap) {
                continue;
            }
            for Disk { center: c, radius: r } in
                self.k().tritangent_disks([self.sites[s1].site, self.sites[s2].site, self.sites[t].site])
            {
                if r <= self.tol.touch() || !c.is_finite() || is_own(c, r, t) {
                    continue;
                }
                // Near-degenerate triples (many disks nearly alike, as at
                // the centre of a symmetric shape) place contacts a few
                // tolerances off: allow that much, in length, per site.
                let slack = |i: SiteRef| {
                    (self.tol.branch_contact_slack() / self.length(i, 0.0, 1.0, r).max(f64::MIN_POSITIVE)).min(cap)
                };
                // A tangency past an element's end at an auxiliary arc,
                // along a curve the disk nearly follows (contacts there are
                // placed only to about √(τ·r) in length), that touches the
                // end within τ in distance is a contact at the end: the
                // element beyond belongs to another subshape. (Past a joint
                // the next site is tried for itself; a fan's end is its
                // point, which every disk through it touches.)
                let near_end = |i: SiteRef, w: f64| {
                    let s = &self.sites[i];
                    let past_end = w > 0.5;
                    let joined = if past_end { s.joined_next } else { self.sites[i.prev(self.n())].joined_next };
                    !joined
                        && !matches!(s.site, Site::Point(_))
                        && (s.ends[usize::from(past_end)].dist(c) - r).abs() <= self.tol.touch()
                };
                let at = |i: SiteRef| {
                    let u = self.param(i, c, r);
                    let w = self.fraction(i, u);
                    let sl = slack(i);
                    ((-sl..=1.0 + sl).contains(&w) || near_end(i, w)).then(|| self.offset(a, self.key(i, u, r)))
                };
                let (Some(o1), Some(o2), Some(ot)) = (at(s1), at(s2), at(t)) else { continue };
                let o2 = if o2 == 0.0 { span } else { o2 };
                let (sl1, sl2, slt) = (slack(s1), slack(s2), slack(t));
                if o1 > x1 + sl1 || o2 < y2 - sl2 || ot < x1 - slt || ot > y2 + slt || o1 >= o2 {
                    continue;
                }
                // Touching all three: the construction is ill-conditioned
                // for nearly parallel lines, where a root can miss a site.
                if [s1, s2, t]
                    .iter()
                    .any(|&i| self.contact(i, c, r, self.tol.branch_contact_slack()) != Contact::Touching)
                {
                    continue;
                }
                candidates.push(Candidate { first_offset: o1, third: t, center: c, radius: r });
            }
        }
        // Stable: among equal offsets the first found wins, as it did.
        candidates.sort_by(|x, y| x.first_offset.total_cmp(&y.first_offset));
        let Candidate { third: t, center: c, radius: r, .. } =
            candidates.into_iter().find(|&Candidate { center: c, radius: r, .. }| {
                // Empty: no site closer than the radius, inside the subshape,
                // and for the whole shape (a subshape's own primitives do not
                // see past its auxiliary arcs).
                !self.site_refs().any(|i| self.contact(i, c, r, self.tol.touch()) == Contact::Overlapping)
                    && self.finder.intruder(c, r, self.tol.intruder()).is_none()
            })?;
        let key = |i: SiteRef| self.key(i, self.param(i, c, r), r);
        let raw = [key(s1), key(s2), key(t)];
        let mut keys = raw;
        let sites = [s1, s2, t];
        // Two contacts within the tolerance of one vertex (a disk in the
        // wedge of a nearly flat convex corner) are still two contacts,
        // each on its own side of the vertex: keep them apart so the
        // corner's own event lies between them.
        for x in 0..3 {
            for y in 0..3 {
                if x != y && raw[x] == raw[y] {
                    let w = self.fraction(sites[x], self.param(sites[x], c, r));
                    keys[x] = Key::at(sites[x], if w > 0.5 { 1.0 - Tolerance::nudge() } else { Tolerance::nudge() });
                }
            }
        }
        Some(Branch { center: c, radius: r, contacts: keys, snapped: raw })
    }
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{shape, with_events};
    use super::super::EventKind;
    use super::*;

    #[test]
    fn a_triangles_branch_point_is_its_incircle() {
        let (a, b, c) = (Point::new(0.0, 0.0), Point::new(5.0, 0.0), Point::new(1.0, 3.0));
        let tri = shape(&[(a.x, a.y, 0.0), (b.x, b.y, 0.0), (c.x, c.y, 0.0)]);
        // The incentre weighs each vertex by the opposite side's length;
        // the inradius is the area over the half perimeter.
        let (la, lb, lc) = (b.dist(c), c.dist(a), a.dist(b));
        let p = la + lb + lc;
        let centre = (a * la + b * lb + c * lc) * (1.0 / p);
        let radius = (b - a).cross(c - a).abs() / p;
        let axis = with_events(&tri, |bld| bld.walk()).unwrap();
        let branches: Vec<_> = axis.nodes.iter().filter(|n| n.kind == EventKind::Branch).collect();
        assert_eq!(branches.len(), 1);
        assert!(branches[0].center.dist(centre) < 1e-12 && (branches[0].radius - radius).abs() < 1e-12);
    }

    #[test]
    fn no_branch_point_outside_the_pocket() {
        let tri = shape(&[(0.0, 0.0, 0.0), (5.0, 0.0, 0.0), (1.0, 3.0, 0.0)]);
        with_events(&tri, |bld| {
            // The pocket of the first corner, with its far end met at the
            // pocket's very start: no disk touches its first site that early.
            let d = 0;
            let start = bld.events[d].feet[0];
            let n = bld.n();
            let (s1, _) = bld.site_after(start);
            let (s2, _) = bld.site_before(start);
            let pocket = Pocket { event: EventRef(d), start, span: 2.0 * n as f64, first_site: s1, last_site: s2 };
            assert!(bld.branch(&pocket, -1.0, 2.0 * n as f64).is_none());
        });
    }
}
