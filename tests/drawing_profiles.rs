//! Profiles out of drawings: closed loops kept and grouped into shapes by
//! containment, everything else reported, nothing refused whole.

use medax::io::Format;
use medax::shape::{Drawing2d, DrawingOptions, IgnoredKind, ShapeOptions};

/// A DXF ENTITIES section of LINEs (x0, y0, x1, y1), CIRCLEs (x, y, r)
/// and TEXTs.
struct Dxf(String, &'static str);

impl Dxf {
    fn new() -> Dxf {
        Dxf("0\nSECTION\n2\nENTITIES\n".into(), "0")
    }
    /// The layer of the entities added next.
    fn on(mut self, layer: &'static str) -> Dxf {
        self.1 = layer;
        self
    }
    fn line(mut self, a: [f64; 2], b: [f64; 2]) -> Dxf {
        self.0 += &format!("0\nLINE\n8\n{}\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n", self.1, a[0], a[1], b[0], b[1]);
        self
    }
    fn rect(self, x0: f64, y0: f64, x1: f64, y1: f64) -> Dxf {
        self.line([x0, y0], [x1, y0]).line([x1, y0], [x1, y1]).line([x1, y1], [x0, y1]).line([x0, y1], [x0, y0])
    }
    fn circle(mut self, c: [f64; 2], r: f64) -> Dxf {
        self.0 += &format!("0\nCIRCLE\n8\n{}\n10\n{}\n20\n{}\n40\n{}\n", self.1, c[0], c[1], r);
        self
    }
    fn text(mut self, at: [f64; 2], s: &str) -> Dxf {
        self.0 += &format!("0\nTEXT\n8\n{}\n10\n{}\n20\n{}\n40\n2.5\n1\n{s}\n", self.1, at[0], at[1]);
        self
    }
    fn read(self) -> Drawing2d {
        self.read_layers(&[])
    }
    fn read_layers(self, layers: &[&str]) -> Drawing2d {
        let text = self.0 + "0\nENDSEC\n0\nEOF\n";
        let select =
            DrawingOptions { layers: layers.iter().map(|l| l.to_string()).collect(), ..DrawingOptions::default() };
        Drawing2d::from_str_as(&text, Format::Dxf, &ShapeOptions::default(), &select).expect("the drawing parses")
    }
}

fn kinds(d: &Drawing2d) -> Vec<IgnoredKind> {
    d.ignored.iter().map(|i| i.kind).collect()
}

#[test]
fn a_part_with_centre_lines_and_text_is_the_part() {
    // A plate with a bore; centre lines cross the bore and stick out.
    let d = Dxf::new()
        .rect(0.0, 0.0, 40.0, 20.0)
        .circle([20.0, 10.0], 5.0)
        .line([12.0, 10.0], [28.0, 10.0])
        .line([20.0, 2.0], [20.0, 18.0])
        .text([1.0, 22.0], "PLATE 40x20")
        .read();
    assert_eq!(d.shapes.len(), 1);
    assert_eq!(d.shapes[0].holes().len(), 1);
    assert!((d.shapes[0].area() - (800.0 - 25.0 * std::f64::consts::PI)).abs() < 1e-9);
    assert_eq!(kinds(&d), [IgnoredKind::Entity, IgnoredKind::OpenChain, IgnoredKind::OpenChain]);
    assert!(d.ignored[0].reason.starts_with("TEXT"), "{}", d.ignored[0].reason);
    assert_eq!(d.ignored[0].position, medax::kernel::Point::new(1.0, 22.0));
    // Each names its entity's line and a loose end.
    let ends: Vec<_> = d.ignored.iter().map(|i| (i.position.x, i.position.y)).collect();
    assert!(ends.contains(&(28.0, 10.0)) || ends.contains(&(12.0, 10.0)), "{ends:?}");
    assert!(d.ignored.iter().all(|i| i.source > 0));
}

#[test]
fn two_parts_side_by_side_are_two_shapes_largest_first() {
    let d = Dxf::new().circle([0.0, 0.0], 3.0).rect(10.0, -5.0, 30.0, 5.0).read();
    assert_eq!(d.shapes.len(), 2);
    assert!(d.shapes[0].area() > d.shapes[1].area());
    assert!((d.shapes[0].area() - 200.0).abs() < 1e-9);
    assert!(d.ignored.is_empty());
    // The JSON holds each shape as medax shape JSON, read back the same.
    let doc: serde_json::Value = serde_json::from_str(&d.to_json()).unwrap();
    let shapes = doc["shapes"].as_array().unwrap();
    assert_eq!(shapes.len(), 2);
    for (json, shape) in shapes.iter().zip(&d.shapes) {
        let again = medax::shape::Shape2d::from_json_str(&json.to_string(), &ShapeOptions::default()).unwrap();
        assert_eq!(again.loops(), shape.loops());
    }
}

#[test]
fn an_island_inside_a_hole_is_a_shape_of_its_own() {
    // A frame (outer + window) with a part inside the window, and a bore
    // in that part: two shapes of one hole each.
    let d = Dxf::new()
        .rect(0.0, 0.0, 100.0, 100.0)
        .rect(10.0, 10.0, 90.0, 90.0)
        .rect(20.0, 20.0, 80.0, 80.0)
        .circle([50.0, 50.0], 10.0)
        .read();
    assert_eq!(d.shapes.len(), 2);
    assert_eq!(d.shapes.iter().map(|s| s.holes().len()).collect::<Vec<_>>(), [1, 1]);
    assert!((d.shapes[0].area() - (10000.0 - 6400.0)).abs() < 1e-9);
    assert!((d.shapes[1].area() - (3600.0 - 100.0 * std::f64::consts::PI)).abs() < 1e-9);
}

#[test]
fn a_gap_below_the_chaining_tolerance_closes_and_a_wider_one_is_reported() {
    let gap = |g: f64| {
        Dxf::new()
            .line([0.0, 0.0], [10.0, 0.0])
            .line([10.0, 0.0], [10.0, 10.0])
            .line([10.0, 10.0], [0.0, 10.0])
            .line([0.0, 10.0], [0.0, g])
            .read()
    };
    // The default chaining tolerance is 1e-6 of the diagonal (1.4e-5).
    let closed = gap(1e-6);
    assert_eq!((closed.shapes.len(), closed.ignored.len()), (1, 0));
    // The gap closed is named, where it was.
    assert_eq!(closed.gaps.len(), 1);
    assert!((closed.gaps[0].1 - 1e-6).abs() < 1e-12);
    assert!(closed.gaps[0].0.dist(medax::kernel::Point::new(0.0, 0.0)) <= 1e-6);
    // An exact drawing closes no gap.
    assert!(Dxf::new().rect(0.0, 0.0, 3.0, 2.0).read().gaps.is_empty());
    let open = gap(1e-3);
    assert!(open.shapes.is_empty());
    assert_eq!(kinds(&open), [IgnoredKind::OpenChain]);
    assert!(open.ignored[0].reason.contains("4 entities"), "{}", open.ignored[0].reason);
}

#[test]
fn a_loop_drawn_twice_is_kept_once() {
    // Lines drawn twice: the square's two copies are found, the second
    // reported as a duplicate of the first.
    let d = Dxf::new().rect(0.0, 0.0, 10.0, 10.0).rect(0.0, 0.0, 10.0, 10.0).circle([30.0, 0.0], 2.0).read();
    assert_eq!(d.shapes.len(), 2);
    assert!((d.shapes[0].area() - 100.0).abs() < 1e-9);
    assert!((d.shapes[1].area() - 4.0 * std::f64::consts::PI).abs() < 1e-9);
    assert_eq!(kinds(&d), [IgnoredKind::DuplicateLoop]);
    // A circle drawn twice: one shape, the copy reported with the line
    // of the one kept.
    let d = Dxf::new().circle([0.0, 0.0], 2.0).circle([0.0, 0.0], 2.0).read();
    assert_eq!(d.shapes.len(), 1);
    assert_eq!(kinds(&d), [IgnoredKind::DuplicateLoop]);
    assert!(d.ignored[0].reason.contains("line/byte 5"), "{}", d.ignored[0].reason);
    // A hole touching its outer loop: the shape is kept without it, the
    // hole reported with the validation error naming both loops.
    let d = Dxf::new().rect(0.0, 0.0, 10.0, 10.0).circle([5.0, 8.0], 2.0).circle([3.0, 3.0], 1.0).read();
    assert_eq!(d.shapes.len(), 1);
    assert_eq!(d.shapes[0].holes().len(), 1);
    assert_eq!(kinds(&d), [IgnoredKind::TouchingLoop]);
    assert!(matches!(d.ignored[0].cause, Some(medax::shape::ShapeError::Intersection { .. })));
    // An outer loop crossing itself: the whole shape is reported.
    let bow = Dxf::new().line([0.0, 0.0], [6.0, 6.0]).line([6.0, 6.0], [6.0, 0.0]).line([6.0, 0.0], [0.0, 3.0]);
    let d = bow.line([0.0, 3.0], [0.0, 0.0]).read();
    assert!(d.shapes.is_empty());
    assert_eq!(kinds(&d), [IgnoredKind::InvalidShape]);
}

#[test]
fn a_drawing_of_open_lines_only_has_no_shape() {
    let d = Dxf::new().line([0.0, 0.0], [1.0, 0.0]).line([5.0, 5.0], [6.0, 7.0]).text([0.0, 0.0], "A").read();
    assert!(d.shapes.is_empty());
    assert_eq!(kinds(&d), [IgnoredKind::Entity, IgnoredKind::OpenChain, IgnoredKind::OpenChain]);
}

#[test]
fn layers_select_the_curves_taken() {
    // A part on PART inside a frame on FRAME, a note on TEXT.
    let drawing = || {
        Dxf::new()
            .on("FRAME")
            .rect(0.0, 0.0, 100.0, 60.0)
            .on("PART")
            .rect(20.0, 20.0, 50.0, 40.0)
            .circle([35.0, 30.0], 4.0)
            .on("TEXT")
            .text([5.0, 5.0], "A1")
    };
    // Every layer: the frame is a shape whose hole is the part's outline,
    // and the part (an island in that hole) is a shape of its own.
    let all = drawing().read();
    assert_eq!(all.shapes.len(), 2);
    // The part's layer only: one shape with its bore; the frame's four
    // lines reported as one other layer, the text left unreported.
    let part = drawing().read_layers(&["PART"]);
    assert_eq!(part.shapes.len(), 1);
    assert!((part.shapes[0].area() - (600.0 - 16.0 * std::f64::consts::PI)).abs() < 1e-9);
    assert_eq!(kinds(&part), [IgnoredKind::OtherLayer]);
    assert_eq!(part.ignored[0].layer, "FRAME");
    assert!(part.ignored[0].reason.starts_with("4 curve(s)"), "{}", part.ignored[0].reason);
    // Two layers.
    let both = drawing().read_layers(&["PART", "TEXT"]);
    assert_eq!(both.shapes.len(), 1);
    assert_eq!(kinds(&both), [IgnoredKind::Entity, IgnoredKind::OtherLayer]);
    assert_eq!(both.ignored[0].layer, "TEXT");
}

#[test]
fn json_stays_one_strict_shape() {
    let json = r#"{"loops": [[[0, 0], [4, 0], [4, 4], [0, 4]]]}"#;
    let d = Drawing2d::from_str_as(json, Format::Json, &ShapeOptions::default(), &DrawingOptions::default()).unwrap();
    assert_eq!(d.shapes.len(), 1);
    assert!(d.ignored.is_empty());
}

#[test]
fn an_svg_of_two_parts_and_a_stroke() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg">
        <path d="M 0 0 L 10 0 L 10 10 L 0 10 Z M 3 3 L 3 7 L 7 7 L 7 3 Z"/>
        <rect x="20" y="0" width="4" height="2"/>
        <path d="M -5 -5 L 30 -5"/>
    </svg>"#;
    let d = Drawing2d::from_str_as(svg, Format::Svg, &ShapeOptions::default(), &DrawingOptions::default()).unwrap();
    assert_eq!(d.shapes.len(), 2);
    assert_eq!(d.shapes[0].holes().len(), 1);
    assert!((d.shapes[0].area() - 84.0).abs() < 1e-9);
    assert!((d.shapes[1].area() - 8.0).abs() < 1e-9);
    assert_eq!(kinds(&d), [IgnoredKind::OpenChain]);
    assert_eq!(d.ignored[0].layer, "");
}

#[test]
fn a_part_inside_a_frame_with_a_title_block() {
    // A sheet: outer edge, inner border, a title block in the border's
    // lower right corner (its bottom and right edges are the border's),
    // split into cells with text; the part (a plate with a bore) and its
    // centre lines in the middle of the sheet.
    let d = Dxf::new()
        .on("FRAME")
        .rect(0.0, 0.0, 297.0, 210.0)
        .rect(10.0, 10.0, 287.0, 200.0)
        .line([187.0, 10.0], [187.0, 50.0])
        .line([187.0, 50.0], [287.0, 50.0])
        .line([187.0, 30.0], [287.0, 30.0])
        .line([237.0, 10.0], [237.0, 30.0])
        .text([190.0, 40.0], "PLATE 1")
        .text([190.0, 20.0], "1:1")
        .on("PART")
        .rect(40.0, 80.0, 120.0, 160.0)
        .circle([80.0, 120.0], 10.0)
        .on("CENTRE")
        .line([65.0, 120.0], [95.0, 120.0])
        .line([80.0, 105.0], [80.0, 135.0])
        .read();
    let part = 6400.0 - 100.0 * std::f64::consts::PI;
    let found: Vec<_> = d.shapes.iter().filter(|s| (s.area() - part).abs() < 1e-9).collect();
    assert_eq!(found.len(), 1, "{:?}", d.shapes.iter().map(|s| s.area()).collect::<Vec<_>>());
    assert_eq!(found[0].holes().len(), 1);
    // Every shape validates, no loop is in two shapes, and the text and
    // centre lines are reported.
    let loops: usize = d.shapes.iter().map(|s| s.loops().len()).sum();
    assert!(loops >= 3, "{loops}");
    assert_eq!(kinds(&d).iter().filter(|&&k| k == IgnoredKind::Entity).count(), 2);
    assert!(kinds(&d).contains(&IgnoredKind::OpenChain));
    // The part's layer alone gives the part alone.
    let only = Dxf::new().on("PART").rect(40.0, 80.0, 120.0, 160.0).circle([80.0, 120.0], 10.0).read_layers(&["PART"]);
    assert_eq!(only.shapes.len(), 1);
}
