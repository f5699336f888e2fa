//! The geometric questions the medial-axis algorithms ask, as one trait.
//!
//! `plane/` (maximal disks, `maxdisk*`, the base cases, polishing in the
//! conquer step) never calls a construction or compares a gap itself: it
//! holds an [`AxisKernel`] and asks it. A kernel with other numbers (an
//! interval-filtered or exact one, thesis 2.2.5 and 2.5) implements these
//! methods and the algorithms run unchanged, as CGAL's traits classes do
//! for its algorithms.
//!
//! The methods come in two groups:
//!
//! * **Constructions** return new geometry rounded to `f64`: contact radii
//!   of the growing disk (Algorithm 1), the disks tangent to three sites
//!   (Apollonius), points on the bisector of two sites.
//! * **Predicates** answer with an enum: how a disk meets a boundary
//!   primitive ([`Contact`]), and the orientation and in-circle tests of
//!   the [`Kernel`] supertrait.
//!
//! The finished axis evaluates and samples its conic edges in `f64`
//! (`plane::axis`), outside the kernel: output is rounded anyway.
//!
//! The provided methods are the `f64` constructions of this module's
//! siblings, so an implementation only overrides what it computes
//! differently. Both [`FloatKernel`](super::FloatKernel) and
//! [`FilteredKernel`](super::FilteredKernel) use them unchanged and differ
//! in their orientation signs only.
//!
//! Tolerances are the caller's: every predicate that compares lengths takes
//! the length tolerance (model units) it decides with, since the algorithm
//! owns which tolerance applies where (contact, touch, emptiness). An
//! exact kernel decides with a tolerance of zero.

use super::apollonius::{self, Site};
use super::bisector;
use super::direction::{self, Alignment, Heading};
use super::element::Element;
use super::fan::BoundSide;
use super::growing_disk::GrowingDisk;
use super::SitePiece;
use super::{construct, Disk, Kernel, Orientation, Point};
use super::{CircleArc, Crossing};

/// How a disk meets a boundary primitive, decided with a length tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Contact {
    /// The primitive stays more than the tolerance outside the circle.
    Apart,
    /// The primitive comes within the tolerance of the circle, from either
    /// side: a footpoint.
    Touching,
    /// The primitive reaches more than the tolerance into the disk: the
    /// disk is not empty.
    Overlapping,
}

/// What the medial-axis algorithms ask of geometry. `Copy + Send + Sync`:
/// kernels are stateless or hold only shared configuration, and every
/// parallel task gets its own copy.
pub trait AxisKernel: Kernel + Copy + Send + Sync + 'static {
    /// Radius at which the growing disk `g` passes through `q`; `None` when
    /// `q` lies on or behind the tangent line at `g.p`.
    fn through_point(&self, g: &GrowingDisk, q: Point) -> Option<f64> {
        g.through_point(q)
    }

    /// Radii at which `g`'s circle is tangent to the line through `a` with
    /// unit normal `m`, with the tangency point: up to two (one per side of
    /// the line), in no fixed order.
    fn tangent_to_line(&self, g: &GrowingDisk, a: Point, m: Point) -> [Option<(f64, Point)>; 2] {
        up_to_two(g.tangent_to_line(a, m))
    }

    /// Radii at which `g`'s circle is tangent to the circle (`o`, `r`),
    /// externally or internally, with the tangency point: up to two.
    fn tangent_to_circle(&self, g: &GrowingDisk, o: Point, r: f64) -> [Option<(f64, Point)>; 2] {
        up_to_two(g.tangent_to_circle(o, r))
    }

    /// Radius at which `g` touches `site` as the site's kind says.
    fn touch_site(&self, g: &GrowingDisk, site: &Site) -> Option<f64> {
        g.touch_site(site)
    }

    /// Every disk (centre, radius > 0) tangent to the three sites as their
    /// kinds say, smallest radius first (thesis 2.2.3, branching points).
    fn tritangent_disks(&self, sites: [Site; 3]) -> Vec<Disk> {
        apollonius::tangent_disks(sites).into_iter().map(|(c, r)| Disk::new(c, r)).collect()
    }

    /// The disk tangent to `a` at footpoint parameter `u` and to `b`.
    fn bisector_point(&self, a: &Site, b: &Site, u: f64) -> Option<Disk> {
        bisector::bisector_point(a, b, u).map(|(c, r)| Disk::new(c, r))
    }

    /// The circle through three points (centre, radius), `None` when they
    /// are collinear: decided by [`Kernel::orientation`] first, then by the
    /// construction's own guard against a centre lost to rounding.
    fn circumcircle(&self, a: Point, b: Point, c: Point) -> Option<Disk> {
        if self.orientation(a, b, c) == Orientation::Collinear {
            return None;
        }
        construct::circumcircle(a, b, c).map(|(o, r)| Disk::new(o, r))
    }

    /// How the circle of radius `radius` around a centre meets a primitive
    /// whose distance from that centre is `distance`, with tolerance `tol`
    /// (all model units). `Overlapping` must mean at least "closer than
    /// `radius − tol`" for a kernel that answers otherwise: the emptiness
    /// search ([`crate::plane::DiskFinder::intruder`]) only opens parts of
    /// the shape that come that close.
    fn contact(&self, distance: f64, radius: f64, tol: f64) -> Contact {
        if distance < radius - tol {
            Contact::Overlapping
        } else if distance <= radius + tol {
            Contact::Touching
        } else {
            Contact::Apart
        }
    }

    /// Whether `disk`'s circle passes through `arc` (by more than `tol`,
    /// model units): such a disk leaves the subshape the arc bounds.
    fn arc_crossing(&self, arc: &CircleArc, disk: Disk, tol: f64) -> Crossing {
        super::circle_arc::arc_crossing(arc, disk, tol)
    }

    /// How `disk` meets the point `p`, with tolerance `tol` (model units).
    fn point_contact(&self, disk: Disk, p: Point, tol: f64) -> Contact {
        self.contact(disk.center.dist(p), disk.radius, tol)
    }

    /// How `disk` meets the element `e` (anywhere along it), with tolerance
    /// `tol` (model units).
    fn element_contact(&self, disk: Disk, e: &Element, tol: f64) -> Contact {
        self.contact(e.closest_point(disk.center).0, disk.radius, tol)
    }

    /// How `disk` meets the carrier piece `piece`, with tolerance `tol`
    /// (model units).
    fn piece_contact(&self, disk: Disk, piece: &SitePiece, tol: f64) -> Contact {
        self.piece_contact_at(disk, piece, tol).0
    }

    /// [`piece_contact`](Self::piece_contact) with the parameter of the
    /// piece's point nearest to the disk's centre (clamped to the piece),
    /// where the contact is.
    fn piece_contact_at(&self, disk: Disk, piece: &SitePiece, tol: f64) -> (Contact, f64) {
        let (d, u) = piece.distance(disk.center);
        (self.contact(d, disk.radius, tol), u)
    }

    /// How `disk` meets a primitive whose distance from the disk's centre
    /// lies in `[near, far]` (model units), when that range alone decides
    /// it within `tol`: `Apart` when even `near` is more than `tol` outside
    /// the circle, `Overlapping` when even `far` is more than `tol` inside;
    /// `None` otherwise. Twice `tol` of room for the rounding of the range.
    #[inline]
    fn range_contact(&self, near: f64, far: f64, radius: f64, tol: f64) -> Option<Contact> {
        if near > radius + 2.0 * tol {
            Some(Contact::Apart)
        } else if far < radius - 2.0 * tol {
            Some(Contact::Overlapping)
        } else {
            None
        }
    }

    /// [`range_contact`](Self::range_contact) for every primitive inside
    /// the disk `bound` (centre, radius): a cheap test before
    /// [`piece_contact_at`](Self::piece_contact_at).
    #[inline]
    fn bound_contact(&self, disk: Disk, bound: (Point, f64), tol: f64) -> Option<Contact> {
        let d = disk.center.dist(bound.0);
        self.range_contact(d - bound.1, d + bound.1, disk.radius, tol)
    }

    /// [`range_contact`](Self::range_contact) for `piece` (whose points at
    /// `u0`, `u1` are `ends`) at its distance without trigonometry
    /// ([`SitePiece::distance_near`]).
    #[inline]
    fn quick_contact(&self, disk: Disk, piece: &SitePiece, ends: [Point; 2], tol: f64) -> Option<Contact> {
        let d = piece.distance_near(disk.center, ends);
        self.range_contact(d, d, disk.radius, tol)
    }

    /// Whether every point of `piece` (whose points at `u0`, `u1` are
    /// `ends`) lies within `tol` (model units) of `disk`'s circle: the
    /// piece runs along the circle, as the boundary does beside a
    /// footpoint that rounding smeared into two.
    #[inline]
    fn piece_hugs(&self, disk: Disk, piece: &SitePiece, ends: [Point; 2], tol: f64) -> bool {
        let (near, far) = piece.distance_range(disk.center, ends);
        near >= disk.radius - tol && far <= disk.radius + tol
    }

    /// Where `v` points relative to the direction `n`: the side of the
    /// line perpendicular to `n` (see [`Heading`]). The directions asked
    /// about are rounded constructions (normals, vectors between
    /// constructed points); an exact kernel may still decide the sign of
    /// the rounded inputs exactly.
    #[inline]
    fn heading(&self, n: Point, v: Point) -> Heading {
        direction::heading(n, v)
    }

    /// Which way direction `b` turns from direction `a`
    /// ([`Orientation::Left`] counter-clockwise).
    #[inline]
    fn turn(&self, a: Point, b: Point) -> Orientation {
        direction::turn(a, b)
    }

    /// How `v` lies along the unit direction `n`, within `tol` across it
    /// (see [`direction::alignment`]).
    #[inline]
    fn alignment(&self, n: Point, v: Point, tol: f64) -> Alignment {
        direction::alignment(n, v, tol)
    }

    /// Whether unit directions `a` and `b` are one (or opposite) within
    /// `eps` of their dot product (see [`direction::direction_match`]).
    #[inline]
    fn direction_match(&self, a: Point, b: Point, eps: f64) -> Alignment {
        direction::direction_match(a, b, eps)
    }

    /// Whether `m` from a vertex points into its fan of normals between
    /// tangents `t_in` and `t_out`, `tol` of play (model units; see
    /// [`direction::vertex_fan_side`]).
    #[inline]
    fn vertex_fan_side(&self, t_in: Point, t_out: Point, m: Point, tol: f64) -> BoundSide {
        direction::vertex_fan_side(t_in, t_out, m, tol)
    }

    /// Which side of `site`'s carrier the point `c` lies on: a point is
    /// faced from every direction, a line from the side its normal points
    /// to, a circle from outside or inside as the site says.
    fn carrier_side(&self, site: &Site, c: Point) -> CarrierSide {
        let signed = match *site {
            Site::Point(_) => return CarrierSide::Front,
            Site::Line { a, n } => (c - a).dot(n),
            Site::Circle { o, r, outside: true } => c.dist(o) - r,
            Site::Circle { o, r, outside: false } => r - c.dist(o),
        };
        match signed.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => CarrierSide::Front,
            Some(std::cmp::Ordering::Equal) => CarrierSide::On,
            _ => CarrierSide::Behind,
        }
    }
}

/// Which side of a site's carrier a point lies on, as the site is seen
/// from the shape: `Front` is the side the medial disks touch it from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CarrierSide {
    /// On the disks' side, strictly.
    Front,
    /// On the carrier (within rounding of the f64 evaluation).
    On,
    /// Behind the carrier: a disk centred there touches it from the
    /// wrong side.
    Behind,
}

/// The first two contacts of `hits`, packed from the front.
fn up_to_two(hits: impl Iterator<Item = (f64, Point)>) -> [Option<(f64, Point)>; 2] {
    let mut out = [None; 2];
    for (slot, hit) in out.iter_mut().zip(hits) {
        *slot = Some(hit);
    }
    out
}

impl AxisKernel for super::FloatKernel {}

impl AxisKernel for super::FilteredKernel {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::FilteredKernel;

    #[test]
    fn contact_bands() {
        let k = FilteredKernel;
        assert_eq!(k.contact(0.5, 1.0, 0.1), Contact::Overlapping);
        assert_eq!(k.contact(0.95, 1.0, 0.1), Contact::Touching);
        assert_eq!(k.contact(1.1, 1.0, 0.1), Contact::Touching);
        assert_eq!(k.contact(1.2, 1.0, 0.1), Contact::Apart);
        // An exact kernel's tolerance of zero: only the circle itself touches.
        assert_eq!(k.contact(1.0, 1.0, 0.0), Contact::Touching);
        assert_eq!(k.contact(1.0 - 1e-15, 1.0, 0.0), Contact::Overlapping);
    }

    #[test]
    fn growing_disk_contacts_match_the_constructions() {
        let k = FilteredKernel;
        let g = GrowingDisk { p: Point::new(0.0, 0.0), n: Point::new(0.0, 1.0) };
        // The line y = 2 seen from below: tangent at radius 1.
        let [a, b] = k.tangent_to_line(&g, Point::new(0.0, 2.0), Point::new(0.0, -1.0));
        let radii: Vec<f64> = [a, b].into_iter().flatten().map(|(t, _)| t).collect();
        assert!(radii.iter().any(|&t| (t - 1.0).abs() < 1e-15), "{radii:?}");
        // The unit circle around (0, 3): external tangency at radius 1.
        let [a, b] = k.tangent_to_circle(&g, Point::new(0.0, 3.0), 1.0);
        let radii: Vec<f64> = [a, b].into_iter().flatten().map(|(t, _)| t).collect();
        assert!(radii.iter().any(|&t| (t - 1.0).abs() < 1e-15), "{radii:?}");
        assert_eq!(k.through_point(&g, Point::new(0.0, 4.0)), Some(2.0));
        assert_eq!(k.through_point(&g, Point::new(0.0, -4.0)), None);
    }
}
