// CGAL's Segment Delaunay graph (the Voronoi diagram of points and
// segments) of a polygon or of a polygon with holes, for cgal_axis (the
// test) and bench_peers (the benchmark). Header-only; pulls in CGAL, so
// only those two translation units include it.
//
// Traits: the filtered traits without intersections (the polygons are
// simple and their holes disjoint, so no two input segments cross):
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

// Inserts the edges of several loops (an outer boundary and its holes) as
// segment sites: all vertices first (point sites, spatially sorted), then
// each edge between its two end vertices. Vertex k of loop l is point
// number first_l + k (first_l = the sizes of the loops before l), so every
// vertex becomes a point site and every edge a segment site: 2 x (total
// vertices) sites.
inline void insert_loops(Sdg& sdg, const std::vector<Polygon>& loops) {
    std::vector<Sdg::Point_2> points;
    std::vector<std::pair<size_t, size_t>> edges;
    for (const Polygon& poly : loops) {
        const size_t first = points.size();
        for (const Pt& p : poly) points.emplace_back(p.first, p.second);
        for (size_t k = 0; k < poly.size(); ++k) edges.emplace_back(first + k, first + (k + 1) % poly.size());
    }
    sdg.insert_segments(points, edges.begin(), edges.end());
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
