//! Small hand-made solids for the 3D tests.

/// Vertices and triangles.
pub type Soup = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// An L-shaped prism, 2 × 2 × `height` with the corner [1, 2] × [1, 2] cut
/// out: one reflex edge, the vertical one at (1, 1). `shear` tilts it off
/// the axes (0: axis-aligned, integer corners for height 1).
pub fn l_prism(height: f64, shear: f64) -> Soup {
    medax::shape::mesh_samples::l_prism(2.0, [1.0, 1.0], height, shear)
}
