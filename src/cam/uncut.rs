//! The area a pocket leaves uncut, from the medial axis.
//!
//! A point x at distance d from the wall, whose footpoint's maximal disk has
//! radius R, is reached by the tool of radius r following ring k (the
//! boundary of Ω^ρ_k) exactly when it lies within r of the ring. Along the
//! normal the ring is at distance |d − ρ_k|, and where the ring does not
//! reach (R < ρ_k) its nearest point is one of its convex corners: the
//! disks of radius ρ_k centred on the axis where the radius is ρ_k. So:
//! * at the wall, the uncut area is the band of points whose maximal disk
//!   is smaller than the tool (corners, necks narrower than the tool),
//!   bounded by the wall and by arcs of radius r round the first ring's
//!   corners — the tool's own circles there, maximal disks of the shape;
//! * between rings k and k + 1 (only when the stepover exceeds r), the band
//!   {d > ρ_k + r, R < ρ_k+1}, less the tool's disks at ring k + 1's
//!   corners;
//! * inside the last ring, the offset at ρ_last + r.
//!
//! The bands come from the axis walk; only the disks are clipped off
//! geometrically, with the arrangement of the band's elements and the
//! circles, which is small (a band's loop and the corners next to it).

use super::{CamError, UncutKind, UncutRegion};
use crate::kernel::construct::{circle_circle, line_circle};
use crate::kernel::tolerance::Tolerance;
use crate::kernel::{BBox, FilteredKernel, Point};
use crate::plane::offset::trim::{BandPiece, Trimmer};
use crate::shape::{Element, Loop, Vertex};
use std::f64::consts::TAU;

/// A loop element in bulge form; `on_disk` is the disk whose circle it runs
/// along (its own tool circle), which must not clip it.
#[derive(Debug, Clone, Copy)]
struct Piece {
    a: Point,
    b: Point,
    bulge: f64,
    on_disk: Option<usize>,
}

impl Piece {
    fn element(&self) -> Element {
        Element::from_bulge(self.a, self.b, self.bulge)
    }
}

/// The uncut regions of the band (`lo`, `hi`) for a tool of radius `r`:
/// `arcs` says the band's turns are replaced by the tool's circle round the
/// corner (at the wall, where that circle is the corner's maximal disk);
/// otherwise the turns are straight and the disks are clipped off.
pub(crate) fn band_regions(
    trimmer: &Trimmer,
    lo: f64,
    hi: f64,
    r: f64,
    kind: UncutKind,
    tol: f64,
) -> Result<Vec<UncutRegion>, CamError> {
    let (band, _) = trimmer.band_loops(lo, hi)?;
    let arcs = kind == UncutKind::Wall;
    let mut disks: Vec<Point> = Vec::new();
    let mut loops: Vec<Vec<Piece>> = Vec::new();
    for (bl, _) in &band {
        let mut verts: Vec<(Point, f64, Option<usize>)> = Vec::new();
        for p in &bl.pieces {
            match *p {
                BandPiece::Run(run) => verts.push((run.start, run.prim.bulge(run.advance), None)),
                BandPiece::Turn { centre, from, to } => {
                    disks.push(centre);
                    if arcs {
                        // Clockwise round the disk: the disk is not uncut.
                        let (u, v) = (from - centre, to - centre);
                        let sweep = (-u.cross(v).atan2(u.dot(v))).rem_euclid(TAU);
                        verts.push((from, -(sweep / 4.0).tan(), Some(disks.len() - 1)));
                    } else {
                        verts.push((from, 0.0, None));
                        verts.push((centre, 0.0, None));
                    }
                }
            }
        }
        let n = verts.len();
        let pieces: Vec<Piece> = (0..n)
            .map(|i| Piece { a: verts[i].0, b: verts[(i + 1) % n].0, bulge: verts[i].1, on_disk: verts[i].2 })
            .filter(|p| p.a.dist(p.b) > tol || p.bulge.abs() > 1.0)
            .collect();
        if pieces.len() >= 2 {
            loops.push(pieces);
        }
    }
    let mut out_loops: Vec<Vec<Piece>> = Vec::new();
    for lp in loops {
        out_loops.extend(clip(lp, &disks, (lo, r), arcs, tol)?);
    }
    Ok(group(out_loops, kind))
}

/// The loop of the band above `lo` less the disks of radius `r` at `disks`.
fn clip(
    lp: Vec<Piece>,
    disks: &[Point],
    (lo, r): (f64, f64),
    own_arcs: bool,
    tol: f64,
) -> Result<Vec<Vec<Piece>>, CamError> {
    let bbox = lp.iter().fold(BBox::default(), |b, p| b.union(&p.element().bbox()));
    let rel: Vec<usize> = (0..disks.len()).filter(|&i| bbox.distance_to(disks[i]) < r).collect();
    // Cut points on each piece (fractions) and on each disk's circle (angles).
    let mut cuts: Vec<Vec<f64>> = vec![Vec::new(); lp.len()];
    let mut on_circle: Vec<Vec<f64>> = vec![Vec::new(); rel.len()];
    let angle = |c: Point, q: Point| (q.y - c.y).atan2(q.x - c.x);
    for (pi, p) in lp.iter().enumerate() {
        let el = p.element();
        for (ri, &d) in rel.iter().enumerate() {
            if p.on_disk == Some(d) {
                continue;
            }
            let hits: Vec<Point> = match el {
                Element::Segment(s) => line_circle(s.a, s.b - s.a, disks[d], r)
                    .into_iter()
                    .filter(|t| (0.0..=1.0).contains(t))
                    .map(|t| s.a + (s.b - s.a) * t)
                    .collect(),
                Element::Arc(a) => circle_circle(a.center, a.radius, disks[d], r)
                    .into_iter()
                    .filter(|&q| a.spans_direction(q))
                    .collect(),
            };
            for q in hits {
                cuts[pi].push(el.param_of(q));
                on_circle[ri].push(angle(disks[d], q));
            }
        }
    }
    for (ri, &d) in rel.iter().enumerate() {
        for (rj, &e) in rel.iter().enumerate() {
            if ri != rj {
                for q in circle_circle(disks[d], r, disks[e], r) {
                    on_circle[ri].push(angle(disks[d], q));
                }
            }
        }
    }
    let inside_other = |m: Point, own: Option<usize>| rel.iter().any(|&d| Some(d) != own && m.dist(disks[d]) < r - tol);
    if lp.iter().zip(&cuts).all(|(p, c)| c.is_empty() && !inside_other(p.element().point_at(0.5), p.on_disk)) {
        return Ok(vec![lp]);
    }
    let mut kept: Vec<Piece> = Vec::new();
    for (p, c) in lp.iter().zip(&mut cuts) {
        let el = p.element();
        c.push(0.0);
        c.push(1.0);
        c.sort_by(f64::total_cmp);
        let sweep = if p.bulge == 0.0 { 0.0 } else { 4.0 * p.bulge.atan() };
        for w in c.windows(2) {
            if w[1] - w[0] <= Tolerance::same_cut() {
                continue;
            }
            let (a, b) = (el.point_at(w[0]), el.point_at(w[1]));
            if inside_other(el.point_at(0.5 * (w[0] + w[1])), p.on_disk) {
                continue;
            }
            kept.push(Piece { a, b, bulge: (sweep * (w[1] - w[0]) / 4.0).tan(), on_disk: p.on_disk });
        }
    }
    // The disks' circles inside the loop and outside the other disks, run
    // clockwise (the disk is cut away).
    let region = Loop::new(lp.iter().map(|p| Vertex { p: p.a, bulge: p.bulge }).collect());
    let k = FilteredKernel;
    for (ri, &d) in rel.iter().enumerate() {
        if own_arcs && lp.iter().any(|p| p.on_disk == Some(d)) {
            continue;
        }
        let c = disks[d];
        let mut angs = std::mem::take(&mut on_circle[ri]);
        angs.sort_by(f64::total_cmp);
        let spans: Vec<(f64, f64)> = if angs.is_empty() {
            vec![(0.0, std::f64::consts::PI), (std::f64::consts::PI, TAU)]
        } else {
            (0..angs.len()).map(|i| (angs[i], if i + 1 < angs.len() { angs[i + 1] } else { angs[0] + TAU })).collect()
        };
        for (a0, a1) in spans {
            if (a1 - a0) * r <= tol {
                continue;
            }
            let mid = 0.5 * (a0 + a1);
            let m = c + Point::new(mid.cos(), mid.sin()) * r;
            if region.winding_number(&k, m) == 0 || inside_other(m, Some(d)) {
                continue;
            }
            let (pa, pb) = (c + Point::new(a1.cos(), a1.sin()) * r, c + Point::new(a0.cos(), a0.sin()) * r);
            kept.push(Piece { a: pa, b: pb, bulge: -((a1 - a0) / 4.0).tan(), on_disk: Some(d) });
        }
    }
    link(kept, lo, tol)
}

/// Closes pieces into loops, each end to the nearest unused start. The
/// pieces come mostly in loop order, so the next one is tried first and the
/// search over all of them is the exception (where a circle was inserted).
fn link(pieces: Vec<Piece>, lo: f64, tol: f64) -> Result<Vec<Vec<Piece>>, CamError> {
    let n = pieces.len();
    let close = Tolerance::new(tol).link_ends();
    let mut used = vec![false; n];
    let mut out = Vec::new();
    for s in 0..n {
        if used[s] {
            continue;
        }
        used[s] = true;
        let (mut lp, mut last) = (vec![pieces[s]], s);
        loop {
            let end = pieces[last].b;
            if lp.len() > 1 && end.dist(lp[0].a) <= close {
                break;
            }
            let next = if last + 1 < n && !used[last + 1] && pieces[last + 1].a.dist(end) <= close {
                Some(last + 1)
            } else {
                (0..n).filter(|&i| !used[i]).min_by(|&i, &j| pieces[i].a.dist(end).total_cmp(&pieces[j].a.dist(end)))
            };
            match next {
                Some(i) if pieces[i].a.dist(end) <= close => {
                    used[i] = true;
                    lp.push(pieces[i]);
                    last = i;
                }
                _ if end.dist(lp[0].a) <= close => break,
                _ => {
                    let what = "an uncut region's pieces do not close";
                    return Err(CamError::Offset(crate::plane::OffsetError::Topology { distance: lo, what }));
                }
            }
        }
        out.push(lp);
    }
    Ok(out)
}

/// Each counter-clockwise loop a region, with the clockwise loops inside
/// it as holes.
fn group(loops: Vec<Vec<Piece>>, kind: UncutKind) -> Vec<UncutRegion> {
    let k = FilteredKernel;
    let as_loop = |lp: &[Piece]| Loop::new(lp.iter().map(|p| Vertex { p: p.a, bulge: p.bulge }).collect());
    let all: Vec<(Loop, f64)> = loops
        .iter()
        .map(|lp| {
            let l = as_loop(lp);
            let a = l.signed_area();
            (l, a)
        })
        .collect();
    let mut regions: Vec<UncutRegion> = Vec::new();
    let mut outer_of = Vec::new();
    for (i, (l, a)) in all.iter().enumerate() {
        if *a > 0.0 {
            outer_of.push(i);
            regions.push(UncutRegion { kind, loops: vec![l.vertices().to_vec()], area: *a });
        }
    }
    for (l, a) in all.iter().filter(|(_, a)| *a < 0.0) {
        let p = l.vertices()[0].p;
        // The smallest outer loop around the hole.
        let host = outer_of
            .iter()
            .enumerate()
            .filter(|(_, &o)| all[o].0.winding_number(&k, p) != 0)
            .min_by(|x, y| all[*x.1].1.total_cmp(&all[*y.1].1))
            .map(|(ri, _)| ri);
        if let Some(ri) = host {
            regions[ri].loops.push(l.vertices().to_vec());
            regions[ri].area += a;
        }
    }
    regions
}
