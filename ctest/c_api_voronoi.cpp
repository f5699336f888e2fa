// Voronoi diagrams through the installed C API: random squares and discs
// (as bulge loops) in grid cells; every edge of the sites' diagram sampled
// through the borrowed mx_axis and each sample's distance to the two sites
// it separates (computed here from the input arrays) equal to its radius;
// each site's region walk closes; the nearest site of random points agrees
// with a brute-force scan; errors leave out-params alone.
//
// Usage: c_api_voronoi [scenes]   (default 20)

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

namespace {

struct Site {
    bool disc;
    double x, y, size;  // disc: centre and radius; square: lower-left corner and side
};

double site_distance(const Site& s, double px, double py) {
    if (s.disc) return std::max(0.0, std::hypot(px - s.x, py - s.y) - s.size);
    const double dx = std::max({s.x - px, px - s.x - s.size, 0.0});
    const double dy = std::max({s.y - py, py - s.y - s.size, 0.0});
    return std::hypot(dx, dy);
}

void append_loop(const Site& s, std::vector<double>& xyb, std::vector<size_t>& lens) {
    if (s.disc) {
        xyb.insert(xyb.end(), {s.x - s.size, s.y, 1.0, s.x + s.size, s.y, 1.0});
        lens.push_back(2);
    } else {
        xyb.insert(xyb.end(), {s.x, s.y, 0.0, s.x + s.size, s.y, 0.0, s.x + s.size, s.y + s.size, 0.0, s.x,
                               s.y + s.size, 0.0});
        lens.push_back(4);
    }
}

mx_sites sites_of(const std::vector<double>& xyb, const std::vector<size_t>& lens) {
    mx_sites s{};
    s.regions_xyb = xyb.data();
    s.regions_xyb_len = xyb.size();
    s.region_lengths = lens.data();
    s.region_count = lens.size();
    return s;
}

void scene(std::mt19937_64& rng, int k) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Site> sites;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
            sites.push_back({u(rng) < 0.5, i * 3.0 + 1.0 + u(rng), j * 3.0 + 1.0 + u(rng), 0.2 + 0.6 * u(rng)});
    std::vector<double> xyb;
    std::vector<size_t> lens;
    for (const Site& s : sites) append_loop(s, xyb, lens);
    const mx_sites in = sites_of(xyb, lens);
    mx_voronoi* vd = nullptr;
    if (!MT_CHECK_OK(mx_voronoi_compute(&in, nullptr, &vd))) return;
    const mx_axis* axis = nullptr;
    MT_CHECK_OK(mx_voronoi_axis(vd, &axis));
    mx_voronoi_info info{};
    MT_CHECK_OK(mx_voronoi_get_info(vd, &info));
    MT_CHECK_EQ(info.region_count, sites.size());
    size_t n_edges = 0;
    MT_CHECK_OK(mx_axis_edge_count(axis, &n_edges));
    size_t kept = 0;
    for (size_t i = 0; i < n_edges; ++i) {
        mx_voronoi_edge e{};
        MT_CHECK_OK(mx_voronoi_get_edge(vd, i, &e));
        if (!e.in_diagram) continue;
        ++kept;
        size_t count = 0;
        MT_CHECK_OK(mx_axis_edge_sample(axis, i, 1e-4, nullptr, 0, &count));
        std::vector<double> xyr(3 * count);
        MT_CHECK_OK(mx_axis_edge_sample(axis, i, 1e-4, xyr.data(), count, &count));
        for (size_t q = 0; q < count; ++q)
            for (const mx_site& side : e.sides) {
                if (!MT_CHECK_EQ(side.kind, MX_SITE_REGION)) continue;
                const double d = site_distance(sites[side.index], xyr[3 * q], xyr[3 * q + 1]);
                MT_CHECK(std::fabs(d - xyr[3 * q + 2]) < 1e-9);
            }
    }
    MT_CHECK(kept >= sites.size());
    for (size_t s = 0; s < sites.size(); ++s) {
        mx_voronoi_region r{};
        MT_CHECK_OK(mx_voronoi_get_region(vd, MX_SITE_REGION, s, &r));
        MT_CHECK_EQ(r.walks, size_t{1});
        std::vector<size_t> walk(r.walk_length);
        std::vector<int32_t> fwd(r.walk_length);
        size_t n = 0;
        MT_CHECK_OK(mx_voronoi_region_walk(vd, MX_SITE_REGION, s, walk.data(), fwd.data(), walk.size(), &n));
        for (size_t q = 0; q < n; ++q) {
            mx_axis_edge a{}, b{};
            MT_CHECK_OK(mx_axis_get_edge(axis, walk[q], &a));
            MT_CHECK_OK(mx_axis_get_edge(axis, walk[(q + 1) % n], &b));
            MT_CHECK_EQ(fwd[q] ? a.to : a.from, fwd[(q + 1) % n] ? b.from : b.to);
        }
    }
    for (int q = 0; q < 50; ++q) {
        const double px = -2.0 + (3.0 * k + 4.0) * u(rng), py = -2.0 + (3.0 * k + 4.0) * u(rng);
        size_t best = 0;
        double bd = std::numeric_limits<double>::infinity(), second = bd;
        for (size_t s = 0; s < sites.size(); ++s) {
            const double d = site_distance(sites[s], px, py);
            if (d < bd) {
                second = bd;
                bd = d;
                best = s;
            } else {
                second = std::min(second, d);
            }
        }
        if (bd == 0.0 || second - bd < 1e-9) continue;
        mx_nearest_site near{};
        MT_CHECK_OK(mx_voronoi_nearest_site(vd, px, py, &near));
        MT_CHECK_EQ(near.site.index, best);
        MT_CHECK(std::fabs(near.distance - bd) < 1e-12);
    }
    mx_voronoi_free(vd);
}

void errors() {
    mt::begin_case("errors leave the handle alone");
    mx_voronoi* const sentinel = reinterpret_cast<mx_voronoi*>(0x5EE7);
    mx_voronoi* vd = sentinel;
    std::vector<double> xyb;
    std::vector<size_t> lens;
    append_loop({false, 0.0, 0.0, 2.0}, xyb, lens);
    append_loop({false, 1.0, 1.0, 2.0}, xyb, lens);
    const mx_sites overlapping = sites_of(xyb, lens);
    MT_CHECK_STATUS(mx_voronoi_compute(&overlapping, nullptr, &vd), MX_ERR_INTERSECTION);
    const mx_sites none{};
    MT_CHECK_STATUS(mx_voronoi_compute(&none, nullptr, &vd), MX_ERR_EMPTY);
    MT_CHECK_STATUS(mx_voronoi_compute(nullptr, nullptr, &vd), MX_ERR_NULL_ARGUMENT);
    MT_CHECK(vd == sentinel);
    mx_voronoi_free(nullptr);
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t scenes = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CTEST_SCENES", 20);
    std::mt19937_64 rng(20261202);
    for (uint64_t i = 0; i < scenes; ++i) {
        mt::begin_case("scene " + std::to_string(i));
        scene(rng, 2 + static_cast<int>(i % 5));
    }
    errors();
    return mt::finish("c_api_voronoi");
}
