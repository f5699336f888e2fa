//! Handles and options structs, and the generic functions every export
//! uses on them (rustls-ffi's `Castable`, simplified: the C type is the
//! Rust type, so no casts between the two are needed).
//!
//! How C holds a handle is stated in types, not only in prose:
//! * [`Handle::Ownership`] says how C owns the handles it creates: today
//!   every handle is [`Boxed`] (made by `Box::into_raw` in [`create`] or
//!   [`into_raw`], given back exactly once to its `_free`, which is
//!   [`free`]);
//! * [`Lends`] says which handle lends C a pointer into itself
//!   (`mx_voronoi` its `mx_axis`, `mx_vcarve` its flat `mx_offset_layer`,
//!   through [`lend`]): such a pointer lives as long as its owner and must
//!   never reach a `_free`.
//!
//! Adding a handle type `mx_foo` costs a few lines:
//! 1. `pub struct mx_foo { .. }` with its doc comment (cbindgen makes it
//!    opaque);
//! 2. `impl Handle for mx_foo { const ARG: &'static str = "foo"; type
//!    Ownership = Boxed; }` (`ARG` is the name of its argument in every
//!    export, for the NULL message);
//! 3. the exports, each its written-out `#[no_mangle] pub unsafe extern "C"
//!    fn` (cbindgen reads the signature and doc comment) around one generic
//!    call: `create(out, || Ok(mx_foo { .. }))` or `compute(out, input,
//!    options, |input, o| ..)` to make one, `query(foo, out, |f| ..)` to
//!    read it, `free(foo)`; a handle lent by another also gets `impl
//!    Lends<mx_foo> for mx_owner`, and the owner's export is `lend(owner,
//!    out)`.
//!
//! An options struct `mx_foo_options` (`#[repr(C)]`, first field
//! `struct_size`) gets [`Options`] from `impl_options!`, with its size in
//! the release that introduced it as a literal (checked at compile time);
//! its `_default` export is [`options_default`], and computing exports read
//! it with [`compute`] or [`Options::read_or_default`]. A field added later
//! goes at the end and leaves that literal alone.
//!
//! Shared handles (`Arc`) would be a second [`Ownership`] kind whose
//! `into_raw` / `release` are `Arc::into_raw` / `Arc::from_raw`.

use super::boundary::{check_out, deref, guard, write_out};
use super::last_error::FfiError;
use super::status::mx_status;

/// An opaque struct C holds pointers to.
pub(crate) trait Handle: Sized {
    /// The name of the handle's argument in every export, for the message
    /// when it is NULL.
    const ARG: &'static str;
    /// How C owns the handles it is given by `create` and `into_raw`.
    type Ownership: Ownership;
}

/// A way for C to own a handle.
pub(crate) trait Ownership {
    /// The pointer C receives for a new handle.
    fn into_raw<H>(h: H) -> *mut H;

    /// Ends the handle `p`.
    ///
    /// # Safety
    /// `p` must come from `into_raw` of the same kind and not be released yet.
    unsafe fn release<H>(p: *mut H);
}

/// Owned through a `Box`: one owner, C, until the handle's `_free`.
pub(crate) enum Boxed {}

impl Ownership for Boxed {
    fn into_raw<H>(h: H) -> *mut H {
        Box::into_raw(Box::new(h))
    }

    unsafe fn release<H>(p: *mut H) {
        // SAFETY: per the contract, `p` came from `Box::into_raw` above.
        drop(unsafe { Box::from_raw(p) });
    }
}

/// A handle that lends C a pointer to an `H` it holds, valid as long as
/// the handle.
pub(crate) trait Lends<H: Handle>: Handle {
    /// The lent handle.
    fn lent(&self) -> &H;
}

/// The handle argument `p`, or a NULL-argument error naming it.
///
/// # Safety
/// `p` must be NULL or a live handle.
pub(crate) unsafe fn arg<'a, H: Handle>(p: *const H) -> Result<&'a H, FfiError> {
    // SAFETY: forwarded contract.
    unsafe { deref(p, H::ARG) }
}

/// The pointer C receives for the new handle `h`.
pub(crate) fn into_raw<H: Handle>(h: H) -> *mut H {
    H::Ownership::into_raw(h)
}

/// The frame of every constructor: checks `out`, runs `f` (check the
/// arguments, call the core, convert) and writes the new handle to `*out`
/// only when `f` succeeded.
///
/// # Safety
/// `out` must be NULL or valid for writes; `f` carries its own contract.
pub(crate) unsafe fn create<H: Handle>(out: *mut *mut H, f: impl FnOnce() -> Result<H, FfiError>) -> mx_status {
    guard(|| {
        check_out(out, "out")?;
        let h = into_raw(f()?);
        // SAFETY: checked non-NULL above.
        unsafe { write_out(out, h) };
        Ok(())
    })
}

/// The frame of every computing constructor: checks `out`, the handle
/// `input` and the options (NULL = defaults), in that order, then `f`
/// calls the core and converts its result into the new handle.
///
/// # Safety
/// `out` NULL or valid for writes; `input` NULL or a live handle;
/// `options` NULL or valid for its `struct_size`.
pub(crate) unsafe fn compute<I: Handle, O: Options, H: Handle>(
    out: *mut *mut H,
    input: *const I,
    options: *const O,
    f: impl FnOnce(&I, O) -> Result<H, FfiError>,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { create(out, || f(arg(input)?, O::read_or_default(options)?)) }
}

/// Runs `f` on the handle `h` and writes its result to `out`: the frame of
/// every read-only query.
///
/// # Safety
/// `h` must be NULL or a live handle; `out` NULL or valid for writes.
pub(crate) unsafe fn query<H: Handle, T>(
    h: *const H,
    out: *mut T,
    f: impl FnOnce(&H) -> Result<T, FfiError>,
) -> mx_status {
    guard(|| {
        check_out(out, "out")?;
        // SAFETY: caller contract: NULL or a live handle.
        let v = f(unsafe { arg(h)? })?;
        // SAFETY: checked non-NULL above.
        unsafe { write_out(out, v) };
        Ok(())
    })
}

/// Writes to `out` the pointer `owner` lends to its `H`.
///
/// # Safety
/// `owner` must be NULL or a live handle; `out` NULL or valid for writes.
pub(crate) unsafe fn lend<O: Lends<H>, H: Handle>(owner: *const O, out: *mut *const H) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(owner, out, |o| Ok(o.lent() as *const H)) }
}

/// Releases `p`; NULL is a no-op.
///
/// # Safety
/// `p` must be NULL or a handle given to C by `create` or `into_raw`, not
/// freed yet and not lent.
pub(crate) unsafe fn free<H: Handle>(p: *mut H) {
    if !p.is_null() {
        // SAFETY: per the contract.
        unsafe { H::Ownership::release(p) }
    }
}

/// An options struct C passes by pointer and size, so that later releases
/// can append fields without breaking callers built against older headers.
///
/// # Safety
/// Implementors are `#[repr(C)]` plain old data whose first field is
/// `struct_size: usize`, and `V1_SIZE` is at most their size.
pub(crate) unsafe trait Options: Copy {
    /// The C type name, for messages.
    const NAME: &'static str;
    /// The struct's size in the release that introduced it, the smallest
    /// `struct_size` accepted. A fixed number (see [`v1_size`]), never
    /// `size_of::<Self>()`: that grows with every appended field and would
    /// reject every caller built before.
    const V1_SIZE: usize;

    /// The defaults, `struct_size` set to today's size.
    fn defaults() -> Self;

    /// The options at `p`: `None` for NULL, else the caller's first
    /// `struct_size` bytes over a copy of the defaults, so fields appended
    /// after the caller's release keep their defaults. A `struct_size`
    /// below `V1_SIZE` is rejected.
    ///
    /// # Safety
    /// `p` must be NULL or point to at least its own `struct_size` readable
    /// bytes.
    unsafe fn read(p: *const Self) -> Result<Option<Self>, FfiError> {
        if p.is_null() {
            return Ok(None);
        }
        // SAFETY: non-NULL, and every release's layout starts with
        // `struct_size`; read it alone before trusting the rest.
        let size = unsafe { p.cast::<usize>().read_unaligned() };
        if size < Self::V1_SIZE {
            let (name, min) = (Self::NAME, Self::V1_SIZE);
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!(
                    "{name}.struct_size = {size} is smaller than any released layout ({min}); call {name}_init(&o, sizeof o) first"
                ),
            ));
        }
        let mut o = Self::defaults();
        let n = size.min(std::mem::size_of::<Self>());
        // SAFETY: the caller's struct holds `size` >= n readable bytes; ours
        // is at least n bytes; both are plain old data.
        unsafe { std::ptr::copy_nonoverlapping(p.cast::<u8>(), std::ptr::addr_of_mut!(o).cast::<u8>(), n) };
        Ok(Some(o))
    }

    /// As [`Options::read`], with the defaults for NULL.
    ///
    /// # Safety
    /// As [`Options::read`].
    unsafe fn read_or_default(p: *const Self) -> Result<Self, FfiError> {
        // SAFETY: forwarded contract.
        Ok(unsafe { Self::read(p)? }.unwrap_or_else(Self::defaults))
    }
}

/// The first released size of an options struct: `lp64`, the literal size
/// on 64-bit targets, checked at compile time against `v1_end`, where the
/// struct's last field of that release ends today (a field inserted before
/// it, removed or resized fails the build). Other targets take `v1_end`:
/// the same fields in the same order, laid out by their own C ABI.
pub(crate) const fn v1_size(lp64: usize, v1_end: usize) -> usize {
    if cfg!(target_pointer_width = "64") {
        assert!(lp64 == v1_end, "the layout of a released options struct changed");
        lp64
    } else {
        v1_end
    }
}

/// Implements [`Options`] for the options struct `$t` and asserts at
/// compile time that it is no smaller than its first release, whose layout
/// (`$lp64` bytes on 64-bit targets) ends with the field `$last: $last_ty`;
/// `$defaults` builds the defaults.
macro_rules! impl_options {
    ($t:ident, v1: $lp64:literal bytes up to $last:ident: $last_ty:ty, defaults: $defaults:expr) => {
        // SAFETY: every options struct is `#[repr(C)]` plain old data
        // starting with `struct_size`; the assertion below keeps `V1_SIZE`
        // within it.
        unsafe impl super::handles::Options for $t {
            const NAME: &'static str = stringify!($t);
            const V1_SIZE: usize =
                super::handles::v1_size($lp64, std::mem::offset_of!($t, $last) + std::mem::size_of::<$last_ty>());

            fn defaults() -> Self {
                $defaults
            }
        }
        const _: () = assert!(std::mem::size_of::<$t>() >= <$t as super::handles::Options>::V1_SIZE);
    };
}
pub(crate) use impl_options;

/// The defaults of `O` in its first release's layout: the first
/// `V1_SIZE` bytes, `struct_size` = `V1_SIZE`: every `_default` export,
/// kept for callers built against medax 0.1, whose struct is that small
/// (writing today's struct overran them).
///
/// # Safety
/// `out` must be NULL or valid for `O::V1_SIZE` bytes of writes.
pub(crate) unsafe fn options_default<O: Options>(out: *mut O) -> mx_status {
    // SAFETY: forwarded contract (the caller's struct holds V1_SIZE bytes).
    unsafe { write_defaults(out, O::V1_SIZE) }
}

/// The defaults of `O` into the caller's struct of `size` bytes (its
/// `sizeof`): the first `min(size, today's size)` bytes, `struct_size` set
/// to that: every `_init` export. Fields the caller's release does not
/// have are neither written nor, later, read. A size below the first
/// release's is refused.
///
/// # Safety
/// `out` must be NULL or valid for `size` bytes of writes.
pub(crate) unsafe fn options_init<O: Options>(out: *mut O, size: usize) -> mx_status {
    if size < O::V1_SIZE {
        let (name, min) = (O::NAME, O::V1_SIZE);
        return guard(|| {
            Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("{name}_init: size {size} is smaller than any released {name} ({min}); pass sizeof"),
            ))
        });
    }
    // SAFETY: forwarded contract.
    unsafe { write_defaults(out, size.min(std::mem::size_of::<O>())) }
}

/// Writes the first `n` bytes (`V1_SIZE <= n <= size_of::<O>()`) of the
/// defaults with `struct_size = n`.
///
/// # Safety
/// `out` must be NULL or valid for `n` bytes of writes.
unsafe fn write_defaults<O: Options>(out: *mut O, n: usize) -> mx_status {
    guard(|| {
        check_out(out, "out")?;
        let mut d = O::defaults();
        // SAFETY: every options struct starts with `struct_size: usize`.
        unsafe { std::ptr::addr_of_mut!(d).cast::<usize>().write_unaligned(n) };
        // SAFETY: `out` holds n writable bytes (contract); `d` is at least
        // n bytes of plain old data.
        unsafe { std::ptr::copy_nonoverlapping(std::ptr::addr_of!(d).cast::<u8>(), out.cast::<u8>(), n) };
        Ok(())
    })
}
