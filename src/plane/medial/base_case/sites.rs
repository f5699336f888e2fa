//! Positions on the cycle of sites: footpoint parameters, their keys
//! (site and fraction), offsets along the cycle, distances and lengths.

use super::Builder;
use crate::kernel::apollonius::Site;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::SitePiece;
use crate::kernel::{AxisKernel, CarrierSide, Point};
use crate::plane::axis::Primitive;
use crate::shape::{Element, JointKind};

/// A primitive as one subshape sees it: a range of footpoint parameters
/// (see [`crate::kernel::bisector::footpoint`]) travelled from `u0` to `u1`.
#[derive(Debug, Clone, Copy)]
pub(super) struct LocalSite {
    pub(super) prim: Primitive,
    pub(super) site: Site,
    pub(super) u0: f64,
    pub(super) u1: f64,
    /// The next primitive in the cycle follows without an auxiliary arc.
    pub(super) joined_next: bool,
    /// The boundary points at `u0` and `u1` (every grown disk tests them).
    pub(super) ends: [Point; 2],
    /// A disk holding the piece ([`SitePiece::bound`]): most disks tested
    /// against a site are decided by it without trigonometry.
    pub(super) bound: (Point, f64),
    /// The normal the joint's own disk grows along at this site's start
    /// ([`Builder::mean_joint_normal`]), set once the cycle is complete:
    /// every contact clamped onto the joint is measured from it.
    pub(super) joint_normal: Option<Point>,
}

/// A site of the cycle: its index in the builder's sites. Valid for one
/// builder; the cycle wraps ([`next`](Self::next), [`prev`](Self::prev)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(super) struct SiteRef(pub(super) usize);

impl SiteRef {
    /// The site after this one in a cycle of `n`.
    #[inline]
    pub(super) fn next(self, n: usize) -> SiteRef {
        SiteRef((self.0 + 1) % n)
    }

    /// The site before this one in a cycle of `n`.
    #[inline]
    pub(super) fn prev(self, n: usize) -> SiteRef {
        SiteRef((self.0 + n - 1) % n)
    }
}

impl std::ops::Index<SiteRef> for Vec<LocalSite> {
    type Output = LocalSite;
    #[inline]
    fn index(&self, i: SiteRef) -> &LocalSite {
        &self[i.0]
    }
}

/// A position on the subshape's boundary cycle: the site and the fraction
/// `w` ∈ [0, 1] of its parameter range. Two keys are equal when their
/// positions are; `lag` only orders keys that share a position.
#[derive(Debug, Clone, Copy)]
pub(super) struct Key {
    pub(super) site: SiteRef,
    pub(super) w: f64,
    /// Signed length (model units, along the cycle) from this position to
    /// the contact as computed, before [`Builder::key`] snapped it to a
    /// site's end: 0 for a position placed exactly (a joint's or a port's
    /// own foot). Snapping is decided on each site alone, so two disks a
    /// few tolerances apart can share a snapped position on one side while
    /// their order on the other side is clear; the lag keeps their order
    /// here the one the disks have.
    pub(super) lag: f64,
}

impl Key {
    /// The position `w` of site `site`, placed exactly.
    pub(super) fn at(site: SiteRef, w: f64) -> Key {
        Key { site, w, lag: 0.0 }
    }
}

impl PartialEq for Key {
    fn eq(&self, other: &Key) -> bool {
        self.site == other.site && self.w == other.w
    }
}

pub(super) fn angle(v: Point) -> f64 {
    crate::kernel::direction::angle_of(v)
}

/// Global footpoint parameter of element fraction `t`.
pub(super) fn element_param(e: &Element, t: f64) -> f64 {
    match e {
        Element::Segment(s) => t * s.a.dist(s.b),
        Element::Arc(a) => angle(a.a - a.center) + t * a.sweep(),
    }
}

impl<K: AxisKernel> Builder<'_, K> {
    pub(super) fn n(&self) -> usize {
        self.sites.len()
    }

    /// Every site of the cycle, in order.
    pub(super) fn site_refs(&self) -> impl Iterator<Item = SiteRef> {
        (0..self.sites.len()).map(SiteRef)
    }

    /// Site `i` as the kernel sees it: its carrier between its parameters.
    #[inline]
    pub(super) fn piece(&self, i: SiteRef) -> SitePiece {
        let s = &self.sites[i];
        SitePiece { site: s.site, u0: s.u0, u1: s.u1 }
    }

    /// Parameter of the disk (`c`, `r`) on site `i`, unwrapped into its range.
    pub(super) fn param(&self, i: SiteRef, c: Point, r: f64) -> f64 {
        self.piece(i).param(c, r)
    }

    pub(super) fn fraction(&self, i: SiteRef, u: f64) -> f64 {
        let s = &self.sites[i];
        (u - s.u0) / (s.u1 - s.u0)
    }

    /// The boundary point at parameter `u` of site `i`.
    pub(super) fn point_of(&self, i: SiteRef, u: f64) -> Point {
        let s = &self.sites[i];
        if u == s.u0 {
            s.ends[0]
        } else if u == s.u1 {
            s.ends[1]
        } else {
            self.piece(i).point_at(u)
        }
    }

    /// The cycle key of parameter `u` on site `i`: ends snapped when within
    /// the tolerance (in length, for a disk of radius `r`), and the end of
    /// a primitive joined to the next stored as the next one's start.
    pub(super) fn key(&self, i: SiteRef, u: f64, r: f64) -> Key {
        self.key_of_contact(i, u, u, r)
    }

    /// [`key`](Self::key) of a contact at parameter `u` clamped to the
    /// site's range from `free`, where the disk is tangent to the site's
    /// carrier: the key's lag measures to `free`, so that contacts clamped
    /// onto one end keep the order of their tangency points.
    pub(super) fn key_of_contact(&self, i: SiteRef, u: f64, free: f64, r: f64) -> Key {
        let s = &self.sites[i];
        let scale = match s.site {
            Site::Line { .. } => 1.0,
            Site::Circle { r: rc, .. } => rc,
            Site::Point(_) => r,
        };
        let raw = self.fraction(i, free);
        let mut w = self.fraction(i, u).clamp(0.0, 1.0);
        if (u - s.u0).abs() * scale <= self.tol.touch() {
            w = 0.0;
        }
        if (u - s.u1).abs() * scale <= self.tol.touch() {
            w = 1.0;
        }
        let lag = |w: f64| self.signed_length(i, raw - w, r);
        let n = self.n();
        if w == 1.0 && s.joined_next {
            let j = i.next(n);
            return Key { site: j, w: 0.0, lag: lag(1.0) - self.joint_lag(j, i, 1.0, r) };
        }
        // Where a site meets an auxiliary arc only the dividing disk itself
        // touches (a maximal disk tangent there lies on the same normal,
        // so it is that disk or not maximal): any other disk's contact
        // there is rounding of one just inside the site.
        if w == 0.0 && !self.sites[i.prev(n)].joined_next {
            w = Tolerance::nudge();
        } else if w == 1.0 && !s.joined_next {
            w = 1.0 - Tolerance::nudge();
        } else if w == 0.0 {
            return Key { site: i, w, lag: lag(0.0) - self.joint_lag(i, i, 0.0, r) };
        }
        Key { site: i, w, lag: lag(w) }
    }

    /// The normal a joint's own disk grows along at the start of site `j`,
    /// where two element pieces meet without a corner event: the mean of
    /// their normals, which agree only within the angular tolerance (so
    /// that a mirror image grows the mirrored disk, and one disk met from
    /// two joints is found twice alike). `None` at other joints. Kept in
    /// [`LocalSite::joint_normal`] by [`Builder::set_joint_normals`].
    fn mean_joint_normal(&self, j: SiteRef) -> Option<Point> {
        let i = j.prev(self.n());
        let (Some(ea), Some(eb)) = (self.sites[i].prim.element(), self.sites[j].prim.element()) else {
            return None;
        };
        if !self.sites[i].joined_next || self.shape.joint(eb.loop_index, eb.element) == JointKind::Convex {
            return None;
        }
        let elements = &self.shape.loops()[eb.loop_index];
        let n_out = elements.element(eb.element).start_tangent().perp();
        Some((elements.element(ea.element).end_tangent().perp() + n_out).unit())
    }

    /// Where the joint at the start of site `j` lies among contacts of
    /// disks of radius `r` measured on site `i` (one of its two sides)
    /// from fraction `w_end`: the lag of the joint's own disk of that
    /// radius. A smooth joint turns by up to the angular tolerance, so
    /// its disk touches the two sides' carriers up to r × that angle / 2
    /// from the joint (far above the touching tolerance for large disks);
    /// measured from it, contacts clamped onto the joint keep the order
    /// their disks have about the joint's disk, whose own footpoint there
    /// is placed exactly.
    fn joint_lag(&self, j: SiteRef, i: SiteRef, w_end: f64, r: f64) -> f64 {
        let Some(nrm) = self.sites[j].joint_normal else { return 0.0 };
        let c = self.sites[j].ends[0] + nrm * r;
        self.signed_length(i, self.fraction(i, self.param(i, c, r)) - w_end, r)
    }

    /// Fills [`LocalSite::joint_normal`] for every site of the complete
    /// cycle (which sites are joined is known only then).
    pub(super) fn set_joint_normals(&mut self) {
        for j in self.site_refs() {
            self.sites[j.0].joint_normal = self.mean_joint_normal(j);
        }
    }

    /// False when a disk centred `c` touches site `i` at parameter `u`
    /// strictly inside the site's piece from the site's outer side: the
    /// two sides of a curve site lie on each other, and a disk touching
    /// one touches the other there from behind.
    pub(super) fn faces_inside(&self, i: SiteRef, c: Point, u: f64) -> bool {
        let s = &self.sites[i];
        let w = self.fraction(i, u);
        if !(w > 0.0 && w < 1.0) {
            return true;
        }
        self.k().carrier_side(&s.site, c) != CarrierSide::Behind
    }

    pub(super) fn pos(&self, k: Key) -> f64 {
        2.0 * k.site.0 as f64 + k.w
    }

    /// Offset of `k` after `a` along the cycle, in [0, 2n).
    pub(super) fn offset(&self, a: Key, k: Key) -> f64 {
        // Both positions lie in [0, 2n): one wrap, exactly what
        // `rem_euclid` gives, without its division (this runs for every
        // footpoint of every event at every pocket walked).
        let d = self.pos(k) - self.pos(a);
        if d < 0.0 {
            d + 2.0 * self.n() as f64
        } else {
            d
        }
    }

    /// Length (model units) of the part of site `i` between fractions
    /// `w0` and `w1`, for a disk of radius `r` at a vertex.
    pub(super) fn length(&self, i: SiteRef, w0: f64, w1: f64, r: f64) -> f64 {
        self.signed_length(i, w1 - w0, r).abs()
    }

    /// Length (model units, signed as `dw`) of a fraction `dw` of site
    /// `i`, for a disk of radius `r` at a vertex.
    pub(super) fn signed_length(&self, i: SiteRef, dw: f64, r: f64) -> f64 {
        let s = &self.sites[i];
        let du = (s.u1 - s.u0).abs() * dw;
        match s.site {
            Site::Line { .. } => du,
            Site::Circle { r: rc, .. } => du * rc,
            Site::Point(_) => du * r,
        }
    }

    /// The site just after `k` and its fraction there.
    pub(super) fn site_after(&self, k: Key) -> (SiteRef, f64) {
        if k.w < 1.0 {
            (k.site, k.w)
        } else {
            (k.site.next(self.n()), 0.0)
        }
    }

    /// The site just before `k` and its fraction there.
    pub(super) fn site_before(&self, k: Key) -> (SiteRef, f64) {
        if k.w > 0.0 {
            (k.site, k.w)
        } else {
            (k.site.prev(self.n()), 1.0)
        }
    }

    pub(super) fn u_at(&self, i: SiteRef, w: f64) -> f64 {
        let s = &self.sites[i];
        s.u0 + (s.u1 - s.u0) * w
    }
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{rectangle, with_events};
    use super::*;

    #[test]
    fn keys_snap_to_site_ends_and_joined_ends_are_the_next_start() {
        with_events(&rectangle(), |b| {
            let tol = b.tol.touch();
            // Site 0 is the bottom edge, parameters 0..4 along it.
            assert_eq!(b.key(SiteRef(0), 2.0, 1.0), Key::at(SiteRef(0), 0.5));
            assert_eq!(b.key(SiteRef(0), 0.5 * tol, 1.0), Key::at(SiteRef(0), 0.0));
            assert_eq!(b.key(SiteRef(0), 4.0 - 0.5 * tol, 1.0), Key::at(SiteRef(1), 0.0));
        });
    }

    #[test]
    fn offsets_run_forwards_round_the_cycle() {
        with_events(&rectangle(), |b| {
            let (a, k) = (Key::at(SiteRef(3), 0.5), Key::at(SiteRef(0), 0.25));
            // Site i lies at [2i, 2i + 1]: from 6.5 round to 8.25.
            assert_eq!(b.offset(a, k), 1.75);
            assert_eq!(b.offset(k, a), 8.0 - 1.75);
        });
    }

    #[test]
    fn distance_and_parameter_of_the_nearest_point() {
        with_events(&rectangle(), |b| {
            let (d, u) = b.piece(SiteRef(0)).distance(Point::new(1.5, 0.75));
            assert!((d - 0.75).abs() < 1e-15 && (u - 1.5).abs() < 1e-15);
            // Beyond the segment's end the end is nearest.
            let (d, u) = b.piece(SiteRef(0)).distance(Point::new(5.0, -1.0));
            assert!((d - 2f64.sqrt()).abs() < 1e-15 && u == 4.0);
        });
    }
}
