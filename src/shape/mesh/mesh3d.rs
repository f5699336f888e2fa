//! The validated solid: a closed, consistently oriented triangle surface
//! whose normals point out of the material, in one or more nested
//! components (a solid with cavities). Built once from a file or arrays,
//! immutable afterwards; every algorithm of space may rely on it.
//!
//! Invariants after [`Mesh3d::from_polygons`]:
//! * positions are finite, within ±[`crate::shape::MAX_COORDINATE`], and
//!   distinct (welded);
//! * every triangle has three corners not on one line (exactly);
//! * every edge has exactly two triangles, running it in opposite
//!   directions; the triangles around each vertex form one fan;
//! * each component's triangles face out of the material: a component at
//!   even nesting depth encloses positive volume, at odd depth (a cavity)
//!   negative.
//!
//! * no two triangles meet except along the edges and vertices they share
//!   (exact predicates over the AABB tree's overlapping boxes), so
//!   components are disjoint and the nesting found by winding numbers is
//!   a proper one.

use super::aabb::TriangleTree;
use super::error::{FaceRef, MeshError};
use super::nesting::nest;
use super::options::MeshOptions;
use super::topology::{analyse, Topology, TopologyError};
use super::triangulate::triangulate;
use super::weld::weld;
use crate::kernel::orient3::collinear3;
use crate::kernel::{BBox3, Point3};

/// One connected surface of a solid.
#[derive(Debug, Clone, PartialEq)]
pub struct Component {
    /// Its triangles.
    pub triangles: usize,
    /// Its vertices.
    pub vertices: usize,
    /// Its edges (3/2 of the triangles).
    pub edges: usize,
    /// Genus: 0 for a sphere-like surface, 1 for a torus, … (from the Euler
    /// characteristic V − E + F = 2 − 2g).
    pub genus: usize,
    /// Signed volume it encloses (negative for a cavity).
    pub volume: f64,
    /// Surface area.
    pub area: f64,
    /// Its bounding box.
    pub bbox: BBox3,
    /// The component directly around it, if any.
    pub parent: Option<usize>,
    /// How many components are around it (odd: it bounds a cavity).
    pub depth: usize,
    /// True when medax reversed all its triangles because they faced into
    /// the material (a solid given inside out).
    pub reversed: bool,
}

/// What building the solid did to the input, worth telling the user.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshReport {
    /// Input vertices merged into an earlier one at the same place.
    pub welded: usize,
    /// Input vertices no face uses (dropped).
    pub unused_vertices: usize,
    /// Faces with more than three corners, cut into triangles.
    pub polygons_triangulated: usize,
    /// Triangles reversed to agree with their neighbours.
    pub triangles_reoriented: usize,
    /// Components reversed because they faced into the material.
    pub components_reversed: usize,
}

/// A validated triangulated solid.
#[derive(Debug, Clone)]
pub struct Mesh3d {
    positions: Vec<Point3>,
    triangles: Vec<[u32; 3]>,
    /// Triangle → the input face it came from.
    face_of: Vec<u32>,
    /// Triangle → component.
    component_of: Vec<u32>,
    /// Half-edge `3t + k` → the opposite half-edge.
    twin: Vec<u32>,
    components: Vec<Component>,
    report: MeshReport,
    bbox: BBox3,
    /// The triangles' AABB tree (validation built it; queries use it).
    tree: TriangleTree,
}

// The tree is derived from the triangles: equal solids have equal trees.
impl PartialEq for Mesh3d {
    fn eq(&self, o: &Mesh3d) -> bool {
        self.positions == o.positions
            && self.triangles == o.triangles
            && self.face_of == o.face_of
            && self.components == o.components
            && self.report == o.report
    }
}

/// Input faces as the file gave them: `indices[starts[i]..starts[i + 1]]`
/// is face `i`, `lines[i]` its 1-based line (0 where none).
pub struct Faces<'a> {
    /// Every face's vertex indices back to back.
    pub indices: &'a [u32],
    /// Where each face starts; one more entry than faces.
    pub starts: &'a [u32],
    /// Each face's line, or empty when there are none.
    pub lines: &'a [u32],
}

impl Faces<'_> {
    fn count(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    fn face(&self, i: usize) -> &[u32] {
        &self.indices[self.starts[i] as usize..self.starts[i + 1] as usize]
    }

    fn at(&self, i: usize) -> FaceRef {
        FaceRef { face: i, line: self.lines.get(i).map_or(0, |&l| l as usize) }
    }
}

impl Mesh3d {
    /// Builds and validates a solid from positions and polygon faces.
    pub fn from_polygons(input: &[[f64; 3]], faces: Faces<'_>, options: &MeshOptions) -> Result<Mesh3d, MeshError> {
        if faces.count() == 0 {
            return Err(MeshError::Empty);
        }
        let mut points = Vec::with_capacity(input.len());
        for (i, &c) in input.iter().enumerate() {
            let p = Point3::from_array(c);
            if !p.is_finite() {
                return Err(MeshError::NonFinite { vertex: i });
            }
            if c.iter().any(|v| v.abs() > crate::shape::MAX_COORDINATE) {
                return Err(MeshError::TooLarge { vertex: i });
            }
            points.push(p);
        }
        for i in 0..faces.count() {
            if let Some(&bad) = faces.face(i).iter().find(|&&v| v as usize >= input.len()) {
                return Err(MeshError::IndexOutOfRange {
                    face: faces.at(i),
                    index: bad as u64,
                    vertex_count: input.len(),
                });
            }
        }
        let welded = weld(&points, options.weld_tolerance);
        let mut triangles = Vec::with_capacity(faces.count());
        let mut face_of = Vec::with_capacity(faces.count());
        let mut polygons = 0;
        let mut ids = Vec::new();
        for i in 0..faces.count() {
            ids.clear();
            ids.extend(faces.face(i).iter().map(|&v| welded.map[v as usize]));
            polygons += usize::from(ids.len() > 3);
            let before = triangles.len();
            triangulate(&ids, &welded.positions, &mut triangles)
                .ok_or(MeshError::DegenerateFace { face: faces.at(i) })?;
            for t in &triangles[before..] {
                let [a, b, c] = t.map(|v| welded.positions[v as usize]);
                if collinear3(a, b, c) {
                    return Err(MeshError::DegenerateFace { face: faces.at(i) });
                }
            }
            face_of.resize(triangles.len(), i as u32);
        }
        // Drop vertices no face uses, so that every vertex has a fan.
        let mut used = vec![u32::MAX; welded.positions.len()];
        let mut positions = Vec::new();
        let mut first_input = Vec::new();
        for t in triangles.iter_mut() {
            for v in t.iter_mut() {
                if used[*v as usize] == u32::MAX {
                    used[*v as usize] = positions.len() as u32;
                    positions.push(welded.positions[*v as usize]);
                    first_input.push(welded.first_input[*v as usize]);
                }
                *v = used[*v as usize];
            }
        }
        let input_vertex = |v: u32| first_input[v as usize] as usize;
        let face_ref = |t: u32| faces.at(face_of[t as usize] as usize);
        let topo = analyse(&mut triangles, positions.len()).map_err(|e| match e {
            TopologyError::Open { a, b, triangle } => {
                MeshError::OpenEdge { edge: [input_vertex(a), input_vertex(b)], face: face_ref(triangle) }
            }
            TopologyError::NonManifoldEdge { a, b, count, triangle } => MeshError::NonManifoldEdge {
                edge: [input_vertex(a), input_vertex(b)],
                faces: count,
                face: face_ref(triangle),
            },
            TopologyError::NonOrientable { triangle } => MeshError::NonOrientable { face: face_ref(triangle) },
            TopologyError::NonManifoldVertex { vertex, fans } => {
                MeshError::NonManifoldVertex { vertex: input_vertex(vertex), fans }
            }
        })?;
        let report = MeshReport {
            welded: welded.merged,
            unused_vertices: welded.positions.len() - positions.len(),
            polygons_triangulated: polygons,
            triangles_reoriented: topo.flipped,
            components_reversed: 0,
        };
        let tree = TriangleTree::new(&positions, &triangles);
        if let Some(&(a, b)) = tree.self_intersections(1).first() {
            return Err(MeshError::SelfIntersection { faces: [face_ref(a), face_ref(b)] });
        }
        let mut mesh = Mesh3d {
            bbox: BBox3::of(positions.iter().copied()),
            tree,
            positions,
            triangles,
            face_of,
            component_of: Vec::new(),
            twin: Vec::new(),
            components: Vec::new(),
            report,
        };
        mesh.orient_components(topo, &faces)?;
        Ok(mesh)
    }

    /// Measures each component, nests them, and reverses those that face
    /// into the material.
    fn orient_components(&mut self, topo: Topology, faces: &Faces<'_>) -> Result<(), MeshError> {
        let Topology { twin, component, components, .. } = topo;
        let mut comps = vec![Component::empty(); components];
        let mut first_tri = vec![usize::MAX; components];
        let mut seen = vec![u32::MAX; self.positions.len()];
        for (t, tri) in self.triangles.iter().enumerate() {
            let c = component[t] as usize;
            first_tri[c] = first_tri[c].min(t);
            let comp = &mut comps[c];
            comp.triangles += 1;
            for &v in tri {
                if seen[v as usize] != c as u32 {
                    seen[v as usize] = c as u32;
                    comp.vertices += 1;
                    comp.bbox = comp.bbox.with(self.positions[v as usize]);
                }
            }
        }
        // Volumes relative to each component's centre: the terms stay the
        // size of the component, not of its distance from the origin.
        for (t, tri) in self.triangles.iter().enumerate() {
            let comp = &mut comps[component[t] as usize];
            let o = comp.bbox.center();
            let [a, b, c] = tri.map(|v| self.positions[v as usize] - o);
            comp.volume += a.dot(b.cross(c)) / 6.0;
            comp.area += (b - a).cross(c - a).norm() / 2.0;
        }
        for (i, comp) in comps.iter_mut().enumerate() {
            comp.edges = comp.triangles * 3 / 2;
            let euler = comp.vertices as i64 - comp.edges as i64 + comp.triangles as i64;
            comp.genus = ((2 - euler) / 2).max(0) as usize;
            if comp.volume.abs() <= f64::EPSILON * comp.area * comp.bbox.diagonal() {
                let face = faces.at(self.face_of[first_tri[i]] as usize);
                return Err(MeshError::FlatComponent { component: i, face });
            }
        }
        // Nest with every component facing out (the winding number's sign
        // then does not matter), then reverse those whose sign is wrong
        // for their depth.
        let probe: Vec<Point3> = first_tri.iter().map(|&t| self.positions[self.triangles[t][0] as usize]).collect();
        let boxes: Vec<BBox3> = comps.iter().map(|c| c.bbox).collect();
        let mut tris_by_comp: Vec<Vec<[Point3; 3]>> = vec![Vec::new(); components];
        if components > 1 {
            for (t, tri) in self.triangles.iter().enumerate() {
                tris_by_comp[component[t] as usize].push(tri.map(|v| self.positions[v as usize]));
            }
        }
        let nesting = nest(&probe, &boxes, |c| tris_by_comp[c].iter().copied());
        let mut reverse = vec![false; components];
        for (i, comp) in comps.iter_mut().enumerate() {
            (comp.parent, comp.depth) = nesting[i];
            let want_positive = comp.depth % 2 == 0;
            if (comp.volume > 0.0) != want_positive {
                reverse[i] = true;
                comp.reversed = true;
                comp.volume = -comp.volume;
            }
        }
        self.report.components_reversed = reverse.iter().filter(|&&r| r).count();
        if self.report.components_reversed > 0 {
            // Reversing [a, b, c] to [a, c, b] moves the half-edge of
            // corner k to corner 2 − k; the twins follow.
            let moved = |h: usize| if reverse[component[h / 3] as usize] { h - h % 3 + 2 - h % 3 } else { h };
            let mut fresh = vec![0u32; twin.len()];
            for (h, &g) in twin.iter().enumerate() {
                fresh[moved(h)] = moved(g as usize) as u32;
            }
            for (t, tri) in self.triangles.iter_mut().enumerate() {
                if reverse[component[t] as usize] {
                    tri.swap(1, 2);
                }
            }
            self.twin = fresh;
        } else {
            self.twin = twin;
        }
        self.component_of = component;
        self.components = comps;
        Ok(())
    }

    /// The vertices (welded, each used by some triangle).
    pub fn positions(&self) -> &[Point3] {
        &self.positions
    }

    /// The triangles, counter-clockwise seen from outside the material.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The input face triangle `t` came from.
    pub fn face_of(&self, t: usize) -> usize {
        self.face_of[t] as usize
    }

    /// The component of triangle `t`.
    pub fn component_of(&self, t: usize) -> usize {
        self.component_of[t] as usize
    }

    /// The half-edge opposite half-edge `h` (`h = 3t + k` runs from corner
    /// `k` of triangle `t` to corner `k + 1`).
    pub fn twin(&self, h: usize) -> usize {
        self.twin[h] as usize
    }

    /// The components, outer surfaces and cavities.
    pub fn components(&self) -> &[Component] {
        &self.components
    }

    /// What building changed.
    pub fn report(&self) -> &MeshReport {
        &self.report
    }

    /// The volume of material (cavities subtracted).
    pub fn volume(&self) -> f64 {
        self.components.iter().map(|c| c.volume).sum()
    }

    /// The total surface area.
    pub fn area(&self) -> f64 {
        self.components.iter().map(|c| c.area).sum()
    }

    /// The bounding box.
    pub fn bbox(&self) -> BBox3 {
        self.bbox
    }

    /// The AABB tree of the triangles (closest points, rays, inside
    /// tests). Triangle ids are this solid's; the tree's copies keep the
    /// orientation before components were reversed, which none of its
    /// queries depends on.
    pub fn tree(&self) -> &TriangleTree {
        &self.tree
    }

    /// The largest ball `c + r·B` inside the solid at `c` (thesis 3.3.2.2),
    /// with where it touches; for `c` outside the material, the largest
    /// such ball that holds no point of the surface.
    pub fn ball_radius(&self, c: Point3, ball: &crate::shape::Ball3) -> super::aabb::BallContact {
        self.tree.ball_radius(c, ball).expect("a valid solid has triangles")
    }

    /// Whether `p` lies in the material (exact: parity of exact crossings;
    /// inside a cavity is outside), `None` when it lies on the surface.
    pub fn inside(&self, p: Point3) -> Option<bool> {
        self.tree.inside(p)
    }
}

impl Component {
    fn empty() -> Component {
        Component {
            triangles: 0,
            vertices: 0,
            edges: 0,
            genus: 0,
            volume: 0.0,
            area: 0.0,
            bbox: BBox3::EMPTY,
            parent: None,
            depth: 0,
            reversed: false,
        }
    }
}
