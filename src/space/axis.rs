//! The medial axis of a solid under a polyhedral ball, assembled from the
//! contact arrangements of its regular classes (thesis 3.3.3.1).
//!
//! Every face is a VF class's domain, every EE class (a ball edge at a
//! reflex edge) has the domain of `edge_domain`. A cell of a domain with
//! opposite class `C'` is the projection of a piece of the sheet of the
//! two classes: the map from a point `p` of the cell to the centre
//! `p − ρ(p)·ṽ` of its maximal* ball is affine (`ρ` is the cell's radius
//! function, `ṽ` the domain's anchor), so the piece is the cell's polygon
//! mapped corner by corner, a planar convex polygon, fanned into
//! triangles. Each sheet projects into the domains of both its classes;
//! where the other class's ball feature holds the domain's representative
//! vertex it collapses to a line there (a jump sheet: a ball vertex on a
//! face and an edge through it on a reflex edge), so an EE class has a
//! domain for each end of its ball edge, and a sheet is taken from the
//! least domain (VF before EE before FV, then by features and
//! representative vertex) where it is two-dimensional. An FV class (a
//! ball facet on a vertex whose exterior lies beyond the facet's plane)
//! has a domain per corner of its facet (`corner_domain`), for the same
//! reason. Corners shared by neighbouring pieces are welded within 10^-9
//! of the solid's size.

use super::along::{AlongError, Opposite};
use super::arrangement::{face_arrangement, Cell};
use super::classes::{contact_classes, ContactClass};
use super::corner_domain::corner_arrangement;
use super::domain::DomainPlane;
use super::edge_domain::edge_arrangement;
use super::radius::radius_fn;
use crate::kernel::Point3;
use crate::shape::ball::{Ball3, ContactKind3, Feature3};
use crate::shape::{Mesh3d, SurfacePart};
use crate::util::fast_hash::FastMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// A sheet of the axis: the centres of the maximal* balls touching two
/// contact classes.
#[derive(Debug, Clone, PartialEq)]
pub struct Sheet3 {
    /// Its two classes, the lesser first (VF before EE before FV; then by
    /// ball feature and surface feature).
    pub classes: [Opposite; 2],
    /// A jump sheet: the two classes' ball features share a vertex
    /// (neighbouring on the ball, Definition 3.1.10), so its balls are
    /// maximal* but not maximal inscribed — scaled about the shared part
    /// they grow or shrink along the sheet (thesis 3.1.4).
    pub jump: bool,
    /// Its triangles, indices into [`Axis3::triangles`].
    pub triangles: Vec<u32>,
}

/// The medial axis of a solid under a polyhedral ball: a non-manifold
/// triangle mesh whose vertices carry the radius of their maximal* ball.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Axis3 {
    /// Vertices: centre `x, y, z` and radius `r` (the largest ball
    /// `c + r·B` inside the solid).
    pub vertices: Vec<[f64; 4]>,
    /// Triangles, indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// The sheets, each with its triangles.
    pub sheets: Vec<Sheet3>,
}

/// Why a solid's axis was not computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Axis3Error {
    /// A ball facet rests on this vertex with one of its edges along the
    /// facet's plane (an FV class at a tie): outside general position.
    CornerParallelToBall {
        /// The vertex.
        vertex: u32,
    },
    /// A ball edge or facet is parallel to this face (its VF class is not
    /// one vertex): outside general position.
    FaceParallelToBall {
        /// The face (triangle index).
        face: u32,
    },
    /// A ball edge's fan of normals touches this reflex edge's at an end
    /// (a ball facet parallel to one of its faces): outside general
    /// position.
    EdgeParallelToBall {
        /// The edge's vertices, the lesser first.
        edge: [u32; 2],
    },
    /// The solid has reflex edges and this ball facet's corners are not
    /// exactly coplanar (a turned ball with facets of more than three
    /// corners): a ball edge sliding along a reflex edge would not lie
    /// exactly on the wall of its cone.
    BallFacetNotPlanar {
        /// The ball facet.
        facet: usize,
    },
    /// A maximal* ball touches opposite with an FV contact that is not a
    /// class (a contradiction of the exact predicates: a defect).
    OppositeFaceVertex {
        /// The surface vertex touched.
        vertex: u32,
    },
    /// Cancelled through [`Watch::cancel`].
    Cancelled,
    /// A domain's arrangement failed.
    Arrangement {
        /// Its class.
        class: Opposite,
        /// Why.
        error: AlongError,
    },
}

impl std::fmt::Display for Axis3Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Axis3Error::CornerParallelToBall { vertex } => {
                write!(f, "an edge at vertex {vertex} is parallel to a ball facet resting on it (not in general position)")
            }
            Axis3Error::FaceParallelToBall { face } => {
                write!(f, "triangle {face} is parallel to a ball edge or facet (not in general position)")
            }
            Axis3Error::EdgeParallelToBall { edge } => {
                write!(f, "reflex edge {}–{} is parallel to a ball facet (not in general position)", edge[0], edge[1])
            }
            Axis3Error::BallFacetNotPlanar { facet } => write!(
                f,
                "ball facet {facet} is not exactly planar (a turned ball?), and the solid has reflex edges: use a ball of triangles (the hull of its points)"
            ),
            Axis3Error::OppositeFaceVertex { vertex } => {
                write!(f, "a maximal* ball touches vertex {vertex} with a facet that is no contact class there (a defect)")
            }
            Axis3Error::Cancelled => write!(f, "cancelled"),
            Axis3Error::Arrangement { class, error } => match (class.ball, class.surface) {
                (_, SurfacePart::Face(t)) => write!(f, "triangle {t}: {error}"),
                (Feature3::Edge(k), SurfacePart::Edge(e)) => {
                    write!(f, "reflex edge {}–{} with ball edge {k}: {error}", e[0], e[1])
                }
                (Feature3::Facet(k), SurfacePart::Vertex(v)) => {
                    write!(f, "vertex {v} with ball facet {k}: {error}")
                }
                _ => write!(f, "{error}"),
            },
        }
    }
}

impl std::error::Error for Axis3Error {}

/// Progress of a 3D axis computation, shared with another thread: how
/// many contact domains are done of how many, and a request to stop.
#[derive(Debug, Default)]
pub struct Watch {
    done: AtomicUsize,
    total: AtomicUsize,
    cancel: AtomicBool,
}

impl Watch {
    /// The fraction of the domains done, in `[0, 1]` (0 before they are
    /// counted).
    pub fn fraction(&self) -> f64 {
        let total = self.total.load(Ordering::Relaxed);
        if total == 0 {
            0.0
        } else {
            self.done.load(Ordering::Relaxed) as f64 / total as f64
        }
    }

    /// Asks the computation to stop.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Whether [`cancel`](Self::cancel) was called.
    pub fn is_cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }
}

/// One contact domain to build.
#[derive(Debug, Clone, Copy)]
enum Job {
    /// A face (its VF class).
    Face(u32),
    /// An EE class, for one end of its ball edge.
    Edge(ContactClass, usize),
    /// An FV class, for one corner of its facet.
    Corner(ContactClass, usize),
}

/// One domain's arrangement with what maps it to the axis.
struct Domain {
    own: Opposite,
    plane: DomainPlane,
    anchor_index: usize,
    anchor: Point3,
    cells: Vec<Cell>,
}

/// The domain a sheet of classes `a` and `b` is taken from: the least
/// (class, representative vertex) among the domains of `a` and `b` in
/// which it is two-dimensional (the anchored balls reach the other class
/// by growing: the representative vertex is not on its ball feature). A
/// VF class has one domain (its vertex); an EE class one per end of its
/// ball edge. `None` when none is (not a sheet of these two alone).
fn sheet_domain(mesh: &Mesh3d, ball: &Ball3, a: Opposite, b: Opposite) -> Option<(Opposite, usize)> {
    let anchors = |c: Opposite| corners_of(ball, c.ball);
    let mut best: Option<(Opposite, usize)> = None;
    for (own, other) in [(a, b), (b, a)] {
        for v in anchors(own) {
            if radius_fn(mesh, ball, v, other.ball, other.surface).is_some() {
                best = Some(best.map_or((own, v), |x| x.min((own, v))));
            }
        }
    }
    best
}

/// The ball vertices of a ball feature (a domain's representative
/// vertices: a VF class has one, an EE class one per end of its edge, an
/// FV class one per corner of its facet).
fn corners_of(ball: &Ball3, x: Feature3) -> Vec<usize> {
    match x {
        Feature3::Vertex(v) => vec![v],
        Feature3::Edge(k) => ball.edges().get(k).map_or(Vec::new(), |e| e.vertices.to_vec()),
        Feature3::Facet(f) => ball.facets().get(f).map_or(Vec::new(), |x| x.vertices.clone()),
    }
}

/// The medial axis of the solid `mesh` under `ball` (thesis 3.3).
///
/// # Errors
///
/// [`Axis3Error`]: a ball facet not exactly planar (with reflex edges), a
/// face, reflex edge or vertex's edge parallel to a ball feature, a
/// domain's arrangement failing (see [`AlongError`]).
pub fn medial_axis_3d(mesh: &Mesh3d, ball: &Ball3) -> Result<Axis3, Axis3Error> {
    medial_axis_3d_watched(mesh, ball, &Watch::default())
}

/// [`medial_axis_3d`] reporting its progress to `watch` (domains done of
/// all) and stopping with [`Axis3Error::Cancelled`] soon after
/// [`Watch::cancel`] (each domain checks it before it starts).
///
/// # Errors
///
/// As [`medial_axis_3d`], and [`Axis3Error::Cancelled`].
pub fn medial_axis_3d_watched(mesh: &Mesh3d, ball: &Ball3, watch: &Watch) -> Result<Axis3, Axis3Error> {
    use rayon::prelude::*;
    let classes = contact_classes(mesh, ball);
    if !classes.reflex_edges.is_empty() {
        if let Some(facet) = ball.non_planar_facet() {
            return Err(Axis3Error::BallFacetNotPlanar { facet });
        }
    }
    let mut anchor = vec![usize::MAX; mesh.triangles().len()];
    for c in &classes.vertex_face {
        if let (Feature3::Vertex(v), SurfacePart::Face(t)) = (c.ball, c.surface) {
            if c.tie {
                return Err(Axis3Error::FaceParallelToBall { face: t });
            }
            anchor[t as usize] = v;
        }
    }
    if let Some(c) = classes.edge_edge.iter().find(|c| c.tie) {
        if let SurfacePart::Edge(edge) = c.surface {
            return Err(Axis3Error::EdgeParallelToBall { edge });
        }
    }
    if let Some(c) = classes.face_vertex.iter().find(|c| c.tie) {
        if let SurfacePart::Vertex(vertex) = c.surface {
            return Err(Axis3Error::CornerParallelToBall { vertex });
        }
    }
    let reach = ball.reach();
    let w = ball.vertices();
    // Every domain is one job: a face, an EE class for one end of its
    // ball edge, an FV class for one corner of its facet.
    let mut jobs: Vec<Job> = (0..mesh.triangles().len() as u32).map(Job::Face).collect();
    for c in &classes.edge_edge {
        jobs.extend([Job::Edge(*c, 0), Job::Edge(*c, 1)]);
    }
    for c in &classes.face_vertex {
        let corners = match c.ball {
            Feature3::Facet(f) => ball.facets().get(f).map_or(0, |x| x.vertices.len()),
            _ => 0,
        };
        jobs.extend((0..corners).map(|k| Job::Corner(*c, k)));
    }
    watch.total.store(jobs.len(), Ordering::Relaxed);
    let domain = |job: &Job| -> Result<Vec<Domain>, Axis3Error> {
        if watch.is_cancelled() {
            return Err(Axis3Error::Cancelled);
        }
        let got = match *job {
            Job::Face(f) => {
                let own = Opposite {
                    ball: Feature3::Vertex(anchor[f as usize]),
                    surface: SurfacePart::Face(f),
                    kind: ContactKind3::VertexFace,
                };
                let failed = |error| Axis3Error::Arrangement { class: own, error };
                let arr = face_arrangement(mesh, &reach, f, anchor[f as usize]).map_err(failed)?;
                let plane = DomainPlane::of_face(mesh, f).ok_or(failed(AlongError::NoClass))?;
                vec![Domain { own, plane, anchor_index: arr.anchor, anchor: w[arr.anchor], cells: arr.cells }]
            }
            Job::Edge(c, end) => {
                let own = Opposite { ball: c.ball, surface: c.surface, kind: ContactKind3::EdgeEdge };
                let failed = |error| Axis3Error::Arrangement { class: own, error };
                let (Feature3::Edge(k), SurfacePart::Edge(e)) = (c.ball, c.surface) else {
                    return Err(failed(AlongError::NoClass));
                };
                let arr = edge_arrangement(mesh, &reach, e, k, end).map_err(failed)?;
                vec![Domain {
                    own,
                    plane: arr.plane,
                    anchor_index: arr.anchor,
                    anchor: w[arr.anchor],
                    cells: arr.cells,
                }]
            }
            Job::Corner(c, k) => {
                let own = Opposite { ball: c.ball, surface: c.surface, kind: ContactKind3::FaceVertex };
                let failed = |error| Axis3Error::Arrangement { class: own, error };
                let (Feature3::Facet(f), SurfacePart::Vertex(v)) = (c.ball, c.surface) else {
                    return Err(failed(AlongError::NoClass));
                };
                let arr = corner_arrangement(mesh, &reach, v, f, k).map_err(failed)?;
                let sectors = arr.sectors.into_iter();
                sectors
                    .map(|s| Domain {
                        own,
                        plane: s.plane,
                        anchor_index: arr.anchor,
                        anchor: w[arr.anchor],
                        cells: s.cells,
                    })
                    .collect()
            }
        };
        watch.done.fetch_add(1, Ordering::Relaxed);
        Ok(got)
    };
    let domains: Vec<Vec<Domain>> = jobs.par_iter().map(domain).collect::<Result<_, _>>()?;
    let domains: Vec<Domain> = domains.into_iter().flatten().collect();
    let mut out = Axis3::default();
    let mut weld = Weld::new(mesh.bbox().diagonal() * 1e-9);
    let mut sheet_of: FastMap<(Opposite, Opposite), usize> = FastMap::default();
    for d in &domains {
        for cell in &d.cells {
            let other = cell.opposite;
            if let (ContactKind3::FaceVertex, SurfacePart::Vertex(vertex)) = (other.kind, other.surface) {
                if !classes.face_vertex.iter().any(|c| c.ball == other.ball && c.surface == other.surface) {
                    return Err(Axis3Error::OppositeFaceVertex { vertex });
                }
            }
            // Each sheet once: from the least domain where it is
            // two-dimensional.
            if sheet_domain(mesh, ball, d.own, other) != Some((d.own, d.anchor_index)) {
                continue;
            }
            let ids: Vec<u32> = cell
                .polygon
                .iter()
                .map(|&q| {
                    let p = d.plane.point(q);
                    let r = cell.radius.at(p);
                    weld.id(p - d.anchor * r, r, &mut out.vertices)
                })
                .collect();
            let key = (d.own.min(other), d.own.max(other));
            let s = *sheet_of.entry(key).or_insert_with(|| {
                let shared = corners_of(ball, key.1.ball);
                let jump = corners_of(ball, key.0.ball).iter().any(|v| shared.contains(v));
                out.sheets.push(Sheet3 { classes: [key.0, key.1], jump, triangles: Vec::new() });
                out.sheets.len() - 1
            });
            for k in 1..ids.len().saturating_sub(1) {
                let t = [ids[0], ids[k], ids[k + 1]];
                if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
                    out.sheets[s].triangles.push(out.triangles.len() as u32);
                    out.triangles.push(t);
                }
            }
        }
    }
    Ok(out)
}

/// Vertices welded within a distance: a grid of cells that wide, each
/// point looked up in its cell and the 26 around it.
struct Weld {
    cell: f64,
    grid: FastMap<[i64; 3], Vec<u32>>,
}

impl Weld {
    fn new(cell: f64) -> Weld {
        Weld { cell: cell.max(f64::MIN_POSITIVE), grid: FastMap::default() }
    }

    fn id(&mut self, c: Point3, r: f64, vertices: &mut Vec<[f64; 4]>) -> u32 {
        let key = [c.x, c.y, c.z].map(|x| (x / self.cell).floor() as i64);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let k = [key[0] + dx, key[1] + dy, key[2] + dz];
                    if let Some(ids) = self.grid.get(&k) {
                        for &i in ids {
                            let q = vertices[i as usize];
                            if (Point3::new(q[0], q[1], q[2]) - c).norm() <= self.cell {
                                return i;
                            }
                        }
                    }
                }
            }
        }
        let id = vertices.len() as u32;
        vertices.push([c.x, c.y, c.z, r]);
        self.grid.entry(key).or_default().push(id);
        id
    }
}
