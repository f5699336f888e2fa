//! Shapes with holes as augmented domains (thesis 2.3.1).
//!
//! The medial axis of a shape with h holes has h independent cycles, and
//! the divide step needs a tree. Each hole gets one augmenting maximal
//! disk: the disk whose north pole is the hole's lowest point (tangent to
//! the horizontal line there, grown straight down). Its centre lies on the
//! cycle around the hole but on no self-edge (Lemma 1), so cutting the axis
//! at all of them leaves a tree. The disk's other contact lies lower than
//! the hole's lowest point, on the outer loop or on a hole whose own lowest
//! point is lower still: following holes to the loops their disks touch
//! always ends at the outer loop, so the loops and disks form a tree.
//!
//! The augmented domain's boundary is one cyclic sequence of pieces
//! (Figure 2.17): walking a loop, at each augmenting disk's contact the
//! walk leaves along the disk's circle (an auxiliary arc) to the loop on
//! the other side, goes round that loop, and comes back along the rest of
//! the circle. The divide step cuts this like any subshape (Lemma 4): the
//! auxiliary arcs only order the boundary pieces, and the maximal disks
//! are those of the shape. Both arcs of a disk refer to one cut, so the
//! conquer step glues the two sides of the axis back together at the
//! disk's centre, closing the hole's cycle.
//!
//! The thesis finds the disks with a plane sweep (Lemma 3); here each is
//! one growing-disk query on the shared element index.

use crate::kernel::direction::Heading;
use crate::kernel::fan::cw_angle;
use crate::kernel::Orientation;
use crate::kernel::{AxisKernel, Point};
use crate::plane::medial::decompose::subshape::{BoundaryPos, Cut, Piece, Subshape};
use crate::plane::medial::disk::maximal::{DiskFinder, MaxDisk};
use crate::shape::{Element, ElementRef, Shape2d};
use rayon::prelude::*;

/// Directions tried for "down", in turn, when some hole's augmenting disk
/// touches more than two places (symmetric inputs: a hole centred over a
/// corner). Any one direction used for every hole keeps the argument above.
const DOWNS: [f64; 8] = [0.0, 0.013_7, -0.029_3, 0.047_1, -0.061_9, 0.083_3, -0.101_7, 0.127_9];

/// The augmented domain of a shape with holes.
#[derive(Debug, Clone)]
pub struct Augmentation {
    /// The augmenting disks: `cuts[h - 1]` for hole `h` (loop index).
    pub cuts: Vec<Cut>,
    /// The single boundary cycle, auxiliary arcs referring to `cuts`.
    pub boundary: Subshape,
}

/// Why a shape with holes could not be augmented.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AugmentError {
    /// No direction gave hole `hole` (loop index) a disk with exactly one
    /// contact off the hole.
    NoDisk {
        /// Loop index of the hole.
        hole: usize,
    },
    /// The disks' contacts did not connect hole `hole` to the outer loop
    /// (only possible through rounding on nearly touching loops).
    Cycle {
        /// Loop index of the hole.
        hole: usize,
    },
}

/// Where an augmenting disk touches a loop.
#[derive(Debug, Clone, Copy)]
struct Contact {
    /// Position with `t` < 1 (a vertex is the start of its element).
    pos: BoundaryPos,
    /// The disk (index into the cuts).
    disk: usize,
    /// From the contact towards the disk's centre.
    dir: Point,
    /// The hole on the disk's other side; `None` for the hole's own contact.
    child: Option<usize>,
    /// Sorted before the hole's own contact and moved behind it: at the
    /// own contact's position, such a contact comes at the end of the walk
    /// round the loop, not at its start.
    wrapped: bool,
}

/// The augmented domain of `finder`'s shape. A shape without holes gives
/// its outer loop and no cuts.
pub fn augment<K: AxisKernel>(finder: &DiskFinder<K>) -> Result<Augmentation, AugmentError> {
    let shape = finder.shape();
    let holes = shape.loops().len() - 1;
    if holes == 0 {
        return Ok(Augmentation { cuts: Vec::new(), boundary: Subshape::whole_loop(shape, 0) });
    }
    let mut last = AugmentError::NoDisk { hole: 1 };
    for &turn in &DOWNS {
        let down = Point::new(turn.sin(), -turn.cos());
        match disks(finder, down) {
            Ok(found) => return Ok(build(finder.kernel(), shape, found)),
            Err(e) => last = e,
        }
    }
    Err(last)
}

/// The augmenting disk of every hole for direction `down`: (own contact,
/// other contact, disk). Fails on a disk with other than one contact off
/// its hole, and on contacts that do not lead every hole to the outer loop.
fn disks<K: AxisKernel>(finder: &DiskFinder<K>, down: Point) -> Result<Vec<(Contact, Contact, Cut)>, AugmentError> {
    let shape = finder.shape();
    let holes = shape.loops().len() - 1;
    // One growing-disk query per hole, each on its own: in parallel (a
    // plate of 9·10^4 holes spent half a second here on one thread). The
    // first hole that fails is reported, as the sequential loop did.
    let found: Vec<Result<(Contact, Contact, Cut), AugmentError>> =
        (1..=holes).into_par_iter().map(|hole| hole_disk(finder, hole, down)).collect();
    let out: Vec<(Contact, Contact, Cut)> = found.into_iter().collect::<Result<_, _>>()?;
    // Every hole's chain of parents reaches the outer loop. Loops known to
    // reach it end a walk early, so each loop is walked over once.
    let parent: Vec<usize> = out.iter().map(|(_, far, _)| far.pos.loop_index).collect();
    let mut reaches = vec![false; holes + 1];
    reaches[0] = true;
    let mut path = Vec::new();
    for hole in 1..=holes {
        path.clear();
        let mut l = hole;
        while !reaches[l] {
            if path.len() > holes {
                return Err(AugmentError::Cycle { hole });
            }
            path.push(l);
            l = parent[l - 1];
        }
        for &p in &path {
            reaches[p] = true;
        }
    }
    Ok(out)
}

/// The augmenting disk of loop `hole` for direction `down`: (own contact,
/// other contact, disk), or why it has none.
fn hole_disk<K: AxisKernel>(
    finder: &DiskFinder<K>,
    hole: usize,
    down: Point,
) -> Result<(Contact, Contact, Cut), AugmentError> {
    let shape = finder.shape();
    let (pos, n) = lowest_point(finder.kernel(), shape, hole, down);
    let at = ElementRef { loop_index: hole, element: pos.element };
    let d: MaxDisk = finder.max_disk_toward(at, pos.t, n);
    let mut others = d.footpoints[1..].iter();
    let (Some(f), None) = (others.next(), others.next()) else { return Err(AugmentError::NoDisk { hole }) };
    if f.element.loop_index == hole || !d.radius.is_finite() || d.radius <= shape.tolerance() {
        return Err(AugmentError::NoDisk { hole });
    }
    let other = snapped(shape, f.element, f.point);
    let disk = hole - 1;
    let own = Contact {
        pos: normalised(shape, pos),
        disk,
        dir: d.center - d.footpoints[0].point,
        child: None,
        wrapped: false,
    };
    let far = Contact { pos: other, disk, dir: d.center - f.point, child: Some(hole), wrapped: false };
    Ok((own, far, Cut { center: d.center, radius: d.radius }))
}

/// The position of contact point `q` on element `at`, at the vertex when
/// `q` lies within the tolerance of one that is not a convex corner (the
/// closest point of an element to a disk's centre lands a few ulps short
/// of a reflex vertex: the vertex's fan, not the element, is touched).
fn snapped(shape: &Shape2d, at: ElementRef, q: Point) -> BoundaryPos {
    let lp = &shape.loops()[at.loop_index];
    let e = lp.element(at.element);
    let tol = shape.tolerance();
    let pos = |t: f64| BoundaryPos { loop_index: at.loop_index, element: at.element, t };
    let not_convex = |v: usize| shape.joint(at.loop_index, v) != crate::shape::JointKind::Convex;
    if q.dist(e.start()) <= tol && not_convex(at.element) {
        return pos(0.0);
    }
    if q.dist(e.end()) <= tol && not_convex((at.element + 1) % lp.len()) {
        return normalised(shape, pos(1.0));
    }
    normalised(shape, pos(e.param_of(q)))
}

/// `p` with a position at an element's end written as the next element's start.
fn normalised(shape: &Shape2d, p: BoundaryPos) -> BoundaryPos {
    if p.t >= 1.0 {
        BoundaryPos { t: 1.0, ..p }.other_way(shape).unwrap_or(p)
    } else {
        BoundaryPos { t: p.t.max(0.0), ..p }
    }
}

/// The point of loop `hole` lowest in direction `down` and the direction
/// to grow its disk: the element's own normal inside an element (`down`
/// up to rounding), `down` itself at a vertex (inside the vertex's fan,
/// since both elements rise from the lowest point). Of equally low
/// points, one inside an element (the middle of a level segment) wins: its
/// disk's centre then lies inside an axis edge.
fn lowest_point(kern: &impl AxisKernel, shape: &Shape2d, hole: usize, down: Point) -> (BoundaryPos, Point) {
    let lp = &shape.loops()[hole];
    if lp.kind() == crate::shape::LoopKind::Point {
        // The disk's north pole is the point itself.
        return (BoundaryPos { loop_index: hole, element: 0, t: 0.0 }, down);
    }
    let depth = |p: Point| p.dot(down);
    let mut best: Option<(f64, bool, BoundaryPos)> = None;
    let mut offer = |h: f64, inner: bool, pos: BoundaryPos| {
        if best.is_none_or(|(bh, bi, _)| h > bh || (h == bh && inner && !bi)) {
            best = Some((h, inner, pos));
        }
    };
    // On a curve site every point is there twice, once per side: only the
    // side facing down (a reflex or smooth vertex, an element whose normal
    // points down) grows its disk downwards. A region hole's lowest point
    // always faces down.
    let curve = lp.kind() == crate::shape::LoopKind::Curve;
    let faces_down = |e: &Element| !curve || kern.heading(e.left_normal_at(e.point_at(0.5)), down) == Heading::Forward;
    for (k, e) in lp.elements().enumerate() {
        let pos = |t: f64| BoundaryPos { loop_index: hole, element: k, t };
        let joint = shape.joint(hole, k);
        let vertex_faces_down = joint == crate::shape::JointKind::Reflex
            || (joint == crate::shape::JointKind::Smooth
                && kern.heading(e.left_normal_at(e.start()), down) == Heading::Forward);
        if !curve || vertex_faces_down {
            offer(depth(e.start()), false, pos(0.0));
        }
        match e {
            Element::Segment(s) if kern.heading(s.b - s.a, down) == Heading::Sideways && faces_down(&e) => {
                offer(depth((s.a + s.b) * 0.5), true, pos(0.5))
            }
            Element::Segment(_) => {}
            Element::Arc(a) => {
                let q = a.center + down * a.radius;
                if a.spans_direction(q) && (!curve || !a.is_ccw()) {
                    let t = e.param_of(q);
                    if t > 0.0 && t < 1.0 {
                        offer(depth(e.point_at(t)), true, pos(t));
                    }
                }
            }
        }
    }
    let (_, inner, pos) = best.expect("validated loops have elements");
    let n = if inner { lp.element(pos.element).left_normal_at(pos.point(shape)) } else { down };
    (pos, n)
}

/// Contacts at one position in the order the boundary meets them: at a
/// reflex vertex the fan of normals turns clockwise from the incoming
/// element's normal to the outgoing one's, so a direction clockwise of
/// another comes later.
fn fan_before(k: &impl AxisKernel, a: Point, b: Point) -> bool {
    k.turn(a, b) == Orientation::Right
}

/// Builds the one boundary cycle from the disks (Figure 2.17).
fn build(k: &impl AxisKernel, shape: &Shape2d, found: Vec<(Contact, Contact, Cut)>) -> Augmentation {
    let loops = shape.loops().len();
    let mut on: Vec<Vec<Contact>> = vec![Vec::new(); loops];
    let mut cuts = Vec::with_capacity(found.len());
    for (own, far, cut) in found {
        on[own.pos.loop_index].push(own);
        on[far.pos.loop_index].push(far);
        cuts.push(cut);
    }
    // Each loop's contacts in travel order, a hole's starting at its own.
    // Round a point (a fan of a whole turn) the order is clockwise from the
    // point's own contact; a cross product orders only within half a turn.
    for (l, list) in on.iter_mut().enumerate() {
        if shape.kind(l) == crate::shape::LoopKind::Point {
            let own = list.iter().find(|c| c.child.is_none()).map(|c| c.dir).expect("every point has its own contact");
            list.sort_by(|a, b| {
                cw_angle(own, a.dir).total_cmp(&cw_angle(own, b.dir)).then(a.child.is_some().cmp(&b.child.is_some()))
            });
            continue;
        }
        list.sort_by(|a, b| {
            (a.pos.element, a.pos.t).partial_cmp(&(b.pos.element, b.pos.t)).unwrap_or(std::cmp::Ordering::Equal).then(
                if fan_before(k, a.dir, b.dir) {
                    std::cmp::Ordering::Less
                } else if fan_before(k, b.dir, a.dir) {
                    std::cmp::Ordering::Greater
                } else {
                    std::cmp::Ordering::Equal
                },
            )
        });
        if l > 0 {
            let own = list.iter().position(|c| c.child.is_none()).expect("every hole has its own contact");
            list.rotate_left(own);
            let len = list.len();
            for c in &mut list[len - own..] {
                c.wrapped = true;
            }
        }
    }
    let mut pieces = Vec::new();
    // Depth-first over the tree of loops. Each contact of a loop is two
    // steps: its excursion (out along the disk, round the loop beyond, back
    // along the disk; nothing for a hole's own contact, where the walk came
    // in) and the chain on to the next contact. Frames: (loop, next step,
    // disk to return along when the loop is done).
    let mut stack: Vec<(usize, usize, Option<usize>)> = vec![(0, 0, None)];
    while let Some(top) = stack.last_mut() {
        let (l, step, back) = *top;
        let list = &on[l];
        if step == 2 * list.len() {
            if let Some(disk) = back {
                pieces.push(Piece::Aux { disk });
            }
            stack.pop();
            continue;
        }
        top.1 += 1;
        let c = list[step / 2];
        if step % 2 == 1 {
            push_chain(shape, &mut pieces, list, step / 2);
        } else if let Some(child) = c.child {
            pieces.push(Piece::Aux { disk: c.disk });
            stack.push((child, 0, Some(c.disk)));
        }
    }
    Augmentation { cuts, boundary: Subshape { pieces } }
}

/// The chain from contact `k` of `list` (one loop's contacts in travel
/// order, starting with the first) to the next one, or back to the first
/// after the last. Contacts at the first one's position sit at both ends
/// of the list (before and after it in its fan): the chain from the last
/// of the leading ones to the first of the trailing ones (or back to the
/// start) is the whole loop; between two contacts at one position any
/// other chain is that single point.
fn push_chain(shape: &Shape2d, pieces: &mut Vec<Piece>, list: &[Contact], k: usize) {
    let first = list[0].pos;
    if shape.kind(first.loop_index) == crate::shape::LoopKind::Point {
        // Every chain of a point is the point.
        pieces.push(Piece::Chain { from: first, to: first });
        return;
    }
    // Leading: at the first position and not wrapped round (those sort
    // after the first contact in its vertex's fan); trailing: wrapped and
    // at the first position (before it in the fan).
    let lead = list.iter().take_while(|c| c.pos == first && !c.wrapped).count();
    let at_end = |i: usize| i >= lead && list[i..].iter().all(|c| c.pos == first && c.wrapped);
    // Where the chain starts and ends: Start / End mark the first
    // position reached at the start of the walk round the loop or at its end.
    let from = list[k].pos;
    let (to, to_end) = if k + 1 == list.len() { (first, true) } else { (list[k + 1].pos, at_end(k + 1)) };
    let from_start = k < lead;
    // A chain ending at a vertex ends on the element before it.
    let end_of = |p: BoundaryPos| if p.t == 0.0 { p.other_way(shape).unwrap_or(p) } else { p };
    if from_start && to_end {
        // The whole loop, from `from` round to itself.
        let vertex = BoundaryPos { element: from.element, t: 0.0, ..from };
        pieces.push(Piece::Chain { from, to: end_of(vertex) });
        if from.t > 0.0 {
            pieces.push(Piece::Chain { from: BoundaryPos { t: 0.0, ..from }, to: from });
        }
    } else if from == to {
        pieces.push(Piece::Chain { from, to: from });
    } else {
        pieces.push(Piece::Chain { from, to: end_of(to) });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{samples, Loop, ShapeOptions, Vertex};

    fn shape_of(loops: Vec<Vec<Vertex>>) -> Shape2d {
        Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap()
    }

    /// The boundary cycle is the outer loop, every hole (clockwise) and
    /// every augmenting circle once: its signed area is the shape's plus
    /// one disk per hole, and it has two auxiliary arcs per hole.
    fn check_boundary(shape: &Shape2d) -> Augmentation {
        let finder = DiskFinder::new(shape);
        let aug = augment(&finder).unwrap();
        let holes = shape.loops().len() - 1;
        assert_eq!(aug.cuts.len(), holes);
        let aux = aug.boundary.pieces.iter().filter(|p| matches!(p, Piece::Aux { .. })).count();
        assert_eq!(aux, 2 * holes);
        let disks: f64 = aug.cuts.iter().map(|c| std::f64::consts::PI * c.radius * c.radius).sum();
        let area = Loop::new(aug.boundary.to_vertices(shape, &aug.cuts)).signed_area();
        let want = shape.area() + disks;
        assert!((area - want).abs() <= 1e-9 * want, "{area} vs {want}");
        for c in &aug.cuts {
            // Each disk is maximal: empty, touching.
            let (_, d) = finder.nearest(c.center).unwrap();
            assert!((d - c.radius).abs() <= 1e-9, "{c:?} nearest at {d}");
        }
        aug
    }

    #[test]
    fn boundary_covers_every_loop_once() {
        for loops in [samples::random_holes(1, 1), samples::random_holes(4, 2), samples::perforated_plate(3)] {
            check_boundary(&shape_of(loops));
        }
        // No holes: the outer loop as it is.
        let s = shape_of(samples::star_polygon(20, 1));
        let aug = check_boundary(&s);
        assert_eq!(aug.boundary, Subshape::whole_loop(&s, 0));
    }

    #[test]
    fn the_cycle_writes_each_vertex_one_way() {
        let at = |loop_index, element, t| BoundaryPos { loop_index, element, t };
        let spike = shape_of(samples::spike_holes(true, false));
        let n = spike.loops()[0].len();
        // Contacts: an element's end is the next one's start, round the
        // loop's end too.
        assert_eq!(normalised(&spike, at(0, n - 1, 1.0)), at(0, 0, 0.0));
        assert_eq!(normalised(&spike, at(0, 2, 1.0)), at(0, 3, 0.0));
        assert_eq!(normalised(&spike, at(0, 2, 0.25)), at(0, 2, 0.25));
        // The spike's disks land on its apex, vertex 0: the chain coming
        // round to it ends on the loop's last element.
        let last = at(0, n - 1, 1.0);
        assert!(check_boundary(&spike)
            .boundary
            .pieces
            .iter()
            .any(|p| matches!(*p, Piece::Chain { to, .. } if to == last)));
        // Chains start at an element's start and end at an element's end,
        // so that a chain's ends name the elements it runs over.
        for s in [spike, shape_of(samples::spike_holes(false, true)), shape_of(samples::random_holes(4, 2))] {
            for p in &check_boundary(&s).boundary.pieces {
                if let Piece::Chain { from, to } = *p {
                    assert!(from == to || (from.t < 1.0 && to.t > 0.0), "{from:?} -> {to:?}");
                }
            }
        }
    }

    #[test]
    fn stacked_holes_hang_on_each_other() {
        // Each hole's disk touches the hole below: a chain of loops, with
        // each hole's walk nested inside the one below it.
        let sq = |y: f64| {
            vec![
                Vertex { p: Point::new(0.4, y), bulge: 0.0 },
                Vertex { p: Point::new(0.4, y + 0.5), bulge: 0.0 },
                Vertex { p: Point::new(0.6, y + 0.5), bulge: 0.0 },
                Vertex { p: Point::new(0.6, y), bulge: 0.0 },
            ]
        };
        let outer = vec![
            Vertex { p: Point::new(0.0, 0.0), bulge: 0.0 },
            Vertex { p: Point::new(1.0, 0.0), bulge: 0.0 },
            Vertex { p: Point::new(1.0, 4.0), bulge: 0.0 },
            Vertex { p: Point::new(0.0, 4.0), bulge: 0.0 },
        ];
        let s = shape_of(vec![outer, sq(0.2), sq(1.2), sq(2.2)]);
        let aug = check_boundary(&s);
        // Bottom segment midpoints: the disks sit straight below them.
        for (h, c) in aug.cuts.iter().enumerate() {
            assert!((c.center.x - 0.5).abs() < 1e-12, "{h}: {c:?}");
        }
        let loops: Vec<usize> = aug
            .boundary
            .pieces
            .iter()
            .filter_map(|p| match p {
                Piece::Chain { from, .. } => Some(from.loop_index),
                Piece::Aux { .. } => None,
            })
            .collect();
        // From the outer loop's one contact: 1, 2, 3 nested, back out, outer.
        let mut squeezed = loops.clone();
        squeezed.dedup();
        assert_eq!(squeezed, vec![1, 2, 3, 2, 1, 0], "{loops:?}");
    }

    #[test]
    fn a_disk_with_three_contacts_turns_the_direction() {
        // A hexagon with its bottom corner straight below a centred circle:
        // the straight-down disk touches both edges beside the corner.
        let hex: Vec<Vertex> = (0..6)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 6.0 - std::f64::consts::FRAC_PI_2;
                Vertex { p: Point::new(3.0 * t.cos(), 3.0 * t.sin()), bulge: 0.0 }
            })
            .collect();
        let hole =
            vec![Vertex { p: Point::new(1.0, 0.0), bulge: -1.0 }, Vertex { p: Point::new(-1.0, 0.0), bulge: -1.0 }];
        let s = shape_of(vec![hex, hole]);
        let finder = DiskFinder::new(&s);
        assert_eq!(disks(&finder, Point::new(0.0, -1.0)).err(), Some(AugmentError::NoDisk { hole: 1 }));
        let aug = check_boundary(&s);
        assert!(aug.cuts[0].center.x.abs() > 1e-3, "{:?}", aug.cuts[0]);
    }
}
