//! Path data (the `d` attribute): the commands M, L, H, V, A and Z,
//! absolute and relative, into subpaths.

use crate::io::svg_path::scan::{error, Ctx, Cursor};
use crate::io::svg_path::subpath::{subpath, PathSeg, SvgSubpath};
use crate::io::ParseError;

/// Collects subpaths while path data is read.
#[derive(Default)]
struct Builder {
    out: Vec<SvgSubpath>,
    open: Option<SvgSubpath>,
    cur: [f64; 2],
}

impl Builder {
    fn move_to(&mut self, p: [f64; 2], source: usize) {
        self.out.extend(self.open.take());
        self.open = Some(subpath(p, Vec::new(), false, source));
        self.cur = p;
    }

    fn push(&mut self, seg: PathSeg, to: [f64; 2], source: usize) {
        // Only after a Z is there no open subpath (a leading non-M is rejected
        // earlier); SVG then starts the next one where the closed one started,
        // which is the current point.
        let cur = self.cur;
        let sub = self.open.get_or_insert_with(|| subpath(cur, Vec::new(), false, source));
        sub.segs.push(seg);
        self.cur = to;
    }

    fn close(&mut self) {
        // A second Z in a row has nothing left to close.
        if let Some(mut sub) = self.open.take() {
            sub.closed = true;
            self.cur = sub.start;
            self.out.push(sub);
        }
    }
}

pub(crate) fn parse_path_at(d: &str, base: usize) -> Result<Vec<SvgSubpath>, ParseError> {
    let mut c = Cursor::new(d, base, Ctx::Command('M'));
    let mut b = Builder::default();
    loop {
        c.skip_wsp();
        let Some(letter) = c.peek() else { break };
        let at = base + c.pos;
        match letter {
            b'M' | b'm' | b'L' | b'l' | b'H' | b'h' | b'V' | b'v' | b'A' | b'a' | b'Z' | b'z' => {}
            b'C' | b'c' | b'S' | b's' | b'Q' | b'q' | b'T' | b't' => {
                let msg = format!(
                    "Bézier curves are not supported yet (found the '{}' command); convert curves to lines and arcs first",
                    letter as char
                );
                return Err(ParseError { unsupported: true, ..error(at, msg) });
            }
            _ => return Err(error(at, format!("expected a path command (M, L, H, V, A or Z), found {}", c.found()))),
        }
        if b.out.is_empty() && b.open.is_none() && !matches!(letter, b'M' | b'm') {
            return Err(error(at, format!("path data must begin with a moveto (M or m), found '{}'", letter as char)));
        }
        c.pos += 1;
        c.ctx = Ctx::Command(letter as char);
        c.skip_wsp();
        let relative = letter.is_ascii_lowercase();
        // Relative coordinates are offsets from the current point at each repetition.
        let abs = |b: &Builder, p: [f64; 2]| {
            if relative {
                [b.cur[0] + p[0], b.cur[1] + p[1]]
            } else {
                p
            }
        };
        match letter.to_ascii_uppercase() {
            b'M' => {
                let p = abs(&b, c.pair()?);
                b.move_to(p, at);
                // Further pairs are implicit linetos (relative after `m`).
                while c.more_args() {
                    let to = abs(&b, c.pair()?);
                    b.push(PathSeg::Line { to }, to, at);
                }
            }
            b'L' => loop {
                let to = abs(&b, c.pair()?);
                b.push(PathSeg::Line { to }, to, at);
                if !c.more_args() {
                    break;
                }
            },
            b'H' | b'V' => loop {
                let v = c.number()?;
                let mut to = b.cur;
                let axis = usize::from(letter.eq_ignore_ascii_case(&b'V'));
                to[axis] = if relative { to[axis] + v } else { v };
                b.push(PathSeg::Line { to }, to, at);
                if !c.more_args() {
                    break;
                }
            },
            b'A' => loop {
                let rx = c.number()?;
                c.skip_comma_wsp();
                let ry = c.number()?;
                c.skip_comma_wsp();
                let x_rotation_deg = c.number()?;
                c.skip_comma_wsp();
                let large_arc = c.flag()?;
                let sweep = c.flag()?;
                let to = abs(&b, c.pair()?);
                b.push(PathSeg::Arc { rx, ry, x_rotation_deg, large_arc, sweep, to }, to, at);
                if !c.more_args() {
                    break;
                }
            },
            _ => b.close(),
        }
    }
    b.out.extend(b.open.take());
    Ok(b.out)
}
