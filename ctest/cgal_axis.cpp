// Cross-checks medax's medial axis of random star polygons, with and
// without holes, against the Voronoi diagram of the shape's vertices and
// edges from CGAL::Segment_Delaunay_graph_2 (SDG; traits in sdg_support.hpp).
//
// Corpus 1, stars: 50 random star polygons (mt::star: sorted jittered
// angles, radii in [0.3, 1] x R, R log-uniform in [0.5, 500], CCW and CW
// alternately), vertex counts a geometric sequence from 10 to 10^4 (the
// third argument changes the top).
//
// Corpus 2, holed stars: 60 shapes (the fourth argument; 0 = none). Shape
// j = 1, 2, ... comes from its own generator, seeded with (seed, j): an
// outer mt::star of n vertices, n a geometric sequence from 10 to 2000
// over j, R log-uniform in [0.5, 500], CW for even j; and k holes, k = 1
// for the first shape, 200 for the last and log-uniform in [1, 200] between.
// A hole is a convex polygon of 3..8 vertices on a randomly turned ellipse
// (aspect in [0.5, 1], angles jittered as in mt::star), CCW or CW at random
// (medax normalises). The star's radii are at least 0.3 R and consecutive
// angles at most 1.8 x 2 pi / n apart, so for n >= 10 its edges keep
// 0.3 R cos(32.4 deg) > 0.25 R from the origin; the holes fill k random
// cells of a ceil(sqrt k) x ceil(sqrt k) grid on the square inscribed in the
// disk of radius 0.24 R, each within 0.45 x the cell's side of the cell's
// (jittered) centre: disjoint, at least 0.1 cell apart, and at least 0.01 R
// inside the star (checked per shape). mx_shape2d_from_bulges must accept
// every shape: a refusal is a failed check, not a skip.
//
// A shape is a list of loops, loop 0 the outer boundary, the others holes;
// a star is the one-loop case and is checked exactly as before holes
// existed. Vertex k of loop l has the global id first_l + k (first_l = the
// vertex counts of the loops before l) and so has edge k of loop l (from
// vertex k to the loop's next vertex), so for one loop the ids are the
// polygon's own indices. The SDG has one site per vertex of every loop (a
// point) and one per edge of every loop (the open segment). Its Voronoi
// vertices are the centres of the circles tangent to the three sites of
// each finite Delaunay face (Sdg::primal). For each one the clearance
// (distance to the nearest edge of any loop) is computed here by brute
// force in double; only vertices strictly inside the shape (inside the
// outer loop and outside every hole, by crossing numbers) with clearance
// > 1e-9 x diagonal are kept. That drops the ones outside and the
// degenerate ones at the shape's own vertices (a vertex and its two edges
// meet at distance 0).
//
// A kept SDG vertex is one of two kinds, by its three sites:
//   joint    a point site v and a segment site e ending or starting at v
//            (on v's own loop: adjacency is per loop): the vertex
//            lies on the normal to e at v (v is then reflex). Of its three
//            Voronoi edges the one between e and v (along that normal, down
//            to v) is not on the medial axis: a disk centred there touches
//            the boundary only at v. medax has a degree-2 node there, where
//            its sites change from (e, other) to (v, other): MX_NODE_JOINT.
//   branch   anything else: all three Voronoi edges are on the medial axis
//            and medax has an MX_NODE_BRANCH.
// No other SDG vertex needs excluding: a vertex equidistant from a segment
// and both its end points cannot exist (the two normals are parallel), and
// one equidistant from a vertex and both its edges is that vertex (r = 0).
// On medax's side, a degree-2 node whose two edges have the same two sites
// (a pass-through node, e.g. where the divide step cut an edge) has no SDG
// vertex; such JOINT nodes are counted and printed, not compared. medax's
// sites (mx_axis_site: loop_index, the caller's element or vertex index,
// is_vertex) are mapped to the same global ids.
//
// Checks, with eps = 1e-9 x diagonal:
//   (a) every medax BRANCH node has an SDG branch vertex within eps in
//       position and radius (the SDG radius being the brute-force clearance)
//   (b) every kept SDG vertex has a medax node of its kind: a branch vertex
//       a BRANCH as in (a); a joint vertex (v, e) a JOINT as below
//   (c) every medax JOINT (not pass-through) is the node of some SDG joint
// so that medax's branch and joint nodes are exactly the SDG's interior
// Voronoi vertices. Four allowances widen (a) - (c), each counted in the
// tally:
//   ill-conditioned branches: medax solves for a branch point until it is
//       equidistant from its three sites to 1e-12 x diagonal; where the
//       vertex is ill-conditioned (e.g. two of the sites nearly collinear
//       edges) that leaves it up to a few eps from the SDG vertex (which is
//       equidistant to ~1e-16). Such a pair also matches when it is within
//       1e-6 x diagonal, the radii within eps, and medax's node is
//       equidistant from the SDG vertex's three sites to 1e-11 x diagonal.
//   inexact SDG vertices: CGAL decides the SDG exactly but constructs its
//       vertices in double, and for a point and two nearly parallel
//       segments the vertex can miss one of its own sites by ~1e-8 x
//       diagonal. Where the SDG vertex is not equidistant from its three
//       sites to eps, medax's node matches when it is within 1e-6 x
//       diagonal, equidistant from those same sites to 1e-10 x diagonal and
//       100 times better than the SDG vertex, and its radius is its
//       brute-force clearance within eps.
//   shifted joints: medax puts most joints exactly (~1e-15) on the SDG
//       vertex, but some on the same axis edge a little towards the v side:
//       the disk still touches v and the line of e, but its foot on that
//       line lies up to tol beyond v (tol = the shape's touching tolerance,
//       relative_tolerance x diagonal = 1e-9 x diagonal), which moves the
//       node about tol / cos(angle between the axis edge and e). The joint
//       match is therefore: a medax JOINT J within 1e-6 x diagonal with
//       |dist(J, line e) - r_J| <= eps, ||J - v| - r_J| <= eps, its foot on
//       e's line between tol + eps beyond v and eps into e, and
//       |r_J - clearance(J)| <= eps (brute force).
//   narrow fans: a reflex vertex whose fan of normals spans less than 4
//       touching tolerances at the disk's radius has no fan in medax (its
//       base cases drop it): both SDG joints at the fan's ends match the one
//       medax JOINT through v within 4 tol + eps of them, radii within the
//       same.
//
// The holed stars get (a) - (c) as above, allowances included, and three
// checks more on medax's sites and topology:
//   (d) every site of every medax edge names an edge of its loop, or a
//       vertex of its loop that is reflex for the shape (or within medax's
//       joint angle, 1e-6 rad, of flat), in the caller's numbering whatever
//       the orientation the loop was given in
//   (e) at every matched pair of (a) - (c) the SDG vertex's three sites are
//       among the sites of the edges at the medax node; allowance (counted
//       as narrow-fan sets): at a joint (v, e) of a fan narrower than 4
//       touching tolerances at the disk's radius (see narrow fans) the node
//       may have v's two edges instead of v
//   (f) the axis is connected and has one independent cycle per hole
//       (edges - nodes + 1 = holes)
// They pass on the stars too (MEDAX_CGAL_AXIS_STAR_SITES=1 turns them on
// there, with (f) wanting no cycle); off by default so that the stars'
// checks and tally stay comparable with earlier runs. The summary prints
// each corpus's tally; the last line before the total gives the check
// counts of the two corpora (each with its skip-rate check).
//
// A shape on which mx_axis_compute fails with MX_ERR_NUMERICAL is printed
// and skipped; the test fails when more than 10 % of either corpus are
// skipped. At medax 0.1.0 no star is, on the default corpus or on seeds 7
// and 11, and no holed star is on the default seed or on seeds 1, 2, 3, 4,
// 5, 6 and 12345 (60 each). Before the augmented boundary walked round a
// hole ahead of an augmenting disk landing on the near side of the hole's
// lowest vertex, 1 or 2 of 60 were, on five of those seeds (three of the
// shapes are in tests/data/holed_*.json).
//
// Usage: cgal_axis [seed] [polygons] [max-vertices] [holed-shapes]
//        (also MEDAX_CGAL_SEED, MEDAX_CGAL_AXIS_CASES, MEDAX_CGAL_AXIS_MAX_N,
//         MEDAX_CGAL_AXIS_HOLED; defaults 20240611, 50, 10000, 60).
//         MEDAX_CGAL_AXIS_DUMP=i writes star i as medax shape JSON to
//         cgal_axis_star_i.json, MEDAX_CGAL_AXIS_HOLED_DUMP=j holed star j
//         to cgal_axis_holed_j.json; MEDAX_CGAL_AXIS_HOLED_ONLY=j checks
//         holed star j alone (of the same corpus size).

#include "sdg_support.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using mt::Failures;
using mt::Polygon;
using mt::Pt;
using mt::seconds_since;

constexpr size_t kNone = std::numeric_limits<size_t>::max();

// A shape as loops of points: loop 0 the outer boundary, the others holes
// (a single polygon is the one-loop case). Vertex k of loop l has the
// global id first[l] + k, and so has edge k of loop l (from vertex k to the
// loop's next vertex); as SDG sites, vertex i is site i and edge i is site
// size() + i. For one loop these are the polygon's own indices.
struct Loops {
    std::vector<Polygon> loops;
    std::vector<size_t> first;  // first[l], and the vertex total at the end
    std::vector<Pt> pts;        // by global id
    std::vector<size_t> succ, pred, loop_of;
    std::vector<std::array<double, 4>> box;  // per loop: x0, y0, x1, y1
    std::vector<double> area2;               // per loop: twice the signed area

    explicit Loops(std::vector<Polygon> ls) : loops(std::move(ls)) {
        for (size_t l = 0; l < loops.size(); ++l) {
            const size_t n = loops[l].size();
            first.push_back(pts.size());
            std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
            for (size_t k = 0; k < n; ++k) {
                const Pt& p = loops[l][k];
                pts.push_back(p);
                succ.push_back(first[l] + (k + 1) % n);
                pred.push_back(first[l] + (k + n - 1) % n);
                loop_of.push_back(l);
                b = {std::min(b[0], p.first), std::min(b[1], p.second), std::max(b[2], p.first), std::max(b[3], p.second)};
            }
            box.push_back(b);
            double a2 = 0.0;
            for (size_t k = 0, j = n - 1; k < n; j = k++)
                a2 += loops[l][j].first * loops[l][k].second - loops[l][k].first * loops[l][j].second;
            area2.push_back(a2);
        }
        first.push_back(pts.size());
    }
    size_t size() const { return pts.size(); }
    size_t holes() const { return loops.size() - 1; }
    const Pt& operator[](size_t v) const { return pts[v]; }
    size_t next(size_t v) const { return succ[v]; }  // on the same loop
    size_t prev(size_t v) const { return pred[v]; }
    // Inside the outer loop and outside every hole (crossing numbers).
    bool inside(Pt p) const {
        if (!mt::inside(loops[0], p)) return false;
        for (size_t l = 1; l < loops.size(); ++l) {
            const auto& b = box[l];
            if (p.first >= b[0] && p.first <= b[2] && p.second >= b[1] && p.second <= b[3] && mt::inside(loops[l], p))
                return false;
        }
        return true;
    }
    // Distance to the nearest edge of any loop, brute force.
    double boundary_distance(Pt p) const {
        double best = INFINITY;
        for (const Polygon& poly : loops) best = std::min(best, mt::boundary_distance(poly, p));
        return best;
    }
    double diagonal() const { return mt::diagonal(pts); }
    // Vertex or edge g in the caller's numbering: "7", or "loop 2 #7" with holes.
    std::string name(size_t g) const {
        const size_t l = loop_of[g];
        return loops.size() == 1 ? std::to_string(g) : "loop " + std::to_string(l) + " #" + std::to_string(g - first[l]);
    }
    std::string site_name(size_t s) const {
        return s == kNone ? std::string("out of range") : s < size() ? "vertex " + name(s) : "edge " + name(s - size());
    }
    // A medax site as a global site id, kNone when it names nothing.
    size_t site_id(const mx_axis_site& s) const {
        if (s.loop_index >= loops.size() || s.index >= loops[s.loop_index].size()) return kNone;
        return (s.is_vertex ? 0 : size()) + first[s.loop_index] + s.index;
    }
    // Whether vertex v is reflex for the shape (the inside is left of an
    // outer loop taken counter-clockwise and of a hole taken clockwise), or
    // within medax's joint angle (1e-6 rad) of flat.
    bool reflex_or_flat(size_t v) const {
        const size_t l = loop_of[v];
        const bool inside_left = (l == 0) == (area2[l] > 0);
        const Pt a = pts[prev(v)], b = pts[v], c = pts[next(v)];
        const double ux = b.first - a.first, uy = b.second - a.second, wx = c.first - b.first, wy = c.second - b.second;
        const double turn = std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
        return std::fabs(turn) < 1e-6 || (inside_left ? turn < 0 : turn > 0);
    }
};

enum class Kind { branch, joint };

const char* kind_name(Kind k) {
    return k == Kind::branch ? "branch" : "joint";
}

// A disk of either side: an SDG Voronoi vertex or a medax node.
struct Disk {
    double x, y, r;
    Kind kind;
    std::array<size_t, 3> sites{};  // SDG: its sites, vertex g as g, edge g as size() + g (see Loops)
    size_t v = 0, e = 0;  // SDG joints: the reflex vertex and the edge (edge g runs from vertex g to next(g))
    bool used = false;    // medax joints: claimed by an SDG joint
    size_t node = kNone;  // medax: the node's index
};

std::string where(const Disk& d) {
    return std::string(kind_name(d.kind)) + " at (" + mt::show(d.x) + ", " + mt::show(d.y) + ") r " + mt::show(d.r);
}

// The kept Voronoi vertices of the SDG of `shape`, classified (see the top).
std::vector<Disk> sdg_vertices(const Loops& shape, double min_clearance, size_t& flat_vertices) {
    mt::Sdg sdg;
    mt::insert_loops(sdg, shape.loops);
    const size_t n = shape.size();
    // Sites back to global vertex ids: the point sites are the input exactly.
    std::map<Pt, size_t> index;
    for (size_t k = 0; k < n; ++k) index.emplace(shape[k], k);
    auto vertex_of = [&](const mt::Sdg::Point_2& p) {
        const auto it = index.find({p.x(), p.y()});
        MT_CHECK(it != index.end());
        return it == index.end() ? n : it->second;
    };
    std::vector<Disk> out;
    for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
        const mt::Sdg::Point_2 c = sdg.primal(f);
        const Pt p{c.x(), c.y()};
        if (!std::isfinite(p.first) || !std::isfinite(p.second) || !shape.inside(p)) continue;
        const double r = shape.boundary_distance(p);
        if (!(r > min_clearance)) continue;
        std::vector<size_t> points, edges;
        for (int i = 0; i < 3; ++i) {
            const mt::Sdg::Site_2& s = f->vertex(i)->site();
            if (s.is_point()) {
                points.push_back(vertex_of(s.point()));
            } else {
                const size_t a = vertex_of(s.source()), b = vertex_of(s.target());
                edges.push_back(a < n && b == shape.next(a) ? a : b);
            }
        }
        Disk d{p.first, p.second, r, Kind::branch};
        for (size_t i = 0; i < points.size(); ++i) d.sites[i] = points[i];
        for (size_t i = 0; i < edges.size(); ++i) d.sites[points.size() + i] = n + edges[i];
        // A point site and an edge of its own loop ending or starting there.
        for (size_t v : points)
            for (size_t e : edges)
                if (v < n && e < n && (v == e || v == shape.next(e))) d.kind = Kind::joint, d.v = v, d.e = e;
        // Three segments, two of them meeting at a vertex v that the disk
        // passes through (within eps): v is nearly flat, its two normals
        // within medax's joint angle (1e-6 rad) of each other, so medax
        // joins the segments smoothly and has one JOINT where its sites
        // change from one segment to the other. (Exactly, a nearly flat
        // convex v adds a corner edge whose disks all touch within eps of
        // v.) Matched like v's joint.
        if (points.empty()) {
            for (size_t i = 0; i < 3; ++i)
                for (size_t j = 0; j < 3; ++j) {
                    if (i == j || edges[i] >= n || d.kind != Kind::branch) continue;
                    const size_t v = shape.next(edges[i]);
                    if (edges[j] != v) continue;
                    const Pt a = shape[edges[i]], b = shape[v], c = shape[shape.next(v)];
                    const double ux = b.first - a.first, uy = b.second - a.second;
                    const double wx = c.first - b.first, wy = c.second - b.second;
                    const double turn = std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
                    const double to_v = std::hypot(p.first - b.first, p.second - b.second);
                    if (std::fabs(turn) < 1e-6 && std::fabs(to_v - r) <= min_clearance)
                        d.kind = Kind::joint, d.v = v, d.e = edges[i], ++flat_vertices;
                }
        }
        out.push_back(d);
    }
    // CGAL shuffles its input with a time-seeded generator, so the faces
    // come in a different order each run; matching takes the first free
    // medax joint, so sort for a reproducible tally.
    std::sort(out.begin(), out.end(), [](const Disk& a, const Disk& b) {
        return std::tie(a.x, a.y, a.r) < std::tie(b.x, b.y, b.r);
    });
    return out;
}

// Disks of `pool` (sorted by x) within `radius` of (x, y), nearest first.
std::vector<size_t> near(const std::vector<Disk>& pool, double x, double y, double radius) {
    auto it = std::lower_bound(pool.begin(), pool.end(), x - radius, [](const Disk& d, double v) { return d.x < v; });
    std::vector<std::pair<double, size_t>> found;
    for (; it != pool.end() && it->x <= x + radius; ++it) {
        const double d = std::hypot(it->x - x, it->y - y);
        if (d <= radius) found.emplace_back(d, static_cast<size_t>(it - pool.begin()));
    }
    std::sort(found.begin(), found.end());
    std::vector<size_t> out;
    for (const auto& f : found) out.push_back(f.second);
    return out;
}

struct Tally {
    size_t polygons = 0, compared = 0, skipped = 0;
    size_t sdg_branches = 0, sdg_joints = 0, medax_branches = 0, medax_joints = 0, pass_through = 0;
    size_t matched_branches = 0, conditioned_branches = 0, sdg_inexact_branches = 0, flat_vertices = 0, exact_joints = 0, shifted_joints = 0, narrow_fan_joints = 0;
    // All / diagonal. Matched branches and exact joints: position and
    // radius; shifted joints: distance from the SDG vertex; all joints:
    // |radius - brute-force clearance|.
    double max_pos = 0.0, max_rad = 0.0, max_joint_pos = 0.0, max_joint_rad = 0.0;
    double max_joint_offset = 0.0, max_joint_clearance = 0.0, max_conditioned = 0.0;
    double medax_secs = 0.0, sdg_secs = 0.0;
    // The site and topology checks (d) - (f) (holes corpus).
    size_t holes = 0, vertices = 0, site_refs = 0, site_nodes = 0, fan_site_nodes = 0, cycles = 0;
};

// Builds the medax shape of `shape`'s loops (all bulges 0).
mx_status make_shape(const Loops& shape, const mx_shape_options& so, mx_shape2d** out) {
    std::vector<double> xyb;
    std::vector<size_t> lens;
    for (const Polygon& poly : shape.loops) {
        const std::vector<double> b = mt::bulges(poly);
        xyb.insert(xyb.end(), b.begin(), b.end());
        lens.push_back(poly.size());
    }
    return mx_shape2d_from_bulges(xyb.data(), xyb.size(), lens.data(), lens.size(), &so, out);
}

// The checks of the top on one shape; `site_checks` adds (d) - (f).
void check_polygon(const Loops& shape, const std::string& name, Tally& tally, bool site_checks) {
    mt::begin_case(name);
    ++tally.polygons;
    tally.holes += shape.holes();
    tally.vertices += shape.size();
    const size_t n = shape.size();
    const double diag = shape.diagonal(), eps = 1e-9 * diag;
    mx_shape_options so;
    mx_shape_options_init(&so, sizeof so);
    const double touch = so.relative_tolerance * diag;
    mx_shape2d* raw_shape = nullptr;
    // A failure here is a failed check (the generator promises valid shapes).
    if (!MT_CHECK_OK(make_shape(shape, so, &raw_shape))) return;
    mt::ShapePtr shape_handle(raw_shape);

    auto t0 = std::chrono::steady_clock::now();
    mx_axis* raw_axis = nullptr;
    const mx_status st = mx_axis_compute(shape_handle.get(), nullptr, &raw_axis);
    tally.medax_secs += seconds_since(t0);
    mt::AxisPtr axis(raw_axis);
    if (st == MX_ERR_NUMERICAL) {
        ++tally.skipped;
        std::cout << "cgal_axis: skipped " << name << ": " << mt::show(st) << " -- " << mt::last_message() << "\n";
        return;
    }
    if (!MT_CHECK_OK(st)) return;
    ++tally.compared;

    // medax's branch and joint nodes; pass-through nodes set aside. Sites
    // as global ids (kNone: names no vertex or edge of the shape).
    const std::vector<mx_axis_node> nodes = mt::nodes_of(axis.get());
    const std::vector<mx_axis_edge> axis_edges = mt::edges_of(axis.get());
    std::vector<std::vector<std::array<size_t, 2>>> pairs(nodes.size());
    std::vector<std::vector<size_t>> node_sites(nodes.size());  // sorted, unique
    Failures d_sites{"(d) medax site naming no reflex vertex or edge"};
    for (const mx_axis_edge& e : axis_edges) {
        std::array<size_t, 2> pair{shape.site_id(e.sites[0]), shape.site_id(e.sites[1])};
        if (site_checks)
            for (int i = 0; i < 2; ++i) {
                ++tally.site_refs;
                const mx_axis_site& s = e.sites[i];
                if (pair[i] == kNone || (s.is_vertex && !shape.reflex_or_flat(pair[i])))
                    d_sites.add("edge " + std::to_string(e.from) + " -> " + std::to_string(e.to) + " site {loop " +
                                std::to_string(s.loop_index) + ", index " + std::to_string(s.index) + ", is_vertex " +
                                std::to_string(s.is_vertex) + "} (" +
                                (pair[i] == kNone ? std::string("out of range") : "a convex vertex") + ")");
            }
        std::sort(pair.begin(), pair.end());
        for (size_t end : {e.from, e.to}) {
            if (end >= nodes.size()) continue;
            pairs[end].push_back(pair);
            node_sites[end].insert(node_sites[end].end(), pair.begin(), pair.end());
        }
    }
    for (auto& s : node_sites) {
        std::sort(s.begin(), s.end());
        s.erase(std::unique(s.begin(), s.end()), s.end());
    }
    std::vector<Disk> branches, joints;
    for (size_t i = 0; i < nodes.size(); ++i) {
        const mx_axis_node& nd = nodes[i];
        if (nd.kind == MX_NODE_BRANCH) {
            branches.push_back({nd.x, nd.y, nd.r, Kind::branch});
            branches.back().node = i;
        }
        if (nd.kind != MX_NODE_JOINT) continue;
        if (pairs[i].size() == 2 && pairs[i][0] == pairs[i][1]) {
            ++tally.pass_through;
            std::cout << "cgal_axis: " << name << ": pass-through medax joint at (" << nd.x << ", " << nd.y << ")\n";
            continue;
        }
        joints.push_back({nd.x, nd.y, nd.r, Kind::joint});
        joints.back().node = i;
    }
    tally.medax_branches += branches.size();
    tally.medax_joints += joints.size();

    t0 = std::chrono::steady_clock::now();
    std::vector<Disk> sdg = sdg_vertices(shape, eps, tally.flat_vertices);
    tally.sdg_secs += seconds_since(t0);
    std::vector<Disk> sdg_branches;
    for (const Disk& d : sdg) {
        if (d.kind == Kind::branch) sdg_branches.push_back(d);
    }
    tally.sdg_branches += sdg_branches.size();
    tally.sdg_joints += sdg.size() - sdg_branches.size();

    auto by_x = [](const Disk& a, const Disk& b) { return a.x < b.x; };
    std::sort(sdg_branches.begin(), sdg_branches.end(), by_x);
    std::sort(branches.begin(), branches.end(), by_x);
    std::sort(joints.begin(), joints.end(), by_x);

    // The angle spanned by the normals at vertex v.
    auto fan_of = [&](size_t v) {
        const Pt a = shape[shape.prev(v)], b = shape[v], c2 = shape[shape.next(v)];
        const double ux = b.first - a.first, uy = b.second - a.second;
        const double wx = c2.first - b.first, wy = c2.second - b.second;
        return std::fabs(std::atan2(ux * wy - uy * wx, ux * wx + uy * wy));
    };
    const double reach = 4.0 * touch + eps;  // narrow fans, see below

    // (e): the SDG vertex's three sites are among the sites of the edges at
    // the medax node matched to it, except that at a joint (v, e) of a fan
    // narrower than 4 touching tolerances at the disk's radius medax may
    // have dropped v for its two edges (see narrow fans below).
    Failures e_sites{"(e) matched medax node without the SDG vertex's sites"};
    auto compare_sites = [&](const Disk& s, const Disk& medax) {
        if (!site_checks) return;
        const std::vector<size_t>& have = node_sites[medax.node];
        auto has = [&](size_t k) { return std::binary_search(have.begin(), have.end(), k); };
        std::vector<size_t> missing;
        for (size_t k : s.sites)
            if (!has(k)) missing.push_back(k);
        if (missing.empty()) {
            ++tally.site_nodes;
            return;
        }
        if (s.kind == Kind::joint && missing.size() == 1 && missing[0] == s.v && has(n + shape.prev(s.v)) &&
            has(n + s.v) && fan_of(s.v) * s.r <= reach) {
            ++tally.fan_site_nodes;
            return;
        }
        std::string lacks, all;
        for (size_t k : missing) lacks += (lacks.empty() ? "" : ", ") + shape.site_name(k);
        for (size_t k : have) all += (all.empty() ? "" : ", ") + shape.site_name(k);
        e_sites.add("SDG " + where(s) + ": medax " + where(medax) + " (node " + std::to_string(medax.node) +
                    ") lacks " + lacks + " (has " + all + ")");
    };

    // (a) and the branch half of (b): within eps in position and radius, or
    // (ill-conditioned) within eps in radius and 1e-6 x diagonal in position
    // with medax's node equidistant from the SDG vertex's three sites to
    // 1e-11 x diagonal.
    auto spread = [&](const Disk& s, double x, double y) {  // of the distances to the sites of s
        double lo = INFINITY, hi = 0.0;
        for (size_t k : s.sites) {
            const double d = k < n ? std::hypot(x - shape[k].first, y - shape[k].second)
                                   : mt::segment_distance({x, y}, shape[k - n], shape[shape.next(k - n)]);
            lo = std::min(lo, d), hi = std::max(hi, d);
        }
        return hi - lo;
    };
    enum class Match { none, exact, conditioned, sdg_inexact };
    auto branch_match = [&](const Disk& medax, const Disk& s) {
        const double pos = std::hypot(medax.x - s.x, medax.y - s.y);
        const bool same_sites = spread(s, medax.x, medax.y) <= 1e-11 * diag;
        if (std::fabs(medax.r - s.r) > eps) {
            // CGAL decides the SDG's topology exactly but constructs its
            // vertices in double: for a point and two nearly parallel
            // segments that vertex can miss one of its own sites by 1e-8 x
            // diagonal. Then medax's node must be equidistant from the
            // same three sites, at its own clearance.
            const double sdg_spread = spread(s, s.x, s.y), medax_spread = spread(s, medax.x, medax.y);
            const bool inexact = sdg_spread > eps && pos <= 1e-6 * diag;
            const bool closer = medax_spread <= 1e-10 * diag && 100.0 * medax_spread <= sdg_spread;
            const bool clear = std::fabs(medax.r - shape.boundary_distance({medax.x, medax.y})) <= eps;
            return inexact && closer && clear ? Match::sdg_inexact : Match::none;
        }
        if (pos <= eps) return Match::exact;
        return same_sites ? Match::conditioned : Match::none;
    };
    auto match_branches = [&](const std::vector<Disk>& from, const std::vector<Disk>& to, bool from_medax,
                              Failures& failures) {
        for (const Disk& d : from) {
            Match m = Match::none;
            const Disk* other = nullptr;
            for (size_t j : near(to, d.x, d.y, 1e-6 * diag)) {
                other = &to[j];
                m = from_medax ? branch_match(d, *other) : branch_match(*other, d);
                if (m != Match::none) break;
            }
            if (m == Match::none) {
                failures.add(where(d) + (other ? ", nearest " + where(*other) : std::string(", nothing near")));
                continue;
            }
            if (!from_medax) compare_sites(d, *other);
            const double pos = std::hypot(other->x - d.x, other->y - d.y) / diag;
            if (m == Match::sdg_inexact) {
                if (from_medax) {
                    ++tally.sdg_inexact_branches;
                    std::cout << "cgal_axis: " << mt::stats().current_case << ": SDG vertex inexact, medax "
                              << where(d) << " is " << pos << " x diagonal from it; the SDG vertex is equidistant "
                              << "from its sites to " << spread(*other, other->x, other->y) / diag
                              << " x diagonal, medax's node to " << spread(*other, d.x, d.y) / diag << "\n";
                }
                continue;
            }
            if (m == Match::conditioned) {
                if (from_medax) {
                    ++tally.conditioned_branches;
                    tally.max_conditioned = std::max(tally.max_conditioned, pos);
                    std::cout << "cgal_axis: " << mt::stats().current_case << ": ill-conditioned branch, medax "
                              << where(d) << " is " << pos << " x diagonal from the SDG vertex, equidistant from its "
                              << "sites to " << spread(*other, d.x, d.y) / diag << " x diagonal\n";
                }
                continue;
            }
            tally.max_pos = std::max(tally.max_pos, pos);
            tally.max_rad = std::max(tally.max_rad, std::fabs(other->r - d.r) / diag);
        }
    };
    Failures a{"(a) medax branch without SDG branch"}, b_branch{"(b) SDG branch without medax branch"};
    match_branches(branches, sdg_branches, true, a);
    match_branches(sdg_branches, branches, false, b_branch);
    tally.matched_branches += branches.size() - a.count;

    // The joint half of (b), and (c).
    Failures b_joint{"(b) SDG joint without medax joint"}, c{"(c) medax joint without SDG joint"};
    for (const Disk& s : sdg) {
        if (s.kind != Kind::joint) continue;
        const Pt v = shape[s.v], o = shape[s.v == s.e ? shape.next(s.e) : s.e];
        const double len = std::hypot(o.first - v.first, o.second - v.second);
        const double tx = (o.first - v.first) / len, ty = (o.second - v.second) / len;
        // The normal of e towards the SDG vertex (the inside).
        const double side = (s.x - v.first) * -ty + (s.y - v.second) * tx;
        const double nx = side > 0 ? -ty : ty, ny = side > 0 ? tx : -tx;
        bool found = false;
        for (size_t j : near(joints, s.x, s.y, 1e-6 * diag)) {
            Disk& J = joints[j];
            const double dx = J.x - v.first, dy = J.y - v.second;
            const double foot = dx * tx + dy * ty;              // along e from v
            const double tangent = dx * nx + dy * ny - J.r;     // distance to e's line - r
            const double through = std::hypot(dx, dy) - J.r;    // distance to v - r
            if (J.used || foot < -touch - eps || foot > eps || std::fabs(tangent) > eps || std::fabs(through) > eps)
                continue;
            const double clearance_error = std::fabs(shape.boundary_distance({J.x, J.y}) - J.r);
            if (!MT_CHECK(clearance_error <= eps)) std::cerr << "    at medax " << where(J) << "\n";
            J.used = found = true;
            compare_sites(s, J);
            const double offset = std::hypot(J.x - s.x, J.y - s.y);
            if (offset <= eps && std::fabs(J.r - s.r) <= eps) {
                ++tally.exact_joints;
                tally.max_joint_pos = std::max(tally.max_joint_pos, offset / diag);
                tally.max_joint_rad = std::max(tally.max_joint_rad, std::fabs(J.r - s.r) / diag);
            } else {
                ++tally.shifted_joints;
                tally.max_joint_offset = std::max(tally.max_joint_offset, offset / diag);
            }
            tally.max_joint_clearance = std::max(tally.max_joint_clearance, clearance_error / diag);
            break;
        }
        if (!found) {
            // A reflex vertex whose fan of normals spans less than 4
            // touching tolerances at the disk's radius is one medax joint
            // for both of the fan's ends (the base cases drop such a fan).
            if (fan_of(s.v) * s.r <= reach) {
                for (size_t j : near(joints, s.x, s.y, reach)) {
                    Disk& J = joints[j];
                    const double through = std::hypot(J.x - v.first, J.y - v.second) - J.r;
                    if (std::fabs(J.r - s.r) > reach || std::fabs(through) > eps) continue;
                    J.used = found = true;
                    ++tally.narrow_fan_joints;
                    compare_sites(s, J);
                    break;
                }
            }
        }
        if (!found)
            b_joint.add(where(s) + " (vertex " + shape.name(s.v) + ", edge " + shape.name(s.e) + ")");
    }
    for (const Disk& J : joints)
        if (!J.used) c.add(where(J));
    for (const Failures* f : {&a, &b_branch, &b_joint, &c})
        mt::record(f->count == 0, __FILE__, __LINE__, std::string(f->what) + ": " + std::to_string(f->count));
    if (!site_checks) return;

    // (f): the axis is connected, with one independent cycle per hole
    // (edges - nodes + components = cycles).
    std::vector<size_t> root(nodes.size());
    std::iota(root.begin(), root.end(), size_t{0});
    auto find = [&](size_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    size_t components = nodes.size();
    for (const mx_axis_edge& e : axis_edges) {
        if (e.from >= nodes.size() || e.to >= nodes.size()) continue;
        const size_t p = find(e.from), q = find(e.to);
        if (p != q) root[p] = q, --components;
    }
    const size_t cycles = axis_edges.size() + components - nodes.size();
    if (components == 1 && cycles == shape.holes()) ++tally.cycles;
    mt::record(components == 1 && cycles == shape.holes(), __FILE__, __LINE__,
               "(f) axis of " + std::to_string(shape.holes()) + " holes: " + std::to_string(nodes.size()) +
                   " nodes, " + std::to_string(axis_edges.size()) + " edges, " + std::to_string(components) +
                   " components, " + std::to_string(cycles) + " independent cycles");
    for (const Failures* f : {&d_sites, &e_sites})
        mt::record(f->count == 0, __FILE__, __LINE__, std::string(f->what) + ": " + std::to_string(f->count));
}

// A random convex polygon of m vertices around (cx, cy): on an ellipse of
// semi-axes rho and rho x [0.5, 1], turned at random, at angles jittered as
// in mt::star (consecutive ones at least 0.2 x 2 pi / m apart);
// counter-clockwise unless `cw`.
Polygon convex_polygon(std::mt19937_64& rng, size_t m, double cx, double cy, double rho, bool cw) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double turn = 2.0 * mt::kPi * u(rng), aspect = 0.5 + 0.5 * u(rng);
    const double ct = std::cos(turn), st = std::sin(turn);
    Polygon p;
    for (size_t k = 0; k < m; ++k) {
        const double t = 2.0 * mt::kPi * (static_cast<double>(k) + 0.1 + 0.8 * u(rng)) / static_cast<double>(m);
        const double x = rho * std::cos(t), y = aspect * rho * std::sin(t);
        p.emplace_back(cx + ct * x - st * y, cy + st * x + ct * y);
    }
    if (cw) std::reverse(p.begin(), p.end());
    return p;
}

// A star (mt::star, n vertices, radius R) with k convex holes of 3..8
// vertices, each hole's orientation random. The star's vertices have radii
// of at least 0.3 R and consecutive ones are at most 1.8 x 2 pi / n apart in
// angle, so for n >= 10 its edges stay 0.3 R cos(0.9 x 2 pi / 10) > 0.25 R
// from the origin. The holes fill k random cells of a g x g grid (g =
// ceil(sqrt k)) on the square inscribed in the disk of radius 0.24 R: in a
// cell of side c, radius rho in [0.15, 0.3] c around the cell's centre
// moved by up to 0.1 c in x and in y, so each hole stays within 0.45 c of
// its cell's centre, at least 0.1 c from the others and 0.01 R from the
// star.
std::vector<Polygon> holed_star(std::mt19937_64& rng, size_t n, size_t k, double R, bool cw) {
    std::vector<Polygon> loops{mt::star(rng, n, R, cw)};
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const size_t g = static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(k)) - 1e-9));
    const double side = 0.24 * std::sqrt(2.0) * R, cell = side / static_cast<double>(g);
    std::vector<size_t> cells(g * g);
    std::iota(cells.begin(), cells.end(), size_t{0});
    std::shuffle(cells.begin(), cells.end(), rng);
    for (size_t h = 0; h < k; ++h) {
        const size_t ix = cells[h] % g, iy = cells[h] / g;
        const double cx = -0.5 * side + (static_cast<double>(ix) + 0.5 + 0.2 * (u(rng) - 0.5)) * cell;
        const double cy = -0.5 * side + (static_cast<double>(iy) + 0.5 + 0.2 * (u(rng) - 0.5)) * cell;
        const double rho = (0.15 + 0.15 * u(rng)) * cell;
        const size_t m = 3 + static_cast<size_t>(u(rng) * 6.0) % 6;
        const bool hole_cw = u(rng) < 0.5;
        loops.push_back(convex_polygon(rng, m, cx, cy, rho, hole_cw));
    }
    return loops;
}

void dump_json(const std::vector<Polygon>& loops, const std::string& path) {
    // The shape as medax shape JSON, to look at a mismatch with the CLI.
    std::ofstream out(path);
    out.precision(17);
    out << "{\"loops\": [";
    for (size_t l = 0; l < loops.size(); ++l) {
        out << (l ? ", [" : "[");
        for (size_t k = 0; k < loops[l].size(); ++k)
            out << (k ? ", [" : "[") << loops[l][k].first << ", " << loops[l][k].second << "]";
        out << "]";
    }
    out << "]}\n";
}

void print_tally(const Tally& t, const std::string& head, double total_secs) {
    std::cout << "cgal_axis: " << head << ", " << t.compared << " compared, " << t.skipped
              << " skipped (MX_ERR_NUMERICAL); interior SDG vertices " << t.sdg_branches << " branch + " << t.sdg_joints
              << " joint; medax nodes " << t.medax_branches << " branch + " << t.medax_joints << " joint ("
              << t.pass_through << " pass-through, not compared); matched " << t.matched_branches << " branch (" << t.conditioned_branches
              << " ill-conditioned, " << t.sdg_inexact_branches << " where the SDG vertex is inexact) + "
              << t.exact_joints + t.shifted_joints + t.narrow_fan_joints << " joint (" << t.shifted_joints
              << " shifted by the tolerance, " << t.narrow_fan_joints << " ends of fans narrower than 4 tolerances, " << t.flat_vertices
              << " SDG branches at a nearly flat vertex)\n"
              << "cgal_axis: max error / diagonal: branch position " << t.max_pos << ", radius " << t.max_rad
              << ", ill-conditioned branch position " << t.max_conditioned
              << "; exact joint position " << t.max_joint_pos << ", radius " << t.max_joint_rad
              << "; shifted joint offset " << t.max_joint_offset << "; joint radius vs clearance "
              << t.max_joint_clearance << "\n"
              << "cgal_axis: medax " << t.medax_secs << " s, SDG + brute force " << t.sdg_secs << " s, total "
              << total_secs << " s\n";
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CGAL_SEED", 20240611);
    const size_t cases = std::max<uint64_t>(2, mt::from_env_or_arg(argc, argv, 2, "MEDAX_CGAL_AXIS_CASES", 50));
    const size_t max_n = std::max<uint64_t>(10, mt::from_env_or_arg(argc, argv, 3, "MEDAX_CGAL_AXIS_MAX_N", 10000));
    const size_t holed = mt::from_env_or_arg(argc, argv, 4, "MEDAX_CGAL_AXIS_HOLED", 60);
    std::cout << "cgal_axis: CGAL " << CGAL_VERSION_STR << ", medax " << mx_version() << ", seed " << seed << ", "
              << cases << " star polygons of 10.." << max_n << " vertices\n";

    const char* sites_env = std::getenv("MEDAX_CGAL_AXIS_STAR_SITES");
    const bool site_checks_on_stars = sites_env && std::string(sites_env) == "1";
    std::mt19937_64 rng(seed);
    Tally tally;
    auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < cases; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(cases - 1);
        const size_t n = static_cast<size_t>(std::lround(10.0 * std::pow(static_cast<double>(max_n) / 10.0, t)));
        const double R = std::exp(std::uniform_real_distribution<double>(std::log(0.5), std::log(500.0))(rng));
        const bool cw = i % 2 == 1;
        const Polygon p = mt::star(rng, n, R, cw);
        if (const char* dump = std::getenv("MEDAX_CGAL_AXIS_DUMP"); dump && std::to_string(i) == dump)
            dump_json({p}, "cgal_axis_star_" + std::to_string(i) + ".json");
        check_polygon(Loops({p}), "star #" + std::to_string(i) + " n=" + std::to_string(n) + (cw ? " cw" : " ccw") +
                                      " (seed " + std::to_string(seed) + ")",
                      tally, site_checks_on_stars);
    }
    const Tally& t = tally;
    print_tally(t, std::to_string(t.polygons) + " polygons", seconds_since(start));
    if (site_checks_on_stars)
        std::cout << "cgal_axis: stars: sites checked: " << t.site_refs << " of medax edges (d), " << t.site_nodes
                  << " + " << t.fan_site_nodes << " narrow-fan sets of matched nodes (e); " << t.cycles << " of "
                  << t.compared << " axes connected without cycles (f)\n";
    mt::begin_case("skip rate");
    MT_CHECK(10 * t.skipped <= t.polygons);
    const int star_checks = mt::stats().checks, star_failures = mt::stats().failures;

    // Holed stars: shape j (1..holed) from its own generator, seeded by
    // (seed, j); outer vertex counts a geometric sequence 10..2000, hole
    // counts log-uniform in 1..200 (1 and 200 at the two ends).
    constexpr size_t kHoledMaxN = 2000, kMaxHoles = 200;
    std::cout << "cgal_axis: " << holed << " holed stars of 10.." << kHoledMaxN << " vertices with 1.." << kMaxHoles
              << " convex holes of 3..8 vertices\n";
    Tally htally;
    start = std::chrono::steady_clock::now();
    const char* only_env = std::getenv("MEDAX_CGAL_AXIS_HOLED_ONLY");
    const size_t only = only_env ? std::strtoull(only_env, nullptr, 0) : 0;
    for (size_t j = 1; j <= holed; ++j) {
        if (only != 0 && j != only) continue;
        const double along = holed == 1 ? 0.0 : static_cast<double>(j - 1) / static_cast<double>(holed - 1);
        std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), static_cast<uint32_t>(j)};
        std::mt19937_64 hrng(seq);
        const size_t n =
            static_cast<size_t>(std::lround(10.0 * std::pow(static_cast<double>(kHoledMaxN) / 10.0, along)));
        const size_t k = j == 1 ? 1
                         : j == holed
                             ? kMaxHoles
                             : static_cast<size_t>(std::lround(std::exp(std::uniform_real_distribution<double>(
                                   0.0, std::log(static_cast<double>(kMaxHoles)))(hrng))));
        const double R = std::exp(std::uniform_real_distribution<double>(std::log(0.5), std::log(500.0))(hrng));
        const bool cw = j % 2 == 0;
        const std::vector<Polygon> loops = holed_star(hrng, n, k, R, cw);
        size_t hole_vertices = 0;
        for (size_t l = 1; l < loops.size(); ++l) hole_vertices += loops[l].size();
        const std::string name = "holed star #" + std::to_string(j) + " n=" + std::to_string(n) + (cw ? " cw" : " ccw") +
                                 " + " + std::to_string(k) + " holes of " + std::to_string(hole_vertices) +
                                 " vertices, R " + mt::show(R) + " (seed " + std::to_string(seed) + ")";
        if (const char* dump = std::getenv("MEDAX_CGAL_AXIS_HOLED_DUMP"); dump && std::to_string(j) == dump)
            dump_json(loops, "cgal_axis_holed_" + std::to_string(j) + ".json");
        // The generator's promise: every hole vertex is inside the star, at
        // least 0.01 R from it (medax's own validation does the rest).
        mt::begin_case(name);
        double gap = INFINITY;
        bool inside = true;
        for (size_t l = 1; l < loops.size(); ++l)
            for (const Pt& p : loops[l]) {
                inside = inside && mt::inside(loops[0], p);
                gap = std::min(gap, mt::boundary_distance(loops[0], p));
            }
        if (!MT_CHECK(inside && gap >= 0.01 * R)) std::cerr << "    nearest hole vertex " << gap << " from the star\n";
        check_polygon(Loops(loops), name, htally, true);
    }
    const Tally& h = htally;
    mt::begin_case("holed skip rate");
    MT_CHECK(10 * h.skipped <= h.polygons);
    print_tally(h, std::to_string(h.polygons) + " holed stars (" + std::to_string(h.holes) + " holes, " +
                       std::to_string(h.vertices) + " vertices)",
                seconds_since(start));
    std::cout << "cgal_axis: holed stars: sites checked: " << h.site_refs << " of medax edges (d), "
              << h.site_nodes << " + " << h.fan_site_nodes << " narrow-fan sets of matched nodes (e); "
              << h.cycles << " of " << h.compared << " axes connected with one cycle per hole (f); "
              << mt::stats().checks - star_checks << " checks, " << mt::stats().failures - star_failures
              << " failed (stars: " << star_checks << " checks, " << star_failures << " failed)\n";
    return mt::finish("cgal_axis");
}
