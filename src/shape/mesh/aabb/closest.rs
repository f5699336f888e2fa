//! Closest points and first hits of rays, in `f64`: constructions, whose
//! answers are rounded anyway, so no exact arithmetic is spent on them.
//! Both descend the tree nearest box first and skip the boxes that cannot
//! beat the best answer so far.

use super::{box_distance2, enter_box, Closest, Hit, TriangleTree};
use crate::kernel::{BBox3, Point3};

/// The point of triangle `a, b, c` closest to `p`: Ericson, "Real-Time
/// Collision Detection" (2005), 5.1.5. The Voronoi regions of the corners
/// and edges are told apart by the same dot products that then give the
/// point, so the answer always lies on the triangle.
pub(super) fn closest_on_triangle(p: Point3, [a, b, c]: [Point3; 3]) -> Point3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = 1.0 / (va + vb + vc);
    a + ab * (vb * denom) + ac * (vc * denom)
}

/// Ray parameter where `o + t·d` meets triangle `t` (closed), if at `t ≥ 0`:
/// Möller and Trumbore, "Fast, minimum storage ray-triangle intersection"
/// (1997). A ray in the triangle's plane counts as missing it.
fn ray_triangle(o: Point3, d: Point3, [a, b, c]: [Point3; 3]) -> Option<f64> {
    let (e1, e2) = (b - a, c - a);
    let pv = d.cross(e2);
    let det = e1.dot(pv);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let tv = o - a;
    let u = tv.dot(pv) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let qv = tv.cross(e1);
    let v = d.dot(qv) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(qv) * inv;
    (t >= 0.0).then_some(t)
}

impl TriangleTree {
    /// The point of the surface closest to `p`; `None` only for an empty
    /// tree.
    pub fn closest_point(&self, p: Point3) -> Option<Closest> {
        let root = self.nodes.first()?;
        let mut best = Closest { point: p, triangle: u32::MAX, squared_distance: f64::INFINITY };
        let mut stack = [(0u32, 0.0f64); 64];
        stack[0] = (0, box_distance2(&root.bbox, p));
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (at, d) = stack[top];
            if d >= best.squared_distance && best.triangle != u32::MAX {
                continue;
            }
            let node = &self.nodes[at as usize];
            if node.is_leaf() {
                for k in node.range() {
                    let corners = self.corners(k);
                    // The triangle's own box is much thinner than its
                    // leaf's, and far cheaper to measure than the triangle.
                    if box_distance2(&BBox3::of(corners), p) >= best.squared_distance {
                        continue;
                    }
                    let q = closest_on_triangle(p, corners);
                    let d2 = (q - p).norm2();
                    if d2 < best.squared_distance || best.triangle == u32::MAX {
                        best = Closest { point: q, triangle: self.ids[k], squared_distance: d2 };
                    }
                }
                continue;
            }
            let (left, right) = (at + 1, node.index);
            let dl = box_distance2(&self.nodes[left as usize].bbox, p);
            let dr = box_distance2(&self.nodes[right as usize].bbox, p);
            // The nearer child goes on top, to be searched first.
            let (near, far) = if dl <= dr { ((left, dl), (right, dr)) } else { ((right, dr), (left, dl)) };
            stack[top] = far;
            stack[top + 1] = near;
            top += 2;
        }
        Some(best)
    }

    /// [`TriangleTree::closest_point`] of many points, in parallel (and in
    /// an order of the points that keeps the tree in cache).
    pub fn closest_points(&self, points: &[Point3]) -> Vec<Option<Closest>> {
        self.batch(points, |p| self.closest_point(p))
    }

    /// Where the ray `origin + t·direction`, `t ≥ 0`, first meets the
    /// surface (edges and corners included); `None` when it misses, and
    /// for a zero or non-finite direction or origin. Any finite direction
    /// works, however short or long (`t` then overflows to infinity only
    /// when the true parameter exceeds the largest `f64`).
    pub fn first_hit(&self, origin: Point3, direction: Point3) -> Option<Hit> {
        let root = self.nodes.first()?;
        if !origin.is_finite() || !direction.is_finite() {
            return None;
        }
        // The same ray with its direction scaled by a power of two to a
        // largest component in [1, 2): Möller–Trumbore's determinant is
        // then neither overflowed nor lost in underflow (a direction of
        // 1e-310 used to miss everything, one of 1e300 every triangle
        // with edges over 1e4 long).
        let e = exponent(direction.x.abs().max(direction.y.abs()).max(direction.z.abs()))?;
        // origin + t·(direction·s) is origin + (t·s)·direction.
        let scaled = |v: f64| v * pow2(-e / 2) * pow2(-e + e / 2);
        let direction = Point3::new(scaled(direction.x), scaled(direction.y), scaled(direction.z));
        let unscale = |h: Hit| Hit { t: scaled(h.t), ..h };
        let scale = [root.bbox.min, root.bbox.max, origin]
            .iter()
            .map(|p| p.x.abs().max(p.y.abs()).max(p.z.abs()))
            .fold(0.0, f64::max);
        let slack = scale * 1e-12;
        let mut best: Option<Hit> = None;
        let limit = |best: &Option<Hit>| best.map_or(f64::INFINITY, |h| h.t);
        let mut stack = [(0u32, 0.0f64); 64];
        let t0 = enter_box(origin, direction, f64::INFINITY, &root.bbox, slack)?;
        stack[0] = (0, t0);
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (at, t_in) = stack[top];
            if t_in > limit(&best) {
                continue;
            }
            let node = &self.nodes[at as usize];
            if node.is_leaf() {
                for k in node.range() {
                    let corners = self.corners(k);
                    if let Some(t) = ray_triangle(origin, direction, corners).filter(|&t| t < limit(&best)) {
                        best = Some(Hit { t, triangle: self.ids[k], point: origin + direction * t });
                    }
                }
                continue;
            }
            let t_max = limit(&best);
            let children = [at + 1, node.index]
                .map(|c| (c, enter_box(origin, direction, t_max, &self.nodes[c as usize].bbox, slack)));
            let [(l, tl), (r, tr)] = children;
            let mut push = |c: u32, t: Option<f64>| {
                if let Some(t) = t {
                    stack[top] = (c, t);
                    top += 1;
                }
            };
            if tl.unwrap_or(f64::INFINITY) <= tr.unwrap_or(f64::INFINITY) {
                push(r, tr);
                push(l, tl);
            } else {
                push(l, tl);
                push(r, tr);
            }
        }
        best.map(unscale)
    }
}

/// The exponent `e` with `2^e ≤ m < 2^(e+1)`, for `m` finite and positive.
fn exponent(m: f64) -> Option<i32> {
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let raw = ((m.to_bits() >> 52) & 0x7ff) as i32;
    if raw == 0 {
        // Subnormal: 2^64 · m is normal, exactly.
        return exponent(m * pow2(64)).map(|e| e - 64);
    }
    Some(raw - 1023)
}

/// 2^k for −1022 ≤ k ≤ 1023 (callers split larger powers in two).
fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}
