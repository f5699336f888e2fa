//! How far a space ball reaches: the least gauge `γ_B(x − c)` over a
//! triangle (where `c + r·B` grown from `c` first touches it) and cheap
//! lower bounds of it over boxes and triangles, which a search over a
//! tree of triangles prunes with (thesis 3.3.2.2).
//!
//! On a triangle T the gauge is convex and piecewise linear. Its minimum
//! over T's plane is where the ray from `c` through the ball's vertex
//! farthest toward the plane meets it (the ball grows until that vertex
//! touches: VF). When that point lies in T it is the answer; otherwise,
//! by convexity, the minimum over T lies on T's boundary, and on each
//! side the gauge is a convex piecewise linear function of one parameter
//! whose pieces are the ball's facets: walking from the side's start
//! through the facets' cones while the slope is negative finds its
//! minimum at a corner (FV) or where the side crosses from one cone to
//! the next (the plane through `c` and a ball edge: EE). The walk's
//! slopes increase strictly, so it takes at most one step per facet, and
//! in practice one or two.
//!
//! The value returned is the gauge evaluated at the point found, a point
//! of T (clamped there), so rounding that moved the point can only raise
//! it: it bounds the true minimum from above up to the rounding of that
//! one gauge (itself a climb in `f64`). The exact contact, with its
//! non-regular types, is decided apart (`touch_exact.rs`).

use super::reach_data::{DirectionTable, Neighbours, Prepared};
use super::Ball3;
use crate::kernel::{BBox3, Point3};

/// The type of a contact between a ball and a surface (thesis 3.1.2):
/// the ball's feature, then the surface's. The `f64` queries name the
/// regular type of the linear program's vertex they stop at (VF, EE or
/// FV, where a degenerate contact counts as the regular type it was found
/// by); the exact contact queries name the least features, so also the
/// non-regular VE, EV and VV.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ContactKind3 {
    /// A vertex of the ball on the interior of a triangle (VF).
    VertexFace,
    /// An edge of the ball crossing an edge of the surface (EE).
    EdgeEdge,
    /// A vertex of the surface on the interior of a ball facet (FV; found
    /// in `f64`: any point of the ball's boundary).
    FaceVertex,
    /// A vertex of the ball on the interior of an edge of the surface (VE).
    VertexEdge,
    /// A vertex of the surface on the interior of a ball edge (EV).
    EdgeVertex,
    /// A vertex of the ball on a vertex of the surface (VV).
    VertexVertex,
}

/// The least gauge over a triangle, where and how.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TriangleReach {
    /// `γ_B(point − c)`: the radius at which `c + r·B` touches.
    pub radius: f64,
    /// The point of the triangle touched.
    pub point: Point3,
    /// The contact's kind.
    pub kind: ContactKind3,
}

/// Balls with at most this many facets bound boxes by their own facet
/// planes (a few dot products each); rounder balls by their circumsphere
/// and bounding box, which are then nearly as tight and much cheaper.
const FACET_BOUND_LIMIT: usize = 16;

/// Cells per side of each face of the cube of directions in a
/// [`DirectionTable`]: 1536 cells, about ten per facet of a 128-facet ball,
/// so that a cell's facet is mostly the top one anywhere in the cell
/// (8 per side measured 35 % more triangles in full, 24 no fewer).
const TABLE_SIDE: usize = 16;

/// The cell of direction `x` (0 for a zero or non-finite one).
#[inline]
fn cell_of(x: Point3) -> usize {
    let a = [x.x.abs(), x.y.abs(), x.z.abs()];
    let axis = if a[0] >= a[1] && a[0] >= a[2] {
        0
    } else if a[1] >= a[2] {
        1
    } else {
        2
    };
    let m = a[axis];
    if !(m > 0.0 && m.is_finite()) {
        return 0;
    }
    let x = [x.x, x.y, x.z];
    let side = usize::from(x[axis] < 0.0);
    // One division: the cells are found often (twice per box opened).
    let half = 0.5 * TABLE_SIDE as f64;
    let scale = half / m;
    let cell = |v: f64| ((v * scale + half) as usize).min(TABLE_SIDE - 1);
    let (u, v) = (cell(x[(axis + 1) % 3]), cell(x[(axis + 2) % 3]));
    ((axis * 2 + side) * TABLE_SIDE + u) * TABLE_SIDE + v
}

/// The centre direction of cell `k` ([`cell_of`]'s inverse).
fn cell_centre(k: usize) -> Point3 {
    let (face, rest) = (k / (TABLE_SIDE * TABLE_SIDE), k % (TABLE_SIDE * TABLE_SIDE));
    let (axis, side) = (face / 2, face % 2);
    let at = |i: usize| (i as f64 + 0.5) / TABLE_SIDE as f64 * 2.0 - 1.0;
    let mut p = [0.0; 3];
    p[axis] = if side == 0 { 1.0 } else { -1.0 };
    p[(axis + 1) % 3] = at(rest / TABLE_SIDE);
    p[(axis + 2) % 3] = at(rest % TABLE_SIDE);
    Point3::from_array(p)
}

/// Where the last search step ended: the next one on a nearby triangle
/// starts its climbs there.
#[derive(Debug, Clone, Copy, Default)]
pub struct ReachHint {
    facet: usize,
    vertex: usize,
}

/// A ball prepared for many least-gauge questions: its facet and vertex
/// graphs (maximising a linear function over the vertices of a convex
/// polytope by climbing its edges ends at the maximum, so the facet whose
/// cone holds a direction and the vertex farthest in a direction are
/// found by a few steps from a nearby start instead of a scan of all of
/// them; the facets' rows are the vertices of the polar polytope) and the
/// lower bounds over boxes and triangles a search prunes with.
#[derive(Debug, Clone, Copy)]
pub struct Reach<'a> {
    ball: &'a Ball3,
    /// Made once per ball and kept in it (`Ball3::reach`).
    p: &'a Prepared,
}

/// Prepares `ball` (O(edges), and the direction table for balls of many
/// facets: about 90 µs for 128 facets, so a ball keeps what this makes).
pub(super) fn prepare(ball: &Ball3) -> Prepared {
    let bb = BBox3::of(ball.vertices().iter().copied());
    let inv = |v: f64| if v > 0.0 { 1.0 / v } else { 0.0 };
    let edges = ball.edges();
    let few = ball.facets().len() <= FACET_BOUND_LIMIT;
    let mut p = Prepared {
        facet_graph: Neighbours::of(ball.facets().len(), edges.iter().map(|e| (e.facets[0], e.facets[1]))),
        vertex_graph: Neighbours::of(ball.vertices().len(), edges.iter().map(|e| (e.vertices[0], e.vertices[1]))),
        table: None,
        few,
        inv_radius: inv(ball.circumradius()),
        up: [0, 1, 2].map(|a| inv(bb.max.coord(a))),
        down: [0, 1, 2].map(|a| inv(-bb.min.coord(a))),
    };
    if !few {
        // Cells in order are mostly neighbours: each climb starts from
        // the last one's answer.
        let reach = Reach { ball, p: &p };
        let (mut f, mut v) = (0, 0);
        let mut table = DirectionTable { facets: Vec::new(), vertices: Vec::new() };
        for k in 0..6 * TABLE_SIDE * TABLE_SIDE {
            let x = cell_centre(k);
            f = reach.climb_facet(x, f);
            v = reach.climb_vertex(x, v);
            table.facets.push(f as u32);
            table.vertices.push(v as u32);
        }
        p.table = Some(table);
    }
    p
}

impl<'a> Reach<'a> {
    /// `ball` prepared for least-gauge questions ([`Ball3::reach`]: made on
    /// the first call and kept in the ball).
    pub fn new(ball: &'a Ball3) -> Reach<'a> {
        Reach { ball, p: ball.prepared.0.get_or_init(|| Box::new(prepare(ball))) }
    }

    /// The ball.
    pub fn ball(&self) -> &'a Ball3 {
        self.ball
    }

    /// Lower bound of `γ_B(x − c)` over the box: the largest of the
    /// circumsphere's, the bounding box's and the least value over the box
    /// (taken at the corner its normal picks) of each facet's piece (few
    /// facets) or of the table's facet toward the box (many facets; no
    /// climb: any facet's piece bounds the gauge from below, and climbing
    /// to the top one for each box costs more than it spares).
    #[inline]
    pub fn over_box(&self, b: &BBox3, c: Point3) -> f64 {
        let (lo, hi) = (b.min - c, b.max - c);
        // Branch-free, as it runs twice per node opened: per axis the gap
        // beyond the box's near side (at most one of the two is nonzero).
        let above = Point3::new(lo.x.max(0.0), lo.y.max(0.0), lo.z.max(0.0));
        let below = Point3::new((-hi.x).max(0.0), (-hi.y).max(0.0), (-hi.z).max(0.0));
        let near = above - below;
        let mut lb = (above.x * self.p.up[0] + below.x * self.p.down[0])
            .max(above.y * self.p.up[1] + below.y * self.p.down[1])
            .max(above.z * self.p.up[2] + below.z * self.p.down[2]);
        let d2 = near.norm2();
        lb = lb.max(d2.sqrt() * self.p.inv_radius);
        // A facet's piece `a·(x − c)` is least over the box at the corner
        // its normal picks.
        let pick = |a: &Point3| {
            let at = |v: f64, l: f64, h: f64| v.max(0.0) * l + v.min(0.0) * h;
            at(a.x, lo.x, hi.x) + at(a.y, lo.y, hi.y) + at(a.z, lo.z, hi.z)
        };
        if self.p.few {
            for a in self.ball.gauge_rows() {
                lb = lb.max(pick(a));
            }
        } else if let (Some(t), true) = (&self.p.table, d2 > 0.0) {
            // The table's facet toward the box's point nearest `c`: its
            // piece is about the gauge there. Even for a nearly round ball
            // (a 128-facet one, inradius 0.96 of circumradius) it halves
            // the boxes opened from points deep in a solid against the
            // circumsphere alone (torus of 10^6 triangles: 569 → 314
            // nodes, 771 → 301 triangles per point).
            lb = lb.max(pick(&self.ball.gauge_rows()[t.facets[cell_of(near)] as usize]));
        }
        lb
    }

    /// Lower bound of `γ_B(x − c)` over the triangle: its box's, and the
    /// least over the corners of each facet's piece (few facets) or of
    /// the piece of the table's facet toward the triangle's centroid (any
    /// facet's piece bounds the gauge from below; the table's is the top
    /// one or a neighbour of it, and a climb to the top one would cost
    /// more than the triangles it spares: on a torus of 10^5 triangles
    /// the centroid's table facet measures 20 % fewer triangles in full
    /// than the first corner's top facet, at a third of the cost).
    /// Stops early, with the box's bound, when that reaches `enough`.
    pub fn over_triangle(&self, [a, b, d]: [Point3; 3], c: Point3, enough: f64, _hint: &mut ReachHint) -> f64 {
        let (a, b, d) = (a - c, b - c, d - c);
        let least = |r: Point3| r.dot(a).min(r.dot(b)).min(r.dot(d));
        let rows = self.ball.gauge_rows();
        if let (false, Some(t)) = (self.p.few, &self.p.table) {
            // The facet's piece alone: the box's bound, with a table
            // lookup of its own, is rarely tighter and costs as much again.
            return least(rows[t.facets[cell_of(a + b + d)] as usize]).max(0.0);
        }
        let mut lb = self.over_box(&BBox3::of([a, b, d]), Point3::new(0.0, 0.0, 0.0));
        if lb >= enough {
            return lb;
        }
        for &r in rows {
            lb = lb.max(least(r));
        }
        lb
    }

    /// The facet whose piece of the gauge is largest at `x` (whose cone
    /// holds `x`), climbing from the table's start or `from`.
    fn top_facet(&self, x: Point3, from: usize) -> usize {
        let from = self.p.table.as_ref().map_or(from, |t| t.facets[cell_of(x)] as usize);
        self.climb_facet(x, from)
    }

    /// The vertex farthest in direction `n`, from the table's start or
    /// `from`.
    fn top_vertex(&self, n: Point3, from: usize) -> usize {
        let from = self.p.table.as_ref().map_or(from, |t| t.vertices[cell_of(n)] as usize);
        self.climb_vertex(n, from)
    }

    /// [`top_facet`](Self::top_facet) climbing from `from`.
    fn climb_facet(&self, x: Point3, from: usize) -> usize {
        let rows = self.ball.gauge_rows();
        let mut f = from.min(rows.len() - 1);
        let mut value = rows[f].dot(x);
        loop {
            let step = self.p.facet_graph.of_item(f).map(|g| (g, rows[g].dot(x))).max_by(|p, q| p.1.total_cmp(&q.1));
            match step {
                Some((g, v)) if v > value => (f, value) = (g, v),
                _ => return f,
            }
        }
    }

    /// The vertex farthest in direction `n`, climbing from `from`.
    fn climb_vertex(&self, n: Point3, from: usize) -> usize {
        let w = self.ball.vertices();
        let mut v = from.min(w.len() - 1);
        let mut value = n.dot(w[v]);
        loop {
            let step = self.p.vertex_graph.of_item(v).map(|u| (u, n.dot(w[u]))).max_by(|p, q| p.1.total_cmp(&q.1));
            match step {
                Some((u, h)) if h > value => (v, value) = (u, h),
                _ => return v,
            }
        }
    }

    /// `γ_B(x)` by a climb from `from` (the facet found is left in `hint`).
    fn gauge(&self, x: Point3, hint: &mut ReachHint) -> f64 {
        hint.facet = self.top_facet(x, hint.facet);
        self.ball.gauge_rows()[hint.facet].dot(x).max(0.0)
    }

    /// The least `γ_B(x − c)` over the closed triangle (where `c + r·B`
    /// grown from `c` first touches it), its point and kind. A degenerate
    /// (zero-area) triangle is measured along its sides.
    pub fn triangle(&self, c: Point3, [a, b, d]: [Point3; 3], hint: &mut ReachHint) -> TriangleReach {
        let n = (b - a).cross(d - a);
        let h = n.dot(a - c);
        // The sides to walk: all, unless the plane's least point says
        // which can hold the least point of the triangle.
        let mut sides = [true; 3];
        if n.norm2() > 0.0 {
            if h == 0.0 {
                if inside_triangle(c, [a, b, d], n) {
                    return TriangleReach { radius: 0.0, point: c, kind: ContactKind3::VertexFace };
                }
            } else {
                match self.plane_touch(c, [a, b, d], n, h, hint) {
                    Ok(q) => {
                        return TriangleReach {
                            radius: self.gauge(q - c, hint),
                            point: q,
                            kind: ContactKind3::VertexFace,
                        }
                    }
                    Err(outside) => sides = outside,
                }
            }
        }
        let mut best: Option<TriangleReach> = None;
        for (k, (p, q)) in [(a, b), (b, d), (d, a)].into_iter().enumerate() {
            if !sides[k] {
                continue;
            }
            let r = self.segment(c, p, q, hint);
            if best.is_none_or(|b| r.radius < b.radius) {
                best = Some(r);
            }
        }
        best.unwrap_or_else(|| self.segment(c, a, b, hint))
    }

    /// Where the ball grown from `c` first touches the triangle's plane
    /// (normal `n`, `h = n·(a − c) ≠ 0`), when that point lies in the
    /// triangle: the ray through the vertex farthest toward the plane, or
    /// through a vertex tying with it (a whole edge or facet of the ball
    /// parallel to the plane touches it at once; the tying vertices are
    /// connected, so they are gathered by a walk from the top one).
    ///
    /// Otherwise the sides `ab`, `bd`, `da` whose lines do not hold the top
    /// vertex's point `q` strictly on the triangle's side: the gauge is
    /// convex on the plane and least at `q`, so from a least point `m` of
    /// the triangle the way to `q` descends, and it must leave the
    /// triangle at once (else `m` were not least) or stay level through a
    /// least point where it leaves; either way across a side whose line
    /// has `q` beyond it. Usually one or two sides of three.
    fn plane_touch(
        &self,
        c: Point3,
        t: [Point3; 3],
        n: Point3,
        h: f64,
        hint: &mut ReachHint,
    ) -> Result<Point3, [bool; 3]> {
        let toward = n * h.signum();
        let w = self.ball.vertices();
        hint.vertex = self.top_vertex(toward, hint.vertex);
        let tie = toward.dot(w[hint.vertex]) * (1.0 - 1e-12);
        let ray = |v: usize| c + w[v] * (h / n.dot(w[v]));
        let q = ray(hint.vertex);
        let outside = outside_sides(q, t, n);
        if outside == [false; 3] {
            return Ok(q);
        }
        // Usually no neighbour ties: then no list of the tying ones.
        if !self.p.vertex_graph.of_item(hint.vertex).any(|u| toward.dot(w[u]) >= tie) {
            return Err(outside);
        }
        let mut seen = vec![hint.vertex];
        let mut at = 0;
        while at < seen.len() {
            let v = seen[at];
            at += 1;
            for u in self.p.vertex_graph.of_item(v) {
                if !seen.contains(&u) && toward.dot(w[u]) >= tie {
                    let q = ray(u);
                    if inside_triangle(q, t, n) {
                        return Ok(q);
                    }
                    seen.push(u);
                }
            }
        }
        Err(outside)
    }

    /// The least gauge on the segment `p q`, by the walk through the
    /// facets' cones described in the module comment: the side leaves a
    /// facet's cone across one of its edges, into a neighbour's.
    fn segment(&self, c: Point3, p: Point3, q: Point3, hint: &mut ReachHint) -> TriangleReach {
        let rows = self.ball.gauge_rows();
        let (x, d) = (p - c, q - p);
        // Facet f's piece along the side: alpha_f + s·beta_f.
        let line = |f: usize| (rows[f].dot(x), rows[f].dot(d));
        let mut f = self.top_facet(x, hint.facet);
        let (mut alpha, mut beta) = line(f);
        let mut s = 0.0f64;
        while beta < 0.0 {
            // The next facet to take over: the first crossing ahead among
            // the steeper neighbours (on a tie, the steepest).
            let mut next: Option<(f64, usize, f64, f64)> = None;
            for g in self.p.facet_graph.of_item(f) {
                let (ag, bg) = line(g);
                if bg <= beta {
                    continue;
                }
                let sg = ((alpha - ag) / (bg - beta)).max(s);
                if next.is_none_or(|(sn, _, _, bn)| sg < sn || (sg == sn && bg > bn)) {
                    next = Some((sg, g, ag, bg));
                }
            }
            match next {
                Some((sg, g, ag, bg)) if sg < 1.0 => (s, f, alpha, beta) = (sg, g, ag, bg),
                _ => {
                    s = 1.0;
                    break;
                }
            }
        }
        hint.facet = f;
        let point = if s <= 0.0 {
            p
        } else if s >= 1.0 {
            q
        } else {
            p + d * s
        };
        let kind = if s <= 0.0 || s >= 1.0 { ContactKind3::FaceVertex } else { ContactKind3::EdgeEdge };
        // The walk's facet is the top one at the point up to rounding: the
        // gauge climbs from it, not from the table.
        hint.facet = self.climb_facet(point - c, f);
        TriangleReach { radius: rows[hint.facet].dot(point - c).max(0.0), point, kind }
    }
}

impl Ball3 {
    /// The ball prepared for least-gauge questions ([`Reach`]), made on
    /// the first call and kept (every later call is free, from any
    /// thread).
    pub fn reach(&self) -> Reach<'_> {
        Reach::new(self)
    }

    /// The least `γ_B(x − c)` over the closed triangle: [`Reach::triangle`]
    /// for one question.
    pub fn reach_triangle(&self, c: Point3, t: [Point3; 3]) -> TriangleReach {
        self.reach().triangle(c, t, &mut ReachHint::default())
    }
}

/// Whether `q` (near the plane of the triangle with normal `n`) lies in it:
/// the three sub-triangles turn the same way as `n`.
fn inside_triangle(q: Point3, t: [Point3; 3], n: Point3) -> bool {
    outside_sides(q, t, n) == [false; 3]
}

/// For the sides `ab`, `bd`, `da`: whether `q` lies strictly beyond the
/// side's line, away from the triangle.
fn outside_sides(q: Point3, [a, b, d]: [Point3; 3], n: Point3) -> [bool; 3] {
    // A NaN counts as outside.
    [(b - a).cross(q - a).dot(n), (d - b).cross(q - b).dot(n), (a - d).cross(q - d).dot(n)]
        .map(|x| x < 0.0 || x.is_nan())
}
