//! Block references in DXF drawings: the entities of a BLOCK placed by
//! each INSERT, with rotation, scale, mirroring, arrays and nesting.

use medax::io::Format;
use medax::kernel::Point;
use medax::shape::{Drawing2d, DrawingOptions, IgnoredKind, Shape2d, ShapeOptions};

/// A block "TAB": a 4 × 2 plate from its base point (1, 1) with a round
/// end (an ARC of radius 1 centred at (5, 2)), on layer 0.
const TAB: &str = "0\nBLOCK\n8\n0\n2\nTAB\n10\n1\n20\n1\n\
0\nLINE\n8\n0\n10\n1\n20\n1\n11\n5\n21\n1\n\
0\nARC\n8\n0\n10\n5\n20\n2\n40\n1\n50\n270\n51\n90\n\
0\nLINE\n8\n0\n10\n5\n20\n3\n11\n1\n21\n3\n\
0\nLINE\n8\n0\n10\n1\n20\n3\n11\n1\n21\n1\n\
0\nENDBLK\n";

fn insert(name: &str, layer: &str, at: [f64; 2], scale: [f64; 2], rotation: f64) -> String {
    format!(
        "0\nINSERT\n8\n{layer}\n2\n{name}\n10\n{}\n20\n{}\n41\n{}\n42\n{}\n50\n{rotation}\n",
        at[0], at[1], scale[0], scale[1]
    )
}

fn read(blocks: &str, entities: &str) -> Drawing2d {
    let text =
        format!("0\nSECTION\n2\nBLOCKS\n{blocks}0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n");
    Drawing2d::from_str_as(&text, Format::Dxf, &ShapeOptions::default(), &DrawingOptions::default()).unwrap()
}

/// The tab's area: 4 × 2 and a half disk of radius 1.
fn tab_area(scale: f64) -> f64 {
    scale * scale * (8.0 + std::f64::consts::FRAC_PI_2)
}

fn bbox(s: &Shape2d) -> [f64; 4] {
    let b = s.bbox();
    [b.min.x, b.min.y, b.max.x, b.max.y]
}

fn close(a: [f64; 4], b: [f64; 4]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
}

#[test]
fn a_block_inserted_three_times_with_rotation_mirror_and_scale() {
    let entities = [
        insert("TAB", "PARTS", [0.0, 0.0], [1.0, 1.0], 0.0),
        insert("TAB", "PARTS", [20.0, 0.0], [1.0, 1.0], 90.0),
        insert("TAB", "PARTS", [40.0, 0.0], [-2.0, 2.0], 0.0),
    ]
    .concat();
    let d = read(TAB, &entities);
    assert!(d.ignored.is_empty(), "{:?}", d.ignored);
    assert_eq!(d.shapes.len(), 3);
    // Largest first: the scaled copy, then the two others.
    assert!((d.shapes[0].area() - tab_area(2.0)).abs() < 1e-9);
    assert!((d.shapes[1].area() - tab_area(1.0)).abs() < 1e-9);
    assert!((d.shapes[2].area() - tab_area(1.0)).abs() < 1e-9);
    let boxes: Vec<[f64; 4]> = d.shapes.iter().map(bbox).collect();
    // Mirrored and doubled: from x = 40 leftwards, the round end at the left.
    assert!(close(boxes[0], [40.0 - 10.0, 0.0, 40.0, 4.0]), "{boxes:?}");
    // As drawn, base point at the insertion point.
    assert!(boxes[1..].iter().any(|&b| close(b, [0.0, 0.0, 5.0, 2.0])), "{boxes:?}");
    // Turned a quarter: along +y from (20, 0), 2 wide to the left.
    assert!(boxes[1..].iter().any(|&b| close(b, [18.0, 0.0, 20.0, 5.0])), "{boxes:?}");
}

#[test]
fn nested_blocks_arrays_and_layer_zero() {
    // PAIR holds two tabs side by side; a MINSERT of PAIR: 2 columns × 3
    // rows, 20 and 10 apart: 12 tabs, on the MINSERT's layer.
    let pair = "0\nBLOCK\n8\n0\n2\nPAIR\n10\n0\n20\n0\n".to_string()
        + &insert("TAB", "0", [0.0, 0.0], [1.0, 1.0], 0.0)
        + &insert("TAB", "0", [8.0, 0.0], [1.0, 1.0], 0.0)
        + "0\nENDBLK\n";
    let minsert = "0\nMINSERT\n8\nCUT\n2\nPAIR\n10\n0\n20\n0\n70\n2\n71\n3\n44\n20\n45\n10\n";
    let d = read(&(TAB.to_string() + &pair), minsert);
    assert_eq!(d.shapes.len(), 12);
    assert!(d.shapes.iter().all(|s| (s.area() - tab_area(1.0)).abs() < 1e-9));
    let corner = |s: &Shape2d| Point::new(s.bbox().min.x, s.bbox().min.y);
    let mut corners: Vec<(i64, i64)> = d.shapes.iter().map(|s| (corner(s).x as i64, corner(s).y as i64)).collect();
    corners.sort_unstable();
    assert_eq!(corners[..4], [(0, 0), (0, 10), (0, 20), (8, 0)]);
    // Layer selection sees the placed curves on the MINSERT's layer.
    let text =
        format!("0\nSECTION\n2\nBLOCKS\n{TAB}{pair}0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{minsert}0\nENDSEC\n0\nEOF\n");
    let other = DrawingOptions { layers: vec!["OTHER".into()], ..DrawingOptions::default() };
    let none = Drawing2d::from_str_as(&text, Format::Dxf, &ShapeOptions::default(), &other).unwrap();
    assert!(none.shapes.is_empty());
    assert_eq!(none.ignored.iter().map(|i| i.kind).collect::<Vec<_>>(), [IgnoredKind::OtherLayer]);
    assert_eq!(none.ignored[0].layer, "CUT");
}

#[test]
fn missing_self_referencing_and_unevenly_scaled_blocks_are_reported() {
    let selfish = "0\nBLOCK\n8\n0\n2\nLOOP\n10\n0\n20\n0\n".to_string()
        + &insert("LOOP", "0", [1.0, 0.0], [1.0, 1.0], 0.0)
        + "0\nENDBLK\n";
    let entities = [
        insert("NOPE", "0", [0.0, 0.0], [1.0, 1.0], 0.0),
        insert("LOOP", "0", [0.0, 0.0], [1.0, 1.0], 0.0),
        // An uneven scale turns the arc into an ellipse: reported, and the
        // three lines left are an open chain.
        insert("TAB", "0", [0.0, 50.0], [2.0, 1.0], 0.0),
    ]
    .concat();
    let d = read(&(TAB.to_string() + &selfish), &entities);
    assert!(d.shapes.is_empty());
    let reasons: Vec<&str> =
        d.ignored.iter().filter(|i| i.kind == IgnoredKind::Entity).map(|i| i.reason.as_str()).collect();
    assert!(reasons.iter().any(|r| r.contains("NOPE") && r.contains("no such block")), "{reasons:?}");
    assert!(reasons.iter().any(|r| r.contains("LOOP") && r.contains("in itself")), "{reasons:?}");
    assert!(reasons.iter().any(|r| r.contains("ARC") && r.contains("unevenly")), "{reasons:?}");
    assert!(d.ignored.iter().any(|i| i.kind == IgnoredKind::OpenChain));
}

#[test]
fn a_huge_array_of_an_empty_block_ends() {
    let empty = "0\nBLOCK\n8\n0\n2\nNIL\n10\n0\n20\n0\n0\nENDBLK\n";
    let minsert = "0\nMINSERT\n8\n0\n2\nNIL\n10\n0\n20\n0\n70\n100000\n71\n100000\n44\n1\n45\n1\n";
    let d = read(empty, minsert);
    assert!(d.shapes.is_empty());
    assert_eq!(d.ignored.len(), 1);
    assert!(d.ignored[0].reason.contains("beyond"), "{}", d.ignored[0].reason);
}
