// Cross-checks medax's medial axis under the square unit ball (L-infinity,
// mx_ball_square, thesis chapter 3) of random star polygons against CGAL's
// Segment_Delaunay_graph_Linf_2: the Voronoi diagram of the polygon's
// vertices and edges under the L-infinity distance.
//
// Corpus: 50 random star polygons (mt::star, as cgal_axis: sorted
// jittered angles, radii in [0.3, 1] x R, R log-uniform in [0.5, 500],
// CCW and CW alternately), vertex counts a geometric sequence from 10 to
// 10^4 (the third argument changes the top). Random coordinates put them
// in general position for the square (no edge parallel to an axis or a
// diagonal, no two reflex vertices on one).
//
// CGAL side: one point site per vertex and one segment site per edge; the
// Voronoi vertex of every finite face (Sdg::primal), kept when strictly
// inside the polygon with an L-infinity clearance (brute force here, over
// every edge) above 1e-9 x the diagonal. A kept vertex whose three sites
// are pairwise unrelated (no point site that is an end of a segment site
// of the three) is a ball touching three separate features: a branch.
// The others (a vertex with one of its own edges) are where the contact
// passes from an edge to its end vertex: medax has a node there too (a
// joint or a pseudo-branching), and they are checked the same way.
//
// Checks: (a) every kept CGAL vertex has a medax node within 1e-9
// relative (of the diagonal) in position and the same radius within 1e-9
// relative; (b) every medax MX_NODE_BRANCH has a kept CGAL vertex there;
// (c) every medax node's radius is its L-infinity clearance (brute force).
// Nodes of medax with no CGAL vertex (joints where only the ball feature
// changes, the same shape features on both sides) are counted, not
// compared.

#include "polygon_support.hpp"

#include <CGAL/Segment_Delaunay_graph_Linf_2.h>
#include <CGAL/Segment_Delaunay_graph_Linf_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using mt::Polygon;
using mt::Pt;
using Kernel = CGAL::Simple_cartesian<double>;
using Traits = CGAL::Segment_Delaunay_graph_Linf_filtered_traits_without_intersections_2<Kernel, CGAL::Field_with_sqrt_tag>;
using SdgLinf = CGAL::Segment_Delaunay_graph_Linf_2<Traits>;

// L-infinity distance from p to the segment a-b: the largest square
// centred at p that does not cross it. The distance along the segment is
// convex and piecewise linear with kinks where the segment crosses the
// diagonals through p, so its minimum is at an end or at one of those.
double linf_segment(Pt p, Pt a, Pt b) {
    auto at = [&](double t) {
        const double x = a.first + (b.first - a.first) * t - p.first, y = a.second + (b.second - a.second) * t - p.second;
        return std::max(std::fabs(x), std::fabs(y));
    };
    double best = std::min(at(0.0), at(1.0));
    const double dx = b.first - a.first, dy = b.second - a.second;
    const double ax = a.first - p.first, ay = a.second - p.second;
    // x = y and x = -y along the segment.
    for (double s : {1.0, -1.0}) {
        const double den = dx - s * dy;
        if (den != 0.0) {
            const double t = -(ax - s * ay) / den;
            if (t > 0.0 && t < 1.0) best = std::min(best, at(t));
        }
    }
    return best;
}

double linf_clearance(const Polygon& poly, Pt p) {
    double best = INFINITY;
    for (size_t k = 0; k < poly.size(); ++k) best = std::min(best, linf_segment(p, poly[k], poly[(k + 1) % poly.size()]));
    return best;
}

struct Vertex {
    double x, y, r;
    bool branch;
};

// The kept Voronoi vertices of CGAL's L-infinity diagram of the polygon.
std::vector<Vertex> cgal_vertices(const Polygon& poly, double min_clearance) {
    SdgLinf sdg;
    std::vector<SdgLinf::Point_2> pts;
    for (const Pt& p : poly) pts.emplace_back(p.first, p.second);
    std::vector<std::pair<size_t, size_t>> edges;
    for (size_t k = 0; k < poly.size(); ++k) edges.emplace_back(k, (k + 1) % poly.size());
    sdg.insert_segments(pts, edges.begin(), edges.end());
    std::map<Pt, size_t> index;
    for (size_t k = 0; k < poly.size(); ++k) index.emplace(poly[k], k);
    const size_t n = poly.size();
    auto id = [&](const SdgLinf::Point_2& p) {
        const auto it = index.find({p.x(), p.y()});
        return it == index.end() ? n : it->second;
    };
    std::vector<Vertex> out;
    for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
        const SdgLinf::Point_2 c = sdg.primal(f);
        const Pt p{c.x(), c.y()};
        if (!std::isfinite(p.first) || !std::isfinite(p.second) || !mt::inside(poly, p)) continue;
        const double r = linf_clearance(poly, p);
        if (!(r > min_clearance)) continue;
        std::vector<size_t> points, segs;  // vertex ids; a segment by its two ends
        for (int i = 0; i < 3; ++i) {
            const SdgLinf::Site_2& s = f->vertex(i)->site();
            if (s.is_point()) {
                points.push_back(id(s.point()));
            } else {
                segs.push_back(id(s.source()));
                segs.push_back(id(s.target()));
            }
        }
        bool branch = true;
        for (size_t v : points)
            if (std::find(segs.begin(), segs.end(), v) != segs.end()) branch = false;
        out.push_back({p.first, p.second, r, branch});
    }
    return out;
}

struct Tally {
    size_t polygons = 0, cgal = 0, cgal_branch = 0, medax = 0, medax_branch = 0, unmatched_nodes = 0;
};

void check_polygon(const Polygon& poly, const std::string& name, const mx_ball* square, Tally& t) {
    mt::begin_case(name);
    const double diag = mt::diagonal(poly), eps = 1e-9 * diag;
    const std::vector<double> xyb = mt::bulges(poly);
    const size_t len = poly.size();
    mx_shape2d* raw = nullptr;
    if (!MT_CHECK_OK(mx_shape2d_from_bulges(xyb.data(), xyb.size(), &len, 1, nullptr, &raw))) return;
    mt::ShapePtr shape(raw);
    mx_axis* a = nullptr;
    if (!MT_CHECK_OK(mx_axis_compute_with_ball(shape.get(), square, nullptr, &a))) {
        std::cerr << "    " << mt::last_message() << "\n";
        return;
    }
    mt::AxisPtr axis(a);
    const std::vector<mx_axis_node> nodes = mt::nodes_of(axis.get());
    const std::vector<Vertex> cg = cgal_vertices(poly, eps);
    ++t.polygons;
    t.cgal += cg.size();
    t.medax += nodes.size();
    // A grid of cells of side 1e-6 x diagonal for the matching.
    const double cell = 1e-6 * diag;
    std::multimap<std::pair<long, long>, size_t> grid;
    auto key = [&](double x, double y) { return std::make_pair(std::lround(x / cell), std::lround(y / cell)); };
    for (size_t i = 0; i < nodes.size(); ++i) grid.emplace(key(nodes[i].x, nodes[i].y), i);
    auto near_node = [&](double x, double y, double r) {
        const auto k = key(x, y);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                auto range = grid.equal_range({k.first + dx, k.second + dy});
                for (auto it = range.first; it != range.second; ++it) {
                    const mx_axis_node& m = nodes[it->second];
                    if (std::hypot(m.x - x, m.y - y) <= eps && std::fabs(m.r - r) <= eps) return true;
                }
            }
        return false;
    };
    size_t missing = 0;
    for (const Vertex& v : cg) {
        t.cgal_branch += v.branch;
        if (!near_node(v.x, v.y, v.r)) {
            if (++missing <= 3)
                std::cerr << "    CGAL vertex (" << v.x << ", " << v.y << ") r " << v.r << (v.branch ? " (branch)" : "")
                          << " has no medax node\n";
        }
    }
    MT_CHECK_EQ(missing, size_t{0});
    // (b) and (c).
    size_t unmatched_branches = 0, wrong_radius = 0;
    std::multimap<std::pair<long, long>, size_t> cgrid;
    for (size_t i = 0; i < cg.size(); ++i) cgrid.emplace(key(cg[i].x, cg[i].y), i);
    for (const mx_axis_node& m : nodes) {
        const double r = linf_clearance(poly, {m.x, m.y});
        if (std::fabs(r - m.r) > eps) {
            if (++wrong_radius <= 3) std::cerr << "    medax node (" << m.x << ", " << m.y << ") r " << m.r << ", clearance " << r << "\n";
        }
        if (m.kind != MX_NODE_BRANCH) continue;
        ++t.medax_branch;
        bool found = false;
        const auto k = key(m.x, m.y);
        for (long dx = -1; dx <= 1 && !found; ++dx)
            for (long dy = -1; dy <= 1 && !found; ++dy) {
                auto range = cgrid.equal_range({k.first + dx, k.second + dy});
                for (auto it = range.first; it != range.second; ++it) {
                    const Vertex& v = cg[it->second];
                    if (std::hypot(m.x - v.x, m.y - v.y) <= eps && std::fabs(m.r - v.r) <= eps) found = true;
                }
            }
        if (!found && ++unmatched_branches <= 3)
            std::cerr << "    medax branch (" << m.x << ", " << m.y << ") r " << m.r << " has no CGAL vertex\n";
    }
    MT_CHECK_EQ(unmatched_branches, size_t{0});
    MT_CHECK_EQ(wrong_radius, size_t{0});
    t.unmatched_nodes += nodes.size() >= cg.size() ? nodes.size() - cg.size() : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CGAL_LINF_SEED", 20261206);
    const size_t cases = mt::from_env_or_arg(argc, argv, 2, "MEDAX_CGAL_LINF_CASES", 50);
    const size_t max_n = mt::from_env_or_arg(argc, argv, 3, "MEDAX_CGAL_LINF_MAX_N", 10000);
    std::cout << "cgal_linf: " << cases << " random stars of 10.." << max_n << " vertices under the square ball, seed "
              << seed << "\n";
    mx_ball* square = nullptr;
    MT_CHECK_OK(mx_ball_square(&square));
    std::mt19937_64 rng(seed);
    Tally t;
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < cases; ++i) {
        const double along = cases == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(cases - 1);
        const size_t n = static_cast<size_t>(std::lround(10.0 * std::pow(static_cast<double>(max_n) / 10.0, along)));
        const double R = std::exp(std::uniform_real_distribution<double>(std::log(0.5), std::log(500.0))(rng));
        const bool cw = i % 2 == 1;
        const Polygon p = mt::star(rng, n, R, cw);
        check_polygon(p, "star #" + std::to_string(i) + " n=" + std::to_string(n) + (cw ? " cw" : " ccw"), square, t);
    }
    mx_ball_free(square);
    std::cout << "cgal_linf: " << t.polygons << " polygons in " << mt::seconds_since(start) << " s: " << t.cgal
              << " CGAL L-inf vertices inside (" << t.cgal_branch << " of three separate sites), " << t.medax
              << " medax nodes (" << t.medax_branch << " branch)\n";
    return mt::finish("cgal_linf");
}
