//! What a drawing's report names: entity handles of duplicate and touching
//! loops and of touching parts, selection by colour (by layer and by block
//! resolved), keeping duplicates as drawn, and drawing JSON read back.

use medax::io::Format;
use medax::shape::{Drawing2d, DrawingOptions, IgnoredKind, Shape2d, ShapeOptions};

/// A DXF of a LAYER table, one BLOCK and entities, each entity with a
/// handle (group 5) and, where given, a colour (group 62).
#[derive(Default)]
struct Dxf {
    layers: String,
    block: String,
    entities: String,
}

/// Common groups of an entity: handle, layer and colour (256: by layer, not written).
fn head(kind: &str, handle: u32, layer: &str, colour: i16) -> String {
    let colour = if colour == 256 { String::new() } else { format!("62\n{colour}\n") };
    format!("0\n{kind}\n5\n{handle:X}\n8\n{layer}\n{colour}")
}

fn polygon(handle: u32, layer: &str, colour: i16, pts: &[[f64; 2]]) -> String {
    let mut s = head("LWPOLYLINE", handle, layer, colour) + &format!("90\n{}\n70\n1\n", pts.len());
    for p in pts {
        s += &format!("10\n{}\n20\n{}\n", p[0], p[1]);
    }
    s
}

fn rect(handle: u32, layer: &str, colour: i16, x0: f64, y0: f64, x1: f64, y1: f64) -> String {
    polygon(handle, layer, colour, &[[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
}

fn circle(handle: u32, layer: &str, colour: i16, c: [f64; 2], r: f64) -> String {
    head("CIRCLE", handle, layer, colour) + &format!("10\n{}\n20\n{}\n40\n{r}\n", c[0], c[1])
}

fn line(handle: u32, a: [f64; 2], b: [f64; 2]) -> String {
    head("LINE", handle, "0", 256) + &format!("10\n{}\n20\n{}\n11\n{}\n21\n{}\n", a[0], a[1], b[0], b[1])
}

impl Dxf {
    fn layer(mut self, name: &str, colour: i16) -> Dxf {
        self.layers += &format!("0\nLAYER\n2\n{name}\n70\n0\n62\n{colour}\n6\nCONTINUOUS\n");
        self
    }
    fn text(&self) -> String {
        format!(
            "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n{}0\nENDTAB\n0\nENDSEC\n\
             0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nB\n10\n0\n20\n0\n{}0\nENDBLK\n0\nENDSEC\n\
             0\nSECTION\n2\nENTITIES\n{}0\nENDSEC\n0\nEOF\n",
            self.layers, self.block, self.entities
        )
    }
    fn read(&self, select: &DrawingOptions) -> Drawing2d {
        Drawing2d::from_str_as(&self.text(), Format::Dxf, &ShapeOptions::default(), select).expect("the drawing parses")
    }
}

fn colours(c: &[i16]) -> DrawingOptions {
    DrawingOptions { colours: c.to_vec(), ..DrawingOptions::default() }
}

fn areas(d: &Drawing2d) -> Vec<f64> {
    d.shapes.iter().map(|s| (s.area() * 1e6).round() / 1e6).collect()
}

#[test]
fn colours_select_by_entity_by_layer_and_by_block() {
    let mut d = Dxf::default().layer("CUT", 1).layer("MARK", -3);
    // Red by layer (area 100), green by layer on a layer that is off
    // (area 4), blue by entity on the red layer (area 9), and a block
    // whose square is "by block", inserted in yellow (area 1).
    d.entities += &rect(0x10, "CUT", 256, 0.0, 0.0, 10.0, 10.0);
    d.entities += &rect(0x11, "MARK", 256, 20.0, 0.0, 22.0, 2.0);
    d.entities += &rect(0x12, "CUT", 5, 30.0, 0.0, 33.0, 3.0);
    d.block += &rect(0x13, "0", 0, 0.0, 0.0, 1.0, 1.0);
    d.entities += "0\nINSERT\n5\n14\n8\nCUT\n62\n2\n2\nB\n10\n40\n20\n0\n";
    assert_eq!(areas(&d.read(&DrawingOptions::default())), [100.0, 9.0, 4.0, 1.0]);
    assert_eq!(areas(&d.read(&colours(&[1]))), [100.0]);
    assert_eq!(areas(&d.read(&colours(&[3]))), [4.0]);
    assert_eq!(areas(&d.read(&colours(&[2, 5]))), [9.0, 1.0]);
    // What the selection leaves out is reported by layer.
    let red = d.read(&colours(&[1]));
    let left: Vec<&str> =
        red.ignored.iter().filter(|i| i.kind == IgnoredKind::OtherLayer).map(|i| i.layer.as_str()).collect();
    assert_eq!(left, ["CUT", "MARK"]);
    // A colour that does not parse is no error: the entity is by layer.
    d.entities = d.entities.replace("62\n5\n", "62\nblue\n");
    assert_eq!(areas(&d.read(&colours(&[1]))), [100.0, 9.0]);
}

#[test]
fn duplicate_and_touching_loops_name_both_entities() {
    let mut d = Dxf::default();
    d.entities += &circle(0xA1, "0", 256, [0.0, 0.0], 2.0);
    d.entities += &circle(0xA2, "0", 256, [0.0, 0.0], 2.0);
    // A plate of four lines with a hole touching its top line (handle C3).
    d.entities += &line(0xC1, [10.0, 0.0], [20.0, 0.0]);
    d.entities += &line(0xC2, [20.0, 0.0], [20.0, 10.0]);
    d.entities += &line(0xC3, [20.0, 10.0], [10.0, 10.0]);
    d.entities += &line(0xC4, [10.0, 10.0], [10.0, 0.0]);
    d.entities += &circle(0xD1, "0", 256, [15.0, 8.0], 2.0);
    let r = d.read(&DrawingOptions::default());
    assert_eq!(r.shapes.len(), 2);
    let by_kind = |k: IgnoredKind| r.ignored.iter().find(|i| i.kind == k).unwrap_or_else(|| panic!("{k:?}"));
    assert_eq!(by_kind(IgnoredKind::DuplicateLoop).handles, [0xA2, 0xA1]);
    assert_eq!(by_kind(IgnoredKind::TouchingLoop).handles, [0xD1, 0xC3]);
    let json: serde_json::Value = serde_json::from_str(&r.to_json()).unwrap();
    let handles: Vec<&serde_json::Value> = json["ignored"].as_array().unwrap().iter().map(|i| &i["handles"]).collect();
    assert!(handles.contains(&&serde_json::json!(["A2", "A1"])), "{handles:?}");
    // Kept as drawn, the two circles meet: one of them is reported as
    // touching the other, whichever way containment took them.
    let kept = d.read(&DrawingOptions { keep_duplicates: true, ..DrawingOptions::default() });
    assert!(kept.ignored.iter().all(|i| i.kind != IgnoredKind::DuplicateLoop));
    let met = kept.ignored.iter().any(|i| i.kind == IgnoredKind::TouchingLoop && i.handles.contains(&0xA1))
        || kept.touching.iter().any(|t| t.handles.contains(&0xA1) && t.handles.contains(&0xA2));
    assert!(met, "{:?} {:?}", kept.ignored, kept.touching);
}

#[test]
fn parts_sharing_an_edge_or_touching_a_hole_are_kept_and_reported() {
    let mut d = Dxf::default();
    d.entities += &rect(0x20, "0", 256, 0.0, 0.0, 10.0, 10.0);
    d.entities += &rect(0x21, "0", 256, 10.0, 2.0, 14.0, 6.0);
    // A plate with a hole, an island in it touching the hole, and a part
    // far away touching nothing.
    d.entities += &rect(0x30, "0", 256, 30.0, 0.0, 50.0, 20.0);
    d.entities += &rect(0x31, "0", 256, 35.0, 5.0, 45.0, 15.0);
    d.entities += &circle(0x32, "0", 256, [40.0, 10.0], 5.0);
    d.entities += &circle(0x40, "0", 256, [80.0, 0.0], 1.0);
    let r = d.read(&DrawingOptions::default());
    assert_eq!(r.shapes.len(), 5, "{:?}", r.ignored);
    let mut pairs: Vec<[u64; 2]> = r
        .touching
        .iter()
        .map(|t| {
            let mut h = t.handles;
            h.sort_unstable();
            assert_ne!(t.shapes[0], t.shapes[1]);
            h
        })
        .collect();
    pairs.sort_unstable();
    assert_eq!(pairs, [[0x20, 0x21], [0x31, 0x32]]);
    let json: serde_json::Value = serde_json::from_str(&r.to_json()).unwrap();
    let kinds: Vec<&str> = json["warnings"].as_array().unwrap().iter().map(|w| w["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["touching_shapes", "touching_shapes"]);
}

#[test]
fn drawing_json_reads_back_as_the_same_shapes() {
    let mut d = Dxf::default();
    d.entities += &rect(0x20, "0", 256, 0.0, 0.0, 10.0, 10.0);
    d.entities += &circle(0x21, "0", 256, [5.0, 5.0], 2.0);
    d.entities += &circle(0x22, "0", 256, [5.0, 5.0], 1.0);
    d.entities += &circle(0x23, "0", 256, [30.0, 5.0], 3.0);
    let r = d.read(&DrawingOptions::default());
    assert_eq!(r.shapes.len(), 3);
    let json = r.to_json();
    let back = Drawing2d::from_str_as(&json, Format::Json, &ShapeOptions::default(), &DrawingOptions::default())
        .expect("drawing JSON reads");
    assert_eq!(areas(&back), areas(&r));
    assert_eq!(back.shapes.iter().map(|s| s.loops().len()).collect::<Vec<_>>(), [2, 1, 1]);
    // One shape expected: the error says it is a drawing.
    let e = Shape2d::from_json_str(&json, &ShapeOptions::default()).unwrap_err().to_string();
    assert!(e.contains("a drawing of 3 shape(s)"), "{e}");
    // A shape of the drawing that does not validate is reported, the
    // others kept.
    let bad = r#"{"shapes": [{"loops": [[[0,0],[4,0],[0,4],[4,4]]]}, {"loops": [[[0,0],[1,0],[0,1]]]}]}"#;
    let back = Drawing2d::from_str_as(bad, Format::Json, &ShapeOptions::default(), &DrawingOptions::default()).unwrap();
    assert_eq!(back.shapes.len(), 1);
    assert_eq!(back.ignored.len(), 1);
    assert_eq!((back.ignored[0].kind, back.ignored[0].source), (IgnoredKind::InvalidShape, 0));
}

#[test]
fn selecting_by_layer_or_colour_needs_a_format_that_has_them() {
    let svg = r#"<svg><rect x="0" y="0" width="4" height="2"/></svg>"#;
    let opts = ShapeOptions::default();
    assert_eq!(Drawing2d::from_str_as(svg, Format::Svg, &opts, &DrawingOptions::default()).unwrap().shapes.len(), 1);
    for select in [colours(&[1]), DrawingOptions { layers: vec!["0".into()], ..DrawingOptions::default() }] {
        let e = Drawing2d::from_str_as(svg, Format::Svg, &opts, &select).unwrap_err();
        assert!(e.to_string().contains("no layers or colours"), "{e}");
        let json = r#"{"loops": [[[0, 0], [4, 0], [4, 2], [0, 2]]]}"#;
        assert!(Drawing2d::from_str_as(json, Format::Json, &opts, &select).is_err());
    }
}

#[test]
fn a_sheet_of_parts_sharing_edges_keeps_every_part() {
    // A 4 x 4 grid of squares, each its own closed polyline, every inner
    // edge drawn by both neighbours: no part is taken for another's hole.
    let mut d = Dxf::default();
    for i in 0..4 {
        for j in 0..4 {
            let (x, y) = (10.0 * i as f64, 10.0 * j as f64);
            d.entities += &rect(0x100 + 4 * i + j, "0", 256, x, y, x + 10.0, y + 10.0);
        }
    }
    let r = d.read(&DrawingOptions::default());
    assert_eq!(r.shapes.len(), 16, "{:?}", r.ignored);
    assert!(r.ignored.is_empty(), "{:?}", r.ignored);
    // 24 shared edges and 18 corners where diagonal neighbours meet.
    assert_eq!(r.touching.len(), 24 + 18);
}
