//! How a solid is read: the welding tolerance and the threads.

/// Options for building a [`super::Mesh3d`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOptions {
    /// Vertices closer than this (model units) become one; 0 (the
    /// default) merges exactly equal positions only.
    pub weld_tolerance: f64,
}

impl MeshOptions {
    /// The defaults: exact welding.
    pub const DEFAULT: MeshOptions = MeshOptions { weld_tolerance: 0.0 };
}

impl Default for MeshOptions {
    fn default() -> Self {
        Self::DEFAULT
    }
}
