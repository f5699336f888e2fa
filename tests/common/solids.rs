//! Small hand-made solids for the 3D tests.

/// Vertices and triangles.
pub type Soup = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// An L-shaped prism, 2 × 2 × `height` with the corner [1, 2] × [1, 2] cut
/// out: one reflex edge, the vertical one at (1, 1). `shear` tilts it off
/// the axes (0: axis-aligned, integer corners for height 1).
pub fn l_prism(height: f64, shear: f64) -> Soup {
    let outline = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
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
