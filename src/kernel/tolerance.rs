//! Every tolerance the algorithms decide by, in one place.
//!
//! All lengths derive from the shape's touching tolerance `τ` (model
//! units; by default 1e-9 of the shape's diagonal, see `ShapeOptions`):
//! two boundary points closer than `τ` are one point, a disk within `τ` of
//! a primitive touches it. The multiples below say how much rounding each
//! decision must absorb on top of that; where a value was measured, its
//! doc says on what. Angles are radians, fractions are of a parameter
//! range.
//!
//! An algorithm never writes `k * tol` or a bare `1e-N` itself: it asks
//! this type by name, so that a value is changed in one place and its
//! reason is written next to it.

/// The tolerances of one shape, derived from its touching tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    touch: f64,
}

impl Tolerance {
    /// The tolerances for a shape whose touching tolerance is `touch`
    /// (model units, ≥ 0).
    #[inline]
    pub fn new(touch: f64) -> Tolerance {
        Tolerance { touch }
    }

    /// `τ`, the shape's touching tolerance (model units): closer than this
    /// is touching; a disk within it of a primitive touches it.
    #[inline]
    pub fn touch(self) -> f64 {
        self.touch
    }

    /// A chain end this close (in length along the boundary) past a vertex
    /// is at the vertex, 4τ: the base cases move such ends back to it and
    /// the divide step cuts no disk with a footpoint this close to a convex
    /// corner (the footpoints of a disk at a nearly flat corner merge).
    #[inline]
    pub fn sliver_end(self) -> f64 {
        4.0 * self.touch
    }

    /// A pocket of a base case holding less boundary than this (in length)
    /// is a sliver left by cuts within rounding of a vertex, 64τ: the axis
    /// in it is shorter than the same.
    #[inline]
    pub fn sliver_pocket(self) -> f64 {
        64.0 * self.touch
    }

    /// How close the boundary of a lobe tip must stay to its one dividing
    /// disk's circle for the disk to be the tip's whole axis, 16τ.
    /// Measured on flowers of 3·10^4 to 10^5 arcs: lobe tips 2–8·10^-5
    /// long whose boundary lies 1–5τ from the cut.
    #[inline]
    pub fn hugged_tip(self) -> f64 {
        16.0 * self.touch
    }

    /// Two event disks of a base case whose centres and radii agree within
    /// this are one event, 4τ.
    #[inline]
    pub fn same_event(self) -> f64 {
        4.0 * self.touch
    }

    /// Two dividing disks (or two branch points) whose centres and radii
    /// agree within this are one disk met twice by the conquer step, 64τ:
    /// disks found by sliding (`maxdisk*`) agree to about 1e-8 of the
    /// diagonal.
    #[inline]
    pub fn same_disk(self) -> f64 {
        64.0 * self.touch
    }

    /// A dividing disk within this of one already glued into another node
    /// (centre and radius) is glued into that node too, 8τ: the same disk
    /// met twice, however far the node it joined lies.
    #[inline]
    pub fn same_merged_cut(self) -> f64 {
        8.0 * self.touch
    }

    /// Two edges joining one pair of nodes whose centres are within this,
    /// 256τ, each node's disk more than twice as large, close a cycle of
    /// rounding, not one round a hole: a hole inside the lens the two
    /// edges bound would lie within this of both centres and so inside
    /// their disks. Measured on Fourier curves of 10^6 arcs: branch points
    /// 46–90τ from a joint whose two contacts snapped onto the joint's
    /// vertex, joined to it on both sides.
    #[inline]
    pub fn rounding_cycle(self) -> f64 {
        256.0 * self.touch
    }

    /// The side of the grid cells that bucket dividing disks' centres when
    /// coinciding ones are found, four times [`same_disk`](Self::same_disk)
    /// (neighbouring cells are searched too).
    #[inline]
    pub fn merge_cell(self) -> f64 {
        4.0 * self.same_disk()
    }

    /// The overlap (model units) by which the final check lets a boundary
    /// element enter a disk of the finished axis before it reports the
    /// axis as wrong, 64τ.
    #[inline]
    pub fn final_check(self) -> f64 {
        64.0 * self.touch
    }

    /// A group of coinciding branch points is one node when one member's
    /// disk fits every primitive of the group within this (model units),
    /// half the final check's slack.
    #[inline]
    pub fn branch_group_fit(self) -> f64 {
        0.5 * self.final_check()
    }

    /// A disk tangent to three of a branch point's primitives replaces it
    /// (polishing) only when centre and radius move by less than this
    /// fraction of its radius, 1e-6.
    #[inline]
    pub fn polish_reach() -> f64 {
        1e-6
    }

    /// How far outside the range it must lie in (in length along the
    /// boundary) a branch point's contact may fall, 16τ: near-degenerate
    /// triples (many disks nearly alike, as at the centre of a symmetric
    /// shape) place contacts a few τ off.
    #[inline]
    pub fn branch_contact_slack(self) -> f64 {
        16.0 * self.touch
    }

    /// The branch-point contact slack is at most this fraction of a site's
    /// parameter range (short sites), 1/2.
    #[inline]
    pub fn branch_contact_slack_cap() -> f64 {
        0.5
    }

    /// A fan of normals whose arc at the disk's radius is no longer than
    /// this (model units) is rounding, not a fan, 4τ.
    #[inline]
    pub fn fan_arc(self) -> f64 {
        4.0 * self.touch
    }

    /// Fans of normals narrower than this (radians) are rounding, not fans,
    /// and a direction this close to a fan part's end is at that end,
    /// 1e-7: disks found by sliding (`maxdisk*`) meet a vertex in a
    /// direction accurate to about 1e-8.
    #[inline]
    pub fn fan_angle() -> f64 {
        1e-7
    }

    /// How far outside a reflex vertex's fan (in length at the disk's
    /// radius) a disk through the vertex may come and still touch it from
    /// inside, 4τ; farther out it touches the element beside it.
    #[inline]
    pub fn fan_slack(self) -> f64 {
        4.0 * self.touch
    }

    /// How far past a disk's circle (model units) elements are gathered as
    /// candidate footpoints, 2τ: the bounds of the boundary runs are
    /// rounded, and the contact test (within τ) decides.
    #[inline]
    pub fn footpoint_search(self) -> f64 {
        2.0 * self.touch
    }

    /// How far (model units) a site may stray from a disk's circle and
    /// still hug it (one footpoint smeared by rounding into two), 4τ.
    #[inline]
    pub fn hug(self) -> f64 {
        4.0 * self.touch
    }

    /// The overlap (model units) by which a boundary element must enter a
    /// constructed disk to make it not empty for the whole shape, 4τ.
    #[inline]
    pub fn intruder(self) -> f64 {
        4.0 * self.touch
    }

    /// A growing disk's contact radius below this (model units) is its
    /// start point's own element, τ/4.
    #[inline]
    pub fn least_growth(self) -> f64 {
        0.25 * self.touch
    }

    /// Footpoint tolerance of disks from closed-form constructions (model
    /// units), τ/1000 but at least 256 ulps of the shape's largest
    /// coordinate `magnitude`, and never above τ: their residuals are a few
    /// ulps, while τ itself would let a disk inside a nearly circular
    /// stretch of arcs (a rounded tip) touch all of them at once.
    #[inline]
    pub fn constructed_touch(self, magnitude: f64) -> f64 {
        (1e-3 * self.touch).max(256.0 * f64::EPSILON * magnitude).min(self.touch)
    }

    /// A disk found by sliding along a bisector is the one looked for when
    /// its centre and radius agree within this, 16τ.
    #[inline]
    pub fn slide_match(self) -> f64 {
        16.0 * self.touch
    }

    /// A disk on the slid bisector (`maxdisk*`) is empty while no element
    /// comes closer than its radius by more than 1e-12 of the shape's
    /// `diagonal` (model units): the slide must stop at the first real
    /// contact, which τ would blur.
    #[inline]
    pub fn slide_emptiness(diagonal: f64) -> f64 {
        1e-12 * diagonal
    }

    /// The first probe step of a slide, 1e-3: radians on an angular
    /// parameter, a fraction of the radius on a line's.
    #[inline]
    pub fn slide_probe() -> f64 {
        1e-3
    }

    /// The step (radians, or a fraction of the radius on a line) that
    /// tells which way each contact moves as the disk slides, 1e-6.
    #[inline]
    pub fn slide_direction_step() -> f64 {
        1e-6
    }

    /// A march step this small (parameter units) is no step: the slide
    /// stops halving it, 1e-15.
    #[inline]
    pub fn least_step() -> f64 {
        1e-15
    }

    /// A disk found ahead on an angular parameter by less than this
    /// (radians) is the start disk itself, 1e-12.
    #[inline]
    pub fn least_turn() -> f64 {
        1e-12
    }

    /// Two unit directions whose dot product exceeds 1 minus this are one
    /// direction, 1e-12 (about 1.4e-6 radians).
    #[inline]
    pub fn same_direction() -> f64 {
        1e-12
    }

    /// An inner extremum of an axis edge's radius this close to an end
    /// (fraction of the edge's parameter range) is at the node itself,
    /// 1e-9: the edge is then monotonic.
    #[inline]
    pub fn extremum_at_node() -> f64 {
        1e-9
    }

    /// A closed-form disk of the offset radius whose centre lies this far
    /// outside its monotonic piece (fraction of the piece's parameter
    /// range) is still on the piece, 1e-6; farther out, bisection finds
    /// the disk instead.
    #[inline]
    pub fn offset_piece_slack() -> f64 {
        1e-6
    }

    /// An offset piece's turn is kept this far (radians) short of a whole
    /// turn, 1e-9, so that its bulge tan(turn/4) stays finite.
    #[inline]
    pub fn whole_turn_margin() -> f64 {
        1e-9
    }

    /// A distance counts as the offsets' outer reach when it exceeds it by
    /// at most this fraction, 1e-12 (a reach computed as r·k/k).
    #[inline]
    pub fn reach_rounding() -> f64 {
        1e-12
    }

    /// Below this (radians, or a fraction of a length) a footpoint
    /// parameter range is a single point when choosing how to parametrise
    /// an axis edge, 1e-12.
    #[inline]
    pub fn point_range() -> f64 {
        1e-12
    }

    /// Two cut fractions along one element this close are one cut, 1e-12.
    #[inline]
    pub fn same_cut() -> f64 {
        1e-12
    }

    /// Loose ends of pieces within this (model units) of each other are
    /// linked into one loop when the uncut area is closed, 64τ: the ends
    /// come from separate constructions of one point.
    #[inline]
    pub fn link_ends(self) -> f64 {
        64.0 * self.touch.max(f64::MIN_POSITIVE)
    }

    /// How far along an edge (fraction of its parameter range) the
    /// direction it leaves a node in is taken, 1e-3: far enough that the
    /// curve's own rounding does not turn it, close enough to be its
    /// tangent for ordering edges round a node.
    #[inline]
    pub fn leaving_direction() -> f64 {
        1e-3
    }

    /// The unit of length for sites all at one place (no extent to measure
    /// tolerances against), model units: 1e-6 of their coordinates'
    /// `magnitude` and at least 1, so that the tolerance derived from it
    /// keeps the coordinates' digits.
    #[inline]
    pub fn unit_at(magnitude: f64) -> f64 {
        1.0_f64.max(1e-6 * magnitude)
    }

    /// The default chordal tolerance (model units) of V-carve paths sampled
    /// along the axis, 1000τ (1e-6 of the diagonal by default): well
    /// below any machine's resolution, coarse enough to keep paths short.
    #[inline]
    pub fn vcarve_sampling(self) -> f64 {
        1000.0 * self.touch
    }

    /// Fraction of a site's parameter range by which coinciding contacts
    /// of a branch point are pulled into their own primitives, and by which
    /// a contact where only the dividing disk touches is moved inside.
    #[inline]
    pub fn nudge() -> f64 {
        1e-12
    }

    /// Two footpoint fractions on one site closer than this are one
    /// footpoint.
    #[inline]
    pub fn same_fraction() -> f64 {
        1e-12
    }

    /// Positions along a base case's cycle (offsets) closer than this are
    /// one position when a pocket's content is measured.
    #[inline]
    pub fn cycle_position() -> f64 {
        1e-12
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_scale_with_the_touching_tolerance() {
        let (a, b) = (Tolerance::new(1e-9), Tolerance::new(2e-9));
        for f in [
            Tolerance::sliver_end,
            Tolerance::sliver_pocket,
            Tolerance::hugged_tip,
            Tolerance::same_event,
            Tolerance::same_disk,
            Tolerance::rounding_cycle,
            Tolerance::branch_contact_slack,
            Tolerance::fan_arc,
            Tolerance::hug,
            Tolerance::intruder,
            Tolerance::least_growth,
        ] {
            assert_eq!(f(b), 2.0 * f(a));
            assert!(f(a) > 0.0);
        }
    }

    #[test]
    fn constructed_touch_stays_between_rounding_and_the_tolerance() {
        let t = Tolerance::new(1e-9);
        assert_eq!(t.constructed_touch(1.0), 1e-3 * 1e-9);
        // Far from the origin the coordinates' own rounding sets the floor.
        assert_eq!(t.constructed_touch(1e3), 256.0 * f64::EPSILON * 1e3);
        assert_eq!(t.constructed_touch(1e12), 1e-9);
    }
}
