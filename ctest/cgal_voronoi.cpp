// Cross-checks medax's Voronoi diagrams of point and segment sites
// (mx_voronoi_compute with the library's frame) against CGAL's
// Segment_Delaunay_graph_2 (SDG; traits in sdg_support.hpp).
//
// Sites: points, and open polylines (curve sites of one segment or
// several). CGAL gets every point and every polyline vertex as a point
// site and every polyline segment as a segment site between its two end
// vertices (mt::insert_chains), so a polyline is connected as in medax. Both
// sides are compared in *primitives*: the point sites, the polylines'
// vertices and the polylines' segments. medax names its primitives through
// mx_axis_site on the borrowed axis: loop 0 is the frame, then one loop per
// curve, then one per point; a curve's vertex and element indices are the
// caller's (a way-back element names the segment it runs over), a point's
// loop has one vertex and one zero-length element, both the point.
//
// Corpus A, points (default 60 scenes, by scene index mod 5): uniform
//   random points (3..2000, a geometric sequence); regular grids
//   (cocircular quadruples; integer spacing, or 0.1 where rounding breaks
//   them); points on a circle (3..400, cos/sin: cocircular to rounding),
//   sometimes with the centre or a second circle; exactly collinear points
//   (on y = c, x = c or x = y), some with 1..3 points off the line;
//   Gaussian clusters of 1e-4..1e-1 spread.
// Corpus B, segments and points (default 64, mod 4): a random segment or
//   point in each cell of a grid (up to 20 x 20); random segments and
//   points by rejection (at least 1e-3 apart, up to 150 segments);
//   segments and points on one line (exactly collinear, sharing no end
//   points), some with points off the line or a second line; a brick wall
//   of horizontal segments in rows (integer and half coordinates) with
//   points between the rows.
// Corpus C, polylines and points (default 48, mod 3): a polyline of 2..8
//   segments (star-shaped about the cell's centre, or x-monotone) or a
//   point in each cell of a grid; x-monotone polylines of up to 200
//   segments in bands, with horizontal runs (exactly flat vertices) and
//   points between the bands; a polyline spiral with points round it, or
//   integer staircases with points at half-integer places.
// Every scene comes from its own generator seeded with (seed, corpus,
// index); the sites are disjoint by construction (grid cells, rejection,
// gaps), at least 1e-7 of the scene apart (checked).
//
// Per scene (eps = 1e-9 x the sites' bounding-box diagonal):
//   status, frame   mx_voronoi_compute is MX_OK, the frame the library's
//                   (auto_frame 1) and complete (1), with one region per
//                   site.
//   sites           every mx_axis_site names a primitive (or the frame).
//   regions         every site's region is one closed walk
//                   (mx_voronoi_region.walks == 1).
//   vertices        genuine Voronoi vertices, both directions:
//     SDG: the circumcentre (Sdg::primal) of every finite face whose three
//       sites are not a segment and one of its own end points (a "joint":
//       that vertex lies on the segment's normal at its end, and medax has
//       a degree-2 MX_NODE_JOINT there, where its sites change from the
//       segment to the end point); the three sites of an SDG face are
//       always distinct primitives. The radius is the distance to the
//       nearest primitive (brute force). Only vertices whose disk lies
//       inside Γ are kept (|c - centre| + r < R; Γ's centre is the sites'
//       box centre and R is read off the nodes of the frame's edges); with
//       complete = 1 none may be dropped, which is checked.
//     medax: the axis nodes of degree >= 3 (edges counted at their ends)
//       with no incident edge facing the frame (in_diagram 0); each must
//       have three primitives among its edges' sites that are pairwise
//       not a segment and its own end point (else a failed check). Two
//       segments of one polyline meeting at a vertex, with a third
//       primitive, make a genuine vertex on both sides (on the bisector of
//       the convex side, where medax's self-edge starts).
//     Every SDG vertex has a medax vertex, and every medax vertex an SDG
//     vertex, within eps in position and in radius; or, ill-conditioned
//     (counted and printed), within 1e-6 x diagonal with medax's disk
//     touching the SDG vertex's three sites within eps and empty (its
//     radius its brute-force clearance within eps): two points a hair
//     apart on a line parallel to a segment pin their vertex down only
//     loosely. At nearly degenerate
//     places (cocircular points, a grid) either side may have several
//     vertices within eps of each other or one of higher degree, so the
//     match is by position, not one to one; and the SDG face's three
//     primitives must be among the primitives of the medax vertices within
//     eps of it, and a medax vertex's among those of the SDG vertices
//     within eps of it, where a segment and its own end point count as one
//     when the disk touches the segment at that end (a brick wall's
//     vertices on the line through the ends of three rows: medax names the
//     rows' segments, the SDG their end points). medax joins branch points
//     whose disks agree within 64 tolerances (multi-branching): vertices
//     within that distance whose disks touch each other's sites within it
//     match, their primitives are gathered within it, and edges shorter
//     than twice it are not compared.
//     CGAL decides the SDG exactly but constructs its vertices in double:
//     the circumcentre of nearly collinear points, or of points far from
//     the origin for their spread, comes out up to ~1e-4 (!) of the
//     diagonal off (Gaussian clusters), so every SDG vertex is refined by
//     Newton's method in long double on its three sites' distance
//     equations before it is compared (the tally prints how far that moved
//     them; medax's nodes then agree to ~1e-11 of the diagonal).
//   edges           site pairs: for every Voronoi edge of the SDG (the dual
//                   of a finite Delaunay edge) between primitives of two
//                   different input sites and longer than 10 eps (or
//                   unbounded), medax has an edge with in_diagram 1 between
//                   those two sites (mx_voronoi_edge.sides); for every such
//                   medax edge (not is_self) whose nodes are more than
//                   10 eps apart, the SDG has a Voronoi edge between those
//                   two sites. Shorter edges are where the two sides may
//                   resolve a near-degeneracy differently.
//
// A scene on which medax fails (a status other than MX_OK, or any failed
// check) is written as sites JSON ({"points": [[x, y], ...], "curves":
// [[[x, y, 0], ...], ...]}) to DIR/cgal_voronoi_<tag>.json when
// MEDAX_CGAL_VORONOI_DUMP=DIR is set (tag = corpus letter and index, e.g.
// B12); `medax voronoi FILE --svg out.svg` draws it.
//
// Usage: cgal_voronoi [seed] [A scenes] [B scenes] [C scenes]
//        (also MEDAX_CGAL_SEED, MEDAX_CGAL_VORONOI_A, _B, _C; defaults
//         20240611, 60, 64, 48; ~8 s in Release). MEDAX_CGAL_VORONOI_ONLY=tag
//         checks that scene alone (of the same corpus sizes).
//
// At medax 0.1.0 the default corpus fails on 9 scenes, all medax's:
// MX_ERR_NUMERICAL on exactly collinear points (A38, A48, A53: "no branch
// point in a pocket", mostly near the frame where the parallel bisectors
// of consecutive points meet it), on collinear segments (B18, B42, B58
// the same, B50 "no maximal disk at a joint") and on random disjoint
// segments (B61, 150 segments by rejection: "no branch point in a
// pocket"); and A44 (Gaussian clusters): a medax node of degree 4 joins
// points 58, 77, 118 and 124, but 118 is 1.2e-8 (8 eps) outside the disk
// through the other three, so the SDG's vertex (58, 118, 124) and its edge
// 58 | 124 (7e-8 of the diagonal long) are missing. medax's branch points
// seem to be solved to 1e-12 of the *framed* shape's diagonal, and the
// library's frame is 4096 sites' diagonals across, so Voronoi vertices get
// ~1e-8 of the sites' diagonal where a vertex is ill-conditioned (seed 1,
// C40: a vertex 1.5e-8 off one of its own sites).

#include "sdg_support.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using mt::Polygon;
using mt::Pt;

constexpr size_t kNone = std::numeric_limits<size_t>::max();

struct Scene {
    std::vector<Pt> points;
    std::vector<Polygon> curves;  // open polylines of two or more vertices
};

// The primitives of a scene: point sites 0..P-1, then every curve's
// vertices (the point primitives end at `points`), then every curve's
// segments. Input sites: point i is site i, curve c is site P + c.
struct Prims {
    const Scene& scene;
    size_t P, C, points = 0;
    std::vector<Pt> at;                         // point primitives
    std::vector<size_t> site;                   // every primitive's input site
    std::vector<std::array<size_t, 2>> ends;    // segment primitive - points: its end points
    std::vector<size_t> vfirst, sfirst;         // per curve: first vertex, first segment
    std::map<Pt, size_t> by_point;
    std::map<std::pair<size_t, size_t>, size_t> by_ends;  // sorted end points -> segment
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;

    explicit Prims(const Scene& s) : scene(s), P(s.points.size()), C(s.curves.size()) {
        for (size_t i = 0; i < P; ++i) add_point(s.points[i], i);
        for (size_t c = 0; c < C; ++c) {
            vfirst.push_back(at.size());
            for (const Pt& p : s.curves[c]) add_point(p, P + c);
        }
        points = at.size();
        for (size_t c = 0; c < C; ++c) {
            sfirst.push_back(site.size());
            for (size_t k = 0; k + 1 < s.curves[c].size(); ++k) {
                const std::array<size_t, 2> e{vfirst[c] + k, vfirst[c] + k + 1};
                by_ends.emplace(std::make_pair(e[0], e[1]), site.size());
                site.push_back(P + c);
                ends.push_back(e);
            }
        }
    }
    void add_point(const Pt& p, size_t s) {
        by_point.emplace(p, at.size());
        at.push_back(p);
        site.push_back(s);
        x0 = std::min(x0, p.first), x1 = std::max(x1, p.first);
        y0 = std::min(y0, p.second), y1 = std::max(y1, p.second);
    }
    size_t size() const { return site.size(); }
    bool is_segment(size_t k) const { return k >= points; }
    double diagonal() const { return std::hypot(x1 - x0, y1 - y0); }
    Pt centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
    // Whether a and b are a segment and one of its own end points.
    bool own_end(size_t a, size_t b) const {
        if (is_segment(b)) std::swap(a, b);
        if (!is_segment(a) || is_segment(b)) return false;
        const auto& e = ends[a - points];
        return e[0] == b || e[1] == b;
    }
    double distance(size_t k, Pt q) const {
        if (!is_segment(k)) return std::hypot(q.first - at[k].first, q.second - at[k].second);
        const auto& e = ends[k - points];
        return mt::segment_distance(q, at[e[0]], at[e[1]]);
    }
    // Distance to the nearest primitive, brute force (a curve's vertices
    // are never nearer than its segments).
    double clearance(Pt q) const {
        double best = INFINITY;
        for (size_t i = 0; i < P; ++i) best = std::min(best, distance(i, q));
        for (size_t k = points; k < size(); ++k) best = std::min(best, distance(k, q));
        return best;
    }
    // A medax site as a primitive; kNone for the frame, kNone - 1 when it
    // names nothing.
    size_t of(const mx_axis_site& s) const {
        if (s.loop_index == 0) return kNone;
        const size_t l = s.loop_index - 1;
        if (l < C) {
            const size_t n = scene.curves[l].size();
            if (s.is_vertex) return s.index < n ? vfirst[l] + s.index : kNone - 1;
            return s.index + 1 < n ? sfirst[l] + s.index : kNone - 1;
        }
        return l - C < P && s.index == 0 ? l - C : kNone - 1;
    }
    // An SDG site as a primitive (the SDG's sites are the input's exactly).
    size_t of(const mt::Sdg::Site_2& s) const {
        auto point = [&](const mt::Sdg::Point_2& p) {
            const auto it = by_point.find({p.x(), p.y()});
            return it == by_point.end() ? kNone : it->second;
        };
        if (s.is_point()) return point(s.point());
        size_t a = point(s.source()), b = point(s.target());
        if (a > b) std::swap(a, b);
        const auto it = by_ends.find({a, b});
        return it == by_ends.end() ? kNone : it->second;
    }
    std::string name(size_t k) const {
        if (k == kNone) return "the frame";
        if (k >= size()) return "nothing";
        if (k < P) return "point " + std::to_string(k);
        const size_t c = site[k] - P;
        if (!is_segment(k)) return "curve " + std::to_string(c) + " vertex " + std::to_string(k - vfirst[c]);
        return "curve " + std::to_string(c) + " segment " + std::to_string(k - sfirst[c]);
    }
};

// A Voronoi vertex of either side.
struct Vertex {
    double x, y, r;
    std::vector<size_t> prims;  // sorted
};

std::string where(const Vertex& v) {
    return "(" + mt::show(v.x) + ", " + mt::show(v.y) + ") r " + mt::show(v.r);
}

// Vertices of `pool` (sorted by x) within `radius` of (x, y).
std::vector<size_t> near(const std::vector<Vertex>& pool, double x, double y, double radius) {
    auto it = std::lower_bound(pool.begin(), pool.end(), x - radius, [](const Vertex& v, double t) { return v.x < t; });
    std::vector<size_t> out;
    for (; it != pool.end() && it->x <= x + radius; ++it)
        if (std::hypot(it->x - x, it->y - y) <= radius) out.push_back(static_cast<size_t>(it - pool.begin()));
    return out;
}

// Whether `prims` holds three primitives pairwise not a segment and its
// own end point.
bool genuine(const Prims& pr, const std::vector<size_t>& prims) {
    const size_t n = prims.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            if (pr.own_end(prims[i], prims[j])) continue;
            for (size_t k = j + 1; k < n; ++k)
                if (!pr.own_end(prims[i], prims[k]) && !pr.own_end(prims[j], prims[k])) return true;
        }
    return false;
}

// CGAL decides the SDG exactly but constructs its vertices in double,
// and for nearly collinear points (or points far from the origin for
// their spread) the circumcentre it gives can be far off. Refines an SDG
// vertex by Newton's method in long double, starting from CGAL's vertex,
// on two equations that keep their digits where the vertex is far from
// its sites: site 0 against site 1 and against site 2, each pair as
//   points p, q:        (q - p) . (2c - p - q) = 0     (the bisector)
//   point p, segment:   |c - p|^2 - l(c)^2 = 0
//   segments:           l1(c) - l2(c) = 0
// (l the signed distance to the segment's line, positive on CGAL's
// vertex's side: the SDG's segment sites are open, so a vertex touches
// one inside). Keeps CGAL's vertex when the iteration does not settle
// within 1e-3 x diagonal of it.
Pt refine(const Prims& pr, const std::array<size_t, 3>& prims, Pt start) {
    using L = long double;
    // Relative to an input point of the face: differences of input
    // coordinates are exact in long double, and the circumcentre of nearly
    // collinear points is as sensitive to its input as ~R / height.
    const Pt& o = pr.at[pr.is_segment(prims[0]) ? pr.ends[prims[0] - pr.points][0] : prims[0]];
    const L ox = o.first, oy = o.second, sx = start.first - ox, sy = start.second - oy;
    struct Site {
        bool line;
        L px, py, nx, ny;  // a point, or a point of the line and its unit normal
    };
    Site site[3];
    for (int i = 0; i < 3; ++i) {
        const size_t k = prims[i];
        if (!pr.is_segment(k)) {
            site[i] = {false, pr.at[k].first - ox, pr.at[k].second - oy, 0, 0};
            continue;
        }
        const auto& e = pr.ends[k - pr.points];
        const L ax = pr.at[e[0]].first - ox, ay = pr.at[e[0]].second - oy;
        const L dx = pr.at[e[1]].first - ox - ax, dy = pr.at[e[1]].second - oy - ay, len = std::hypot(dx, dy);
        L nx = -dy / len, ny = dx / len;
        if (nx * (sx - ax) + ny * (sy - ay) < 0) nx = -nx, ny = -ny;  // towards CGAL's vertex
        site[i] = {true, ax, ay, nx, ny};
    }
    L x = sx, y = sy;
    for (int iter = 0; iter < 30; ++iter) {
        L f[2], gx[2], gy[2];
        for (int e = 0; e < 2; ++e) {
            const Site &a = site[0], &b = site[e + 1];
            const Site &p = a.line ? b : a, &q = a.line ? a : b;  // a point first, if any
            if (!p.line && !q.line) {
                f[e] = (q.px - p.px) * (2 * x - p.px - q.px) + (q.py - p.py) * (2 * y - p.py - q.py);
                gx[e] = 2 * (q.px - p.px), gy[e] = 2 * (q.py - p.py);
            } else if (!p.line) {
                const L l = q.nx * (x - q.px) + q.ny * (y - q.py);
                f[e] = (x - p.px) * (x - p.px) + (y - p.py) * (y - p.py) - l * l;
                gx[e] = 2 * (x - p.px) - 2 * l * q.nx, gy[e] = 2 * (y - p.py) - 2 * l * q.ny;
            } else {
                f[e] = p.nx * (x - p.px) + p.ny * (y - p.py) - q.nx * (x - q.px) - q.ny * (y - q.py);
                gx[e] = p.nx - q.nx, gy[e] = p.ny - q.ny;
            }
        }
        const L det = gx[0] * gy[1] - gy[0] * gx[1];
        if (!(std::fabs(det) > 0)) return start;
        const L dx = (-f[0] * gy[1] + f[1] * gy[0]) / det, dy = (-gx[0] * f[1] + gx[1] * f[0]) / det;
        x += dx, y += dy;
        if (std::fabs(dx) + std::fabs(dy) <= 1e-18L * (std::fabs(x) + std::fabs(y) + std::fabs(ox) + std::fabs(oy)))
            break;
    }
    const Pt out{static_cast<double>(ox + x), static_cast<double>(oy + y)};
    // Nearly singular (nearly parallel sites): keep CGAL's.
    const bool settled = std::isfinite(out.first) && std::isfinite(out.second) &&
                         std::hypot(out.first - start.first, out.second - start.second) <= 1e-3 * pr.diagonal();
    return settled ? out : start;
}

struct Tally {
    size_t scenes = 0, failed_scenes = 0, points = 0, segments = 0, curves = 0;
    size_t sdg_vertices = 0, sdg_joints = 0, medax_vertices = 0, medax_joints = 0;
    size_t sdg_pairs = 0, medax_pairs = 0, regions = 0;
    double max_pos = 0.0, max_rad = 0.0;  // of matched vertices, / diagonal
    double max_refined = 0.0;             // SDG vertices moved by refine(), / diagonal
    size_t conditioned = 0;               // medax vertices matched as ill-conditioned
    double max_conditioned = 0.0;         // their distance from the SDG vertex, / diagonal
    double medax_secs = 0.0, sdg_secs = 0.0;
    std::vector<std::string> failed;
};

struct VdDeleter {
    void operator()(mx_voronoi* p) const noexcept { mx_voronoi_free(p); }
};

void dump_json(const Scene& s, const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        std::cerr << "    cannot write " << path << "\n";
        return;
    }
    std::fputs("{\"points\": [", f);
    for (size_t i = 0; i < s.points.size(); ++i)
        std::fprintf(f, "%s[%.17g, %.17g]", i ? ", " : "", s.points[i].first, s.points[i].second);
    std::fputs("],\n \"curves\": [", f);
    for (size_t c = 0; c < s.curves.size(); ++c) {
        std::fputs(c ? ",\n  [" : "\n  [", f);
        for (size_t k = 0; k < s.curves[c].size(); ++k)
            std::fprintf(f, "%s[%.17g, %.17g, 0]", k ? ", " : "", s.curves[c][k].first, s.curves[c][k].second);
        std::fputs("]", f);
    }
    std::fputs("]}\n", f);
    std::fclose(f);
    std::cerr << "    written to " << path << "\n";
}

void check_scene(const Scene& scene, const std::string& tag, const std::string& name, Tally& tally) {
    mt::begin_case(tag + " " + name);
    const int failures_before = mt::stats().failures;
    ++tally.scenes;
    const Prims pr(scene);
    tally.points += scene.points.size();
    tally.curves += scene.curves.size();
    tally.segments += pr.size() - pr.points;
    // medax joins branch points whose disks agree within 64 tolerances
    // (multi-branching, thesis 2.2.2.2; tolerance 1e-9 x the sites'
    // diagonal): an SDG edge shorter than that between two vertices is one
    // medax node touching all their sites.
    const double diag = pr.diagonal(), eps = 1e-9 * diag, merged = 64.0 * eps, short_edge = 2.0 * merged;

    std::vector<double> points_xy, curves_xyb;
    std::vector<size_t> lengths;
    for (const Pt& p : scene.points) points_xy.insert(points_xy.end(), {p.first, p.second});
    for (const Polygon& c : scene.curves) {
        for (const Pt& p : c) curves_xyb.insert(curves_xyb.end(), {p.first, p.second, 0.0});
        lengths.push_back(c.size());
    }
    mx_sites in{};
    in.points_xy = points_xy.data();
    in.point_count = scene.points.size();
    in.curves_xyb = curves_xyb.data();
    in.curves_xyb_len = curves_xyb.size();
    in.curve_lengths = lengths.data();
    in.curve_count = lengths.size();

    auto finish = [&] {
        if (mt::stats().failures == failures_before) return;
        ++tally.failed_scenes;
        tally.failed.push_back(tag);
        if (const char* dir = std::getenv("MEDAX_CGAL_VORONOI_DUMP"))
            dump_json(scene, std::string(dir) + "/cgal_voronoi_" + tag + ".json");
    };
    auto t0 = std::chrono::steady_clock::now();
    mx_voronoi* raw = nullptr;
    const mx_status st = mx_voronoi_compute(&in, nullptr, &raw);
    tally.medax_secs += mt::seconds_since(t0);
    std::unique_ptr<mx_voronoi, VdDeleter> vd(raw);
    if (!MT_CHECK_OK(st)) return finish();
    mx_voronoi_info info{};
    MT_CHECK_OK(mx_voronoi_get_info(vd.get(), &info));
    MT_CHECK_EQ(info.auto_frame, 1);
    MT_CHECK_EQ(info.complete, 1);
    MT_CHECK_EQ(info.region_count, pr.P + pr.C);
    const mx_axis* axis = nullptr;
    if (!MT_CHECK_OK(mx_voronoi_axis(vd.get(), &axis))) return finish();

    // Regions: one closed walk each.
    mt::Failures regions{"region not one walk"};
    for (size_t s = 0; s < pr.P + pr.C; ++s) {
        const uint32_t kind = s < pr.P ? MX_SITE_POINT : MX_SITE_CURVE;
        const size_t index = s < pr.P ? s : s - pr.P;
        mx_voronoi_region r{};
        ++tally.regions;
        if (!MT_CHECK_OK(mx_voronoi_get_region(vd.get(), kind, index, &r)) || r.walks != 1)
            regions.add((s < pr.P ? "point " : "curve ") + std::to_string(index) + ": " + std::to_string(r.walks) +
                        " walks");
    }

    // medax: nodes, edges, what they separate.
    const std::vector<mx_axis_node> nodes = mt::nodes_of(axis);
    const std::vector<mx_axis_edge> edges = mt::edges_of(axis);
    std::vector<mx_voronoi_edge> vedges(edges.size());
    for (size_t i = 0; i < edges.size(); ++i) MT_CHECK_OK(mx_voronoi_get_edge(vd.get(), i, &vedges[i]));
    std::vector<size_t> degree(nodes.size());
    std::vector<bool> at_frame(nodes.size());
    std::vector<std::vector<size_t>> node_prims(nodes.size());
    mt::Failures bad_sites{"mx_axis_site naming no primitive"};
    const Pt centre = pr.centre();
    double frame_r = 0.0;  // Γ's radius, from the disks touching it
    std::set<std::pair<size_t, size_t>> medax_pairs;
    std::map<std::pair<size_t, size_t>, size_t> medax_long;  // pair -> an edge longer than short_edge
    auto input_site = [&](const mx_site& s) { return s.kind == MX_SITE_POINT ? s.index : pr.P + s.index; };
    for (size_t i = 0; i < edges.size(); ++i) {
        const mx_axis_edge& e = edges[i];
        if (!MT_CHECK(e.from < nodes.size() && e.to < nodes.size())) continue;
        const bool frame = !vedges[i].in_diagram;
        for (const mx_axis_site& s : e.sites) {
            const size_t k = pr.of(s);
            if (k == kNone - 1)
                bad_sites.add("edge " + std::to_string(i) + ": {loop " + std::to_string(s.loop_index) + ", index " +
                              std::to_string(s.index) + ", is_vertex " + std::to_string(s.is_vertex) + "}");
            for (size_t end : {e.from, e.to})
                if (k < pr.size()) node_prims[end].push_back(k);
        }
        for (size_t end : {e.from, e.to}) {
            ++degree[end];
            if (frame) {
                at_frame[end] = true;
                const mx_axis_node& n = nodes[end];
                frame_r = std::max(frame_r, std::hypot(n.x - centre.first, n.y - centre.second) + n.r);
            }
        }
        if (frame || vedges[i].is_self) continue;
        const size_t a = input_site(vedges[i].sides[0]), b = input_site(vedges[i].sides[1]);
        const std::pair<size_t, size_t> pair{std::min(a, b), std::max(a, b)};
        medax_pairs.insert(pair);
        const double len = std::hypot(nodes[e.from].x - nodes[e.to].x, nodes[e.from].y - nodes[e.to].y);
        if (len > short_edge) medax_long.emplace(pair, i);
    }
    mt::Failures not_genuine{"medax node of degree >= 3 without three distinct sites"};
    std::vector<Vertex> mvs;
    for (size_t i = 0; i < nodes.size(); ++i) {
        auto& p = node_prims[i];
        std::sort(p.begin(), p.end());
        p.erase(std::unique(p.begin(), p.end()), p.end());
        if (degree[i] == 2 && nodes[i].kind == MX_NODE_JOINT) ++tally.medax_joints;
        if (degree[i] < 3 || at_frame[i]) continue;
        const Vertex v{nodes[i].x, nodes[i].y, nodes[i].r, p};
        if (!genuine(pr, p)) {
            std::string names;
            for (size_t k : p) names += (names.empty() ? "" : ", ") + pr.name(k);
            not_genuine.add("node " + std::to_string(i) + " at " + where(v) + ": " + names);
            continue;
        }
        mvs.push_back(v);
    }
    tally.medax_vertices += mvs.size();

    // CGAL: vertices and edges.
    t0 = std::chrono::steady_clock::now();
    mt::Sdg sdg;
    mt::insert_chains(sdg, scene.curves, false, scene.points);
    std::vector<Vertex> svs;
    size_t beyond = 0;
    mt::Failures unknown{"SDG site that is no input primitive"};
    auto prim_of = [&](mt::Sdg::Vertex_handle v) {
        const size_t k = pr.of(v->site());
        if (k == kNone) unknown.add("an SDG site");
        return k;
    };
    if (sdg.dimension() == 2) {
        for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
            std::vector<size_t> p{prim_of(f->vertex(0)), prim_of(f->vertex(1)), prim_of(f->vertex(2))};
            if (std::count(p.begin(), p.end(), kNone)) continue;
            std::sort(p.begin(), p.end());
            if (!genuine(pr, p)) {
                ++tally.sdg_joints;
                continue;
            }
            const mt::Sdg::Point_2 c = sdg.primal(f);
            if (!MT_CHECK(std::isfinite(c.x()) && std::isfinite(c.y()))) continue;
            const Pt q = refine(pr, {p[0], p[1], p[2]}, {c.x(), c.y()});
            tally.max_refined = std::max(tally.max_refined, std::hypot(q.first - c.x(), q.second - c.y()) / diag);
            const double r = pr.clearance(q);
            if (std::hypot(q.first - centre.first, q.second - centre.second) + r >= frame_r) {
                ++beyond;
                continue;
            }
            svs.push_back({q.first, q.second, r, p});
        }
    }
    // Site pairs of the SDG's Voronoi edges: all, and the long ones.
    std::set<std::pair<size_t, size_t>> sdg_pairs;
    std::map<std::pair<size_t, size_t>, double> sdg_long;  // pair -> the longest edge's length
    for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
        const auto f = e->first;
        const int i = e->second;
        const size_t p = prim_of(f->vertex(sdg.ccw(i))), q = prim_of(f->vertex(sdg.cw(i)));
        if (p == kNone || q == kNone || pr.site[p] == pr.site[q]) continue;
        const std::pair<size_t, size_t> pair{std::min(pr.site[p], pr.site[q]), std::max(pr.site[p], pr.site[q])};
        sdg_pairs.insert(pair);
        double len = INFINITY;
        const auto g = f->neighbor(i);
        if (sdg.dimension() == 2 && !sdg.is_infinite(f) && !sdg.is_infinite(g)) {
            const mt::Sdg::Point_2 a = sdg.primal(f), b = sdg.primal(g);
            len = std::hypot(a.x() - b.x(), a.y() - b.y());
        }
        if (len > short_edge) sdg_long[pair] = std::max(sdg_long[pair], len);
    }
    tally.sdg_secs += mt::seconds_since(t0);
    tally.sdg_vertices += svs.size();
    MT_CHECK(unknown.count == 0);
    if (!MT_CHECK(beyond == 0))
        std::cerr << "    " << beyond << " SDG vertices beyond the frame (radius " << frame_r << ") of a complete diagram\n";

    // Vertices, both directions, and their primitives.
    auto by_x = [](const Vertex& a, const Vertex& b) { return a.x < b.x; };
    std::sort(svs.begin(), svs.end(), by_x);
    std::sort(mvs.begin(), mvs.end(), by_x);
    // A medax vertex m and an SDG vertex v match exactly when they are
    // within eps in position and radius; ill-conditioned, when they are
    // within 1e-6 x diagonal and m's disk touches v's three sites within
    // eps (|distance - r| <= eps) and is empty (its radius is its
    // clearance within eps): m is then as good a vertex of those sites as
    // v at the tolerance, only the sites pin it down loosely (two points a
    // hair apart on a line parallel to a segment).
    enum class Match { none, exact, conditioned };
    auto pair_match = [&](const Vertex& m, const Vertex& v) {
        const double pos = std::hypot(m.x - v.x, m.y - v.y);
        if (pos <= eps && std::fabs(m.r - v.r) <= eps) return Match::exact;
        // Within the merge distance, m's disk touching v's sites within it.
        if (pos <= merged && std::fabs(m.r - v.r) <= merged &&
            std::all_of(v.prims.begin(), v.prims.end(),
                        [&](size_t k) { return std::fabs(pr.distance(k, {m.x, m.y}) - m.r) <= merged; }))
            return Match::exact;
        if (pos > 1e-6 * diag) return Match::none;
        for (size_t k : v.prims)
            if (std::fabs(pr.distance(k, {m.x, m.y}) - m.r) > eps) return Match::none;
        return std::fabs(pr.clearance({m.x, m.y}) - m.r) <= eps ? Match::conditioned : Match::none;
    };
    auto match = [&](const std::vector<Vertex>& from, const std::vector<Vertex>& to, bool from_medax,
                     mt::Failures& missing, mt::Failures& sites) {
        for (const Vertex& v : from) {
            std::vector<size_t> all;
            Match found = Match::none;
            for (size_t j : near(to, v.x, v.y, merged)) {
                const Vertex& w = to[j];
                all.insert(all.end(), w.prims.begin(), w.prims.end());
                if ((from_medax ? pair_match(v, w) : pair_match(w, v)) != Match::exact) continue;
                found = Match::exact;
                tally.max_pos = std::max(tally.max_pos, std::hypot(w.x - v.x, w.y - v.y) / diag);
                tally.max_rad = std::max(tally.max_rad, std::fabs(w.r - v.r) / diag);
            }
            const Vertex* nearest = nullptr;
            double best = INFINITY;
            for (size_t j : near(to, v.x, v.y, 1e-6 * diag)) {
                const Vertex& w = to[j];
                const double d = std::hypot(w.x - v.x, w.y - v.y);
                if (d < best) best = d, nearest = &w;
                if (found != Match::none || (from_medax ? pair_match(v, w) : pair_match(w, v)) == Match::none) continue;
                found = Match::conditioned;
                if (!from_medax) continue;
                ++tally.conditioned;
                tally.max_conditioned = std::max(tally.max_conditioned, d / diag);
                std::cout << "cgal_voronoi: " << mt::stats().current_case << ": ill-conditioned vertex, medax "
                          << where(v) << " is " << d / diag << " x diagonal from the SDG's " << where(w) << "\n";
            }
            if (found == Match::none) {
                std::string names;
                for (size_t k : v.prims) names += (names.empty() ? "" : ", ") + pr.name(k);
                missing.add(where(v) + " (" + names + ")" +
                            (nearest ? ", nearest " + where(*nearest) : ", nothing within 1e-6 x diagonal"));
                continue;
            }
            if (found == Match::conditioned) continue;
            // A segment and its own end point are one contact when the
            // disk touches the segment at that end (|end - c| = r).
            auto same_contact = [&](size_t k, size_t m) {
                if (k == m) return true;
                if (!pr.own_end(k, m)) return false;
                const size_t end = pr.is_segment(k) ? m : k;
                return std::fabs(pr.distance(end, {v.x, v.y}) - v.r) <= eps;
            };
            std::string lacks;
            for (size_t k : v.prims)
                if (std::none_of(all.begin(), all.end(), [&](size_t m) { return same_contact(k, m); }))
                    lacks += (lacks.empty() ? "" : ", ") + pr.name(k);
            if (!lacks.empty()) sites.add(where(v) + " lacks " + lacks);
        }
    };
    mt::Failures sdg_missing{"SDG vertex without medax vertex"}, medax_missing{"medax vertex without SDG vertex"};
    mt::Failures sdg_sites{"SDG vertex's primitives not at the medax vertices there"};
    mt::Failures medax_sites{"medax vertex's primitives not at the SDG vertices there"};
    match(svs, mvs, false, sdg_missing, sdg_sites);
    match(mvs, svs, true, medax_missing, medax_sites);

    // Edges: site pairs.
    auto site_name = [&](size_t s) {
        return s < pr.P ? "point " + std::to_string(s) : "curve " + std::to_string(s - pr.P);
    };
    mt::Failures sdg_edges{"SDG edge without medax edge"}, medax_edges{"medax edge without SDG edge"};
    for (const auto& [pair, len] : sdg_long) {
        ++tally.sdg_pairs;
        if (!medax_pairs.count(pair))
            sdg_edges.add(site_name(pair.first) + " | " + site_name(pair.second) + ", length " + mt::show(len));
    }
    for (const auto& [pair, i] : medax_long) {
        ++tally.medax_pairs;
        if (!sdg_pairs.count(pair)) {
            const mx_axis_node &a = nodes[edges[i].from], &b = nodes[edges[i].to];
            medax_edges.add(site_name(pair.first) + " | " + site_name(pair.second) + ", edge " + std::to_string(i) +
                            " from (" + mt::show(a.x) + ", " + mt::show(a.y) + ") to (" + mt::show(b.x) + ", " +
                            mt::show(b.y) + ")");
        }
    }
    for (const mt::Failures* f : {&regions, &bad_sites, &not_genuine, &sdg_missing, &medax_missing, &sdg_sites,
                              &medax_sites, &sdg_edges, &medax_edges})
        mt::record(f->count == 0, __FILE__, __LINE__, std::string(f->what) + ": " + std::to_string(f->count));
    finish();
}

// ---------------------------------------------------------------------------
// Scenes.

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}
double log_uniform(Rng& rng, double lo, double hi) {
    return std::exp(uniform(rng, std::log(lo), std::log(hi)));
}
// The k-th of `count` values of a geometric sequence from lo to hi.
size_t geometric(size_t lo, size_t hi, size_t k, size_t count) {
    const double t = count < 2 ? 0.0 : static_cast<double>(k) / static_cast<double>(count - 1);
    return static_cast<size_t>(std::lround(static_cast<double>(lo) * std::pow(static_cast<double>(hi) / lo, t)));
}

// Drops points nearer than `gap` to an earlier one (sorted sweep).
std::vector<Pt> spaced(std::vector<Pt> pts, double gap) {
    std::sort(pts.begin(), pts.end());
    std::vector<Pt> out;
    for (const Pt& p : pts) {
        bool keep = true;
        for (auto it = out.rbegin(); it != out.rend() && p.first - it->first <= gap; ++it)
            if (std::hypot(p.first - it->first, p.second - it->second) <= gap) keep = false;
        if (keep) out.push_back(p);
    }
    std::shuffle(out.begin(), out.end(), std::mt19937_64(out.size()));
    return out;
}

// Corpus A, points. `j` the scene's index, `n` the corpus size.
std::pair<Scene, std::string> points_scene(Rng& rng, size_t j, size_t n) {
    Scene s;
    const size_t kind = j % 5, rank = j / 5, per_kind = (n + 4 - kind) / 5;
    std::string what;
    switch (kind) {
        case 0: {  // uniform
            const size_t count = geometric(3, 2000, rank, per_kind);
            const double w = log_uniform(rng, 1e-2, 1e3), ox = w * uniform(rng, -50, 50), oy = w * uniform(rng, -50, 50);
            std::vector<Pt> p;
            for (size_t i = 0; i < count; ++i) p.emplace_back(ox + w * uniform(rng, 0, 1), oy + w * uniform(rng, 0, 1));
            s.points = spaced(p, 1e-7 * w);
            what = "uniform points, w " + mt::show(w);
            break;
        }
        case 1: {  // grid
            const size_t kx = 2 + rank * 28 / std::max<size_t>(1, per_kind - 1), ky = 2 + (rank * 7 + 3) % (kx + 1);
            const bool exact = rank % 2 == 0;
            const double h = exact ? 1.0 : 0.1, o = exact ? 3.0 : 0.3;
            for (size_t i = 0; i < kx; ++i)
                for (size_t k = 0; k < ky; ++k) s.points.emplace_back(o + h * static_cast<double>(i), o + h * static_cast<double>(k));
            std::shuffle(s.points.begin(), s.points.end(), rng);
            what = std::to_string(kx) + " x " + std::to_string(ky) + " grid, spacing " + mt::show(h);
            break;
        }
        case 2: {  // circle
            const size_t count = geometric(3, 400, rank, per_kind);
            const double R = log_uniform(rng, 0.1, 100), cx = uniform(rng, -R, R), cy = uniform(rng, -R, R);
            const double phase = uniform(rng, 0, 2 * mt::kPi);
            for (size_t i = 0; i < count; ++i) {
                const double t = phase + 2 * mt::kPi * static_cast<double>(i) / static_cast<double>(count);
                s.points.emplace_back(cx + R * std::cos(t), cy + R * std::sin(t));
            }
            if (rank % 3 == 1) s.points.emplace_back(cx, cy);
            if (rank % 3 == 2)
                for (size_t i = 0; i < count / 2 + 1; ++i) {
                    const double t = phase + 2 * mt::kPi * (static_cast<double>(i) + 0.5) / static_cast<double>(count / 2 + 1);
                    s.points.emplace_back(cx + 0.5 * R * std::cos(t), cy + 0.5 * R * std::sin(t));
                }
            what = std::to_string(count) + " points on a circle" +
                   (rank % 3 == 1 ? " and its centre" : rank % 3 == 2 ? " and a second circle" : "");
            break;
        }
        case 3: {  // collinear
            const size_t count = geometric(3, 100, rank, per_kind), line = rank % 3;
            const double c = uniform(rng, -5, 5);
            std::vector<Pt> p;
            for (size_t i = 0; i < count; ++i) {
                const double t = uniform(rng, -10, 10);
                p.push_back(line == 0 ? Pt{t, c} : line == 1 ? Pt{c, t} : Pt{t, t});
            }
            const size_t off = rank % 2 == 1 ? 1 + rank % 3 : 0;
            for (size_t i = 0; i < off; ++i) p.emplace_back(uniform(rng, -10, 10), uniform(rng, -10, 10));
            s.points = spaced(p, 1e-6);
            what = std::to_string(count) + " collinear points (" + (line == 0 ? "y = c" : line == 1 ? "x = c" : "x = y") +
                   "), " + std::to_string(off) + " off the line";
            break;
        }
        default: {  // clusters
            const size_t clusters = 2 + rank % 19;
            std::vector<Pt> p;
            std::normal_distribution<double> g(0.0, 1.0);
            for (size_t c = 0; c < clusters; ++c) {
                const double cx = uniform(rng, 0, 1), cy = uniform(rng, 0, 1), sigma = log_uniform(rng, 1e-4, 1e-1);
                const size_t m = 3 + static_cast<size_t>(uniform(rng, 0, 48));
                for (size_t i = 0; i < m; ++i) p.emplace_back(cx + sigma * g(rng), cy + sigma * g(rng));
            }
            s.points = spaced(p, 1e-7);
            what = std::to_string(clusters) + " Gaussian clusters";
            break;
        }
    }
    return {s, what + ", " + std::to_string(s.points.size()) + " points"};
}

// Distance between segments ab and cd (0 when they cross).
double segments_distance(Pt a, Pt b, Pt c, Pt d) {
    auto orient = [](Pt p, Pt q, Pt r) {
        return (q.first - p.first) * (r.second - p.second) - (q.second - p.second) * (r.first - p.first);
    };
    const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return 0.0;
    return std::min({mt::segment_distance(a, c, d), mt::segment_distance(b, c, d), mt::segment_distance(c, a, b),
                     mt::segment_distance(d, a, b)});
}

// Corpus B, segments (curves of one segment) and points.
std::pair<Scene, std::string> segments_scene(Rng& rng, size_t j, size_t n) {
    Scene s;
    const size_t kind = j % 4, rank = j / 4, per_kind = (n + 3 - kind) / 4;
    std::string what;
    switch (kind) {
        case 0: {  // one segment or point per grid cell
            const size_t g = geometric(2, 20, rank, per_kind);
            const double cell = log_uniform(rng, 0.1, 10);
            for (size_t i = 0; i < g; ++i)
                for (size_t k = 0; k < g; ++k) {
                    const double x = cell * static_cast<double>(i), y = cell * static_cast<double>(k), u = uniform(rng, 0, 1);
                    auto in_cell = [&] { return Pt{x + cell * uniform(rng, 0.05, 0.95), y + cell * uniform(rng, 0.05, 0.95)}; };
                    if (u < 0.65) {
                        Pt a = in_cell(), b = in_cell();
                        while (std::hypot(a.first - b.first, a.second - b.second) < 0.05 * cell) b = in_cell();
                        s.curves.push_back({a, b});
                    } else if (u < 0.9) {
                        s.points.push_back(in_cell());
                    }
                }
            what = std::to_string(g) + " x " + std::to_string(g) + " cells";
            break;
        }
        case 1: {  // rejection sampling in the unit square
            const size_t m = geometric(3, 150, rank, per_kind);
            std::vector<std::pair<Pt, Pt>> segs;
            auto clear = [&](Pt a, Pt b) {
                for (const auto& [c, d] : segs)
                    if (segments_distance(a, b, c, d) < 1e-3) return false;
                return true;
            };
            for (size_t tries = 0; segs.size() < m && tries < 100 * m; ++tries) {
                const double len = log_uniform(rng, 0.02, 0.4), t = uniform(rng, 0, 2 * mt::kPi);
                const Pt a{uniform(rng, 0, 1), uniform(rng, 0, 1)};
                const Pt b{a.first + len * std::cos(t), a.second + len * std::sin(t)};
                if (clear(a, b)) segs.emplace_back(a, b);
            }
            for (const auto& [a, b] : segs) s.curves.push_back({a, b});
            for (size_t tries = 0; s.points.size() < m / 2 + 1 && tries < 100 * m; ++tries) {
                const Pt p{uniform(rng, 0, 1), uniform(rng, 0, 1)};
                bool ok = clear(p, p);
                for (const Pt& q : s.points) ok = ok && std::hypot(p.first - q.first, p.second - q.second) >= 1e-3;
                if (ok) s.points.push_back(p);
                segs.emplace_back(p, p);  // later points keep clear of it too
            }
            what = "random segments by rejection";
            break;
        }
        case 2: {  // collinear segments and points on one line
            const size_t m = geometric(2, 60, rank, per_kind), line = rank % 3;
            // Multiples of 2^-20: t + c stays exact for the line y = x + c.
            auto dyadic = [&](double lo, double hi) { return std::ldexp(std::round(std::ldexp(uniform(rng, lo, hi), 20)), -20); };
            std::vector<double> cuts;
            for (size_t i = 0; i < 3 * m; ++i) cuts.push_back(dyadic(0, 10));
            std::sort(cuts.begin(), cuts.end());
            auto on = [&](double t, double c) { return line == 0 ? Pt{t, c} : line == 1 ? Pt{c, t} : Pt{t, t + c}; };
            const bool second = rank % 4 == 3;
            for (double c : second ? std::vector<double>{0.0, 1.0} : std::vector<double>{0.0})
                for (size_t i = 0; i + 2 < cuts.size(); i += 3) {
                    if (cuts[i + 1] - cuts[i] < 1e-3 || cuts[i + 2] - cuts[i + 1] < 2e-3) continue;
                    s.curves.push_back({on(cuts[i], c), on(cuts[i + 1], c)});
                    // A point in the gap after the segment, on the line too.
                    if (i % 2 == 0) s.points.push_back(on(0.5 * (cuts[i + 1] + cuts[i + 2]), c));
                }
            if (rank % 2 == 1)
                for (size_t i = 0; i < m / 3 + 1; ++i) {
                    const double t = dyadic(0, 10);
                    s.points.push_back(on(t, second ? (i % 2 ? -1.0 : 2.0) : (i % 2 ? -1.0 : 1.0) * dyadic(0.1, 3)));
                }
            what = std::string("collinear segments (") + (line == 0 ? "y = c" : line == 1 ? "x = c" : "y = x + c") + ")" +
                   (second ? " on two parallel lines" : "") + (rank % 2 == 1 ? " with points off the line" : "");
            break;
        }
        default: {  // brick wall
            const size_t rows = 2 + rank % 11, per_row = 2 + (rank * 5) % 11;
            for (size_t r = 0; r < rows; ++r) {
                const double y = static_cast<double>(r), shift = r % 2 ? 1.0 : 0.0;
                for (size_t k = 0; k < per_row; ++k) {
                    const double x = 2.0 * static_cast<double>(k) + shift;
                    s.curves.push_back({{x, y}, {x + 1.5, y}});
                    if (r + 1 < rows && (k + r) % 2 == 0) s.points.emplace_back(x + 0.75, y + 0.5);
                }
            }
            what = std::to_string(rows) + " rows of " + std::to_string(per_row) + " bricks";
            break;
        }
    }
    return {s, what + ", " + std::to_string(s.curves.size()) + " segments, " + std::to_string(s.points.size()) +
                   " points"};
}

// Corpus C, polylines and points.
std::pair<Scene, std::string> polylines_scene(Rng& rng, size_t j, size_t n) {
    Scene s;
    const size_t kind = j % 3, rank = j / 3, per_kind = (n + 2 - kind) / 3;
    std::string what;
    switch (kind) {
        case 0: {  // a polyline or a point per grid cell
            const size_t g = geometric(2, 14, rank, per_kind);
            for (size_t i = 0; i < g; ++i)
                for (size_t k = 0; k < g; ++k) {
                    const double cx = static_cast<double>(i) + 0.5, cy = static_cast<double>(k) + 0.5, u = uniform(rng, 0, 1);
                    const size_t m = 2 + static_cast<size_t>(uniform(rng, 0, 7));
                    Polygon c;
                    if (u < 0.35) {  // star-shaped about the centre: angles sorted over less than 1.6 pi
                        const double t0 = uniform(rng, 0, 2 * mt::kPi), span = uniform(rng, 0.5, 1.6) * mt::kPi;
                        for (size_t q = 0; q <= m; ++q) {
                            const double t = t0 + span * (static_cast<double>(q) + 0.1 + 0.8 * uniform(rng, 0, 1)) / static_cast<double>(m + 1);
                            const double r = 0.45 * uniform(rng, 0.3, 1.0);
                            c.emplace_back(cx + r * std::cos(t), cy + r * std::sin(t));
                        }
                    } else if (u < 0.7) {  // x-monotone
                        std::vector<double> xs;
                        for (size_t q = 0; q <= m; ++q) xs.push_back(uniform(rng, -0.45, 0.45));
                        std::sort(xs.begin(), xs.end());
                        for (size_t q = 0; q <= m; ++q) xs[q] = cx - 0.45 + 0.9 * (static_cast<double>(q) + 0.5 + 0.8 * (xs[q] + 0.45) / 0.9 - 0.4) / static_cast<double>(m + 1);
                        for (double x : xs) c.emplace_back(x, cy + uniform(rng, -0.45, 0.45));
                    } else if (u < 0.9) {
                        s.points.emplace_back(cx + uniform(rng, -0.45, 0.45), cy + uniform(rng, -0.45, 0.45));
                    }
                    if (!c.empty()) s.curves.push_back(c);
                }
            what = std::to_string(g) + " x " + std::to_string(g) + " cells";
            break;
        }
        case 1: {  // x-monotone polylines in bands, points between them
            const size_t bands = 2 + rank % 7, m = geometric(3, 200, rank, per_kind);
            for (size_t b = 0; b < bands; ++b) {
                const double y0 = static_cast<double>(b);
                Polygon c;
                double y = y0 + uniform(rng, 0, 0.8);
                for (size_t q = 0; q <= m; ++q) {
                    const double x = 10.0 * (static_cast<double>(q) + uniform(rng, 0.1, 0.9)) / static_cast<double>(m + 1);
                    if (uniform(rng, 0, 1) >= 0.25) y = y0 + uniform(rng, 0, 0.8);  // else flat: the same y
                    c.emplace_back(x, y);
                }
                s.curves.push_back(c);
                if (b + 1 < bands)
                    for (size_t q = 0; q < m / 4 + 1; ++q) s.points.emplace_back(uniform(rng, 0, 10), y0 + 0.9);
            }
            what = std::to_string(bands) + " banded polylines of " + std::to_string(m) + " segments";
            break;
        }
        default: {
            if (rank % 2 == 0) {  // a spiral with points round it
                const size_t m = geometric(20, 400, rank / 2, (per_kind + 1) / 2);
                const double turns = 2.0 + static_cast<double>(rank % 5);
                Polygon c;
                for (size_t q = 0; q <= m; ++q) {
                    const double t = 2 * mt::kPi * turns * static_cast<double>(q) / static_cast<double>(m);
                    const double r = 0.2 + t / (2 * mt::kPi);
                    c.emplace_back(r * std::cos(t), r * std::sin(t));
                }
                s.curves.push_back(c);
                const double extent = 1.2 + turns;
                for (size_t tries = 0; s.points.size() < m / 4 + 2 && tries < 100 * m; ++tries) {
                    const Pt p{uniform(rng, -extent, extent), uniform(rng, -extent, extent)};
                    bool ok = true;
                    for (size_t q = 0; ok && q + 1 < c.size(); ++q) ok = mt::segment_distance(p, c[q], c[q + 1]) >= 1e-2;
                    if (ok) s.points.push_back(p);
                }
                what = "a spiral of " + std::to_string(m) + " segments";
            } else {  // integer staircases, points at half-integer places
                const size_t stairs = 2 + rank % 5, steps = 2 + rank % 9;
                for (size_t k = 0; k < stairs; ++k) {
                    Polygon c;
                    const double x0 = 3.0 * static_cast<double>(k);
                    for (size_t q = 0; q <= 2 * steps; ++q)
                        c.emplace_back(x0 + static_cast<double>((q + 1) / 2), static_cast<double>(q / 2));
                    s.curves.push_back(c);
                    for (size_t q = 0; q < steps; ++q) s.points.emplace_back(x0 + static_cast<double>(q) + 2.0, static_cast<double>(q) + 0.5);
                }
                what = std::to_string(stairs) + " staircases of " + std::to_string(steps) + " steps";
            }
            break;
        }
    }
    size_t segments = 0;
    for (const Polygon& c : s.curves) segments += c.size() - 1;
    return {s, what + ", " + std::to_string(s.curves.size()) + " polylines of " + std::to_string(segments) +
                   " segments, " + std::to_string(s.points.size()) + " points"};
}

// The smallest distance between two different sites (brute force on
// primitives; a site's own primitives are not compared).
double min_gap(const Prims& pr) {
    double best = INFINITY;
    for (size_t a = 0; a < pr.points; ++a)
        for (size_t b = 0; b < pr.size(); ++b)
            if (pr.site[b] != pr.site[a]) best = std::min(best, pr.distance(b, pr.at[a]));
    for (size_t a = pr.points; a < pr.size(); ++a)
        for (size_t b = a + 1; b < pr.size(); ++b) {
            if (pr.site[a] == pr.site[b]) continue;
            const auto &ea = pr.ends[a - pr.points], &eb = pr.ends[b - pr.points];
            best = std::min(best, segments_distance(pr.at[ea[0]], pr.at[ea[1]], pr.at[eb[0]], pr.at[eb[1]]));
        }
    return best;
}

void print_tally(const char* corpus, const Tally& t, double secs) {
    std::cout << "cgal_voronoi: " << corpus << ": " << t.scenes << " scenes (" << t.points << " points, " << t.curves
              << " curves of " << t.segments << " segments), " << t.failed_scenes << " failed";
    for (const std::string& f : t.failed) std::cout << " " << f;
    std::cout << "; vertices: SDG " << t.sdg_vertices << " (+" << t.sdg_joints << " joints), medax "
              << t.medax_vertices << " (+" << t.medax_joints << " joints); site pairs: SDG " << t.sdg_pairs
              << ", medax " << t.medax_pairs << "; " << t.regions << " regions\n"
              << "cgal_voronoi: " << corpus << ": max error / diagonal: position " << t.max_pos << ", radius "
              << t.max_rad << "; " << t.conditioned << " ill-conditioned, up to " << t.max_conditioned
              << " apart; SDG vertices refined by up to " << t.max_refined << "; medax " << t.medax_secs << " s, SDG + brute force " << t.sdg_secs << " s, total "
              << secs << " s\n";
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CGAL_SEED", 20240611);
    const size_t counts[3] = {mt::from_env_or_arg(argc, argv, 2, "MEDAX_CGAL_VORONOI_A", 60),
                              mt::from_env_or_arg(argc, argv, 3, "MEDAX_CGAL_VORONOI_B", 64),
                              mt::from_env_or_arg(argc, argv, 4, "MEDAX_CGAL_VORONOI_C", 48)};
    const char* only_env = std::getenv("MEDAX_CGAL_VORONOI_ONLY");
    const std::string only = only_env ? only_env : "";
    std::cout << "cgal_voronoi: CGAL " << CGAL_VERSION_STR << ", medax " << mx_version() << ", seed " << seed << ", "
              << counts[0] << " point scenes (A), " << counts[1] << " segment scenes (B), " << counts[2]
              << " polyline scenes (C)\n";
    using Generator = std::pair<Scene, std::string> (*)(Rng&, size_t, size_t);
    const Generator generators[3] = {points_scene, segments_scene, polylines_scene};
    const char* names[3] = {"A (points)", "B (segments and points)", "C (polylines and points)"};
    for (uint32_t corpus = 0; corpus < 3; ++corpus) {
        Tally tally;
        const auto start = std::chrono::steady_clock::now();
        for (size_t j = 0; j < counts[corpus]; ++j) {
            const std::string tag = std::string(1, static_cast<char>('A' + corpus)) + std::to_string(j);
            if (!only.empty() && tag != only) continue;
            std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), corpus,
                              static_cast<uint32_t>(j)};
            Rng rng(seq);
            const auto [scene, what] = generators[corpus](rng, j, counts[corpus]);
            mt::begin_case(tag + " " + what);
            // The generators' promise: disjoint sites, well apart.
            const Prims pr(scene);
            const double gap = min_gap(pr);
            if (!MT_CHECK(gap >= 1e-7 * pr.diagonal())) std::cerr << "    sites " << gap << " apart\n";
            check_scene(scene, tag, what + " (seed " + std::to_string(seed) + ")", tally);
        }
        print_tally(names[corpus], tally, mt::seconds_since(start));
    }
    return mt::finish("cgal_voronoi");
}
