//! A picture of a solid's medial axis: an SVG of one oblique view, the
//! axis triangles filled by radius (blue small, red large) and painted far
//! to near, over the solid's outline (its feature edges, where the faces
//! turn by more than 20°, and its silhouette). Where a mesh viewer is at
//! hand the PLY coloured by radius shows more; this is for a README, a
//! report or a quick look.

use super::axis::Axis3;
use crate::io::svg_writer::{PathCmd, Style, SvgDocument};
use crate::kernel::Point3;
use crate::shape::Mesh3d;

/// The colour of a radius at `t` in `[0, 1]` of the axis's range: blue,
/// green, red (as the PLY's).
pub fn radius_rgb(t: f64) -> [u8; 3] {
    let t = t.clamp(0.0, 1.0);
    [(255.0 * t) as u8, (255.0 * (1.0 - (2.0 * t - 1.0).abs())) as u8, (255.0 * (1.0 - t)) as u8]
}

/// The view: looking along `toward` (from above, in front, to the right),
/// the screen's right and up.
struct View {
    toward: Point3,
    right: Point3,
    up: Point3,
}

impl View {
    fn oblique() -> View {
        let toward = Point3::new(-1.0, -0.7, -0.55);
        let toward = toward * (1.0 / toward.norm());
        let right = toward.cross(Point3::new(0.0, 0.0, 1.0));
        let right = right * (1.0 / right.norm());
        View { toward, right, up: right.cross(toward) }
    }

    fn screen(&self, p: Point3) -> [f64; 2] {
        [p.dot(self.right), p.dot(self.up)]
    }
}

/// The SVG picture of `axis`, the medial axis of `mesh`, `width_px` wide.
pub fn axis3d_svg(mesh: &Mesh3d, axis: &Axis3, width_px: f64) -> String {
    let view = View::oblique();
    let pos = mesh.positions();
    let corners: Vec<[Point3; 3]> = mesh.triangles().iter().map(|t| t.map(|i| pos[i as usize])).collect();
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for &p in pos {
        let s = view.screen(p);
        for k in 0..2 {
            lo[k] = lo[k].min(s[k]);
            hi[k] = hi[k].max(s[k]);
        }
    }
    let mut doc = SvgDocument::new([lo[0], lo[1], hi[0], hi[1]], width_px);
    // The outline: an edge whose two faces turn by more than 20°, or
    // whose faces look one toward the viewer and one away.
    let normal = |t: usize| {
        let [a, b, c] = corners[t];
        let n = (b - a).cross(c - a);
        n * (1.0 / n.norm().max(f64::MIN_POSITIVE))
    };
    let outline = Style::stroke("#555555", 0.7);
    for h in 0..3 * corners.len() {
        let twin = mesh.twin(h);
        if twin < h {
            continue;
        }
        let (n1, n2) = (normal(h / 3), normal(twin / 3));
        let turned = n1.dot(n2) < 20f64.to_radians().cos();
        let silhouette = (n1.dot(view.toward) < 0.0) != (n2.dot(view.toward) < 0.0);
        if turned || silhouette {
            let [a, b] = [h % 3, (h + 1) % 3].map(|k| corners[h / 3][k]);
            doc.path(&[PathCmd::MoveTo(view.screen(a)), PathCmd::LineTo(view.screen(b))], &outline);
        }
    }
    // The axis, far to near.
    let at = |k: u32| {
        let v = axis.vertices[k as usize];
        (Point3::new(v[0], v[1], v[2]), v[3])
    };
    let (rlo, rhi) =
        axis.vertices.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v[3]), h.max(v[3])));
    let span = if rhi > rlo { rhi - rlo } else { 1.0 };
    let depth = |t: &[u32; 3]| t.iter().map(|&k| at(k).0.dot(view.toward)).sum::<f64>();
    let mut order: Vec<&[u32; 3]> = axis.triangles.iter().collect();
    order.sort_by(|a, b| depth(b).total_cmp(&depth(a)));
    for t in order {
        let r = t.iter().map(|&k| at(k).1).sum::<f64>() / 3.0;
        let [red, green, blue] = radius_rgb((r - rlo) / span);
        let fill = format!("#{red:02x}{green:02x}{blue:02x}");
        let style = Style::filled("#333333", &fill, 0.25, 0.8);
        let [p, q, s] = t.map(|k| view.screen(at(k).0));
        doc.path(&[PathCmd::MoveTo(p), PathCmd::LineTo(q), PathCmd::LineTo(s), PathCmd::Close], &style);
    }
    doc.caption(
        0,
        &format!(
            "medial axis: {} sheets, {} triangles; radius {:.4} (blue) to {:.4} (red)",
            axis.sheets.len(),
            axis.triangles.len(),
            rlo,
            rhi
        ),
    );
    doc.finish()
}
