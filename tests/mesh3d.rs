//! Solids: validation with typed errors, orientation, nesting and facts,
//! checked against closed-form volumes and areas, on generated solids of
//! up to 2·10^5 triangles, metamorphically (translated, scaled, faces
//! shuffled and reversed) and on every bad input the issue lists.

use medax::shape::mesh_samples::{cuboid, sphere, torus, union, Soup};
use medax::shape::{Faces, Mesh3d, MeshError, MeshOptions};
use rand::rngs::SmallRng;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};

fn build((v, t): &Soup) -> Result<Mesh3d, MeshError> {
    Mesh3d::from_triangles(v, t, &MeshOptions::default())
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

#[test]
fn a_box_has_its_volume_area_and_genus() {
    let m = build(&cuboid([0.0, 0.0, 0.0], [2.0, 3.0, 4.0])).unwrap();
    assert!(close(m.volume(), 24.0, 1e-14), "{}", m.volume());
    assert!(close(m.area(), 52.0, 1e-14));
    let c = &m.components()[0];
    assert_eq!((c.triangles, c.vertices, c.edges, c.genus, c.depth), (12, 8, 18, 0, 0));
    assert_eq!(m.report().components_reversed, 0);
}

/// A polyhedral torus of n × m quads: its volume is the sum of n prisms,
/// computed here from the cross-section polygon (independent of the
/// library's divergence sum): V = n · A · r̄ · sin(2π/n), with A the
/// section's area and r̄ its centroid's distance from the axis.
#[test]
fn tori_have_genus_one_and_their_polyhedral_volume() {
    for (n, m) in [(3, 3), (12, 8), (200, 100)] {
        let (big, small) = (3.0, 1.0);
        let mesh = build(&torus(big, small, n, m)).unwrap();
        let c = &mesh.components()[0];
        assert_eq!((c.genus, c.triangles), (1, 2 * n * m));
        let section: Vec<(f64, f64)> = (0..m)
            .map(|j| {
                let w = std::f64::consts::TAU * j as f64 / m as f64;
                (big + small * w.cos(), small * w.sin())
            })
            .collect();
        let (mut area, mut moment) = (0.0, 0.0);
        for j in 0..m {
            let (p, q) = (section[j], section[(j + 1) % m]);
            let cross = p.0 * q.1 - q.0 * p.1;
            area += cross / 2.0;
            moment += (p.0 + q.0) * cross / 6.0;
        }
        let rbar = moment / area;
        let expect = n as f64 * area * rbar * (std::f64::consts::TAU / n as f64).sin();
        assert!(close(mesh.volume(), expect, 1e-10), "{n}x{m}: {} vs {expect}", mesh.volume());
    }
}

#[test]
fn an_inside_out_solid_is_reversed_and_reported() {
    let (v, mut t) = sphere([1.0, 2.0, 3.0], 2.0, 10, 16);
    for tri in &mut t {
        tri.swap(1, 2);
    }
    let m = build(&(v, t)).unwrap();
    assert!(m.volume() > 0.0);
    assert_eq!(m.report().components_reversed, 1);
    assert!(m.components()[0].reversed);
}

#[test]
fn one_flipped_face_is_reoriented() {
    let (v, mut t) = torus(3.0, 1.0, 10, 6);
    t[17].swap(0, 1);
    let m = build(&(v, t)).unwrap();
    assert_eq!(m.report().triangles_reoriented, 1);
    assert_eq!(m.report().components_reversed, 0);
}

/// A box with a cavity with an island inside it: depths 0, 1, 2; the
/// cavity's surface is reversed (it was given facing out of itself), the
/// volume is the material's.
#[test]
fn cavities_and_islands_nest() {
    let soup = union(&[
        cuboid([0.0, 0.0, 0.0], [10.0, 10.0, 10.0]),
        cuboid([2.0, 2.0, 2.0], [8.0, 8.0, 8.0]),
        cuboid([4.0, 4.0, 4.0], [5.0, 5.0, 5.0]),
        cuboid([20.0, 0.0, 0.0], [21.0, 1.0, 1.0]),
    ]);
    let m = build(&soup).unwrap();
    let depths: Vec<(Option<usize>, usize)> = m.components().iter().map(|c| (c.parent, c.depth)).collect();
    assert_eq!(depths, [(None, 0), (Some(0), 1), (Some(1), 2), (None, 0)]);
    assert!(close(m.volume(), 1000.0 - 216.0 + 1.0 + 1.0, 1e-14));
    assert_eq!(m.report().components_reversed, 1);
    assert!(m.components()[1].volume < 0.0);
}

/// Translated, scaled, faces shuffled and each rotated, vertices
/// permuted: the same volume (scaled by s³), area (s²) and counts.
#[test]
fn metamorphic_copies_agree() {
    let (v, t) = union(&[torus(3.0, 1.0, 30, 20), sphere([0.0, 0.0, 0.0], 1.5, 12, 18)]);
    let base = build(&(v.clone(), t.clone())).unwrap();
    let mut rng = SmallRng::seed_from_u64(7);
    for s in [1.0, 1e-3, 1e4] {
        let shift = [rng.gen_range(-1e3..1e3), rng.gen_range(-1e3..1e3), 17.0];
        let mut perm: Vec<u32> = (0..v.len() as u32).collect();
        perm.shuffle(&mut rng);
        let mut v2 = vec![[0.0; 3]; v.len()];
        for (i, p) in v.iter().enumerate() {
            v2[perm[i] as usize] = [p[0] * s + shift[0], p[1] * s + shift[1], p[2] * s + shift[2]];
        }
        let mut t2: Vec<[u32; 3]> = t.iter().map(|tri| tri.map(|i| perm[i as usize])).collect();
        t2.shuffle(&mut rng);
        for tri in &mut t2 {
            tri.rotate_left(rng.gen_range(0..3));
        }
        let m = build(&(v2, t2)).unwrap();
        assert!(close(m.volume(), base.volume() * s * s * s, 1e-9), "{s}");
        assert!(close(m.area(), base.area() * s * s, 1e-9));
        assert_eq!(m.components().len(), 2);
        let mut genus: Vec<usize> = m.components().iter().map(|c| c.genus).collect();
        genus.sort();
        assert_eq!(genus, [0, 1]);
    }
}

/// STL-like input: every triangle with its own three corners. Welding
/// restores the topology; the count is reported.
#[test]
fn unshared_corners_are_welded() {
    let (v, t) = torus(3.0, 1.0, 16, 10);
    let loose: Vec<[f64; 3]> = t.iter().flat_map(|tri| tri.map(|i| v[i as usize])).collect();
    let tris: Vec<[u32; 3]> = (0..t.len() as u32).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
    let m = build(&(loose, tris)).unwrap();
    assert_eq!(m.positions().len(), v.len());
    assert_eq!(m.report().welded, 3 * t.len() - v.len());
    assert_eq!(m.components()[0].genus, 1);
}

#[test]
fn quads_are_triangulated() {
    let (v, _) = cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
    let quads: [[u32; 4]; 6] = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let indices: Vec<u32> = quads.iter().flatten().copied().collect();
    let starts: Vec<u32> = (0..=6).map(|i| 4 * i).collect();
    let m =
        Mesh3d::from_polygons(&v, Faces { indices: &indices, starts: &starts, lines: &[] }, &MeshOptions::default())
            .unwrap();
    assert_eq!(m.triangles().len(), 12);
    assert_eq!(m.report().polygons_triangulated, 6);
    assert!(close(m.volume(), 1.0, 1e-15));
}

#[test]
fn bad_solids_get_typed_errors() {
    let (v, t) = cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
    // Open: one triangle missing.
    let open = build(&(v.clone(), t[..11].to_vec())).unwrap_err();
    assert!(matches!(open, MeshError::OpenEdge { .. }), "{open}");
    // NaN and huge vertices.
    let mut nan = v.clone();
    nan[5][1] = f64::NAN;
    assert_eq!(build(&(nan, t.clone())), Err(MeshError::NonFinite { vertex: 5 }));
    let mut huge = v.clone();
    huge[2][0] = 1e12;
    assert_eq!(build(&(huge, t.clone())), Err(MeshError::TooLarge { vertex: 2 }));
    // A face naming a vertex that does not exist.
    let mut out_of_range = t.clone();
    out_of_range[4][2] = 8;
    assert!(matches!(build(&(v.clone(), out_of_range)), Err(MeshError::IndexOutOfRange { index: 8, .. })));
    // A face with a repeated corner, and one with three corners on a line.
    let mut repeated = t.clone();
    repeated[3] = [1, 1, 5];
    assert!(matches!(build(&(v.clone(), repeated)), Err(MeshError::DegenerateFace { face, .. }) if face.face == 3));
    let mut line_v = v.clone();
    line_v.push([0.5, 0.0, 0.0]);
    let mut flat = t.clone();
    flat.push([0, 8, 1]);
    assert!(matches!(build(&(line_v, flat)), Err(MeshError::DegenerateFace { face, .. }) if face.face == 12));
    // Non-manifold edge: a fin of two triangles on edge 0–1.
    let mut fin_v = v.clone();
    fin_v.push([0.5, -1.0, -1.0]);
    let mut fin = t.clone();
    fin.extend([[0, 1, 8], [1, 0, 8]]);
    assert!(matches!(build(&(fin_v, fin)), Err(MeshError::NonManifoldEdge { faces: 4, .. })));
    // Non-manifold vertex: two boxes sharing a corner.
    let bow = union(&[cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]), cuboid([1.0, 1.0, 1.0], [2.0, 2.0, 2.0])]);
    let e = build(&bow).unwrap_err();
    assert!(matches!(e, MeshError::NonManifoldVertex { vertex: 7, fans: 2 }), "{e}");
    // Empty.
    assert_eq!(build(&(v.clone(), Vec::new())), Err(MeshError::Empty));
    // Every message names what it is about.
    assert!(open.to_string().contains("vertex") && open.to_string().contains("face"));
}

/// Random closed solids at scale: unions of tori and spheres at random
/// places (disjoint: spaced on a grid), 2·10^5 triangles, several seeds.
#[test]
fn many_components_at_scale() {
    for seed in 0..3u64 {
        let mut rng = SmallRng::seed_from_u64(seed);
        let mut parts = Vec::new();
        let mut expect_genus = 0;
        for k in 0..40 {
            let c = [(k % 5) as f64 * 10.0, (k / 5 % 4) as f64 * 10.0, (k / 20) as f64 * 10.0];
            if rng.gen_bool(0.5) {
                let (mut v, t) = torus(3.0, rng.gen_range(0.5..1.5), 60, 40);
                for p in &mut v {
                    for a in 0..3 {
                        p[a] += c[a];
                    }
                }
                parts.push((v, t));
                expect_genus += 1;
            } else {
                parts.push(sphere(c, rng.gen_range(1.0..4.0), 40, 60));
            }
        }
        let soup = union(&parts);
        let m = build(&soup).unwrap();
        assert_eq!(m.components().len(), 40);
        assert_eq!(m.components().iter().map(|c| c.genus).sum::<usize>(), expect_genus);
        assert!(m.components().iter().all(|c| c.depth == 0 && c.volume > 0.0));
        assert!(m.triangles().len() > 100_000);
    }
}

/// Crossing surfaces: two interpenetrating boxes, a box through a torus,
/// a box whose corner was pushed through the opposite face, two boxes
/// touching face to face (a touch is a crossing for a solid), and a
/// cavity that pokes out of its solid. Each names two faces; the inside
/// test then agrees with the analytic inside of the valid solids.
#[test]
fn crossing_and_touching_surfaces_are_refused() {
    let crossing = |soup: &Soup| match build(soup) {
        Err(MeshError::SelfIntersection { faces }) => faces,
        other => panic!("{:?}", other.map(|m| m.components().len())),
    };
    crossing(&union(&[cuboid([0.0; 3], [2.0; 3]), cuboid([1.0; 3], [3.0; 3])]));
    crossing(&union(&[torus(3.0, 1.0, 24, 12), cuboid([2.5, -0.5, -2.0], [3.5, 0.5, 2.0])]));
    let (mut v, t) = cuboid([0.0; 3], [1.0; 3]);
    v[7] = [0.5, 0.5, -0.5]; // the top corner pushed below the bottom face
    crossing(&(v, t));
    crossing(&union(&[cuboid([0.0; 3], [1.0; 3]), cuboid([1.0, 0.2, 0.2], [2.0, 0.8, 0.8])]));
    let f = crossing(&union(&[cuboid([0.0; 3], [4.0; 3]), cuboid([1.0; 3], [5.0, 2.0, 2.0])]));
    assert!(f[0].face != f[1].face);
    let e = build(&union(&[cuboid([0.0; 3], [2.0; 3]), cuboid([1.0; 3], [3.0; 3])])).unwrap_err();
    assert!(e.to_string().contains("cross or touch"), "{e}");
}

#[test]
fn inside_the_material_excludes_cavities() {
    // A box with a cavity and, in the cavity, a torus (an island).
    let (mut tv, tt) = torus(1.5, 0.5, 16, 8);
    for q in &mut tv {
        for c in q.iter_mut() {
            *c += 5.0;
        }
    }
    let m = build(&union(&[cuboid([0.0; 3], [10.0; 3]), cuboid([2.0; 3], [8.0; 3]), (tv, tt)]))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(m.components().iter().map(|c| c.depth).collect::<Vec<_>>(), [0, 1, 2]);
    let p = medax::kernel::Point3::new;
    assert_eq!(m.inside(p(1.0, 1.0, 1.0)), Some(true)); // the box's wall
    assert_eq!(m.inside(p(2.5, 2.5, 2.5)), Some(false)); // in the cavity
    assert_eq!(m.inside(p(5.0, 5.0, 5.0)), Some(false)); // the torus's hole
    assert_eq!(m.inside(p(6.5, 5.0, 5.0)), Some(true)); // the torus's tube
    assert_eq!(m.inside(p(20.0, 5.0, 5.0)), Some(false));
    assert_eq!(m.inside(p(0.0, 3.0, 7.0)), None); // on the surface
}
