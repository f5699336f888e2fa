//! Gluing (thesis 2.2.4): the leaves' axes become one graph, a node per
//! dividing disk (a disk met twice, from both sides, is one node), then the
//! graph surgery of `merge.rs`, node kinds from the final degrees and the
//! graph check.

use crate::kernel::bisector::ConicKind;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::AxisKernel;
use crate::plane::axis::{edge_kind, AxisEdge, AxisNode, MedialAxis2d, NodeKind};
use crate::plane::medial::base_case::EventKind;
use crate::plane::medial::conquer::check::{check_graph, drop_repeats, root};
use crate::plane::medial::conquer::error::AxisError;
use crate::plane::medial::conquer::locals::{LocalAxes, LocalView};
use crate::plane::medial::conquer::merge::{merge_coinciding_branches, merge_pass_through, polish_branches};
use crate::plane::medial::conquer::rounding::contract_rounding_cycles;
use crate::plane::medial::conquer::thin_cycles::drop_thin_cycles;
use crate::plane::medial::decompose::subshape::Cut;
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::util::fast_hash::{FastMap, FastSet};

/// Glues the axes of the subshapes (`locals`) at the centres of the
/// dividing disks `cuts`; `finder` indexes the shape they were made of.
/// The subshapes' nodes and edges become the axis's in place.
pub fn glue<K: AxisKernel>(finder: &DiskFinder<K>, cuts: &[Cut], locals: LocalAxes) -> Result<MedialAxis2d, AxisError> {
    let shape = finder.shape();
    let tol = shape.tolerance();
    let same_as = coinciding_cuts(cuts, &joined_ports(&locals), Tolerance::new(tol));
    let same_as = with_aliases(same_as, &locals.aliases);
    let skip = redundant_bands(&locals, &same_as);
    let (mut nodes, events, mut edges) = locals.into_parts(&skip);
    let mut port_node: Vec<Option<u32>> = vec![None; cuts.len()];
    let mut is_port: Vec<bool> = Vec::with_capacity(nodes.len());
    let mut is_joint: Vec<bool> = Vec::with_capacity(nodes.len());
    // The axis node of every subshape node; `u32::MAX` for the nodes of a
    // subshape left out, whose edges go with them. Nodes are compacted in
    // place: a node's new index is never past its old one.
    let mut ids: Vec<u32> = vec![u32::MAX; nodes.len()];
    let mut count = 0u32;
    for (v, event) in events.iter().enumerate() {
        let Some(event) = *event else { continue };
        // Node `v` moved down to the next free index.
        let mut keep = |port: bool| {
            nodes[count as usize] = nodes[v];
            is_port.push(port);
            is_joint.push(event == EventKind::Joint);
            count += 1;
            count - 1
        };
        ids[v] = match event {
            EventKind::Port(c) => *port_node[same_as[c]].get_or_insert_with(|| keep(true)),
            _ => keep(false),
        };
    }
    nodes.truncate(count as usize);
    drop((events, port_node));
    // Two subshapes that both hold the same stretch of axis (between two
    // disks met twice) give the same edge twice: keep one. Only an edge
    // between two ports can repeat (every other node is one subshape's,
    // whose walk links each pair once).
    edges.retain_mut(|e| {
        if ids[e.from] == u32::MAX {
            return false;
        }
        (e.from, e.to) = (ids[e.from] as usize, ids[e.to] as usize);
        e.kind = if e.straight { ConicKind::Line } else { edge_kind(shape, e.sites[0], e.sites[1]) };
        e.from != e.to
    });
    drop(ids);
    let between_ports: Vec<bool> = edges.iter().map(|e| is_port[e.from] && is_port[e.to]).collect();
    drop_repeats(&mut edges, &between_ports);
    let mut axis = MedialAxis2d { nodes, edges };
    is_joint.resize(axis.nodes.len(), false);
    merge_pass_through(shape, &mut axis, &is_port, &is_joint);
    classify(&mut axis, tol);
    merge_coinciding_branches(shape, &mut axis, Tolerance::new(tol));

    // After the merges, which settle the edges that subshapes share, and
    // before the node kinds, which follow from the degrees.
    let fit = Tolerance::new(tol).branch_group_fit();
    let fits =
        |n: &AxisNode, e: &AxisEdge| e.sites.iter().all(|s| (s.distance(shape, n.point) - n.radius).abs() <= fit);
    contract_rounding_cycles(&mut axis, Tolerance::new(tol).rounding_cycle(), fits);
    drop_thin_cycles(shape, &mut axis);
    classify(&mut axis, tol);
    polish_branches(finder.kernel(), shape, &mut axis);
    check_graph(&axis, shape.loops().len() - 1)?;
    Ok(axis)
}

/// Pairs of dividing disks (smaller id first) that some subshape's axis
/// joins by an edge: two nodes of that axis, so two disks, however close.
fn joined_ports(locals: &LocalAxes) -> FastSet<(usize, usize)> {
    let port = |v: usize| match locals.events[v] {
        EventKind::Port(c) => Some(c),
        _ => None,
    };
    locals.edges.iter().filter_map(|e| Some((port(e.from)?, port(e.to)?))).map(|(a, b)| (a.min(b), a.max(b))).collect()
}

/// For each dividing disk, the first one that is the same disk (centre and
/// radius within [`Tolerance::same_disk`]): the divide step can meet one
/// disk twice, from two sides, and both must be one node. Two disks that a
/// subshape's axis joins by an edge (`apart`) are two nodes even within
/// that tolerance: random cuts along one edge of the axis can fall that
/// close (two of 1.7·10^5 cuts of a plate of letters of 10^6 elements,
/// 58τ apart, glued into one node that missed the other's primitives).
fn coinciding_cuts(cuts: &[Cut], apart: &FastSet<(usize, usize)>, t: Tolerance) -> Vec<usize> {
    let (tol, side) = (t.same_disk(), t.merge_cell());
    let cell = |x: f64| (x / side).floor() as i64;
    let mut grid: FastMap<(i64, i64), Vec<usize>> = FastMap::default();
    // Cuts merged into an earlier one, by cell.
    let mut merged: FastMap<(i64, i64), Vec<usize>> = FastMap::default();
    let mut out: Vec<usize> = Vec::with_capacity(cuts.len());
    for (i, c) in cuts.iter().enumerate() {
        let (gx, gy) = (cell(c.center.x), cell(c.center.y));
        let near = |j: usize, tol: f64| {
            cuts[j].center.dist(c.center) <= tol
                && (cuts[j].radius - c.radius).abs() <= tol
                && !apart.contains(&(j.min(i), j.max(i)))
        };
        let cells = || (-1..=1).flat_map(|dx| (-1..=1).map(move |dy| (gx + dx, gy + dy)));
        let found = cells().filter_map(|k| grid.get(&k)).flatten().copied().find(|&j| near(j, tol));
        // A disk within rounding of one that was merged into a disk
        // farther away is that one's node too: matched to representatives
        // only, a cut 4τ from another stayed a node of its own when the
        // other had merged into a disk just over 64τ from it, and the
        // sliver subshape between the two (whose axis is its one port)
        // left it unjoined.
        let found = found.or_else(|| {
            let close = t.same_merged_cut();
            cells().filter_map(|k| merged.get(&k)).flatten().copied().find(|&j| near(j, close)).map(|j| out[j])
        });
        match found {
            Some(j) => {
                merged.entry((gx, gy)).or_default().push(i);
                out.push(j)
            }
            None => {
                grid.entry((gx, gy)).or_default().push(i);
                out.push(i);
            }
        }
    }
    out
}

/// `same_as` (each disk's representative) with the disks that leaves
/// named by one node ([`LocalAxes::aliases`]) made one: the union of both
/// relations, each class represented by its smallest disk.
fn with_aliases(mut same_as: Vec<usize>, aliases: &[[usize; 2]]) -> Vec<usize> {
    if aliases.is_empty() {
        return same_as;
    }
    for &[a, b] in aliases {
        let (ra, rb) = (root(&mut same_as, a), root(&mut same_as, b));
        same_as[ra.max(rb)] = ra.min(rb);
    }
    for i in 0..same_as.len() {
        same_as[i] = root(&mut same_as, i);
    }
    same_as
}

/// Which locals to leave out: a band's straight edge stands for whatever
/// axis joins its two ports, so where another subshape holding the same
/// stretch (between two disks met twice) has those ports too, its axis is
/// kept instead, and of two bands with the same ports one is kept.
/// `same_as` maps a dividing disk to the one it coincides with.
fn redundant_bands(locals: &LocalAxes, same_as: &[usize]) -> Vec<bool> {
    let is_band = |local: &LocalView| local.edges.len() == 1 && local.edges[0].straight;
    if !locals.iter().any(|l| is_band(&l)) {
        return vec![false; locals.count()];
    }
    let ports_of = |local: &LocalView| {
        let mut p: Vec<usize> = local
            .events
            .iter()
            .filter_map(|event| match *event {
                EventKind::Port(c) => Some(same_as[c]),
                _ => None,
            })
            .collect();
        p.sort_unstable();
        p
    };
    let solved: FastSet<Vec<usize>> =
        locals.iter().filter(|l| !is_band(l)).map(|l| ports_of(&l)).filter(|p| p.len() == 2).collect();
    let mut bands: FastSet<Vec<usize>> = FastSet::default();
    locals
        .iter()
        .map(|local| {
            is_band(&local) && {
                let ports = ports_of(&local);
                solved.contains(&ports) || !bands.insert(ports)
            }
        })
        .collect()
}

/// Node kinds from the final degrees. An end whose disk is within the
/// tolerance `tol` of radius 0 is a convex corner (a dividing disk that
/// small, in a needle's tip, is that corner's node).
fn classify(axis: &mut MedialAxis2d, tol: f64) {
    let deg = axis.degrees();
    for (v, node) in axis.nodes.iter_mut().enumerate() {
        node.kind = if node.radius == 0.0 || (deg[v] <= 1 && node.radius <= tol) {
            NodeKind::Corner
        } else if deg[v] >= 3 {
            NodeKind::Branch
        } else if deg[v] <= 1 {
            NodeKind::Leaf
        } else {
            NodeKind::Joint
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;

    #[test]
    fn a_disk_met_twice_joins_the_node_its_twin_joined() {
        // Cut 1 lies 60τ from cut 0 (one node); cut 2 lies 4τ from cut 1
        // but 64.5τ from cut 0: it is the node cuts 0 and 1 are. Cut 3,
        // 20τ from cut 1 and 80τ from cut 0, is a disk of its own.
        let tau = 1e-9;
        let t = Tolerance::new(tau);
        let cut = |x: f64| Cut { center: Point::new(x * tau, 0.0), radius: 1.0 };
        let cuts = [cut(0.0), cut(60.0), cut(64.5), cut(80.0)];
        assert_eq!(coinciding_cuts(&cuts, &FastSet::default(), t), [0, 0, 0, 3]);
        // Joined by a subshape's edge, two disks stay two nodes (and cut 3
        // is then within 64τ of a node of its own, cut 2's).
        let apart: FastSet<(usize, usize)> = [(1, 2)].into_iter().collect();
        assert_eq!(coinciding_cuts(&cuts, &apart, t), [0, 0, 2, 2]);
    }

    #[test]
    fn disks_a_leaf_named_by_one_node_are_one_node_however_far() {
        // 0 and 1 coincide; leaves named 3 by 2's node and 4 by 3's.
        let same_as = vec![0, 0, 2, 3, 4, 5];
        assert_eq!(with_aliases(same_as.clone(), &[]), same_as);
        assert_eq!(with_aliases(same_as.clone(), &[[3, 2], [4, 3]]), [0, 0, 2, 2, 2, 5]);
        // An alias to a merged disk joins its representative's class.
        assert_eq!(with_aliases(same_as, &[[5, 1]]), [0, 0, 2, 3, 4, 0]);
    }
}
