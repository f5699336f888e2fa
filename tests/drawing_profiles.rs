//! Profiles out of drawings: closed loops kept and grouped into shapes by
//! containment, everything else reported, nothing refused whole.

use medax::io::Format;
use medax::shape::{Drawing2d, IgnoredKind, ShapeOptions};

/// A DXF ENTITIES section of LINEs (x0, y0, x1, y1), CIRCLEs (x, y, r)
/// and TEXTs.
struct Dxf(String);

impl Dxf {
    fn new() -> Dxf {
        Dxf("0\nSECTION\n2\nENTITIES\n".into())
    }
    fn line(mut self, a: [f64; 2], b: [f64; 2]) -> Dxf {
        self.0 += &format!("0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n", a[0], a[1], b[0], b[1]);
        self
    }
    fn rect(self, x0: f64, y0: f64, x1: f64, y1: f64) -> Dxf {
        self.line([x0, y0], [x1, y0]).line([x1, y0], [x1, y1]).line([x1, y1], [x0, y1]).line([x0, y1], [x0, y0])
    }
    fn circle(mut self, c: [f64; 2], r: f64) -> Dxf {
        self.0 += &format!("0\nCIRCLE\n8\n0\n10\n{}\n20\n{}\n40\n{}\n", c[0], c[1], r);
        self
    }
    fn text(mut self, at: [f64; 2], s: &str) -> Dxf {
        self.0 += &format!("0\nTEXT\n8\n0\n10\n{}\n20\n{}\n40\n2.5\n1\n{s}\n", at[0], at[1]);
        self
    }
    fn read(self) -> Drawing2d {
        let text = self.0 + "0\nENDSEC\n0\nEOF\n";
        Drawing2d::from_str_as(&text, Format::Dxf, &ShapeOptions::default()).expect("the drawing parses")
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
    assert_eq!(kinds(&d), [IgnoredKind::OpenChain, IgnoredKind::OpenChain]);
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
    let open = gap(1e-3);
    assert!(open.shapes.is_empty());
    assert_eq!(kinds(&open), [IgnoredKind::OpenChain]);
    assert!(open.ignored[0].reason.contains("4 entities"), "{}", open.ignored[0].reason);
}

#[test]
fn a_loop_drawn_twice_is_reported_not_taken() {
    // Lines drawn twice: each one chains with its own copy, back and
    // forth, into loops that enclose nothing.
    let d = Dxf::new().rect(0.0, 0.0, 10.0, 10.0).rect(0.0, 0.0, 10.0, 10.0).circle([30.0, 0.0], 2.0).read();
    assert_eq!(d.shapes.len(), 1);
    assert!((d.shapes[0].area() - 4.0 * std::f64::consts::PI).abs() < 1e-9);
    assert!(!d.ignored.is_empty() && d.ignored.iter().all(|i| i.kind == IgnoredKind::FlatLoop), "{:?}", kinds(&d));
    // A circle drawn twice: one shape, the copy reported with the line
    // of the one kept.
    let d = Dxf::new().circle([0.0, 0.0], 2.0).circle([0.0, 0.0], 2.0).read();
    assert_eq!(d.shapes.len(), 1);
    assert_eq!(kinds(&d), [IgnoredKind::DuplicateLoop]);
    assert!(d.ignored[0].reason.contains("line/byte 5"), "{}", d.ignored[0].reason);
    // A hole touching its outer loop: the shape is reported with the
    // validation error.
    let d = Dxf::new().rect(0.0, 0.0, 10.0, 10.0).circle([5.0, 8.0], 2.0).read();
    assert!(d.shapes.is_empty());
    assert_eq!(kinds(&d), [IgnoredKind::InvalidShape]);
    assert!(d.ignored[0].cause.is_some());
}

#[test]
fn a_drawing_of_open_lines_only_has_no_shape() {
    let d = Dxf::new().line([0.0, 0.0], [1.0, 0.0]).line([5.0, 5.0], [6.0, 7.0]).text([0.0, 0.0], "A").read();
    assert!(d.shapes.is_empty());
    assert_eq!(kinds(&d), [IgnoredKind::OpenChain, IgnoredKind::OpenChain]);
}

#[test]
fn json_stays_one_strict_shape() {
    let json = r#"{"loops": [[[0, 0], [4, 0], [4, 4], [0, 4]]]}"#;
    let d = Drawing2d::from_str_as(json, Format::Json, &ShapeOptions::default()).unwrap();
    assert_eq!(d.shapes.len(), 1);
    assert!(d.ignored.is_empty());
}

/// LibreCAD's library of real drawings (Debian `librecad-data`, installed
/// by `scripts/test-all`): every file is read without a panic, and the
/// profiles found leave out no file a plain chaining of its LINE, ARC,
/// CIRCLE and polyline entities finds a closed profile in: the issue that
/// asked for profile extraction counted 864 of them (1,272 library files;
/// the package's 1,335 DXF files include hatch patterns and fonts).
#[test]
fn the_librecad_library_yields_profiles() {
    let root = std::path::Path::new("/usr/share/librecad");
    if !root.exists() {
        eprintln!("skipped: {} is not installed (Debian package librecad-data)", root.display());
        return;
    }
    let mut files = Vec::new();
    let mut dirs = vec![root.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            let p = entry.path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|e| e.eq_ignore_ascii_case("dxf")) {
                files.push(p);
            }
        }
    }
    let opts = ShapeOptions::default();
    let mut with_shapes = 0;
    for f in &files {
        if let Ok(d) = Drawing2d::from_file(f, &opts) {
            with_shapes += usize::from(!d.shapes.is_empty());
            // Every shape is validated; its loops come out of the drawing.
            assert!(d.shapes.iter().all(|s| s.element_count() >= 2), "{}", f.display());
        }
    }
    assert!(files.len() > 1000, "{} DXF files", files.len());
    assert!(with_shapes >= 864, "{with_shapes} of {} files gave a shape", files.len());
}
