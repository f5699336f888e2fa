//! Cutting a subshape by a maximal disk (thesis 2.2.1, Figure 2.1): each
//! footpoint located on the chain that holds it (at a reflex vertex, the
//! chain whose part of the vertex's fan holds the disk's direction), and
//! the pieces between consecutive footpoints closed by an auxiliary arc
//! of the disk.

use crate::kernel::fan::{BoundSide, Fan, FanEnd};
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Point;
use crate::plane::medial::decompose::subshape::{chain_holds, BoundaryPos, CutIds, Piece, Slot, Subshape};
use crate::shape::{JointKind, Shape2d};

impl Subshape {
    /// Cuts this subshape by disk `disk` (centred at `center`) touching it
    /// at `feet` (positions on its chains, any order): one subshape per
    /// footpoint, each starting at a footpoint, in boundary order. `cuts`
    /// are the disks the auxiliary arcs refer to. `None` when a footpoint
    /// lies on none of the chains.
    pub fn split<C: CutIds + ?Sized>(
        &self,
        shape: &Shape2d,
        disk: usize,
        feet: &[BoundaryPos],
        center: Point,
        cuts: &C,
    ) -> Option<Vec<Subshape>> {
        let out = split_slots(&self.pieces, shape, disk, feet, center, cuts)?;
        Some(out.into_iter().map(|pieces| Subshape { pieces }).collect())
    }
}

/// The chain of `pieces` holding `p` and where along it, if any.
fn locate<P: Slot>(pieces: &[P], shape: &Shape2d, p: BoundaryPos) -> Option<(usize, (usize, f64))> {
    pieces.iter().enumerate().find_map(|(j, piece)| {
        let (from, to) = piece.chain()?;
        chain_holds(shape, from, to, p).map(|k| (j, k))
    })
}

/// The chain of `pieces` holding footpoint `p` of a disk centred at
/// `center` and where along it, with the position as that chain writes it.
///
/// At a reflex vertex a chain may hold only part of the vertex's fan
/// of normals (which turns clockwise from the incoming element's normal
/// to the outgoing one's): a chain ending at the vertex with an
/// auxiliary arc after it holds the fan up to that arc's disk, one
/// starting there after an auxiliary arc holds it from that disk on. A
/// disk touching the vertex belongs where its own direction lies; both
/// ways of writing the vertex (end of one element, start of the next)
/// are tried. A vertex can end one chain and start another of the same
/// subshape when an augmenting disk of a hole touches there (thesis
/// 2.3.1). `None` when no chain holds the footpoint.
fn locate_foot<P: Slot, C: CutIds + ?Sized>(
    pieces: &[P],
    shape: &Shape2d,
    p: BoundaryPos,
    center: Point,
    cuts: &C,
) -> Option<(usize, (usize, f64), BoundaryPos)> {
    let Some(w) = p.vertex(shape).filter(|&w| shape.joint(p.loop_index, w) == JointKind::Reflex) else {
        return locate(pieces, shape, p).map(|(j, k)| (j, k, p));
    };
    let q = shape.loops()[p.loop_index].vertices()[w].p;
    let m = (center - q).unit();
    let m_len = pieces.len();
    let dir = |j: usize| match pieces[j % m_len].piece()? {
        Piece::Aux { disk } => Some((cuts[disk].center - q).unit()),
        Piece::Chain { .. } => None,
    };
    // Directions within this much (radians) of a fan part's end are
    // that end.
    let fan_slack = Tolerance::fan_angle();
    let aux = |j: usize| match pieces[j % m_len].piece()? {
        Piece::Aux { disk } => Some(disk),
        Piece::Chain { .. } => None,
    };
    let point = shape.kind(p.loop_index) == crate::shape::LoopKind::Point;
    let holds = |j: usize, at: BoundaryPos| {
        let Some((from, to)) = pieces[j].chain() else { return false };
        if point {
            // A point's fan is a whole turn: its part between the arcs
            // before and after, clockwise, measured by angle (a whole
            // turn between the two arcs of one disk).
            let (Some(a), Some(b)) = (dir(j + m_len - 1), dir(j + 1)) else { return true };
            if aux(j + m_len - 1) == aux(j + 1) {
                return true;
            }
            return Fan::clockwise(a, b).contains(m, fan_slack);
        }
        // The part's ends: the arcs' disks where the chain starts or ends
        // at the vertex, else the normals of the chain's own elements.
        let start = if from == at { dir(j + m_len - 1) } else { None }.unwrap_or_else(|| normal_into(shape, at, q));
        let end = if to == at { dir(j + 1) } else { None }.unwrap_or_else(|| normal_out_of(shape, at, q));
        // The disk must lie on the part's side of the arcs it starts or
        // ends at (kernel::fan::Fan::bound_side handles the half turn).
        let part = Fan::clockwise(start, end);
        let beside = |d: Point, end: FanEnd| part.bound_side(d, end, m, fan_slack) == BoundSide::Within;
        let after_ok = to != at || dir(j + 1).is_none_or(|d| beside(d, FanEnd::End));
        let before_ok = from != at || dir(j + m_len - 1).is_none_or(|d| beside(d, FanEnd::Start));
        after_ok && before_ok
    };
    let reps = [Some(p), p.other_way(shape)];
    // Every chain holding either way of writing the vertex (one that
    // starts there first: chains meeting at the vertex both hold it),
    // the first whose part of the fan holds the disk. A single point
    // between two augmenting disks at one vertex shares its position
    // with the chain beyond them, so the first candidate is not enough.
    reps.into_iter()
        .flatten()
        .find_map(|r| every_location(pieces, shape, r).into_iter().find(|&(j, _)| holds(j, r)).map(|(j, k)| (j, k, r)))
}

/// The left normal, at vertex position `at` (point `q`), of the element
/// that arrives there: where a chain ending at `at` has its fan part start.
fn normal_into(shape: &Shape2d, at: BoundaryPos, q: Point) -> Point {
    let lp = &shape.loops()[at.loop_index];
    let e = if at.t == 0.0 { (at.element + lp.len() - 1) % lp.len() } else { at.element };
    lp.element(e).left_normal_at(q)
}

/// The left normal, at vertex position `at` (point `q`), of the element
/// that leaves there: where a chain starting at `at` has its fan part end.
fn normal_out_of(shape: &Shape2d, at: BoundaryPos, q: Point) -> Point {
    let lp = &shape.loops()[at.loop_index];
    let e = if at.t == 1.0 { (at.element + 1) % lp.len() } else { at.element };
    lp.element(e).left_normal_at(q)
}

/// Every chain of `pieces` holding `p` and where along it: those that
/// start exactly at `p` first, then the rest in piece order.
fn every_location<P: Slot>(pieces: &[P], shape: &Shape2d, p: BoundaryPos) -> Vec<(usize, (usize, f64))> {
    let chains = || pieces.iter().enumerate().filter_map(|(j, piece)| piece.chain().map(|c| (j, c)));
    let starts = chains().filter(|&(_, (from, _))| from == p).map(|(j, _)| (j, (0, p.t)));
    let holding = chains()
        .filter(|&(_, (from, _))| from != p)
        .filter_map(|(j, (from, to))| chain_holds(shape, from, to, p).map(|k| (j, k)));
    starts.chain(holding).collect()
}

/// [`Subshape::split`] on any piece list: stand-ins between footpoints are
/// copied like pieces.
pub(crate) fn split_slots<P: Slot, C: CutIds + ?Sized>(
    pieces: &[P],
    shape: &Shape2d,
    disk: usize,
    feet: &[BoundaryPos],
    center: Point,
    cuts: &C,
) -> Option<Vec<Vec<P>>> {
    let mut at: Vec<(usize, (usize, f64), BoundaryPos)> =
        feet.iter().map(|&f| locate_foot(pieces, shape, f, center, cuts)).collect::<Option<_>>()?;
    at.sort_by(|a, b| (a.0, a.1 .0).cmp(&(b.0, b.1 .0)).then(a.1 .1.total_cmp(&b.1 .1)));
    let m = pieces.len();
    let chain = |j: usize| pieces[j].chain().expect("footpoints are located on chains");
    let k = at.len();
    let mut out = Vec::with_capacity(k);
    for i in 0..k {
        let (j0, key0, f0) = at[i];
        let (j1, key1, f1) = at[(i + 1) % k];
        let mut part: Vec<P> = Vec::new();
        // Consecutive footpoints on one chain, in order: the subshape
        // runs along that chain only (with one footpoint it goes round).
        if j0 == j1 && key0 <= key1 && k > 1 {
            part.push(Piece::Chain { from: f0, to: f1 }.into());
        } else {
            part.push(Piece::Chain { from: f0, to: chain(j0).1 }.into());
            let mut j = (j0 + 1) % m;
            while j != j1 {
                part.push(pieces[j]);
                j = (j + 1) % m;
            }
            part.push(Piece::Chain { from: chain(j1).0, to: f1 }.into());
        }
        part.push(Piece::Aux { disk }.into());
        out.push(part);
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plane::medial::decompose::subshape::Cut;
    use crate::plane::DiskFinder;
    use crate::shape::{samples, Element, ElementRef, Loop, ShapeOptions, Vertex};
    use rand::{Rng, SeedableRng};

    fn area(v: Vec<Vertex>) -> f64 {
        Loop::new(v).signed_area()
    }

    /// Cuts shapes again and again with maximal disks grown from random
    /// points of random subshapes' chains, and checks what a cut must keep:
    /// every subshape closes up on the disk's circle, the areas add up (each
    /// of the k subshapes holds the whole disk), and the chains still cover
    /// the original boundary exactly once.
    #[test]
    fn cutting_keeps_area_and_boundary() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(4);
        let mut cuts_done = 0;
        for (si, loops) in
            [samples::flower_arcs(60), samples::star_polygon(40, 3), samples::flower_arcs(300)].into_iter().enumerate()
        {
            let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
            let finder = DiskFinder::new(&shape);
            let mut parts = vec![Subshape::whole_loop(&shape, 0)];
            let mut cuts: Vec<Cut> = Vec::new();
            let total = shape.area();
            let mut expected_extra = 0.0;
            for _ in 0..40 {
                let which = rng.gen_range(0..parts.len());
                let chains: Vec<(BoundaryPos, BoundaryPos)> = parts[which].chains().collect();
                if chains.is_empty() {
                    continue;
                }
                let (from, to) = chains[rng.gen_range(0..chains.len())];
                // A random inner point of the chain's first element.
                let hi = if to.element == from.element && to.t > from.t { to.t } else { 1.0 };
                if hi - from.t < 1e-6 {
                    continue;
                }
                let t = rng.gen_range(from.t..hi);
                let d = finder.max_disk(ElementRef { loop_index: 0, element: from.element }, t);
                if d.radius == 0.0 || d.leaf_arc || d.footpoints.len() < 2 {
                    continue;
                }
                let feet: Vec<BoundaryPos> = d
                    .footpoints
                    .iter()
                    .map(|f| {
                        let e = shape.loops()[0].element(f.element.element);
                        let t = if f.element.element == from.element && f.point == d.footpoints[0].point {
                            t
                        } else {
                            e.param_of(f.point)
                        };
                        BoundaryPos { loop_index: 0, element: f.element.element, t }
                    })
                    .collect();
                let disk = cuts.len();
                cuts.push(Cut { center: d.center, radius: d.radius });
                let Some(children) = parts[which].split(&shape, disk, &feet, d.center, &cuts) else {
                    cuts.pop();
                    continue;
                };
                assert_eq!(children.len(), feet.len());
                let parent_area = area(parts[which].to_vertices(&shape, &cuts));
                let child_areas: f64 = children.iter().map(|c| area(c.to_vertices(&shape, &cuts))).sum();
                let disk_area = std::f64::consts::PI * d.radius * d.radius;
                let want = parent_area + (feet.len() - 1) as f64 * disk_area;
                assert!(
                    (child_areas - want).abs() < 1e-9 * total.abs().max(1.0),
                    "shape {si}: {child_areas} vs {want}"
                );
                expected_extra += (feet.len() - 1) as f64 * disk_area;
                for c in &children {
                    // Each subshape's aux arc ends lie on the disk's circle.
                    let v = c.to_vertices(&shape, &cuts);
                    let last = v.last().unwrap();
                    assert!((last.p.dist(d.center) - d.radius).abs() < 1e-9, "shape {si}");
                }
                parts.splice(which..=which, children);
                cuts_done += 1;
            }
            let sum: f64 = parts.iter().map(|p| area(p.to_vertices(&shape, &cuts))).sum();
            assert!((sum - (total + expected_extra)).abs() < 1e-8 * (total + expected_extra), "shape {si}");
            // The chains cover the original boundary once: their lengths add up.
            let mut len = 0.0;
            for p in &parts {
                for piece in &p.pieces {
                    if let Piece::Chain { from, to } = *piece {
                        let chain = Subshape { pieces: vec![Piece::Chain { from, to }] };
                        let v = chain.to_vertices(&shape, &cuts);
                        for (k, x) in v.iter().enumerate() {
                            let next = if k + 1 < v.len() { v[k + 1].p } else { to.point(&shape) };
                            len += Element::from_bulge(x.p, next, x.bulge).length();
                        }
                    }
                }
            }
            let perimeter = shape.loops()[0].perimeter();
            assert!((len - perimeter).abs() < 1e-9 * perimeter, "shape {si}: {len} vs {perimeter}");
        }
        assert!(cuts_done > 60, "{cuts_done}");
    }

    /// A disk tangent to one side of a segment site at its end, met by the
    /// end's fan (a half turn) where an arc tangent to the other side
    /// starts a chain: the disk is opposite that arc, the cross product is
    /// 0, and the footpoint must still go to the part of the fan it lies
    /// in, however the end is written (4000 random segments broke down
    /// with a leaf holding the whole segment between two disks at its end).
    #[test]
    fn a_disk_opposite_an_arc_at_a_curve_end_goes_to_its_own_part() {
        let v = |x: f64, y: f64| Vertex { p: Point::new(x, y), bulge: 0.0 };
        let square = vec![v(-10.0, -10.0), v(10.0, -10.0), v(10.0, 10.0), v(-10.0, 10.0)];
        let shape =
            Shape2d::from_sites(vec![square], vec![vec![v(0.0, 0.0), v(1.0, 0.0)]], vec![], &ShapeOptions::default())
                .unwrap();
        let at = |l: usize, element: usize, t: f64| BoundaryPos { loop_index: l, element, t };
        // The end (0, 0): its fan turns clockwise from down (the way
        // back's normal) through left to up (the way out's normal).
        let cuts = [
            Cut { center: Point::new(0.0, 2.0), radius: 2.0 },
            Cut { center: Point::new(-1.0, -1.0), radius: 2f64.sqrt() },
            Cut { center: Point::new(0.0, -3.0), radius: 3.0 },
        ];
        // The way out starts after the arc of disk 0 (up, the fan's end);
        // the way back ends before the arc of disk 1 (down and left).
        let s = Subshape {
            pieces: vec![
                Piece::Aux { disk: 0 },
                Piece::Chain { from: at(1, 0, 0.0), to: at(1, 1, 1.0) },
                Piece::Aux { disk: 1 },
                Piece::Chain { from: at(0, 0, 0.2), to: at(0, 0, 0.8) },
            ],
        };
        // Disk 2 touches the end from straight below: the fan's start, in
        // the part between the way back and disk 1.
        for end in [at(1, 0, 0.0), at(1, 1, 1.0)] {
            let parts = s.split(&shape, 2, &[end, at(0, 0, 0.5)], cuts[2].center, &cuts[..]).unwrap();
            let single = Piece::Chain { from: at(1, 1, 1.0), to: at(1, 1, 1.0) };
            assert!(parts.iter().any(|p| p.pieces.contains(&single)), "{end:?}: {parts:?}");
            let whole = Piece::Chain { from: at(1, 0, 0.0), to: at(1, 1, 1.0) };
            let with_whole: Vec<_> = parts.iter().filter(|p| p.pieces.contains(&whole)).collect();
            assert!(with_whole.len() == 1 && !with_whole[0].pieces.contains(&Piece::Aux { disk: 1 }), "{parts:?}");
        }
    }
}
