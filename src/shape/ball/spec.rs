//! Balls named on a command line or in a file: `square`, `diamond`,
//! `triangle`, `ngon:K[:DEGREES]`, or ball JSON `{"vertices": [[x, y],
//! ...]}`.

use super::ball2::Ball2;
use super::error::BallError;
use crate::io::json::read_ball;
use crate::kernel::Point;

/// The forms [`Ball2::parse`] reads, for messages.
const FORMS: &str =
    "square, diamond, triangle, ngon:K or ngon:K:DEGREES (a regular K-gon, first vertex at DEGREES), or ball JSON {\"vertices\": [[x, y], ...]}";

impl Ball2 {
    /// The ball a description names: `square` (L∞), `diamond` (L1),
    /// `triangle` (or `tri`), `ngon:K[:DEGREES]` (a regular K-gon, the
    /// first vertex at DEGREES from the x axis), or ball JSON (`{"vertices":
    /// [[x, y], ...]}`, text starting with `{`). Case and surrounding
    /// blanks do not matter.
    ///
    /// # Errors
    ///
    /// [`BallError::Parse`] for JSON that does not parse,
    /// [`BallError::InvalidArgument`] for a description that names no
    /// ball, and the errors of [`Ball2::new`] and [`Ball2::regular`].
    pub fn parse(text: &str) -> Result<Ball2, BallError> {
        let t = text.trim();
        if t.starts_with('{') {
            let xy = read_ball(t).map_err(BallError::Parse)?;
            let vertices: Vec<Point> = xy.iter().map(|&[x, y]| Point::new(x, y)).collect();
            return Ball2::new(&vertices);
        }
        let lower = t.to_ascii_lowercase();
        let named = |what: String| BallError::InvalidArgument { what: format!("{what}; a ball is one of: {FORMS}") };
        match lower.as_str() {
            "square" => Ok(Ball2::square()),
            "diamond" => Ok(Ball2::diamond()),
            "triangle" | "tri" => Ok(Ball2::triangle()),
            _ => {
                let Some(rest) = lower.strip_prefix("ngon:") else {
                    return Err(named(format!("{t:?} names no ball")));
                };
                let mut parts = rest.split(':');
                let k = parts.next().and_then(|k| k.trim().parse::<usize>().ok());
                let degrees = match parts.next() {
                    None => Some(0.0),
                    Some(d) => d.trim().parse::<f64>().ok(),
                };
                match (k, degrees, parts.next()) {
                    (Some(k), Some(d), None) => Ball2::regular(k, d.to_radians()),
                    _ => Err(named(format!("{t:?}: expected ngon:K or ngon:K:DEGREES"))),
                }
            }
        }
    }
}
