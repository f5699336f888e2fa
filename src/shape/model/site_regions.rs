//! The region of each Voronoi site (thesis Corollary 2): bounded by the
//! edges between the site and other sites and by its self-edges, cracks
//! in the region walked once each way; the walk keeps the site on its left
//! (counter-clockwise round it). Regions are simply connected, so the walk
//! is one closed walk.

use crate::kernel::fan::cw_angle;
use crate::kernel::Point;
use crate::shape::{SiteId, VoronoiEdge};

/// The region of one site.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SiteRegion {
    /// The site.
    pub site: SiteId,
    /// The boundary walk: axis edge indices, each with `true` when walked
    /// from its `from` node to its `to` node (the site on the walk's left);
    /// a self-edge of the site appears twice, once each way. Consecutive
    /// entries share a node, and the last leads back to the first.
    pub boundary: Vec<(usize, bool)>,
    /// How many closed walks the boundary edges form: 1 for every region
    /// of a valid diagram (regions are simply connected), 0 for a site
    /// without edges.
    pub walks: usize,
    /// The site's self-edges (axis edge indices).
    pub self_edges: Vec<usize>,
    /// The boundary meets the library's frame: the region is unbounded in
    /// the sites' own diagram.
    pub unbounded: bool,
}

/// Per node of a diagram with the library's frame: whether edges between
/// sites and edges facing the frame meet there (an edge between sites
/// runs on to infinity from it). `ends(i)` gives edge `i`'s two nodes.
pub(crate) fn frontier_nodes(
    node_count: usize,
    ends: impl Fn(usize) -> (usize, usize),
    edges: &[VoronoiEdge],
) -> Vec<bool> {
    let (mut at_frame, mut at_sites) = (vec![false; node_count], vec![false; node_count]);
    for (i, v) in edges.iter().enumerate() {
        let seen = if v.sides.contains(&SiteId::Frame) { &mut at_frame } else { &mut at_sites };
        let (a, b) = ends(i);
        seen[a] = true;
        seen[b] = true;
    }
    at_frame.iter().zip(&at_sites).map(|(a, b)| *a && *b).collect()
}

/// The regions of every site but the library's frame (`loop_sites[0]`
/// when it is [`SiteId::Frame`] and `skip_frame`), in loop order.
/// `ends(i)` gives the `from` and `to` nodes of axis edge `i` (any axis:
/// Euclidean or under a ball).
pub(crate) fn site_regions(
    ends: impl Fn(usize) -> (usize, usize),
    edges: &[VoronoiEdge],
    loop_sites: &[SiteId],
    skip_frame: bool,
    toward: impl Fn(usize, bool) -> Point,
) -> Vec<SiteRegion> {
    let mut by_site: std::collections::HashMap<SiteId, Vec<(usize, bool)>> = Default::default();
    let mut selfs: std::collections::HashMap<SiteId, Vec<usize>> = Default::default();
    for (i, v) in edges.iter().enumerate() {
        if v.self_edge {
            selfs.entry(v.sides[0]).or_default().push(i);
        }
        // A self-edge is a crack in its site's region, walked both ways: it
        // may be all that joins two parts of the boundary (a C-shaped site
        // round another site has an outer and an inner part, joined
        // through the self-edges in its mouth).
        by_site.entry(v.sides[0]).or_default().push((i, true));
        by_site.entry(v.sides[1]).or_default().push((i, false));
    }
    loop_sites
        .iter()
        .filter(|&&s| !(skip_frame && s == SiteId::Frame))
        .map(|&site| {
            let directed = by_site.remove(&site).unwrap_or_default();
            let unbounded = skip_frame && directed.iter().any(|&(i, _)| edges[i].sides.contains(&SiteId::Frame));
            let (boundary, walks) = closed_walks(&ends, &directed, &toward);
            SiteRegion { site, boundary, walks, self_edges: selfs.remove(&site).unwrap_or_default(), unbounded }
        })
        .collect()
}

/// The directed edges joined into closed walks (Hierholzer, choosing by
/// rotation where several edges leave a node): the walk, and how many
/// separate walks it is made of. `toward(i, from_start)` is the direction
/// in which edge `i` leaves its `from` node (`true`) or its `to` node.
fn closed_walks(
    edge_ends: &impl Fn(usize) -> (usize, usize),
    directed: &[(usize, bool)],
    toward: &impl Fn(usize, bool) -> Point,
) -> (Vec<(usize, bool)>, usize) {
    let ends = |&(i, fwd): &(usize, bool)| {
        let (from, to) = edge_ends(i);
        if fwd {
            (from, to)
        } else {
            (to, from)
        }
    };
    let mut out_of: std::collections::HashMap<usize, Vec<usize>> = Default::default();
    for (k, d) in directed.iter().enumerate().rev() {
        out_of.entry(ends(d).0).or_default().push(k);
    }
    let mut used = vec![false; directed.len()];
    let mut walk = Vec::with_capacity(directed.len());
    let mut walks = 0;
    for start in 0..directed.len() {
        if used[start] {
            continue;
        }
        walks += 1;
        used[start] = true;
        let mut stack = vec![start];
        let mut circuit = Vec::new();
        while let Some(&top) = stack.last() {
            let head = ends(&directed[top]).1;
            let next = out_of.get_mut(&head).and_then(|v| {
                v.retain(|&k| !used[k]);
                // Several ways on (a tree of self-edges meets the walk
                // here): the first clockwise from the way back keeps the
                // region on the left, as a face is walked.
                let pick = if v.len() > 1 {
                    let back = toward(directed[top].0, !directed[top].1);
                    let turn = |k: usize| cw_angle(back, toward(directed[k].0, directed[k].1));
                    (0..v.len()).min_by(|&a, &b| turn(v[a]).total_cmp(&turn(v[b])))?
                } else {
                    v.len().checked_sub(1)?
                };
                Some(v.swap_remove(pick))
            });
            match next {
                Some(k) => {
                    used[k] = true;
                    stack.push(k);
                }
                None => circuit.push(stack.pop().unwrap_or(top)),
            }
        }
        walk.extend(circuit.into_iter().rev().map(|k| directed[k]));
    }
    (walk, walks)
}
