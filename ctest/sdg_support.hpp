// CGAL's Segment Delaunay graph (the Voronoi diagram of points and
// segments) of a polygon or of a polygon with holes, for cgal_axis (the
// test) and bench_peers (the benchmark), and of point and polyline sites
// for cgal_voronoi. Header-only; pulls in CGAL, so only those translation
// units include it.
//
// Traits: the filtered traits without intersections (the polygons are
// simple and their holes disjoint, the sites disjoint, so no two input
// segments cross):
// predicates are exact (interval filter, exact fallback), constructions
// such as the Voronoi vertices are in double with square roots
// (Field_with_sqrt_tag).
#ifndef MEDAX_CTEST_SDG_SUPPORT_HPP
#define MEDAX_CTEST_SDG_SUPPORT_HPP

#include "polygon_support.hpp"

#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <utility>
#include <vector>

namespace mt {

using SdgKernel = CGAL::Simple_cartesian<double>;
using SdgTraits = CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<SdgKernel, CGAL::Field_with_sqrt_tag>;
using Sdg = CGAL::Segment_Delaunay_graph_2<SdgTraits>;

// Inserts chains of vertices (closed loops, or open polylines) and lone
// points as SDG sites: all vertices and points first (point sites,
// spatially sorted), then each edge between its two end vertices, so that
// consecutive edges share their end point's site. Vertex k of chain c is
// point number first_c + k (first_c = the sizes of the chains before c),
// the lone points come after the chains' vertices.
inline void insert_chains(Sdg& sdg, const std::vector<Polygon>& chains, bool closed,
                          const std::vector<Pt>& points = {}) {
    std::vector<Sdg::Point_2> pts;
    std::vector<std::pair<size_t, size_t>> edges;
    for (const Polygon& chain : chains) {
        const size_t first = pts.size(), n = chain.size();
        for (const Pt& p : chain) pts.emplace_back(p.first, p.second);
        for (size_t k = 0; k + (closed ? 0 : 1) < n; ++k) edges.emplace_back(first + k, first + (k + 1) % n);
    }
    for (const Pt& p : points) pts.emplace_back(p.first, p.second);
    sdg.insert_segments(pts, edges.begin(), edges.end());
}

// The edges of several loops (an outer boundary and its holes) as segment
// sites: every vertex becomes a point site and every edge a segment site,
// 2 x (total vertices) sites.
inline void insert_loops(Sdg& sdg, const std::vector<Polygon>& loops) {
    insert_chains(sdg, loops, true);
}

// The same for one polygon (without copying it): 2 n sites.
inline void insert_polygon(Sdg& sdg, const Polygon& poly) {
    std::vector<Sdg::Point_2> points;
    points.reserve(poly.size());
    for (const Pt& p : poly) points.emplace_back(p.first, p.second);
    std::vector<std::pair<size_t, size_t>> edges;
    edges.reserve(poly.size());
    for (size_t k = 0; k < poly.size(); ++k) edges.emplace_back(k, (k + 1) % poly.size());
    sdg.insert_segments(points, edges.begin(), edges.end());
}

}  // namespace mt

#endif  // MEDAX_CTEST_SDG_SUPPORT_HPP
