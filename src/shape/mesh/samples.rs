//! Generated solids for tests, benchmarks and the demo: parametric tori
//! and spheres of any resolution, boxes, a box with a cavity, and
//! L-shaped prisms (one reflex edge).

/// Vertices and triangles of a generated solid.
pub type Soup = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// A torus about the z axis: tube of radius `minor` around a circle of
/// radius `major`, `n` steps around the axis and `m` around the tube
/// (2·n·m triangles, genus 1), facing outward.
pub fn torus(major: f64, minor: f64, n: usize, m: usize) -> Soup {
    let (n, m) = (n.max(3), m.max(3));
    let mut v = Vec::with_capacity(n * m);
    for i in 0..n {
        let u = std::f64::consts::TAU * i as f64 / n as f64;
        for j in 0..m {
            let w = std::f64::consts::TAU * j as f64 / m as f64;
            let r = major + minor * w.cos();
            v.push([r * u.cos(), r * u.sin(), minor * w.sin()]);
        }
    }
    let id = |i: usize, j: usize| ((i % n) * m + j % m) as u32;
    let mut t = Vec::with_capacity(2 * n * m);
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    (v, t)
}

/// A sphere of radius `r` about `center`, `n` rings by `m` meridians
/// (2·m·(n − 1) triangles), facing outward.
pub fn sphere(center: [f64; 3], r: f64, n: usize, m: usize) -> Soup {
    let (n, m) = (n.max(2), m.max(3));
    let mut v = vec![[center[0], center[1], center[2] + r]];
    for i in 1..n {
        let polar = std::f64::consts::PI * i as f64 / n as f64;
        for j in 0..m {
            let az = std::f64::consts::TAU * j as f64 / m as f64;
            v.push([
                center[0] + r * polar.sin() * az.cos(),
                center[1] + r * polar.sin() * az.sin(),
                center[2] + r * polar.cos(),
            ]);
        }
    }
    v.push([center[0], center[1], center[2] - r]);
    let south = (v.len() - 1) as u32;
    let ring = |i: usize, j: usize| (1 + (i - 1) * m + j % m) as u32;
    let mut t = Vec::new();
    for j in 0..m {
        t.push([0, ring(1, j), ring(1, j + 1)]);
        t.push([south, ring(n - 1, j + 1), ring(n - 1, j)]);
    }
    for i in 1..n - 1 {
        for j in 0..m {
            let (a, b, c, d) = (ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    (v, t)
}

/// The box `lo`–`hi` (12 triangles), facing outward.
pub fn cuboid(lo: [f64; 3], hi: [f64; 3]) -> Soup {
    let v: Vec<[f64; 3]> = (0..8)
        .map(|i| {
            [
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            ]
        })
        .collect();
    let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let t = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    (v, t)
}

/// Several solids as one soup (indices shifted).
pub fn union(parts: &[Soup]) -> Soup {
    let mut out: Soup = (Vec::new(), Vec::new());
    for (v, t) in parts {
        let base = out.0.len() as u32;
        out.0.extend_from_slice(v);
        out.1.extend(t.iter().map(|tri| tri.map(|i| i + base)));
    }
    out
}

/// An L-shaped prism: the square `[0, size]²` less the corner beyond
/// `corner` (`0 < corner < size` in both coordinates), extruded to
/// `height`; one reflex edge, the vertical one at `corner`. `shear` tilts
/// it off the axes (0: axis-aligned), so that no face is parallel to an
/// axis-aligned ball's facets. Facing outward.
pub fn l_prism(size: f64, corner: [f64; 2], height: f64, shear: f64) -> Soup {
    let [cx, cy] = corner;
    let outline = [[0.0, 0.0], [size, 0.0], [size, cy], [cx, cy], [cx, size], [0.0, size]];
    let lift = |p: [f64; 2], z: f64| [p[0] + 0.07 * shear * z, p[1] - 0.03 * shear * z, z + 0.05 * shear * p[0]];
    let mut v: Vec<[f64; 3]> = outline.iter().map(|&p| lift(p, 0.0)).collect();
    v.extend(outline.iter().map(|&p| lift(p, height)));
    let mut t = Vec::new();
    for [a, b, c] in [[0u32, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]] {
        t.push([a, c, b]);
        t.push([a + 6, b + 6, c + 6]);
    }
    for i in 0..6u32 {
        let j = (i + 1) % 6;
        t.push([i, j, j + 6]);
        t.push([i, j + 6, i + 6]);
    }
    (v, t)
}

/// The union of unit cubes at the integer cells `cells` (`[i, j, k]` is
/// the cube `[i, i + 1] × [j, j + 1] × [k, k + 1]`), scaled by `size`:
/// every face between a cell and an empty one as two triangles, facing
/// outward, vertices shared. Concave corners, saddles and pockets for the
/// tests of chapter 3; cells meeting only along an edge or at a corner
/// give a surface that is not manifold there (which validation refuses).
pub fn polycube(cells: &[[i32; 3]], size: f64) -> Soup {
    use std::collections::{HashMap, HashSet};
    let filled: HashSet<[i32; 3]> = cells.iter().copied().collect();
    let mut index: HashMap<[i32; 3], u32> = HashMap::new();
    let mut v: Vec<[f64; 3]> = Vec::new();
    let mut id = |p: [i32; 3]| {
        *index.entry(p).or_insert_with(|| {
            v.push(p.map(|x| f64::from(x) * size));
            (v.len() - 1) as u32
        })
    };
    let mut t = Vec::new();
    let mut sorted: Vec<[i32; 3]> = filled.iter().copied().collect();
    sorted.sort_unstable();
    for c in sorted {
        for axis in 0..3 {
            for side in [0, 1] {
                let mut n = c;
                n[axis] += if side == 1 { 1 } else { -1 };
                if filled.contains(&n) {
                    continue;
                }
                // The face's corners counter-clockwise seen along the
                // outward normal (+axis for side 1, −axis for side 0).
                let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
                let corner = |du: i32, dw: i32| {
                    let mut p = c;
                    p[axis] += side;
                    p[u] += du;
                    p[w] += dw;
                    p
                };
                let mut q = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                if side == 0 {
                    q.reverse();
                }
                let q = q.map(&mut id);
                t.push([q[0], q[1], q[2]]);
                t.push([q[0], q[2], q[3]]);
            }
        }
    }
    (v, t)
}
