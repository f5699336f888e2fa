//! Contact classes of a solid under a polyhedral ball (thesis 3.1.2,
//! Definitions 3.1.7–3.1.9): the pairs (ball feature, surface feature)
//! that a ball inscribed in the solid can touch with, the sets the 3D
//! axis is computed over (each regular class has a contact plane and a
//! contact domain, 3.3.1).
//!
//! A ball `c + r·B` inside the solid that touches the surface at `x` is
//! separated from the solid's exterior near `x` by a plane through `x`:
//! its normal `ν` lies in the ball's normal cone at the ball feature and
//! in the exterior's normal cone at the surface feature. For the regular
//! types that is a condition on outward normals alone:
//!
//! * VF `(ṽ, t)`: `t`'s outward normal lies in the normal cone of `B` at
//!   `ṽ`, i.e. `ṽ` is the ball vertex farthest along it (a climb over the
//!   ball's vertex graph, each step an exact sign). Every triangle has
//!   one; a ball edge or facet parallel to `t` ties several vertices,
//!   and each is listed, marked `tie` (the input is then outside the
//!   thesis's general position).
//! * EE `(ẽ, e)`: `e` is a reflex edge (the exterior near it is the convex
//!   wedge of its two faces; at a convex edge no ball fits: it would poke
//!   out along its own edge) and the planar fans of outward normals of
//!   `ẽ` (its two facets) and of `e` (its two triangles) cross: four
//!   normals `a, b` (ball) and `c, d` (surface) share a direction
//!   `αa + βb = γc + δd` with all coefficients positive iff
//!   `det(b,c,d)`, `−det(a,c,d)`, `−det(a,b,d)` and `det(a,b,c)` have one
//!   strict sign (Cramer's rule for the dependency of four vectors in
//!   space). Zeros with the other signs agreeing are fans touching at an
//!   end: listed, marked `tie`.
//! * FV `(f̃, v)`: a plane through `v` parallel to the facet `f̃` (outward
//!   normal `ñ`) has the exterior near `v` strictly on its outer side:
//!   `ñ·(x − v) > 0` for every neighbour `x` of `v` (the exterior's cone
//!   is spanned by its edges), and the exterior is the side of `v`'s link
//!   that lies in that open half-space, not the solid. Where `v` has no
//!   convex edge the exterior is locally convex and that holds at once; at
//!   a saddle (convex and reflex edges, the floor corner of an L-shaped
//!   pocket) the link, projected from `v` onto the plane `ñ·d = 1`, must
//!   turn counter-clockwise seen from outside: the exterior lies left of
//!   each link edge (its triangle's normal points there), so it is the
//!   small side iff the projected polygon's signed area is positive. A
//!   neighbour on the plane (`ñ·(x − v) = 0`, the others beyond) is a
//!   facet parallel to an edge at `v`: listed, marked `tie`.
//!
//! These are the classes that are locally possible; whether a maximal*
//! ball features one is what its contact domain tells (empty or not).
//!
//! Cost: VF is a short climb per triangle; EE asks every ball edge at
//! every reflex edge (reflex edges × ball edges tests), FV every ball
//! facet at every vertex with a reflex edge. Output-sensitive
//! would be a walk on the ball's Gauss map: the arc from the reflex edge's
//! first normal to its second crosses exactly the fans of the ball edges
//! of its classes, from the region of the vertex farthest along the first
//! normal to that of the second (left for when large solids need it).
//! Every sign is exact: the normals are cross products of coordinate
//! differences, the signs triple products of them, decided on the `f64`
//! filter of `kernel/exact_space.rs` and on integers where it is unsure.

use crate::kernel::bigint::BigInt;
use crate::kernel::exact_line::Units;
use crate::kernel::exact_space::{Fb, Ring, V3};
use crate::kernel::Point3;
use crate::shape::ball::{Ball3, ContactKind3, Feature3};
use crate::shape::{Mesh3d, SurfacePart};
use std::cmp::Ordering;

/// One contact class: a ball feature and a surface feature that an
/// inscribed ball can touch with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ContactClass {
    /// The contact type (VF, EE or FV).
    pub kind: ContactKind3,
    /// The ball's feature.
    pub ball: Feature3,
    /// The surface's feature (a triangle's interior, an edge or a
    /// vertex).
    pub surface: SurfacePart,
    /// True when a normal of the ball lies on the boundary of the
    /// surface feature's normal cone or the other way round: a ball
    /// feature parallel to a surface feature, outside general position.
    pub tie: bool,
}

/// The regular contact classes of a solid under a ball.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ContactClasses {
    /// VF classes, by triangle then ball vertex.
    pub vertex_face: Vec<ContactClass>,
    /// EE classes, by surface edge then ball edge.
    pub edge_edge: Vec<ContactClass>,
    /// FV classes, by surface vertex then ball facet.
    pub face_vertex: Vec<ContactClass>,
    /// The reflex edges of the surface (ends, lesser first), sorted.
    pub reflex_edges: Vec<[u32; 2]>,
    /// The convex edges (ends, lesser first), sorted; the rest are flat.
    pub convex_edges: Vec<[u32; 2]>,
}

impl ContactClasses {
    /// Every class, VF first.
    pub fn all(&self) -> impl Iterator<Item = &ContactClass> {
        self.vertex_face.iter().chain(&self.edge_edge).chain(&self.face_vertex)
    }

    /// Whether `(ball, surface)` is a class (of any kind listed here).
    pub fn contains(&self, ball: Feature3, surface: SurfacePart) -> bool {
        self.all().any(|c| c.ball == ball && c.surface == surface)
    }
}

/// The VF, EE and FV contact classes of `mesh` under `ball` (thesis
/// 3.1.2).
pub fn contact_classes(mesh: &Mesh3d, ball: &Ball3) -> ContactClasses {
    let p = mesh.positions();
    let tris = mesh.triangles();
    let corners = |t: usize| tris[t].map(|i| p[i as usize]);
    let mut out = ContactClasses::default();
    let around = vertex_neighbours(ball);
    let mut start = 0;
    for t in 0..tris.len() {
        let (tops, tie) = top_vertices(ball, &around, corners(t), start);
        start = tops[0];
        for v in tops {
            out.vertex_face.push(ContactClass {
                kind: ContactKind3::VertexFace,
                ball: Feature3::Vertex(v),
                surface: SurfacePart::Face(t as u32),
                tie,
            });
        }
    }
    for h in 0..3 * tris.len() {
        let twin = mesh.twin(h);
        if twin < h {
            continue;
        }
        let (t1, k1, t2, k2) = (h / 3, h % 3, twin / 3, twin % 3);
        let (a, b) = (tris[t1][k1], tris[t1][(k1 + 1) % 3]);
        let other = p[tris[t2][(k2 + 2) % 3] as usize];
        let edge = [a.min(b), a.max(b)];
        match turn(corners(t1), other) {
            Ordering::Less => {
                out.convex_edges.push(edge);
                continue;
            }
            Ordering::Equal => continue,
            Ordering::Greater => out.reflex_edges.push(edge),
        }
        for (k, e) in ball.edges().iter().enumerate() {
            let fans = [e.facets[0], e.facets[1]].map(|f| facet_corners(ball, f));
            if let Some(tie) = fans_cross(fans, [corners(t1), corners(t2)]) {
                out.edge_edge.push(ContactClass {
                    kind: ContactKind3::EdgeEdge,
                    ball: Feature3::Edge(k),
                    surface: SurfacePart::Edge(edge),
                    tie,
                });
            }
        }
    }
    out.reflex_edges.sort_unstable();
    out.convex_edges.sort_unstable();
    out.edge_edge.sort_by_key(|c| (c.surface, c.ball));
    out.face_vertex = face_vertex_classes(mesh, ball, &out.reflex_edges, &out.convex_edges);
    out
}

/// The FV classes: at every vertex with a reflex edge, the ball facets
/// whose plane through the vertex leaves the exterior strictly outside
/// near it (see the module's notes).
fn face_vertex_classes(mesh: &Mesh3d, ball: &Ball3, reflex: &[[u32; 2]], convex: &[[u32; 2]]) -> Vec<ContactClass> {
    let p = mesh.positions();
    let (mut has_reflex, mut has_convex) = (vec![false; p.len()], vec![false; p.len()]);
    reflex.iter().flatten().for_each(|&i| has_reflex[i as usize] = true);
    convex.iter().flatten().for_each(|&i| has_convex[i as usize] = true);
    // A half-edge out of each vertex.
    let mut out_of = vec![usize::MAX; p.len()];
    for (h, &v) in mesh.triangles().iter().flatten().enumerate() {
        out_of[v as usize] = h;
    }
    let mut out = Vec::new();
    for v in (0..p.len()).filter(|&v| has_reflex[v] && out_of[v] != usize::MAX) {
        let link = link_of(mesh, out_of[v]);
        let x = p[v];
        for f in 0..ball.facets().len() {
            let t = facet_corners(ball, f);
            let mut tie = false;
            let beyond = link.iter().all(|&i| {
                let s = sign_of(&[t[0], t[1], t[2], x, p[i as usize]], &Along { t, from: x, to: p[i as usize] });
                tie |= s == Ordering::Equal;
                s != Ordering::Less
            });
            if !beyond
                || (has_convex[v]
                    && !exterior_is_small_side(t, x, &link.iter().map(|&i| p[i as usize]).collect::<Vec<_>>()))
            {
                continue;
            }
            out.push(ContactClass {
                kind: ContactKind3::FaceVertex,
                ball: Feature3::Facet(f),
                surface: SurfacePart::Vertex(v as u32),
                tie,
            });
        }
    }
    out
}

/// The neighbours of the vertex that half-edge `start` leaves, in the
/// order of its triangles around it: triangle `(v, xⱼ, xⱼ₊₁)` is
/// counter-clockwise seen from outside.
fn link_of(mesh: &Mesh3d, start: usize) -> Vec<u32> {
    let tris = mesh.triangles();
    // Round by twins: the edge into `v` of one triangle, turned, leaves
    // `v` in the next one (the surface is vertex-manifold).
    let mut link = Vec::new();
    let mut h = start;
    loop {
        let (t, k) = (h / 3, h % 3);
        link.push(tris[t][(k + 1) % 3]);
        h = mesh.twin(3 * t + (k + 2) % 3);
        if h == start || link.len() > tris.len() {
            return link;
        }
    }
}

/// Whether the exterior near `x` is the side of its link (`xⱼ` in order,
/// all beyond the plane through `x` parallel to facet `t`) inside that
/// half-space: the link projected from `x` onto `ñ·d = 1` turns
/// counter-clockwise seen from outside, `Σⱼ det(ñ, dⱼ, dⱼ₊₁) / (ñ·dⱼ ñ·dⱼ₊₁)
/// > 0` for `dⱼ = xⱼ − x`, taken over the common positive denominator.
fn exterior_is_small_side(t: [Point3; 3], x: Point3, link: &[Point3]) -> bool {
    let mut values = vec![t[0], t[1], t[2], x];
    values.extend_from_slice(link);
    sign_of(&values, &LinkTurn { t, x, link: link.to_vec() }) == Ordering::Greater
}

/// `Σⱼ det(ñ, dⱼ, dⱼ₊₁) · Πᵢ≠ⱼ,ⱼ₊₁ ñ·dᵢ` (see `exterior_is_small_side`).
struct LinkTurn {
    t: [Point3; 3],
    x: Point3,
    link: Vec<Point3>,
}

impl Expr for LinkTurn {
    fn eval<R: Ring>(&self, units: Units) -> R {
        let n = normal::<R>(self.t, units);
        let d: Vec<V3<R>> = self.link.iter().map(|&q| V3::diff(q, self.x, units)).collect();
        let heights: Vec<R> = d.iter().map(|dj| n.dot(dj)).collect();
        let k = d.len();
        let mut sum = R::of(0.0, units);
        for j in 0..k {
            let mut term = n.det(&d[j], &d[(j + 1) % k]);
            for (i, h) in heights.iter().enumerate() {
                if i != j && i != (j + 1) % k {
                    term = term.mul(h);
                }
            }
            sum = sum.add(&term);
        }
        sum
    }
}

/// Each ball vertex's neighbours along the ball's edges.
fn vertex_neighbours(ball: &Ball3) -> Vec<Vec<usize>> {
    let mut around = vec![Vec::new(); ball.vertices().len()];
    for e in ball.edges() {
        around[e.vertices[0]].push(e.vertices[1]);
        around[e.vertices[1]].push(e.vertices[0]);
    }
    around
}

/// Three corners of ball facet `f`, counter-clockwise seen from outside:
/// their normal points out.
fn facet_corners(ball: &Ball3, f: usize) -> [Point3; 3] {
    let k = &ball.facets()[f].vertices;
    [k[0], k[1], k[2]].map(|i| ball.vertices()[i])
}

/// The sign of an expression written once over a [`Ring`]: the filter
/// first, integers in units covering `values` behind it.
fn sign_of<E: Expr>(values: &[Point3], expr: &E) -> Ordering {
    let units = Units::covering(values.iter().flat_map(|q| q.to_array()));
    expr.eval::<Fb>(units).sign().or_else(|| expr.eval::<BigInt>(units).sign()).unwrap_or(Ordering::Equal)
}

/// An expression evaluated on any ring.
trait Expr {
    fn eval<R: Ring>(&self, units: Units) -> R;
}

/// The outward normal of a triangle (counter-clockwise seen from outside).
fn normal<R: Ring>([a, b, c]: [Point3; 3], units: Units) -> V3<R> {
    V3::diff(b, a, units).cross(&V3::diff(c, a, units))
}

/// `n_t · (w_u − w_v)` for triangle `t`'s normal.
struct Along {
    t: [Point3; 3],
    from: Point3,
    to: Point3,
}

impl Expr for Along {
    fn eval<R: Ring>(&self, units: Units) -> R {
        normal::<R>(self.t, units).dot(&V3::diff(self.to, self.from, units))
    }
}

/// The ball vertices farthest along triangle `t`'s outward normal (one,
/// unless a ball edge or facet is parallel to `t`: then all of that face
/// of the ball, and `true`): a climb from `start` over the vertex graph,
/// each step an exact sign (on a convex polytope a vertex no neighbour
/// beats is farthest).
fn top_vertices(ball: &Ball3, around: &[Vec<usize>], t: [Point3; 3], start: usize) -> (Vec<usize>, bool) {
    let w = ball.vertices();
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    // An f64 start near the answer (the climb is exact).
    let mut v = start.min(w.len() - 1);
    loop {
        let better = around[v].iter().copied().max_by(|&a, &b| n.dot(w[a]).total_cmp(&n.dot(w[b])));
        match better {
            Some(u) if n.dot(w[u]) > n.dot(w[v]) => v = u,
            _ => break,
        }
    }
    let beats = |v: usize, u: usize| sign_of(&[t[0], t[1], t[2], w[v], w[u]], &Along { t, from: w[v], to: w[u] });
    while let Some(u) = around[v].iter().copied().find(|&u| beats(v, u) == Ordering::Greater) {
        v = u;
    }
    // Vertices tying with `v` are connected to it through tying ones.
    let mut tops = vec![v];
    let mut at = 0;
    while at < tops.len() {
        let x = tops[at];
        at += 1;
        for &u in &around[x] {
            if !tops.contains(&u) && beats(v, u) == Ordering::Equal {
                tops.push(u);
            }
        }
    }
    let tie = tops.len() > 1;
    tops.sort_unstable();
    (tops, tie)
}

/// How the edge shared by triangle `t` and another triangle whose third
/// corner is `other` turns: reflex (`Greater`: `other` lies strictly on
/// the outer side of `t`'s plane), convex (`Less`) or flat (`Equal`).
fn turn(t: [Point3; 3], other: Point3) -> Ordering {
    sign_of(&[t[0], t[1], t[2], other], &Along { t, from: t[0], to: other })
}

/// A triple product `det(u, v, w)` of the normals `a, b` (two ball
/// facets), `c, d` (two triangles) and `n = a × b`, by index 0–4.
struct Triple {
    ball: [[Point3; 3]; 2],
    surface: [[Point3; 3]; 2],
    rows: [usize; 3],
}

impl Expr for Triple {
    fn eval<R: Ring>(&self, units: Units) -> R {
        let [a, b] = self.ball.map(|t| normal::<R>(t, units));
        let [c, d] = self.surface.map(|t| normal::<R>(t, units));
        let n = a.cross(&b);
        let all = [a, b, c, d, n];
        let [i, j, k] = self.rows;
        all[i].det(&all[j], &all[k])
    }
}

/// Whether the fans of the outward normals of two ball facets (`a`, `b`)
/// and of two triangles (`c`, `d`) cross (`Some(false)`), touch or
/// overlap only at their ends or along a common plane (`Some(true)`, a
/// tie: a ball edge parallel to the surface edge, or a normal of one
/// on the other's fan) or miss (`None`).
fn fans_cross(ball: [[Point3; 3]; 2], surface: [[Point3; 3]; 2]) -> Option<bool> {
    let values: Vec<Point3> = ball.iter().chain(&surface).flatten().copied().collect();
    let sign = |rows: [usize; 3]| sign_of(&values, &Triple { ball, surface, rows });
    // det(b,c,d), −det(a,c,d), −det(a,b,d), det(a,b,c).
    let signs = [sign([1, 2, 3]), sign([0, 2, 3]).reverse(), sign([0, 1, 3]).reverse(), sign([0, 1, 2])];
    let zeros = signs.iter().filter(|&&s| s == Ordering::Equal).count();
    if zeros == 4 {
        // All four normals in one plane (a ball edge parallel to the
        // surface edge): the arcs of one great circle overlap iff an end
        // of one lies on the other. `n = a × b` orients the circle, and
        // `det(n, a, b) > 0`; `c` and `d` in that orientation turn as
        // `det(n, c, d)`.
        let within_ab = |x: usize| sign([4, 0, x]) != Ordering::Less && sign([4, x, 1]) != Ordering::Less;
        let cd = sign([4, 2, 3]);
        let within_cd = |x: usize| {
            let (lo, hi) = if cd == Ordering::Less { (3, 2) } else { (2, 3) };
            sign([4, lo, x]) != Ordering::Less && sign([4, x, hi]) != Ordering::Less
        };
        return (within_ab(2) || within_ab(3) || within_cd(0) || within_cd(1)).then_some(true);
    }
    let positive = signs.iter().all(|&s| s != Ordering::Less);
    let negative = signs.iter().all(|&s| s != Ordering::Greater);
    (positive || negative).then_some(zeros > 0)
}
