// Shared pieces of the peer benchmarks (bench_peers, bench_sites): timing,
// medax from bulge loops and medax's Voronoi diagram of sites through the C
// API, the loops as integer segments for Boost.Polygon's voronoi, and table
// cells. Header-only, C++17; pulls
// in Boost.Polygon but not CGAL.
#ifndef MEDAX_CTEST_BENCH_SUPPORT_HPP
#define MEDAX_CTEST_BENCH_SUPPORT_HPP

#include "polygon_support.hpp"

#include <boost/polygon/polygon.hpp>
#include <boost/polygon/voronoi.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

namespace mt {

using BoostSegment = boost::polygon::segment_data<int>;
using BoostPoint = boost::polygon::point_data<int>;

struct Times {
    double wall = 0, cpu = 0;  // seconds; cpu: of the whole process, all threads
};

inline double process_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The medians of up to `runs` timings, wall-clock and CPU (on a shared
// machine a single-threaded run's CPU time is what it would take alone);
// stops early once the runs together took `cap` seconds, so that one slow
// cell cannot eat the budget of the whole table (a single run is then its
// own median).
inline Times median_times(size_t runs, const std::function<void()>& f, double cap = 1e300) {
    std::vector<double> wall, cpu;
    double total = 0.0;
    for (size_t i = 0; i < runs && total < cap; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const double cpu0 = process_cpu_seconds();
        f();
        cpu.push_back(process_cpu_seconds() - cpu0);
        wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        total += wall.back();
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

// The command line every bench takes: `[runs] [sizes...]` (default 3 runs,
// sizes 10^3, 10^4, 10^5).
struct BenchArgs {
    size_t runs = 3;
    std::vector<size_t> sizes;
};

inline BenchArgs bench_args(int argc, char** argv) {
    BenchArgs a;
    if (argc > 1) a.runs = static_cast<size_t>(std::max(1, std::atoi(argv[1])));
    for (int i = 2; i < argc; ++i) a.sizes.push_back(static_cast<size_t>(std::atol(argv[i])));
    if (a.sizes.empty()) a.sizes = {1000, 10000, 100000};
    return a;
}

inline double median_seconds(size_t runs, const std::function<void()>& f) {
    return median_times(runs, f).wall;
}

// medax from flat `x, y, bulge` triples, loop 0 outer, as a C caller would
// (validation included in the time); the status of the call that failed.
inline mx_status run_medax(const std::vector<double>& xyb, const std::vector<size_t>& loop_lengths, size_t threads) {
    // The shape is checked on the same number of threads as the axis:
    // "one thread" is the whole call on one thread.
    mx_shape_options so;
    mx_shape_options_init(&so, sizeof so);
    so.threads = threads;
    mx_shape2d* shape = nullptr;
    mx_status st = mx_shape2d_from_bulges(xyb.data(), xyb.size(), loop_lengths.data(), loop_lengths.size(), &so,
                                          &shape);
    if (st != MX_OK) return st;
    mx_axis_options o;
    mx_axis_options_init(&o, sizeof o);
    o.threads = threads;
    mx_axis* axis = nullptr;
    st = mx_axis_compute(shape, &o, &axis);
    mx_axis_free(axis);
    mx_shape2d_free(shape);
    return st;
}

// Sites for mx_voronoi_compute as a C caller holds them: point pairs,
// curve triples and lengths, and optionally the caller's boundary Γ
// (empty: the library chooses its frame).
struct VoronoiInput {
    std::vector<double> points_xy, curves_xyb, boundary_xyb;
    std::vector<size_t> curve_lengths;
};

// mx_voronoi_compute on `in` (validation included in the time); `inspect`,
// when given, sees the diagram before it is freed. The status of the call.
inline mx_status run_medax_voronoi(const VoronoiInput& in, size_t threads,
                                   const std::function<void(const mx_voronoi*)>& inspect = {}) {
    mx_sites sites{};
    sites.points_xy = in.points_xy.empty() ? nullptr : in.points_xy.data();
    sites.point_count = in.points_xy.size() / 2;
    sites.curves_xyb = in.curves_xyb.empty() ? nullptr : in.curves_xyb.data();
    sites.curves_xyb_len = in.curves_xyb.size();
    sites.curve_lengths = in.curve_lengths.empty() ? nullptr : in.curve_lengths.data();
    sites.curve_count = in.curve_lengths.size();
    sites.boundary_xyb = in.boundary_xyb.empty() ? nullptr : in.boundary_xyb.data();
    sites.boundary_count = in.boundary_xyb.size() / 3;
    mx_voronoi_options o;
    mx_voronoi_options_init(&o, sizeof o);
    o.threads = threads;
    mx_voronoi* vd = nullptr;
    const mx_status st = mx_voronoi_compute(&sites, &o, &vd);
    if (st == MX_OK && inspect) inspect(vd);
    mx_voronoi_free(vd);
    return st;
}

// Every edge of every loop as an integer segment, coordinates x scale
// rounded: Boost.Polygon's voronoi takes integers only.
inline std::vector<BoostSegment> boost_segments(const std::vector<Polygon>& loops, double scale) {
    auto q = [&](Pt v) {
        return boost::polygon::point_data<int>(static_cast<int>(std::lround(v.first * scale)),
                                               static_cast<int>(std::lround(v.second * scale)));
    };
    std::vector<BoostSegment> segments;
    for (const Polygon& p : loops)
        for (size_t k = 0; k < p.size(); ++k) segments.emplace_back(q(p[k]), q(p[(k + 1) % p.size()]));
    return segments;
}

inline size_t run_boost(const std::vector<BoostSegment>& segments) {
    boost::polygon::voronoi_diagram<double> vd;
    boost::polygon::construct_voronoi(segments.begin(), segments.end(), &vd);
    return vd.num_vertices();
}

inline size_t run_boost(const std::vector<BoostPoint>& points) {
    boost::polygon::voronoi_diagram<double> vd;
    boost::polygon::construct_voronoi(points.begin(), points.end(), &vd);
    return vd.num_vertices();
}

inline std::string cell(double secs, mx_status st = MX_OK) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", secs);
    std::string s = buf;
    if (st != MX_OK) s += " (" + std::string(mx_status_str(static_cast<int32_t>(st))) + ")";
    return s;
}

inline std::string ratio(double a, double b) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", a / b);
    return buf;
}

}  // namespace mt

#endif  // MEDAX_CTEST_BENCH_SUPPORT_HPP
