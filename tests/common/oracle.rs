//! The axis oracle: checks that share nothing with the library's
//! constructions (brute-force distances, bisection along inward normals).

use super::{bisected_radius, boundary_distance, inside};
use medax::kernel::Point;
use medax::plane::{MedialAxis2d, NodeKind};
use medax::shape::{Element, JointKind, Shape2d};
use rand::{Rng, SeedableRng};

/// Distance from `p` to the sampled axis polyline.
pub fn axis_distance(polylines: &[Vec<(Point, f64)>], p: Point) -> f64 {
    let mut best = f64::INFINITY;
    for pl in polylines {
        for w in pl.windows(2) {
            let (a, b) = (w[0].0, w[1].0);
            let d = b - a;
            let t = if d.norm2() > 0.0 { ((p - a).dot(d) / d.norm2()).clamp(0.0, 1.0) } else { 0.0 };
            best = best.min(p.dist(a + d * t));
        }
        if pl.len() == 1 {
            best = best.min(p.dist(pl[0].0));
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
}

/// Every check on one shape's axis: soundness of every sample, topology
/// (connected, one independent cycle per hole, ends at convex corners and
/// leaf arcs), node kinds by degree, and completeness from `probes` random
/// points of every loop.
pub fn check(s: &Shape2d, axis: &MedialAxis2d, probes: usize, seed: u64) -> Report {
    let diag = s.bbox().diagonal();
    let tol = 1e-9 * diag;
    let sample_tol = 1e-4 * diag;
    let lines = axis.sampled(s, sample_tol);
    let mut samples = 0;
    // Soundness: every sample is the centre of a disk of its radius that
    // touches the boundary and holds no boundary point.
    for (e, pl) in axis.edges.iter().zip(&lines) {
        assert!(pl.len() >= 2, "edge {e:?}");
        for &(c, r) in pl {
            let d = boundary_distance(s, c);
            assert!((d - r).abs() <= tol, "edge {e:?}: sample {c:?} r {r} but distance {d}");
            if r > tol {
                assert!(inside(s, c), "edge {e:?}: sample {c:?} outside");
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
            NodeKind::Corner | NodeKind::Leaf => assert_eq!(deg[v], 1, "{n:?}"),
            NodeKind::Branch => assert!(deg[v] >= 3, "{n:?}"),
            NodeKind::Joint => assert_eq!(deg[v], 2, "{n:?}"),
        }
        assert!((boundary_distance(s, n.point) - n.radius).abs() <= tol, "node {n:?}");
    }
    // Completeness: the maximal disk at random boundary points is centred
    // on the axis.
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    for _ in 0..probes {
        let lp = &s.loops()[rng.gen_range(0..s.loops().len())];
        let k = rng.gen_range(0..lp.len());
        let e = lp.element(k);
        let t = rng.gen_range(0.05..0.95);
        let p = e.point_at(t);
        let n = match e {
            Element::Segment(g) => (g.b - g.a).unit().perp(),
            Element::Arc(a) if a.is_ccw() => (a.center - p).unit(),
            Element::Arc(a) => (p - a.center).unit(),
        };
        let c = p + n * bisected_radius(s, p, n, diag);
        let d = axis_distance(&lines, c);
        assert!(d <= sample_tol + 1e-9 * diag, "probe at {p:?}: centre {c:?} is {d} from the axis");
    }
    Report { samples, probes }
}
