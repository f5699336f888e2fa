// Sites for bench_sites. Region sites (thesis 2.3.2, Tables 2.1 and 2.2):
// closed loops of tangent-continuous circular arcs placed in a rectangle Γ.
// The Voronoi diagram of the sites inside Γ is the medial axis of Γ with
// the sites as holes (thesis Observation 6), so a scene is a list of bulge
// loops, Γ first. Point and segment sites (tables `points` and `segments`,
// for mx_voronoi_compute without a boundary): a SiteSet. Header-only,
// C++17, standard library only.
#ifndef MEDAX_CTEST_SITES_SUPPORT_HPP
#define MEDAX_CTEST_SITES_SUPPORT_HPP

#include "polygon_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace mt {

struct BulgeVertex {
    double x, y, bulge;  // bulge of the element from this vertex to the next
};
using BulgeLoop = std::vector<BulgeVertex>;

struct Scene {
    std::vector<BulgeLoop> loops;  // Γ first, then the sites
    double width = 0, height = 0;  // Γ = [0, width] x [0, height]

    size_t elements() const {
        size_t n = 0;
        for (const BulgeLoop& l : loops) n += l.size();
        return n;
    }
    std::vector<double> xyb() const {
        std::vector<double> v;
        v.reserve(3 * elements());
        for (const BulgeLoop& l : loops)
            for (const BulgeVertex& p : l) v.insert(v.end(), {p.x, p.y, p.bulge});
        return v;
    }
    std::vector<size_t> loop_lengths() const {
        std::vector<size_t> v;
        for (const BulgeLoop& l : loops) v.push_back(l.size());
        return v;
    }
    // Every arc replaced by its chord: the peers take segments only, and
    // this way they see the same vertices and element count as medax.
    std::vector<Polygon> chords() const {
        std::vector<Polygon> v;
        for (const BulgeLoop& l : loops) {
            Polygon p;
            p.reserve(l.size());
            for (const BulgeVertex& q : l) p.emplace_back(q.x, q.y);
            v.push_back(std::move(p));
        }
        return v;
    }
    // The shape JSON of the medax CLI ({"loops": [[[x, y, bulge], ...], ...]}).
    bool write_json(const std::string& path) const {
        std::FILE* f = std::fopen(path.c_str(), "w");
        if (!f) return false;
        std::fputs("{\"loops\": [", f);
        for (size_t i = 0; i < loops.size(); ++i) {
            std::fputs(i ? ",\n[" : "\n[", f);
            for (size_t k = 0; k < loops[i].size(); ++k)
                std::fprintf(f, "%s[%.17g, %.17g, %.17g]", k ? ", " : "", loops[i][k].x, loops[i][k].y,
                             loops[i][k].bulge);
            std::fputs("]", f);
        }
        std::fputs("]}\n", f);
        return std::fclose(f) == 0;
    }
};

namespace sites_detail {

struct V2 {
    double x, y;
};
inline V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
inline V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
inline V2 operator*(V2 a, double s) { return {a.x * s, a.y * s}; }
inline double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
inline V2 unit(V2 a) { return a * (1.0 / std::hypot(a.x, a.y)); }

// Bulge of the arc from p to q leaving p along unit tangent t, and the
// arc's end tangent (the tangent turns by twice the chord's angle to t).
inline std::pair<double, V2> arc_from_tangent(V2 p, V2 t, V2 q) {
    const V2 u = unit(q - p);
    const double half = std::atan2(cross(t, u), dot(t, u));
    const double s = std::sin(half), c = std::cos(half);
    return {std::tan(half / 2.0), V2{c * u.x - s * u.y, s * u.x + c * u.y}};
}

// The equal-parameter biarc from (p0, t0) to (p1, t1), as samples.rs
// builds its flowers: the joint and the two bulges.
inline void biarc(V2 p0, V2 t0, V2 p1, V2 t1, BulgeLoop& out) {
    const V2 v = p1 - p0, t = t0 + t1;
    const double denom = 2.0 * (1.0 - dot(t0, t1));
    // Parallel end tangents: the quadratic degenerates to a linear equation.
    const double d = std::abs(denom) < 1e-12
                         ? dot(v, v) / (4.0 * dot(v, t1))
                         : (-dot(v, t) + std::sqrt(dot(v, t) * dot(v, t) + denom * dot(v, v))) / denom;
    const V2 joint = (p0 + t0 * d + p1 - t1 * d) * 0.5;
    const auto [b1, tj] = arc_from_tangent(p0, t0, joint);
    const double b2 = arc_from_tangent(joint, tj, p1).first;
    out.push_back({p0.x, p0.y, b1});
    out.push_back({joint.x, joint.y, b2});
}

inline BulgeLoop rectangle(double w, double h) {
    return {{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}};
}

// A smooth star-shaped blob r(θ) = r0 (1 + a1 sin(k1 θ + φ1) + a2 sin(k2 θ + φ2))
// round `c`, reaching at most `rmax` from it, as `samples` biarcs
// (2 x samples arcs, counter-clockwise). Lobes are limited by the sample
// count so that every lobe gets at least 8 samples.
inline BulgeLoop blob(std::mt19937_64& rng, V2 c, double rmax, size_t samples) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int max_lobes = static_cast<int>(std::clamp<size_t>(samples / 8, 2, 9));
    const double k1 = 2 + static_cast<int>(u(rng) * (max_lobes - 1)), k2 = k1 + 1 + static_cast<int>(3 * u(rng));
    const double a1 = 0.08 + 0.17 * u(rng), a2 = 0.08 * u(rng);
    const double p1 = 2 * kPi * u(rng), p2 = 2 * kPi * u(rng);
    const double r0 = rmax / (1.0 + a1 + a2);
    auto radius = [&](double t) { return r0 * (1 + a1 * std::sin(k1 * t + p1) + a2 * std::sin(k2 * t + p2)); };
    auto slope = [&](double t) { return r0 * (a1 * k1 * std::cos(k1 * t + p1) + a2 * k2 * std::cos(k2 * t + p2)); };
    std::vector<std::pair<V2, V2>> pts(samples);
    for (size_t i = 0; i < samples; ++i) {
        const double t = 2 * kPi * static_cast<double>(i) / static_cast<double>(samples);
        const double r = radius(t), dr = slope(t), ct = std::cos(t), st = std::sin(t);
        pts[i] = {c + V2{r * ct, r * st}, unit(V2{dr * ct - r * st, dr * st + r * ct})};
    }
    BulgeLoop out;
    out.reserve(2 * samples);
    for (size_t i = 0; i < samples; ++i) {
        const auto& [p0, t0] = pts[i];
        const auto& [p1, t1] = pts[(i + 1) % samples];
        biarc(p0, t0, p1, t1, out);
    }
    return out;
}

// A four-centre oval (two arcs of radius r1 at the ends of the long axis,
// two of radius r2 > a along the sides, tangent where they meet) with
// half-axes a > b, turned by `turn` round `c`: 4 arcs, counter-clockwise.
// Tangency: |C1 C2| = r2 - r1 with C1 = (a - r1, 0) and C2 = (0, b - r2)
// (the upper side's centre, below the long axis).
inline BulgeLoop oval(V2 c, double a, double b, double r1, double turn) {
    const double r2 = (a * a + b * b - 2 * a * r1) / (2 * (b - r1));
    const V2 c1{a - r1, 0}, c2{0, b - r2};
    const V2 j = c1 + unit(c1 - c2) * r1;  // the joint in the first quadrant
    const V2 joints[4] = {{j.x, -j.y}, j, {-j.x, j.y}, {-j.x, -j.y}};
    const V2 centres[4] = {c1, c2, c1 * -1.0, c2 * -1.0};  // of the arc leaving joints[i]
    const double ct = std::cos(turn), st = std::sin(turn);
    BulgeLoop out;
    for (int i = 0; i < 4; ++i) {
        const V2 p = joints[i] - centres[i], q = joints[(i + 1) % 4] - centres[i];
        const double sweep = std::atan2(cross(p, q), dot(p, q));  // in (0, π): convex, CCW
        const V2 w = c + V2{ct * joints[i].x - st * joints[i].y, st * joints[i].x + ct * joints[i].y};
        out.push_back({w.x, w.y, std::tan(sweep / 4)});
    }
    return out;
}

}  // namespace sites_detail

// Thesis Table 2.1: 40 smooth blobs in an 8 x 5 grid of unit cells (one
// per cell, jittered, at least 0.06 apart), `arcs` arcs in all (rounded up
// to even, shared as evenly as biarcs allow), Γ the 8 x 5 rectangle.
inline Scene table21(size_t arcs, uint64_t seed) {
    using namespace sites_detail;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene s;
    s.width = 8, s.height = 5;
    s.loops.push_back(rectangle(s.width, s.height));
    const size_t sites = 40, half = (arcs + 1) / 2;
    for (size_t i = 0; i < sites; ++i) {
        const double rmax = 0.3 + 0.12 * u(rng), slack = 0.47 - rmax;
        const V2 c{static_cast<double>(i % 8) + 0.5 + slack * (2 * u(rng) - 1),
                   static_cast<double>(i / 8) + 0.5 + slack * (2 * u(rng) - 1)};
        s.loops.push_back(blob(rng, c, rmax, std::max<size_t>(4, half / sites + (i < half % sites))));
    }
    return s;
}

// Thesis Table 2.2: `n` ovals of 4 arcs each, one per unit cell of a
// near-square grid (row by row), random size (long half-axis 0.2 - 0.38),
// aspect 1.2 - 2.5, end radius, turn and jitter; at least 0.1 apart and
// 0.05 from Γ, the rectangle round the grid.
inline Scene table22(size_t n, uint64_t seed) {
    using namespace sites_detail;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const size_t cols = static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    Scene s;
    s.width = static_cast<double>(cols), s.height = std::ceil(static_cast<double>(n) / static_cast<double>(cols));
    s.loops.push_back(rectangle(s.width, s.height));
    for (size_t i = 0; i < n; ++i) {
        const double a = 0.2 + 0.18 * u(rng), b = a / (1.2 + 1.3 * u(rng)), r1 = b * (0.3 + 0.5 * u(rng));
        const double slack = 0.45 - a;
        const V2 c{static_cast<double>(i % cols) + 0.5 + slack * (2 * u(rng) - 1),
                   static_cast<double>(i / cols) + 0.5 + slack * (2 * u(rng) - 1)};
        s.loops.push_back(oval(c, a, b, r1, 2 * kPi * u(rng)));
    }
    return s;
}

// Point sites or segment sites (never both) in the square [0, side]^2, for
// mx_voronoi_compute without a boundary (the library chooses its frame).
struct SiteSet {
    std::vector<Pt> points;
    std::vector<std::pair<Pt, Pt>> segments;
    double side = 0;

    size_t sites() const { return points.size() + segments.size(); }
    // `x, y` pairs of the points (mx_sites.points_xy).
    std::vector<double> points_xy() const {
        std::vector<double> v;
        v.reserve(2 * points.size());
        for (const Pt& p : points) v.insert(v.end(), {p.first, p.second});
        return v;
    }
    // `x, y, bulge` triples of the segments as curves of one segment each
    // (mx_sites.curves_xyb), and the curve lengths (all 2).
    std::vector<double> curves_xyb() const {
        std::vector<double> v;
        v.reserve(6 * segments.size());
        for (const auto& [a, b] : segments) v.insert(v.end(), {a.first, a.second, 0.0, b.first, b.second, 0.0});
        return v;
    }
    std::vector<size_t> curve_lengths() const { return std::vector<size_t>(segments.size(), 2); }
    // The segments as two-vertex chains (for sdg_support's insert_chains).
    std::vector<Polygon> chains() const {
        std::vector<Polygon> v;
        v.reserve(segments.size());
        for (const auto& [a, b] : segments) v.push_back({a, b});
        return v;
    }
    // The sites JSON of `medax voronoi`: {"points": [[x, y], ...]} or
    // {"curves": [[[x, y, 0], [x, y, 0]], ...]}.
    bool write_json(const std::string& path) const {
        std::FILE* f = std::fopen(path.c_str(), "w");
        if (!f) return false;
        if (segments.empty()) {
            std::fputs("{\"points\": [", f);
            for (size_t i = 0; i < points.size(); ++i)
                std::fprintf(f, "%s[%.17g, %.17g]", i ? ",\n" : "\n", points[i].first, points[i].second);
        } else {
            std::fputs("{\"curves\": [", f);
            for (size_t i = 0; i < segments.size(); ++i)
                std::fprintf(f, "%s[[%.17g, %.17g, 0], [%.17g, %.17g, 0]]", i ? ",\n" : "\n",
                             segments[i].first.first, segments[i].first.second, segments[i].second.first,
                             segments[i].second.second);
        }
        std::fputs("]}\n", f);
        return std::fclose(f) == 0;
    }
};

// `n` points uniformly at random in the square of side √n (one point per
// unit area, so the density does not change with n).
inline SiteSet random_points(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    SiteSet s;
    s.side = std::sqrt(static_cast<double>(n));
    std::uniform_real_distribution<double> u(0.0, s.side);
    s.points.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const double x = u(rng);
        s.points.emplace_back(x, u(rng));
    }
    return s;
}

// `n` disjoint segments, one per unit cell of a near-square grid (row by
// row): random direction, half-length 0.15 - 0.4, the midpoint jittered so
// that the segment keeps 0.05 inside its cell (at least 0.1 apart, no
// shared endpoints); the square round the grid is [0, side]^2.
inline SiteSet random_segments(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const size_t cols = static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    SiteSet s;
    s.side = static_cast<double>(cols);
    s.segments.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const double h = 0.15 + 0.25 * u(rng), t = 2 * kPi * u(rng);
        const double dx = h * std::cos(t), dy = h * std::sin(t);
        const double cx = static_cast<double>(i % cols) + 0.5 + (0.45 - std::abs(dx)) * (2 * u(rng) - 1);
        const double cy = static_cast<double>(i / cols) + 0.5 + (0.45 - std::abs(dy)) * (2 * u(rng) - 1);
        s.segments.push_back({{cx - dx, cy - dy}, {cx + dx, cy + dy}});
    }
    return s;
}

}  // namespace mt

#endif  // MEDAX_CTEST_SITES_SUPPORT_HPP
