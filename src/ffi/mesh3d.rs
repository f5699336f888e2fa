//! C functions for solids (`mx_mesh3d`): read from files, memory or
//! arrays, validated; counts, facts, components, vertices and triangles;
//! written back as OBJ, OFF or PLY. Mirrors `crate::shape::Mesh3d`.

use super::boundary::{c_str, check_threads, fill_items, guard, in_pool, nth, slice};
use super::handles::{arg, create, free, impl_options, options_init, query, Boxed, Handle, Options};
use super::last_error::{mx_error_info, FfiError};
use super::shape_kinds::mesh_format_of;
use super::status::mx_status;
use crate::io::mesh::{write_obj, write_off, write_ply, MeshFormat};
use crate::shape::{Mesh3d, MeshError, MeshOptions};
use std::ffi::c_char;
use std::mem::size_of;

/// A validated triangulated solid: closed, manifold, triangles facing out
/// of the material, components nested (cavities). Opaque; create with
/// `mx_mesh3d_from_*`, release with `mx_mesh3d_free`. Immutable: a `const
/// mx_mesh3d*` may be used from several threads at once.
pub struct mx_mesh3d {
    pub(crate) inner: Mesh3d,
}

impl Handle for mx_mesh3d {
    const ARG: &'static str = "mesh";
    type Ownership = Boxed;
}

/// How a solid is read. Initialise with `mx_mesh_options_init(&o, sizeof
/// o)` (which sets `struct_size`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_mesh_options {
    /// `sizeof(mx_mesh_options)` as the caller was compiled.
    pub struct_size: usize,
    /// Vertices closer than this (model units) become one; 0 (default)
    /// merges exactly equal positions only.
    pub weld_tolerance: f64,
    /// Worker threads: 0 = all cores (default), else at most
    /// `MX_AXIS_MAX_THREADS`.
    pub threads: usize,
}

impl_options!(mx_mesh_options, v1: 24 bytes up to threads: usize, defaults: mx_mesh_options {
    struct_size: size_of::<Self>(),
    weld_tolerance: 0.0,
    threads: 0,
});

/// Fills the caller's `mx_mesh_options` with the defaults: `size` is its
/// `sizeof`; at most that many bytes are written.
///
/// # Safety
/// `out` NULL or `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh_options_init(out: *mut mx_mesh_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// Facts of a solid.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_mesh3d_info {
    /// Vertices (welded; each used by a triangle).
    pub vertex_count: usize,
    /// Triangles (polygon faces cut into triangles).
    pub triangle_count: usize,
    /// Connected surfaces: outer surfaces and cavities.
    pub component_count: usize,
    /// Volume of material (cavities subtracted), cubic model units.
    pub volume: f64,
    /// Surface area, square model units.
    pub area: f64,
    /// Smallest corner of the bounding box.
    pub min: [f64; 3],
    /// Largest corner of the bounding box.
    pub max: [f64; 3],
    /// Input vertices merged into an equal (or, with a tolerance, close)
    /// earlier one.
    pub welded: usize,
    /// Input vertices no face uses, dropped.
    pub unused_vertices: usize,
    /// Polygon faces cut into triangles.
    pub polygons_triangulated: usize,
    /// Triangles reversed to agree with their neighbours.
    pub triangles_reoriented: usize,
    /// Components reversed because they faced into the material.
    pub components_reversed: usize,
}

/// One connected surface of a solid.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_mesh3d_component {
    /// Its triangles.
    pub triangle_count: usize,
    /// Its vertices.
    pub vertex_count: usize,
    /// Genus (0: sphere-like, 1: torus-like, …).
    pub genus: usize,
    /// Signed volume (negative for a cavity).
    pub volume: f64,
    /// Surface area.
    pub area: f64,
    /// Smallest corner of its bounding box.
    pub min: [f64; 3],
    /// Largest corner of its bounding box.
    pub max: [f64; 3],
    /// 1 when `parent` holds the component directly around it.
    pub has_parent: i32,
    /// The component directly around it (valid when `has_parent` is 1).
    pub parent: usize,
    /// How many components are around it: odd for a cavity.
    pub depth: usize,
    /// 1 when medax reversed it (it faced into the material).
    pub reversed: i32,
}

impl From<MeshError> for FfiError {
    fn from(e: MeshError) -> FfiError {
        use mx_status::*;
        let status = match &e {
            MeshError::Parse(p) if p.unsupported => MX_ERR_UNSUPPORTED,
            MeshError::Parse(_) => MX_ERR_PARSE,
            MeshError::Io { .. } => MX_ERR_IO,
            MeshError::Empty => MX_ERR_EMPTY,
            MeshError::NonFinite { .. } => MX_ERR_NON_FINITE,
            MeshError::TooLarge { .. } => MX_ERR_OUT_OF_RANGE,
            MeshError::IndexOutOfRange { .. } => MX_ERR_INVALID_ARGUMENT,
            MeshError::DegenerateFace { .. } | MeshError::FlatComponent { .. } => MX_ERR_DEGENERATE,
            MeshError::OpenEdge { .. } => MX_ERR_NOT_CLOSED,
            MeshError::SelfIntersection { .. } => MX_ERR_INTERSECTION,
            MeshError::NonManifoldEdge { .. }
            | MeshError::NonManifoldVertex { .. }
            | MeshError::NonOrientable { .. } => MX_ERR_NOT_MANIFOLD,
        };
        let mut info = mx_error_info::none(status);
        let i = |v: usize| v as i64;
        match &e {
            MeshError::Parse(p) => {
                (info.line, info.column) = if p.line > 0 { (i(p.line), -1) } else { (0, i(p.offset)) };
            }
            MeshError::NonFinite { vertex } | MeshError::TooLarge { vertex } => info.other_element = i(*vertex),
            MeshError::NonManifoldVertex { vertex, .. } => info.other_element = i(*vertex),
            MeshError::IndexOutOfRange { face, .. }
            | MeshError::DegenerateFace { face }
            | MeshError::NonOrientable { face }
            | MeshError::FlatComponent { face, .. } => {
                info.element = i(face.face);
                info.line = if face.line > 0 { i(face.line) } else { -1 };
            }
            MeshError::OpenEdge { edge, face } | MeshError::NonManifoldEdge { edge, face, .. } => {
                info.element = i(face.face);
                info.other_element = i(edge[0]);
                info.line = if face.line > 0 { i(face.line) } else { -1 };
            }
            MeshError::SelfIntersection { faces } => {
                info.element = i(faces[0].face);
                info.other_element = i(faces[1].face);
                info.line = if faces[0].line > 0 { i(faces[0].line) } else { -1 };
            }
            MeshError::Io { .. } | MeshError::Empty => {}
        }
        FfiError { info, message: e.to_string() }
    }
}

/// The options C gave, or the defaults for NULL.
///
/// # Safety
/// `p` NULL or a valid `mx_mesh_options` of at least its `struct_size`.
unsafe fn read_options(p: *const mx_mesh_options) -> Result<(MeshOptions, usize), FfiError> {
    // SAFETY: forwarded contract.
    let Some(o) = (unsafe { mx_mesh_options::read(p)? }) else {
        return Ok((MeshOptions::default(), 0));
    };
    check_threads("mx_mesh_options", o.threads)?;
    if !(o.weld_tolerance.is_finite() && o.weld_tolerance >= 0.0) {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("mx_mesh_options.weld_tolerance = {}: use 0 or a positive length", o.weld_tolerance),
        ));
    }
    Ok((MeshOptions { weld_tolerance: o.weld_tolerance }, o.threads))
}

fn built(threads: usize, build: impl FnOnce() -> Result<Mesh3d, MeshError> + Send) -> Result<mx_mesh3d, FfiError> {
    Ok(mx_mesh3d { inner: in_pool(threads, build)?? })
}

/// Reads and validates a solid: OBJ, OFF, STL (ASCII or binary) or PLY
/// (ASCII or binary little-endian); `format` an `mx_format`
/// (`MX_FORMAT_AUTO`: by extension, else by content). A surface that is
/// not a solid's gives its typed error (`MX_ERR_NOT_CLOSED`,
/// `MX_ERR_NOT_MANIFOLD`, `MX_ERR_INTERSECTION`, `MX_ERR_DEGENERATE`, …)
/// with the face (`element`), the vertex or, for crossing faces, the
/// second face (`other_element`) and the file line in `mx_last_error_info`.
///
/// # Safety
/// `path` NULL or NUL-terminated UTF-8; `options` NULL or valid; `out`
/// writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_from_file(
    path: *const c_char,
    format: u32,
    options: *const mx_mesh_options,
    out: *mut *mut mx_mesh3d,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let path = std::path::Path::new(c_str(path, "path")?);
            let format = mesh_format_of(format)?.or_else(|| MeshFormat::from_path(path));
            let (o, threads) = read_options(options)?;
            let bytes = std::fs::read(path)
                .map_err(|e| FfiError::new(mx_status::MX_ERR_IO, format!("cannot read {}: {e}", path.display())))?;
            built(threads, || Mesh3d::from_bytes(&bytes, format, &o))
        })
    }
}

/// Reads and validates a solid from `len` bytes of a file's content
/// (`MX_FORMAT_AUTO` guesses from the content).
///
/// # Safety
/// `data` NULL (only when `len` is 0) or `len` readable bytes; `options`
/// NULL or valid; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_from_memory(
    data: *const u8,
    len: usize,
    format: u32,
    options: *const mx_mesh_options,
    out: *mut *mut mx_mesh3d,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let bytes = slice(data, len, "data")?;
            let format = mesh_format_of(format)?;
            let (o, threads) = read_options(options)?;
            built(threads, || Mesh3d::from_bytes(bytes, format, &o))
        })
    }
}

/// A solid from arrays: `xyz` (`xyz_len` doubles, 3 per vertex) and
/// `triangles` (`triangles_len` indices, 3 per triangle, 0-based), in
/// either orientation; validated as a file is.
///
/// # Safety
/// `xyz` and `triangles` NULL (only with length 0) or readable for their
/// lengths; `options` NULL or valid; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_from_arrays(
    xyz: *const f64,
    xyz_len: usize,
    triangles: *const u32,
    triangles_len: usize,
    options: *const mx_mesh_options,
    out: *mut *mut mx_mesh3d,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let bad = |what: &str, n: usize| {
                FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("{what} = {n} is not a multiple of 3"))
            };
            if xyz_len % 3 != 0 {
                return Err(bad("xyz_len", xyz_len));
            }
            if triangles_len % 3 != 0 {
                return Err(bad("triangles_len", triangles_len));
            }
            let xyz = slice(xyz, xyz_len, "xyz")?;
            let tris = slice(triangles, triangles_len, "triangles")?;
            let (o, threads) = read_options(options)?;
            let points: Vec<[f64; 3]> = xyz.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
            let tris: Vec<[u32; 3]> = tris.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
            built(threads, || Mesh3d::from_triangles(&points, &tris, &o))
        })
    }
}

/// Releases a `mx_mesh3d`. NULL is a no-op.
///
/// # Safety
/// `mesh` must be NULL or a handle returned by medax and not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_free(mesh: *mut mx_mesh3d) {
    // SAFETY: forwarded contract.
    unsafe { free(mesh) }
}

/// The solid's facts.
///
/// # Safety
/// `mesh` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_get_info(mesh: *const mx_mesh3d, out: *mut mx_mesh3d_info) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(mesh, out, |m| {
            let (m, r) = (&m.inner, m.inner.report());
            let b = m.bbox();
            Ok(mx_mesh3d_info {
                vertex_count: m.positions().len(),
                triangle_count: m.triangles().len(),
                component_count: m.components().len(),
                volume: m.volume(),
                area: m.area(),
                min: b.min.to_array(),
                max: b.max.to_array(),
                welded: r.welded,
                unused_vertices: r.unused_vertices,
                polygons_triangulated: r.polygons_triangulated,
                triangles_reoriented: r.triangles_reoriented,
                components_reversed: r.components_reversed,
            })
        })
    }
}

/// Component `index` (0 ≤ index < `component_count`).
///
/// # Safety
/// `mesh` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_get_component(
    mesh: *const mx_mesh3d,
    index: usize,
    out: *mut mx_mesh3d_component,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(mesh, out, |m| {
            let c = nth(m.inner.components(), index, "component")?;
            Ok(mx_mesh3d_component {
                triangle_count: c.triangles,
                vertex_count: c.vertices,
                genus: c.genus,
                volume: c.volume,
                area: c.area,
                min: c.bbox.min.to_array(),
                max: c.bbox.max.to_array(),
                has_parent: i32::from(c.parent.is_some()),
                parent: c.parent.unwrap_or(0),
                depth: c.depth,
                reversed: i32::from(c.reversed),
            })
        })
    }
}

/// Copies the vertices as x, y, z triples into `xyz` of `capacity`
/// vertices and writes their number to `*count` (capacity 0: size query;
/// a shorter buffer: `MX_ERR_BUFFER_TOO_SMALL`, nothing written).
///
/// # Safety
/// `mesh` NULL or a live handle; `xyz` NULL or `3 * capacity` writable
/// doubles; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_vertices(
    mesh: *const mx_mesh3d,
    xyz: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let m = unsafe { arg(mesh)? };
        let p = m.inner.positions();
        let n = p.len();
        // SAFETY: caller contract.
        unsafe {
            fill_items((xyz, "xyz"), (capacity, count), (n, 3), p.iter().flat_map(|q| q.to_array()), || {
                format!("the solid has {n} vertices, the buffer room for {capacity}")
            })
        }
    })
}

/// Copies the triangles as vertex index triples (0-based, counter-clockwise
/// seen from outside the material) into `abc` of `capacity` triangles and
/// writes their number to `*count` (the buffer protocol of
/// `mx_mesh3d_vertices`).
///
/// # Safety
/// `mesh` NULL or a live handle; `abc` NULL or `3 * capacity` writable
/// `uint32_t`; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_triangles(
    mesh: *const mx_mesh3d,
    abc: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let m = unsafe { arg(mesh)? };
        let t = m.inner.triangles();
        let n = t.len();
        // SAFETY: caller contract.
        unsafe {
            fill_items((abc, "abc"), (capacity, count), (n, 3), t.iter().flatten().copied(), || {
                format!("the solid has {n} triangles, the buffer room for {capacity}")
            })
        }
    })
}

/// Writes the solid to `path` as OBJ, OFF or PLY (binary little-endian):
/// `format` `MX_FORMAT_OBJ`, `MX_FORMAT_OFF`, `MX_FORMAT_PLY`, or
/// `MX_FORMAT_AUTO` by the path's extension. STL is not written (it would
/// lose the shared vertices).
///
/// # Safety
/// `mesh` NULL or a live handle; `path` NULL or NUL-terminated UTF-8.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_write(mesh: *const mx_mesh3d, path: *const c_char, format: u32) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let (m, path) = unsafe { (arg(mesh)?, std::path::Path::new(c_str(path, "path")?)) };
        let format = mesh_format_of(format)?.or_else(|| MeshFormat::from_path(path));
        let p: Vec<[f64; 3]> = m.inner.positions().iter().map(|q| q.to_array()).collect();
        let t = m.inner.triangles();
        let bytes = match format {
            Some(MeshFormat::Obj) => write_obj(&p, t).into_bytes(),
            Some(MeshFormat::Off) => write_off(&p, t).into_bytes(),
            Some(MeshFormat::Ply) => write_ply(&p, t, true),
            _ => {
                return Err(FfiError::new(
                    mx_status::MX_ERR_INVALID_ARGUMENT,
                    format!("write {}: use MX_FORMAT_OBJ, MX_FORMAT_OFF or MX_FORMAT_PLY", path.display()),
                ))
            }
        };
        std::fs::write(path, bytes)
            .map_err(|e| FfiError::new(mx_status::MX_ERR_IO, format!("cannot write {}: {e}", path.display())))
    })
}
