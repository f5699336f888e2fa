//! The convex hull of points in space for [`Ball3`](super::Ball3),
//! decided with the exact orientation test `plane_side` only, so that
//! coplanar and collinear inputs (a cube given by its 27 grid points)
//! come out as the polytope they are rather than as rounding noise.
//!
//! Incremental (beneath–beyond): each point is tested against every
//! current triangle, O(n·F) in all, plenty for balls of a few thousand
//! points and free of the bookkeeping of conflict lists. A triangle is
//! visible from a point only when the point is strictly above its plane:
//! a point on the hull (on a facet, an edge, a vertex) changes nothing,
//! and a point beyond an edge in a facet's plane extends that facet with
//! coplanar triangles, merged at the end.

use super::error::BallError;
use crate::kernel::orient3::{collinear3, plane_side, PlaneSide};
use crate::kernel::Point3;
use std::collections::{HashMap, HashSet};

/// The hull's facets as indices into the points given.
pub(super) struct Hull {
    /// Facet polygons, counter-clockwise seen from outside, no three
    /// consecutive corners collinear, each starting at its least index.
    pub facets: Vec<Vec<usize>>,
    /// For each facet three corners spanning its plane, counter-clockwise
    /// seen from outside: exact tests against the facet's plane.
    pub planes: Vec<[usize; 3]>,
}

/// The convex hull of `points`.
///
/// # Errors
///
/// Fewer than 4 points, a NaN or infinite coordinate, all points on one
/// plane.
pub(super) fn hull(points: &[Point3]) -> Result<Hull, BallError> {
    if points.len() < 4 {
        return Err(BallError::TooFewPoints { count: points.len() });
    }
    if let Some(point) = points.iter().position(|p| !p.is_finite()) {
        return Err(BallError::NonFinitePoint { point });
    }
    let seed = seed_simplex(points)?;
    let mut faces = seed_faces(points, seed);
    for (j, &p) in points.iter().enumerate() {
        if seed.contains(&j) {
            continue;
        }
        let visible: Vec<bool> =
            faces.iter().map(|f| plane_side(points[f[0]], points[f[1]], points[f[2]], p) == PlaneSide::Above).collect();
        if !visible.contains(&true) {
            // Inside or on the hull: not a vertex.
            continue;
        }
        let seen: HashSet<(usize, usize)> =
            faces.iter().zip(&visible).filter(|(_, &v)| v).flat_map(|(f, _)| directed_edges(f)).collect();
        let mut next = Vec::with_capacity(faces.len() + 4);
        let mut cone = Vec::new();
        for (f, &v) in faces.iter().zip(&visible) {
            if !v {
                next.push(*f);
                continue;
            }
            // The horizon: edges of the visible region whose other
            // triangle stays; p sees across them, so (a, b, p) keeps the
            // orientation of the triangle it replaces.
            for (a, b) in directed_edges(f) {
                if !seen.contains(&(b, a)) {
                    cone.push([a, b, j]);
                }
            }
        }
        next.extend(cone);
        faces = next;
    }
    Ok(merge_coplanar(points, &faces))
}

/// Four points spanning space, the first ones that do (so the output is
/// deterministic), or `Flat`.
fn seed_simplex(points: &[Point3]) -> Result<[usize; 4], BallError> {
    let a = points[0];
    let i1 = (1..points.len()).find(|&j| points[j] != a).ok_or(BallError::Flat)?;
    let b = points[i1];
    let i2 = (i1 + 1..points.len()).find(|&j| !collinear3(a, b, points[j])).ok_or(BallError::Flat)?;
    let c = points[i2];
    let i3 =
        (i2 + 1..points.len()).find(|&j| plane_side(a, b, c, points[j]) != PlaneSide::On).ok_or(BallError::Flat)?;
    Ok([0, i1, i2, i3])
}

/// The tetrahedron's four triangles, each turned so that the fourth corner
/// is below it (counter-clockwise seen from outside).
fn seed_faces(points: &[Point3], s: [usize; 4]) -> Vec<[usize; 3]> {
    [(0, 1, 2, 3), (0, 1, 3, 2), (0, 2, 3, 1), (1, 2, 3, 0)]
        .iter()
        .map(|&(x, y, z, w)| {
            let f = [s[x], s[y], s[z]];
            if plane_side(points[f[0]], points[f[1]], points[f[2]], points[s[w]]) == PlaneSide::Above {
                [f[0], f[2], f[1]]
            } else {
                f
            }
        })
        .collect()
}

fn directed_edges(f: &[usize; 3]) -> [(usize, usize); 3] {
    [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])]
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Neighbouring triangles in one plane (the far corner of one exactly on
/// the other's plane) form one facet; its boundary, minus the corners that
/// lie on a straight stretch of it, is the facet polygon.
fn merge_coplanar(points: &[Point3], faces: &[[usize; 3]]) -> Hull {
    let owner: HashMap<(usize, usize), usize> =
        faces.iter().enumerate().flat_map(|(t, f)| directed_edges(f).map(|e| (e, t))).collect();
    let mut parent: Vec<usize> = (0..faces.len()).collect();
    for (t, f) in faces.iter().enumerate() {
        for (a, b) in directed_edges(f) {
            let u = owner[&(b, a)];
            if u < t {
                continue;
            }
            let far = faces[u].iter().copied().find(|&v| v != a && v != b).unwrap_or(a);
            if plane_side(points[f[0]], points[f[1]], points[f[2]], points[far]) == PlaneSide::On {
                let (ra, rb) = (find(&mut parent, t), find(&mut parent, u));
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
    }
    let roots: Vec<usize> = (0..faces.len()).map(|t| find(&mut parent, t)).collect();
    let mut groups: Vec<usize> = roots.clone();
    groups.sort_unstable();
    groups.dedup();
    let mut facets = Vec::with_capacity(groups.len());
    let mut planes = Vec::with_capacity(groups.len());
    for &g in &groups {
        // Boundary edges: those whose reverse belongs to another facet.
        let mut next: HashMap<usize, usize> = HashMap::new();
        for (_, f) in faces.iter().enumerate().filter(|&(t, _)| roots[t] == g) {
            for (a, b) in directed_edges(f) {
                if roots[owner[&(b, a)]] != g {
                    next.insert(a, b);
                }
            }
        }
        let start = *next.keys().min().unwrap_or(&faces[g][0]);
        let mut cycle = vec![start];
        let mut at = next.get(&start).copied().unwrap_or(start);
        // A facet of a convex polytope is a convex polygon: its boundary is
        // one simple cycle, at most `next.len()` steps long.
        while at != start && cycle.len() <= next.len() {
            cycle.push(at);
            at = next.get(&at).copied().unwrap_or(start);
        }
        let m = cycle.len();
        let corners: Vec<usize> = (0..m)
            .filter(|&i| {
                let (p, v, q) = (cycle[(i + m - 1) % m], cycle[i], cycle[(i + 1) % m]);
                !collinear3(points[p], points[v], points[q])
            })
            .map(|i| cycle[i])
            .collect();
        facets.push(corners);
        planes.push(faces[g]);
    }
    Hull { facets, planes }
}
