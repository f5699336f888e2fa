//! Leaves of large decompositions that once broke the base case, replayed
//! exactly (`plane::leaf_text`) against the shape they came from, and
//! checked by brute force: every node's disk touches the boundary and holds
//! none of it.

mod common;

use common::boundary_distance;
use medax::plane::internals::{base_case, leaf_text};
use medax::plane::DiskFinder;
use medax::shape::{samples, Shape2d, ShapeOptions};

fn replay(shape: &Shape2d, finder: &DiskFinder, file: &str) -> base_case::LocalAxis {
    let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let (s, cuts) = leaf_text::read_leaf(shape, &text).unwrap_or_else(|e| panic!("{file}: {e}"));
    base_case::solve(shape, &s, &cuts, shape.tolerance(), finder).unwrap_or_else(|e| panic!("{file}: {e:?}"))
}

#[test]
fn a_joint_at_a_fan_end_is_not_its_own_branch_point() {
    // Dense stars have reflex fans too narrow to hold a footpoint: the
    // joint disk at a fan's end touches the element after the fan, the
    // fan's vertex and another site, so it is a candidate for the branch
    // point of its own pocket. Taken, it merged back into the joint and
    // the pocket was walked again until the step budget ran out (100 of
    // the 166 685 leaves of a 10^6-vertex star, 5 of a 10^5-vertex one).
    let shape = Shape2d::from_bulge_loops(samples::star_polygon(100_000, 1), &ShapeOptions::default()).unwrap();
    let finder = DiskFinder::new(&shape);
    let tol = 1e-9 * shape.bbox().diagonal();
    for file in ["star1e5_seed1_leaf_3754.txt", "star1e5_seed1_leaf_7766.txt", "star1e5_seed1_leaf_12278.txt"] {
        let local = replay(&shape, &finder, file);
        assert_eq!(local.edges.len() + 1, local.nodes.len(), "{file}: not a tree");
        assert!(local.nodes.len() > 10, "{file}");
        for n in &local.nodes {
            let d = boundary_distance(&shape, n.center);
            assert!((d - n.radius).abs() <= tol, "{file}: node {n:?} is {d} from the boundary");
        }
    }
}
