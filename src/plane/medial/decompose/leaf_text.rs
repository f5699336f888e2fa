//! A subshape and the dividing disks its auxiliary arcs come from, as
//! exact text: for reproducing a base-case breakdown found deep inside a
//! large decomposition (minutes to reach) in a test or a debugger (seconds),
//! against the same shape.
//!
//! One piece per line, in travel order; numbers are the bits of the `f64`
//! in hexadecimal, so a round trip is exact:
//!
//! ```text
//! chain LOOP ELEMENT T_BITS LOOP ELEMENT T_BITS
//! aux CENTER_X_BITS CENTER_Y_BITS RADIUS_BITS
//! ```
//!
//! Each `aux` line is its own dividing disk; the cut list read back has one
//! entry per `aux` line, in order (disk indices are renumbered; positions
//! and disks round-trip exactly).

use crate::kernel::Point;
use crate::plane::medial::decompose::subshape::{BoundaryPos, Cut, Piece, Subshape};
use crate::shape::Shape2d;
use std::fmt::Write;

/// Why a leaf text could not be read: the 1-based line and what was wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LeafTextError {
    /// 1-based line number.
    pub line: usize,
    /// What was expected there.
    pub reason: &'static str,
}

impl std::fmt::Display for LeafTextError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "leaf text line {}: {}", self.line, self.reason)
    }
}

impl std::error::Error for LeafTextError {}

/// Writes `s`; its auxiliary arcs index `cuts`. An index outside `cuts`
/// (a caller's bug) is written as a disk of NaN radius, which
/// [`read_leaf`] refuses.
pub fn write_leaf(s: &Subshape, cuts: &[Cut]) -> String {
    let mut out = String::new();
    for p in &s.pieces {
        // Writing to a String cannot fail.
        let _ = match *p {
            Piece::Chain { from, to } => writeln!(
                out,
                "chain {} {} {:x} {} {} {:x}",
                from.loop_index,
                from.element,
                from.t.to_bits(),
                to.loop_index,
                to.element,
                to.t.to_bits()
            ),
            Piece::Aux { disk } => {
                debug_assert!(disk < cuts.len(), "auxiliary arc of disk {disk} of {}", cuts.len());
                let c = cuts.get(disk).copied().unwrap_or(Cut { center: Point::default(), radius: f64::NAN });
                writeln!(out, "aux {:x} {:x} {:x}", c.center.x.to_bits(), c.center.y.to_bits(), c.radius.to_bits())
            }
        };
    }
    out
}

/// Reads a leaf written by [`write_leaf`] for `shape`: the subshape and its
/// own cut list. Every position must name an element of `shape`.
pub fn read_leaf(shape: &Shape2d, text: &str) -> Result<(Subshape, Vec<Cut>), LeafTextError> {
    let (mut pieces, mut cuts) = (Vec::new(), Vec::new());
    for (i, line) in text.lines().enumerate() {
        let err = |reason| LeafTextError { line: i + 1, reason };
        let w: Vec<&str> = line.split_whitespace().collect();
        let bits = |k: usize| -> Result<f64, LeafTextError> {
            let s = w.get(k).ok_or(err("too few fields"))?;
            u64::from_str_radix(s, 16).map(f64::from_bits).map_err(|_| err("a number is not hexadecimal f64 bits"))
        };
        let index = |k: usize| -> Result<usize, LeafTextError> {
            w.get(k).ok_or(err("too few fields"))?.parse().map_err(|_| err("an index is not a whole number"))
        };
        let pos = |k: usize| -> Result<BoundaryPos, LeafTextError> {
            let t = bits(k + 2)?;
            if !(0.0..=1.0).contains(&t) {
                return Err(err("a fraction lies outside [0, 1]"));
            }
            let (loop_index, element) = (index(k)?, index(k + 1)?);
            if shape.loops().get(loop_index).is_none_or(|lp| element >= lp.len()) {
                return Err(err("a position names no element of the shape"));
            }
            Ok(BoundaryPos { loop_index, element, t })
        };
        match w.first().copied() {
            None => continue,
            Some("chain") if w.len() == 7 => pieces.push(Piece::Chain { from: pos(1)?, to: pos(4)? }),
            Some("aux") if w.len() == 4 => {
                let (x, y, r) = (bits(1)?, bits(2)?, bits(3)?);
                if !(x.is_finite() && y.is_finite() && r.is_finite() && r >= 0.0) {
                    return Err(err("a disk is not finite with a radius of at least 0"));
                }
                cuts.push(Cut { center: Point::new(x, y), radius: r });
                pieces.push(Piece::Aux { disk: cuts.len() - 1 });
            }
            Some("chain") | Some("aux") => return Err(err("wrong number of fields")),
            Some(_) => return Err(err("a line starts with neither `chain` nor `aux`")),
        }
    }
    Ok((Subshape { pieces }, cuts))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{samples, ShapeOptions};

    fn star() -> Shape2d {
        Shape2d::from_bulge_loops(samples::star_polygon(20, 1), &ShapeOptions::default()).unwrap()
    }

    #[test]
    fn round_trip_is_exact() {
        let a = BoundaryPos { loop_index: 0, element: 7, t: 0.1 + 0.2 };
        let b = BoundaryPos { loop_index: 0, element: 9, t: 1.0 };
        let cuts = vec![Cut { center: Point::new(1.0 / 3.0, -2e-300), radius: 5e-9 }];
        let s = Subshape { pieces: vec![Piece::Chain { from: a, to: b }, Piece::Aux { disk: 0 }] };
        let (back, back_cuts) = read_leaf(&star(), &write_leaf(&s, &cuts)).unwrap();
        assert_eq!(back, s);
        assert_eq!(back_cuts, cuts);
    }

    #[test]
    fn bad_lines_are_named() {
        let s = star();
        assert_eq!(read_leaf(&s, "chain 0 1 0 0 2 3ff0000000000000\nfoo").unwrap_err().line, 2);
        assert_eq!(read_leaf(&s, "aux 0 0").unwrap_err().reason, "wrong number of fields");
        // Radius -1.
        assert!(read_leaf(&s, "aux 0 0 bff0000000000000").is_err());
        // Fraction 2.
        assert!(read_leaf(&s, "chain 0 1 4000000000000000 0 2 0").is_err());
        assert!(read_leaf(&s, "chain 0 x 0 0 2 0").is_err());
        // Element 20 of a 20-element loop, loop 1 of one.
        assert!(read_leaf(&s, "chain 0 20 0 0 2 0").is_err());
        assert!(read_leaf(&s, "chain 1 0 0 0 2 0").is_err());
    }
}
