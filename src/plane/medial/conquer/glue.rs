//! Gluing (thesis 2.2.4): the leaves' axes become one graph, a node per
//! dividing disk (a disk met twice, from both sides, is one node), then the
//! graph surgery of `merge.rs`, node kinds from the final degrees and the
//! graph check.

use crate::kernel::bisector::ConicKind;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::AxisKernel;
use crate::plane::axis::{edge_kind, AxisEdge, AxisNode, MedialAxis2d, NodeKind};
use crate::plane::medial::base_case::{Alias, EventKind};
use crate::plane::medial::conquer::check::{check_graph, drop_repeats, root};
use crate::plane::medial::conquer::error::AxisError;
use crate::plane::medial::conquer::locals::{LocalAxes, LocalView};
use crate::plane::medial::conquer::merge::{merge_coinciding_branches, merge_pass_through, polish_branches};
use crate::plane::medial::conquer::rounding::contract_rounding_cycles;
use crate::plane::medial::conquer::self_stubs::{drop_rounding_spikes, drop_self_stubs};
use crate::plane::medial::conquer::stray_conics::straighten_stray_conics;
use crate::plane::medial::conquer::thin_cycles::drop_thin_cycles;
use crate::plane::medial::decompose::subshape::Cut;
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::Shape2d;
use crate::util::fast_hash::{FastMap, FastSet};

/// Glues the axes of the subshapes (`locals`) at the centres of the
/// dividing disks `cuts`; `finder` indexes the shape they were made of.
/// The subshapes' nodes and edges become the axis's in place.
pub fn glue<K: AxisKernel>(
    finder: &DiskFinder<K>,
    cuts: &[Cut],
    mut locals: LocalAxes,
) -> Result<MedialAxis2d, AxisError> {
    let shape = finder.shape();
    let tol = shape.tolerance();
    let t = Tolerance::new(tol);
    let same_as = coinciding_cuts(cuts, &joined_ports(&locals), t);
    let (same_as, refused) = with_aliases(same_as, &locals.aliases, cuts, t);
    for i in refused {
        if let Some(bridge) = locals.aliases[i].bridge.take() {
            locals.push(bridge);
        }
    }
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
    // The disk each class's node took, and the other disks of classes
    // that met more than one (node, disk).
    let mut node_cut: Vec<usize> = vec![usize::MAX; cuts.len()];
    let mut others: Vec<(u32, usize)> = Vec::new();
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
            EventKind::Port(c) => {
                let c = c as usize;
                let rep = same_as[c];
                match port_node[rep] {
                    Some(id) => {
                        if node_cut[rep] != c {
                            others.push((id, c));
                        }
                        id
                    }
                    None => {
                        node_cut[rep] = c;
                        *port_node[rep].insert(keep(true))
                    }
                }
            }
            _ => keep(false),
        };
    }
    nodes.truncate(count as usize);
    // Each such class's first disk too.
    let several: FastSet<u32> = others.iter().map(|&(id, _)| id).collect();
    let firsts = port_node.iter().zip(&node_cut).filter_map(|(id, &c)| Some(((*id)?, c)));
    others.extend(firsts.filter(|(id, _)| several.contains(id)).collect::<Vec<_>>());
    drop(several);
    drop((events, port_node, node_cut));
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
    fit_class_nodes(shape, cuts, &mut axis, others);
    is_joint.resize(axis.nodes.len(), false);
    merge_pass_through(shape, &mut axis, &is_port, &is_joint);
    classify(&mut axis, tol);
    merge_coinciding_branches(shape, &mut axis, t);

    // After the merges, which settle the edges that subshapes share, and
    // before the node kinds, which follow from the degrees.
    let fit = t.branch_group_fit();
    let fits =
        |n: &AxisNode, e: &AxisEdge| e.sites.iter().all(|s| (s.distance(shape, n.point) - n.radius).abs() <= fit);
    contract_rounding_cycles(&mut axis, t.rounding_cycle(), fits);
    drop_thin_cycles(shape, &mut axis, shape.loops().len() - 1);
    drop_self_stubs(&mut axis, t.rounding_cycle());
    drop_rounding_spikes(&mut axis, t.same_disk());
    classify(&mut axis, tol);
    polish_branches(finder.kernel(), shape, &mut axis);
    straighten_stray_conics(finder, &mut axis, t.rounding_cycle(), t.final_check());
    check_graph(&axis, shape.loops().len() - 1)?;
    // The lists held every subshape's nodes and edges; the axis is
    // returned without the room they no longer fill.
    axis.nodes.shrink_to_fit();
    axis.edges.shrink_to_fit();
    Ok(axis)
}

/// Pairs of dividing disks (smaller id first) that some subshape's axis
/// joins by an edge: two nodes of that axis, so two disks, however close.
fn joined_ports(locals: &LocalAxes) -> FastSet<(usize, usize)> {
    let port = |v: usize| match locals.events[v] {
        EventKind::Port(c) => Some(c as usize),
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
/// relations, each class represented by its smallest disk. An alias with
/// a bridge is refused (its index returned) where it would stretch a
/// class's centres over more than [`Tolerance::same_disk`] (or more than
/// either class spans already): its bridge joins the two disks instead.
fn with_aliases(mut same_as: Vec<usize>, aliases: &[Alias], cuts: &[Cut], t: Tolerance) -> (Vec<usize>, Vec<usize>) {
    if aliases.is_empty() {
        return (same_as, Vec::new());
    }
    // Each class's box of centres, at its representative.
    let mut boxes: Vec<[f64; 4]> = cuts.iter().map(|c| [c.center.x, c.center.y, c.center.x, c.center.y]).collect();
    let join = |a: [f64; 4], b: [f64; 4]| [a[0].min(b[0]), a[1].min(b[1]), a[2].max(b[2]), a[3].max(b[3])];
    let span = |b: [f64; 4]| (b[2] - b[0]).hypot(b[3] - b[1]);
    for i in 0..cuts.len() {
        let r = root(&mut same_as, i);
        boxes[r] = join(boxes[r], boxes[i]);
    }
    let mut refused = Vec::new();
    for (i, alias) in aliases.iter().enumerate() {
        let [a, b] = alias.disks;
        let (ra, rb) = (root(&mut same_as, a), root(&mut same_as, b));
        if ra == rb {
            continue;
        }
        let merged = join(boxes[ra], boxes[rb]);
        if alias.bridge.is_some() && span(merged) > t.same_disk().max(span(boxes[ra])).max(span(boxes[rb])) {
            refused.push(i);
            continue;
        }
        let (lo, hi) = (ra.min(rb), ra.max(rb));
        same_as[hi] = lo;
        boxes[lo] = merged;
    }
    for i in 0..same_as.len() {
        same_as[i] = root(&mut same_as, i);
    }
    (same_as, refused)
}

/// Places each node of a class of several dividing disks (`members`:
/// node and disk, every class's first disk among them) at the member disk
/// that fits its edges best (the least largest distance from its circle to
/// an edge's primitive): the class's first disk can lie tens of
/// tolerances from the disks that other leaves' edges end at.
fn fit_class_nodes(shape: &Shape2d, cuts: &[Cut], axis: &mut MedialAxis2d, members: Vec<(u32, usize)>) {
    let mut of_node: FastMap<u32, Vec<usize>> = FastMap::default();
    for &(id, c) in &members {
        of_node.entry(id).or_default().push(c);
    }
    of_node.retain(|_, cs| {
        cs.sort_unstable();
        cs.dedup();
        cs.len() > 1
    });
    if of_node.is_empty() {
        return;
    }
    let mut edges_at: FastMap<u32, Vec<usize>> = FastMap::default();
    for (i, e) in axis.edges.iter().enumerate() {
        for v in [e.from as u32, e.to as u32] {
            if of_node.contains_key(&v) {
                edges_at.entry(v).or_default().push(i);
            }
        }
    }
    for (id, cs) in of_node {
        let Some(at) = edges_at.get(&id) else { continue };
        let misfit = |c: usize| {
            let Cut { center, radius } = cuts[c];
            at.iter()
                .flat_map(|&i| axis.edges[i].sites)
                .map(|p| (p.distance(shape, center) - radius).abs())
                .fold(0.0f64, f64::max)
        };
        if let Some(best) =
            cs.into_iter().map(|c| (misfit(c), c)).min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
        {
            let node = &mut axis.nodes[id as usize];
            (node.point, node.radius) = (cuts[best.1].center, cuts[best.1].radius);
        }
    }
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
                EventKind::Port(c) => Some(same_as[c as usize]),
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
    fn a_node_of_several_disks_takes_the_one_that_fits_its_edges() {
        use crate::plane::axis::{AxisEdge, AxisNode, Primitive};
        use crate::shape::{ElementRef, Shape2d, ShapeOptions};
        let json = r#"{"loops": [[[-10, -10], [10, -10], [10, 10], [-10, 10]]]}"#;
        let shape = Shape2d::from_json_str(json, &ShapeOptions::default()).unwrap();
        // Between the bottom and the top side: centred on y = 0, radius 10.
        let cuts =
            [Cut { center: Point::new(0.0, 1e-3), radius: 10.0 }, Cut { center: Point::new(0.0, 0.0), radius: 10.0 }];
        let node = |c: Cut| AxisNode { point: c.center, radius: c.radius, kind: NodeKind::Joint };
        let side = |element: usize| Primitive::of_element(ElementRef { loop_index: 0, element });
        let edge = AxisEdge {
            from: 0,
            to: 1,
            sites: [side(0), side(2)],
            params: [(0.0, 0.0); 2],
            kind: ConicKind::Line,
            straight: false,
        };
        let far = Cut { center: Point::new(5.0, 0.0), radius: 10.0 };
        let mut axis = MedialAxis2d { nodes: vec![node(cuts[0]), node(far)], edges: vec![edge] };
        fit_class_nodes(&shape, &cuts, &mut axis, vec![(0, 0), (0, 1)]);
        assert_eq!(axis.nodes[0].point, Point::new(0.0, 0.0));
        // A node of one disk stays where it is.
        let mut axis = MedialAxis2d { nodes: vec![node(cuts[0]), node(far)], edges: axis.edges };
        fit_class_nodes(&shape, &cuts, &mut axis, vec![(0, 0)]);
        assert_eq!(axis.nodes[0].point, cuts[0].center);
    }

    #[test]
    fn disks_a_leaf_named_by_one_node_are_one_node_unless_a_bridge_is_shorter() {
        // 0 and 1 coincide; 2..5 lie 10τ apart one after the other.
        let tau = 1e-9;
        let t = Tolerance::new(tau);
        let cut = |x: f64| Cut { center: Point::new(x * tau, 0.0), radius: 1.0 };
        let cuts: Vec<Cut> = [0.0, 1.0, 100.0, 110.0, 120.0, 300.0].map(cut).to_vec();
        let same_as = vec![0, 0, 2, 3, 4, 5];
        let alias = |a: usize, b: usize, bridge: bool| Alias {
            disks: [a, b],
            bridge: bridge.then(crate::plane::medial::base_case::LocalAxis::default),
        };
        assert_eq!(with_aliases(same_as.clone(), &[], &cuts, t), (same_as.clone(), vec![]));
        // Named as one by leaves: one node, however far apart.
        let (merged, refused) = with_aliases(same_as.clone(), &[alias(3, 2, false), alias(5, 1, false)], &cuts, t);
        assert_eq!((merged, refused), (vec![0, 0, 2, 2, 4, 0], vec![]));
        // With bridges: 3 joins 2 and 4 joins them (20τ across), but 5,
        // 300τ from 0 and 1, is bridged instead.
        let aliases = [alias(3, 2, true), alias(4, 3, true), alias(5, 1, true)];
        assert_eq!(with_aliases(same_as, &aliases, &cuts, t), (vec![0, 0, 2, 2, 2, 5], vec![2]));
    }
}
