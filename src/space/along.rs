//! The contact arrangement of a contact domain along a segment of it (a
//! VF class's face, an EE class's plane: [`DomainPlane`]): which class
//! the maximal* balls anchored on the segment touch opposite,
//! piece by piece, and where and how that changes (thesis 3.3.2.3, the
//! one-dimensional step of Algorithms 3 and 4).
//!
//! The balls are `p + s·(B − ṽ)` for `p` on the segment and `ṽ` the
//! domain's representative vertex; on each piece the radius `ρ(p)` of the largest
//! one inside the solid equals one opposite class's affine radius
//! function ([`radius_fn`]). Where the opposite class changes from `A` to
//! `B`, at `t*`, either `ρ` is continuous, so `ρ_A(t*) = ρ_B(t*)` for the
//! affine functions extended beyond where their contacts hold and `t*` is
//! the meeting point of two lines (both contacts holding there: a tie, a
//! seam's projection; one of them ending there with a neighbour taking
//! over: a handover, a pseudo-seam), or `ρ` jumps, where a contact starts
//! or stops holding against the wall of the cone the balls fill (a jump
//! sheet seen edge-on), and `t*` is where that contact's condition
//! crosses 0. When the classes just beside a candidate are not `A` and
//! `B`, more than one change lies between, and the interval is halved
//! (`searchcc`).
//!
//! Between two samples with one class the stretch is crossing-free when
//! no triangle enters the hull of their two balls (`sweep`: the balls in
//! between fill it), and halved otherwise (`searchcc*`); so is each
//! stretch from a sample to a confirmed change.
//!
//! Which class holds at a point is decided exactly (the exact maximal*
//! ball at the sample, taken on the triangle's plane); the change points
//! and the hull test are `f64` (a triangle entering the hull by less than
//! 10^-10 of the solid's size is not seen, nor a piece narrower than the
//! check's width, 10^-6 of the interval being resolved); inputs outside
//! general position (a ball facet lying flat on a
//! triangle) are refused, as are segments whose samples see no ball
//! (radius 0 or unbounded: the segment leaves the open face).

use super::domain::DomainPlane;
use super::radius::{radius_fn, RadiusFn};
use crate::kernel::Point3;
use crate::shape::ball::{ContactKind3, Feature3, Reach};
use crate::shape::{Mesh3d, SurfacePart};

/// Stretches the segment is cut into before any halving: one, as the
/// hull test tells whether a stretch needs halving (16 found the same
/// pieces on the test families at four times the cost).
const SAMPLES: usize = 1;

/// Halvings before a change is given up as unresolvable.
const MAX_DEPTH: usize = 48;

/// An opposite contact class: a ball feature and a surface feature.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Opposite {
    /// The ball's feature.
    pub ball: Feature3,
    /// The surface's feature.
    pub surface: SurfacePart,
    /// The contact type (VF, EE or FV).
    pub kind: ContactKind3,
}

/// A stretch of the segment with one opposite class.
#[derive(Debug, Clone, PartialEq)]
pub struct AlongPiece {
    /// Where it starts and ends, as parameters of the segment in `[0, 1]`.
    pub from: f64,
    /// See `from`.
    pub to: f64,
    /// The opposite class of every maximal* ball anchored on the piece.
    pub opposite: Opposite,
    /// Its radius function: the maximal* radius on the piece.
    pub radius: RadiusFn,
}

/// How the opposite class changes at a point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChangeKind {
    /// Both contacts hold there: the ball touches the domain's class and
    /// both opposite ones (a seam's projection, or a jump seam's).
    Tie,
    /// One contact ends there (its met point reaches the end of its
    /// feature, a non-regular contact) and a neighbour takes over: a
    /// pseudo-seam's or jump sheet's projection.
    Handover,
    /// The two classes have one radius function (the same ball feature
    /// on coplanar triangles, or on a triangle and an edge or vertex in
    /// its plane): the contact moves on across the flat edge between
    /// them, and the axis has no seam there.
    Continued,
    /// The radius jumps: one contact starts or stops holding where the
    /// balls' cone only grazes its triangle (the ball edge from the anchor
    /// to the touching vertex lies along the cone's wall), so beside it the
    /// triangle is never entered. The projection of a jump sheet that
    /// collapses to a segment in this domain (its balls share the anchor
    /// vertex: thesis 3.3.1.2, vertex-dependent jump projections).
    Jump,
}

/// A change between two pieces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AlongChange {
    /// Where, as a parameter of the segment.
    pub at: f64,
    /// The point of the domain there.
    pub point: Point3,
    /// The maximal* radius there.
    pub radius: f64,
    /// Tie or handover.
    pub kind: ChangeKind,
}

/// The opposite classes along a segment: `changes[i]` lies between
/// `pieces[i]` and `pieces[i + 1]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Along {
    /// The pieces, in order along the segment.
    pub pieces: Vec<AlongPiece>,
    /// The changes.
    pub changes: Vec<AlongChange>,
}

/// Why a segment's arrangement was not found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AlongError {
    /// The face or the ball vertex does not exist, or the vertex is not
    /// the one farthest along the face's normal (no VF class).
    NoClass,
    /// A sample's ball has radius 0 or grows without bound: the point is
    /// not in the open face's domain.
    NoBall {
        /// The sample's parameter.
        at: f64,
    },
    /// A sample's ball lies flat on a triangle or touches several classes
    /// at once however it is nudged: outside general position.
    NotGeneral {
        /// The sample's parameter.
        at: f64,
    },
    /// Changes closer together than halving can separate.
    Unresolved {
        /// Where.
        at: f64,
    },
}

impl std::fmt::Display for AlongError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            AlongError::NoClass => write!(f, "no VF class of that face and ball vertex"),
            AlongError::NoBall { at } => write!(f, "no maximal* ball of positive finite radius at t = {at}"),
            AlongError::NotGeneral { at } => write!(f, "the ball at t = {at} is outside general position"),
            AlongError::Unresolved { at } => write!(f, "changes too close together near t = {at}"),
        }
    }
}

impl std::error::Error for AlongError {}

/// A sample: where, its maximal* ball and that ball's opposite class.
#[derive(Debug, Clone, Copy)]
struct Sample {
    t: f64,
    class: Opposite,
    centre: Point3,
    radius: f64,
}

/// A change found: where, the class after it, how.
#[derive(Debug, Clone, Copy)]
struct Change {
    at: f64,
    next: Opposite,
    kind: ChangeKind,
}

/// One question: the domain's plane, its anchor and the segment in the
/// plane's coordinates.
struct Walk<'a> {
    mesh: &'a Mesh3d,
    reach: &'a Reach<'a>,
    plane: DomainPlane,
    anchor: usize,
    from: (f64, f64),
    to: (f64, f64),
}

impl Walk<'_> {
    fn params(&self, t: f64) -> (f64, f64) {
        (self.from.0 + t * (self.to.0 - self.from.0), self.from.1 + t * (self.to.1 - self.from.1))
    }

    fn point(&self, t: f64) -> Point3 {
        self.plane.point(self.params(t))
    }

    /// The maximal* ball at `t` and its opposite class, exactly:
    /// `Ok(None)` when the ball there touches more than one class or a
    /// non-regular one (a change lies exactly there).
    fn sample_exactly_at(&self, t: f64) -> Result<Option<Sample>, AlongError> {
        let got = self
            .plane
            .maximal_ball(self.mesh, self.params(t), self.anchor, self.reach)
            .ok_or(AlongError::NoBall { at: t })?;
        if !(got.radius > 0.0 && got.radius.is_finite()) {
            return Err(AlongError::NoBall { at: t });
        }
        if got.flat {
            return Err(AlongError::NotGeneral { at: t });
        }
        Ok(match got.opposite.as_slice() {
            [c] if matches!(c.kind, ContactKind3::VertexFace | ContactKind3::EdgeEdge | ContactKind3::FaceVertex) => {
                let class = Opposite { ball: c.ball, surface: c.surface, kind: c.kind };
                Some(Sample { t, class, centre: got.centre, radius: got.radius })
            }
            _ => None,
        })
    }

    /// The sample at `t`, or nudged toward `toward` by a few millionths
    /// of the way when the ball at `t` itself touches several classes.
    fn sample_near(&self, t: f64, toward: f64) -> Result<Sample, AlongError> {
        let mut at = t;
        for k in 0..4 {
            if let Some(s) = self.sample_exactly_at(at)? {
                return Ok(s);
            }
            at = t + (toward - t) * 1e-6 * f64::from(1 << (2 * k));
        }
        Err(AlongError::NotGeneral { at: t })
    }

    /// Whether the balls between two samples of one class stay inside:
    /// no triangle enters their hull (`sweep`), so no other class lies
    /// between.
    fn crossing_free(&self, a: &Sample, b: &Sample) -> bool {
        let size = self.mesh.tree().bbox().diagonal();
        let tol = 1e-10 * (size + a.radius.max(b.radius));
        self.mesh.tree().enters_hull((a.centre, a.radius), (b.centre, b.radius), self.reach, tol).is_none()
    }

    /// The radius function of class `c`, seen at `at` (for the error).
    fn radius_of(&self, c: Opposite, at: f64) -> Result<RadiusFn, AlongError> {
        radius_fn(self.mesh, self.reach.ball(), self.anchor, c.ball, c.surface).ok_or(AlongError::NotGeneral { at })
    }

    /// The changes strictly between samples `a` and `b`, appended in
    /// order: none when they have one class and the balls between them
    /// stay inside; one where a candidate is confirmed by the classes just
    /// beside it (and the stretches from `a` and to `b` are crossing-free);
    /// else those of the two halves.
    fn resolve(&self, a: &Sample, b: &Sample, depth: usize, out: &mut Vec<Change>) -> Result<(), AlongError> {
        let (t0, t1) = (a.t, b.t);
        if a.class == b.class && self.crossing_free(a, b) {
            return Ok(());
        }
        if depth > MAX_DEPTH || t1 - t0 <= 4.0 * f64::EPSILON {
            return Err(AlongError::Unresolved { at: t0 });
        }
        if a.class != b.class {
            if let Some((lo, kind, t, hi)) = self.confirmed_change(a, b)? {
                self.resolve(a, &lo, depth + 1, out)?;
                out.push(Change { at: t, next: b.class, kind });
                return self.resolve(&hi, b, depth + 1, out);
            }
        }
        // More than one change, or one class with another between: halve
        // (`searchcc`, `searchcc*`).
        let m = self.sample_near(0.5 * (t0 + t1), t1)?;
        self.resolve(a, &m, depth + 1, out)?;
        self.resolve(&m, b, depth + 1, out)
    }

    /// The single change between samples of two classes, when a candidate
    /// for it has those classes just beside it: the samples there, its
    /// kind and place.
    fn confirmed_change(
        &self,
        a: &Sample,
        b: &Sample,
    ) -> Result<Option<(Sample, ChangeKind, f64, Sample)>, AlongError> {
        let (t0, t1) = (a.t, b.t);
        let (fa, fb) = (self.radius_of(a.class, a.t)?, self.radius_of(b.class, b.t)?);
        let same = self.same_function(&fa, &fb);
        // Where the radius is continuous, the change lies where the two
        // lines meet; where it jumps, where one of the two contacts
        // starts or stops holding.
        let candidates = [
            (!same).then(|| self.meeting(&fa, &fb, t0, t1)).flatten(),
            self.holds_from(&fb, t0, t1, false),
            self.holds_from(&fa, t0, t1, true),
        ];
        for t in candidates.into_iter().flatten() {
            let width = 1e-6 * (t1 - t0);
            let (lo, hi) = ((t - width).max(t0), (t + width).min(t1));
            if !(lo > t0 && hi < t1) {
                continue;
            }
            let (slo, shi) = (self.sample_near(lo, t0)?, self.sample_near(hi, t1)?);
            if slo.class != a.class || shi.class != b.class {
                continue;
            }
            let p = self.point(t);
            let tol = 1e-9 * (self.point(t0) - self.point(t1)).norm().max(fa.at(p).abs());
            let kind = if same {
                ChangeKind::Continued
            } else if (fa.at(p) - fb.at(p)).abs() > tol {
                ChangeKind::Jump
            } else if fa.margin(p).min(fb.margin(p)) > tol {
                ChangeKind::Tie
            } else {
                ChangeKind::Handover
            };
            return Ok(Some((slo, kind, t, shi)));
        }
        Ok(None)
    }

    /// Whether two radius functions agree along the whole segment (to
    /// rounding): then they have no meeting point, and the change is where
    /// the first one's contact ends.
    fn same_function(&self, fa: &RadiusFn, fb: &RadiusFn) -> bool {
        let (p0, p1) = (self.point(0.0), self.point(1.0));
        let scale = (p1 - p0).norm() + fa.at(p0).abs() + fa.at(p1).abs();
        [p0, p1].iter().all(|&p| (fa.at(p) - fb.at(p)).abs() <= 1e-12 * scale)
    }

    /// Where `f`'s contact stops holding (`ends`: the first of its
    /// conditions to fall to 0 after `t0`) or starts holding (the last to
    /// rise to 0 before `t1`), strictly between `t0` and `t1`.
    fn holds_from(&self, f: &RadiusFn, t0: f64, t1: f64, ends: bool) -> Option<f64> {
        let (p0, p1) = (self.point(0.0), self.point(1.0));
        let zeros = f.holds.iter().filter_map(|h| {
            let (v0, v1) = (h.at(p0), h.at(p1));
            ((v1 < v0) == ends && v1 != v0).then(|| v0 / (v0 - v1))
        });
        let inside = zeros.filter(|&t| t > t0 && t < t1);
        if ends {
            inside.min_by(f64::total_cmp)
        } else {
            inside.max_by(f64::total_cmp)
        }
    }

    /// Where the two radius functions meet strictly between `t0` and `t1`.
    fn meeting(&self, fa: &RadiusFn, fb: &RadiusFn, t0: f64, t1: f64) -> Option<f64> {
        let (p0, p1) = (self.point(0.0), self.point(1.0));
        let (a0, a1) = (fa.at(p0), fa.at(p1));
        let (b0, b1) = (fb.at(p0), fb.at(p1));
        let slope = (a1 - a0) - (b1 - b0);
        if slope == 0.0 {
            return None;
        }
        let t = (b0 - a0) / slope;
        (t > t0 && t < t1).then_some(t)
    }
}

/// The opposite classes of the maximal* balls anchored at ball vertex
/// `anchor` along the segment from `from` to `to` of triangle `face`
/// (points given by the triangle's own parameters `(a, b)`:
/// `corner0 + a·(corner1 − corner0) + b·(corner2 − corner0)`, both ends
/// inside the open triangle). `(anchor, face)` must be a VF class: the
/// anchor is the ball vertex farthest along the face's outward normal,
/// so the balls grow into the solid.
///
/// # Errors
///
/// [`AlongError`]: no such class, a sample with no ball of positive
/// finite radius, input outside general position, changes closer
/// together than halving separates.
pub fn opposite_along(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    face: u32,
    anchor: usize,
    from: (f64, f64),
    to: (f64, f64),
) -> Result<Along, AlongError> {
    let plane = vf_plane(mesh, reach, face, anchor)?;
    opposite_along_in(mesh, reach, &plane, anchor, from, to)
}

/// The plane of the VF class `(anchor, face)`: its face's. `NoClass` when
/// the face or the vertex does not exist, or the vertex is not the one
/// farthest along the face's outward normal.
pub(crate) fn vf_plane(mesh: &Mesh3d, reach: &Reach<'_>, face: u32, anchor: usize) -> Result<DomainPlane, AlongError> {
    let plane = DomainPlane::of_face(mesh, face).ok_or(AlongError::NoClass)?;
    let corners = plane.face.ok_or(AlongError::NoClass)?;
    let n = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    let w = reach.ball().vertices();
    if anchor >= w.len() || w.iter().any(|&x| n.dot(x - w[anchor]) > 0.0) {
        return Err(AlongError::NoClass);
    }
    Ok(plane)
}

/// The opposite classes of the maximal* balls anchored at ball vertex
/// `anchor` along the segment from `from` to `to` of a contact domain's
/// plane (points in its coordinates, both ends inside the domain: every
/// ball there has a positive finite radius).
///
/// # Errors
///
/// As [`opposite_along`], less the check of the class.
pub fn opposite_along_in(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    plane: &DomainPlane,
    anchor: usize,
    from: (f64, f64),
    to: (f64, f64),
) -> Result<Along, AlongError> {
    let walk = Walk { mesh, reach, plane: *plane, anchor, from, to };
    let ts: Vec<f64> = (0..=SAMPLES).map(|k| k as f64 / SAMPLES as f64).collect();
    let mut seen = Vec::with_capacity(ts.len());
    for (k, &t) in ts.iter().enumerate() {
        let toward = if k + 1 < ts.len() { ts[k + 1] } else { ts[k - 1] };
        seen.push(walk.sample_near(t, toward)?);
    }
    let mut changes: Vec<Change> = Vec::new();
    for pair in seen.windows(2) {
        walk.resolve(&pair[0], &pair[1], 0, &mut changes)?;
    }
    let mut pieces = Vec::with_capacity(changes.len() + 1);
    let mut start = (0.0, seen[0].class);
    let mut out_changes = Vec::with_capacity(changes.len());
    for &Change { at: t, next, kind } in &changes {
        let radius = walk.radius_of(start.1, start.0)?;
        let p = walk.point(t);
        out_changes.push(AlongChange { at: t, point: p, radius: radius.at(p), kind });
        pieces.push(AlongPiece { from: start.0, to: t, opposite: start.1, radius });
        start = (t, next);
    }
    pieces.push(AlongPiece { from: start.0, to: 1.0, opposite: start.1, radius: walk.radius_of(start.1, start.0)? });
    Ok(Along { pieces, changes: out_changes })
}
