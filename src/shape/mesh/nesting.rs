//! Which component of a solid lies inside which: a solid with cavities is
//! an outer surface and, inside it, surfaces bounding holes of empty space
//! (and inside those, islands of material again). A component's depth is
//! the number of components around it; even depths bound material from
//! outside, odd depths bound cavities.
//!
//! A component is inside another when one of its vertices is: the winding
//! number of the other's closed surface about that vertex, the sum of the
//! signed solid angles of its triangles (Van Oosterom and Strackee) over
//! 4π, which is ±1 inside and 0 outside. It needs no ray and so has no
//! degenerate hits; for disjoint surfaces the vertex is off the other
//! surface, where the sum is far from the half-way value.

use crate::kernel::{BBox3, Point3};

/// The signed solid angle of triangle `a, b, c` seen from `p`, in units of
/// 4π steradians (positive when the triangle runs counter-clockwise seen
/// from `p`... as outward faces do from inside).
fn solid_angle(p: Point3, a: Point3, b: Point3, c: Point3) -> f64 {
    let (a, b, c) = (a - p, b - p, c - p);
    let (la, lb, lc) = (a.norm(), b.norm(), c.norm());
    let det = a.dot(b.cross(c));
    let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    2.0 * det.atan2(den) / (4.0 * std::f64::consts::PI)
}

/// The winding number of the closed triangle surface `tris` about `p`.
pub(crate) fn winding_number(p: Point3, tris: impl Iterator<Item = [Point3; 3]>) -> f64 {
    tris.map(|[a, b, c]| solid_angle(p, a, b, c)).sum()
}

/// For each component, the component directly around it (`None` at depth
/// 0) and its depth. `probe[i]` is a vertex of component `i`, `boxes[i]`
/// its bounding box, `tris_of(i)` its triangles.
pub(crate) fn nest<'a, I>(
    probe: &[Point3],
    boxes: &[BBox3],
    tris_of: impl Fn(usize) -> I,
) -> Vec<(Option<usize>, usize)>
where
    I: Iterator<Item = [Point3; 3]> + 'a,
{
    let n = probe.len();
    // Containers of i: components whose box holds i's box and whose
    // surface winds around i's probe vertex.
    let containers: Vec<Vec<usize>> = (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| j != i && boxes[j].contains_box(&boxes[i]))
                .filter(|&j| winding_number(probe[i], tris_of(j)).abs() > 0.5)
                .collect()
        })
        .collect();
    // The direct parent is the container with the most containers itself.
    (0..n)
        .map(|i| {
            let depth = containers[i].len();
            let parent = containers[i].iter().copied().max_by_key(|&j| containers[j].len());
            (parent, depth)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(lo: f64, hi: f64) -> Vec<[Point3; 3]> {
        let v = |i: usize| {
            Point3::new(
                if i & 1 == 0 { lo } else { hi },
                if i & 2 == 0 { lo } else { hi },
                if i & 4 == 0 { lo } else { hi },
            )
        };
        // Outward faces of the cube with corners v(0..8).
        let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        quads.iter().flat_map(|q| [[v(q[0]), v(q[1]), v(q[2])], [v(q[0]), v(q[2]), v(q[3])]]).collect()
    }

    #[test]
    fn winding_numbers_inside_and_outside() {
        let c = cube(0.0, 1.0);
        assert!((winding_number(Point3::new(0.5, 0.5, 0.5), c.iter().copied()) - 1.0).abs() < 1e-12);
        assert!(winding_number(Point3::new(1.5, 0.5, 0.5), c.iter().copied()).abs() < 1e-12);
    }

    #[test]
    fn nested_cubes_have_depths_and_parents() {
        let comps = [cube(0.0, 10.0), cube(1.0, 9.0), cube(2.0, 3.0), cube(20.0, 21.0)];
        let probe: Vec<Point3> = comps.iter().map(|c| c[0][0]).collect();
        let boxes: Vec<BBox3> = comps.iter().map(|c| BBox3::of(c.iter().flatten().copied())).collect();
        let n = nest(&probe, &boxes, |i| comps[i].iter().copied());
        assert_eq!(n, vec![(None, 0), (Some(0), 1), (Some(1), 2), (None, 0)]);
    }
}
