//! Any bytes through the mesh readers: the first byte picks the format
//! (OBJ, OFF, STL, PLY, or sniffing), the rest is the file. Each read must
//! return Ok or a typed error, never panic or hang, and a mesh it returns
//! must keep the promises of `RawMesh`: face starts from 0 to the end of
//! the indices, every face at least 3 long, every index a vertex, one
//! source per face. A mesh that passes is written back (as triangle fans)
//! and must read again with the same positions.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::io::mesh::{read_mesh, write_obj, write_off, write_ply, MeshFormat, RawMesh};

fn check(m: &RawMesh) {
    assert_eq!(m.face_starts.first(), Some(&0));
    assert_eq!(m.face_starts.last().map(|&s| s as usize), Some(m.indices.len()));
    assert!(m.face_starts.windows(2).all(|w| w[0] <= w[1] && w[1] - w[0] >= 3), "{:?}", m.face_starts);
    assert_eq!(m.face_source.len(), m.face_count());
    assert!(m.indices.iter().all(|&i| (i as usize) < m.positions.len()));
    for i in 0..m.face_count() {
        assert!(m.face(i).len() >= 3);
    }
}

/// The same doubles, bit for bit (so -0 is not 0), except that a NaN's
/// payload is not kept: text has one NaN.
fn same(a: &[[f64; 3]], b: &[[f64; 3]]) -> bool {
    let eq = |x: &f64, y: &f64| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
    a.len() == b.len() && a.iter().zip(b).all(|(p, q)| p.iter().zip(q).all(|(x, y)| eq(x, y)))
}

fuzz_target!(|data: &[u8]| {
    let Some((&choice, file)) = data.split_first() else { return };
    let format = match choice % 5 {
        0 => Some(MeshFormat::Obj),
        1 => Some(MeshFormat::Off),
        2 => Some(MeshFormat::Stl),
        3 => Some(MeshFormat::Ply),
        _ => None,
    };
    let Ok(m) = read_mesh(file, format) else { return };
    check(&m);
    // The writers and readers agree on every mesh a reader returns: its
    // positions (infinities and -0 too) come back bit for bit.
    let fans: Vec<[u32; 3]> = (0..m.face_count())
        .flat_map(|i| {
            let f = m.face(i);
            (1..f.len() - 1).map(move |j| [f[0], f[j], f[j + 1]])
        })
        .collect();
    for (fmt, bytes) in [
        (MeshFormat::Obj, write_obj(&m.positions, &fans).into_bytes()),
        (MeshFormat::Off, write_off(&m.positions, &fans).into_bytes()),
        (MeshFormat::Ply, write_ply(&m.positions, &fans, choice & 0x80 != 0)),
    ] {
        let again =
            read_mesh(&bytes, Some(fmt)).unwrap_or_else(|e| panic!("{fmt:?} writer gave an unreadable file: {e}"));
        check(&again);
        assert!(same(&again.positions, &m.positions), "{fmt:?} round trip changed positions");
        assert_eq!(again.face_count(), fans.len());
    }
});
