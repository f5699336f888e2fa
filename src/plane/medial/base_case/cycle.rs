//! The boundary cycle of a subshape as sites: element pieces, reflex
//! fans (the thesis's zero-length arcs) and point-site fans cut into
//! quarter turns, with where auxiliary arcs separate them.

use super::port::Port;
use super::prepare::{drop_sliver_ends, merge_touching_chains, same_position};
use super::sites::{angle, element_param};
use super::{Builder, LocalSite, POINT_SPLITS};
use crate::kernel::apollonius::Site;
use crate::kernel::fan::Fan;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::CircleArc;
use crate::kernel::SitePiece;
use crate::kernel::{AxisKernel, Point};
use crate::plane::axis::Primitive;
use crate::plane::medial::decompose::subshape::{ChainParts, Cut, Piece, Subshape};
use crate::shape::{ElementRef, JointKind};

impl<K: AxisKernel> Builder<'_, K> {
    pub(super) fn push_site(&mut self, prim: Primitive, site: Site, u0: f64, u1: f64) {
        let piece = SitePiece { site, u0, u1 };
        let (ends, bound) = ([piece.point_at(u0), piece.point_at(u1)], piece.bound());
        self.sites.push(LocalSite { prim, site, u0, u1, joined_next: true, ends, bound, joint_normal: None });
    }

    /// A reflex vertex's fan between directions `from` and `to` (clockwise),
    /// measured from the fan's start (the previous element's end normal)
    /// so that the parameter agrees in every subshape; skipped when it is
    /// no wider than the tolerance.
    pub(super) fn push_fan(&mut self, l: usize, v: usize, from: Point, to: Point, r: f64) {
        let lp = &self.shape.loops()[l];
        if lp.kind() == crate::shape::LoopKind::Point {
            self.push_point_fan(l, from, to, r);
            return;
        }
        let n = lp.len();
        let n_prev = lp.element((v + n - 1) % n).end_tangent().perp();
        let n_next = lp.element(v).start_tangent().perp();
        let base = angle(n_prev);
        let fan = Fan::clockwise(n_prev, n_next);
        // A dividing disk may meet the vertex from a direction just outside
        // its fan: it touches the element beside the vertex within the
        // tolerance there. Such a direction stays on its own side of the
        // end (a fan of this subshape a hair wider, or one of the
        // neighbouring subshape a hair narrower), ordered as the disks are.
        let (d0, d1) = (fan.signed_offset_of(from), fan.signed_offset_of(to));
        // Dividing disks found by sliding (maxdisk*) meet a vertex in a
        // direction accurate to about 1e-8 rad; narrower fans are that.
        if d1 - d0 <= Tolerance::fan_angle() || (d1 - d0) * r <= self.tol.fan_arc() {
            return;
        }
        let q = lp.vertices()[v].p;
        self.push_site(Primitive::of_vertex(l, v), Site::Point(q), base - d0, base - d1);
    }

    /// A point site's fan from direction `from` clockwise to `to` (a whole
    /// turn when they are one direction: the point between the two arcs of
    /// one disk), cut at the fixed directions of [`POINT_SPLITS`] into
    /// pieces narrower than a quarter turn, each a site of its own joined to
    /// the next: the joint between two pieces is an event (the maximal disk
    /// through the point in that direction), so that no site's range comes
    /// near a whole turn, where angles are ambiguous.
    pub(super) fn push_point_fan(&mut self, l: usize, from: Point, to: Point, r: f64) {
        let q = self.shape.loops()[l].vertices()[0].p;
        let fan = Fan::clockwise_or_whole(from, to, Tolerance::fan_angle());
        let width = fan.width();
        if width * r <= self.tol.fan_arc() {
            return;
        }
        let mut cuts: Vec<f64> = POINT_SPLITS
            .iter()
            .map(|&a| fan.offset_of(Point::new(a.cos(), a.sin())))
            .filter(|&o| o > Tolerance::fan_angle() && o < width - Tolerance::fan_angle())
            .collect();
        cuts.sort_by(f64::total_cmp);
        cuts.push(width);
        let base = angle(from);
        let prim = Primitive::of_vertex(l, 0);
        let mut d0 = 0.0;
        for d1 in cuts {
            self.push_site(prim, Site::Point(q), base - d0, base - d1);
            d0 = d1;
        }
    }

    pub(super) fn element_site(&mut self, l: usize, k: usize, lo: f64, hi: f64) {
        let e = self.shape.loops()[l].element(k);
        let prim = Primitive::of_element(ElementRef { loop_index: l, element: k });
        self.push_site(prim, prim.site(self.shape), element_param(&e, lo), element_param(&e, hi));
    }

    pub(super) fn collect_sites(&mut self, s: &Subshape, cuts: &[Cut]) {
        let shape = self.shape;
        let s = &drop_sliver_ends(shape, s, self.tol.sliver_end());
        // A chain with no parts next to another chain is the other chain's
        // end point (a cut at an element's very end leaves one): drop it.
        let is_point =
            |p: &Piece| matches!(*p, Piece::Chain { from, to } if ChainParts::new(shape, from, to).is_empty());
        let k = s.pieces.len();
        let pieces: Vec<Piece> = (0..k)
            .filter(|&j| {
                let neighbour_chain = |i: usize| matches!(s.pieces[i], Piece::Chain { .. }) && !is_point(&s.pieces[i]);
                let (next, prev) = ((j + 1) % k, (j + k - 1) % k);
                // Of two points in a row (the two ends of a vertex), keep one.
                let twin = is_point(&s.pieces[next]) && next != j;
                !(k > 1 && is_point(&s.pieces[j]) && (neighbour_chain(next) || neighbour_chain(prev) || twin))
            })
            .map(|j| s.pieces[j])
            .collect();
        let s = &Subshape { pieces: merge_touching_chains(shape, pieces) };
        let m = s.pieces.len();
        let aux_center = |j: usize| match s.pieces[j % m] {
            Piece::Aux { disk } => Some((cuts[disk].center, cuts[disk].radius)),
            Piece::Chain { .. } => None,
        };
        // A single chain of a whole loop closes on itself.
        let closed = m == 1;
        for (j, piece) in s.pieces.iter().enumerate() {
            let Piece::Chain { from, to } = *piece else {
                if let Some(last) = self.sites.last_mut() {
                    last.joined_next = false;
                }
                if let Piece::Aux { disk } = *piece {
                    let end_of = |p: &Piece, start: bool| match *p {
                        Piece::Chain { from, to } => Some(if start { from } else { to }.point(shape)),
                        Piece::Aux { .. } => None,
                    };
                    let c = cuts[disk];
                    let a = end_of(&s.pieces[(j + m - 1) % m], false).unwrap_or(c.center);
                    let b = end_of(&s.pieces[(j + 1) % m], true).unwrap_or(c.center);
                    self.aux.push(Port {
                        disk,
                        site_after: self.sites.len(),
                        arc: CircleArc { center: c.center, radius: c.radius, from: a, to: b },
                    });
                }
                continue;
            };
            let l = from.loop_index;
            let lp = &shape.loops()[l];
            let n = lp.len();
            let before = aux_center(j + m - 1);
            let after = aux_center(j + 1);
            let parts = ChainParts::new(shape, from, to);
            if parts.is_empty() {
                // A single point between two auxiliary arcs: a reflex
                // vertex's fan between the two disks' directions.
                if let (Some(v), Some((c0, r0)), Some((c1, r1))) = (from.vertex(shape), before, after) {
                    if shape.joint(l, v) == JointKind::Reflex {
                        let q = lp.vertices()[v].p;
                        self.push_fan(l, v, c0 - q, c1 - q, r0.min(r1));
                    }
                }
                continue;
            }
            let (e0, lo0, _) = parts.get(0);
            let start_vertex = (lo0 == 0.0).then_some(e0);
            if let (Some(v), Some((c, r))) = (start_vertex, before) {
                if shape.joint(l, v) == JointKind::Reflex {
                    let q = lp.vertices()[v].p;
                    let n_next = lp.element(v).start_tangent().perp();
                    self.push_fan(l, v, c - q, n_next, r);
                }
            }
            // The chain carries on from the one before (the two halves of
            // a whole loop): the joint where they meet is inside the boundary.
            let carries_on =
                matches!(s.pieces[(j + m - 1) % m], Piece::Chain { to, .. } if m > 1 && same_position(shape, to, from));
            for i in 0..parts.len() {
                let (e, lo, hi) = parts.get(i);
                if i > 0 || (closed && e == 0 && lo == 0.0) || (i == 0 && lo == 0.0 && carries_on) {
                    // The joint at this element's start, inside the chain.
                    if shape.joint(l, e) == JointKind::Reflex {
                        let prev = lp.element((e + n - 1) % n);
                        let np = prev.end_tangent().perp();
                        self.push_fan(l, e, np, lp.element(e).start_tangent().perp(), f64::INFINITY);
                    }
                }
                // A chain that is one sliver (a cut within the tolerance of
                // a vertex) is that vertex; slivers at the ends of longer
                // chains went in `drop_sliver_ends`, except next to a
                // convex corner, whose corner event needs the sliver's site.
                let sliver = parts.len() == 1 && (hi - lo) * lp.element(e).length() <= self.tol.touch();
                if !sliver {
                    self.element_site(l, e, lo, hi);
                }
            }
            let (el, _, hil) = parts.get(parts.len() - 1);
            if let (true, Some((c, r))) = (hil == 1.0, after) {
                let v = (el + 1) % n;
                if shape.joint(l, v) == JointKind::Reflex {
                    let q = lp.vertices()[v].p;
                    let n_prev = lp.element(el).end_tangent().perp();
                    self.push_fan(l, v, n_prev, c - q, r);
                }
            }
        }
        if !closed {
            if let Some(last) = self.sites.last_mut() {
                // The cycle wraps from the last piece to the first: joined
                // only when no auxiliary arc lies between, which happens
                // when the pieces start with a chain and end with one.
                let ends_aux = matches!(s.pieces.last(), Some(Piece::Aux { .. }));
                let starts_aux = matches!(s.pieces.first(), Some(Piece::Aux { .. }));
                last.joined_next = !(ends_aux || starts_aux);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{l_shape, rectangle, with_events};
    use crate::plane::axis::Primitive;

    #[test]
    fn a_whole_polygon_is_one_closed_cycle_of_its_elements() {
        with_events(&rectangle(), |b| {
            assert_eq!(b.sites.len(), 4);
            assert!(b.sites.iter().all(|s| s.joined_next));
            assert!(b.sites.iter().all(|s| matches!(s.prim, Primitive::Element { .. })));
            assert!(b.aux.is_empty());
        });
    }

    #[test]
    fn a_reflex_vertex_is_a_fan_site_between_its_elements() {
        let l = l_shape();
        with_events(&l, |b| {
            let fans: Vec<usize> = (0..b.sites.len())
                .filter(|&i| matches!(b.sites[i].prim, Primitive::Vertex { vertex: 3, .. }))
                .collect();
            assert_eq!(fans.len(), 1);
            let fan = b.sites[fans[0]];
            // A quarter turn of normals, between the elements 2 and 3.
            assert!(((fan.u1 - fan.u0).abs() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
            let n = b.sites.len();
            let before = b.sites[(fans[0] + n - 1) % n].prim;
            let after = b.sites[(fans[0] + 1) % n].prim;
            assert!(matches!(before, Primitive::Element { element: 2, .. }));
            assert!(matches!(after, Primitive::Element { element: 3, .. }));
        });
    }
}
