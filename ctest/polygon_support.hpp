// Plain polygons for the medial-axis tests and the peer benchmark: random
// star polygons, brute-force distance / inside tests in double, and RAII and
// accessors for mx_axis handles. Header-only, C++17, medax.h and the
// standard library only (no CGAL: c_api_axis uses it too).
#ifndef MEDAX_CTEST_POLYGON_SUPPORT_HPP
#define MEDAX_CTEST_POLYGON_SUPPORT_HPP

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace mt {

constexpr double kPi = 3.14159265358979323846;

using Pt = std::pair<double, double>;
using Polygon = std::vector<Pt>;

// A random star polygon around the origin: one vertex per angular sector,
// its angle uniform in the middle 80 % of the sector (so the angles are
// sorted and consecutive ones at least 0.2 x 2 pi / n apart), radius uniform
// in [0.3, 1] x R; counter-clockwise unless `cw`.
inline Polygon star(std::mt19937_64& rng, size_t n, double R, bool cw) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Polygon p;
    p.reserve(n);
    for (size_t k = 0; k < n; ++k) {
        const double t = 2.0 * kPi * (static_cast<double>(k) + 0.1 + 0.8 * u(rng)) / static_cast<double>(n);
        const double r = R * (0.3 + 0.7 * u(rng));
        p.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    if (cw) std::reverse(p.begin(), p.end());
    return p;
}

inline double segment_distance(Pt p, Pt a, Pt b) {
    const double dx = b.first - a.first, dy = b.second - a.second;
    double t = ((p.first - a.first) * dx + (p.second - a.second) * dy) / (dx * dx + dy * dy);
    t = std::min(1.0, std::max(0.0, t));
    return std::hypot(p.first - a.first - t * dx, p.second - a.second - t * dy);
}

// Distance from p to the closed polygon boundary, brute force.
inline double boundary_distance(const Polygon& poly, Pt p) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < poly.size(); ++k) best = std::min(best, segment_distance(p, poly[k], poly[(k + 1) % poly.size()]));
    return best;
}

inline bool inside(const Polygon& poly, Pt p) {  // crossing number
    bool in = false;
    for (size_t k = 0, j = poly.size() - 1; k < poly.size(); j = k++) {
        const Pt a = poly[k], b = poly[j];
        if ((a.second > p.second) != (b.second > p.second) &&
            p.first < (b.first - a.first) * (p.second - a.second) / (b.second - a.second) + a.first)
            in = !in;
    }
    return in;
}

inline double diagonal(const Polygon& poly) {
    double x0 = poly[0].first, x1 = x0, y0 = poly[0].second, y1 = y0;
    for (const Pt& p : poly) {
        x0 = std::min(x0, p.first), x1 = std::max(x1, p.first);
        y0 = std::min(y0, p.second), y1 = std::max(y1, p.second);
    }
    return std::hypot(x1 - x0, y1 - y0);
}

// The polygon as one bulge loop (all bulges 0) for mx_shape2d_from_bulges.
inline std::vector<double> bulges(const Polygon& poly) {
    std::vector<double> xyb;
    xyb.reserve(3 * poly.size());
    for (const Pt& p : poly) xyb.insert(xyb.end(), {p.first, p.second, 0.0});
    return xyb;
}

struct AxisDeleter {
    void operator()(mx_axis* p) const noexcept { mx_axis_free(p); }
};
using AxisPtr = std::unique_ptr<mx_axis, AxisDeleter>;

// Every item of an axis: `count` says how many, `get` reads one.
template <typename T>
std::vector<T> items(const mx_axis* a, mx_status (*count)(const mx_axis*, size_t*),
                     mx_status (*get)(const mx_axis*, size_t, T*)) {
    size_t n = 0;
    MT_CHECK_OK(count(a, &n));
    std::vector<T> v(n);
    for (size_t i = 0; i < n; ++i) MT_CHECK_OK(get(a, i, &v[i]));
    return v;
}

inline std::vector<mx_axis_node> nodes_of(const mx_axis* a) {
    return items(a, mx_axis_node_count, mx_axis_get_node);
}

inline std::vector<mx_axis_edge> edges_of(const mx_axis* a) {
    return items(a, mx_axis_edge_count, mx_axis_get_edge);
}

}  // namespace mt

#endif  // MEDAX_CTEST_POLYGON_SUPPORT_HPP
