//! Where a contact domain lies (thesis 3.3.1): the contact plane of its
//! class, with coordinates in which its points are taken exactly.
//!
//! A VF class's domain is its face: the point `(a, b)` is
//! `corner₀ + a·(corner₁ − corner₀) + b·(corner₂ − corner₀)`. An EE
//! class `([ṽ, ṽ*], [e₀, e₁])`'s contact plane holds the surface edge and
//! is parallel to the ball edge: the point `(a, b)` is
//! `e₀ + a·(e₁ − e₀) + b·(ṽ* − ṽ)`, so `b = 0` is the edge's line and the
//! ball `p + s·(B − ṽ)` anchored at `p` reaches that line with its edge
//! at `s = −b` (at `a` along the edge). An FV class `(f̃, v)`'s plane
//! holds `v` and is parallel to the facet: for a representative corner
//! `ṽ` and two consecutive corners `x̃ₖ, x̃ₖ₊₁` of `f̃` the point `(a, b)`
//! is `v + a·(ṽ − x̃ₖ) + b·(ṽ − x̃ₖ₊₁)`, so the anchored ball's facet holds
//! `v` in its sector `ṽ, x̃ₖ, x̃ₖ₊₁` from radius `a + b` on. All are
//! differences of given
//! points, so a point with `f64` coordinates `(a, b)` is a rational point
//! of the plane exactly (the maximal* ball there is decided on it, not a
//! rounding beside it).

use super::radius::Affine3;
use crate::kernel::Point3;
use crate::shape::ball::Reach;
use crate::shape::{ExactMaximalBall, Mesh3d};

/// A contact plane with its coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DomainPlane {
    /// The point `(0, 0)`.
    pub base: Point3,
    /// `(1, 0)` lies at `base + u₁ − u₀`.
    pub u: [Point3; 2],
    /// `(0, 1)` lies at `base + w₁ − w₀`.
    pub w: [Point3; 2],
    /// For a face's plane, its corners (the ball at a point of the open
    /// face is stopped by the face only where its cone enters it).
    pub face: Option<[Point3; 3]>,
}

/// A line of a domain, `ca·a + cb·b + c0 = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line2 {
    /// The coefficient of `a`.
    pub ca: f64,
    /// The coefficient of `b`.
    pub cb: f64,
    /// The constant.
    pub c0: f64,
}

impl Line2 {
    /// Its affine function at `(a, b)`.
    pub fn at(&self, (a, b): (f64, f64)) -> f64 {
        self.ca * a + self.cb * b + self.c0
    }
}

impl DomainPlane {
    /// The plane of triangle `face` of `mesh`, in the triangle's own
    /// parameters. `None` for a face out of range.
    pub fn of_face(mesh: &Mesh3d, face: u32) -> Option<DomainPlane> {
        let c = mesh.triangles().get(face as usize)?.map(|i| mesh.positions()[i as usize]);
        Some(DomainPlane { base: c[0], u: [c[0], c[1]], w: [c[0], c[2]], face: Some(c) })
    }

    /// The contact plane of the edge from `e0` to `e1` and the ball edge
    /// from `anchor` (`ṽ`) to `far` (`ṽ*`).
    pub fn of_edge(e0: Point3, e1: Point3, anchor: Point3, far: Point3) -> DomainPlane {
        DomainPlane { base: e0, u: [e0, e1], w: [anchor, far], face: None }
    }

    /// The contact plane of the vertex `v` and a ball facet, for its
    /// corner `anchor` (`ṽ`) and the sector towards its corners `xk`,
    /// `xk1` (consecutive).
    pub fn of_corner(v: Point3, anchor: Point3, xk: Point3, xk1: Point3) -> DomainPlane {
        DomainPlane { base: v, u: [xk, anchor], w: [xk1, anchor], face: None }
    }

    /// The point `(a, b)`, rounded.
    pub fn point(&self, (a, b): (f64, f64)) -> Point3 {
        self.base + (self.u[1] - self.u[0]) * a + (self.w[1] - self.w[0]) * b
    }

    /// An affine function of space on the plane, in its coordinates.
    pub fn line(&self, f: &Affine3) -> Line2 {
        Line2 { ca: f.grad.dot(self.u[1] - self.u[0]), cb: f.grad.dot(self.w[1] - self.w[0]), c0: f.at(self.base) }
    }

    /// The coordinate `b` as an affine function of a point of space (on
    /// the plane; extended across it along its normal).
    pub fn b_of(&self) -> Affine3 {
        let (u, w) = (self.u[1] - self.u[0], self.w[1] - self.w[0]);
        // (u × q)·(u × w) = q·(|u|²·w − (u·w)·u) for q = p − base.
        let g = w * u.norm2() - u * u.dot(w);
        let k = u.cross(w).norm2();
        Affine3 { grad: g * (1.0 / k), at0: -g.dot(self.base) / k }
    }

    /// The maximal* ball with ball vertex `anchor` at the point `(a, b)`,
    /// taken exactly on the plane.
    pub fn maximal_ball(
        &self,
        mesh: &Mesh3d,
        at: (f64, f64),
        anchor: usize,
        reach: &Reach<'_>,
    ) -> Option<ExactMaximalBall> {
        match self.face {
            Some(corners) => mesh.tree().maximal_ball_exact_on(corners, at, anchor, reach),
            None => mesh.tree().maximal_ball_exact_span(self.base, self.u, self.w, at, anchor, reach),
        }
    }
}
