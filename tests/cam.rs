//! The CAM layer against oracles that share nothing with it (distances
//! and winding numbers of tests/common/offset_oracle.rs): rings nest
//! geometrically as the tree says, the uncut area is exactly the set of
//! points farther than the tool radius from every ring, and V-carve depths
//! are the distance to the wall over tan(α/2).

mod common;

use common::offset_oracle::{elems, loop_samples, Loops};
use common::{rect, shape, v};
use medax::cam::{pocket, vcarve, CamError, PocketOptions, PocketOrder, UncutKind, VCarveOptions};
use medax::kernel::Disk;
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions, OffsetLoop, OffsetOptions, Offsets};
use medax::shape::{Element, Shape2d, Vertex};
use rand::{Rng, SeedableRng};

fn winding(loops: &[Vec<Vertex>], p: Point) -> i32 {
    let ls: Vec<&[Vertex]> = loops.iter().map(Vec::as_slice).collect();
    Loops::new(&ls).winding(p)
}

/// The oracle's view of offset loops.
fn loops_of<'a>(ls: impl IntoIterator<Item = &'a OffsetLoop>) -> Loops {
    let vs: Vec<&[Vertex]> = ls.into_iter().map(|l| l.vertices.as_slice()).collect();
    Loops::new(&vs)
}

/// Two 4 × 4 bulbs joined by a neck 0.8 wide: narrower than a tool of
/// radius 1.
fn dumbbell() -> Shape2d {
    shape(vec![common::square_dumbbell(0.4)])
}

fn plate() -> Shape2d {
    shape(vec![rect(0.0, 0.0, 12.0, 8.0), common::circle(4.0, 4.0, 1.5), common::circle(9.0, 4.0, 1.0)])
}

fn demo() -> Shape2d {
    shape(common::demo_shape())
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
                        let inside = loops_of(&other.loops).winding(x) != 0;
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
        let (rings, wall) = (loops_of(p.rings.iter().flat_map(|g| &g.loops)), Loops::of_shape(&s));
        let bb = s.bbox();
        let diag = bb.diagonal();
        let uncut_at = |q: Point| p.uncut.iter().any(|u| winding(&u.loops, q) != 0);
        let check = |q: Point| -> Option<bool> {
            if wall.winding(q) == 0 {
                return None;
            }
            let d = rings.dist(q);
            if (d - r).abs() < 1e-7 * diag {
                return None;
            }
            assert_eq!(uncut_at(q), d > r, "{name} r={r} s={step}: {q:?} at distance {d} from the rings");
            Some(d > r)
        };
        let (mut uncut, mut checked) = (0, 0);
        for _ in 0..1500 {
            let q = Point::new(rng.gen_range(bb.min.x..bb.max.x), rng.gen_range(bb.min.y..bb.max.y));
            if let Some(u) = check(q) {
                checked += 1;
                uncut += usize::from(u);
            }
        }
        assert!(checked > 500 && uncut > 0, "{name}: {checked} points checked, {uncut} uncut");
        // Where uncut regions lie, whether or not any was reported (random
        // points rarely land in a small one): just beyond the tool's reach
        // round every corner of every ring (corner fillets, scallops between
        // rings, necks), along the medial axis (what the last ring leaves)
        // and just inside the wall.
        for g in &p.rings {
            for lp in &g.loops {
                let es = elems(&lp.vertices);
                for (k, e) in es.iter().enumerate() {
                    let next = &es[(k + 1) % es.len()];
                    if e.tangent(1.0).dot(next.tangent(0.0)) > 1.0 - 1e-9 {
                        continue;
                    }
                    for f in [1.0 + 1e-4, 1.05, 1.3] {
                        for a in 0..48 {
                            let t = a as f64 * std::f64::consts::TAU / 48.0;
                            check(next.a + Point::new(t.cos(), t.sin()) * (f * r));
                        }
                    }
                }
            }
        }
        let axis = medial_axis(&s, &AxisOptions::default()).unwrap();
        for Disk { center: q, .. } in axis.sampled(&s, 1e-4 * diag).into_iter().flatten() {
            check(q);
        }
        for lp in s.loops() {
            for (q, t) in loop_samples(lp.vertices(), 64) {
                check(q + Point::new(-t.y, t.x) * (1e-4 * diag));
            }
        }
        // Either side of every uncut loop, so that a small region left out
        // or added is seen too (random points rarely land in one).
        for u in &p.uncut {
            assert!(u.area > 0.0, "{name}: an uncut region has positive area");
            for lp in &u.loops {
                for (q, t) in loop_samples(lp, 2) {
                    let n = Point::new(-t.y, t.x) * (1e-6 * diag);
                    check(q + n);
                    check(q - n);
                }
            }
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
        let wall = Loops::of_shape(&s);
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
                    let d = wall.dist(Point::new(x, y));
                    // Points on the axis are exact; a path's end at the cap
                    // lies on the chord between samples.
                    let allow = if depth >= max_depth * (1.0 - 1e-12) { tol + 1e-9 * diag } else { 1e-9 * diag };
                    assert!((d - depth * slope).abs() <= allow, "{name}: depth {depth} at distance {d}");
                    assert!(depth <= max_depth * (1.0 + 1e-12));
                    deepest = deepest.max(depth);
                }
            }
            if cap < 1.0 {
                assert!((deepest - max_depth).abs() <= 1e-9 * max_depth, "{name}: paths reach the cap");
                assert!(!vc.flat.is_empty());
                for lp in &vc.flat.loops {
                    for (q, _) in loop_samples(&lp.vertices, 3) {
                        let d = wall.dist(q);
                        assert!((d - vc.flat_radius()).abs() <= 1e-9 * diag, "{name}: flat ring at {d}");
                    }
                }
            } else {
                assert!(vc.flat.is_empty());
            }
            // Every axis sample shallower than the cap lies on some path.
            for samples in axis.sampled(&s, tol) {
                for Disk { center: c, radius: r } in
                    samples.into_iter().filter(|d| d.radius < vc.flat_radius() * (1.0 - 1e-9))
                {
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

/// Pocket rings and the V-carve flat and paths of smooth biarc curves (with
/// and without holes; one where disks hug stretches of nearly concentric
/// arcs) lie at their distances from the wall at points along every arc,
/// not only at their ends.
#[test]
fn pockets_and_vcarve_of_smooth_curves_lie_at_their_distances() {
    let blob = {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/offset_gross_blob_1030.json");
        Shape2d::from_json_str(&std::fs::read_to_string(path).unwrap(), &medax::shape::ShapeOptions::default()).unwrap()
    };
    let cases = [
        ("fourier 800", shape(medax::shape::samples::fourier_biarcs(800, 71))),
        ("fourier 800 with 3 holes", shape(medax::shape::samples::fourier_with_holes(800, 3, 72))),
        ("blob 1030", blob),
    ];
    for (name, s) in cases {
        let diag = s.bbox().diagonal();
        let wall = Loops::of_shape(&s);
        let off = Offsets::new(&s, &OffsetOptions::default()).unwrap();
        let m = off.max_inner_distance();
        let p = pocket(&off, &PocketOptions::new(0.01 * m, 0.15 * m)).unwrap();
        let mut seen = 0;
        for g in &p.rings {
            for l in &g.loops {
                for (q, _) in loop_samples(&l.vertices, 5) {
                    let d = wall.dist(q);
                    assert!((d - g.distance).abs() <= 1e-9 * diag, "{name}: ring at {} has {q:?} at {d}", g.distance);
                    seen += 1;
                }
            }
        }
        assert!(p.rings.len() >= 6 && seen > 5000, "{name}: {} rings, {seen} points", p.rings.len());
        let axis = medial_axis(&s, &AxisOptions::default()).unwrap();
        let slope = 30f64.to_radians().tan();
        let max_depth = 0.5 * m / slope;
        let vc = vcarve(&s, &axis, &VCarveOptions { angle_deg: 60.0, max_depth, tolerance: 1e-4 * diag }).unwrap();
        assert!(!vc.flat.is_empty(), "{name}");
        for lp in &vc.flat.loops {
            for (q, _) in loop_samples(&lp.vertices, 5) {
                let d = wall.dist(q);
                assert!((d - vc.flat_radius()).abs() <= 1e-9 * diag, "{name}: flat ring point {q:?} at {d}");
            }
        }
        for path in &vc.paths {
            for &[x, y, depth] in &path.points {
                let d = wall.dist(Point::new(x, y));
                let allow = if depth >= max_depth * (1.0 - 1e-12) { 1e-4 * diag } else { 1e-9 * diag };
                assert!((d - depth * slope).abs() <= allow, "{name}: V-carve depth {depth} at distance {d}");
            }
        }
    }
}
