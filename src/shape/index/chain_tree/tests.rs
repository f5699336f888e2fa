//! Tests of the chain tree: every query against a scan of all elements.

use super::*;
use crate::shape::{samples, Shape2d, ShapeOptions};

#[test]
fn a_node_is_as_large_as_documented() {
    assert_eq!(std::mem::size_of::<Node>(), 144);
}

#[test]
fn first_contacts_agree_with_a_scan() {
    // Key: the radius at which the growing disk reaches an element's
    // start point, which lies in every box that holds the element.
    let mut rng = crate::util::mix::Mix(11);
    for (s, t) in fixtures() {
        let lp = &s.loops()[0];
        for _ in 0..300 {
            let e = lp.element((rng.next() * lp.len() as f64) as usize % lp.len());
            let p = e.point_at(0.5);
            let a = 2.0 * std::f64::consts::PI * rng.next();
            let g = GrowingDisk { p, n: Point::new(a.cos(), a.sin()) };
            let key = |r: ElementRef| g.through_point(lp.element(r.element).start()).filter(|&k| k > 1e-9);
            let slack = 1e-3;
            let got = t.first_contacts(&g, slack, key);
            let mut scan: Vec<(ElementRef, f64)> = (0..lp.len())
                .filter_map(|i| {
                    let r = ElementRef { loop_index: 0, element: i };
                    key(r).map(|k| (r, k))
                })
                .collect();
            let least = scan.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
            scan.retain(|x| x.1 <= least + slack);
            scan.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
            assert_eq!(got, scan, "{p:?} {a}");
        }
    }
}

#[test]
fn first_by_bound_agrees_with_a_scan_and_respects_its_cutoff() {
    // Key: the distance from a point to an element; bound: the run's
    // distance lower bound. Half the queries carry a cutoff below the
    // answer, where nothing may come back.
    let mut rng = crate::util::mix::Mix(12);
    for (s, t) in fixtures() {
        let lp = &s.loops()[0];
        for q in 0..300 {
            let (p, d) = probe(&s, &mut rng);
            let key = |r: ElementRef| Some(lp.element(r.element).closest_point(p).0);
            let cutoff = if q % 2 == 0 { f64::INFINITY } else { d * 0.999 };
            let slack = 1e-2 * d;
            let got = t.first_by_bound(cutoff, slack, |run, _| Some(run.distance_to(p)), key);
            let mut scan: Vec<(ElementRef, f64)> = (0..lp.len())
                .map(|i| ElementRef { loop_index: 0, element: i })
                .filter_map(|r| key(r).map(|k| (r, k)))
                .filter(|x| x.1 <= cutoff)
                .collect();
            let least = scan.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
            scan.retain(|x| x.1 <= least + slack);
            scan.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
            assert_eq!(got, scan, "{p:?} cutoff {cutoff}");
            assert_eq!(got.is_empty(), cutoff < d);
        }
    }
}

/// The test shapes (smooth arcs, spikes) with their trees.
fn fixtures() -> Vec<(Shape2d, ChainTree)> {
    [samples::flower_arcs(500), samples::star_polygon(300, 2)]
        .into_iter()
        .map(|loops| {
            let s = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
            let t = ChainTree::new(s.loops());
            (s, t)
        })
        .collect()
}

/// A random point in the shape's box and its distance to the boundary, by a scan.
fn probe(s: &Shape2d, rng: &mut crate::util::mix::Mix) -> (Point, f64) {
    let bb = s.bbox();
    let p = Point::new(bb.min.x + rng.next() * bb.width(), bb.min.y + rng.next() * bb.height());
    (p, s.loops()[0].elements().map(|e| e.closest_point(p).0).fold(f64::INFINITY, f64::min))
}

#[test]
fn closer_than_agrees_with_a_scan() {
    let mut rng = crate::util::mix::Mix(9);
    for (s, t) in fixtures() {
        let (mut hits, mut misses) = (0, 0);
        for _ in 0..2000 {
            let (p, scan) = probe(&s, &mut rng);
            // Radii just around the true distance, where pruning matters.
            let d = scan * (0.98 + 0.04 * rng.next());
            // Rejecting elements nearer than 0.99 d: only those between
            // count, and the search must go on past the others.
            let inner = 0.99 * d;
            let ring = s.loops()[0].elements().any(|e| (inner..d).contains(&e.closest_point(p).0));
            let found = t.closer_than(s.loops(), p, d, |e| e.closest_point(p).0 >= inner);
            assert_eq!(found.is_some(), ring, "{p:?} {d}");
            match t.closer_than(s.loops(), p, d, |_| true) {
                Some((r, e)) => {
                    assert!(scan < d && e < d, "{p:?} {d}");
                    assert_eq!(e, s.loops()[0].element(r.element).closest_point(p).0);
                    hits += 1;
                }
                None => {
                    assert!(scan >= d, "{p:?} {d}: missed an element at {scan}");
                    misses += 1;
                }
            }
        }
        assert!(hits > 100 && misses > 100, "{hits} {misses}");
    }
}

#[test]
fn any_closer_than_agrees_with_a_scan_per_disk() {
    // Groups of three disks near each other, each with a radius just
    // around its centre's true distance: the group is reported exactly
    // when a scan finds a disk holding an element, and the reported
    // disk does hold the reported element.
    let mut rng = crate::util::mix::Mix(17);
    for (s, t) in fixtures() {
        let (mut hits, mut misses) = (0, 0);
        for _ in 0..1000 {
            let (p, _) = probe(&s, &mut rng);
            let disks: Vec<(Point, f64)> = (0..3)
                .map(|_| {
                    let q = p + Point::new(rng.next() - 0.5, rng.next() - 0.5) * (0.01 * s.bbox().diagonal());
                    let scan = s.loops()[0].elements().map(|e| e.closest_point(q).0).fold(f64::INFINITY, f64::min);
                    (q, scan * (0.99 + 0.02 * rng.next()))
                })
                .collect();
            let scan = disks.iter().any(|&(q, d)| s.loops()[0].elements().any(|e| e.closest_point(q).0 < d));
            match t.any_closer_than(s.loops(), &disks, |_, _| true) {
                Some((k, r, e)) => {
                    assert!(scan && e < disks[k].1, "{disks:?}");
                    assert_eq!(e, s.loops()[0].element(r.element).closest_point(disks[k].0).0);
                    hits += 1;
                }
                None => {
                    assert!(!scan, "{disks:?}: missed an element");
                    misses += 1;
                }
            }
        }
        assert!(hits > 100 && misses > 50, "{hits} {misses}");
    }
}

#[test]
fn visit_within_sees_every_element_a_scan_finds() {
    let mut rng = crate::util::mix::Mix(5);
    for (s, t) in fixtures() {
        let mut seen = vec![false; s.loops()[0].len()];
        for _ in 0..500 {
            let (p, scan) = probe(&s, &mut rng);
            let d = scan * (1.0 + 0.2 * rng.next());
            seen.fill(false);
            let mut visits = 0;
            t.visit_within(p, d, |r| {
                seen[r.element] = true;
                visits += 1;
            });
            assert!(visits < s.loops()[0].len() || d > 0.1, "{p:?} {d}: no pruning");
            for (i, e) in s.loops()[0].elements().enumerate() {
                if e.closest_point(p).0 < d {
                    assert!(seen[i], "{p:?} {d}: element {i} missed");
                }
            }
        }
    }
}

#[test]
fn nearest_agrees_with_a_scan() {
    let mut rng = crate::util::mix::Mix(7);
    for (s, t) in fixtures() {
        for _ in 0..500 {
            let (p, scan) = probe(&s, &mut rng);
            let (_, d) = t.nearest(s.loops(), p).unwrap();
            assert_eq!(d, scan, "{p:?}");
        }
    }
}
