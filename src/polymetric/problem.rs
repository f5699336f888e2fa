//! A polygonal shape under a polygon ball, prepared for the axis: vertices
//! in one global list, convex and reflex vertices decided exactly, the
//! contact classes of every edge and reflex vertex (ids in a fixed order,
//! which is also the tie-break of the symbolic perturbation), the exact
//! and the `f64` data of each class on demand, and a box tree of the edges.

use super::classes::{ApproxClass, BallFeature, ClassKind, ContactClass, ExactClass, ShapeFeature};
use super::error::BallAxisError;
use crate::kernel::exact_line::{ILine, IVec, Units};
use crate::kernel::{BBox, FilteredKernel, Kernel, Orientation, Point};
use crate::shape::model::error::ElementRef;
use crate::shape::{Ball2, ChainTree, Shape2d};
use std::sync::OnceLock;

/// Class ids: `0..edges` are the edges' VE/EE classes (class `e` belongs to
/// edge `e`), then the EV classes vertex by vertex.
pub(crate) type ClassId = u32;

pub(crate) struct Problem<'a> {
    pub ball: &'a Ball2,
    /// All vertices of all loops (outer counter-clockwise, holes clockwise:
    /// the interior lies left of every edge).
    pub pts: Vec<Point>,
    /// Loop `l` holds vertices `offsets[l]..offsets[l + 1]`.
    pub offsets: Vec<usize>,
    pub reflex: Vec<bool>,
    /// `degenerate[e]`: edge `e` is a point site's zero-length element; its
    /// class (kept so that class `e` stays edge `e`'s) is never a contact.
    pub degenerate: Vec<bool>,
    pub classes: Vec<ContactClass>,
    /// EV classes of vertex `v`: `ev[v]..ev[v + 1]` (empty unless reflex).
    ev: Vec<u32>,
    pub shape_units: Units,
    pub ball_units: Units,
    ball_ints: Vec<IVec>,
    /// The edges in runs along their loops, bounded by capsules and boxes
    /// (plain edge boxes fail among long thin spikes, where a point lies in
    /// the boxes of a fixed fraction of all edges).
    pub chain: ChainTree,
    /// The shape's diagonal (model units): the scale of the filters' margins.
    pub diag: f64,
    /// Largest |v| over the ball's vertices: c + r·B lies in the disk of
    /// radius r·reach.
    pub reach: f64,
    /// The ball's box `[min x, max x, min y, max y]` (ball units): c + r·B
    /// lies in c + r·box.
    pub extent: [f64; 4],
    /// Every class in `f64` ([`Problem::approx`]).
    approx: Vec<ApproxClass>,
    /// The exact classes made so far ([`Problem::exact`]).
    exact: Vec<OnceLock<Box<ExactClass>>>,
}

impl<'a> Problem<'a> {
    pub(crate) fn new(shape: &Shape2d, ball: &'a Ball2) -> Result<Problem<'a>, BallAxisError> {
        let mut pts = Vec::with_capacity(shape.element_count());
        let mut offsets = vec![0];
        let mut point = Vec::new();
        for (l, lp) in shape.loops().iter().enumerate() {
            point.push(lp.kind() == crate::shape::LoopKind::Point);
            for (i, v) in lp.vertices().iter().enumerate() {
                if v.bulge != 0.0 {
                    return Err(BallAxisError::Arc { l, i: shape.input_element_index(l, i) });
                }
                pts.push(v.p);
            }
            offsets.push(pts.len());
        }
        let n = pts.len();
        let degenerate: Vec<bool> =
            (0..offsets.len() - 1).flat_map(|l| std::iter::repeat_n(point[l], offsets[l + 1] - offsets[l])).collect();
        let mut p = Problem {
            ball,
            pts,
            offsets,
            reflex: vec![false; n],
            degenerate,
            classes: Vec::with_capacity(n),
            ev: Vec::with_capacity(n + 1),
            shape_units: Units::covering([]),
            ball_units: Units::covering(ball.vertices().iter().flat_map(|v| [v.x, v.y])),
            ball_ints: Vec::new(),
            chain: ChainTree::new(shape.loops()),
            diag: shape.bbox().diagonal(),
            reach: ball.vertices().iter().map(|v| v.norm()).fold(0.0, f64::max),
            extent: ball
                .vertices()
                .iter()
                .fold([f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY], |e, v| {
                    [e[0].min(v.x), e[1].max(v.x), e[2].min(v.y), e[3].max(v.y)]
                }),
            approx: Vec::new(),
            exact: Vec::new(),
        };
        p.shape_units = Units::covering(p.pts.iter().flat_map(|v| [v.x, v.y]));
        p.ball_ints = ball.vertices().iter().map(|v| p.ball_units.vec(*v)).collect();
        for e in 0..n {
            let (a, b) = p.edge(e as u32);
            let kind = match ball.touching_edge(a, b) {
                f @ BallFeature::Vertex(_) => (ClassKind::VE, f),
                f @ BallFeature::Edge(_) => (ClassKind::EE, f),
            };
            p.classes.push(ContactClass { kind: kind.0, shape: ShapeFeature::Edge(e as u32), ball: kind.1 });
        }
        let k = ball.len();
        let bv = ball.vertices();
        for v in 0..n {
            p.ev.push(p.classes.len() as u32);
            let (prev, next) = (p.pts[p.prev(v as u32) as usize], p.pts[p.next(v as u32) as usize]);
            let here = p.pts[v];
            // A point site's vertex faces every way (its fan of normals is
            // a whole turn); a curve site's ends are cusps (a fan of π,
            // which the cross-product test below picks out as it is).
            let (point, cusp) = (p.degenerate[v], prev == next);
            p.reflex[v] = point || cusp || FilteredKernel.orientation(prev, here, next) == Orientation::Right;
            if !p.reflex[v] {
                continue;
            }
            if point {
                for i in 0..k {
                    p.classes.push(ContactClass {
                        kind: ClassKind::EV,
                        shape: ShapeFeature::Vertex(v as u32),
                        ball: BallFeature::Edge(i),
                    });
                }
                continue;
            }
            // Ball edges whose outward normal lies strictly inside the fan
            // from the incoming edge's normal clockwise to the outgoing one's;
            // normals turned alike keep their cross products.
            for i in 0..k {
                let (vi, vj) = (bv[i], bv[(i + 1) % k]);
                if FilteredKernel.cross_sign(prev, here, vi, vj) == Orientation::Right
                    && FilteredKernel.cross_sign(vi, vj, here, next) == Orientation::Right
                {
                    p.classes.push(ContactClass {
                        kind: ClassKind::EV,
                        shape: ShapeFeature::Vertex(v as u32),
                        ball: BallFeature::Edge(i),
                    });
                }
            }
        }
        p.ev.push(p.classes.len() as u32);
        p.approx = (0..p.classes.len() as ClassId).map(|c| p.make_approx(c)).collect();
        p.exact = (0..p.classes.len()).map(|_| OnceLock::new()).collect();
        Ok(p)
    }

    /// The edge of the chain tree's element `r`.
    pub(crate) fn edge_of(&self, r: ElementRef) -> u32 {
        (self.offsets[r.loop_index] + r.element) as u32
    }

    /// The edge's box.
    pub(crate) fn edge_box(&self, e: u32) -> BBox {
        let (a, b) = self.edge(e);
        BBox::of_points(a, b)
    }

    pub(crate) fn edge_count(&self) -> usize {
        self.pts.len()
    }

    /// The loop holding global vertex `v`.
    pub(crate) fn loop_of(&self, v: u32) -> usize {
        self.offsets.partition_point(|&o| o <= v as usize) - 1
    }

    pub(crate) fn next(&self, v: u32) -> u32 {
        let l = self.loop_of(v);
        if v as usize + 1 == self.offsets[l + 1] {
            self.offsets[l] as u32
        } else {
            v + 1
        }
    }

    pub(crate) fn prev(&self, v: u32) -> u32 {
        let l = self.loop_of(v);
        if v as usize == self.offsets[l] {
            self.offsets[l + 1] as u32 - 1
        } else {
            v - 1
        }
    }

    /// Edge `e`'s end points.
    pub(crate) fn edge(&self, e: u32) -> (Point, Point) {
        (self.pts[e as usize], self.pts[self.next(e) as usize])
    }

    /// The EV classes of vertex `v`.
    pub(crate) fn ev_classes(&self, v: u32) -> std::ops::Range<ClassId> {
        self.ev[v as usize]..self.ev[v as usize + 1]
    }

    /// Every class whose contact can lie on edge `e` (closed): its own, and
    /// the EV classes of its two end points.
    pub(crate) fn classes_of_edge(&self, e: u32) -> impl Iterator<Item = ClassId> + '_ {
        let own = (!self.degenerate[e as usize]).then_some(e);
        // A point site's element starts and ends at its one vertex.
        let end = (!self.degenerate[e as usize]).then(|| self.ev_classes(self.next(e))).into_iter().flatten();
        own.into_iter().chain(self.ev_classes(e)).chain(end)
    }

    /// The edges a class's contact lies on: its edge, or both edges at its vertex.
    pub(crate) fn edges_of(&self, c: ClassId) -> [u32; 2] {
        match self.classes[c as usize].shape {
            ShapeFeature::Edge(e) => [e, e],
            ShapeFeature::Vertex(v) => [self.prev(v), v],
        }
    }

    /// The ball's vertices as integers in ball units.
    pub(crate) fn ball_ints(&self) -> &[IVec] {
        &self.ball_ints
    }

    fn ball_vertex(&self, i: usize) -> (Point, &IVec) {
        let k = self.ball.len();
        (self.ball.vertices()[i % k], &self.ball_ints[i % k])
    }

    /// The class's function and validity lines, exact: made on first use
    /// and kept (a class is asked for at every node it ties and every
    /// trace along it; making one costs a dozen big-integer products).
    pub(crate) fn exact(&self, c: ClassId) -> &ExactClass {
        self.exact[c as usize].get_or_init(|| Box::new(self.make_exact(c)))
    }

    fn make_exact(&self, c: ClassId) -> ExactClass {
        let cl = self.classes[c as usize];
        match (cl.kind, cl.shape, cl.ball) {
            (ClassKind::EV, ShapeFeature::Vertex(v), BallFeature::Edge(i)) => {
                let p = self.shape_units.vec(self.pts[v as usize]);
                let (vi, vj) = (self.ball_vertex(i).1, self.ball_vertex(i + 1).1);
                let d = vj.sub(vi);
                let m = IVec::new(d.y.clone(), -&d.x);
                let h = m.dot(vi);
                let k = m.dot(&p);
                // cross(v_i, p − c) ≥ 0 and cross(p − c, v_j) ≥ 0.
                let g1 = ILine::new(IVec::new(vi.y.clone(), -&vi.x), vi.cross(&p));
                let g2 = ILine::new(IVec::new(-&vj.y, vj.x.clone()), p.cross(vj));
                ExactClass { n: m, k, h, valid: vec![g1, g2] }
            }
            (kind, ShapeFeature::Edge(e), ball) => {
                let (a, b) = self.edge(e);
                let (a, b) = (self.shape_units.vec(a), self.shape_units.vec(b));
                let u = b.sub(&a);
                let n = IVec::new(u.y.clone(), -&u.x);
                // The ball vertices at the contact's two ends along u.
                let (ahead, behind) = match (kind, ball) {
                    (ClassKind::EE, BallFeature::Edge(i)) => (i + 1, i),
                    (_, BallFeature::Vertex(i)) | (_, BallFeature::Edge(i)) => (i, i),
                };
                let (va, vb) = (self.ball_vertex(ahead).1, self.ball_vertex(behind).1);
                let h = n.dot(va);
                let k = n.dot(&a);
                // h·(c − a)·u + (K − n·c)(v·u) ≥ 0 with v the end ahead;
                // h·(b − c)·u − (K − n·c)(v·u) ≥ 0 with v the end behind.
                let (au, bu) = (a.dot(&u), b.dot(&u));
                let vau = va.dot(&u);
                let vbu = vb.dot(&u);
                let g1 = ILine::new(u.scale(&h).sub(&n.scale(&vau)), &(&k * &vau) - &(&h * &au));
                let g2 = ILine::new(n.scale(&vbu).sub(&u.scale(&h)), &(&h * &bu) - &(&k * &vbu));
                let g3 = ILine::new(n.neg(), k.clone());
                ExactClass { n, k, h, valid: vec![g1, g2, g3] }
            }
            _ => unreachable!("classes are built as VE/EE on edges and EV on vertices"),
        }
    }

    /// The class's function and validity in model units (rounded), made
    /// once per class when the problem is built: the new-contact search
    /// asks for it at every box it opens.
    #[inline]
    pub(crate) fn approx(&self, c: ClassId) -> ApproxClass {
        self.approx[c as usize]
    }

    fn make_approx(&self, c: ClassId) -> ApproxClass {
        let cl = self.classes[c as usize];
        let unit = |g: Point, g0: f64| {
            let l = g.norm();
            if l > 0.0 {
                (g * (1.0 / l), g0 / l)
            } else {
                (g, g0)
            }
        };
        match (cl.shape, cl.ball) {
            (ShapeFeature::Vertex(v), BallFeature::Edge(i)) => {
                let p = self.pts[v as usize];
                let (vi, vj) = (self.ball_vertex(i).0, self.ball_vertex(i + 1).0);
                let d = vj - vi;
                let m = Point::new(d.y, -d.x);
                let g1 = unit(Point::new(vi.y, -vi.x), vi.x * p.y - vi.y * p.x);
                let g2 = unit(Point::new(-vj.y, vj.x), p.x * vj.y - p.y * vj.x);
                ApproxClass { n: m, k: m.dot(p), h: m.dot(vi), valid: [g1, g2, g2], n_valid: 2 }
            }
            (ShapeFeature::Edge(e), ball) => {
                let (a, b) = self.edge(e);
                let u = b - a;
                let n = Point::new(u.y, -u.x);
                let (ahead, behind) = match (cl.kind, ball) {
                    (ClassKind::EE, BallFeature::Edge(i)) => (i + 1, i),
                    (_, BallFeature::Vertex(i)) | (_, BallFeature::Edge(i)) => (i, i),
                };
                let (va, vb) = (self.ball_vertex(ahead).0, self.ball_vertex(behind).0);
                let (h, k) = (n.dot(va), n.dot(a));
                let (vau, vbu) = (va.dot(u), vb.dot(u));
                let g1 = unit(u * h - n * vau, k * vau - h * a.dot(u));
                let g2 = unit(n * vbu - u * h, h * b.dot(u) - k * vbu);
                let g3 = unit(n * -1.0, k);
                ApproxClass { n, k, h, valid: [g1, g2, g3], n_valid: 3 }
            }
            _ => unreachable!("classes are built as VE/EE on edges and EV on vertices"),
        }
    }
}
