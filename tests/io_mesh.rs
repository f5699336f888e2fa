//! The mesh readers and writers of `medax::io::mesh`: each format from a
//! small literal, write → read round trips that give the same doubles back,
//! STL's two encodings agreeing, every error with its message and position,
//! and CGAL's sample files (read when libcgal-demo's data is installed).

use medax::io::mesh::{read_mesh, write_obj, write_off, write_ply, MeshFormat, MeshParseError, RawMesh};
use std::path::Path;

fn read(bytes: &[u8], format: MeshFormat) -> RawMesh {
    let mesh = read_mesh(bytes, Some(format)).unwrap_or_else(|e| panic!("{e}"));
    check_invariants(&mesh);
    mesh
}

fn read_err(bytes: &[u8], format: MeshFormat) -> MeshParseError {
    match read_mesh(bytes, Some(format)) {
        Ok(m) => panic!("expected an error, read {m:?}"),
        Err(e) => e,
    }
}

/// What every reader promises of a mesh it returns.
fn check_invariants(m: &RawMesh) {
    assert_eq!(m.face_starts.first(), Some(&0));
    assert_eq!(*m.face_starts.last().unwrap() as usize, m.indices.len());
    assert!(m.face_starts.windows(2).all(|w| w[1] >= w[0] + 3));
    assert_eq!(m.face_source.len(), m.face_count());
    assert!(m.indices.iter().all(|&i| (i as usize) < m.positions.len()));
}

fn faces(m: &RawMesh) -> Vec<Vec<u32>> {
    (0..m.face_count()).map(|i| m.face(i).to_vec()).collect()
}

/// A tetrahedron, outward faces.
fn tetra() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let p = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    (p, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
}

/// Numbers that a careless writer or reader would change.
fn awkward_positions() -> Vec<[f64; 3]> {
    vec![
        [0.1, -0.0, 1e-300],
        [1e300, -2.5e-8, std::f64::consts::PI],
        [f64::MIN_POSITIVE, 5e-324, -1.0 / 3.0],
        [123456789.12345679, f64::MAX, f64::INFINITY],
        [f64::NAN, f64::NEG_INFINITY, 7.0],
    ]
}

fn same_bits(a: &[[f64; 3]], b: &[[f64; 3]]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(p, q)| p.iter().zip(q).all(|(x, y)| x.to_bits() == y.to_bits()))
}

fn binary_stl(header: &[u8; 80], facets: &[[[f32; 3]; 3]]) -> Vec<u8> {
    let mut out = header.to_vec();
    out.extend_from_slice(&(facets.len() as u32).to_le_bytes());
    for f in facets {
        out.extend_from_slice(&[0u8; 12]);
        for v in f {
            v.iter().for_each(|c| out.extend_from_slice(&c.to_le_bytes()));
        }
        out.extend_from_slice(&[0, 0]);
    }
    out
}

// ---- formats and sniffing ----

#[test]
fn formats_by_extension_and_content() {
    assert_eq!(MeshFormat::from_path(Path::new("a/b.OBJ")), Some(MeshFormat::Obj));
    assert_eq!(MeshFormat::from_path(Path::new("b.off")), Some(MeshFormat::Off));
    assert_eq!(MeshFormat::from_path(Path::new("b.Stl")), Some(MeshFormat::Stl));
    assert_eq!(MeshFormat::from_path(Path::new("b.ply")), Some(MeshFormat::Ply));
    assert_eq!(MeshFormat::from_path(Path::new("b.dxf")), None);
    assert_eq!(MeshFormat::from_path(Path::new("off")), None);
    assert_eq!(MeshFormat::Ply.name(), "PLY");

    let sniff = MeshFormat::sniff;
    assert_eq!(sniff(b"OFF\n3 1 0\n"), Some(MeshFormat::Off));
    assert_eq!(sniff(b"# c\n\nCOFF 3 1 0\n"), Some(MeshFormat::Off));
    assert_eq!(sniff(b"NOFF\n"), Some(MeshFormat::Off));
    assert_eq!(sniff(b"ply\r\nformat ascii 1.0\n"), Some(MeshFormat::Ply));
    assert_eq!(sniff(b"solid x\nfacet normal 0 0 1\n"), Some(MeshFormat::Stl));
    assert_eq!(sniff(b"# obj\no thing\nv 0 0 0\n"), Some(MeshFormat::Obj));
    assert_eq!(sniff(b"f 1 2 3\n"), Some(MeshFormat::Obj));
    let (p, _) = tetra();
    let bin = binary_stl(&[b' '; 80], &[[to_f32(p[0]), to_f32(p[1]), to_f32(p[2])]]);
    assert_eq!(sniff(&bin), Some(MeshFormat::Stl));
    assert_eq!(sniff(b"hello world"), None);
    assert_eq!(sniff(b""), None);

    let e = read_mesh(b"hello", None).unwrap_err();
    assert!(e.unsupported && e.message.contains("not a mesh file"), "{e}");
    let m = read_mesh(b"OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", None).unwrap();
    assert_eq!(faces(&m), vec![vec![0, 1, 2]]);
}

fn to_f32(p: [f64; 3]) -> [f32; 3] {
    [p[0] as f32, p[1] as f32, p[2] as f32]
}

// ---- OBJ ----

#[test]
fn obj_polygons_groups_and_index_forms() {
    let src = b"# a cube's corner\nmtllib missing.mtl\no first\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
vt 0 0\nvn 0 0 1\ng side\nusemtl red\nf 1/1/1 2/1/1 3/1/1 4/1/1\nv 0 0 1 1 0 0\nv 9 9 9\n\
o second\nf -5//1 -4//1 -3\nl 1 2 3\nf 1 2 6\ns off\n";
    let m = read(src, MeshFormat::Obj);
    // All the file's vertices, in its order, the unused one too; the colour is not a coordinate.
    assert_eq!(m.positions, vec![[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.], [0., 0., 1.], [9., 9., 9.]]);
    // The quad stays a quad; the second object's faces share the first's vertices.
    assert_eq!(faces(&m), vec![vec![0, 1, 2, 3], vec![1, 2, 3], vec![0, 1, 5]]);
    assert!(m.source_is_line);
    assert_eq!(m.face_source, vec![12, 16, 18]);
}

#[test]
fn obj_homogeneous_w_and_crlf() {
    let m = read(b"v 2 4 6 2\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n", MeshFormat::Obj);
    assert_eq!(m.positions[0], [1.0, 2.0, 3.0]);
    assert_eq!(m.face_source, vec![4]);
}

#[test]
fn obj_errors_name_the_line() {
    let e = read_err(b"v 0 0 0\nv 1 0 0\nf 1 2\n", MeshFormat::Obj);
    assert_eq!((e.line, e.message.as_str()), (3, "face 0: 2 vertices; a face needs at least 3"));
    let e = read_err(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n", MeshFormat::Obj);
    assert_eq!(e.line, 5);
    assert!(e.message.contains("face 1: vertex index 4 is out of range (the file has 3)"), "{e}");
    let e = read_err(b"v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", MeshFormat::Obj);
    assert_eq!(e.line, 3);
    assert!(e.message.contains("vertex index -3 is out of range (the file has 2 so far)"), "{e}");
    let e = read_err(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", MeshFormat::Obj);
    assert!(e.message.contains("vertex index 0 is out of range"), "{e}");
    let e = read_err(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n", MeshFormat::Obj);
    assert!(e.message.contains("texture index 2 is out of range"), "{e}");
    // Absurd texture indices where the file has texture coordinates (tobj would overflow).
    let e = read_err(b"v 0 0 0\nvt 0 0\nvn 0 0 1\nf 1//-2 1 1\n", MeshFormat::Obj);
    assert!(e.message.contains("normal index -2"), "{e}");
    let e = read_err(b"v 0 0 0\nf 1/x 1 1\n", MeshFormat::Obj);
    assert!(e.message.contains("`x` is not an index"), "{e}");
    let e = read_err(b"v 0 0 0\nf 1/1/1/1 1 1\n", MeshFormat::Obj);
    assert!(e.message.contains("too many indices"), "{e}");
    let e = read_err(b"v 0 0 0\nf /1 1 1\n", MeshFormat::Obj);
    assert!(e.message.contains("has no vertex index"), "{e}");
    // tobj's own errors, placed on their line.
    let e = read_err(b"# x\nv 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::Obj);
    assert_eq!(e.line, 3);
    assert!(e.message.contains("position parse error in `v 1 zero 0`"), "{e}");
    let e = read_err(b"v 0 0 0\nvn 0 1\n", MeshFormat::Obj);
    assert_eq!(e.line, 2);
    assert!(e.message.contains("normal parse error"), "{e}");
    let e = read_err(b"v 0 0 0 0\n", MeshFormat::Obj);
    assert!(e.message.contains("scaling (w) by zero"), "{e}");
    let e = read_err(b"v 0 0 0\n# \xff\xfe fine\nv 1 \xff 0\n", MeshFormat::Obj);
    assert_eq!((e.line, e.message.as_str()), (3, "the line is not UTF-8 text"));
    assert_eq!(e.to_string(), "OBJ parse error at line 3: the line is not UTF-8 text");
}

// ---- OFF ----

#[test]
fn off_variants_comments_and_colours() {
    let src = b"# header comment\nOFF # the keyword\n\n5 2 0\n0 0 0\n1 0 0 # a comment\n1 1 0\n  0 1 0\n\
0.5 0.5 1\n4 0 1 2 3 255 0 0\n3 0 1 4\n";
    let m = read(src, MeshFormat::Off);
    assert_eq!(m.positions.len(), 5);
    assert_eq!(faces(&m), vec![vec![0, 1, 2, 3], vec![0, 1, 4]]);
    assert_eq!(m.face_source, vec![10, 11]);
    // Counts on the keyword's line; colours and normals on the vertices.
    let m = read(b"COFF 3 1 0\n0 0 0 1 0 0 1\n1 0 0 0.5 0.5 0.5 1\n0 1 0 1 1 1 1\n3 2 1 0\n", MeshFormat::Off);
    assert_eq!(m.positions, vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.]]);
    let m = read(b"NOFF\n3 1 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n", MeshFormat::Off);
    assert_eq!(faces(&m), vec![vec![0, 1, 2]]);
    let m = read(
        b"STCNOFF\n3 1 3\n0 0 0 0 0 1 1 1 1 0 0\n1 0 0 0 0 1 7 1 0\n0 1 0 0 0 1 7 0 1\n3 0 1 2\n",
        MeshFormat::Off,
    );
    assert_eq!(m.positions[1], [1., 0., 0.]);
    // No keyword at all (Geomview allows it).
    let m = read(b"3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Off);
    assert_eq!(m.face_count(), 1);
}

#[test]
fn off_errors() {
    let e = read_err(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", MeshFormat::Off);
    assert_eq!((e.line, e.message.as_str()), (6, "face 0 has 2 vertices; a face needs at least 3"));
    let e = read_err(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", MeshFormat::Off);
    assert_eq!((e.line, e.message.as_str()), (6, "face 0: vertex index 3 is out of range (the file has 3 vertices)"));
    let e = read_err(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", MeshFormat::Off);
    assert_eq!(e.message, "face 0: expected 3 vertex indices, found 2");
    let e = read_err(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n", MeshFormat::Off);
    assert_eq!(e.message, "face 0: `-2` is not a vertex index");
    let e = read_err(b"OFF\n4000000000 1 0\n0 0 0\n", MeshFormat::Off);
    assert_eq!((e.line, e.message.as_str()), (3, "the file ends after 1 of 4000000000 vertices"));
    let e = read_err(b"OFF\n3 99999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Off);
    assert_eq!(e.message, "the file ends after 1 of 99999999999999 faces");
    let e = read_err(b"OFF\n3 1 0\n0 0 0\n1 x 0\n", MeshFormat::Off);
    assert_eq!((e.line, e.message.as_str()), (4, "vertex 1: expected three coordinates, found `1 x 0`"));
    let e = read_err(b"OFF\n3 one 0\n", MeshFormat::Off);
    assert_eq!((e.line, e.message.as_str()), (2, "expected the vertex and face counts, found `3 one 0`"));
    let e = read_err(b"OFF\n", MeshFormat::Off);
    assert_eq!(e.message, "the file ends before the vertex and face counts");
    let e = read_err(b"", MeshFormat::Off);
    assert_eq!(e.message, "empty file: no OFF header");
    let e = read_err(b"MESH\n", MeshFormat::Off);
    assert_eq!(e.message, "expected the OFF keyword, found `MESH`");
    let e = read_err(b"4OFF\n1 0 0\n0 0 0 1\n", MeshFormat::Off);
    assert!(e.unsupported && e.message.contains("4-dimensional"), "{e}");
    let e = read_err(b"OFF BINARY\n", MeshFormat::Off);
    assert!(e.unsupported, "{e}");
    // NaN and infinities are the shape layer's to report, with the vertex.
    let m = read(b"OFF\n3 1 0\nnan 0 0\ninf 0 0\n0 -inf 0\n3 0 1 2\n", MeshFormat::Off);
    assert!(m.positions[0][0].is_nan() && m.positions[2][1] == f64::NEG_INFINITY);
}

// ---- STL ----

const TETRA_STL: &str = "solid tetra  made by hand\n\
  facet normal 0 0 -1\n    outer loop\n      vertex 0 0 0\n      vertex 0 1 0\n      vertex 1 0 0\n    endloop\n  endfacet\n\
  FACET NORMAL 0 -1 0\n OUTER LOOP\n VERTEX 0 0 0\n VERTEX 1 0 0\n VERTEX 0 0 1\n ENDLOOP\n ENDFACET\n\
  facet normal -1 0 0 outer loop vertex 0 0 0 vertex 0 0 1 vertex 0 1 0 endloop endfacet\n\
  facet\tnormal 0.577 0.577 0.577\r\n outer loop\r\n vertex 1 0 0\r\n vertex 0 1 0\r\n vertex 0 0 1\r\n endloop\r\n endfacet\r\n\
endsolid tetra\n";

fn tetra_facets() -> Vec<[[f32; 3]; 3]> {
    let (p, t) = tetra();
    t.iter().map(|f| [to_f32(p[f[0] as usize]), to_f32(p[f[1] as usize]), to_f32(p[f[2] as usize])]).collect()
}

#[test]
fn stl_ascii_and_binary_agree() {
    let ascii = read(TETRA_STL.as_bytes(), MeshFormat::Stl);
    assert_eq!(ascii.positions.len(), 12, "facets keep their own vertices");
    assert_eq!(faces(&ascii)[3], vec![9, 10, 11]);
    assert_eq!(ascii.face_source, vec![2, 9, 16, 17]);
    assert!(ascii.source_is_line);
    let bin = read(&binary_stl(&[0; 80], &tetra_facets()), MeshFormat::Stl);
    assert!(!bin.source_is_line);
    assert_eq!(bin.face_source, vec![0, 1, 2, 3]);
    assert_eq!(
        (&bin.positions, &bin.indices, &bin.face_starts),
        (&ascii.positions, &ascii.indices, &ascii.face_starts)
    );
}

#[test]
fn stl_binary_that_starts_with_solid() {
    let mut header = [b' '; 80];
    header[..20].copy_from_slice(b"solid exported by XY");
    let bytes = binary_stl(&header, &tetra_facets());
    assert_eq!(MeshFormat::sniff(&bytes), Some(MeshFormat::Stl));
    let m = read(&bytes, MeshFormat::Stl);
    assert_eq!(m.face_count(), 4);
    assert!(!m.source_is_line);
    // Cut short, it still reads as binary (NUL bytes), and says where it ends.
    let e = read_err(&bytes[..bytes.len() - 7], MeshFormat::Stl);
    assert_eq!((e.line, e.offset), (0, 84 + 50 * 3));
    assert_eq!(e.message, "the file ends in facet 3 of 4 (a binary STL of 4 facets has 284 bytes, this one 277)");
    assert_eq!(e.to_string(), format!("STL parse error at byte 234: {}", e.message));
}

#[test]
fn stl_errors() {
    let e = read_err(b"\x00\x01 short", MeshFormat::Stl);
    assert!(e.message.contains("too short for a binary STL"), "{e}");
    let mut b = binary_stl(&[0; 80], &tetra_facets());
    b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let e = read_err(&b, MeshFormat::Stl);
    assert_eq!(e.offset, 284);
    assert!(e.message.starts_with("the file ends in facet 4 of 4294967295"), "{e}");
    let two = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n";
    let e = read_err(two.as_bytes(), MeshFormat::Stl);
    assert_eq!((e.line, e.message.as_str()), (2, "facet 0 has 2 vertices; a facet needs at least 3"));
    let e = read_err(b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n", MeshFormat::Stl);
    assert_eq!((e.line, e.message.as_str()), (5, "the file ends where a vertex coordinate should be"));
    let e = read_err(b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n", MeshFormat::Stl);
    assert_eq!((e.line, e.message.as_str()), (4, "expected a vertex coordinate, found `zero`"));
    let e = read_err(b"solid t\nfacet normal 0 0 1\ninner loop\n", MeshFormat::Stl);
    assert_eq!(e.message, "expected `outer`, found `inner`");
    let e = read_err(b"solid t\nvertex 1 2 3\n", MeshFormat::Stl);
    assert_eq!(e.message, "expected `facet` or `endsolid`, found `vertex`");
    // Several solids in one file, and a missing `endsolid`, are fine.
    let two_solids = format!("{TETRA_STL}solid again\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 endloop endfacet\n");
    assert_eq!(read(two_solids.as_bytes(), MeshFormat::Stl).face_count(), 5);
    assert_eq!(read(b"solid\nendsolid\n", MeshFormat::Stl).face_count(), 0);
}

// ---- PLY ----

const PLY_ASCII: &str = "ply\nformat ascii 1.0\ncomment made by hand\nobj_info nothing\n\
element vertex 4\nproperty float32 x\nproperty uchar red\nproperty double y\nproperty list uint8 int32 extra\nproperty int16 z\n\
element face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\nproperty float quality\n\
element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n\
0 255 0 2 7 7 0\n1 0 0 0 0\n1 9 1 0 0\n0 0 1 1 5 0\n\
0 4 0 1 2 3 0.5\n1 3\n  0 1 3 1.0\n0 1\n";

#[test]
fn ply_ascii_skips_what_it_does_not_need() {
    let m = read(PLY_ASCII.as_bytes(), MeshFormat::Ply);
    assert_eq!(m.positions, vec![[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]]);
    assert_eq!(faces(&m), vec![vec![0, 1, 2, 3], vec![0, 1, 3]]);
    // A face is on the line of its vertex count.
    assert_eq!(m.face_source, vec![23, 24]);
    assert!(m.source_is_line);
}

/// The same mesh as `PLY_ASCII`, binary little-endian.
fn ply_binary() -> Vec<u8> {
    let head = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float32 x\nproperty uchar red\n\
property double y\nproperty list uint8 int32 extra\nproperty int16 z\nelement face 2\nproperty uchar flags\n\
property list uchar int vertex_indices\nproperty float quality\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\r\n";
    let mut b = head.as_bytes().to_vec();
    let vertex = |b: &mut Vec<u8>, x: f32, y: f64, z: i16, extra: &[i32]| {
        b.extend_from_slice(&x.to_le_bytes());
        b.push(255);
        b.extend_from_slice(&y.to_le_bytes());
        b.push(extra.len() as u8);
        extra.iter().for_each(|e| b.extend_from_slice(&e.to_le_bytes()));
        b.extend_from_slice(&z.to_le_bytes());
    };
    vertex(&mut b, 0.0, 0.0, 0, &[7, 7]);
    vertex(&mut b, 1.0, 0.0, 0, &[]);
    vertex(&mut b, 1.0, 1.0, 0, &[]);
    vertex(&mut b, 0.0, 0.0, 1, &[5]);
    let face = |b: &mut Vec<u8>, idx: &[i32]| {
        b.push(0);
        b.push(idx.len() as u8);
        idx.iter().for_each(|e| b.extend_from_slice(&e.to_le_bytes()));
        b.extend_from_slice(&0.5f32.to_le_bytes());
    };
    face(&mut b, &[0, 1, 2, 3]);
    face(&mut b, &[0, 1, 3]);
    b.extend_from_slice(&0i32.to_le_bytes());
    b.extend_from_slice(&1i32.to_le_bytes());
    b
}

#[test]
fn ply_binary_reads_the_same_mesh() {
    let m = read(&ply_binary(), MeshFormat::Ply);
    assert_eq!(m.positions, vec![[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 0., 1.]]);
    assert_eq!(faces(&m), vec![vec![0, 1, 2, 3], vec![0, 1, 3]]);
    assert_eq!(m.face_source, vec![0, 1]);
    assert!(!m.source_is_line);
}

#[test]
fn ply_errors() {
    let b = ply_binary();
    // Cut in the edge element (skipped, but its data must be there).
    let e = read_err(&b[..b.len() - 2], MeshFormat::Ply);
    assert_eq!((e.line, e.offset), (0, b.len() - 4));
    assert_eq!(e.message, "the file ends in element `edge` record 0");
    // Cut in a face's index list.
    let cut = b.len() - 8 - 4 - 4 * 3 + 2;
    let e = read_err(&b[..cut], MeshFormat::Ply);
    assert_eq!(e.message, "the file ends in face 1");
    assert_eq!(e.offset, cut - 2);
    let big = String::from_utf8_lossy(&b).replace("little", "big");
    let e = read_err(big.as_bytes(), MeshFormat::Ply);
    assert!(e.unsupported);
    assert_eq!((e.line, e.message.as_str()), (2, "binary big-endian PLY is not read"));

    let ascii = |body: &str| {
        format!("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n{body}")
    };
    let e = read_err(ascii("0 0 0\n1 0 0\n0 1 0\n2 0 1\n").as_bytes(), MeshFormat::Ply);
    assert_eq!((e.line, e.message.as_str()), (13, "face 0 has 2 vertices; a face needs at least 3"));
    let e = read_err(ascii("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n").as_bytes(), MeshFormat::Ply);
    assert_eq!((e.line, e.message.as_str()), (13, "face 0: vertex index 3 is out of range (the file has 3 vertices)"));
    let e = read_err(ascii("0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n").as_bytes(), MeshFormat::Ply);
    assert!(e.message.contains("vertex index -1 is out of range"), "{e}");
    let e = read_err(ascii("0 0 0\n1 zero 0\n").as_bytes(), MeshFormat::Ply);
    assert_eq!((e.line, e.message.as_str()), (11, "vertex 1: `zero` is not a number"));
    let e = read_err(ascii("0 0 0\n1 0 0\n").as_bytes(), MeshFormat::Ply);
    assert_eq!(e.message, "the file ends in vertex 2");
    let e = read_err(ascii("0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n").as_bytes(), MeshFormat::Ply);
    assert_eq!(e.message, "face 0: `1.5` is not an integer");
    // A count far beyond the data: an error, no huge allocation.
    let huge = ascii("0 0 0\n").replace("vertex 3", "vertex 18446744073709551615");
    let e = read_err(huge.as_bytes(), MeshFormat::Ply);
    assert!(e.message.contains("the file ends in vertex 1") || e.message.contains("more than medax reads"), "{e}");

    let header = |h: &str| read_err(format!("ply\nformat ascii 1.0\n{h}\nend_header\n").as_bytes(), MeshFormat::Ply);
    assert_eq!(
        header("element vertex 1\nproperty float x\nproperty float y").message,
        "the vertex element has no `z` property"
    );
    assert_eq!(header("element vertex 1\nproperty quad x").message, "`quad` is not a PLY type");
    assert_eq!(header("property float x").message, "a property before any element");
    assert_eq!(header("element vertex many").message, "element `vertex`: `many` is not a count");
    assert_eq!(header("bogus line").message, "unknown header line `bogus`");
    assert_eq!(header("element vertex 0\nproperty float x\nproperty float y\nproperty float z\nelement face 0\nproperty list uchar float vertex_indices").message, "vertex indices must have an integer type");
    assert_eq!(
        header("element face 0\nproperty int vertex_indices").message,
        "the face property `vertex_indices` is no list"
    );
    assert_eq!(header("element face 0").message, "the face element has no `vertex_indices` property");
    assert_eq!(header("").message, "the header has no `vertex` element");
    let e = read_err(b"ply\nformat ascii 1.0\nelement vertex 1\n", MeshFormat::Ply);
    assert_eq!((e.line, e.message.as_str()), (3, "the file ends before `end_header`"));
    let e = read_err(
        b"ply\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
        MeshFormat::Ply,
    );
    assert_eq!((e.line, e.message.as_str()), (6, "the header has no `format` line"));
    let e = read_err(b"plyx\n", MeshFormat::Ply);
    assert_eq!((e.line, e.message.as_str()), (1, "the first line is not `ply`"));
    // Elements without properties take no bytes, whatever their count.
    let m = read(
        ascii("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
            .replace("element face 1", "element nothing 18446744073709551615\nelement face 1")
            .as_bytes(),
        MeshFormat::Ply,
    );
    assert_eq!(m.face_count(), 1);
}

// ---- writers ----

#[test]
fn writers_round_trip_exactly() {
    let mut positions = awkward_positions();
    positions.extend(tetra().0);
    let triangles = vec![[0, 1, 2], [3, 4, 5], [8, 7, 6], [0, 4, 8]];
    let expected_faces: Vec<Vec<u32>> = triangles.iter().map(|t| t.to_vec()).collect();
    let texts: Vec<(MeshFormat, Vec<u8>)> = vec![
        (MeshFormat::Obj, write_obj(&positions, &triangles).into_bytes()),
        (MeshFormat::Off, write_off(&positions, &triangles).into_bytes()),
        (MeshFormat::Ply, write_ply(&positions, &triangles, false)),
        (MeshFormat::Ply, write_ply(&positions, &triangles, true)),
    ];
    for (format, bytes) in texts {
        assert_eq!(MeshFormat::sniff(&bytes), Some(format));
        let m = read(&bytes, format);
        assert!(same_bits(&m.positions, &positions), "{format:?}: {:?}", m.positions);
        assert_eq!(faces(&m), expected_faces, "{format:?}");
    }
    // Empty meshes too.
    for (format, bytes) in [
        (MeshFormat::Obj, write_obj(&[], &[]).into_bytes()),
        (MeshFormat::Off, write_off(&[], &[]).into_bytes()),
        (MeshFormat::Ply, write_ply(&[], &[], true)),
    ] {
        let m = read(&bytes, format);
        assert!(m.positions.is_empty() && m.face_count() == 0, "{format:?}");
    }
    assert_eq!(write_off(&tetra().0[..3], &[[0, 1, 2]]), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    assert_eq!(write_obj(&tetra().0[..3], &[[0, 1, 2]]), "# medax\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
}

// ---- the sample files (also the fuzz target's seeds) ----

#[test]
fn sample_files_read_and_sniff() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mesh");
    let mut files: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    let mut got = Vec::new();
    for p in &files {
        let bytes = std::fs::read(p).unwrap();
        let format = MeshFormat::from_path(p);
        assert_eq!(MeshFormat::sniff(&bytes), format, "{}", p.display());
        let m = read(&bytes, format.unwrap());
        got.push((p.file_stem().unwrap().to_string_lossy().into_owned(), m.positions.len(), m.face_count()));
    }
    let expected = [
        ("obj_crlf", 3, 1),
        ("obj_quad", 5, 2),
        ("off_basic", 4, 2),
        ("off_coff", 3, 1),
        ("off_noff", 3, 1),
        ("ply_ascii", 4, 2),
        ("ply_binary", 3, 1),
        ("stl_ascii", 6, 2),
        ("stl_binary", 6, 2),
        ("stl_binary_solid", 6, 2),
    ];
    let expected: Vec<_> = expected.iter().map(|&(n, v, f)| (n.to_string(), v, f)).collect();
    assert_eq!(got, expected);
}

// ---- CGAL's sample files ----

/// CGAL's sample meshes (libcgal-demo's data.tar.gz), unpacked once into a
/// temporary folder; `None`, with a note, where they are not installed.
fn cgal_meshes() -> Option<std::path::PathBuf> {
    let tarball = Path::new("/usr/share/doc/libcgal-dev/data.tar.gz");
    if !tarball.exists() {
        eprintln!("note: {} is absent (apt-get install libcgal-demo); CGAL sample files skipped", tarball.display());
        return None;
    }
    let dir = std::env::temp_dir().join(format!("medax-cgal-data-{}", std::process::id()));
    std::fs::create_dir_all(&dir).ok()?;
    let ok = std::process::Command::new("tar")
        .args(["xzf", tarball.to_str()?, "-C", dir.to_str()?, "--wildcards", "*.off", "*.stl", "*.ply"])
        .status()
        .is_ok_and(|s| s.success());
    if !ok {
        eprintln!("note: could not unpack {}; CGAL sample files skipped", tarball.display());
        return None;
    }
    Some(dir)
}

fn files_with_extension(dir: &Path, ext: &str, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let p = e.path();
        if p.is_dir() {
            files_with_extension(&p, ext, out);
        } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case(ext)) {
            out.push(p);
        }
    }
}

#[test]
fn cgal_sample_files_read() {
    let Some(dir) = cgal_meshes() else { return };
    let mut off = Vec::new();
    files_with_extension(&dir, "off", &mut off);
    assert!(off.len() > 50, "found only {} OFF files", off.len());
    let mut failed = Vec::new();
    for p in &off {
        let bytes = std::fs::read(p).unwrap();
        assert_eq!(MeshFormat::sniff(&bytes), Some(MeshFormat::Off), "{}", p.display());
        match read_mesh(&bytes, None) {
            Ok(m) => check_invariants(&m),
            Err(e) => failed.push(format!("{}: {e}", p.display())),
        }
    }
    // The PLY files (meshes and point clouds, ASCII and binary) and the STL ones.
    let mut others = Vec::new();
    files_with_extension(&dir, "ply", &mut others);
    files_with_extension(&dir, "stl", &mut others);
    assert!(others.len() > 10, "found only {} PLY and STL files", others.len());
    for p in &others {
        let bytes = std::fs::read(p).unwrap();
        let format = MeshFormat::from_path(p);
        assert_eq!(MeshFormat::sniff(&bytes), format, "{}", p.display());
        match read_mesh(&bytes, format) {
            Ok(m) => check_invariants(&m),
            Err(e) => failed.push(format!("{}: {e}", p.display())),
        }
    }
    let count = |name: &str| {
        let p = dir.join("data/meshes").join(name);
        let m = read_mesh(&std::fs::read(&p).unwrap(), None).unwrap_or_else(|e| panic!("{name}: {e}"));
        let quads = (0..m.face_count()).filter(|&i| m.face(i).len() == 4).count();
        (m.positions.len(), m.face_count(), quads)
    };
    let expected = [
        ("elephant.off", (2775, 5558, 0)),
        ("lion-head.off", (8356, 16674, 0)),
        ("sphere.off", (162, 320, 0)),
        ("cube-meshed.off", (866, 1728, 0)),
        ("torus_quad.off", (25, 25, 25)),
        ("cactus.off", (620, 1236, 0)),
        ("mesh_with_colors.off", (8, 4, 0)),
        ("cube4-shuffled.off", (8, 6, 6)),
        ("sphere.ply", (162, 320, 0)),
        ("colored_tetra.ply", (4, 4, 0)),
        ("pig.stl", (0, 0, 0)),
        ("sphere.stl", (0, 0, 0)),
    ];
    for (name, (nv, nf, quads)) in expected {
        let got = count(name);
        if name.ends_with(".stl") {
            // Binary STL: three vertices of its own per facet.
            assert!(got.1 > 0 && got.0 == 3 * got.1 && got.2 == 0, "{name}: {got:?}");
        } else {
            assert_eq!(got, (nv, nf, quads), "{name}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failed.is_empty(), "CGAL files that did not read:\n{}", failed.join("\n"));
}
