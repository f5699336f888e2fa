//! A node of the axis analysed exactly: the contact classes of its ball,
//! and the rays of the axis leaving it.
//!
//! Near a node `P` of radius `r` the distance to the boundary is
//! `r + min L_C(x)` over the classes `C` tied at `P` whose validity cone
//! holds the step `x` (`L_C(x) = −n_C·x / h_C`). The classes' owner regions
//! meet along rays: the tie lines of two classes and the validity
//! boundaries through `P`. Those directions are sorted by angle, the owner
//! of each gap between two of them is decided at a direction inside it,
//! and a direction with different owners on its two sides is a ray of the
//! axis unless both owners touch at one point (a *hair*: a ball vertex on
//! a shape vertex sliding out of it; these are pruned, Definition 3.2.1).
//!
//! Symbolic perturbation: equal values are broken by the class id (the
//! smaller id wins), as if class `C` were raised by `ε·C` for an
//! infinitesimal ε. Outside general position (a ball edge parallel to a
//! line through two reflex vertices, collinear shape edges under a ball
//! edge) two classes can be equal on a whole region; the rule gives that
//! region to one of them and the axis stays one-dimensional, every point of
//! it still the centre of a ball touching the boundary twice.

use super::classes::{ContactClass, ExactClass, ShapeFeature};
use super::problem::{ClassId, Problem};
use crate::kernel::exact_line::{cmp_angle, HPoint, ILine, IVec};
use crate::kernel::xfloat::{sign_or, Fx};
use crate::kernel::{BBox, BigInt, Point};
use std::cmp::Ordering;

/// A ray of the axis out of a node.
#[derive(Debug, Clone)]
pub(crate) struct Ray {
    pub dir: IVec,
    /// The input-level line the ray runs on (a tie line or a validity line).
    pub carrier: ILine,
    /// Owners on the ray's left and right.
    pub left: ClassId,
    pub right: ClassId,
    /// Every class equal to the distance along the ray (left and right among them).
    pub along: Vec<ClassId>,
    pub traced: bool,
}

/// A node: exact position, contacts, rays.
#[derive(Debug, Clone)]
pub(crate) struct Node {
    pub p: HPoint,
    pub at: Point,
    pub r: f64,
    pub corner: bool,
    /// A ball vertex on a shape vertex (VV contact).
    pub vv: bool,
    pub tied: Vec<ClassId>,
    /// Edges the ball touches here (closed).
    pub touching: Vec<u32>,
    pub rays: Vec<Ray>,
}

struct Tied<'p> {
    id: ClassId,
    ex: &'p ExactClass,
    /// Validity lines through the node.
    active: Vec<usize>,
}

/// `(n_a·x)·h_b` against `(n_b·x)·h_a`: `Less` when class `a` grows slower along `x`.
fn cmp_slope(a: &ExactClass, b: &ExactClass, x: &IVec) -> Ordering {
    // L = −n·x/h, so a grows slower when n_a·x/h_a is larger.
    let [xx, xy] = x.fx();
    let dot = |c: &ExactClass| {
        let [nx, ny] = c.n.fx();
        nx * xx + ny * xy
    };
    let f = dot(b) * Fx::of(&a.h) - dot(a) * Fx::of(&b.h);
    sign_or(f, || (&b.n.dot(x) * &a.h).cmp_value(&(&a.n.dot(x) * &b.h)))
}

trait CmpValue {
    fn cmp_value(&self, o: &Self) -> Ordering;
}

impl CmpValue for BigInt {
    fn cmp_value(&self, o: &BigInt) -> Ordering {
        (self - o).signum()
    }
}

/// The tie line `f_a = f_b` (positive side: `f_a > f_b`), `None` when the
/// two have the same slope everywhere.
pub(crate) fn tie_line(a: &ExactClass, b: &ExactClass) -> Option<ILine> {
    let n = b.n.scale(&a.h).sub(&a.n.scale(&b.h));
    (!n.is_zero()).then(|| ILine::new(n, &(&a.k * &b.h) - &(&b.k * &a.h)))
}

/// `W·(K − n·P)`-type numerator of a class's radius at `p` (denominator `h·W`).
pub(crate) fn radius_num(c: &ExactClass, p: &HPoint) -> BigInt {
    &(&c.k * &p.w) - &(&(&c.n.x * &p.x) + &(&c.n.y * &p.y))
}

/// Whether class `c` gives `p` the radius `rn / (h_ref·W)` of the reference class.
fn same_radius(c: &ExactClass, reference: &ExactClass, rn: &BigInt, p: &HPoint) -> bool {
    let [nx, ny] = c.n.fx();
    let num = Fx::of(&c.k) * Fx::of(&p.w) - (nx * Fx::of(&p.x) + ny * Fx::of(&p.y));
    let f = num * Fx::of(&reference.h) - Fx::of(rn) * Fx::of(&c.h);
    if f.sign().is_some_and(|s| s != Ordering::Equal) {
        return false;
    }
    &radius_num(c, p) * &reference.h == rn * &c.h
}

/// Whether `p` satisfies every validity line of `c`.
pub(crate) fn valid_at(c: &ExactClass, p: &HPoint) -> bool {
    c.valid.iter().all(|g| g.side(p) != Ordering::Less)
}

impl Problem<'_> {
    /// True when the two classes touch the boundary at one point wherever
    /// they meet: their shape features are incident and so are their ball
    /// features. Their common boundary is then no part of the axis.
    pub(crate) fn is_hair(&self, a: ClassId, b: ClassId) -> bool {
        let (ca, cb) = (self.classes[a as usize], self.classes[b as usize]);
        self.shape_incident(&ca, &cb) && ca.ball_neighbours(&cb, self.ball.len())
    }

    fn shape_incident(&self, a: &ContactClass, b: &ContactClass) -> bool {
        use ShapeFeature::{Edge, Vertex};
        match (a.shape, b.shape) {
            (Edge(x), Edge(y)) => x == y || self.next(x) == y || self.next(y) == x,
            (Edge(e), Vertex(v)) | (Vertex(v), Edge(e)) => v == e || v == self.next(e),
            (Vertex(x), Vertex(y)) => x == y,
        }
    }

    /// The classes whose contact may lie in the box `query` and within
    /// `radius` of `at` (closed edges).
    pub(crate) fn classes_near(&self, at: Point, radius: f64, query: &BBox) -> Vec<ClassId> {
        let mut out = Vec::new();
        self.chain.visit_within(at, radius, |r| {
            let e = self.edge_of(r);
            if self.edge_box(e).overlaps(query) {
                out.extend(self.classes_of_edge(e));
            }
        });
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Analyses the node at `p`, where class `reference` is tied (its
    /// radius is the node's).
    pub(crate) fn analyse(&self, p: HPoint, reference: ClassId) -> Node {
        let at = p.approx(self.shape_units);
        let re = self.exact(reference);
        let r = self.approx(reference).radius(at).max(0.0);
        let rn = radius_num(re, &p);
        let corner = rn.is_zero();
        let slack = 1e-7 * self.diag + 1e-9 * r;
        // The ball at + r·B lies in at + r·(the ball's box); every contact
        // of a tied class lies on it.
        let e = self.extent;
        let grow = 1e-9 * r * self.reach + slack;
        let query =
            BBox::of_points(at + Point::new(r * e[0], r * e[2]), at + Point::new(r * e[1], r * e[3])).inflate(grow);
        // At a corner only the classes of its own vertex are tied: a curve
        // site's way back passes through the same point (radius 0 too),
        // but on the other side of the curve.
        let own_vertex = if corner {
            match self.classes[reference as usize].shape {
                ShapeFeature::Edge(e) => [e, self.next(e)]
                    .into_iter()
                    .find(|&v| HPoint::at(&self.shape_units.vec(self.pts[v as usize])).same(&p)),
                ShapeFeature::Vertex(v) => Some(v),
            }
        } else {
            None
        };
        let mut tied: Vec<Tied> = Vec::new();
        for c in self.classes_near(at, r * self.reach * (1.0 + 1e-9) + 2.0 * grow, &query) {
            if let Some(v) = own_vertex {
                let at_v = match self.classes[c as usize].shape {
                    ShapeFeature::Edge(e) => e == v || self.next(e) == v,
                    ShapeFeature::Vertex(x) => x == v,
                };
                if !at_v {
                    continue;
                }
            }
            // The f64 filter first: a class whose radius at the node or
            // validity misses by more than the slack is not tied (near the
            // middle of a large shape the box holds many edges, and each
            // exact class costs a dozen big-integer products).
            // Rounding of `at` moves the class's radius by its gradient
            // (|n|/h) times that rounding.
            let ac = self.approx(c);
            let off = 1e-12 * (at.x.abs() + at.y.abs() + r) * (1.0 + ac.n.norm() / ac.h.abs());
            if c != reference && ((ac.radius(at) - r).abs() > slack + off || ac.validity(at) < -(slack + off)) {
                continue;
            }
            let ex = self.exact(c);
            if !same_radius(ex, re, &rn, &p) || !valid_at(ex, &p) {
                continue;
            }
            let active = (0..ex.valid.len()).filter(|&i| ex.valid[i].side(&p) == Ordering::Equal).collect();
            tied.push(Tied { id: c, ex, active });
        }
        let mut node = Node { p, at, r, corner, vv: false, tied: Vec::new(), touching: Vec::new(), rays: Vec::new() };
        for t in &tied {
            node.tied.push(t.id);
            let cl = self.classes[t.id as usize];
            let [e0, e1] = self.edges_of(t.id);
            node.touching.extend([e0, e1]);
            // Validity lines 0 and 1 are the contact's two ends: a ball
            // vertex on a shape vertex when one holds with equality.
            let end_active = t.active.iter().any(|&i| i < 2);
            node.vv |= end_active && !corner;
            if let ShapeFeature::Edge(e) = cl.shape {
                if t.active.contains(&0) {
                    node.touching.push(self.prev(e));
                }
                if t.active.contains(&1) {
                    node.touching.push(self.next(e));
                }
            }
        }
        node.touching.sort_unstable();
        node.touching.dedup();
        node.rays = self.rays(&tied, corner);
        node
    }

    fn rays(&self, tied: &[Tied<'_>], corner: bool) -> Vec<Ray> {
        // Candidate directions with the line they lie on, and for a tie
        // line the two classes it ties: along it their slopes are equal
        // by construction, which the filter could never certify.
        type Dir = (IVec, Option<ILine>, Option<(usize, usize)>);
        let mut dirs: Vec<Dir> = Vec::new();
        for (i, a) in tied.iter().enumerate() {
            for (j, b) in tied.iter().enumerate().skip(i + 1) {
                if let Some(l) = tie_line(a.ex, b.ex) {
                    let d = l.direction();
                    dirs.push((d.neg(), Some(l.clone()), Some((i, j))));
                    dirs.push((d, Some(l), Some((i, j))));
                }
            }
            for &k in &a.active {
                let l = a.ex.valid[k].clone();
                let d = l.direction();
                dirs.push((d.neg(), Some(l.clone()), None));
                dirs.push((d, Some(l), None));
            }
        }
        for (x, y) in [(1, 0), (0, 1), (-1, 0), (0, -1)] {
            dirs.push((IVec::small(x, y), None, None));
        }
        dirs.sort_by(|a, b| cmp_angle(&a.0, &b.0).then_with(|| b.1.is_some().cmp(&a.1.is_some())));
        dirs.dedup_by(|b, a| cmp_angle(&a.0, &b.0) == Ordering::Equal);
        let m = dirs.len();
        // owners[j]: the owner of the gap from dirs[j] to dirs[j + 1].
        let owners: Vec<Option<usize>> = (0..m)
            .map(|j| {
                let mid = dirs[j].0.add_balanced(&dirs[(j + 1) % m].0);
                // At a corner the classes' regions reach outside the shape;
                // only steps into the wedge of its two edges count.
                let into = !corner || tied.iter().all(|t| t.ex.n.dot_sign(&mid) == Ordering::Less);
                if into {
                    self.owner(tied, &mid, false)
                } else {
                    None
                }
            })
            .collect();
        let mut rays = Vec::new();
        for j in 0..m {
            let (Some(l), Some(r)) = (owners[j], owners[(j + m - 1) % m]) else {
                continue;
            };
            if l == r || self.is_hair(tied[l].id, tied[r].id) {
                continue;
            }
            let Some(carrier) = dirs[j].1.clone() else {
                continue;
            };
            let d = &dirs[j].0;
            let tie = dirs[j].2;
            let slope = |a: usize, b: usize| {
                if a == b || tie == Some((a.min(b), a.max(b))) {
                    Ordering::Equal
                } else {
                    cmp_slope(tied[a].ex, tied[b].ex, d)
                }
            };
            let valid: Vec<usize> = (0..tied.len()).filter(|&i| self.valid_towards(&tied[i], d, true)).collect();
            let best = valid.iter().copied().min_by(|&a, &b| slope(a, b));
            let along = match best {
                Some(b) => {
                    valid.iter().copied().filter(|&i| slope(i, b) == Ordering::Equal).map(|i| tied[i].id).collect()
                }
                None => Vec::new(),
            };
            rays.push(Ray { dir: d.clone(), carrier, left: tied[l].id, right: tied[r].id, along, traced: false });
        }
        rays
    }

    fn valid_towards(&self, t: &Tied<'_>, x: &IVec, closed: bool) -> bool {
        t.active.iter().all(|&k| match t.ex.valid[k].n.dot_sign(x) {
            Ordering::Greater => true,
            Ordering::Equal => closed,
            Ordering::Less => false,
        })
    }

    /// The class owning the step `x` (index into `tied`): valid towards it,
    /// growing slowest, the smaller id on a tie.
    fn owner(&self, tied: &[Tied<'_>], x: &IVec, closed: bool) -> Option<usize> {
        let mut best: Option<usize> = None;
        for (i, t) in tied.iter().enumerate() {
            if !self.valid_towards(t, x, closed) {
                continue;
            }
            best = match best {
                None => Some(i),
                Some(b) => match cmp_slope(t.ex, tied[b].ex, x) {
                    Ordering::Less => Some(i),
                    Ordering::Equal if t.id < tied[b].id => Some(i),
                    _ => Some(b),
                },
            };
        }
        best
    }
}
