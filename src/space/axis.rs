//! The medial axis of a convex solid under a polyhedral ball, assembled
//! from the contact arrangements of its VF classes (thesis 3.3.3.1).
//!
//! On a convex solid every contact class is VF (no reflex edge or vertex
//! admits EE or FV, thesis 3.1.2), one per face. A cell of face `f`'s
//! arrangement with opposite class `(w̃, g)` is the projection of a piece
//! of the sheet of the classes of `f` and `g`: the map from a point `p` of
//! the cell to the centre `p − ρ(p)·ṽ` of its maximal* ball is affine
//! (`ρ` is the cell's radius function), so the piece is the cell's
//! polygon mapped corner by corner, a planar convex polygon, fanned into
//! triangles. Each sheet projects into both of its classes' arrangements;
//! it is taken from the face with the lesser index. Corners shared by
//! neighbouring pieces are welded within 10^-9 of the solid's size.
//!
//! Solids with reflex edges need the EE and FV domains (3.3.2.2.3–4),
//! not built yet: they are refused, naming a reflex edge.

use super::arrangement::face_arrangement;
use super::classes::contact_classes;
use super::AlongError;
use crate::kernel::Point3;
use crate::shape::ball::{Ball3, Feature3};
use crate::shape::{Mesh3d, SurfacePart};
use crate::util::fast_hash::FastMap;

/// A sheet of the axis: the centres of the maximal* balls touching two
/// contact classes (here two VF classes: a ball vertex on a face each).
#[derive(Debug, Clone, PartialEq)]
pub struct Sheet3 {
    /// The faces of its two classes, the lesser first.
    pub faces: [u32; 2],
    /// The ball vertices touching them, in the same order.
    pub ball_vertices: [usize; 2],
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
    /// The solid has a reflex edge (its ends): only convex solids are
    /// handled so far.
    NotConvex {
        /// The edge's vertices, the lesser first.
        edge: [u32; 2],
    },
    /// A ball edge or facet is parallel to this face (its VF class is not
    /// one vertex): outside general position.
    FaceParallelToBall {
        /// The face (triangle index).
        face: u32,
    },
    /// A cell of this face's arrangement touches opposite with an EE or
    /// FV contact, which a convex solid cannot hold: its piece of the
    /// axis cannot be assembled yet.
    OppositeNotVertexFace {
        /// The face.
        face: u32,
    },
    /// A face's arrangement failed.
    Arrangement {
        /// The face.
        face: u32,
        /// Why.
        error: AlongError,
    },
}

impl std::fmt::Display for Axis3Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Axis3Error::NotConvex { edge } => {
                write!(f, "edge {}–{} is reflex: only convex solids are handled so far", edge[0], edge[1])
            }
            Axis3Error::FaceParallelToBall { face } => {
                write!(f, "triangle {face} is parallel to a ball edge or facet (not in general position)")
            }
            Axis3Error::OppositeNotVertexFace { face } => {
                write!(f, "triangle {face}: a maximal* ball touches an edge or vertex opposite (not yet assembled)")
            }
            Axis3Error::Arrangement { face, error } => write!(f, "triangle {face}: {error}"),
        }
    }
}

impl std::error::Error for Axis3Error {}

/// The medial axis of the convex solid `mesh` under `ball` (thesis 3.3).
///
/// # Errors
///
/// [`Axis3Error`]: a reflex edge, a face parallel to a ball edge or
/// facet, a face's arrangement failing (see [`AlongError`]).
pub fn medial_axis_3d(mesh: &Mesh3d, ball: &Ball3) -> Result<Axis3, Axis3Error> {
    use rayon::prelude::*;
    let classes = contact_classes(mesh, ball);
    if let Some(&edge) = classes.reflex_edges.first() {
        return Err(Axis3Error::NotConvex { edge });
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
    let reach = ball.reach();
    let arrangements: Vec<_> = (0..mesh.triangles().len() as u32)
        .into_par_iter()
        .map(|f| {
            face_arrangement(mesh, &reach, f, anchor[f as usize])
                .map_err(|error| Axis3Error::Arrangement { face: f, error })
        })
        .collect::<Result<_, _>>()?;
    let mut out = Axis3::default();
    let mut weld = Weld::new(mesh.bbox().diagonal() * 1e-9);
    let mut sheet_of: FastMap<(u32, u32), usize> = FastMap::default();
    for arr in &arrangements {
        let f = arr.face;
        let corners = mesh.triangles()[f as usize].map(|i| mesh.positions()[i as usize]);
        let v = ball.vertices()[arr.anchor];
        for cell in &arr.cells {
            // On a convex solid every opposite class is VF; another one
            // means the solid was not convex after all (a piece of the
            // axis would be dropped): refused, not skipped.
            let (Feature3::Vertex(w), SurfacePart::Face(g)) = (cell.opposite.ball, cell.opposite.surface) else {
                return Err(Axis3Error::OppositeNotVertexFace { face: f });
            };
            if g < f {
                continue;
            }
            let ids: Vec<u32> = cell
                .polygon
                .iter()
                .map(|&(a, b)| {
                    let p = corners[0] + (corners[1] - corners[0]) * a + (corners[2] - corners[0]) * b;
                    let r = cell.radius.at(p);
                    weld.id(p - v * r, r, &mut out.vertices)
                })
                .collect();
            let s = *sheet_of.entry((f, g)).or_insert_with(|| {
                out.sheets.push(Sheet3 { faces: [f, g], ball_vertices: [arr.anchor, w], triangles: Vec::new() });
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
