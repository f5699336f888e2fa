//! Small hand-made solids for the 3D tests.

/// Vertices and triangles.
pub type Soup = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// An L-shaped prism, 2 × 2 × `height` with the corner [1, 2] × [1, 2] cut
/// out: one reflex edge, the vertical one at (1, 1). `shear` tilts it off
/// the axes (0: axis-aligned, integer corners for height 1).
pub fn l_prism(height: f64, shear: f64) -> Soup {
    medax::shape::mesh_samples::l_prism(2.0, [1.0, 1.0], height, shear)
}

/// A 4 × 4 × 2 slab of unit cubes with an L-shaped pocket in its top layer
/// (cells (1, 1), (2, 1), (1, 2) left out), the floor's vertex at the L's
/// inner corner, (2, 2, 1), lowered to z = 0.4: a valley. The pocket's
/// floor corners are concave; the valley is a saddle (a convex edge up,
/// reflex ones along the floor) whose exterior lies beyond a plane.
#[allow(dead_code)] // `tests/cli.rs` includes this file alone.
pub fn pocket_with_valley() -> Soup {
    let mut slab: Vec<[i32; 3]> = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            slab.push([i, j, 0]);
            if ![[1, 1], [2, 1], [1, 2]].contains(&[i, j]) {
                slab.push([i, j, 1]);
            }
        }
    }
    let mut pocket = medax::shape::mesh_samples::polycube(&slab, 1.0);
    pocket.0.iter_mut().filter(|p| **p == [2.0, 2.0, 1.0]).for_each(|p| p[2] = 0.4);
    pocket
}
