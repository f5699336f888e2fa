//! ASCII DXF writer: closed bulge polylines as LWPOLYLINE and 3D polylines
//! (tool paths with depth) as POLYLINE/VERTEX/SEQEND, each on a named layer.
//!
//! The file has a HEADER naming release R2000 (`AC1015`, the first with
//! LWPOLYLINE) and an ENTITIES section, nothing else: CAM programs and
//! libraries (and [`super::dxf::read_dxf`]) read such minimal files, and
//! tables or handles would only add what a reader ignores. Numbers are
//! written in Rust's shortest round-trip decimal form without exponents
//! (some DXF readers do not take exponents), so reading the file back gives
//! bit-identical coordinates and bulges.

use super::RawVertex;
use std::fmt::Write as _;

/// A DXF document under construction.
#[derive(Debug, Default)]
pub struct DxfWriter {
    body: String,
}

impl DxfWriter {
    /// An empty document.
    pub fn new() -> DxfWriter {
        DxfWriter::default()
    }

    fn group(&mut self, code: i32, value: impl std::fmt::Display) {
        let _ = write!(self.body, "{code:>3}\n{value}\n");
    }

    /// Adds a polyline with bulges (`vertices[i].bulge` is that of the
    /// element from vertex `i` to the next) on `layer`, closed (flag 70 = 1:
    /// the last vertex joins the first with its bulge) or open. Model units.
    pub fn lwpolyline(&mut self, layer: &str, vertices: &[RawVertex], closed: bool) {
        self.lwpolyline_at(layer, vertices, closed, 0.0);
    }

    /// [`DxfWriter::lwpolyline`] at height `z` (group 38, the elevation of
    /// the whole entity; model units): a flat-bottom ring at its depth.
    pub fn lwpolyline_at(&mut self, layer: &str, vertices: &[RawVertex], closed: bool, z: f64) {
        self.group(0, "LWPOLYLINE");
        self.group(8, layer);
        self.group(100, "AcDbEntity");
        self.group(100, "AcDbPolyline");
        self.group(90, vertices.len());
        self.group(70, u8::from(closed));
        if z != 0.0 {
            self.group(38, z);
        }
        for v in vertices {
            self.group(10, v.x);
            self.group(20, v.y);
            if v.bulge != 0.0 {
                self.group(42, v.bulge);
            }
        }
    }

    /// Adds an open 3D polyline through `points` (x, y, z; model units) on
    /// `layer`.
    ///
    /// A V-carve path changes depth along its length, which LWPOLYLINE (one
    /// elevation for the whole entity) cannot hold. The classic POLYLINE
    /// with flag 70 = 8 (3D polyline) and VERTEX flag 32 is what CAD and
    /// CAM programs read as a 3D tool path (R12 onwards); a 2D reader, ours
    /// included, skips it.
    pub fn polyline_3d(&mut self, layer: &str, points: &[[f64; 3]]) {
        self.group(0, "POLYLINE");
        self.group(8, layer);
        self.group(100, "AcDbEntity");
        self.group(100, "AcDb3dPolyline");
        self.group(66, 1);
        self.group(10, 0.0);
        self.group(20, 0.0);
        self.group(30, 0.0);
        self.group(70, 8);
        for p in points {
            self.group(0, "VERTEX");
            self.group(8, layer);
            self.group(100, "AcDbEntity");
            self.group(100, "AcDbVertex");
            self.group(100, "AcDb3dPolylineVertex");
            self.group(10, p[0]);
            self.group(20, p[1]);
            self.group(30, p[2]);
            self.group(70, 32);
        }
        self.group(0, "SEQEND");
        self.group(8, layer);
    }

    /// The finished file.
    pub fn finish(self) -> String {
        let mut out = String::with_capacity(self.body.len() + 200);
        out.push_str("  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1015\n  0\nENDSEC\n");
        out.push_str("  0\nSECTION\n  2\nENTITIES\n");
        out.push_str(&self.body);
        out.push_str("  0\nENDSEC\n  0\nEOF\n");
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::dxf::read_dxf;

    fn v(x: f64, y: f64, bulge: f64) -> RawVertex {
        RawVertex { x, y, bulge }
    }

    #[test]
    fn our_reader_reads_back_what_we_write_bit_for_bit() {
        // Awkward numbers: thirds, tiny and huge magnitudes, negative
        // bulges, an arc over 180 degrees and a full circle as two halves.
        let square =
            vec![v(0.0, 0.0, 0.0), v(1.0 / 3.0, -1e-7, 0.41421356237309503), v(2.5e8, 7.0, -1.7), v(0.1, 0.2, 0.0)];
        let circle = vec![v(-1.0, 0.0, 1.0), v(1.0, 0.0, 1.0)];
        let open = vec![v(5.0, 5.0, 0.25), v(6.0, 5.0, 0.0)];
        let mut w = DxfWriter::new();
        w.lwpolyline("RING_0", &square, true);
        w.polyline_3d("VCARVE", &[[0.0, 0.0, -0.5], [1.0, 1.0, -0.25]]);
        w.lwpolyline_at("RING_1", &circle, true, -2.5);
        w.lwpolyline("OPEN", &open, false);
        let text = w.finish();
        let read = read_dxf(&text).expect("our own DXF parses");
        assert!(read.lines.is_empty() && read.arcs.is_empty() && read.circles.is_empty());
        // The 3D polyline is skipped by the 2D reader; the three others come
        // back in order, exactly.
        let back: Vec<(Vec<RawVertex>, bool)> = read.polylines.into_iter().map(|p| (p.vertices, p.closed)).collect();
        assert_eq!(back, vec![(square, true), (circle, true), (open, false)]);
    }

    #[test]
    fn a_3d_polyline_has_its_flags_and_depths() {
        let mut w = DxfWriter::new();
        w.polyline_3d("VCARVE", &[[1.0, 2.0, -0.125], [3.0, 4.0, 0.0]]);
        let text = w.finish();
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        let pair = |code: &str, value: &str| lines.windows(2).filter(|w| w[0] == code && w[1] == value).count();
        assert_eq!(pair("0", "POLYLINE"), 1);
        assert_eq!(pair("70", "8"), 1);
        assert_eq!(pair("0", "VERTEX"), 2);
        assert_eq!(pair("70", "32"), 2);
        assert_eq!(pair("30", "-0.125"), 1);
        assert_eq!(pair("0", "SEQEND"), 1);
        assert!(text.ends_with("  0\nEOF\n"));
    }
}
