//! Helpers for the tests that call the C ABI from Rust as a C caller would.

use medax::ffi::*;
use medax::shape::{Mesh3d, MeshOptions};
use std::ffi::CStr;
use std::ptr::{null, null_mut};

/// A triangle soup as a Rust solid and as a C handle (`mx_mesh3d_from_arrays`).
pub fn c_solid((v, t): &(Vec<[f64; 3]>, Vec<[u32; 3]>)) -> (Mesh3d, *mut mx_mesh3d) {
    let rust = Mesh3d::from_triangles(v, t, &MeshOptions::default()).unwrap();
    let xyz: Vec<f64> = v.iter().flatten().copied().collect();
    let abc: Vec<u32> = t.iter().flatten().copied().collect();
    let mut m = null_mut();
    let st = unsafe { mx_mesh3d_from_arrays(xyz.as_ptr(), xyz.len(), abc.as_ptr(), abc.len(), null(), &mut m) };
    assert_eq!(st, mx_status::MX_OK, "{}", last_message());
    (rust, m)
}

/// The thread's last error message.
pub fn last_message() -> String {
    let n = unsafe { mx_last_error_message(null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; n.max(1)];
    unsafe { mx_last_error_message(buf.as_mut_ptr(), buf.len()) };
    unsafe { CStr::from_ptr(buf.as_ptr()) }.to_string_lossy().into_owned()
}

/// A ball from its text form (`square`, `ngon:6:10`, JSON, ...).
pub fn ball(spec: &str) -> *mut mx_ball {
    let text = std::ffi::CString::new(spec).unwrap();
    let mut b = null_mut();
    assert_eq!(unsafe { mx_ball_parse(text.as_ptr(), &mut b) }, mx_status::MX_OK);
    b
}

/// The ball's vertices, counter-clockwise.
pub fn ball_vertices(b: *const mx_ball) -> Vec<(f64, f64)> {
    let (mut n, mut queried, mut written) = (0, 0, 0);
    assert_eq!(unsafe { mx_ball_vertex_count(b, &mut n) }, mx_status::MX_OK);
    assert_eq!(unsafe { mx_ball_vertices(b, std::ptr::null_mut(), 0, &mut queried) }, mx_status::MX_OK);
    assert_eq!(queried, n, "size query and vertex count disagree");
    let mut xy = vec![0.0; 2 * n];
    if n > 1 {
        // One vertex short: refused, nothing written.
        let st = unsafe { mx_ball_vertices(b, xy.as_mut_ptr(), n - 1, &mut written) };
        assert_eq!(st, mx_status::MX_ERR_BUFFER_TOO_SMALL);
        assert!(xy.iter().all(|&v| v == 0.0) && written == 0);
    }
    assert_eq!(unsafe { mx_ball_vertices(b, xy.as_mut_ptr(), n, &mut written) }, mx_status::MX_OK);
    assert_eq!(written, n);
    xy.chunks_exact(2).map(|c| (c[0], c[1])).collect()
}

/// The gauge of `x` under the ball with counter-clockwise vertices `v`,
/// from its facets (independent of the library's own).
pub fn gauge(v: &[(f64, f64)], x: (f64, f64)) -> f64 {
    let k = v.len();
    (0..k)
        .map(|i| {
            let (p, q) = (v[i], v[(i + 1) % k]);
            let (dx, dy) = (q.0 - p.0, q.1 - p.1);
            // Facet a with a·p = 1.
            let (ax, ay) = (dy, -dx);
            let s = ax * p.0 + ay * p.1;
            (ax * x.0 + ay * x.1) / s
        })
        .fold(0.0, f64::max)
}
