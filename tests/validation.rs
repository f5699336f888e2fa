//! Every validation class with its exact typed error, and the absence of
//! false alarms on valid shapes, checked against independent oracles.

mod common;

use common::*;
use medax::kernel::Point;
use medax::shape::{Degeneracy, ElementRef, ElementSpec, Shape2d, ShapeError, ShapeOptions, MAX_COORDINATE};

fn build(loops: Vec<Vec<medax::shape::Vertex>>) -> Result<Shape2d, ShapeError> {
    Shape2d::from_bulge_loops(loops, &ShapeOptions::default())
}

fn at(loop_index: usize, element: usize) -> ElementRef {
    ElementRef { loop_index, element }
}

#[test]
fn empty_input() {
    assert_eq!(build(vec![]), Err(ShapeError::Empty));
}

#[test]
fn too_few_elements() {
    assert_eq!(
        build(vec![poly(&[(0.0, 0.0), (1.0, 0.0)])]),
        Err(ShapeError::TooFewElements { loop_index: 0, count: 2 })
    );
    assert_eq!(
        build(vec![rect(0.0, 0.0, 9.0, 9.0), vec![v(1.0, 1.0, 0.5)]]),
        Err(ShapeError::TooFewElements { loop_index: 1, count: 1 })
    );
    // Two arcs are enough: a circle.
    assert!(build(vec![circle(0.0, 0.0, 1.0)]).is_ok());
}

#[test]
fn non_finite_numbers_name_the_element() {
    let mut l = rect(0.0, 0.0, 1.0, 1.0);
    l[2].p.x = f64::NAN;
    assert_eq!(build(vec![l]), Err(ShapeError::NonFinite { at: at(0, 2) }));
    let mut l = rect(0.0, 0.0, 1.0, 1.0);
    l[3].bulge = f64::INFINITY;
    assert_eq!(build(vec![rect(-5.0, -5.0, 5.0, 5.0), l]), Err(ShapeError::NonFinite { at: at(1, 3) }));
}

#[test]
fn coordinates_out_of_range() {
    let l = rect(0.0, 0.0, 2e9, 1.0);
    assert_eq!(build(vec![l]), Err(ShapeError::OutOfRange { at: at(0, 1), value: 2e9 }));
    // Vertices in range, but a nearly full circle (huge bulge) reaches beyond.
    let l = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 1e12), v(1.0, 1.0, 0.0), v(0.0, 1.0, 0.0)];
    match build(vec![l]) {
        Err(ShapeError::OutOfRange { at: a, value }) => {
            assert_eq!(a, at(0, 1));
            assert!(value.abs() > MAX_COORDINATE);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn zero_length_element() {
    let l = poly(&[(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (1.0, 1.0)]);
    assert_eq!(
        build(vec![l]),
        Err(ShapeError::Degenerate { at: at(0, 1), kind: Degeneracy::ZeroLength, position: Point::new(1.0, 0.0) })
    );
}

#[test]
fn a_repeated_closing_vertex_is_dropped() {
    let l = poly(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 0.0)]);
    assert_eq!(build(vec![l]).unwrap().outer().len(), 3);
}

#[test]
fn cusp_is_degenerate() {
    // A spike: out along the x axis and straight back.
    let l = poly(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (3.0, 1.0), (0.0, 1.0)]);
    match build(vec![l]) {
        Err(ShapeError::Degenerate { at: a, kind: Degeneracy::Cusp, position }) => {
            assert_eq!(a, at(0, 3));
            assert_eq!(position, Point::new(1.0, 1.0));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn zero_area_loop() {
    // Three collinear points: every element non-degenerate, no cusp at the
    // middle vertex, but the ends turn back: a cusp or zero area, never valid.
    let l = poly(&[(0.0, 0.0), (1.0, 0.0), (2.0, 1e-13)]);
    match build(vec![l]) {
        Err(ShapeError::Degenerate { kind: Degeneracy::ZeroArea | Degeneracy::Cusp, .. }) => {}
        other => panic!("{other:?}"),
    }
}

#[test]
fn bow_tie_names_both_edges() {
    let l = poly(&[(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)]);
    match build(vec![l]) {
        Err(ShapeError::Intersection { first, second, position }) => {
            assert_eq!((first, second), (at(0, 0), at(0, 2)));
            assert!(position.dist(Point::new(1.0, 1.0)) < 1e-12);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn touching_vertices_and_near_touches() {
    // Figure eight: two squares sharing the vertex (1, 1).
    let l = poly(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0), (1.0, 1.0), (0.0, 1.0)]);
    assert!(matches!(build(vec![l]), Err(ShapeError::Intersection { .. })));
    // A notch whose tip comes within 1e-12 of the opposite side.
    let tip = 1e-12;
    let l = poly(&[(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.5, 2.0), (2.0, tip), (1.5, 2.0), (0.0, 2.0)]);
    match build(vec![l]) {
        Err(ShapeError::Intersection { first, second, .. }) => assert_eq!((first, second), (at(0, 0), at(0, 3))),
        other => panic!("{other:?}"),
    }
    // The same notch 1e-3 away is fine.
    let l = poly(&[(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.5, 2.0), (2.0, 1e-3), (1.5, 2.0), (0.0, 2.0)]);
    assert!(build(vec![l]).is_ok());
}

#[test]
fn arcs_crossing_segments_and_arcs() {
    // Rectangle 4 × 1; elements: 0 bottom, 1 right, 2 top, 3 left.
    let mut l = rect(0.0, 0.0, 4.0, 1.0);
    l[1].bulge = -0.5; // right side bulges in by 0.25 and stays inside
    assert!(build(vec![l.clone()]).is_ok());
    // A full inward half circle would leave the corners tangentially backwards: cusps.
    let mut cusp = l.clone();
    cusp[1].bulge = -1.0;
    assert!(matches!(build(vec![cusp]), Err(ShapeError::Degenerate { kind: Degeneracy::Cusp, .. })));
    assert!(build(vec![l.clone()]).is_ok());
    l[1].bulge = 0.0;
    l[0].bulge = -0.9; // bottom bulges up by 1.8, through the top
    match build(vec![l]) {
        Err(ShapeError::Intersection { first, second, .. }) => assert_eq!((first, second), (at(0, 0), at(0, 2))),
        other => panic!("{other:?}"),
    }
    // A hole circle crossing the outer circle.
    assert!(matches!(
        build(vec![circle(0.0, 0.0, 10.0), circle(9.5, 0.0, 1.0)]),
        Err(ShapeError::Intersection { first, second, .. }) if first.loop_index == 0 && second.loop_index == 1
    ));
}

#[test]
fn holes_outside_nested_overlapping() {
    let outer = rect(0.0, 0.0, 10.0, 10.0);
    assert!(build(vec![outer.clone(), rect(1.0, 1.0, 2.0, 2.0)]).is_ok());
    assert!(matches!(
        build(vec![outer.clone(), rect(11.0, 1.0, 12.0, 2.0)]),
        Err(ShapeError::HoleOutside { hole: 1, .. })
    ));
    // The outer given as a hole of its hole.
    assert!(matches!(
        build(vec![rect(1.0, 1.0, 2.0, 2.0), outer.clone()]),
        Err(ShapeError::HoleOutside { hole: 1, .. })
    ));
    assert!(matches!(
        build(vec![outer.clone(), rect(1.0, 1.0, 8.0, 8.0), rect(2.0, 2.0, 3.0, 3.0)]),
        Err(ShapeError::HoleInsideHole { hole: 2, container: 1, .. })
    ));
    assert!(matches!(
        build(vec![outer.clone(), rect(1.0, 1.0, 5.0, 5.0), rect(4.0, 4.0, 6.0, 6.0)]),
        Err(ShapeError::Intersection { first, second, .. }) if first.loop_index == 1 && second.loop_index == 2
    ));
    // A hole touching the outer loop.
    assert!(matches!(
        build(vec![outer, rect(0.0, 1.0, 2.0, 2.0)]),
        Err(ShapeError::Intersection { first, second, .. }) if first.loop_index == 0 && second.loop_index == 1
    ));
}

#[test]
fn explicit_elements_must_close_and_arcs_must_be_consistent() {
    let p = Point::new;
    let ok = vec![
        ElementSpec::Segment { a: p(0.0, 0.0), b: p(2.0, 0.0) },
        ElementSpec::ArcPoints { a: p(2.0, 0.0), b: p(0.0, 0.0), center: p(1.0, 0.0), ccw: true },
    ];
    let s = Shape2d::from_elements(&[ok], &ShapeOptions::default()).unwrap();
    assert!((s.area() - std::f64::consts::PI / 2.0).abs() < 1e-12);
    let gap = vec![
        ElementSpec::Segment { a: p(0.0, 0.0), b: p(2.0, 0.0) },
        ElementSpec::Segment { a: p(2.0, 0.0), b: p(2.0, 2.0) },
        ElementSpec::Segment { a: p(2.0, 2.0), b: p(0.1, 0.0) },
    ];
    match Shape2d::from_elements(&[gap], &ShapeOptions::default()) {
        Err(ShapeError::NotClosed { at: a, position, .. }) => {
            assert_eq!(a, at(0, 2));
            assert_eq!(position, p(0.1, 0.0));
        }
        other => panic!("{other:?}"),
    }
    let off = vec![
        ElementSpec::Segment { a: p(0.0, 0.0), b: p(2.0, 0.0) },
        ElementSpec::ArcPoints { a: p(2.0, 0.0), b: p(0.0, 0.1), center: p(1.0, 0.0), ccw: true },
    ];
    assert!(matches!(
        Shape2d::from_elements(&[off], &ShapeOptions::default()),
        Err(ShapeError::InconsistentArc { at: a, .. }) if a == at(0, 1)
    ));
    let nan = vec![
        ElementSpec::Segment { a: p(0.0, 0.0), b: p(1.0, 0.0) },
        ElementSpec::Segment { a: p(1.0, 0.0), b: p(f64::NAN, 1.0) },
        ElementSpec::Segment { a: p(f64::NAN, 1.0), b: p(0.0, 0.0) },
    ];
    assert_eq!(Shape2d::from_elements(&[nan], &ShapeOptions::default()), Err(ShapeError::NonFinite { at: at(0, 1) }));
    // A full circle by angles becomes two half arcs.
    let full = vec![ElementSpec::ArcAngles { center: p(1.0, 1.0), radius: 2.0, start: 0.3, end: 0.3, ccw: false }];
    let s = Shape2d::from_elements(&[full], &ShapeOptions::default()).unwrap();
    assert_eq!(s.outer().len(), 2);
    assert!((s.area() - 4.0 * std::f64::consts::PI).abs() < 1e-12);
}

#[test]
fn invalid_options() {
    let o = ShapeOptions { tolerance: Some(-1.0), ..ShapeOptions::default() };
    assert!(matches!(
        Shape2d::from_bulge_loops(vec![rect(0.0, 0.0, 1.0, 1.0)], &o),
        Err(ShapeError::InvalidArgument { .. })
    ));
}

#[test]
fn parse_errors_carry_positions() {
    let o = ShapeOptions::default();
    match Shape2d::from_json_str("{\"loops\": [[[0,0],\n[1,0],\n[1,]]]}", &o) {
        Err(ShapeError::Parse(e)) => assert_eq!(e.line, 3),
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(Shape2d::from_dxf_str("0\nSECTION\nabc\nENTITIES\n", &o), Err(ShapeError::Parse(e)) if e.line == 3)
    );
    assert!(matches!(
        Shape2d::from_svg_str("M 0 0 L 1 0 C 1 1 2 2 3 3 Z", &o),
        Err(ShapeError::Parse(e)) if e.unsupported && e.column == 12
    ));
    assert!(matches!(Shape2d::from_svg_str("M 0 0 L 4 0 A 2 1 0 0 1 0 0 Z", &o), Err(ShapeError::Unsupported { .. })));
}

#[test]
fn random_polygons_agree_with_brute_force_oracle() {
    // Stars are simple; swapping two vertices usually makes them cross. The
    // O(n²) oracle decides which, with its own predicate.
    let mut checked = [0usize; 2];
    for seed in 0..400u64 {
        let n = 5 + (seed % 40) as usize;
        let mut p = star(n, seed);
        if seed % 2 == 1 {
            let (i, j) = ((seed as usize * 7) % p.len(), (seed as usize * 13 + 3) % p.len());
            p.swap(i, j);
        }
        let expect_bad = polygon_self_intersects(&p);
        let got = build(vec![p.clone()]);
        match (&got, expect_bad) {
            (Ok(_), false) | (Err(ShapeError::Intersection { .. }), true) => checked[expect_bad as usize] += 1,
            // A swap can also create a zero-length element or a cusp; the
            // oracle sees those as touching edges too.
            (Err(ShapeError::Degenerate { .. }), true) => checked[1] += 1,
            _ => panic!("seed {seed}: oracle says intersecting = {expect_bad}, medax says {got:?}"),
        }
    }
    assert!(checked[0] > 150 && checked[1] > 100, "{checked:?}");
}

#[test]
fn metamorphic_start_vertex_reversal_translation_scale() {
    let base = vec![
        v(0.0, 0.0, 0.0),
        v(3.0, 0.0, 0.4),
        v(4.0, 2.0, 0.0),
        v(2.0, 2.5, -0.3),
        v(0.5, 3.0, 0.0),
        v(-1.0, 1.5, 0.2),
    ];
    let reference = build(vec![base.clone(), circle(1.5, 1.2, 0.4)]).unwrap();
    let (area, joints) = (reference.area(), reference.joint_counts());
    let check = |loops: Vec<Vec<medax::shape::Vertex>>, scale: f64, what: &str| {
        let s = build(loops).unwrap_or_else(|e| panic!("{what}: {e}"));
        assert!((s.area() / (scale * scale) - area).abs() <= 1e-9 * area, "{what}: area {} vs {area}", s.area());
        assert_eq!(s.joint_counts(), joints, "{what}");
    };
    for k in 0..base.len() {
        let mut r = base.clone();
        r.rotate_left(k);
        check(vec![r, circle(1.5, 1.2, 0.4)], 1.0, "rotated start");
    }
    let rev = medax::shape::Loop::new(base.clone()).reversed().vertices().to_vec();
    check(vec![rev, circle(1.5, 1.2, 0.4)], 1.0, "reversed");
    for (dx, s) in [(1e6, 1.0), (0.0, 1e-3), (0.0, 1e3), (-1e6, 1e3)] {
        let tf = |l: &[medax::shape::Vertex]| {
            l.iter().map(|w| v(w.p.x * s + dx, w.p.y * s - dx, w.bulge)).collect::<Vec<_>>()
        };
        check(vec![tf(&base), tf(&circle(1.5, 1.2, 0.4))], s, &format!("translate {dx} scale {s}"));
    }
}

#[test]
fn joint_classes_of_the_demo_like_plate() {
    // Square with a reflex notch: convex corners, one reflex corner.
    let l = poly(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 2.0), (0.0, 4.0)]);
    let s = build(vec![l]).unwrap();
    assert_eq!(s.joint_counts(), [0, 4, 1]);
    assert_eq!(s.joint(0, 3), medax::shape::JointKind::Reflex);
    // Tangent arcs: a stadium has only smooth joints.
    let stadium = vec![v(0.0, 0.0, 0.0), v(4.0, 0.0, 1.0), v(4.0, 2.0, 0.0), v(0.0, 2.0, 1.0)];
    assert_eq!(build(vec![stadium]).unwrap().joint_counts(), [4, 0, 0]);
}

#[test]
fn nearly_flat_arcs_become_segments() {
    let l = vec![v(0.0, 0.0, 1e-14), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(0.0, 1.0, 0.0)];
    let s = build(vec![l]).unwrap();
    assert_eq!(s.flattened_arcs(), 1);
    assert_eq!(s.element_counts(), (4, 0));
}

/// Inputs found by the fuzz targets, kept as regressions.
mod fuzz_regressions {
    use super::*;

    #[test]
    fn hole_vertex_on_the_chord_of_an_outer_arc_is_inside() {
        // fuzz/json: the hole's first vertex after normalisation, (2, 1),
        // lies exactly on the chord of the outward arc from (0,0) to (4,2).
        let text = r#"{"loops": [[[0,0,0.4],[4,2],[2,6,-0],[0,3]], [[1,1,1],[2,1,1]]]}"#;
        let s = Shape2d::from_json_str(text, &ShapeOptions::default()).unwrap();
        let again = Shape2d::from_json_str(&s.to_json(), &ShapeOptions::default()).unwrap();
        assert_eq!(again.loops(), s.loops());
        let l = vec![v(2.0, 1.0, 1.0), v(1.0, 1.0, 1.0)];
        // Without the outward arc, (2, 1) lies on the outer edge: touching.
        assert!(matches!(
            build(vec![poly(&[(0.0, 0.0), (4.0, 2.0), (2.0, 6.0), (0.0, 3.0)]), l.clone()]),
            Err(ShapeError::Intersection { first, second, .. }) if first.loop_index == 0 && second.loop_index == 1
        ));
        let mut outer = poly(&[(0.0, 0.0), (4.0, 2.0), (2.0, 6.0), (0.0, 3.0)]);
        outer[0].bulge = 0.4;
        assert!(build(vec![outer, l]).is_ok());
    }

    #[test]
    fn json_round_trip_is_bit_exact_for_awkward_bulges() {
        // fuzz/dxf, fuzz/svg: 0.9999999999999999 came back as 1.0 with the
        // default (approximate) float parser.
        let l = vec![v(0.0, 0.0, 0.0), v(4.0, 0.0, 0.9999999999999999), v(4.0, 4.0, 0.0), v(0.0, 4.0, 0.0)];
        let s = build(vec![l]).unwrap();
        let again = Shape2d::from_json_str(&s.to_json(), &ShapeOptions::default()).unwrap();
        assert_eq!(again.loops(), s.loops());
    }

    #[test]
    fn huge_bulge_on_a_tiny_chord_is_out_of_range() {
        // fuzz/bulge: radius ~ chord·bulge/4 overflowed and gave a NaN centre.
        let l = vec![v(1.66e-26, 3.8e-27, -5.0e307), v(1.9e-27, -6.2e-27, -2.6e-69), v(-2.6e-27, 1.5e-27, 0.0)];
        assert!(matches!(build(vec![l]), Err(ShapeError::OutOfRange { .. })));
        // And a shape far below the smallest supported extent.
        let tiny = poly(&[(0.0, 0.0), (1e-120, 0.0), (0.0, 1e-120)]);
        assert!(matches!(build(vec![tiny]), Err(ShapeError::OutOfRange { at: a, .. }) if a == at(0, 0)));
    }
}

#[test]
fn dxf_circles_nested_as_holes_are_rejected() {
    // fuzz/dxf: the small hole's test point lies on the big hole's chord.
    let dxf = "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n1\n20\n0\n40\n5.0\n0\nCIRCLE\n10\n1\n20\n1\n40\n0.05\n0\nCIRCLE\n10\n1\n20\n1\n40\n0.5\n0\nENDSEC\n0\nEOF\n";
    assert!(matches!(
        Shape2d::from_dxf_str(dxf, &ShapeOptions::default()),
        Err(ShapeError::HoleInsideHole { hole: 1, container: 2, .. })
    ));
}

#[test]
fn arcs_with_huge_radii_become_segments() {
    // fuzz/json: an arc of radius 1.5e9 on a shape of size 100 hid a
    // crossing in one orientation (its centre-based distances lose ~1e-7).
    // Flattened, the crossing is found whichever way the loop runs.
    let l = vec![
        v(1.0, 0.0, 2.030706113e-8),
        v(100.0, 70.0, -2.0),
        v(40.0, 70.0, 0.0),
        v(15.0, 70.0, 0.0),
        v(15.0, 34.0, 1.0),
    ];
    let rev = medax::shape::Loop::new(l.clone()).reversed().vertices().to_vec();
    assert!(matches!(build(vec![l.clone()]), Err(ShapeError::Intersection { .. })));
    assert!(matches!(build(vec![rev]), Err(ShapeError::Intersection { .. })));
    // The same with radius 1e6 (kept as an arc): found only once circle
    // intersections were computed from the smaller circle.
    let mut l = l;
    l[0].bulge = 3.002030706113e-5;
    let rev = medax::shape::Loop::new(l.clone()).reversed().vertices().to_vec();
    assert!(matches!(build(vec![l]), Err(ShapeError::Intersection { .. })));
    assert!(matches!(build(vec![rev]), Err(ShapeError::Intersection { .. })));
    // A gently curved long arc (radius 1e4 on a shape of size ~100) stays an arc.
    let mut r = rect(0.0, 0.0, 100.0, 10.0);
    r[0].bulge = -(100.0f64 / 2e4).asin() / 2.0; // sweep = 2·asin(c/2r), bulge = tan(sweep/4)
    r[0].bulge = r[0].bulge.tan();
    let s = build(vec![r]).unwrap();
    assert_eq!(s.flattened_arcs(), 0);
}
