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

#[test]
fn leaves_near_the_centre_of_a_nearly_circular_curve() {
    // A curve within 10^-3 of a circle, 3·10^5 arcs: every disk near the
    // centre hugs about a hundred arcs within the tolerance. Leaf 2010:
    // joint disks with footpoints smeared over those arcs, ordered by
    // rounding (one footpoint per hugged stretch now); 7294: a branch
    // point 2τ from its pocket's own joint disk, once rejected as that
    // disk (now merged into it); 15949 and 16020: several dividing disks
    // at the end of a branch, every chain within 10^-11 of every disk
    // (their axis is the path through the ports).
    let shape = Shape2d::from_bulge_loops(samples::fourier_curve(300_000, 3, 1e-3), &ShapeOptions::default()).unwrap();
    let finder = DiskFinder::new(&shape);
    let tol = 1e-9 * shape.bbox().diagonal();
    for (leaf, least_nodes) in [(2010, 20), (7294, 10), (15949, 3), (16020, 8)] {
        let file = format!("circle3e5_seed3_leaf_{leaf}.txt");
        let local = replay(&shape, &finder, &file);
        assert_eq!(local.edges.len() + 1, local.nodes.len(), "{file}: not a tree");
        assert!(local.nodes.len() >= least_nodes, "{file}: {} nodes", local.nodes.len());
        for n in &local.nodes {
            let d = boundary_distance(&shape, n.center);
            assert!((d - n.radius).abs() <= tol, "{file}: node {n:?} is {d} from the boundary");
        }
    }
}

#[test]
fn a_band_whose_other_side_is_only_a_joint() {
    // Near the centre of a nearly circular curve of 10^6 arcs: two dividing
    // disks 5·10^-6 apart that both hug an arc, one on either end of it;
    // the band between them is a sliver of that arc's ends, one side only
    // the joint after it (a chain of no part). The walk finds no
    // consistent order there, and the fallback (the straight edge
    // between the ports) could not name that side's element.
    let shape =
        Shape2d::from_bulge_loops(samples::fourier_curve(1_000_000, 4, 1e-3), &ShapeOptions::default()).unwrap();
    let finder = DiskFinder::new(&shape);
    let local = replay(&shape, &finder, "circle1e6_seed4_leaf_43826.txt");
    assert_eq!((local.nodes.len(), local.edges.len()), (2, 1));
    assert!(local.edges[0].straight);
}

/// Replays `files` of `shape` and checks each leaf's axis by brute force.
fn replay_checked(shape: &Shape2d, files: &[&str]) {
    let finder = DiskFinder::new(shape);
    let tol = 1e-9 * shape.bbox().diagonal();
    for file in files {
        let local = replay(shape, &finder, file);
        assert_eq!(local.edges.len() + 1, local.nodes.len(), "{file}: not a tree");
        for n in &local.nodes {
            let d = boundary_distance(shape, n.center);
            assert!((d - n.radius).abs() <= tol, "{file}: node {n:?} is {d} from the boundary");
        }
    }
}

#[test]
fn leaves_where_contacts_are_placed_by_rounding() {
    // A smooth random curve of 3·10^5 biarcs (Fourier seed 11), where arcs
    // are shorter than the √(τ·r) to which a contact along them is placed.
    // Leaf 10723: two chains between dividing disks 3·10^-4 apart; a joint
    // of two segments that turn by 7·10^-7 rad (smooth within the angular
    // tolerance) grows its disk along their mean normal, which touches
    // each side 8·10^-8 (25τ) from the joint, while another disk's contact
    // clamped onto the joint was ordered after it (measured from the
    // segment's end, not from the joint's own disk). Leaf 1093: three
    // dividing disks 2·10^-4 apart; the branch point touches one side's
    // carrier half an arc before the chain's end, within τ of that end.
    let shape = Shape2d::from_bulge_loops(samples::fourier_biarcs(300_000, 11), &ShapeOptions::default()).unwrap();
    replay_checked(&shape, &["fourier3e5_seed11_leaf_10723.txt", "fourier3e5_seed11_leaf_1093.txt"]);
}

#[test]
fn a_branch_point_far_from_the_origin_between_long_lines() {
    // A comb of 75 000 slanted teeth 53 033 long: the branch point at a
    // channel's foot (x ≈ 53 404) touches the base line, whose anchor is
    // at x = 0, and a wall anchored at the tooth's far end. Solved around
    // the mean of those anchors, the construction lost 10^-4 of the radius
    // and the disk overlapped the vertex beside it.
    let shape = Shape2d::from_bulge_loops(samples::slanted_comb(75_000, 37_500.0), &ShapeOptions::default()).unwrap();
    replay_checked(&shape, &["comb3e5_leaf_8080.txt"]);
}
