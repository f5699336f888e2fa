//! Writers of triangle meshes: OBJ, OFF and PLY (ASCII or binary
//! little-endian).
//!
//! Coordinates go out with `{}` of `f64`, the shortest text that reads back
//! to the same double, so a write and a read give the very same numbers (and
//! NaN or infinities come back as such; the readers pass them through).
//! The triangles' indices are written as given: the caller's mesh is
//! trusted, these are no validators.

use std::fmt::Write as _;

/// An OBJ file: `v x y z` lines, then `f a b c` lines (1-based indices).
pub fn write_obj(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> String {
    let mut out = String::with_capacity(32 * positions.len() + 24 * triangles.len() + 32);
    out.push_str("# medax\n");
    for [x, y, z] in positions {
        let _ = writeln!(out, "v {x} {y} {z}");
    }
    for [a, b, c] in triangles {
        let _ = writeln!(out, "f {} {} {}", u64::from(*a) + 1, u64::from(*b) + 1, u64::from(*c) + 1);
    }
    out
}

/// An OFF file: the keyword, the counts, the vertices, then `3 a b c` faces.
pub fn write_off(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> String {
    let mut out = String::with_capacity(32 * positions.len() + 24 * triangles.len() + 32);
    let _ = writeln!(out, "OFF\n{} {} 0", positions.len(), triangles.len());
    for [x, y, z] in positions {
        let _ = writeln!(out, "{x} {y} {z}");
    }
    for [a, b, c] in triangles {
        let _ = writeln!(out, "3 {a} {b} {c}");
    }
    out
}

/// A PLY file with `double` coordinates and faces as a `uchar` count and
/// `uint` indices; `binary` gives `binary_little_endian` data, otherwise
/// ASCII.
pub fn write_ply(positions: &[[f64; 3]], triangles: &[[u32; 3]], binary: bool) -> Vec<u8> {
    let format = if binary { "binary_little_endian" } else { "ascii" };
    let mut head = String::new();
    let _ = write!(
        head,
        "ply\nformat {format} 1.0\ncomment medax\nelement vertex {}\n\
         property double x\nproperty double y\nproperty double z\n\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        positions.len(),
        triangles.len()
    );
    let mut out = head.into_bytes();
    if binary {
        out.reserve(24 * positions.len() + 13 * triangles.len());
        for p in positions {
            p.iter().for_each(|c| out.extend_from_slice(&c.to_le_bytes()));
        }
        for t in triangles {
            out.push(3);
            t.iter().for_each(|i| out.extend_from_slice(&i.to_le_bytes()));
        }
    } else {
        let mut body = String::with_capacity(32 * positions.len() + 24 * triangles.len());
        for [x, y, z] in positions {
            let _ = writeln!(body, "{x} {y} {z}");
        }
        for [a, b, c] in triangles {
            let _ = writeln!(body, "3 {a} {b} {c}");
        }
        out.extend_from_slice(body.as_bytes());
    }
    out
}
