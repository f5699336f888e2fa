// Cross-checks medax's medial axis of random star polygons against the
// Voronoi diagram of the polygon's vertices and edges from
// CGAL::Segment_Delaunay_graph_2 (SDG; traits in sdg_support.hpp).
//
// Corpus: 50 random star polygons (mt::star: sorted jittered angles, radii
// in [0.3, 1] x R, R log-uniform in [0.5, 500], CCW and CW alternately),
// vertex counts a geometric sequence from 10 to 10^4 (the third argument
// changes the top).
//
// The SDG has one site per polygon vertex (a point) and one per edge (the
// open segment). Its Voronoi vertices are the centres of the circles
// tangent to the three sites of each finite Delaunay face (Sdg::primal).
// For each one the clearance (distance to the nearest polygon edge) is
// computed here by brute force in double; only vertices strictly inside the
// polygon with clearance > 1e-9 x diagonal are kept. That drops the ones
// outside and the degenerate ones at the polygon's own vertices (a vertex
// and its two edges meet at distance 0).
//
// A kept SDG vertex is one of two kinds, by its three sites:
//   joint    a point site v and a segment site e ending at v: the vertex
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
// vertex; such JOINT nodes are counted and printed, not compared.
//
// Checks, with eps = 1e-9 x diagonal:
//   (a) every medax BRANCH node has an SDG branch vertex within eps in
//       position and radius (the SDG radius being the brute-force clearance)
//   (b) every kept SDG vertex has a medax node of its kind: a branch vertex
//       a BRANCH as in (a); a joint vertex (v, e) a JOINT as below
//   (c) every medax JOINT (not pass-through) is the node of some SDG joint
// so that medax's branch and joint nodes are exactly the SDG's interior
// Voronoi vertices. Three allowances widen (a) - (c), each
// counted and its largest error printed:
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
// A star on which mx_axis_compute fails with MX_ERR_NUMERICAL is printed
// and skipped; the test fails when more than 10 % are skipped (none is, at
// medax 0.1.0, on the default corpus or on seeds 7 and 11).
//
// Usage: cgal_axis [seed] [polygons] [max-vertices]
//        (also MEDAX_CGAL_SEED, MEDAX_CGAL_AXIS_CASES, MEDAX_CGAL_AXIS_MAX_N;
//         defaults 20240611, 50, 10000). MEDAX_CGAL_AXIS_DUMP=i writes polygon
//         i as medax shape JSON to cgal_axis_star_i.json.

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
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace {

using mt::Polygon;
using mt::Pt;

enum class Kind { branch, joint };

const char* kind_name(Kind k) {
    return k == Kind::branch ? "branch" : "joint";
}

// A disk of either side: an SDG Voronoi vertex or a medax node.
struct Disk {
    double x, y, r;
    Kind kind;
    std::array<size_t, 3> sites{};  // SDG: its sites, vertex k as k, edge k as n + k
    size_t v = 0, e = 0;  // SDG joints: the reflex vertex and the edge (edge k runs from vertex k to k + 1)
    bool used = false;    // medax joints: claimed by an SDG joint
};

std::string where(const Disk& d) {
    return std::string(kind_name(d.kind)) + " at (" + mt::show(d.x) + ", " + mt::show(d.y) + ") r " + mt::show(d.r);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The kept Voronoi vertices of the SDG of `poly`, classified (see the top).
std::vector<Disk> sdg_vertices(const Polygon& poly, double min_clearance, size_t& flat_vertices) {
    mt::Sdg sdg;
    mt::insert_polygon(sdg, poly);
    const size_t n = poly.size();
    // Sites back to polygon vertices: the point sites are the input exactly.
    std::map<Pt, size_t> index;
    for (size_t k = 0; k < n; ++k) index.emplace(poly[k], k);
    auto vertex_of = [&](const mt::Sdg::Point_2& p) {
        const auto it = index.find({p.x(), p.y()});
        MT_CHECK(it != index.end());
        return it == index.end() ? n : it->second;
    };
    std::vector<Disk> out;
    for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
        const mt::Sdg::Point_2 c = sdg.primal(f);
        const Pt p{c.x(), c.y()};
        if (!std::isfinite(p.first) || !std::isfinite(p.second) || !mt::inside(poly, p)) continue;
        const double r = mt::boundary_distance(poly, p);
        if (!(r > min_clearance)) continue;
        std::vector<size_t> points, edges;
        for (int i = 0; i < 3; ++i) {
            const mt::Sdg::Site_2& s = f->vertex(i)->site();
            if (s.is_point()) {
                points.push_back(vertex_of(s.point()));
            } else {
                const size_t a = vertex_of(s.source()), b = vertex_of(s.target());
                edges.push_back(b == (a + 1) % n ? a : b);
            }
        }
        Disk d{p.first, p.second, r, Kind::branch};
        for (size_t i = 0; i < points.size(); ++i) d.sites[i] = points[i];
        for (size_t i = 0; i < edges.size(); ++i) d.sites[points.size() + i] = n + edges[i];
        for (size_t v : points)
            for (size_t e : edges)
                if (v == e || v == (e + 1) % n) d.kind = Kind::joint, d.v = v, d.e = e;
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
                    const size_t v = (edges[i] + 1) % n;
                    if (i == j || edges[j] != v || d.kind != Kind::branch) continue;
                    const Pt a = poly[edges[i]], b = poly[v], c = poly[(v + 1) % n];
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
};

// Prints the first few failures of one kind per polygon.
struct Failures {
    const char* what;
    size_t count = 0;
    void add(const std::string& detail) {
        if (++count <= 5) std::cerr << "    " << what << ": " << detail << "\n";
    }
};

// A site of a medax edge as a comparable tuple.
std::tuple<size_t, size_t, int32_t> key(const mx_axis_site& s) {
    return {s.loop_index, s.index, s.is_vertex};
}

void check_polygon(const Polygon& poly, const std::string& name, Tally& tally) {
    mt::begin_case(name);
    ++tally.polygons;
    const size_t n = poly.size();
    const double diag = mt::diagonal(poly), eps = 1e-9 * diag;
    const std::vector<double> xyb = mt::bulges(poly);
    mx_shape_options so;
    mx_shape_options_default(&so);
    const double touch = so.relative_tolerance * diag;
    mx_shape2d* raw_shape = nullptr;
    if (!MT_CHECK_OK(mx_shape2d_from_bulges(xyb.data(), xyb.size(), &n, 1, &so, &raw_shape))) return;
    mt::ShapePtr shape(raw_shape);

    auto t0 = std::chrono::steady_clock::now();
    mx_axis* raw_axis = nullptr;
    const mx_status st = mx_axis_compute(shape.get(), nullptr, &raw_axis);
    tally.medax_secs += seconds_since(t0);
    mt::AxisPtr axis(raw_axis);
    if (st == MX_ERR_NUMERICAL) {
        ++tally.skipped;
        std::cout << "cgal_axis: skipped " << name << ": " << mt::show(st) << " -- " << mt::last_message() << "\n";
        return;
    }
    if (!MT_CHECK_OK(st)) return;
    ++tally.compared;

    // medax's branch and joint nodes; pass-through nodes set aside.
    const std::vector<mx_axis_node> nodes = mt::nodes_of(axis.get());
    std::vector<std::vector<std::array<std::tuple<size_t, size_t, int32_t>, 2>>> pairs(nodes.size());
    for (const mx_axis_edge& e : mt::edges_of(axis.get())) {
        auto pair = std::array{key(e.sites[0]), key(e.sites[1])};
        std::sort(pair.begin(), pair.end());
        if (e.from < nodes.size()) pairs[e.from].push_back(pair);
        if (e.to < nodes.size()) pairs[e.to].push_back(pair);
    }
    std::vector<Disk> branches, joints;
    for (size_t i = 0; i < nodes.size(); ++i) {
        const mx_axis_node& nd = nodes[i];
        if (nd.kind == MX_NODE_BRANCH) branches.push_back({nd.x, nd.y, nd.r, Kind::branch});
        if (nd.kind != MX_NODE_JOINT) continue;
        if (pairs[i].size() == 2 && pairs[i][0] == pairs[i][1]) {
            ++tally.pass_through;
            std::cout << "cgal_axis: " << name << ": pass-through medax joint at (" << nd.x << ", " << nd.y << ")\n";
            continue;
        }
        joints.push_back({nd.x, nd.y, nd.r, Kind::joint});
    }
    tally.medax_branches += branches.size();
    tally.medax_joints += joints.size();

    t0 = std::chrono::steady_clock::now();
    std::vector<Disk> sdg = sdg_vertices(poly, eps, tally.flat_vertices);
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

    // (a) and the branch half of (b): within eps in position and radius, or
    // (ill-conditioned) within eps in radius and 1e-6 x diagonal in position
    // with medax's node equidistant from the SDG vertex's three sites to
    // 1e-11 x diagonal.
    auto spread = [&](const Disk& s, double x, double y) {  // of the distances to the sites of s
        double lo = INFINITY, hi = 0.0;
        for (size_t k : s.sites) {
            const double d = k < n ? std::hypot(x - poly[k].first, y - poly[k].second)
                                   : mt::segment_distance({x, y}, poly[k - n], poly[(k - n + 1) % n]);
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
            const bool clear = std::fabs(medax.r - mt::boundary_distance(poly, {medax.x, medax.y})) <= eps;
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
        const Pt v = poly[s.v], o = poly[s.v == s.e ? (s.e + 1) % n : s.e];
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
            const double clearance_error = std::fabs(mt::boundary_distance(poly, {J.x, J.y}) - J.r);
            if (!MT_CHECK(clearance_error <= eps)) std::cerr << "    at medax " << where(J) << "\n";
            J.used = found = true;
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
            const Pt a = poly[(s.v + n - 1) % n], c2 = poly[(s.v + 1) % n];
            const double ux = v.first - a.first, uy = v.second - a.second;
            const double wx = c2.first - v.first, wy = c2.second - v.second;
            const double fan = std::fabs(std::atan2(ux * wy - uy * wx, ux * wx + uy * wy));
            const double reach = 4.0 * touch + eps;
            if (fan * s.r <= reach) {
                for (size_t j : near(joints, s.x, s.y, reach)) {
                    Disk& J = joints[j];
                    const double through = std::hypot(J.x - v.first, J.y - v.second) - J.r;
                    if (std::fabs(J.r - s.r) > reach || std::fabs(through) > eps) continue;
                    J.used = found = true;
                    ++tally.narrow_fan_joints;
                    break;
                }
            }
        }
        if (!found) b_joint.add(where(s) + " (vertex " + std::to_string(s.v) + ", edge " + std::to_string(s.e) + ")");
    }
    for (const Disk& J : joints)
        if (!J.used) c.add(where(J));
    for (const Failures* f : {&a, &b_branch, &b_joint, &c})
        mt::record(f->count == 0, __FILE__, __LINE__, std::string(f->what) + ": " + std::to_string(f->count));
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CGAL_SEED", 20240611);
    const size_t cases = std::max<uint64_t>(2, mt::from_env_or_arg(argc, argv, 2, "MEDAX_CGAL_AXIS_CASES", 50));
    const size_t max_n = std::max<uint64_t>(10, mt::from_env_or_arg(argc, argv, 3, "MEDAX_CGAL_AXIS_MAX_N", 10000));
    std::cout << "cgal_axis: CGAL " << CGAL_VERSION_STR << ", medax " << mx_version() << ", seed " << seed << ", "
              << cases << " star polygons of 10.." << max_n << " vertices\n";

    std::mt19937_64 rng(seed);
    Tally tally;
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < cases; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(cases - 1);
        const size_t n = static_cast<size_t>(std::lround(10.0 * std::pow(static_cast<double>(max_n) / 10.0, t)));
        const double R = std::exp(std::uniform_real_distribution<double>(std::log(0.5), std::log(500.0))(rng));
        const bool cw = i % 2 == 1;
        const Polygon p = mt::star(rng, n, R, cw);
        if (const char* dump = std::getenv("MEDAX_CGAL_AXIS_DUMP"); dump && std::to_string(i) == dump) {
            // The polygon as medax shape JSON, to look at a mismatch with the CLI.
            std::ofstream out("cgal_axis_star_" + std::to_string(i) + ".json");
            out.precision(17);
            out << "{\"loops\": [[";
            for (size_t k = 0; k < p.size(); ++k) out << (k ? ", [" : "[") << p[k].first << ", " << p[k].second << "]";
            out << "]]}\n";
        }
        check_polygon(p, "star #" + std::to_string(i) + " n=" + std::to_string(n) + (cw ? " cw" : " ccw") +
                             " (seed " + std::to_string(seed) + ")",
                      tally);
    }
    const Tally& t = tally;
    std::cout << "cgal_axis: " << t.polygons << " polygons, " << t.compared << " compared, " << t.skipped
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
              << seconds_since(start) << " s\n";
    mt::begin_case("skip rate");
    MT_CHECK(10 * t.skipped <= t.polygons);
    return mt::finish("cgal_axis");
}
