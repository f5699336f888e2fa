//! C functions for the medial axis under a polygon ball (thesis chapter 3
//! in the plane): compute it into an `mx_axis`, read its contact classes,
//! take offsets from any axis. Mirrors `crate::polymetric`; the node and
//! edge accessors of `axis.rs` read both kinds of axis.

use super::axis::{
    axis_error, mx_axis, mx_axis_edge, mx_axis_node, mx_axis_options, mx_axis_site, mx_conic_kind, mx_node_kind,
};
use super::ball::mx_ball;
use super::boundary::{guard, nth, run_with_progress, write_out};
use super::handles::{arg, compute, into_raw, query};
use super::last_error::FfiError;
use super::offset::{mx_offset_layer, offset_error};
use super::shape2d::mx_shape2d;
use super::status::mx_status;
use crate::kernel::Disk;
use crate::plane::{medial_axis, AxisOptions, OffsetLayer, OffsetLoop, OffsetOptions, OffsetRegion, Offsets};
use crate::polymetric::{
    medial_axis_with_ball, outer_offset, BallAxis, BallAxisError, BallNodeKind, BallOffsetLayer, ClassKind,
    ShapeFeature,
};
use crate::shape::{Feature, Shape2d, Vertex};

pub(crate) fn ball_axis_error(e: BallAxisError) -> FfiError {
    let message = e.to_string();
    match e {
        BallAxisError::Arc { l, i } => {
            let mut f = FfiError::new(mx_status::MX_ERR_UNSUPPORTED, message);
            f.info.loop_index = l as i64;
            f.info.element = i as i64;
            f
        }
        BallAxisError::NotRegion { l } => {
            let mut f = FfiError::new(mx_status::MX_ERR_UNSUPPORTED, message);
            f.info.loop_index = l as i64;
            f
        }
        BallAxisError::Inconsistent { at, .. } => {
            let mut f = FfiError::new(mx_status::MX_ERR_NUMERICAL, message);
            f.info.has_position = 1;
            f.info.x = at.x;
            f.info.y = at.y;
            f
        }
    }
}

pub(crate) fn node(b: &BallAxis, index: usize) -> Result<mx_axis_node, FfiError> {
    let n = nth(&b.nodes, index, "node")?;
    let kind = match n.kind {
        BallNodeKind::Branch => mx_node_kind::MX_NODE_BRANCH,
        BallNodeKind::PseudoBranch => mx_node_kind::MX_NODE_PSEUDO_BRANCH,
        BallNodeKind::Corner => mx_node_kind::MX_NODE_CORNER,
        BallNodeKind::Joint => mx_node_kind::MX_NODE_JOINT,
        BallNodeKind::Leaf => mx_node_kind::MX_NODE_LEAF,
    };
    Ok(mx_axis_node { x: n.at.x, y: n.at.y, r: n.r, kind })
}

pub(crate) fn edge(shape: &Shape2d, b: &BallAxis, index: usize) -> Result<mx_axis_edge, FfiError> {
    let e = nth(&b.edges, index, "edge")?;
    let site = |f: ShapeFeature| {
        let (l, i) = b.locate(f);
        match f {
            ShapeFeature::Edge(_) => {
                mx_axis_site { loop_index: l, index: shape.input_element_index(l, i), is_vertex: 0 }
            }
            ShapeFeature::Vertex(_) => {
                mx_axis_site { loop_index: l, index: shape.input_vertex_index(l, i), is_vertex: 1 }
            }
        }
    };
    Ok(mx_axis_edge {
        from: e.from,
        to: e.to,
        kind: mx_conic_kind::MX_CONIC_LINE,
        sites: [site(e.left.shape), site(e.right.shape)],
    })
}

pub(crate) fn ends(b: &BallAxis, index: usize) -> Result<Vec<Disk>, FfiError> {
    let e = nth(&b.edges, index, "edge")?;
    Ok([e.from, e.to].iter().map(|&v| Disk::new(b.nodes[v].at, b.nodes[v].r)).collect())
}

/// Computes the medial axis of `shape` under the unit ball `ball` (thesis
/// 3.1–3.2: the centres of maximal* balls `c + r·B`) and writes a new
/// handle to `*out`; `ball` NULL computes the Euclidean axis
/// (`mx_axis_compute`). The shape must be a polygon (segments only;
/// `MX_ERR_UNSUPPORTED` names the first arc's loop and element). Nodes
/// and edges are read with `mx_axis_get_node` (kinds add
/// `MX_NODE_PSEUDO_BRANCH`) and `mx_axis_get_edge` (every edge
/// `MX_CONIC_LINE`, sites the shape features of its two contact
/// classes); `mx_axis_edge_contacts` gives the classes and jump flag;
/// `mx_axis_edge_sample` gives the two end nodes, r the ball radius.
/// `options` may be NULL; its `seed` does not apply (the construction is
/// deterministic), `threads` and `progress` do. `MX_ERR_NUMERICAL` with
/// the position when the exact tracing meets a configuration it does not
/// resolve; `*out` is then untouched.
///
/// # Safety
/// `shape` NULL or a live handle; `ball` NULL or a live handle; `options`
/// NULL or valid; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_compute_with_ball(
    shape: *const mx_shape2d,
    ball: *const mx_ball,
    options: *const mx_axis_options,
    out: *mut *mut mx_axis,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        compute(out, shape, options, |s, o| {
            let export = "mx_axis_compute_with_ball";
            if ball.is_null() {
                let opts = AxisOptions { seed: o.seed, ..AxisOptions::default() };
                let axis = run_with_progress(export, "mx_axis_options", o.threads, o.progress, o.user, || {
                    medial_axis(&s.inner, &opts).map_err(axis_error)
                })?;
                return Ok(mx_axis { shape: s.inner.clone(), axis, ball: None });
            }
            // SAFETY: non-NULL, a live handle per the contract.
            let b = arg(ball)?.as_plane()?;
            let axis = run_with_progress(export, "mx_axis_options", o.threads, o.progress, o.user, || {
                medial_axis_with_ball(&s.inner, b).map_err(ball_axis_error)
            })?;
            Ok(mx_axis { shape: s.inner.clone(), axis: Default::default(), ball: Some(axis) })
        })
    }
}

/// Which features of ball and shape are in contact (thesis 3.1.2).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum mx_contact_kind {
    /// A ball vertex on the inside of a shape edge.
    MX_CONTACT_VE = 0,
    /// A ball edge on a (reflex) shape vertex.
    MX_CONTACT_EV = 1,
    /// A ball edge along a parallel shape edge (outside general position).
    MX_CONTACT_EE = 2,
}

/// The contact classes on the two sides of an edge of an axis under a
/// ball. The shape features are the edge's `sites` (`mx_axis_get_edge`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_axis_contacts {
    /// The kind of each side's class (`[0]` the left walking from `from`
    /// to `to`, as `mx_axis_edge.sites`).
    pub kind: [mx_contact_kind; 2],
    /// The ball feature of each class: a vertex index for VE, an edge
    /// index (from vertex i to vertex i + 1) for EV and EE, counting the
    /// ball's vertices counter-clockwise (`mx_ball_vertices`).
    pub ball_feature: [usize; 2],
    /// 1 when the two classes neighbour on the ball (a jump edge,
    /// Observation 10: its balls are maximal* but not maximal inscribed),
    /// else 0.
    pub jump: i32,
}

/// The contact classes and jump flag of edge `index` of an axis computed
/// under a ball (`MX_ERR_INVALID_ARGUMENT` for a Euclidean axis,
/// `MX_ERR_INDEX_OUT_OF_RANGE` unless below `mx_axis_edge_count`).
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_edge_contacts(
    axis: *const mx_axis,
    index: usize,
    out: *mut mx_axis_contacts,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(axis, out, |a| {
            let Some(b) = &a.ball else {
                return Err(FfiError::new(
                    mx_status::MX_ERR_INVALID_ARGUMENT,
                    "mx_axis_edge_contacts: the axis is Euclidean (computed without a ball)",
                ));
            };
            let e = nth(&b.edges, index, "edge")?;
            let kind = |k: ClassKind| match k {
                ClassKind::VE => mx_contact_kind::MX_CONTACT_VE,
                ClassKind::EV => mx_contact_kind::MX_CONTACT_EV,
                ClassKind::EE => mx_contact_kind::MX_CONTACT_EE,
            };
            let feature = |f: Feature| match f {
                Feature::Vertex(i) | Feature::Edge(i) => i,
            };
            Ok(mx_axis_contacts {
                kind: [kind(e.left.kind), kind(e.right.kind)],
                ball_feature: [feature(e.left.ball), feature(e.right.ball)],
                jump: e.jump as i32,
            })
        })
    }
}

/// The inner offset at `distance` (> 0, model units) read off `axis`, as
/// a new layer handle in `*out` (`mx_offset_layer_*`; free with
/// `mx_offset_layer_free`). For a Euclidean axis it is the layer
/// `mx_offsets_layer` gives. For an axis under a ball B it is the set of
/// centres c whose ball c + distance·B fits inside the shape: the path of
/// the reference point of a tool shaped distance·B (the thesis's trimmed
/// offset under the mirrored ball −B, Observation 13), straight loops.
/// `MX_ERR_INVALID_ARGUMENT` for a distance that is not finite and
/// positive; `*out` is then untouched.
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_offset_layer(
    axis: *const mx_axis,
    distance: f64,
    out: *mut *mut mx_offset_layer,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        new_layer(out, distance, || {
            let a = arg(axis)?;
            match &a.ball {
                None => Offsets::from_axis(&a.shape, &a.axis).and_then(|o| o.layer(distance)).map_err(offset_error),
                Some(b) => Ok(plain_layer(&b.offset(&a.shape, distance).map_err(ball_axis_error)?)),
            }
        })
    }
}

/// Checks `out` and `distance`, makes the layer and writes a new handle
/// to `*out` (nothing on failure).
///
/// # Safety
/// `out` NULL or writable; `make` upholds its handles' contracts.
unsafe fn new_layer(
    out: *mut *mut mx_offset_layer,
    distance: f64,
    make: impl FnOnce() -> Result<OffsetLayer, FfiError>,
) -> mx_status {
    guard(|| {
        if out.is_null() {
            return Err(super::boundary::null_arg("out"));
        }
        check_distance(distance)?;
        let layer = make()?;
        // SAFETY: checked non-NULL above.
        unsafe { write_out(out, into_raw(mx_offset_layer::new(layer))) };
        Ok(())
    })
}

/// The outer offset of `shape` at `distance` (> 0, model units) under the
/// unit ball `ball`, as a new layer handle in `*out` (`mx_offset_layer_*`;
/// free with `mx_offset_layer_free`; its distance is −`distance`): the
/// loops where the centre of the tool `c + distance·B` touches the shape
/// from outside (outer loops counter-clockwise, the holes of the grown
/// shape clockwise). Computed from the axes of the shape's complement
/// under the ball. `ball` NULL gives the Euclidean outer offset (as
/// `mx_offsets_compute` with `outer_reach` = `distance`, then
/// `mx_offsets_layer` at −`distance`). The shape must be polygonal under
/// a ball (`MX_ERR_UNSUPPORTED` names the arc); `MX_ERR_INVALID_ARGUMENT`
/// for a distance that is not finite and positive; `*out` is then
/// untouched.
///
/// # Safety
/// `shape` NULL or a live handle; `ball` NULL or a live handle; `out` NULL
/// or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_outer_offset_with_ball(
    shape: *const mx_shape2d,
    ball: *const mx_ball,
    distance: f64,
    out: *mut *mut mx_offset_layer,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        new_layer(out, distance, || {
            let s = arg(shape)?;
            if ball.is_null() {
                let opts = OffsetOptions { outer_reach: distance, ..OffsetOptions::default() };
                Offsets::new(&s.inner, &opts).and_then(|o| o.layer(-distance)).map_err(offset_error)
            } else {
                let b = arg(ball)?.as_plane()?;
                Ok(plain_layer(&outer_offset(&s.inner, b, distance).map_err(ball_axis_error)?))
            }
        })
    }
}

/// A layer under a ball as the C API's layer type (straight elements).
/// (The CLI converts the same way; the two algorithm layers do not see
/// each other's types.)
pub(crate) fn plain_layer(l: &BallOffsetLayer) -> OffsetLayer {
    let loops = l
        .loops
        .iter()
        .map(|lp| OffsetLoop {
            vertices: lp.points.iter().map(|&p| Vertex { p, bulge: 0.0 }).collect(),
            area: lp.area,
            region: lp.region,
        })
        .collect();
    let regions = l.regions.iter().map(|r| OffsetRegion { outer: r.outer, holes: r.holes.clone() }).collect();
    OffsetLayer::from_loops(l.distance, loops, regions)
}

/// A distance argument: finite and positive.
fn check_distance(distance: f64) -> Result<(), FfiError> {
    if distance.is_finite() && distance > 0.0 {
        Ok(())
    } else {
        Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("distance = {distance}: use a finite distance > 0"),
        ))
    }
}
