//! A bounding-volume hierarchy over the triangles of a surface, and the
//! queries a solid needs from it: closest points, first hits of rays,
//! exact point-in-solid, and exact self-intersections.
//!
//! The tree splits the triangles at the median centroid along the longest
//! axis of the centroids' box, so it is balanced whatever the triangles'
//! sizes (depth ⌈log2(n / 4)⌉ + 1), and building is a sequence of linear
//! selections: O(n log n), the two halves built in parallel. Nodes live in
//! one flat vector in depth-first order (left child right after its
//! parent), whose size is known from n alone: so both halves can be
//! written in place at the same time.
//!
//! The tree keeps its own copy of the positions and of the triangles (in
//! tree order, so that a leaf's triangles are contiguous), so a caller
//! may keep it beside the data it came from or drop that data.
//!
//! * `closest.rs`: closest points and first hits of rays (`f64`).
//! * `inside.rs`: exact point-in-solid by crossing parity.
//! * `intersect.rs`: exact tests of a segment, a triangle or a box against
//!   the surface.
//! * `self_cross.rs`: exact self-intersections by a descent of the tree
//!   against itself.
//! * `ball_radius.rs`: the largest ball `c + r·B` at a centre under a
//!   space ball; `maximal.rs`: maximal* balls grown about a point, and
//!   every contact of a ball; `sweep.rs`: whether a triangle enters the
//!   hull of two balls (the balls between them).

use crate::kernel::{BBox3, Point3};

mod ball_radius;
pub use ball_radius::{BallContact, ContactKind3};
mod closest;
mod contact_exact;
pub use contact_exact::{ExactContact, ExactContacts, SurfacePart};
mod inside;
mod intersect;
mod maximal;
mod maximal_exact;
pub use maximal::MaximalBall;
pub use maximal_exact::ExactMaximalBall;
mod self_cross;
mod sweep;

/// Most triangles in a leaf: few enough that scanning a leaf costs about
/// as much as descending one more level.
const LEAF: usize = 4;

/// Below this many triangles a subtree is built on the current thread.
const PARALLEL_BUILD: usize = 4096;

#[derive(Debug, Clone, Copy)]
struct Node {
    bbox: BBox3,
    /// Leaf: tree position of its first triangle. Inner node: index of
    /// its right child (the left one is the next node).
    index: u32,
    /// Leaf: how many triangles it holds (1 to [`LEAF`]). Inner node: 0.
    count: u32,
}

impl Node {
    fn is_leaf(&self) -> bool {
        self.count > 0
    }

    /// Tree positions of a leaf's triangles.
    fn range(&self) -> std::ops::Range<usize> {
        self.index as usize..(self.index + self.count) as usize
    }
}

/// A bounding-volume hierarchy over the triangles of a surface (a static
/// AABB tree). Triangles are named by their index in the slice the tree
/// was built from.
#[derive(Debug, Clone)]
pub struct TriangleTree {
    nodes: Vec<Node>,
    /// Triangles in tree order.
    triangles: Vec<[u32; 3]>,
    /// Index in the input of each triangle in tree order.
    ids: Vec<u32>,
    positions: Vec<Point3>,
}

/// The point of a surface closest to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closest {
    /// The closest point (on the triangle).
    pub point: Point3,
    /// The triangle it lies on (its index in the input); the first one the
    /// search met when several are equally close.
    pub triangle: u32,
    /// Squared distance from the query point.
    pub squared_distance: f64,
}

/// Where a ray first meets a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Ray parameter: the point is `origin + t · direction` (so `t` is a
    /// distance only for a unit direction), `t ≥ 0`.
    pub t: f64,
    /// The triangle hit (its index in the input).
    pub triangle: u32,
    /// The point hit.
    pub point: Point3,
}

/// Number of nodes of the tree over `n ≥ 1` triangles, with its pair
/// `f(n + 1)`: halves of `n` and `n + 1` are `⌊n/2⌋` and `⌊n/2⌋ + 1`, so
/// the pair at `n / 2` gives both (O(log n) steps instead of a walk over
/// the whole tree).
fn node_counts(n: usize) -> (usize, usize) {
    if n < LEAF {
        return (1, 1);
    }
    let (h, h1) = node_counts(n / 2);
    let inner = |m: usize, children: usize| if m <= LEAF { 1 } else { 1 + children };
    if n % 2 == 0 {
        (inner(n, 2 * h), inner(n + 1, h + h1))
    } else {
        (inner(n, h + h1), inner(n + 1, 2 * h1))
    }
}

fn node_count(n: usize) -> usize {
    if n == 0 {
        0
    } else {
        node_counts(n).0
    }
}

/// What every step of the build reads.
struct Input<'a> {
    positions: &'a [Point3],
    triangles: &'a [[u32; 3]],
    centroids: &'a [Point3],
}

/// Builds the subtree over `order` (tree positions from `first`) into
/// `nodes`, whose first entry is node `at`; returns its box.
fn build(input: &Input<'_>, nodes: &mut [Node], order: &mut [u32], first: usize, at: usize) -> BBox3 {
    let n = order.len();
    if n <= LEAF {
        let bbox =
            BBox3::of(order.iter().flat_map(|&t| input.triangles[t as usize].map(|v| input.positions[v as usize])));
        nodes[0] = Node { bbox, index: first as u32, count: n as u32 };
        return bbox;
    }
    let spread = BBox3::of(order.iter().map(|&t| input.centroids[t as usize]));
    let size = spread.max - spread.min;
    let axis = if size.x >= size.y && size.x >= size.z {
        0
    } else if size.y >= size.z {
        1
    } else {
        2
    };
    let mid = n / 2;
    let key = |t: &u32| input.centroids[*t as usize].coord(axis);
    order.select_nth_unstable_by(mid, |s, t| key(s).total_cmp(&key(t)));
    let (low, high) = order.split_at_mut(mid);
    let left = node_count(mid);
    let (head, rest) = nodes.split_at_mut(1);
    let (left_nodes, right_nodes) = rest.split_at_mut(left);
    let right_at = at + 1 + left;
    let (lb, rb) = if n > PARALLEL_BUILD {
        rayon::join(
            || build(input, left_nodes, low, first, at + 1),
            || build(input, right_nodes, high, first + mid, right_at),
        )
    } else {
        (build(input, left_nodes, low, first, at + 1), build(input, right_nodes, high, first + mid, right_at))
    };
    let bbox = lb.union(rb);
    head[0] = Node { bbox, index: right_at as u32, count: 0 };
    bbox
}

impl TriangleTree {
    /// Builds the tree over `triangles` (indices into `positions`).
    ///
    /// # Panics
    /// When a triangle names a vertex past the end of `positions`, or when
    /// there are 2^32 − 1 triangles or more.
    pub fn new(positions: &[Point3], triangles: &[[u32; 3]]) -> TriangleTree {
        use rayon::prelude::*;
        let n = triangles.len();
        assert!(n < u32::MAX as usize, "too many triangles for a TriangleTree: {n}");
        if let Some(bad) = triangles.iter().flatten().find(|&&v| v as usize >= positions.len()) {
            panic!("triangle vertex {bad} is out of range ({} positions)", positions.len());
        }
        let centroids: Vec<Point3> = triangles
            .par_iter()
            .map(|t| (positions[t[0] as usize] + positions[t[1] as usize] + positions[t[2] as usize]) * (1.0 / 3.0))
            .collect();
        let mut order: Vec<u32> = (0..n as u32).collect();
        let mut nodes = vec![Node { bbox: BBox3::EMPTY, index: 0, count: 0 }; node_count(n)];
        if n > 0 {
            let input = Input { positions, triangles, centroids: &centroids };
            build(&input, &mut nodes, &mut order, 0, 0);
        }
        let triangles = order.par_iter().map(|&t| triangles[t as usize]).collect();
        TriangleTree { nodes, triangles, ids: order, positions: positions.to_vec() }
    }

    /// From coordinate arrays, as the mesh samples and readers give them.
    ///
    /// # Panics
    /// As [`TriangleTree::new`].
    pub fn from_arrays(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> TriangleTree {
        let points: Vec<Point3> = positions.iter().map(|&p| Point3::from_array(p)).collect();
        TriangleTree::new(&points, triangles)
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    /// True when the tree holds no triangle.
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }

    /// Box of all triangles ([`BBox3::EMPTY`] for an empty tree).
    pub fn bbox(&self) -> BBox3 {
        self.nodes.first().map_or(BBox3::EMPTY, |n| n.bbox)
    }

    /// Bytes the tree holds beyond its copy of positions and triangles:
    /// nodes and the triangle order.
    pub fn index_bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.ids.len() * std::mem::size_of::<u32>()
    }

    /// Corners of the triangle at tree position `k`.
    fn corners(&self, k: usize) -> [Point3; 3] {
        self.triangles[k].map(|v| self.positions[v as usize])
    }

    /// Calls `leaf` with the tree position of each triangle in the leaves
    /// whose boxes pass `enter`, until it breaks.
    fn visit(
        &self,
        mut enter: impl FnMut(&BBox3) -> bool,
        mut leaf: impl FnMut(usize) -> std::ops::ControlFlow<()>,
    ) -> std::ops::ControlFlow<()> {
        let mut stack = [0u32; 64];
        let mut top = 0;
        if !self.nodes.is_empty() {
            top = 1;
        }
        while top > 0 {
            top -= 1;
            let at = stack[top] as usize;
            let node = &self.nodes[at];
            if !enter(&node.bbox) {
                continue;
            }
            if node.is_leaf() {
                for k in node.range() {
                    leaf(k)?;
                }
            } else {
                stack[top] = node.index;
                stack[top + 1] = at as u32 + 1;
                top += 2;
            }
        }
        std::ops::ControlFlow::Continue(())
    }
}

/// Spreads the low 21 bits of `v` to every third bit.
fn spread3(v: u64) -> u64 {
    let mut x = v & 0x1f_ffff;
    x = (x | (x << 32)) & 0x1f_0000_0000_ffff;
    x = (x | (x << 16)) & 0x1f_0000_ff00_00ff;
    x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
    x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
    x = (x | (x << 2)) & 0x1249_2492_4924_9249;
    x
}

impl TriangleTree {
    /// Answers `query` for every point, in parallel, in the order of a
    /// Z-order curve through the points: consecutive queries then walk the
    /// same nodes and triangles, which stay in cache, where queries in the
    /// caller's order (often random) would miss it at almost every node.
    fn batch<T: Send>(&self, points: &[Point3], query: impl Fn(Point3) -> T + Sync) -> Vec<T> {
        self.batch_by(points, |&p| p, |&p| query(p))
    }

    /// Answers `query` for every item, in parallel, in the order of a
    /// Z-order curve through the items' places `at(item)` (a ray at its
    /// origin), returned in the items' order: for any batch of queries
    /// against this tree (in random order, about half the time of asking
    /// one by one at 10^6 triangles).
    pub fn batch_by<I: Sync, T: Send>(
        &self,
        items: &[I],
        at: impl Fn(&I) -> Point3 + Sync,
        query: impl Fn(&I) -> T + Sync,
    ) -> Vec<T> {
        use rayon::prelude::*;
        let b = self.bbox();
        let size = b.max - b.min;
        let cell = |v: f64, lo: f64, ext: f64| {
            let t = if ext > 0.0 { (v - lo) / ext } else { 0.0 };
            (t.clamp(0.0, 1.0) * 2_097_151.0) as u64
        };
        let mut order: Vec<(u64, usize)> = items
            .par_iter()
            .enumerate()
            .map(|(i, item)| {
                let p = at(item);
                let key = spread3(cell(p.x, b.min.x, size.x))
                    | spread3(cell(p.y, b.min.y, size.y)) << 1
                    | spread3(cell(p.z, b.min.z, size.z)) << 2;
                (key, i)
            })
            .collect();
        order.par_sort_unstable();
        let mut answers: Vec<(usize, T)> = order.par_iter().map(|&(_, i)| (i, query(&items[i]))).collect();
        answers.par_sort_unstable_by_key(|a| a.0);
        answers.into_iter().map(|a| a.1).collect()
    }
}

/// Squared distance from `p` to the box (0 inside).
fn box_distance2(b: &BBox3, p: Point3) -> f64 {
    let gap = |lo: f64, hi: f64, v: f64| (lo - v).max(v - hi).max(0.0);
    let (x, y, z) = (gap(b.min.x, b.max.x, p.x), gap(b.min.y, b.max.y, p.y), gap(b.min.z, b.max.z, p.z));
    x * x + y * y + z * z
}

/// Parameter at which `o + t·d`, `0 ≤ t ≤ t_max`, enters the box grown by
/// `slack` on every side; `None` when it misses. The slack absorbs the
/// rounding of the slab parameters, so that a caller needing every box
/// the exact line meets (crossing parity) gets them all.
fn enter_box(o: Point3, d: Point3, t_max: f64, b: &BBox3, slack: f64) -> Option<f64> {
    let (mut t0, mut t1) = (0.0f64, t_max);
    for axis in 0..3 {
        let (v, lo, hi) = (o.coord(axis), b.min.coord(axis) - slack, b.max.coord(axis) + slack);
        let dv = d.coord(axis);
        if dv == 0.0 {
            if v < lo || v > hi {
                return None;
            }
            continue;
        }
        let (a, c) = ((lo - v) / dv, (hi - v) / dv);
        let (a, c) = if a <= c { (a, c) } else { (c, a) };
        t0 = t0.max(a);
        t1 = t1.min(c);
        if t0 > t1 {
            return None;
        }
    }
    Some(t0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The node counts the build allocates are the counts of the tree it
    /// builds, for every size around the leaf size and its powers of two.
    #[test]
    fn node_counts_match_the_recursion() {
        fn direct(n: usize) -> usize {
            if n <= LEAF {
                1
            } else {
                1 + direct(n / 2) + direct(n - n / 2)
            }
        }
        for n in (1..2000).chain([4095, 4096, 4097, 65535, 65536, 65537]) {
            assert_eq!(node_count(n), direct(n), "{n}");
        }
    }

    #[test]
    fn leaves_hold_every_triangle_once_inside_their_boxes() {
        let (v, t) = crate::shape::mesh::samples::torus(3.0, 1.0, 90, 60);
        let tree = TriangleTree::from_arrays(&v, &t);
        let mut seen = vec![0; t.len()];
        for (i, node) in tree.nodes.iter().enumerate() {
            if node.is_leaf() {
                for k in node.range() {
                    seen[tree.ids[k] as usize] += 1;
                    assert!(tree.corners(k).iter().all(|&p| node.bbox.contains_box(&BBox3::of([p]))));
                }
            } else {
                for child in [i + 1, node.index as usize] {
                    assert!(node.bbox.contains_box(&tree.nodes[child].bbox));
                }
            }
        }
        assert!(seen.iter().all(|&s| s == 1));
        assert!(tree.index_bytes() <= 64 * t.len());
    }
}
