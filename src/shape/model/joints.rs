//! Classification of the joints between consecutive elements (thesis 2.2.1).

use crate::shape::model::bulge_loop::Loop;

/// What a loop does at a vertex, seen from the shape's interior.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum JointKind {
    /// Tangent-continuous within the angular tolerance.
    Smooth = 0,
    /// A corner that points out of the shape (interior angle below 180°).
    /// Maximal disks shrink to radius 0 here; the medial axis reaches it.
    Convex = 1,
    /// A corner that points into the shape (interior angle above 180°);
    /// it acts as a zero-length arc for the medial axis.
    Reflex = 2,
}

/// Signed turning angle at vertex `i` of `l`, in (−π, π]: the angle from the
/// incoming element's end tangent to the outgoing element's start tangent,
/// positive for left turns.
pub fn turning_angle(l: &Loop, i: usize) -> f64 {
    let n = l.len();
    let t_in = l.element((i + n - 1) % n).end_tangent();
    let t_out = l.element(i).start_tangent();
    t_in.cross(t_out).atan2(t_in.dot(t_out))
}

/// The joint kind for a turning angle, for a loop whose interior is on its
/// left (outer loops counter-clockwise, holes clockwise).
pub fn classify(turn: f64, angle_tolerance: f64) -> JointKind {
    if turn > angle_tolerance {
        JointKind::Convex
    } else if turn < -angle_tolerance {
        JointKind::Reflex
    } else {
        JointKind::Smooth
    }
}
