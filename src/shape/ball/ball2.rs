//! The plane unit ball: a strictly convex polygon around the origin,
//! validated with exact predicates, stored counter-clockwise with the
//! supporting line of each edge.

use super::error::BallError;
use crate::kernel::{FilteredKernel, Kernel, Orientation, Point};
use std::f64::consts::TAU;

/// A unit ball of the plane: a bounded, strictly convex polygon holding
/// the origin strictly inside (thesis Definition 3.1.4). Coordinates are
/// unitless (a radius r scales the ball to r·B, model units). Not
/// necessarily symmetric: δ_B(p, q) may differ from δ_B(q, p), and
/// [`mirrored`](Self::mirrored) gives the ball −B of the other direction.
/// Immutable; validated once by exact predicates, so a ball always holds
/// its invariants.
#[derive(Debug, Clone, PartialEq)]
pub struct Ball2 {
    /// Counter-clockwise; no three consecutive collinear.
    vertices: Vec<Point>,
    /// For edge i (vertex i to i + 1), `a_i` with `a_i · x = 1` on its line
    /// and `a_i · x < 1` on the origin's side: the gauge is `max_i a_i · x`.
    facets: Vec<Point>,
}

/// Regular polygons with more vertices than this are refused: the ball
/// is then within 5·10^-10 of the circle, where the Euclidean kernel is
/// the better tool, and every distance query costs a pass over k facets.
const MAX_REGULAR: usize = 100_000;

impl Ball2 {
    /// The ball with these vertices, in either orientation.
    ///
    /// # Errors
    ///
    /// [`BallError`] naming the vertex: fewer than 3, NaN or infinite, a
    /// vertex repeating the one before, three consecutive vertices
    /// collinear, not convex (also a star polygon winding round twice), the
    /// origin not strictly inside.
    pub fn new(vertices: &[Point]) -> Result<Ball2, BallError> {
        let n = vertices.len();
        if n < 3 {
            return Err(BallError::TooFewVertices { count: n });
        }
        if let Some(vertex) = vertices.iter().position(|v| !v.x.is_finite() || !v.y.is_finite()) {
            return Err(BallError::NonFinite { vertex });
        }
        let out_of_scale = |c: f64| c.abs() > 1e100 || (c != 0.0 && c.abs() < 1e-100);
        if let Some(vertex) = vertices.iter().position(|v| out_of_scale(v.x) || out_of_scale(v.y)) {
            return Err(BallError::IllConditioned { vertex });
        }
        let at = |i: usize| vertices[i % n];
        if let Some(vertex) = (0..n).find(|&i| at(i) == at(i + n - 1)) {
            return Err(BallError::Repeated { vertex });
        }
        let k = FilteredKernel;
        // The way the polygon turns, by its area; every vertex must turn so.
        let area2: f64 = (0..n).map(|i| at(i).cross(at(i + 1))).sum();
        let turn = |i: usize| k.orientation(at(i + n - 1), at(i), at(i + 1));
        let want = match area2.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => Orientation::Left,
            Some(std::cmp::Ordering::Less) => Orientation::Right,
            _ => turn(0),
        };
        for i in 0..n {
            match turn(i) {
                Orientation::Collinear => return Err(BallError::Collinear { vertex: i }),
                t if t != want || want == Orientation::Collinear => return Err(BallError::NotConvex { vertex: i }),
                _ => {}
            }
        }
        // Turning the same way everywhere, a polygon may still wind round
        // more than once (a pentagram): the exterior angles must sum to one
        // turn. Each lies in (0, π), so rounding cannot blur 2π and 4π.
        let mut turned = 0.0;
        for i in 0..n {
            let (d0, d1) = (at(i) - at(i + n - 1), at(i + 1) - at(i));
            turned += d0.cross(d1).abs().atan2(d0.dot(d1));
            if turned > 1.5 * TAU {
                return Err(BallError::NotConvex { vertex: i });
            }
        }
        // Counter-clockwise from here.
        let ccw = want == Orientation::Left;
        let vertices: Vec<Point> = if ccw { vertices.to_vec() } else { vertices.iter().rev().copied().collect() };
        let origin = Point::new(0.0, 0.0);
        for i in 0..n {
            let (a, b) = (vertices[i], vertices[(i + 1) % n]);
            match k.orientation(a, b, origin) {
                Orientation::Left => {}
                side => {
                    // Reversed, edge i joins the given vertices n − 1 − i
                    // and n − 2 − i: name the one it starts from as given.
                    let vertex = if ccw { i } else { (2 * n - 2 - i) % n };
                    return Err(BallError::OriginNotInside { vertex, on_edge: side == Orientation::Collinear });
                }
            }
        }
        // Distances divide by the origin's distance to each edge's line:
        // a ball that thin gives no useful digits.
        let size = vertices.iter().map(|v| v.norm()).fold(0.0, f64::max);
        let mut facets = Vec::with_capacity(n);
        for i in 0..n {
            let (a, b) = (vertices[i], vertices[(i + 1) % n]);
            let outward = Point::new(b.y - a.y, a.x - b.x);
            let height = outward.dot(a) / outward.norm();
            // NaN (an overflow) counts as too thin.
            if height.is_nan() || height <= 1e-12 * size {
                let vertex = if ccw { i } else { (2 * n - 2 - i) % n };
                return Err(BallError::IllConditioned { vertex });
            }
            facets.push(outward * (1.0 / outward.dot(a)));
        }
        Ok(Ball2 { vertices, facets })
    }

    /// The regular polygon of `k` vertices on the unit circle, the first at
    /// angle `rotation` (radians) from the x axis. As k grows its axis
    /// tends to the Euclidean one (thesis Theorem 2).
    ///
    /// # Errors
    ///
    /// `k` below 3 or above 100 000, a non-finite rotation.
    pub fn regular(k: usize, rotation: f64) -> Result<Ball2, BallError> {
        if !(3..=MAX_REGULAR).contains(&k) || !rotation.is_finite() {
            return Err(BallError::InvalidArgument {
                what: format!(
                    "a regular polygon needs 3 to {MAX_REGULAR} vertices and a finite rotation ({k}, {rotation})"
                ),
            });
        }
        let vertices: Vec<Point> = (0..k)
            .map(|i| {
                let (s, c) = (rotation + TAU * i as f64 / k as f64).sin_cos();
                Point::new(c, s)
            })
            .collect();
        Ball2::new(&vertices)
    }

    /// The square [−1, 1]²: the L∞ distance (CGAL's
    /// `Segment_Delaunay_graph_Linf_2` computes the Voronoi diagram of
    /// segments under it).
    pub fn square() -> Ball2 {
        Ball2::from_valid(&[(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)])
    }

    /// The diamond |x| + |y| ≤ 1: the L1 (Manhattan) distance.
    pub fn diamond() -> Ball2 {
        Ball2::from_valid(&[(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)])
    }

    /// The equilateral triangle of circumradius 1 around the origin, one
    /// vertex straight up: the simplest ball that is not symmetric.
    pub fn triangle() -> Ball2 {
        let h = 0.75f64.sqrt();
        Ball2::from_valid(&[(0.0, 1.0), (-h, -0.5), (h, -0.5)])
    }

    fn from_valid(xy: &[(f64, f64)]) -> Ball2 {
        let vertices: Vec<Point> = xy.iter().map(|&(x, y)| Point::new(x, y)).collect();
        // The presets are valid by construction; tests build each one.
        Ball2::new(&vertices).unwrap_or_else(|e| unreachable!("preset ball: {e}"))
    }

    /// The vertices, counter-clockwise (the order given, or its reverse).
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }

    /// The number of vertices (and of edges).
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Always false: a ball has at least three vertices.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Edge `i`'s supporting line as `a` with `a · x = 1` on it (the gauge
    /// is the largest `a_i · x`).
    pub(crate) fn facet(&self, i: usize) -> Point {
        self.facets[i]
    }

    /// The mirrored ball −B: δ_{−B}(p, q) = δ_B(q, p) (thesis Observation
    /// 13: offsets under B are taken with −B from the axis).
    pub fn mirrored(&self) -> Ball2 {
        let vertices: Vec<Point> = self.vertices.iter().map(|&v| Point::new(-v.x, -v.y)).collect();
        let facets = self.facets.iter().map(|&a| Point::new(-a.x, -a.y)).collect();
        Ball2 { vertices, facets }
    }

    /// True when −B = B exactly (then δ_B is a metric, not only a
    /// quasi-metric).
    pub fn is_symmetric(&self) -> bool {
        let n = self.len();
        n % 2 == 0
            && (0..n).all(|i| self.vertices[(i + n / 2) % n] == Point::new(-self.vertices[i].x, -self.vertices[i].y))
    }

    /// The radius of the largest disk about the origin inside the ball (the
    /// least distance from the origin to an edge's line): the gauge is
    /// 1/inradius-Lipschitz, so a position rounded by ε moves a distance
    /// by at most ε/inradius.
    pub fn inradius(&self) -> f64 {
        let n = self.len();
        (0..n)
            .map(|i| {
                let (p, q) = (self.vertices[i], self.vertices[(i + 1) % n]);
                p.cross(q).abs() / (q - p).norm()
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The vertices of the ball `c + r·B` (model units), counter-clockwise.
    pub fn placed(&self, c: Point, r: f64) -> Vec<Point> {
        self.vertices.iter().map(|&v| c + v * r).collect()
    }
}
