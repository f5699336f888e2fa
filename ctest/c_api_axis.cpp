// The medial axis through the installed C API: mx_axis_compute on a 4 x 2
// rectangle (known axis) and on random star polygons, every node radius and
// every sampled disk checked against a brute-force distance to the polygon
// computed here; sites in the caller's numbering; options (threads,
// progress, cancel); a hole (one cycle); size queries; the axis outliving its shape.
//
// Usage: c_api_axis [star-polygons]   (default 40)

#include "polygon_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace {

using mt::AxisPtr;
using mt::boundary_distance;
using mt::diagonal;
using mt::edges_of;
using mt::inside;
using mt::nodes_of;
using mt::Polygon;
using mt::Pt;
using mt::segment_distance;
using mt::star;

mt::ShapePtr make(const std::vector<Polygon>& loops) {
    std::vector<std::vector<double>> xyb;
    for (const Polygon& l : loops) xyb.push_back(mt::bulges(l));
    mx_shape2d* s = nullptr;
    MT_CHECK_OK(mt::from_loops(xyb, &s));
    return mt::ShapePtr(s);
}

AxisPtr compute(const mx_shape2d* s, const mx_axis_options* o = nullptr) {
    mx_axis* a = nullptr;
    MT_CHECK_OK(mx_axis_compute(s, o, &a));
    return AxisPtr(a);
}

std::vector<double> samples_of(const mx_axis* a, size_t i, double tol) {
    size_t n = 0;
    if (!MT_CHECK_OK(mx_axis_edge_sample(a, i, tol, nullptr, 0, &n))) return {};
    std::vector<double> xyr(3 * n);
    size_t m = 0;
    MT_CHECK_OK(mx_axis_edge_sample(a, i, tol, xyr.data(), n, &m));
    MT_CHECK_EQ(m, n);
    return xyr;
}

// Distance from p to a site given in the caller's numbering of poly.
double site_distance(const Polygon& poly, const mx_axis_site& s, Pt p) {
    if (s.loop_index != 0 || s.index >= poly.size()) return std::numeric_limits<double>::infinity();
    const Pt v = poly[s.index];
    if (s.is_vertex == 1) return std::hypot(p.first - v.first, p.second - v.second);
    return segment_distance(p, v, poly[(s.index + 1) % poly.size()]);
}

// Every node and sample: a disk of its radius inside the polygon, touching
// the boundary (brute force) and both sites of its edge. Returns the number
// of disks checked.
size_t check_disks(const Polygon& poly, const mx_axis* a) {
    const double diag = diagonal(poly), eps = 1e-9 * diag;
    const auto nodes = nodes_of(a);
    const auto edges = edges_of(a);
    size_t bad_nodes = 0, bad_samples = 0, bad_sites = 0, checked = 0;
    for (const mx_axis_node& n : nodes) {
        const double d = boundary_distance(poly, {n.x, n.y});
        bad_nodes += !(std::fabs(d - n.r) <= eps && (n.r == 0.0 || inside(poly, {n.x, n.y})));
        bad_nodes += n.kind == MX_NODE_CORNER && n.r != 0.0;
        ++checked;
    }
    for (size_t i = 0; i < edges.size(); ++i) {
        const mx_axis_edge& e = edges[i];
        if (!MT_CHECK(e.from < nodes.size() && e.to < nodes.size())) continue;
        const std::vector<double> s = samples_of(a, i, 1e-5 * diag);
        if (!MT_CHECK(s.size() >= 6)) continue;
        MT_CHECK(s[0] == nodes[e.from].x && s[1] == nodes[e.from].y && s[2] == nodes[e.from].r);
        MT_CHECK(s[s.size() - 3] == nodes[e.to].x && s[s.size() - 1] == nodes[e.to].r);
        for (size_t k = 0; k < s.size(); k += 3) {
            const Pt p{s[k], s[k + 1]};
            const double r = s[k + 2];
            bad_samples += !(std::fabs(boundary_distance(poly, p) - r) <= eps);
            for (const mx_axis_site& site : e.sites) bad_sites += !(std::fabs(site_distance(poly, site, p) - r) <= eps);
            ++checked;
        }
    }
    MT_CHECK_EQ(bad_nodes, size_t{0});
    MT_CHECK_EQ(bad_samples, size_t{0});
    MT_CHECK_EQ(bad_sites, size_t{0});
    return checked;
}

void test_rectangle() {
    mt::begin_case("rectangle 4 x 2");
    const Polygon rect = {{0, 0}, {4, 0}, {4, 2}, {0, 2}};
    auto s = make({rect});
    if (!s) return;
    AxisPtr a = compute(s.get());
    s.reset();  // the axis owns what it needs
    if (!a) return;
    const auto nodes = nodes_of(a.get());
    MT_CHECK_EQ(nodes.size(), size_t{6});
    size_t branches = 0, corners = 0;
    for (const mx_axis_node& n : nodes) {
        if (n.kind == MX_NODE_BRANCH) {
            ++branches;
            MT_CHECK(std::fabs(n.x - 1.0) < 1e-9 || std::fabs(n.x - 3.0) < 1e-9);
            MT_CHECK_NEAR(n.y, 1.0, 1e-9);
            MT_CHECK_NEAR(n.r, 1.0, 1e-9);
        }
        corners += n.kind == MX_NODE_CORNER;
    }
    MT_CHECK_EQ(branches, size_t{2});
    MT_CHECK_EQ(corners, size_t{4});
    const auto edges = edges_of(a.get());
    MT_CHECK_EQ(edges.size(), size_t{5});
    for (const mx_axis_edge& e : edges) MT_CHECK_EQ(static_cast<int>(e.kind), static_cast<int>(MX_CONIC_LINE));
    check_disks(rect, a.get());

    // Errors leave out-params alone.
    size_t n = 77;
    MT_CHECK_STATUS(mx_axis_node_count(nullptr, &n), MX_ERR_NULL_ARGUMENT);
    mx_axis_node node{7, 7, 7, MX_NODE_LEAF};
    MT_CHECK_STATUS(mx_axis_get_node(a.get(), 6, &node), MX_ERR_INDEX_OUT_OF_RANGE);
    MT_CHECK_EQ(node.x, 7.0);
    double buf[5] = {7, 7, 7, 7, 7};  // room for one sample; an edge has at least two
    MT_CHECK_STATUS(mx_axis_edge_sample(a.get(), 0, 1e-3, buf, 1, &n), MX_ERR_BUFFER_TOO_SMALL);
    MT_CHECK_STATUS(mx_axis_edge_sample(a.get(), 0, 0.0, buf, 1, &n), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_axis_edge_sample(a.get(), 5, 1e-3, buf, 1, &n), MX_ERR_INDEX_OUT_OF_RANGE);
    MT_CHECK_EQ(n, size_t{77});
    MT_CHECK_EQ(buf[0], 7.0);
}

void test_stars(size_t count) {
    std::mt19937_64 rng(20240611);
    size_t disks = 0, computed = 0;
    for (size_t i = 0; i < count; ++i) {
        const size_t n = 5 + i * 7 % 120;
        const double R = std::exp(std::uniform_real_distribution<double>(std::log(0.5), std::log(500.0))(rng));
        const Polygon p = star(rng, n, R, i % 2 == 1);
        mt::begin_case("star #" + std::to_string(i) + " n=" + std::to_string(n));
        auto s = make({p});
        if (!s) continue;
        mx_axis_options o;
        mx_axis_options_init(&o, sizeof o);
        o.threads = i % 3;  // 0 (shared pool), 1, 2
        mx_axis* raw = nullptr;
        const mx_status st = mx_axis_compute(s.get(), &o, &raw);
        AxisPtr a(raw);
        if (!MT_CHECK_OK(st)) continue;
        ++computed;
        disks += check_disks(p, a.get());
    }
    std::cout << "c_api_axis: " << computed << " star axes, " << disks << " disks checked\n";
}

struct Progress {
    std::vector<double> seen;
    bool cancel = false;
};

int on_progress(double fraction, void* user) {
    auto* p = static_cast<Progress*>(user);
    p->seen.push_back(fraction);
    return p->cancel ? 1 : 0;
}

void test_options_and_errors() {
    mt::begin_case("options, progress, cancel, holes");
    const Polygon rect = {{0, 0}, {4, 0}, {4, 2}, {0, 2}};
    auto s = make({rect});
    if (!s) return;
    mx_axis_options o;
    MT_CHECK_OK(mx_axis_options_init(&o, sizeof o));
    MT_CHECK_EQ(o.struct_size, sizeof(mx_axis_options));
    MT_CHECK_EQ(o.threads, size_t{0});
    Progress seen;
    o.progress = on_progress;
    o.user = &seen;
    auto a = compute(s.get(), &o);
    MT_CHECK(a != nullptr);
    MT_CHECK(seen.seen == std::vector<double>({0.0, 1.0}));

    Progress cancel;
    cancel.cancel = true;
    o.user = &cancel;
    mx_axis* out = reinterpret_cast<mx_axis*>(static_cast<std::uintptr_t>(0x5EE7u));
    MT_CHECK_STATUS(mx_axis_compute(s.get(), &o, &out), MX_ERR_CANCELLED);
    MT_CHECK(out == reinterpret_cast<mx_axis*>(static_cast<std::uintptr_t>(0x5EE7u)));
    MT_CHECK_EQ(cancel.seen.size(), size_t{1});

    o.progress = nullptr;
    o.threads = MX_AXIS_MAX_THREADS + 1;
    MT_CHECK_STATUS(mx_axis_compute(s.get(), &o, &out), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_axis_compute(nullptr, nullptr, &out), MX_ERR_NULL_ARGUMENT);

    // A hole: the axis is connected with one independent cycle, every
    // node's radius is its distance to the nearer loop, and the hole's
    // sides are sites.
    const Polygon hole = {{1, 0.5}, {1, 1.5}, {3, 1.5}, {3, 0.5}};
    auto holed = make({rect, hole});
    auto h = compute(holed.get());
    if (h) {
        const auto ns = nodes_of(h.get());
        const auto es = edges_of(h.get());
        MT_CHECK_EQ(es.size(), ns.size());
        for (const mx_axis_node& n : ns) {
            const double d = std::min(boundary_distance(rect, {n.x, n.y}), boundary_distance(hole, {n.x, n.y}));
            MT_CHECK(std::fabs(d - n.r) <= 1e-9);
        }
        size_t on_hole = 0;
        for (const mx_axis_edge& e : es) on_hole += (e.sites[0].loop_index == 1) + (e.sites[1].loop_index == 1);
        MT_CHECK(on_hole >= 4);
    }
    mx_axis_free(nullptr);
}

}  // namespace

int main(int argc, char** argv) {
    const size_t stars = argc > 1 ? static_cast<size_t>(std::max(1, std::atoi(argv[1]))) : 40;
    test_rectangle();
    test_stars(stars);
    test_options_and_errors();
    return mt::finish("c_api_axis");
}
