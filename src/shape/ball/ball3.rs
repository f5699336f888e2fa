//! The unit ball of space: a convex polytope around the origin, the hull
//! of the points given (decided exactly), stored with its facet planes,
//! edges and the facets around each vertex.

use super::error::BallError;
use super::hull3::hull;
use super::reach_data::PreparedCell;
use crate::kernel::orient3::{plane_side, PlaneSide};
use crate::kernel::Point3;
use std::collections::HashMap;

/// A unit ball of space: a bounded convex polytope holding the origin
/// strictly inside (thesis Definition 3.1.4). Coordinates are unitless (a
/// radius r scales the ball to r·B, model units). Not necessarily
/// symmetric: δ_B(p, q) may differ from δ_B(q, p), and
/// [`mirrored`](Self::mirrored) gives the ball −B of the other direction.
/// Immutable; the combinatorics (which points are vertices, which lie on
/// one facet) are decided once by exact predicates, the facet planes are
/// `f64`.
#[derive(Debug, Clone, PartialEq)]
pub struct Ball3 {
    /// In the order of the points given (the hull's vertices only).
    vertices: Vec<Point3>,
    facets: Vec<BallFacet3>,
    /// Sorted by their vertex pairs.
    edges: Vec<BallEdge3>,
    /// For each vertex its facets, counter-clockwise seen from outside.
    around: Vec<Vec<usize>>,
    /// For facet f, `n_f / h_f`: the gauge is the largest `a_f · x`.
    rows: Vec<Point3>,
    /// Points given that are not vertices.
    dropped: usize,
    /// What least-gauge questions need, made on the first (`reach3.rs`).
    pub(super) prepared: PreparedCell,
}

/// A facet of a [`Ball3`]: a convex polygon in the plane `normal · x =
/// offset` with the ball on the side `normal · x ≤ offset`.
#[derive(Debug, Clone, PartialEq)]
pub struct BallFacet3 {
    /// Its corners, indices into [`Ball3::vertices`], counter-clockwise
    /// seen from outside, starting at the least index; no three consecutive
    /// corners collinear.
    pub vertices: Vec<usize>,
    /// The outward unit normal (`f64`, from the corners by Newell's
    /// method, which averages out the rounding of any one corner).
    pub normal: Point3,
    /// The plane's distance from the origin (positive: the origin is
    /// inside).
    pub offset: f64,
}

/// An edge of a [`Ball3`] and the two facets that meet there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BallEdge3 {
    /// Its ends, indices into [`Ball3::vertices`], the lesser first.
    pub vertices: [usize; 2],
    /// `facets[0]` runs from `vertices[0]` to `vertices[1]` (counter-
    /// clockwise seen from outside), `facets[1]` the other way.
    pub facets: [usize; 2],
}

/// A feature of a [`Ball3`]: where a plane touches it, the contact class
/// of chapter 3 in space.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Feature3 {
    /// A vertex, by index into [`Ball3::vertices`].
    Vertex(usize),
    /// An edge, by index into [`Ball3::edges`].
    Edge(usize),
    /// A facet, by index into [`Ball3::facets`].
    Facet(usize),
}

/// Geodesic spheres with more facets than 20·4^5 are refused: the hull is
/// O(n²) and such a ball is within 2·10^-4 of the sphere, where the
/// Euclidean kernel is the better tool.
const MAX_GEODESIC_LEVEL: u32 = 5;

impl Ball3 {
    /// The ball that is the convex hull of `points`, the origin kept where
    /// it is (no recentring: a ball off-centre is a quasi-metric). Points
    /// inside the hull, on a facet or on an edge, and repeats, are not
    /// vertices ([`dropped_points`](Self::dropped_points) counts them).
    /// Output order is deterministic: vertices in the order given, facets
    /// sorted by their corner lists.
    ///
    /// # Errors
    ///
    /// [`BallError`]: fewer than 4 points, a NaN or infinite coordinate (the
    /// point), a coordinate beyond ±1e100 or, unless zero, below 1e-100 in
    /// magnitude (the point), all points on one plane, the origin on a
    /// facet or outside (the facet, an index into the hull's facets), the
    /// origin within 1e-12 of the ball's size from a facet plane.
    pub fn from_points(points: &[Point3]) -> Result<Ball3, BallError> {
        let h = hull(points)?;
        let out_of_scale = |c: f64| c.abs() > 1e100 || (c != 0.0 && c.abs() < 1e-100);
        if let Some(vertex) = points.iter().position(|p| p.to_array().into_iter().any(out_of_scale)) {
            return Err(BallError::IllConditioned { vertex });
        }
        // Keep the hull's vertices, in the order given.
        let mut used: Vec<usize> = h.facets.iter().flatten().copied().collect();
        used.sort_unstable();
        used.dedup();
        let new_index: HashMap<usize, usize> = used.iter().enumerate().map(|(k, &i)| (i, k)).collect();
        let mut order: Vec<usize> = (0..h.facets.len()).collect();
        let polys: Vec<Vec<usize>> =
            h.facets.iter().map(|f| canonical(f.iter().map(|i| new_index[i]).collect())).collect();
        order.sort_by(|&a, &b| polys[a].cmp(&polys[b]));
        let origin = Point3::new(0.0, 0.0, 0.0);
        for (facet, &k) in order.iter().enumerate() {
            let [a, b, c] = h.planes[k].map(|i| points[i]);
            match plane_side(a, b, c, origin) {
                PlaneSide::Below => {}
                side => return Err(BallError::OriginNotInsideHull { facet, on_facet: side == PlaneSide::On }),
            }
        }
        let vertices = used.iter().map(|&i| points[i]).collect();
        let polys = order.iter().map(|&k| polys[k].clone()).collect();
        Ball3::assemble(vertices, polys, points.len() - used.len())
    }

    /// The ball with these vertices and facet polygons (counter-clockwise
    /// seen from outside, each starting at its least index): its planes,
    /// edges and vertex stars.
    fn assemble(vertices: Vec<Point3>, polys: Vec<Vec<usize>>, dropped: usize) -> Result<Ball3, BallError> {
        let size = vertices.iter().map(|v| v.norm()).fold(0.0, f64::max);
        let mut facets = Vec::with_capacity(polys.len());
        let mut rows = Vec::with_capacity(polys.len());
        for (k, poly) in polys.into_iter().enumerate() {
            let m = poly.len();
            let newell = (0..m).fold(Point3::default(), |s, i| {
                let (p, q) = (vertices[poly[i]], vertices[poly[(i + 1) % m]]);
                s + Point3::new((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y))
            });
            let normal = newell * (1.0 / newell.norm());
            let offset = poly.iter().map(|&i| normal.dot(vertices[i])).sum::<f64>() / m as f64;
            // NaN (an overflow) counts as too thin.
            if offset.is_nan() || offset <= 1e-12 * size {
                return Err(BallError::ThinFacet { facet: k });
            }
            rows.push(normal * (1.0 / offset));
            facets.push(BallFacet3 { vertices: poly, normal, offset });
        }
        // Directed edge (a, b) → the facet that runs along it.
        let mut along: HashMap<(usize, usize), usize> = HashMap::new();
        let mut prev: HashMap<(usize, usize), usize> = HashMap::new();
        for (f, facet) in facets.iter().enumerate() {
            let (poly, m) = (&facet.vertices, facet.vertices.len());
            for i in 0..m {
                along.insert((poly[i], poly[(i + 1) % m]), f);
                prev.insert((f, poly[i]), poly[(i + m - 1) % m]);
            }
        }
        let mut edges: Vec<BallEdge3> = along
            .iter()
            .filter(|(&(a, b), _)| a < b)
            .map(|(&(a, b), &f)| BallEdge3 { vertices: [a, b], facets: [f, along[&(b, a)]] })
            .collect();
        edges.sort_by_key(|e| e.vertices);
        // Around v, the facet after f (counter-clockwise seen from outside)
        // shares f's edge into v: it runs from v back to f's corner before v.
        let mut first: Vec<Option<usize>> = vec![None; vertices.len()];
        for (f, facet) in facets.iter().enumerate() {
            for &v in &facet.vertices {
                first[v].get_or_insert(f);
            }
        }
        let around = first
            .iter()
            .enumerate()
            .map(|(v, &start)| {
                let start = start.unwrap_or_default();
                let mut star = vec![start];
                let mut f = along[&(v, prev[&(start, v)])];
                while f != start && star.len() <= facets.len() {
                    star.push(f);
                    f = along[&(v, prev[&(f, v)])];
                }
                star
            })
            .collect();
        Ok(Ball3 { vertices, facets, edges, around, rows, dropped, prepared: PreparedCell::default() })
    }

    fn from_valid(xyz: &[[f64; 3]]) -> Ball3 {
        let points: Vec<Point3> = xyz.iter().map(|&a| Point3::from_array(a)).collect();
        // The presets are valid by construction; tests build each one.
        Ball3::from_points(&points).unwrap_or_else(|e| unreachable!("preset ball: {e}"))
    }

    /// The regular tetrahedron on alternate corners of [−1, 1]³ (a corner
    /// towards (1, 1, 1)): the simplest ball that is not symmetric. Turn
    /// it (and every preset) with [`rotated`](Self::rotated).
    pub fn tetrahedron() -> Ball3 {
        Ball3::from_valid(&[[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]])
    }

    /// The cube [−1, 1]³: the L∞ distance.
    pub fn cube() -> Ball3 {
        let corners: Vec<[f64; 3]> =
            (0..8).map(|i| [0, 1, 2].map(|b| if i >> b & 1 == 1 { 1.0 } else { -1.0 })).collect();
        Ball3::from_valid(&corners)
    }

    /// The octahedron |x| + |y| + |z| ≤ 1: the L1 distance.
    pub fn octahedron() -> Ball3 {
        Ball3::from_valid(&[
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ])
    }

    /// The regular icosahedron with vertices (0, ±1, ±φ) and their cyclic
    /// shifts (edge 2, φ the golden ratio).
    pub fn icosahedron() -> Ball3 {
        Ball3::from_valid(&icosahedron_corners())
    }

    /// The geodesic sphere: the icosahedron on the unit sphere, its
    /// triangles split into four k times (midpoints pushed out to the
    /// sphere), for the least k giving at least `n_facets_at_least` facets:
    /// 20·4^k triangles, 10·4^k + 2 vertices. Tends to the Euclidean ball.
    ///
    /// # Errors
    ///
    /// More than 20·4^5 = 20 480 facets asked for.
    pub fn geodesic(n_facets_at_least: usize) -> Result<Ball3, BallError> {
        let level = (0..=MAX_GEODESIC_LEVEL).find(|&k| 20usize << (2 * k) >= n_facets_at_least).ok_or_else(|| {
            BallError::InvalidArgument {
                what: format!(
                    "a geodesic sphere has at most {} facets ({n_facets_at_least} asked for)",
                    20usize << (2 * MAX_GEODESIC_LEVEL)
                ),
            }
        })?;
        let ico = Ball3::icosahedron();
        let unit = |p: Point3| p * (1.0 / p.norm());
        let mut points: Vec<Point3> = ico.vertices.iter().map(|&v| unit(v)).collect();
        let mut triangles: Vec<[usize; 3]> =
            ico.facets.iter().map(|f| [f.vertices[0], f.vertices[1], f.vertices[2]]).collect();
        for _ in 0..level {
            let mut mid: HashMap<(usize, usize), usize> = HashMap::new();
            let mut split = Vec::with_capacity(4 * triangles.len());
            for t in &triangles {
                let mut m = [0; 3];
                for (i, slot) in m.iter_mut().enumerate() {
                    let (a, b) = (t[i], t[(i + 1) % 3]);
                    *slot = *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                        points.push(unit(points[a] + points[b]));
                        points.len() - 1
                    });
                }
                split.extend([[t[0], m[0], m[2]], [m[0], t[1], m[1]], [m[2], m[1], t[2]], [m[0], m[1], m[2]]]);
            }
            triangles = split;
        }
        Ball3::from_points(&points)
    }

    /// This ball turned about the origin by the rotation vector `rotation`
    /// (axis–angle: the axis is its direction, the angle in radians its
    /// length; [0, 0, 0] leaves the ball as it is). The vertices are
    /// rotated in `f64` and the facets kept as they are (a turned cube keeps
    /// its six squares, though its corners are no longer exactly coplanar);
    /// the facet planes are fitted anew.
    ///
    /// # Errors
    ///
    /// A non-finite rotation.
    pub fn rotated(&self, rotation: [f64; 3]) -> Result<Ball3, BallError> {
        if rotation.iter().any(|c| !c.is_finite()) {
            return Err(BallError::InvalidArgument { what: format!("a rotation must be finite ({rotation:?})") });
        }
        let axis = Point3::from_array(rotation);
        let angle = axis.norm();
        if angle == 0.0 {
            return Ok(self.clone());
        }
        let k = axis * (1.0 / angle);
        let (s, c) = angle.sin_cos();
        // Rodrigues' formula.
        let turn = |v: Point3| v * c + k.cross(v) * s + k * (k.dot(v) * (1.0 - c));
        let vertices = self.vertices.iter().map(|&v| turn(v)).collect();
        let polys = self.facets.iter().map(|f| f.vertices.clone()).collect();
        Ball3::assemble(vertices, polys, self.dropped)
    }

    /// The mirrored ball −B: δ_{−B}(p, q) = δ_B(q, p) (thesis Observation
    /// 13). Exact: the vertices are negated, facet k stays facet k (its
    /// corners in the reverse order, so still counter-clockwise).
    pub fn mirrored(&self) -> Ball3 {
        let vertices = self.vertices.iter().map(|&v| -v).collect();
        let polys = self.facets.iter().map(|f| canonical(f.vertices.iter().rev().copied().collect())).collect();
        // Negation keeps every facet height, so a valid ball stays valid.
        Ball3::assemble(vertices, polys, self.dropped).unwrap_or_else(|e| unreachable!("mirrored ball: {e}"))
    }

    /// True when −B = B exactly as vertex sets (then δ_B is a metric, not
    /// only a quasi-metric).
    pub fn is_symmetric(&self) -> bool {
        let key = |p: &Point3| p.to_array().map(|c| if c == 0.0 { 0.0 } else { c });
        let cmp = |a: &[f64; 3], b: &[f64; 3]| a.iter().zip(b).map(|(x, y)| x.total_cmp(y)).find(|o| o.is_ne());
        let sorted = |neg: bool| {
            let mut v: Vec<[f64; 3]> = self.vertices.iter().map(|&p| key(&if neg { -p } else { p })).collect();
            v.sort_by(|a, b| cmp(a, b).unwrap_or(std::cmp::Ordering::Equal));
            v
        };
        sorted(false) == sorted(true)
    }

    /// The gauge of `v`: the least r ≥ 0 with v ∈ r·B, the largest
    /// `normal · v / offset` over the facets.
    pub fn gauge(&self, v: Point3) -> f64 {
        self.rows.iter().map(|a| a.dot(v)).fold(0.0, f64::max)
    }

    /// The gauge's rows `normal / offset`, one per facet in facet order:
    /// the gauge is the largest `row · v` (and at least 0).
    pub fn gauge_rows(&self) -> &[Point3] {
        &self.rows
    }

    /// δ_B(p, q) = min{r ≥ 0 : q ∈ p + r·B}, the gauge of q − p.
    pub fn distance(&self, p: Point3, q: Point3) -> f64 {
        self.gauge(q - p)
    }

    /// The vertices, in the order of the points given.
    pub fn vertices(&self) -> &[Point3] {
        &self.vertices
    }

    /// The facets: for a ball from points sorted by their corner lists; a
    /// mirrored or rotated ball keeps the facet indices of its original.
    pub fn facets(&self) -> &[BallFacet3] {
        &self.facets
    }

    /// The edges, sorted by their vertex pairs.
    pub fn edges(&self) -> &[BallEdge3] {
        &self.edges
    }

    /// The first facet whose corners are not exactly coplanar, if any (a
    /// turned ball keeps its facets, whose corners were rotated in `f64`:
    /// see [`rotated`](Self::rotated)). The exact questions take a facet's
    /// plane through its first three corners; where a ball edge must lie
    /// exactly along the wall of a cone (a ball edge sliding along a
    /// reflex edge of a solid) the other corners must lie on it too.
    pub fn non_planar_facet(&self) -> Option<usize> {
        let w = &self.vertices;
        self.facets.iter().position(|f| {
            let [a, b, c] = [0, 1, 2].map(|k| w[f.vertices[k]]);
            f.vertices[3..].iter().any(|&d| plane_side(a, b, c, w[d]) != PlaneSide::On)
        })
    }

    /// The facets around vertex `v`, counter-clockwise seen from outside.
    pub fn facets_around(&self, v: usize) -> &[usize] {
        &self.around[v]
    }

    /// How many of the points given are not vertices (inside the hull, on
    /// a facet or an edge, or repeating another point).
    pub fn dropped_points(&self) -> usize {
        self.dropped
    }

    /// The radius of the largest Euclidean ball about the origin inside B
    /// (the nearest facet plane): the gauge is 1/inradius-Lipschitz.
    pub fn inradius(&self) -> f64 {
        self.facets.iter().map(|f| f.offset).fold(f64::INFINITY, f64::min)
    }

    /// The radius of the least Euclidean ball about the origin holding B
    /// (the farthest vertex).
    pub fn circumradius(&self) -> f64 {
        self.vertices.iter().map(|v| v.norm()).fold(0.0, f64::max)
    }

    /// The vertices of the ball `c + r·B` (model units), in vertex order.
    pub fn placed(&self, c: Point3, r: f64) -> Vec<Point3> {
        self.vertices.iter().map(|&v| c + v * r).collect()
    }

    /// The feature of B extreme in direction `normal` (where the plane
    /// with that outward normal touches B): the facet whose corners all
    /// reach the maximum of `normal · v`, else the edge whose ends do,
    /// else the vertex. Inexact: "reach" is within 1e-12 of the ball's
    /// size, so a direction within about 1e-12 of a facet's normal gives
    /// the facet. `None` for a zero or non-finite direction.
    pub fn feature_touching_plane_inexact(&self, normal: Point3) -> Option<Feature3> {
        let len = normal.norm();
        if !(len.is_finite() && len > 0.0) {
            return None;
        }
        let d = normal * (1.0 / len);
        let heights: Vec<f64> = self.vertices.iter().map(|&v| d.dot(v)).collect();
        let top = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let tol = 1e-12 * self.circumradius();
        let reaches = |v: usize| heights[v] >= top - tol;
        let best_facet = (0..self.facets.len())
            .filter(|&f| self.facets[f].vertices.iter().all(|&v| reaches(v)))
            .max_by(|&a, &b| d.dot(self.facets[a].normal).total_cmp(&d.dot(self.facets[b].normal)));
        if let Some(f) = best_facet {
            return Some(Feature3::Facet(f));
        }
        if let Some(e) = self.edges.iter().position(|e| e.vertices.iter().all(|&v| reaches(v))) {
            return Some(Feature3::Edge(e));
        }
        (0..heights.len()).max_by(|&a, &b| heights[a].total_cmp(&heights[b])).map(Feature3::Vertex)
    }
}

/// The polygon turned to start at its least index (the same cycle).
fn canonical(mut poly: Vec<usize>) -> Vec<usize> {
    let at = (0..poly.len()).min_by_key(|&i| poly[i]).unwrap_or(0);
    poly.rotate_left(at);
    poly
}

/// The icosahedron's twelve corners: (0, ±1, ±φ) and cyclic shifts.
fn icosahedron_corners() -> Vec<[f64; 3]> {
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let mut out = Vec::with_capacity(12);
    for shift in 0..3 {
        for (a, b) in [(1.0, phi), (1.0, -phi), (-1.0, phi), (-1.0, -phi)] {
            let mut p = [0.0, a, b];
            p.rotate_right(shift);
            out.push(p);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cube_has_six_squares_and_stars_of_three() {
        let cube = Ball3::cube();
        assert_eq!((cube.vertices().len(), cube.edges().len(), cube.facets().len()), (8, 12, 6));
        assert!(cube.facets().iter().all(|f| f.vertices.len() == 4 && (f.offset - 1.0).abs() < 1e-15));
        for v in 0..8 {
            let star = cube.facets_around(v);
            assert_eq!(star.len(), 3);
            // Counter-clockwise seen from outside: the normals turn
            // positively about the vertex's direction.
            let n = star.iter().map(|&f| cube.facets()[f].normal).collect::<Vec<_>>();
            assert!(n[0].cross(n[1]).dot(cube.vertices()[v]) > 0.0, "{v}");
        }
        assert_eq!(cube.distance(Point3::new(1.0, 1.0, 1.0), Point3::new(4.0, -1.0, 0.0)), 3.0);
    }

    #[test]
    fn mirror_and_symmetry() {
        let t = Ball3::tetrahedron();
        assert!(!t.is_symmetric() && Ball3::octahedron().is_symmetric() && Ball3::cube().is_symmetric());
        let m = t.mirrored();
        let (p, q) = (Point3::new(0.3, -0.2, 0.9), Point3::new(-1.0, 0.5, 0.25));
        assert!((m.distance(p, q) - t.distance(q, p)).abs() < 1e-12);
        assert_eq!(m.mirrored(), t);
    }
}
