//! The axis oracle: checks that share nothing with the library's
//! constructions (brute-force distances, bisection along inward normals).

use medax::kernel::Disk;
use medax::kernel::{BBox, FilteredKernel, Point};
use medax::plane::{MedialAxis2d, NodeKind};
use medax::shape::{Element, JointKind, Shape2d};
use rand::{Rng, SeedableRng};

/// A uniform grid of items (by bounding box) answering "nearest item" by
/// searching rings of cells outwards: plain enough to trust, and fast
/// enough for shapes of thousands of holes in a debug build.
pub struct Grid<T> {
    items: Vec<T>,
    origin: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    cells: Vec<Vec<u32>>,
}

/// Where an item lies, for bucketing: its box, or for a segment the
/// segment itself (a long slanted side's box would cover a square of
/// cells, 10^5 of them each on a comb of long teeth).
#[derive(Debug, Clone, Copy)]
pub enum Extent {
    Box(BBox),
    Segment(Point, Point),
}

impl<T> Grid<T> {
    /// Buckets `items` (each with its box) into about `items.len()` cells of `bbox`.
    pub fn new(items: Vec<(T, BBox)>, bbox: BBox) -> Grid<T> {
        Self::with_extents(items.into_iter().map(|(t, b)| (t, Extent::Box(b))).collect(), bbox)
    }

    /// [`new`](Self::new) for items given by their extents: an item is in
    /// every cell it meets (a segment row by row, its x-range in each row
    /// widened by a thousandth of a cell against rounding).
    pub fn with_extents(items: Vec<(T, Extent)>, bbox: BBox) -> Grid<T> {
        let n = items.len().max(1) as f64;
        let (w, h) = (bbox.width().max(1e-300), bbox.height().max(1e-300));
        let cell = (w * h / n).sqrt().max(w.max(h) / 4096.0);
        let nx = ((w / cell).ceil() as usize).max(1);
        let ny = ((h / cell).ceil() as usize).max(1);
        let mut cells = vec![Vec::new(); nx * ny];
        let origin = bbox.min;
        let ix = |x: f64, n: usize| ((x / cell).floor().max(0.0) as usize).min(n - 1);
        let mut kept = Vec::with_capacity(items.len());
        for (i, (t, extent)) in items.into_iter().enumerate() {
            let b = match extent {
                Extent::Box(b) => b,
                Extent::Segment(a, c) => BBox::of_points(a, c),
            };
            let (x0, x1) = (ix(b.min.x - origin.x, nx), ix(b.max.x - origin.x, nx));
            let (y0, y1) = (ix(b.min.y - origin.y, ny), ix(b.max.y - origin.y, ny));
            for y in y0..=y1 {
                let (xa, xb) = match extent {
                    Extent::Segment(a, c) if a.y != c.y => {
                        // The segment's x-range within this row of cells.
                        let (lo, hi) = (origin.y + y as f64 * cell, origin.y + (y + 1) as f64 * cell);
                        let at = |yy: f64| a.x + (c.x - a.x) * ((yy - a.y) / (c.y - a.y)).clamp(0.0, 1.0);
                        let (p, q) = (at(lo.max(b.min.y)), at(hi.min(b.max.y)));
                        let margin = 1e-3 * cell;
                        (ix(p.min(q) - margin - origin.x, nx).max(x0), ix(p.max(q) + margin - origin.x, nx).min(x1))
                    }
                    _ => (x0, x1),
                };
                for x in xa..=xb {
                    cells[y * nx + x].push(i as u32);
                }
            }
            kept.push(t);
        }
        Grid { items: kept, origin, cell, nx, ny, cells }
    }

    /// The items, in the order given.
    pub fn items(&self) -> &[T] {
        &self.items
    }

    /// The smallest `dist(item, p)`: rings of cells around `p` until the
    /// best found is nearer than anything beyond the ring.
    pub fn nearest(&self, p: Point, dist: impl Fn(&T, Point) -> f64) -> f64 {
        let cx = ((p.x - self.origin.x) / self.cell).floor().clamp(0.0, (self.nx - 1) as f64) as i64;
        let cy = ((p.y - self.origin.y) / self.cell).floor().clamp(0.0, (self.ny - 1) as f64) as i64;
        let mut best = f64::INFINITY;
        let rings = self.nx.max(self.ny) as i64;
        let (nx, ny) = (self.nx as i64, self.ny as i64);
        let visit = |x: i64, y: i64, best: &mut f64| {
            if x >= 0 && y >= 0 && x < nx && y < ny {
                for &i in &self.cells[(y * nx + x) as usize] {
                    *best = best.min(dist(&self.items[i as usize], p));
                }
            }
        };
        for r in 0..=rings {
            // The ring of cells at Chebyshev distance r: rows, then columns.
            for x in cx - r..=cx + r {
                visit(x, cy - r, &mut best);
                if r > 0 {
                    visit(x, cy + r, &mut best);
                }
            }
            for y in cy - r + 1..cy + r {
                visit(cx - r, y, &mut best);
                visit(cx + r, y, &mut best);
            }
            // Cells not reached yet lie more than r cells away in x or y
            // from p's (clamped) cell, so at least r cells from p itself.
            if best <= r as f64 * self.cell {
                break;
            }
        }
        best
    }
}

/// Distances to a shape's boundary by the grid: every element of every loop.
pub struct Boundary<'s> {
    shape: &'s Shape2d,
    grid: Grid<Element>,
    boxes: Vec<BBox>,
}

impl<'s> Boundary<'s> {
    /// Indexes the elements of `shape`.
    pub fn new(shape: &'s Shape2d) -> Boundary<'s> {
        let extent = |e: &Element| match e {
            Element::Segment(g) => Extent::Segment(g.a, g.b),
            Element::Arc(_) => Extent::Box(e.bbox()),
        };
        let items = shape.loops().iter().flat_map(|l| l.elements()).map(|e| (e, extent(&e))).collect();
        let boxes = shape.loops().iter().map(|l| l.bbox()).collect();
        Boundary { shape, grid: Grid::with_extents(items, shape.bbox()), boxes }
    }

    /// Distance from `p` to the boundary.
    pub fn distance(&self, p: Point) -> f64 {
        self.grid.nearest(p, |e, q| e.closest_point(q).0)
    }

    /// Inside the shape: winding numbers with the exact kernel, only for
    /// loops whose box holds `p` (outside its box a loop winds 0 times).
    pub fn inside(&self, p: Point) -> bool {
        let k = FilteredKernel;
        let loops = self.shape.loops().iter().zip(&self.boxes);
        loops.filter(|(_, b)| b.contains(p)).map(|(l, _)| l.winding_number(&k, p)).sum::<i32>() == 1
    }

    /// The largest t for which the disk of radius t at `p + t·n` stays
    /// inside (as [`super::bisected_radius`], on the grid's distances).
    pub fn bisected_radius(&self, p: Point, n: Point, diag: f64) -> f64 {
        // No disk inside is wider than the diagonal.
        super::bisect_radius(|q| self.distance(q), p, n, diag, diag)
    }
}

/// Distance from `p` to the sampled axis polyline.
pub fn axis_distance(polylines: &[Vec<Disk>], p: Point) -> f64 {
    let mut best = f64::INFINITY;
    for pl in polylines {
        for w in pl.windows(2) {
            let (a, b) = (w[0].center, w[1].center);
            let d = b - a;
            let t = if d.norm2() > 0.0 { ((p - a).dot(d) / d.norm2()).clamp(0.0, 1.0) } else { 0.0 };
            best = best.min(p.dist(a + d * t));
        }
        if pl.len() == 1 {
            best = best.min(p.dist(pl[0].center));
        }
    }
    best
}

/// How much one check looked at.
pub struct Report {
    /// Axis samples checked for soundness.
    pub samples: usize,
    /// Boundary probes checked for completeness.
    pub probes: usize,
    /// Probes whose maximal disk lay off the axis but within the final
    /// check's slack inside a disk of the axis (maximal only up to the
    /// tolerance), and the largest such distance from the axis.
    pub nested: (usize, f64),
}

/// Every check on one shape's axis: soundness of every sample, topology
/// (connected, one independent cycle per hole, ends at convex corners and
/// leaf arcs), node kinds by degree, and completeness from `probes` random
/// points of every loop.
pub fn check(s: &Shape2d, axis: &MedialAxis2d, probes: usize, seed: u64) -> Report {
    check_strided(s, axis, probes, seed, 1, 1.0)
}

/// [`check`] with the brute-force distances of soundness taken at every
/// `stride`-th edge and node only (from an offset the seed picks), for
/// axes of 10^5 edges and more; topology and node kinds are checked
/// everywhere. Distances must agree within `slack` times 1e-9 of the
/// bounding-box diagonal ([`check`]: 1).
pub fn check_strided(s: &Shape2d, axis: &MedialAxis2d, probes: usize, seed: u64, stride: usize, slack: f64) -> Report {
    let stride = stride.max(1);
    let start = (seed as usize).wrapping_mul(0x9e37_79b9) % stride;
    let chosen = |i: usize| i % stride == start;
    let diag = s.bbox().diagonal();
    let boundary = Boundary::new(s);
    let tol = slack * 1e-9 * diag;
    let sample_tol = 1e-4 * diag;
    let lines = axis.sampled(s, sample_tol);
    let mut samples = 0;
    // Soundness: every sample is the centre of a disk of its radius that
    // touches the boundary and holds no boundary point.
    for (i, (e, pl)) in axis.edges.iter().zip(&lines).enumerate() {
        assert!(pl.len() >= 2, "edge {e:?}");
        if !chosen(i) {
            continue;
        }
        for (k, &Disk { center: c, radius: r }) in pl.iter().enumerate() {
            let d = boundary.distance(c);
            assert!((d - r).abs() <= tol, "edge {e:?}: sample {c:?} r {r} but distance {d}");
            // The winding number costs a pass over the boundary: strided,
            // one sample per edge.
            if r > tol && (stride == 1 || k == pl.len() / 2) {
                assert!(boundary.inside(c), "edge {e:?}: sample {c:?} outside");
            }
            samples += 1;
        }
    }
    // Topology: connected with one independent cycle per hole (a tree for
    // one loop); its ends are convex corners and leaf arcs.
    let deg = axis.degrees();
    let holes = s.loops().len() - 1;
    assert_eq!(
        axis.nodes.len() + holes,
        axis.edges.len() + 1,
        "not connected with {holes} cycles: {} nodes, {} edges",
        axis.nodes.len(),
        axis.edges.len()
    );
    let mut seen = vec![false; axis.nodes.len()];
    let mut stack = vec![0];
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); axis.nodes.len()];
    for e in &axis.edges {
        adj[e.from].push(e.to);
        adj[e.to].push(e.from);
    }
    while let Some(v) = stack.pop() {
        if !std::mem::replace(&mut seen[v], true) {
            stack.extend(adj[v].iter().copied());
        }
    }
    assert!(seen.iter().all(|&x| x), "axis not connected");
    let convex = s.joint_counts()[JointKind::Convex as usize];
    let corners = axis.nodes.iter().filter(|n| n.kind == NodeKind::Corner).count();
    assert_eq!(corners, convex, "one corner node per convex vertex");
    for (v, n) in axis.nodes.iter().enumerate() {
        match n.kind {
            // A disk's axis is its centre alone: a leaf of degree 0.
            NodeKind::Leaf if axis.nodes.len() == 1 => assert_eq!(deg[v], 0, "{n:?}"),
            NodeKind::Corner | NodeKind::Leaf => assert_eq!(deg[v], 1, "{n:?}"),
            NodeKind::Branch => assert!(deg[v] >= 3, "{n:?}"),
            NodeKind::Joint => assert_eq!(deg[v], 2, "{n:?}"),
        }
        if chosen(v) {
            assert!((boundary.distance(n.point) - n.radius).abs() <= tol, "node {n:?}");
        }
    }
    // Completeness: the maximal disk at random boundary points is centred
    // on the axis.
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let mut pieces: Vec<((Disk, Disk), Extent)> = Vec::new();
    for pl in &lines {
        for w in pl.windows(2).map(|w| (w[0], w[1])).chain((pl.len() == 1).then(|| (pl[0], pl[0]))) {
            pieces.push((w, Extent::Segment(w.0.center, w.1.center)));
        }
    }
    // A lone node (a disk's centre) is a piece of its own.
    if axis.edges.is_empty() {
        for n in &axis.nodes {
            let d = Disk { center: n.point, radius: n.radius };
            pieces.push(((d, d), Extent::Segment(d.center, d.center)));
        }
    }
    let axis_grid = Grid::with_extents(pieces, s.bbox());
    let mut nested = (0, 0.0f64);
    for _ in 0..probes {
        let lp = &s.loops()[rng.gen_range(0..s.loops().len())];
        let k = rng.gen_range(0..lp.len());
        let e = lp.element(k);
        let t = rng.gen_range(0.05..0.95);
        let p = e.point_at(t);
        let n = match e {
            // A point site: any direction.
            Element::Segment(g) if g.a == g.b => {
                let a: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
                Point::new(a.cos(), a.sin())
            }
            Element::Segment(g) => (g.b - g.a).unit().perp(),
            Element::Arc(a) if a.is_ccw() => (a.center - p).unit(),
            Element::Arc(a) => (p - a.center).unit(),
        };
        let r = boundary.bisected_radius(p, n, diag);
        let c = p + n * r;
        let d = axis_grid.nearest(c, |&(a, b), q| {
            let (a, b) = (a.center, b.center);
            let ab = b - a;
            let t = if ab.norm2() > 0.0 { ((q - a).dot(ab) / ab.norm2()).clamp(0.0, 1.0) } else { 0.0 };
            q.dist(a + ab * t)
        });
        if d <= sample_tol + 1e-9 * diag {
            continue;
        }
        // Where the boundary stays within a few τ of a circle over a
        // stretch (a curvature extremum of a nearly circular run of arcs),
        // disks far apart touch it equally within τ: the axis there is
        // determined only up to the tolerance, and the library ends it
        // where the stretch becomes one contact. The probe's disk must
        // then lie within the final check's slack (64τ) inside a disk of
        // the axis: it is maximal only up to the tolerance.
        let nest = axis_grid.items().iter().fold(f64::INFINITY, |best, &(a, b)| {
            (0..=16).map(|i| i as f64 / 16.0).fold(best, |best, t| {
                let (q, rq) = (a.center + (b.center - a.center) * t, a.radius + (b.radius - a.radius) * t);
                best.min(c.dist(q) + r - rq)
            })
        });
        assert!(
            nest <= 64e-9 * diag,
            "probe at {p:?}: centre {c:?} is {d} from the axis, its disk {nest} outside every axis disk"
        );
        nested = (nested.0 + 1, nested.1.max(d));
    }
    Report { samples, probes, nested }
}
