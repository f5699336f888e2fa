//! The offset oracle: bulge-loop geometry written again from the
//! definitions, sharing nothing with the library's elements, winding
//! numbers, areas or offsets. An element is a chord plus, for an arc, the
//! circle through its ends given by the bulge; distances are to the
//! element itself (the angular range of an arc), winding numbers are the
//! chord polygon's plus ±1 for a point inside an arc's circular segment,
//! areas the shoelace sum of the chords plus the circular segments.

use super::oracle::Grid;
use medax::kernel::{BBox, Point};
use medax::shape::{Shape2d, Vertex};
use std::f64::consts::{PI, TAU};

/// One element of a bulge loop.
#[derive(Debug, Clone, Copy)]
pub struct Elem {
    pub a: Point,
    pub b: Point,
    pub bulge: f64,
    /// For an arc: centre, radius, signed sweep (positive counter-clockwise).
    pub arc: Option<(Point, f64, f64)>,
}

impl Elem {
    pub fn new(a: Point, b: Point, bulge: f64) -> Elem {
        if bulge == 0.0 {
            return Elem { a, b, bulge, arc: None };
        }
        let half = (b - a) * 0.5;
        let l2 = half.norm();
        // The bulge point is mid + right·(L/2)·bulge, right = the chord's
        // right-hand normal; the centre lies on the same normal at
        // (L/2)·(bulge² − 1)/(2·bulge) on that side.
        let right = Point::new(half.y, -half.x) * (1.0 / l2);
        let centre = a + half + right * (l2 * (bulge * bulge - 1.0) / (2.0 * bulge));
        let radius = l2 * (1.0 + bulge * bulge) / (2.0 * bulge.abs());
        Elem { a, b, bulge, arc: Some((centre, radius, 4.0 * bulge.atan())) }
    }

    /// Where the element is at `t` in [0, 1] (by arc length).
    pub fn at(&self, t: f64) -> Point {
        match self.arc {
            None => self.a + (self.b - self.a) * t,
            Some((c, r, sweep)) => {
                let a0 = (self.a.y - c.y).atan2(self.a.x - c.x) + sweep * t;
                c + Point::new(a0.cos(), a0.sin()) * r
            }
        }
    }

    /// The unit tangent (direction of travel) at `t`.
    pub fn tangent(&self, t: f64) -> Point {
        match self.arc {
            None => (self.b - self.a).unit(),
            Some((c, _, sweep)) => {
                let a0 = (self.a.y - c.y).atan2(self.a.x - c.x) + sweep * t;
                let radial = Point::new(a0.cos(), a0.sin());
                if sweep > 0.0 {
                    Point::new(-radial.y, radial.x)
                } else {
                    Point::new(radial.y, -radial.x)
                }
            }
        }
    }

    pub fn length(&self) -> f64 {
        match self.arc {
            None => self.a.dist(self.b),
            Some((_, r, sweep)) => r * sweep.abs(),
        }
    }

    /// Whether the direction from the centre to `p` lies within the arc's
    /// angular range (ends included).
    fn spans(&self, c: Point, sweep: f64, p: Point) -> bool {
        let s = self.a - c;
        let u = p - c;
        let mut phi = s.cross(u).atan2(s.dot(u));
        if sweep < 0.0 {
            phi = -phi;
        }
        if phi < 0.0 {
            phi += TAU;
        }
        phi <= sweep.abs()
    }

    /// Euclidean distance from `p` to the element.
    pub fn dist(&self, p: Point) -> f64 {
        match self.arc {
            None => {
                let d = self.b - self.a;
                let t = ((p - self.a).dot(d) / d.norm2()).clamp(0.0, 1.0);
                p.dist(self.a + d * t)
            }
            Some((c, r, sweep)) => {
                if self.spans(c, sweep, p) {
                    (p.dist(c) - r).abs()
                } else {
                    p.dist(self.a).min(p.dist(self.b))
                }
            }
        }
    }

    /// The element's bounding box (exact: ends plus the circle's extreme
    /// points within the sweep).
    pub fn bbox(&self) -> BBox {
        let mut b = BBox::of_points(self.a, self.b);
        if let Some((c, r, sweep)) = self.arc {
            for d in [Point::new(1.0, 0.0), Point::new(0.0, 1.0), Point::new(-1.0, 0.0), Point::new(0.0, -1.0)] {
                let q = c + d * r;
                if self.spans(c, sweep, q) {
                    b.add_point(q);
                }
            }
        }
        b
    }

    /// Signed area between the chord and the arc (positive for a
    /// counter-clockwise arc), by r²/2·(θ − sin θ), with the series for
    /// small sweeps.
    pub fn segment_area(&self) -> f64 {
        match self.arc {
            None => 0.0,
            Some((_, r, th)) => {
                let f = if th.abs() < 0.1 {
                    let t2 = th * th;
                    th * t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0)))
                } else {
                    th - th.sin()
                };
                0.5 * r * r * f
            }
        }
    }

    /// Contribution to the winding number of `p`: the chord's signed
    /// crossing of the rightward ray, plus ±1 inside the circular segment.
    ///
    /// A point on a chord's line is moved by (ε², ε), ε infinitesimal
    /// (consistently for every element), so that points on the chords of
    /// half circles (diameters through their centres) count once.
    pub fn winding(&self, p: Point) -> i32 {
        let (a, b) = (self.a, self.b);
        let u = b - a;
        let mut side = u.cross(p - a);
        if side == 0.0 {
            side = if u.x != 0.0 { u.x } else { -u.y };
        }
        let mut w = 0;
        if a.y <= p.y {
            if b.y > p.y && side > 0.0 {
                w += 1;
            }
        } else if b.y <= p.y && side < 0.0 {
            w -= 1;
        }
        if let Some((c, r, _)) = self.arc {
            // The arc bulges to the right of the chord when counter-clockwise.
            if self.bulge * side < 0.0 && p.dist(c) < r {
                w += if self.bulge > 0.0 { 1 } else { -1 };
            }
        }
        w
    }
}

/// The elements of a closed bulge loop.
pub fn elems(vs: &[Vertex]) -> Vec<Elem> {
    (0..vs.len()).map(|i| Elem::new(vs[i].p, vs[(i + 1) % vs.len()].p, vs[i].bulge)).collect()
}

/// Signed area of a closed bulge loop (counter-clockwise positive), with
/// coordinates taken relative to the first vertex.
pub fn area(vs: &[Vertex]) -> f64 {
    let o = vs[0].p;
    elems(vs).iter().map(|e| 0.5 * (e.a - o).cross(e.b - o) + e.segment_area()).sum()
}

pub fn perimeter(vs: &[Vertex]) -> f64 {
    elems(vs).iter().map(Elem::length).sum()
}

/// Winding number of `p` with respect to several loops.
pub fn winding(loops: &[Vec<Elem>], p: Point) -> i32 {
    loops.iter().flatten().map(|e| e.winding(p)).sum()
}

/// One point inside each element (at 0.37 of its length: off the chords
/// and symmetry lines of the test shapes).
pub fn interior_points(vs: &[Vertex]) -> Vec<Point> {
    elems(vs).iter().map(|e| e.at(0.37)).collect()
}

/// Points along a loop's elements: each vertex and `per` interior points
/// per element (more on arcs of large sweep).
pub fn loop_samples(vs: &[Vertex], per: usize) -> Vec<(Point, Point)> {
    let mut out = Vec::new();
    for e in elems(vs) {
        let k = match e.arc {
            None => per,
            Some((_, _, s)) => per + (s.abs() / (PI / 8.0)) as usize,
        };
        for j in 0..=k {
            let t = j as f64 / (k + 1) as f64;
            out.push((e.at(t), e.tangent(t)));
        }
    }
    out
}

/// Distances to a set of bulge loops (a shape's boundary or an offset's
/// loops), nearest element by a uniform grid.
pub struct Loops {
    pub elems: Vec<Vec<Elem>>,
    grid: Grid<Elem>,
    pub bbox: BBox,
}

impl Loops {
    pub fn new(loops: &[&[Vertex]]) -> Loops {
        let elems: Vec<Vec<Elem>> = loops.iter().map(|l| elems(l)).collect();
        let mut bbox = BBox::EMPTY;
        let items: Vec<(Elem, BBox)> = elems
            .iter()
            .flatten()
            .map(|e| {
                let b = e.bbox();
                bbox = bbox.union(&b);
                (*e, b)
            })
            .collect();
        if items.is_empty() {
            bbox = BBox::of_points(Point::new(0.0, 0.0), Point::new(1.0, 1.0));
        }
        Loops { grid: Grid::new(items, bbox), elems, bbox }
    }

    /// The boundary of a validated shape (its stored loops: outer
    /// counter-clockwise, holes clockwise).
    pub fn of_shape(s: &Shape2d) -> Loops {
        let vs: Vec<&[Vertex]> = s.loops().iter().map(|l| l.vertices()).collect();
        Loops::new(&vs)
    }

    pub fn dist(&self, p: Point) -> f64 {
        if self.elems.iter().all(Vec::is_empty) {
            return f64::INFINITY;
        }
        self.grid.nearest(p, |e, q| e.dist(q))
    }

    pub fn winding(&self, p: Point) -> i32 {
        winding(&self.elems, p)
    }
}
