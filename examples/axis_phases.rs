//! Where the medial axis spends its time, phase by phase, as
//! `medial_axis` runs them (first decomposition only):
//! `cargo run --release --features internals --example axis_phases -- KIND N [THREADS]`
//! with KIND one of `fourier`, `circle`, `star`, `flower`, `holes` (a
//! `write_sample` family; `MEDAX_SEED` picks the random one) or a shape
//! file with N = 0. Prints one line per phase: seconds and share, resident
//! memory after the phase and its peak so far, and (with
//! `MEDAX_COUNT_ALLOC=1`) the bytes allocated after the phase and the most
//! during it, all per element; then the
//! divide step's critical path (span) and, from this run's times, the
//! time Brent's bound predicts on more cores (run with THREADS = 1 for
//! the work): validation, augmenting disks, base cases and the final check are parallel
//! maps over many small independent items, the divide step takes at most
//! work / p + span, index and gluing are serial.
use medax::plane::internals::{augment, decompose_in, final_check, glue, solve_leaves};
use medax::plane::{AxisOptions, DiskFinder};
use medax::shape::{samples, Shape2d, ShapeOptions};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering::Relaxed};
use std::time::Instant;

/// The system allocator, counting (with `MEDAX_COUNT_ALLOC=1`) the bytes
/// held and the most held since the last phase: resident memory also
/// counts freed blocks the allocator keeps, so it alone cannot tell what a
/// phase holds. Off by default: the shared counters cost 10 % of the time
/// on two threads.
struct Counting;

static COUNT: AtomicBool = AtomicBool::new(false);
static LIVE: AtomicUsize = AtomicUsize::new(0);
static LIVE_PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is passed on to `System` unchanged; only counters
// are updated beside it.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if !COUNT.load(Relaxed) {
            // SAFETY: the caller's contract, passed on.
            return unsafe { System.alloc(layout) };
        }
        let now = LIVE.fetch_add(layout.size(), Relaxed) + layout.size();
        LIVE_PEAK.fetch_max(now, Relaxed);
        // SAFETY: the caller's contract, passed on.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        if !COUNT.load(Relaxed) {
            // SAFETY: the caller's contract, passed on.
            return unsafe { System.dealloc(ptr, layout) };
        }
        LIVE.fetch_sub(layout.size(), Relaxed);
        // SAFETY: the caller's contract, passed on.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if !COUNT.load(Relaxed) {
            // SAFETY: the caller's contract, passed on.
            return unsafe { System.realloc(ptr, layout, new_size) };
        }
        if new_size > layout.size() {
            let now = LIVE.fetch_add(new_size - layout.size(), Relaxed) + new_size - layout.size();
            LIVE_PEAK.fetch_max(now, Relaxed);
        } else {
            LIVE.fetch_sub(layout.size() - new_size, Relaxed);
        }
        // SAFETY: the caller's contract, passed on.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn main() {
    // Counting is switched on before anything else is allocated and never
    // off, so every block freed was counted when allocated.
    let count = std::env::var("MEDAX_COUNT_ALLOC").is_ok_and(|v| v == "1");
    COUNT.store(count, Relaxed);
    let args: Vec<String> = std::env::args().collect();
    let kind = args.get(1).map_or("fourier", String::as_str);
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let threads: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(0);
    let seed: u64 = std::env::var("MEDAX_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let mut phases: Vec<(&str, f64)> = Vec::new();
    let mut memory: Vec<(u64, u64, usize, usize)> = Vec::new();
    let mut clock = Instant::now();
    let mut lap = |name: &'static str, phases: &mut Vec<(&str, f64)>| {
        phases.push((name, clock.elapsed().as_secs_f64()));
        let live = LIVE.load(Relaxed);
        memory.push((status_kb("VmRSS:"), status_kb("VmHWM:"), live, LIVE_PEAK.swap(live, Relaxed)));
        clock = Instant::now();
    };
    let loops = match kind {
        "fourier" => samples::fourier_biarcs(n, seed),
        "circle" => samples::fourier_curve(n, seed, 1e-3),
        "star" => samples::star_polygon(n, seed),
        "flower" => samples::flower_arcs(n),
        "holes" => samples::random_holes(n, seed),
        path => {
            let text = std::fs::read_to_string(path).expect("readable shape file");
            let shape = medax::plane::shape_or_sites(&text).expect("a valid shape file");
            shape.loops().iter().map(|l| l.vertices().to_vec()).collect()
        }
    };
    lap("generate", &mut phases);
    let mut span = 0.0;
    let mut large_depth = 0;
    let mut elements = n;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
    pool.install(|| {
        let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid shape");
        lap("validate", &mut phases);
        let finder = DiskFinder::new(&shape);
        lap("index (run hierarchy)", &mut phases);
        let aug = augment(&finder).expect("augmenting disks");
        lap("augment (holes)", &mut phases);
        let mut opts = AxisOptions::default();
        if let Some(k) = std::env::var("MEDAX_LEAF_PARTS").ok().and_then(|s| s.parse().ok()) {
            opts.leaf_parts = k;
        }
        let mut d = decompose_in(&finder, &aug, opts.seed, opts.leaf_parts.max(3));
        drop(aug);
        lap("divide", &mut phases);
        span = d.span;
        large_depth = d.large_depth;
        let locals = solve_leaves(&finder, &mut d, opts.seed).expect("leaves solved");
        lap("base cases", &mut phases);
        let leaves = locals.count();
        let axis = glue(&finder, &d.cuts, locals).expect("glued");
        lap("glue (conquer)", &mut phases);
        final_check(&finder, &axis).expect("checked");
        lap("final check", &mut phases);
        elements = shape.element_count();
        println!("{kind} {}: {} elements, {} leaves, {} nodes", n, elements, leaves, axis.nodes.len());
    });
    let total: f64 = phases.iter().skip(1).map(|p| p.1).sum();
    // Resident memory after each phase and the peak so far (Linux /proc; 0
    // elsewhere), and the bytes allocated after it and the most during
    // it, per input element.
    let per = |kb: u64| kb as f64 * 1024.0 / elements.max(1) as f64;
    let bytes = |b: usize| if count { b as f64 / elements.max(1) as f64 } else { f64::NAN };
    println!(
        "{:>24} {:>10} {:>7} {:>22} {:>22} (B/elt)",
        "phase", "time", "share", "resident / peak", "allocated / peak"
    );
    for ((name, t), (rss, peak, live, live_peak)) in phases.iter().zip(&memory) {
        println!(
            "{name:>24} {t:8.3} s {:5.1} %   {:9.0} / {:9.0}   {:9.0} / {:9.0}",
            100.0 * t / total,
            per(*rss),
            per(*peak),
            bytes(*live),
            bytes(*live_peak)
        );
    }
    println!("{:>24} {total:8.3} s (without generate)", "total");
    let t = |name: &str| phases.iter().find(|p| p.0 == name).map_or(0.0, |p| p.1);
    let (flat, serial) = (
        t("validate") + t("augment (holes)") + t("base cases") + t("final check"),
        t("index (run hierarchy)") + t("glue (conquer)"),
    );
    println!("{:>24} {span:8.3} s (critical path of the divide step)", "divide span");
    println!("{:>24} {large_depth:8} cuts of subshapes taking balanced cuts, on one path", "divide depth");
    for p in [2.0, 8.0, 16.0] {
        let predicted = serial + flat / p + t("divide") / p + span;
        println!("{:>24} {predicted:8.3} s on {p} cores ({:.1}x)", "predicted", total / predicted);
    }
}

/// A memory line of /proc/self/status (`VmRSS:`, `VmHWM:`), kB; 0 where
/// there is none.
fn status_kb(key: &str) -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with(key)).and_then(|l| l.split_whitespace().nth(1)?.parse().ok()))
        .unwrap_or(0)
}
