//! Offsets as DXF: each loop a closed LWPOLYLINE with bulges (arcs stay
//! arcs, so a CAM program can emit G2/G3), one DXF layer per distance.

use crate::io::dxf_writer::DxfWriter;
use crate::io::RawVertex;
use crate::plane::offset::layer::OffsetLayer;
use crate::shape::Vertex;

/// Adds closed bulge loops to `w` on `layer`, at height `z` (model units).
pub fn add_loops(w: &mut DxfWriter, layer: &str, loops: impl IntoIterator<Item = impl AsRef<[Vertex]>>, z: f64) {
    for l in loops {
        let raw: Vec<RawVertex> = l.as_ref().iter().map(|&v| RawVertex::from(v)).collect();
        w.lwpolyline_at(layer, &raw, true, z);
    }
}

/// The layers as a DXF file: the loops of `layers[k]` on DXF layer
/// `OFFSET_k` (layer names cannot hold every number a distance may be).
pub fn offsets_to_dxf(layers: &[OffsetLayer]) -> String {
    let mut w = DxfWriter::new();
    for (k, layer) in layers.iter().enumerate() {
        add_loops(&mut w, &format!("OFFSET_{k}"), &layer.loops, 0.0);
    }
    w.finish()
}
