//! The medial-axis algorithm is written against `AxisKernel`: a kernel
//! plugged in from outside the crate answers every geometric question, and
//! the axis changes exactly when its answers do.

mod common;

use common::{circle, shape, star, v};
use medax::kernel::apollonius::Site;
use medax::kernel::growing_disk::GrowingDisk;
use medax::kernel::{AxisKernel, CircleSide, Contact, Disk, FilteredKernel, Kernel, Orientation, Point};
use medax::plane::{medial_axis, medial_axis_with, AxisOptions, MedialAxis2d, NodeKind};
use medax::shape::Shape2d;
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

/// Calls per question, shared by every copy of the kernel (the algorithm
/// copies it into parallel tasks).
#[derive(Default)]
struct Calls {
    growing: AtomicUsize,
    apollonius: AtomicUsize,
    bisector: AtomicUsize,
    contact: AtomicUsize,
}

/// Delegates to the default kernel and counts; optionally refuses to
/// construct tritangent disks, or moves their centres by `shift` (model
/// units) along x.
#[derive(Clone, Copy)]
struct Counting {
    calls: &'static Calls,
    no_apollonius: bool,
    shift: f64,
}

impl Counting {
    fn new(no_apollonius: bool) -> Counting {
        Counting { calls: Box::leak(Box::default()), no_apollonius, shift: 0.0 }
    }
}

impl Kernel for Counting {
    fn orientation(&self, p: Point, q: Point, r: Point) -> Orientation {
        FilteredKernel.orientation(p, q, r)
    }

    fn circle_side(&self, a: Point, b: Point, c: Point, d: Point) -> CircleSide {
        FilteredKernel.circle_side(a, b, c, d)
    }
}

impl AxisKernel for Counting {
    fn through_point(&self, g: &GrowingDisk, q: Point) -> Option<f64> {
        self.calls.growing.fetch_add(1, Relaxed);
        FilteredKernel.through_point(g, q)
    }

    fn tangent_to_line(&self, g: &GrowingDisk, a: Point, m: Point) -> [Option<(f64, Point)>; 2] {
        self.calls.growing.fetch_add(1, Relaxed);
        FilteredKernel.tangent_to_line(g, a, m)
    }

    fn tangent_to_circle(&self, g: &GrowingDisk, o: Point, r: f64) -> [Option<(f64, Point)>; 2] {
        self.calls.growing.fetch_add(1, Relaxed);
        FilteredKernel.tangent_to_circle(g, o, r)
    }

    fn tritangent_disks(&self, sites: [Site; 3]) -> Vec<Disk> {
        self.calls.apollonius.fetch_add(1, Relaxed);
        if self.no_apollonius {
            return Vec::new();
        }
        let shift = Point::new(self.shift, 0.0);
        FilteredKernel.tritangent_disks(sites).into_iter().map(|d| Disk::new(d.center + shift, d.radius)).collect()
    }

    fn bisector_point(&self, a: &Site, b: &Site, u: f64) -> Option<Disk> {
        self.calls.bisector.fetch_add(1, Relaxed);
        FilteredKernel.bisector_point(a, b, u)
    }

    fn contact(&self, distance: f64, radius: f64, tol: f64) -> Contact {
        self.calls.contact.fetch_add(1, Relaxed);
        FilteredKernel.contact(distance, radius, tol)
    }
}

/// Polygons with reflex vertices, arcs curving both ways, a circle.
fn corpus() -> Vec<Shape2d> {
    vec![
        shape(vec![star(40, 3)]),
        shape(vec![star(300, 8)]),
        shape(vec![circle(0.0, 0.0, 2.0)]),
        shape(vec![vec![v(0.0, 0.0, 0.0), v(4.0, 0.0, 0.4), v(4.0, 2.0, -0.3), v(2.0, 3.0, 0.0), v(0.0, 2.0, 0.2)]]),
        Shape2d::from_bulge_loops(medax::shape::samples::flower_arcs(200), &Default::default()).unwrap(),
    ]
}

fn same(a: &MedialAxis2d, b: &MedialAxis2d) -> bool {
    a.nodes == b.nodes && a.edges == b.edges
}

#[test]
fn every_question_goes_through_the_plugged_kernel() {
    let opts = AxisOptions::default();
    for (i, s) in corpus().iter().enumerate() {
        let k = Counting::new(false);
        let plugged = medial_axis_with(s, &opts, k).unwrap_or_else(|e| panic!("shape {i}: {e}"));
        let default = medial_axis(s, &opts).unwrap();
        // Same answers, same axis, to the bit.
        assert!(same(&plugged, &default), "shape {i}");
        let c = k.calls;
        assert!(c.growing.load(Relaxed) > 0, "shape {i}: maximal disks grew without the kernel");
        assert!(c.contact.load(Relaxed) > 0, "shape {i}: contacts decided without the kernel");
        if i < 2 || i == 4 {
            // Polygons with reflex vertices and flowers have branch points.
            assert!(c.apollonius.load(Relaxed) > 0, "shape {i}: branch points built without the kernel");
        }
    }
}

#[test]
fn a_kernel_without_tritangent_disks_finds_no_branch_points() {
    // The branch points of a star come from the kernel's Apollonius
    // construction; a kernel that has none makes the base cases fail,
    // which the algorithm reports instead of inventing nodes.
    let s = shape(vec![star(40, 3)]);
    let k = Counting::new(true);
    assert!(medial_axis_with(&s, &AxisOptions::default(), k).is_err());
    assert!(k.calls.apollonius.load(Relaxed) > 0);
}

#[test]
fn branch_points_are_where_the_kernel_puts_them() {
    // A kernel whose tritangent disks sit 1e-10 off the true ones (well
    // within the tolerance, 1e-9 of the diagonal): the branch points move
    // with it, and nowhere else.
    let s = shape(vec![star(40, 3)]);
    let opts = AxisOptions::default();
    let default = medial_axis(&s, &opts).unwrap();
    let shift = 1e-10;
    let k = Counting { shift, ..Counting::new(false) };
    let moved = medial_axis_with(&s, &opts, k).unwrap();
    assert_eq!(moved.nodes.len(), default.nodes.len());
    // Node order follows the decomposition, whose cuts come from the
    // kernel too: match each node to the nearest one.
    let mut shifted = 0;
    for d in &default.nodes {
        let m = moved.nodes.iter().min_by(|a, b| a.point.dist(d.point).total_cmp(&b.point.dist(d.point))).unwrap();
        assert!(m.point.dist(d.point) <= 2.0 * shift && m.kind == d.kind, "{m:?} {d:?}");
        if d.kind == NodeKind::Branch && (m.point.x - d.point.x - shift).abs() < 1e-3 * shift {
            shifted += 1;
        }
    }
    let branches = default.nodes.iter().filter(|n| n.kind == NodeKind::Branch).count();
    assert!(shifted > branches / 2, "{shifted} of {branches} branch points moved with the kernel");
}
