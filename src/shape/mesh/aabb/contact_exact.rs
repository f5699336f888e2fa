//! The largest ball at a centre with its contacts decided exactly: the
//! exact radius (rounded), and every point where `c + r·B` touches the
//! surface with the least features of ball and surface holding it, so
//! with the non-regular contact types VE, EV and VV (thesis 3.1.2) the
//! `f64` search cannot tell from the regular ones.
//!
//! The `f64` search gives the least gauge `r₀`; every triangle whose
//! `f64` gauge is within a band of `r₀` (far wider than the rounding of a
//! gauge: relative 1e-9, plus 1e-9 of the coordinates' size over the
//! ball's inradius) is then asked exactly at once (`touch_exact_many`:
//! floating filter, integers behind it). A triangle outside the band is
//! farther than `r₀` by a million roundings, so it cannot hold the exact
//! least gauge.

use super::TriangleTree;
use crate::kernel::Point3;
use crate::shape::ball::{touch_exact_many, Ball3, ContactKind3, Feature3, Reach, TouchPoint, TrianglePart};

/// Relative width of the band of triangles asked exactly.
pub(super) const BAND: f64 = 1e-9;

/// A feature of the surface: a vertex, an edge (its two vertices, the
/// lesser first) or the interior of a triangle (its index).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SurfacePart {
    /// A vertex, by index into the positions.
    Vertex(u32),
    /// An edge by its ends, the lesser index first.
    Edge([u32; 2]),
    /// The interior of a triangle, by its index.
    Face(u32),
}

/// One contact of the largest ball, decided exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactContact {
    /// The least feature of the ball (scaled and placed) holding the point.
    pub ball: Feature3,
    /// The least feature of the surface holding it.
    pub surface: SurfacePart,
    /// The contact type those features make.
    pub kind: ContactKind3,
    /// A triangle holding the point (the least index among them).
    pub triangle: u32,
    /// The point (exact value rounded to `f64`).
    pub point: Point3,
    /// True when the ball lies flat on a triangle holding the point (a ball
    /// edge or facet along it): the point is a corner of a contact segment
    /// or polygon.
    pub flat: bool,
}

/// The largest ball at a centre, decided exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactContacts {
    /// The radius: the exact least gauge, rounded to `f64`.
    pub radius: f64,
    /// Every contact, each once, ordered by surface feature then ball
    /// feature.
    pub contacts: Vec<ExactContact>,
    /// True when the ball lies flat on some triangle (a ball edge or facet
    /// along it, not in general position): the contact is then a segment
    /// or polygon and `contacts` holds its corners.
    pub flat: bool,
}

/// The contact type of a ball feature on a surface feature.
fn kind(ball: Feature3, surface: SurfacePart) -> ContactKind3 {
    match (ball, surface) {
        (Feature3::Vertex(_), SurfacePart::Face(_)) => ContactKind3::VertexFace,
        (Feature3::Vertex(_), SurfacePart::Edge(_)) => ContactKind3::VertexEdge,
        (Feature3::Vertex(_), SurfacePart::Vertex(_)) => ContactKind3::VertexVertex,
        (Feature3::Edge(_), SurfacePart::Vertex(_)) => ContactKind3::EdgeVertex,
        (Feature3::Facet(_), SurfacePart::Vertex(_)) => ContactKind3::FaceVertex,
        // A ball edge on a surface edge; the linear program's vertices
        // give no other pairs (an edge on a face or a facet on an edge is
        // a flat contact, reported by its corners).
        _ => ContactKind3::EdgeEdge,
    }
}

impl TriangleTree {
    /// [`exact_contacts`](Self::exact_contacts) at many centres, in
    /// parallel (in Z-order of the centres).
    pub fn exact_contacts_many(&self, centres: &[Point3], ball: &Ball3) -> Vec<Option<ExactContacts>> {
        let reach = ball.reach();
        self.batch_by(centres, |&c| c, |&c| self.exact_contacts(c, &reach))
    }

    /// The largest ball `c + r·B` whose interior holds no point of the
    /// surface, with its radius and contacts decided exactly (`None` for
    /// an empty tree or a non-finite centre). Slower than
    /// [`ball_radius_with`](Self::ball_radius_with) (it asks the few
    /// triangles near the answer again in exact arithmetic); meant where
    /// the contact's combinatorics matter.
    pub fn exact_contacts(&self, c: Point3, reach: &Reach<'_>) -> Option<ExactContacts> {
        let (first, _) = self.ball_radius_at(c, reach)?;
        let ball = reach.ball();
        let b = self.bbox();
        let size = [c, b.min, b.max].iter().flat_map(|p| p.to_array()).fold(0.0f64, |m, v| m.max(v.abs()));
        let limit = first.radius + BAND * (first.radius + size / ball.inradius());
        let near: Vec<usize> = self.near_triangles(c, limit, reach).into_iter().map(|(k, _)| k).collect();
        if near.is_empty() {
            // The answer's own triangle is always near; only a NaN gets here.
            return None;
        }
        let corners: Vec<[Point3; 3]> = near.iter().map(|&k| self.corners(k)).collect();
        let (radius, points) = touch_exact_many(ball, c, &corners)?;
        let (contacts, flat) = self.contacts_of(&near, points);
        Some(ExactContacts { radius, contacts, flat })
    }

    /// The points of contact of triangles `near[i]` as contacts with
    /// surface features, one per pair of features (the least triangle,
    /// flat when any triangle holding it is), and whether any is flat.
    pub(super) fn contacts_of(&self, near: &[usize], points: Vec<(usize, TouchPoint)>) -> (Vec<ExactContact>, bool) {
        let mut per_triangle = vec![0usize; near.len()];
        points.iter().for_each(|(i, _)| per_triangle[*i] += 1);
        let mut contacts: Vec<ExactContact> = points
            .into_iter()
            .map(|(i, p)| {
                let k = near[i];
                let vs = self.triangles[k];
                let surface = match p.triangle {
                    TrianglePart::Corner(j) => SurfacePart::Vertex(vs[j as usize]),
                    TrianglePart::Side(j) => {
                        let (a, b) = (vs[j as usize], vs[(j as usize + 1) % 3]);
                        SurfacePart::Edge([a.min(b), a.max(b)])
                    }
                    TrianglePart::Face => SurfacePart::Face(self.ids[k]),
                };
                let (triangle, point, flat) = (self.ids[k], p.point, per_triangle[i] > 1);
                ExactContact { ball: p.ball, surface, kind: kind(p.ball, surface), triangle, point, flat }
            })
            .collect();
        let flat = contacts.iter().any(|x| x.flat);
        // One contact per pair of features: the least triangle, flat when
        // any triangle holding it is.
        contacts.sort_by_key(|x| (x.surface, x.ball, x.triangle));
        let mut merged: Vec<ExactContact> = Vec::with_capacity(contacts.len());
        for x in contacts {
            match merged.last_mut() {
                Some(m) if (m.surface, m.ball) == (x.surface, x.ball) => m.flat |= x.flat,
                _ => merged.push(x),
            }
        }
        let contacts = merged;
        (contacts, flat)
    }
}
