//! Solids from files and from the readers' raw data.

use super::error::MeshError;
use super::mesh3d::{Faces, Mesh3d};
use super::options::MeshOptions;
use crate::io::mesh::{read_mesh, MeshFormat, RawMesh};

impl Mesh3d {
    /// A solid from what a reader returned.
    pub fn from_raw(raw: &RawMesh, options: &MeshOptions) -> Result<Mesh3d, MeshError> {
        let lines: &[u32] = if raw.source_is_line { &raw.face_source } else { &[] };
        let faces = Faces { indices: &raw.indices, starts: &raw.face_starts, lines };
        Mesh3d::from_polygons(&raw.positions, faces, options)
    }

    /// A solid from a file's bytes (`None`: the format is guessed from the
    /// content).
    pub fn from_bytes(bytes: &[u8], format: Option<MeshFormat>, options: &MeshOptions) -> Result<Mesh3d, MeshError> {
        Mesh3d::from_raw(&read_mesh(bytes, format)?, options)
    }

    /// A solid from a file (format by extension, else by content).
    pub fn from_path(path: &std::path::Path, options: &MeshOptions) -> Result<Mesh3d, MeshError> {
        let bytes = std::fs::read(path)
            .map_err(|e| MeshError::Io { path: path.display().to_string(), message: e.to_string() })?;
        Mesh3d::from_bytes(&bytes, MeshFormat::from_path(path), options)
    }

    /// A solid from flat arrays: `xyz` three coordinates per vertex,
    /// `triangles` three vertex indices each.
    pub fn from_triangles(
        xyz: &[[f64; 3]],
        triangles: &[[u32; 3]],
        options: &MeshOptions,
    ) -> Result<Mesh3d, MeshError> {
        let indices: Vec<u32> = triangles.iter().flatten().copied().collect();
        let starts: Vec<u32> = (0..=triangles.len() as u32).map(|i| 3 * i).collect();
        Mesh3d::from_polygons(xyz, Faces { indices: &indices, starts: &starts, lines: &[] }, options)
    }
}
