//! How far a maximal* ball anchored at a point grows before a given
//! contact stops it, as a function of the point: affine (thesis 3.3.1).
//!
//! In a contact domain the balls are `p + s·(B − ṽ)`: the copy of the
//! representative vertex `ṽ` sits at `p` and the centre is `p − s·ṽ`. A
//! ball feature `x̃` reaches a surface feature `y` at a radius that solves
//! one linear equation in `s` whose right-hand side is affine in `p`:
//!
//! * VF `(w̃, t)`: `n·(p + s·(w̃ − ṽ) − a) = 0` for `t`'s normal `n` and a
//!   corner `a`: `s = n·(a − p) / n·(w̃ − ṽ)`.
//! * EE `([ã, b̃], [e₀, e₁])`: the ball edge `p + s·(ã − ṽ) + μ·s·(b̃ − ã)`
//!   meets the line `e₀ + λ·(e₁ − e₀)`: coplanarity with `N = (b̃ − ã) ×
//!   (e₁ − e₀)` gives `s = N·(e₀ − p) / N·(ã − ṽ)`.
//! * FV `(f̃, v)`: `v` on the facet's plane `ñ·x = h̃` scaled and placed:
//!   `ñ·(v − p) + s·ñ·ṽ = s·h̃`, `s = ñ·(v − p) / (h̃ − ñ·ṽ)`.
//!
//! The contact holds (the point met lies on both features) where a few
//! affine functions of `p` are non-negative: the met point's barycentric
//! sides in `t`, its `λ` and `μ` in `[0, 1]`, the point `v − c` inside
//! the facet `s·f̃`. So a contact domain's arrangement is the lower
//! envelope of affine functions, each on a convex polygon: its edges are
//! where two functions tie (seams) or one's polygon ends (pseudo-seams),
//! and every vertex of it is a small linear system with rational
//! coordinates (Lemma 8).
//!
//! These are the `f64` functions, for constructions and for finding where
//! a change lies; which class holds at a point is decided exactly by the
//! maximal* ball query (`TriangleTree::maximal_ball_exact_on`).

use crate::kernel::Point3;
use crate::shape::ball::{Ball3, Feature3};
use crate::shape::{Mesh3d, SurfacePart};

/// An affine function of a point of space: `grad·p + at0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine3 {
    /// Its gradient.
    pub grad: Point3,
    /// Its value at the origin.
    pub at0: f64,
}

impl Affine3 {
    /// Its value at `p`.
    #[inline]
    pub fn at(&self, p: Point3) -> f64 {
        self.grad.dot(p) + self.at0
    }
}

/// The radius at which the maximal* ball anchored at `p` (ball vertex `ṽ`
/// at `p`) reaches one contact class, and where that contact holds.
#[derive(Debug, Clone, PartialEq)]
pub struct RadiusFn {
    /// `s(p)`.
    pub radius: Affine3,
    /// The contact holds at `p` iff every one of these is `≥ 0` (each
    /// scaled to a unit gradient, so its value is a distance in space)
    /// and the radius is `≥ 0`.
    pub holds: Vec<Affine3>,
}

impl RadiusFn {
    /// The radius at `p` (the affine function, wherever the contact holds
    /// or not).
    #[inline]
    pub fn at(&self, p: Point3) -> f64 {
        self.radius.at(p)
    }

    /// How far inside the region where the contact holds `p` lies: the
    /// least of the (unit) conditions, negative outside.
    pub fn margin(&self, p: Point3) -> f64 {
        self.holds.iter().map(|h| h.at(p)).fold(f64::INFINITY, f64::min)
    }
}

/// The unit condition `g·q(p) + g0 ≥ 0` on a point `q(p) = p + s(p)·u`
/// moved along `u` by the radius: affine in `p` again.
fn along(g: Point3, g0: f64, u: Point3, s: Affine3) -> Option<Affine3> {
    let gu = g.dot(u);
    let grad = g + s.grad * gu;
    let at0 = g0 + gu * s.at0;
    unit(Affine3 { grad, at0 })
}

/// `f` scaled to a unit gradient (`None` for a constant or a non-finite
/// one: a condition that does not depend on the point is always or never
/// true, and callers only build ones that do).
fn unit(f: Affine3) -> Option<Affine3> {
    let n = f.grad.norm();
    (n > 0.0 && n.is_finite()).then(|| Affine3 { grad: f.grad * (1.0 / n), at0: f.at0 / n })
}

/// The radius function of contact class `(x̃, y)` for balls anchored at
/// ball vertex `anchor` (the domain's representative vertex), for the
/// regular types VF, EE and FV. `None` for a non-regular pair, indices
/// out of range, or a class the anchored balls never reach by growing
/// (its equation does not depend on the radius: the anchor lies on the
/// feature, `w̃ = ṽ`, `ṽ` on the facet, or the ball edge's line through
/// `ṽ` parallel to the surface edge's plane).
pub fn radius_fn(mesh: &Mesh3d, ball: &Ball3, anchor: usize, x: Feature3, y: SurfacePart) -> Option<RadiusFn> {
    let pos = |i: u32| mesh.positions().get(i as usize).copied();
    let v = *ball.vertices().get(anchor)?;
    match (x, y) {
        (Feature3::Vertex(w), SurfacePart::Face(t)) => {
            if w == anchor {
                return None;
            }
            let [a, b, d] = mesh.triangles().get(t as usize)?.map(|i| mesh.positions()[i as usize]);
            let n = (b - a).cross(d - a);
            let u = *ball.vertices().get(w)? - v;
            let k = n.dot(u);
            if k.is_nan() || k <= 0.0 {
                return None;
            }
            let s = Affine3 { grad: n * (-1.0 / k), at0: n.dot(a) / k };
            // The met point q lies left of each side seen from outside:
            // (n × (e₁ − e₀))·(q − e₀) ≥ 0.
            let mut holds = Vec::with_capacity(4);
            for (e0, e1) in [(a, b), (b, d), (d, a)] {
                let m = n.cross(e1 - e0);
                holds.push(along(m, -m.dot(e0), u, s)?);
            }
            holds.push(unit(s)?);
            Some(RadiusFn { radius: s, holds })
        }
        (Feature3::Edge(k), SurfacePart::Edge([i, j])) => {
            let edge = ball.edges().get(k)?;
            // An edge through the anchor keeps its line as the ball grows
            // (its equation is `0 = …`, which rounding would not show).
            if edge.vertices.contains(&anchor) {
                return None;
            }
            let (ta, tb) = (ball.vertices()[edge.vertices[0]], ball.vertices()[edge.vertices[1]]);
            let (e0, e1) = (pos(i)?, pos(j)?);
            let (u, w, alpha) = (tb - ta, e1 - e0, ta - v);
            let nn = u.cross(w);
            let den = nn.dot(alpha);
            let n2 = nn.norm2();
            if den == 0.0 || n2.is_nan() || n2 <= 0.0 {
                return None;
            }
            let s = Affine3 { grad: nn * (-1.0 / den), at0: nn.dot(e0) / den };
            // With P(p) = p + s(p)·α − e₀ (the ball edge's start less
            // e₀): λ = −P·(u × N)/|N|², μ·s = −P·(w × N)/|N|².
            let (un, wn) = (u.cross(nn), w.cross(nn));
            let holds = vec![
                along(-un, un.dot(e0), alpha, s)?,     // λ ≥ 0
                along(un, n2 - un.dot(e0), alpha, s)?, // λ ≤ 1
                along(-wn, wn.dot(e0), alpha, s)?,     // μ·s ≥ 0
                mu_below_one(wn, e0, alpha, s, n2)?,   // μ·s ≤ s
                unit(s)?,
            ];
            Some(RadiusFn { radius: s, holds })
        }
        (Feature3::Facet(f), SurfacePart::Vertex(i)) => {
            let facet = ball.facets().get(f)?;
            if facet.vertices.contains(&anchor) {
                return None;
            }
            let q = pos(i)?;
            let (nt, h) = (facet.normal, facet.offset);
            let k = h - nt.dot(v);
            if k.is_nan() || k <= 0.0 {
                return None;
            }
            let s = Affine3 { grad: nt * (-1.0 / k), at0: nt.dot(q) / k };
            // q − c = q − p + s·ṽ lies in s·f̃: left of each of the
            // facet's sides seen from outside, m·(q − c − s·ẽ₀) ≥ 0 for
            // m = ñ × (ẽ₁ − ẽ₀).
            let corners = &facet.vertices;
            let mut holds = Vec::with_capacity(corners.len() + 1);
            for (idx, &c0) in corners.iter().enumerate() {
                let (t0, t1) = (ball.vertices()[c0], ball.vertices()[corners[(idx + 1) % corners.len()]]);
                let m = nt.cross(t1 - t0);
                let g = m.dot(v - t0);
                holds.push(unit(Affine3 { grad: -m + s.grad * g, at0: m.dot(q) + g * s.at0 })?);
            }
            holds.push(unit(s)?);
            Some(RadiusFn { radius: s, holds })
        }
        _ => None,
    }
}

/// `s − μ·s ≥ 0` times `|N|²`: `|N|²·s(p) + P(p)·(w × N) ≥ 0`.
fn mu_below_one(wn: Point3, e0: Point3, alpha: Point3, s: Affine3, n2: f64) -> Option<Affine3> {
    let ga = wn.dot(alpha);
    let grad = s.grad * n2 + wn + s.grad * ga;
    let at0 = n2 * s.at0 - wn.dot(e0) + ga * s.at0;
    unit(Affine3 { grad, at0 })
}
