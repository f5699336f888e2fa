//! The panic boundary and pointer checks every export goes through, so each
//! exported function reads: check arguments, call the core, convert.

use super::axis::{mx_progress_fn, MX_AXIS_MAX_THREADS};
use super::last_error::{set_last_error, FfiError};
use super::status::mx_status;
use std::ffi::c_void;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f`, turning its error or a panic into a status and the thread's
/// last error. No panic unwinds into C.
pub(crate) fn guard(f: impl FnOnce() -> Result<(), FfiError>) -> mx_status {
    // The closure only touches data it owns or that C lent for this call;
    // after a panic nothing of it is used again, so unwind safety holds.
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(())) => mx_status::MX_OK,
        Ok(Err(e)) => {
            let s = e.info.status;
            set_last_error(e);
            s
        }
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            set_last_error(FfiError::new(
                mx_status::MX_ERR_PANIC,
                format!("internal error in medax (please report with the input): {what}"),
            ));
            mx_status::MX_ERR_PANIC
        }
    }
}

pub(crate) fn null_arg(name: &str) -> FfiError {
    FfiError::new(mx_status::MX_ERR_NULL_ARGUMENT, format!("argument `{name}` is NULL"))
}

/// A shared reference from a C pointer, or a NULL-argument error.
///
/// # Safety
/// `p` must be NULL or valid for reads for the duration of the call.
pub(crate) unsafe fn deref<'a, T>(p: *const T, name: &str) -> Result<&'a T, FfiError> {
    // SAFETY: per the contract above.
    unsafe { p.as_ref() }.ok_or_else(|| null_arg(name))
}

/// A slice from a C pointer and length; NULL is allowed only for length 0.
///
/// # Safety
/// `p` must be NULL or point to `len` readable, initialised `T`s.
pub(crate) unsafe fn slice<'a, T>(p: *const T, len: usize, name: &str) -> Result<&'a [T], FfiError> {
    if len == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(null_arg(name));
    }
    // SAFETY: non-NULL and, per the contract, `len` elements long.
    Ok(unsafe { std::slice::from_raw_parts(p, len) })
}

/// Writes `v` through an out-pointer that was checked to be non-NULL.
///
/// # Safety
/// `out` must be non-NULL and valid for writes.
pub(crate) unsafe fn write_out<T>(out: *mut T, v: T) {
    // SAFETY: per the contract above.
    unsafe { out.write(v) }
}

/// Checks an out-pointer for NULL before any work is done.
pub(crate) fn check_out<T>(out: *mut T, name: &str) -> Result<(), FfiError> {
    if out.is_null() {
        Err(null_arg(name))
    } else {
        Ok(())
    }
}

/// A UTF-8 string from a NUL-terminated C string.
///
/// # Safety
/// `p` must be NULL or a valid NUL-terminated string.
pub(crate) unsafe fn c_str<'a>(p: *const std::ffi::c_char, name: &str) -> Result<&'a str, FfiError> {
    if p.is_null() {
        return Err(null_arg(name));
    }
    // SAFETY: non-NULL and NUL-terminated per the contract.
    let s = unsafe { std::ffi::CStr::from_ptr(p) };
    s.to_str()
        .map_err(|_| FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("argument `{name}` is not valid UTF-8")))
}

pub(crate) fn index_error(what: &str, index: usize, len: usize) -> FfiError {
    FfiError::new(mx_status::MX_ERR_INDEX_OUT_OF_RANGE, format!("{what} index {index} is out of range (0..{len})"))
}

/// Item `index` of `items` (a node, edge, loop… named `what` in the error).
pub(crate) fn nth<'a, T>(items: &'a [T], index: usize, what: &str) -> Result<&'a T, FfiError> {
    items.get(index).ok_or_else(|| index_error(what, index, items.len()))
}

/// Writes the `need` entries of `items` to the caller's buffer `buf`
/// (argument `name`) of `capacity` entries, after checking that they fit
/// (else `MX_ERR_BUFFER_TOO_SMALL` with the message `too_small`, nothing
/// written) and that `buf` is not NULL.
///
/// # Safety
/// `buf` must be NULL or valid for `capacity` writes.
pub(crate) unsafe fn fill<T>(
    buf: *mut T,
    name: &str,
    capacity: usize,
    need: usize,
    items: impl IntoIterator<Item = T>,
    too_small: impl FnOnce() -> String,
) -> Result<(), FfiError> {
    if capacity < need {
        return Err(FfiError::new(mx_status::MX_ERR_BUFFER_TOO_SMALL, too_small()));
    }
    check_out(buf, name)?;
    for (i, v) in items.into_iter().take(need).enumerate() {
        // SAFETY: i < need <= capacity entries, writable per the contract.
        unsafe { buf.add(i).write(v) };
    }
    Ok(())
}

/// Protocol 2 of docs/C_API.md for `n` items of `width` numbers each:
/// `capacity` counts items; 0 is a size query (only `*count` written);
/// a shorter buffer is `MX_ERR_BUFFER_TOO_SMALL` with nothing written.
///
/// # Safety
/// `buf` NULL or `capacity * width` writable values; `count` NULL or
/// writable.
pub(crate) unsafe fn fill_items<T>(
    (buf, name): (*mut T, &str),
    (capacity, count): (usize, *mut usize),
    (n, width): (usize, usize),
    values: impl IntoIterator<Item = T>,
    too_small: impl FnOnce() -> String,
) -> Result<(), FfiError> {
    check_out(count, "count")?;
    if capacity != 0 {
        // SAFETY: forwarded contract; `capacity` items are `capacity * width` values.
        unsafe { fill(buf, name, capacity.saturating_mul(width), n * width, values, too_small)? };
    }
    // SAFETY: checked non-NULL above.
    unsafe { write_out(count, n) };
    Ok(())
}

/// The front of a batched query answering `n` items by protocol 2: a
/// size query (capacity 0) writes `*count = n` and gives `Ok(false)`; a
/// shorter buffer is refused before any work is done; else `Ok(true)`:
/// compute, then [`fill_items`].
///
/// # Safety
/// `count` NULL or writable.
pub(crate) unsafe fn batch_room<T>(
    buf: *mut T,
    (capacity, count): (usize, *mut usize),
    n: usize,
    what: &str,
) -> Result<bool, FfiError> {
    if capacity == 0 {
        // SAFETY: forwarded contract; nothing is written to `buf`.
        unsafe { fill_items((buf, "buffer"), (0, count), (n, 1), std::iter::empty(), String::new)? };
        return Ok(false);
    }
    if capacity < n {
        return Err(FfiError::new(
            mx_status::MX_ERR_BUFFER_TOO_SMALL,
            format!("{n} {what}, the buffer room for {capacity}"),
        ));
    }
    Ok(true)
}

/// NULL for an empty array: C callers never see a dangling pointer.
pub(crate) fn ptr_or_null<T>(v: &[T]) -> *const T {
    if v.is_empty() {
        std::ptr::null()
    } else {
        v.as_ptr()
    }
}

/// Reports `fraction` to the caller's callback; true when it asks to cancel.
fn progress(callback: mx_progress_fn, user: *mut c_void, fraction: f64) -> bool {
    // SAFETY: the caller supplied the callback and its `user` pointer for
    // this call; the callback's contract is documented on `mx_progress_fn`.
    callback.is_some_and(|f| unsafe { f(fraction, user) } != 0)
}

/// Runs `f` on the shared pool (`threads` 0) or on a pool of exactly
/// `threads` threads.
pub(crate) fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T, FfiError> {
    if threads == 0 {
        return Ok(f());
    }
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| {
        FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("cannot start {threads} threads: {e}"))
    })?;
    Ok(pool.install(f))
}

/// Checks an options struct's `threads` (its name `options`): 0 (all
/// cores) or at most `MX_AXIS_MAX_THREADS`.
pub(crate) fn check_threads(options: &str, threads: usize) -> Result<(), FfiError> {
    if threads > MX_AXIS_MAX_THREADS {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("{options}.threads = {threads}: use 0 (all cores) or at most {MX_AXIS_MAX_THREADS}"),
        ));
    }
    Ok(())
}

/// The frame of every long-running export (`export`, whose options struct
/// is `options`): checks `threads` (0 or at most `MX_AXIS_MAX_THREADS`),
/// reports 0 to the progress callback (a nonzero answer cancels with
/// `MX_ERR_CANCELLED`), runs `f` on `threads` threads and reports 1 when it
/// succeeded.
pub(crate) fn run_with_progress<T: Send>(
    export: &str,
    options: &str,
    threads: usize,
    callback: mx_progress_fn,
    user: *mut c_void,
    f: impl FnOnce() -> Result<T, FfiError> + Send,
) -> Result<T, FfiError> {
    check_threads(options, threads)?;
    if progress(callback, user, 0.0) {
        return Err(FfiError::new(mx_status::MX_ERR_CANCELLED, format!("{export} cancelled by the progress callback")));
    }
    let v = in_pool(threads, f)??;
    progress(callback, user, 1.0);
    Ok(v)
}
