//! The axis of a subshape its dividing disks hug (see
//! [`Hugged`](crate::plane::medial::decompose::subshape::Hugged)): the
//! boundary stays within a few tolerances of the disks' circles, so the
//! order of footpoints along it is rounding, and the true axis runs inside
//! a sliver where every disk is one of the dividing disks within those
//! tolerances. No contact is decided there; the axis is the ports.

use super::{EventKind, LocalAxis, LocalEdge, LocalNode};
use crate::kernel::apollonius::Site;
use crate::kernel::bisector::footpoint_param;
use crate::plane::axis::Primitive;
use crate::plane::medial::decompose::subshape::{BoundaryPos, ChainParts, Cut, Hugged, Piece, Subshape};
use crate::shape::{ElementRef, Shape2d};

/// The node of dividing disk `disk` (an index into `cuts`) as a port.
fn port(cuts: &[Cut], disk: usize) -> LocalNode {
    LocalNode { center: cuts[disk].center, radius: cuts[disk].radius, kind: EventKind::Port(disk) }
}

/// The axis of a lobe's tip hugged by its one dividing disk `disk`: that
/// port alone, a leaf of the axis.
pub(super) fn tip_axis(cuts: &[Cut], disk: usize) -> LocalAxis {
    LocalAxis { nodes: vec![port(cuts, disk)], edges: Vec::new() }
}

/// The axis of `s`, a band hugged by both its dividing disks (`h`): the
/// straight edge between its two ports, whose disks (radius linear from
/// port to port) stay within the tolerance of both chains. `None` for a
/// tip, or when a band's chains cannot be named (never for a subshape
/// [`hugged`](crate::plane::medial::decompose::subshape::hugged) returned
/// it for).
pub(super) fn band_axis(shape: &Shape2d, s: &Subshape, cuts: &[Cut], h: Hugged) -> Option<LocalAxis> {
    let port = |disk: usize| port(cuts, disk);
    match h {
        Hugged::Tip(_) => None,
        Hugged::Band([j0, j1]) => {
            let disk = |j: usize| match s.pieces[j] {
                Piece::Aux { disk } => Some(disk),
                Piece::Chain { .. } => None,
            };
            let chain = |j: usize| match s.pieces[j % s.pieces.len()] {
                Piece::Chain { from, to } if from != to => Some((from, to)),
                _ => None,
            };
            let (d0, d1) = (disk(j0)?, disk(j1)?);
            // Chain `a` runs from port 0 to port 1 with the inside on its
            // left, so walking the axis the same way it is on the right.
            let (a, b) = (chain(j0 + 1)?, chain(j1 + 1)?);
            let (c0, c1) = (cuts[d0], cuts[d1]);
            let (left, right) = (middle_element(shape, b)?, middle_element(shape, a)?);
            let params = |p: Primitive| {
                let site = p.site(shape);
                let u0 = footpoint_param(&site, c0.center, c0.radius);
                let u1 = footpoint_param(&site, c1.center, c1.radius);
                (u0, near(&site, u1, u0))
            };
            Some(LocalAxis {
                nodes: vec![port(d0), port(d1)],
                edges: vec![LocalEdge {
                    from: 0,
                    to: 1,
                    sites: [left, right],
                    params: [params(left), params(right)],
                    straight: true,
                }],
            })
        }
    }
}

/// The element in the middle of the chain `from` → `to`: every element of
/// a hugged chain touches every disk of the band, and the middle one lies
/// wholly inside the chain wherever the chain holds three or more.
fn middle_element(shape: &Shape2d, (from, to): (BoundaryPos, BoundaryPos)) -> Option<Primitive> {
    let parts = ChainParts::new(shape, from, to);
    let (e, _, _) = parts.iter().nth(parts.len() / 2)?;
    Some(Primitive::Element(ElementRef { loop_index: from.loop_index, element: e }))
}

/// An angular footpoint parameter `u` moved by whole turns next to `at`;
/// a line's parameter unchanged.
fn near(site: &Site, u: f64, at: f64) -> f64 {
    match site {
        Site::Line { .. } => u,
        Site::Point(_) | Site::Circle { .. } => {
            let tau = std::f64::consts::TAU;
            at + (u - at + std::f64::consts::PI).rem_euclid(tau) - std::f64::consts::PI
        }
    }
}
