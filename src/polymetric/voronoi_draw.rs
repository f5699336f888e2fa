//! Pictures of Voronoi diagrams under a polygon ball: the sites, the edges
//! between sites (dark; jump edges, whose balls touch both sites at one
//! ball feature's two ends, dashed as in the axis pictures), self-edges
//! (orange, on request), the vertices, and the ball at a few of the
//! largest vertices so that the metric can be seen. The library's frame is
//! not drawn.

use super::draw::ball_path;
use super::voronoi::BallVoronoi;
use crate::io::svg_writer::Style;
use crate::kernel::Point;
use crate::shape::draw_sites::{clipped, sites_document};

/// Balls drawn (at the vertices of largest radius inside the picture).
const BALLS_DRAWN: usize = 3;

impl BallVoronoi {
    /// An SVG picture `width_px` wide, self-edges when `self_edges`.
    pub fn to_svg(&self, width_px: f64, self_edges: bool) -> String {
        let (mut doc, view) = sites_document(self.shape(), self.auto_frame, width_px);
        let inside = |p: Point| p.x >= view[0] && p.x <= view[2] && p.y >= view[1] && p.y <= view[3];
        let axis = &self.axis;
        let mut degree = vec![0usize; axis.nodes.len()];
        let drawn: Vec<usize> = (0..axis.edges.len())
            .filter(|&i| {
                let framed = self.auto_frame && self.edges[i].sides.contains(&crate::shape::SiteId::Frame);
                !framed && (self_edges || !self.edges[i].self_edge)
            })
            .collect();
        for &i in &drawn {
            degree[axis.edges[i].from] += 1;
            degree[axis.edges[i].to] += 1;
        }
        let vertices: Vec<usize> =
            (0..axis.nodes.len()).filter(|&v| degree[v] >= 3 && inside(axis.nodes[v].at)).collect();
        let mut big = vertices.clone();
        big.sort_by(|&a, &b| axis.nodes[b].r.total_cmp(&axis.nodes[a].r));
        for &v in big.iter().take(BALLS_DRAWN) {
            let n = &axis.nodes[v];
            doc.path(&ball_path(&axis.ball, n.at, n.r), &Style::filled("#7f8c8d", "#bdc3c7", 0.8, 0.3));
        }
        let mut shown = 0;
        for &i in &drawn {
            let e = &axis.edges[i];
            let (a, b) = (axis.nodes[e.from].at, axis.nodes[e.to].at);
            let path = clipped(&[a, b], &view);
            if path.is_empty() {
                continue;
            }
            let style = match (self.edges[i].self_edge, e.jump) {
                (true, _) => Style::stroke("#e67e22", 1.0),
                (false, false) => Style::stroke("#c0392b", 1.6),
                (false, true) => Style::stroke("#c0392b", 0.8),
            };
            doc.path(&path, &style);
            shown += 1;
        }
        for &v in &vertices {
            let p = axis.nodes[v].at;
            doc.dot([p.x, p.y], 2.2, "#111111");
        }
        let sites = self.regions.len();
        doc.caption(
            0,
            &format!(
                "Voronoi diagram under a {}-gon ball: {sites} sites, {shown} edges (jump edges thin){}, {} vertices",
                axis.ball.len(),
                if self_edges { ", self-edges orange" } else { "" },
                vertices.len()
            ),
        );
        doc.finish()
    }
}
