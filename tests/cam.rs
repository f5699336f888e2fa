//! The CAM layer against oracles that share nothing with it: rings nest
//! geometrically as the tree says, the uncut area is exactly the set of
//! points farther than the tool radius from every ring (brute-force
//! distances to the ring elements), and V-carve depths are the distance to
//! the wall over tan(α/2).

mod common;

use common::{rect, shape, v};
use medax::cam::{pocket, vcarve, CamError, PocketOptions, PocketOrder, UncutKind, VCarveOptions};
use medax::kernel::{FilteredKernel, Point};
use medax::plane::{medial_axis, AxisOptions, OffsetOptions, Offsets};
use medax::shape::{Element, Loop, Shape2d, ShapeOptions, Vertex};
use rand::{Rng, SeedableRng};

fn winding(loops: &[Vec<Vertex>], p: Point) -> i32 {
    loops.iter().map(|l| Loop::new(l.clone()).winding_number(&FilteredKernel, p)).sum()
}

fn dumbbell() -> Shape2d {
    // Two 4 × 4 bulbs joined by a neck 0.8 wide: narrower than a tool of
    // radius 1.
    shape(vec![common::poly(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 1.6),
        (6.0, 1.6),
        (6.0, 0.0),
        (10.0, 0.0),
        (10.0, 4.0),
        (6.0, 4.0),
        (6.0, 2.4),
        (4.0, 2.4),
        (4.0, 4.0),
        (0.0, 4.0),
    ])])
}

fn plate() -> Shape2d {
    shape(vec![rect(0.0, 0.0, 12.0, 8.0), common::circle(4.0, 4.0, 1.5), common::circle(9.0, 4.0, 1.0)])
}

fn demo() -> Shape2d {
    Shape2d::from_file("src/cli/demo_shape.json", &ShapeOptions::default()).unwrap()
}

fn cases() -> Vec<(&'static str, Shape2d, f64, f64)> {
    let mut out = Vec::new();
    for (r, s) in [(1.0, 0.8), (1.0, 1.5), (0.7, 1.3)] {
        out.push(("square", shape(vec![rect(0.0, 0.0, 10.0, 10.0)]), r, s));
        out.push(("dumbbell", dumbbell(), r, s));
        out.push(("plate", plate(), 0.5 * r, 0.5 * s));
        out.push(("demo", demo(), 3.0 * r, 3.0 * s));
    }
    out
}

#[test]
fn rings_are_the_offsets_at_r_plus_k_s_and_nest_as_the_tree_says() {
    let k = FilteredKernel;
    for (name, s, r, step) in cases() {
        let off = Offsets::new(&s, &OffsetOptions::default()).unwrap();
        let p = pocket(&off, &PocketOptions::new(r, step)).unwrap();
        let levels = p.rings.iter().map(|g| g.level).max().map_or(0, |m| m + 1);
        assert!(levels > 0, "{name}");
        for lvl in 0..levels {
            let d = r + lvl as f64 * step;
            let layer = off.layer(d).unwrap();
            let here: Vec<_> = p.rings.iter().filter(|g| g.level == lvl).collect();
            assert_eq!(here.len(), layer.regions.len(), "{name} level {lvl}");
            let ring_area: f64 = here.iter().flat_map(|g| &g.loops).map(|l| l.area).sum();
            assert!((ring_area - layer.area()).abs() <= 1e-9 * layer.area().abs().max(1.0), "{name} level {lvl}");
            for g in &here {
                assert_eq!(g.distance, d);
                assert!(g.loops[0].area > 0.0 && g.loops[1..].iter().all(|l| l.area < 0.0), "{name}: outer loop first");
            }
        }
        // Nothing is left one level further.
        assert!(off.layer(r + levels as f64 * step).unwrap().is_empty(), "{name}: rings stop early");
        for (i, g) in p.rings.iter().enumerate() {
            match g.parent {
                None => assert_eq!(g.level, 0),
                Some(q) => {
                    let parent = &p.rings[q];
                    assert_eq!(parent.level + 1, g.level);
                    assert!(parent.children.contains(&i));
                    // A point of the child lies inside the parent's region,
                    // and in no other ring of that level.
                    let x = g.loops[0].vertices[0].p;
                    for (j, other) in p.rings.iter().enumerate().filter(|(_, o)| o.level == parent.level) {
                        let loops: Vec<Vec<Vertex>> = other.loops.iter().map(|l| l.vertices.clone()).collect();
                        let inside = loops.iter().map(|l| Loop::new(l.clone()).winding_number(&k, x)).sum::<i32>() != 0;
                        assert_eq!(inside, j == q, "{name}: ring {i} nests in ring {q}, found in {j}");
                    }
                }
            }
        }
        // Inside-out: children before their parent; outside-in: after.
        let mut order = p.order.clone();
        order.sort();
        assert_eq!(order, (0..p.rings.len()).collect::<Vec<_>>(), "{name}: order is a permutation");
        let at = |order: &[usize]| {
            let mut pos = vec![0; order.len()];
            for (n, &i) in order.iter().enumerate() {
                pos[i] = n;
            }
            pos
        };
        let pos = at(&p.order);
        let out_in =
            pocket(&off, &PocketOptions { order: PocketOrder::OutsideIn, ..PocketOptions::new(r, step) }).unwrap();
        let pos_oi = at(&out_in.order);
        for (i, g) in p.rings.iter().enumerate() {
            if let Some(q) = g.parent {
                assert!(pos[i] < pos[q], "{name}: inside-out");
                assert!(pos_oi[i] > pos_oi[q], "{name}: outside-in");
            }
        }
    }
}

#[test]
fn uncut_area_is_what_no_ring_passes_within_the_tool_radius() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(5);
    for (name, s, r, step) in cases() {
        let off = Offsets::new(&s, &OffsetOptions::default()).unwrap();
        let p = pocket(&off, &PocketOptions::new(r, step)).unwrap();
        let elems: Vec<Element> = p
            .rings
            .iter()
            .flat_map(|g| &g.loops)
            .flat_map(|l| Loop::new(l.vertices.clone()).elements().collect::<Vec<_>>())
            .collect();
        let bb = s.bbox();
        let diag = bb.diagonal();
        let (mut uncut, mut checked) = (0, 0);
        for _ in 0..1500 {
            let q = Point::new(rng.gen_range(bb.min.x..bb.max.x), rng.gen_range(bb.min.y..bb.max.y));
            if !common::inside(&s, q) {
                continue;
            }
            let d = elems.iter().map(|e| e.closest_point(q).0).fold(f64::INFINITY, f64::min);
            if (d - r).abs() < 1e-7 * diag {
                continue;
            }
            let mine = p.uncut.iter().any(|u| winding(&u.loops, q) != 0);
            assert_eq!(mine, d > r, "{name} r={r} s={step}: {q:?} at distance {d} from the rings");
            checked += 1;
            uncut += usize::from(mine);
        }
        assert!(checked > 500, "{name}");
        // Every case leaves its corners, so the test sees both answers.
        assert!(uncut > 0 || p.uncut.iter().all(|u| u.area < 1e-3 * diag * diag), "{name}");
        for u in &p.uncut {
            assert!(u.area > 0.0, "{name}: an uncut region has positive area");
        }
    }
}

#[test]
fn a_neck_narrower_than_the_tool_stays_uncut_and_splits_the_rings() {
    let s = dumbbell();
    let off = Offsets::new(&s, &OffsetOptions::default()).unwrap();
    let p = pocket(&off, &PocketOptions::new(1.0, 0.8)).unwrap();
    assert_eq!(p.rings.iter().filter(|g| g.level == 0).count(), 2, "one ring per bulb");
    let neck = Point::new(5.0, 2.0);
    let holder: Vec<_> = p.uncut.iter().filter(|u| winding(&u.loops, neck) != 0).collect();
    assert_eq!(holder.len(), 1);
    assert_eq!(holder[0].kind, UncutKind::Wall);
    // With stepover below the tool radius nothing is left between rings.
    assert!(p.uncut.iter().all(|u| u.kind == UncutKind::Wall));
}

#[test]
fn square_corners_leave_exactly_the_tool_fillets() {
    let s = shape(vec![rect(0.0, 0.0, 10.0, 10.0)]);
    let off = Offsets::new(&s, &OffsetOptions::default()).unwrap();
    let r = 1.0;
    let p = pocket(&off, &PocketOptions::new(r, 0.9)).unwrap();
    let walls: Vec<_> = p.uncut.iter().filter(|u| u.kind == UncutKind::Wall).collect();
    assert_eq!(walls.len(), 4);
    let fillet = (1.0 - std::f64::consts::FRAC_PI_4) * r * r;
    for w in walls {
        assert!((w.area - fillet).abs() < 1e-12, "{}", w.area);
    }
}

#[test]
fn pocket_options_are_checked() {
    let s = shape(vec![rect(0.0, 0.0, 1.0, 1.0)]);
    let off = Offsets::new(&s, &OffsetOptions::default()).unwrap();
    for (r, step) in [(0.0, 0.1), (-1.0, 0.1), (f64::NAN, 0.1), (0.1, 0.0), (0.1, f64::INFINITY)] {
        let e = pocket(&off, &PocketOptions::new(r, step)).unwrap_err();
        assert!(matches!(e, CamError::BadOption { .. }), "{e}");
    }
    // A tool too large for the pocket: no ring, the whole shape uncut.
    let p = pocket(&off, &PocketOptions::new(0.6, 0.1)).unwrap();
    assert!(p.rings.is_empty());
    let area: f64 = p.uncut.iter().map(|u| u.area).sum();
    assert!((area - 1.0).abs() < 1e-12, "{area}");
    // The level guard.
    let p = pocket(&off, &PocketOptions { max_levels: 2, ..PocketOptions::new(0.01, 0.01) }).unwrap();
    assert!(p.truncated && p.rings.len() == 2);
}

#[test]
fn vcarve_depth_is_the_wall_distance_over_the_half_angle_tangent() {
    for (name, s) in [("demo", demo()), ("plate", plate()), ("star", shape(vec![common::star(40, 3)]))] {
        let axis = medial_axis(&s, &AxisOptions::default()).unwrap();
        let diag = s.bbox().diagonal();
        let max_r = axis.nodes.iter().map(|n| n.radius).fold(0.0, f64::max);
        for (angle, cap) in [(60.0, 0.5), (90.0, 2.0), (30.0, 0.3)] {
            let slope = (0.5f64 * angle).to_radians().tan();
            let max_depth = cap * max_r / slope;
            let tol = 1e-4 * diag;
            let opts = VCarveOptions { angle_deg: angle, max_depth, tolerance: tol };
            let vc = vcarve(&s, &axis, &opts).unwrap();
            assert!((vc.flat_radius() - max_depth * slope).abs() <= 1e-12 * diag);
            let mut deepest: f64 = 0.0;
            for path in &vc.paths {
                assert!(path.points.len() >= 2);
                for &[x, y, depth] in &path.points {
                    let d = common::boundary_distance(&s, Point::new(x, y));
                    assert!((d - depth * slope).abs() <= tol + 1e-9 * diag, "{name}: depth {depth} at distance {d}");
                    assert!(depth <= max_depth * (1.0 + 1e-12));
                    deepest = deepest.max(depth);
                }
            }
            if cap < 1.0 {
                assert!((deepest - max_depth).abs() <= 1e-9 * max_depth, "{name}: paths reach the cap");
                assert!(!vc.flat.is_empty());
                for lp in &vc.flat.loops {
                    for vx in &lp.vertices {
                        let d = common::boundary_distance(&s, vx.p);
                        assert!((d - vc.flat_radius()).abs() <= 1e-9 * diag, "{name}: flat ring at {d}");
                    }
                }
            } else {
                assert!(vc.flat.is_empty());
            }
            // Every axis sample shallower than the cap lies on some path.
            for samples in axis.sampled(&s, tol) {
                for (c, r) in samples.into_iter().filter(|&(_, r)| r < vc.flat_radius() * (1.0 - 1e-9)) {
                    let near = vc.paths.iter().any(|p| {
                        p.points.windows(2).any(|w| {
                            let (a, b) = (Point::new(w[0][0], w[0][1]), Point::new(w[1][0], w[1][1]));
                            Element::Segment(medax::shape::Segment { a, b }).closest_point(c).0 <= 2.0 * tol
                        })
                    });
                    assert!(near, "{name}: axis point {c:?} (radius {r}) on no path");
                }
            }
        }
    }
}

#[test]
fn vcarve_options_are_checked() {
    let s = shape(vec![rect(0.0, 0.0, 1.0, 1.0)]);
    let axis = medial_axis(&s, &AxisOptions::default()).unwrap();
    for (a, d) in [(0.0, 1.0), (180.0, 1.0), (f64::NAN, 1.0), (60.0, 0.0), (60.0, -1.0)] {
        let e = vcarve(&s, &axis, &VCarveOptions { angle_deg: a, max_depth: d, tolerance: 0.0 }).unwrap_err();
        assert!(matches!(e, CamError::BadOption { .. }));
    }
    let vc = vcarve(&s, &axis, &VCarveOptions { angle_deg: 90.0, max_depth: f64::INFINITY, tolerance: 0.0 }).unwrap();
    assert!(vc.flat.is_empty() && !vc.paths.is_empty());
    let _ = v(0.0, 0.0, 0.0);
}
