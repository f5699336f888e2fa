//! Pictures of Voronoi diagrams: the sites, the edges between sites (dark),
//! self-edges (orange, on request) and the vertices. The library's frame is
//! not drawn: the picture shows the sites with a margin, and edges that run
//! on to infinity leave it at the border.

use crate::io::svg_writer::Style;
use crate::kernel::Point;
use crate::plane::voronoi::{SiteId, VoronoiDiagram};
use crate::shape::draw_sites::{clipped, sites_document};

impl VoronoiDiagram {
    /// An SVG picture `width_px` wide, edges drawn to chordal tolerance
    /// `tol` (model units), self-edges when `self_edges`.
    pub fn to_svg(&self, width_px: f64, tol: f64, self_edges: bool) -> String {
        let shape = self.shape();
        let (mut doc, view) = sites_document(shape, self.auto_frame, width_px);
        let mut shown = 0;
        for i in self.diagram_edges(self_edges) {
            let e = &self.axis.edges[i];
            let pts: Vec<Point> = e.sample(shape, &self.axis.nodes, tol).into_iter().map(|s| s.center).collect();
            let path = clipped(&pts, &view);
            if path.is_empty() {
                continue;
            }
            let style =
                if self.edges[i].self_edge { Style::stroke("#e67e22", 1.0) } else { Style::stroke("#c0392b", 1.6) };
            doc.path(&path, &style);
            shown += 1;
        }
        let deg = self.axis.degrees();
        let mut vertices = 0;
        for (v, n) in self.axis.nodes.iter().enumerate() {
            if deg[v] >= 3 && !self.frontier[v] {
                doc.dot([n.point.x, n.point.y], 2.2, "#111111");
                vertices += 1;
            }
        }
        let sites = self.regions.iter().filter(|r| r.site != SiteId::Frame).count();
        doc.caption(
            0,
            &format!(
                "Voronoi diagram: {sites} sites, {shown} edges{}, {vertices} vertices{}",
                if self_edges { " (self-edges orange)" } else { "" },
                if self.complete { "" } else { "; frame limit reached, far vertices missing" }
            ),
        );
        doc.finish()
    }
}
