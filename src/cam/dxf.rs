//! Pockets and V-carves as DXF: rings as closed LWPOLYLINEs with bulges
//! (arcs stay arcs), V-carve paths as 3D POLYLINEs. The surface of the
//! stock is z = 0 and depths go down to negative z, the usual CAM work
//! origin on top of the stock.

use super::pocket::Pocket;
use super::vcarve::VCarve;
use crate::io::dxf_writer::DxfWriter;
use crate::plane::offset::dxf::add_loops;

impl Pocket {
    /// The pocket as DXF: rings in machining order, the rings of level k on
    /// DXF layer `RING_k`, the uncut regions' loops on layer `UNCUT`.
    pub fn to_dxf(&self) -> String {
        let mut w = DxfWriter::new();
        for &i in &self.order {
            let r = &self.rings[i];
            add_loops(&mut w, &format!("RING_{}", r.level), &r.loops, 0.0);
        }
        for u in &self.uncut {
            add_loops(&mut w, "UNCUT", &u.loops, 0.0);
        }
        w.finish()
    }
}

impl VCarve {
    /// The V-carve as DXF: each path a 3D polyline at z = −depth on layer
    /// `VCARVE`, the flat bottom's rings at z = −max_depth on layer
    /// `FLAT`.
    pub fn to_dxf(&self) -> String {
        let mut w = DxfWriter::new();
        for p in &self.paths {
            let pts: Vec<[f64; 3]> = p.points.iter().map(|&[x, y, d]| [x, y, -d]).collect();
            w.polyline_3d("VCARVE", &pts);
        }
        let z = if self.opts.max_depth.is_finite() { -self.opts.max_depth } else { 0.0 };
        add_loops(&mut w, "FLAT", &self.flat.loops, z);
        w.finish()
    }
}
