//! Polygon faces cut into triangles. OFF, OBJ and PLY files carry quads and
//! larger polygons; the solid's algorithms (AABB tree, contact domains)
//! work on triangles. A face is projected onto the coordinate plane its
//! normal is most aligned with and cut by ear clipping with exact
//! orientations, so a non-convex face (an L-shaped cap) gives triangles
//! inside it; a corner where the boundary runs straight on is never an ear,
//! so no triangle is flat where the face is not.

use crate::kernel::{FilteredKernel, Kernel, Orientation, Point, Point3};

/// The triangles of the polygon `face` (welded vertex ids, in order), or
/// `None` when it has fewer than three distinct corners or no ear can be
/// cut (all corners on one line, or a self-crossing outline).
pub(crate) fn triangulate(face: &[u32], positions: &[Point3], out: &mut Vec<[u32; 3]>) -> Option<()> {
    // Consecutive repeats (a quad whose two corners welded) carry nothing.
    let mut ids: Vec<u32> = Vec::with_capacity(face.len());
    for &v in face {
        if ids.last() != Some(&v) {
            ids.push(v);
        }
    }
    while ids.len() > 1 && ids.first() == ids.last() {
        ids.pop();
    }
    match ids.len() {
        0..=2 => None,
        3 => {
            out.push([ids[0], ids[1], ids[2]]);
            Some(())
        }
        _ => ear_clip(&ids, positions, out),
    }
}

/// Newell's normal of the polygon: robust for non-planar and non-convex
/// outlines, and its largest component names the projection that keeps
/// the polygon's orientation.
fn newell(ids: &[u32], positions: &[Point3]) -> Point3 {
    let mut n = Point3::default();
    for (i, &a) in ids.iter().enumerate() {
        let (p, q) = (positions[a as usize], positions[ids[(i + 1) % ids.len()] as usize]);
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    n
}

fn ear_clip(ids: &[u32], positions: &[Point3], out: &mut Vec<[u32; 3]>) -> Option<()> {
    let n = newell(ids, positions);
    let axis = (0..3).max_by(|&a, &b| n.coord(a).abs().total_cmp(&n.coord(b).abs()))?;
    if n.coord(axis) == 0.0 {
        return None;
    }
    // Drop `axis`; swap the other two when the normal points down it, so
    // that the projected polygon runs counter-clockwise.
    let flip = n.coord(axis) < 0.0;
    let project = |v: u32| {
        let p = positions[v as usize];
        let (u, w) = match axis {
            0 => (p.y, p.z),
            1 => (p.z, p.x),
            _ => (p.x, p.y),
        };
        if flip {
            Point::new(w, u)
        } else {
            Point::new(u, w)
        }
    };
    let pts: Vec<Point> = ids.iter().map(|&v| project(v)).collect();
    let k = FilteredKernel;
    let mut ring: Vec<usize> = (0..ids.len()).collect();
    let mut guard = 0;
    while ring.len() > 3 {
        let m = ring.len();
        let ear = (0..m).find(|&i| {
            let (a, b, c) = (ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]);
            if k.orientation(pts[a], pts[b], pts[c]) != Orientation::Left {
                return false;
            }
            // No other corner inside or on the ear (closed triangle).
            ring.iter().all(|&o| {
                o == a
                    || o == b
                    || o == c
                    || pts[o] == pts[a]
                    || pts[o] == pts[c]
                    || k.orientation(pts[a], pts[b], pts[o]) == Orientation::Right
                    || k.orientation(pts[b], pts[c], pts[o]) == Orientation::Right
                    || k.orientation(pts[c], pts[a], pts[o]) == Orientation::Right
            })
        })?;
        let (a, b, c) = (ring[(ear + m - 1) % m], ring[ear], ring[(ear + 1) % m]);
        out.push([ids[a], ids[b], ids[c]]);
        ring.remove(ear);
        guard += 1;
        if guard > ids.len() {
            return None;
        }
    }
    let last = [ids[ring[0]], ids[ring[1]], ids[ring[2]]];
    if k.orientation(pts[ring[0]], pts[ring[1]], pts[ring[2]]) != Orientation::Left {
        return None;
    }
    out.push(last);
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_l() -> Vec<Point3> {
        // An L in the plane z = 1, counter-clockwise seen from +z.
        [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)]
            .iter()
            .map(|&(x, y)| Point3::new(x, y, 1.0))
            .collect()
    }

    fn area(t: &[u32; 3], p: &[Point3]) -> Point3 {
        let (a, b, c) = (p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]);
        (b - a).cross(c - a) * 0.5
    }

    #[test]
    fn a_non_convex_face_gives_triangles_inside_it_with_its_orientation() {
        let p = square_l();
        let mut out = Vec::new();
        triangulate(&[0, 1, 2, 3, 4, 5], &p, &mut out).unwrap();
        assert_eq!(out.len(), 4);
        let total: f64 = out.iter().map(|t| area(t, &p).z).sum();
        assert!((total - 3.0).abs() < 1e-12);
        assert!(out.iter().all(|t| area(t, &p).z > 0.0), "{out:?}");
        // Reversed: every triangle turns the other way.
        let mut back = Vec::new();
        triangulate(&[5, 4, 3, 2, 1, 0], &p, &mut back).unwrap();
        assert!(back.iter().all(|t| area(t, &p).z < 0.0));
    }

    #[test]
    fn repeats_and_straight_corners() {
        let p: Vec<Point3> = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]
            .iter()
            .map(|&(x, y)| Point3::new(x, 0.0, y))
            .collect();
        let mut out = Vec::new();
        // A straight corner at vertex 1 is never an ear tip: no flat triangle.
        triangulate(&[0, 1, 2, 3, 4], &p, &mut out).unwrap();
        assert_eq!(out.len(), 3);
        assert!(out.iter().all(|t| area(t, &p).norm() > 0.0));
        assert!(triangulate(&[0, 0, 1, 1], &p, &mut Vec::new()).is_none());
        assert!(triangulate(&[0, 1, 2, 1], &p, &mut Vec::new()).is_none(), "all on one line");
    }
}
