// Benchmark, not a test (not registered with CTest, not built by default):
// times on the same random star polygons (mt::star, R = 1, CCW, the same
// generator and seed as bench_peers's star table, so the same polygons)
//   medax square     mx_shape2d_from_bulges + mx_axis_compute_with_ball
//                    under mx_ball_square (the L-infinity axis),
//                    threads = 1 and 2
//   medax Euclidean  mx_shape2d_from_bulges + mx_axis_compute, threads = 1:
//                    what the square ball costs over the plain axis
//   CGAL SDG-L∞      Segment_Delaunay_graph_Linf_2 construction, the
//                    polygon's vertices and edges inserted as in cgal_linf
// and prints a markdown table of the medians (seconds) and ratios.
//
// Usage: bench_linf [runs] [sizes...]     default: 3 runs; 1000 10000 100000
// A column is not run on a size when its previous size took more than
// 10 s (every column grows at least linearly, so ten times that would pass
// a minute and a half per run). medax's status is shown when it failed
// (the time is then the time to the failure, and its ratios are left
// out: they would compare a partial run), and its message goes to stderr.
//
// Run with scripts/bench-linf (installs the prefix, builds in Release).

#include "bench_support.hpp"

#include <CGAL/Segment_Delaunay_graph_Linf_2.h>
#include <CGAL/Segment_Delaunay_graph_Linf_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using mt::cell;
using mt::median_seconds;
using mt::Polygon;
using mt::ratio;

// The types of cgal_linf: filtered traits without intersections (a simple
// polygon's edges do not cross), constructions in double with square roots.
using Kernel = CGAL::Simple_cartesian<double>;
using Traits = CGAL::Segment_Delaunay_graph_Linf_filtered_traits_without_intersections_2<Kernel, CGAL::Field_with_sqrt_tag>;
using SdgLinf = CGAL::Segment_Delaunay_graph_Linf_2<Traits>;

constexpr double kSkipAfter = 10.0;  // seconds; see the head comment

// One point site per vertex and one segment site per edge between them, as
// cgal_linf inserts them (the point conversion is part of the time, as the
// bulge triples' validation is part of medax's).
size_t run_cgal_linf(const Polygon& poly) {
    std::vector<SdgLinf::Point_2> pts;
    pts.reserve(poly.size());
    for (const mt::Pt& p : poly) pts.emplace_back(p.first, p.second);
    std::vector<std::pair<size_t, size_t>> edges;
    edges.reserve(poly.size());
    for (size_t k = 0; k < poly.size(); ++k) edges.emplace_back(k, (k + 1) % poly.size());
    SdgLinf sdg;
    sdg.insert_segments(pts, edges.begin(), edges.end());
    return sdg.number_of_faces();
}

// mt::run_medax under `ball`: the shape checked and the axis computed on
// the same number of threads, as a C caller would (validation included).
mx_status run_medax_ball(const std::vector<double>& xyb, size_t len, const mx_ball* ball, size_t threads) {
    mx_shape_options so;
    mx_shape_options_init(&so, sizeof so);
    so.threads = threads;
    mx_shape2d* shape = nullptr;
    mx_status st = mx_shape2d_from_bulges(xyb.data(), xyb.size(), &len, 1, &so, &shape);
    if (st != MX_OK) return st;
    mx_axis_options o;
    mx_axis_options_init(&o, sizeof o);
    o.threads = threads;
    mx_axis* axis = nullptr;
    st = mx_axis_compute_with_ball(shape, ball, &o, &axis);
    mx_axis_free(axis);
    mx_shape2d_free(shape);
    return st;
}

// One medax column's cell: the median of `runs` runs unless the previous
// size took more than kSkipAfter (`last`, updated here). `t` < 0 when not
// run; a failure's message is printed once (the last error is the calling
// thread's, so it is read right after the call).
struct Column {
    double last = 0.0, t = -1.0;
    mx_status st = MX_OK;

    template <typename F>
    void measure(const char* name, size_t n, size_t runs, F f) {
        t = -1.0, st = MX_OK;
        if (last > kSkipAfter) return;
        std::string message;
        t = median_seconds(runs, [&] {
            st = f();
            if (st != MX_OK) message = mt::last_message();
        });
        last = t;
        if (st != MX_OK) std::cerr << "bench_linf: " << name << ", n = " << n << ": " << message << "\n";
    }
    bool ok() const { return t >= 0.0 && st == MX_OK; }
    std::string text() const { return t >= 0.0 ? cell(t, st) : "not run"; }
};

}  // namespace

int main(int argc, char** argv) {
    const mt::BenchArgs args = mt::bench_args(argc, argv);
    const size_t runs = args.runs;
    const std::vector<size_t>& sizes = args.sizes;

    mx_ball* square = nullptr;
    if (mx_ball_square(&square) != MX_OK) {
        std::cerr << "bench_linf: mx_ball_square: " << mt::last_message() << "\n";
        return 1;
    }
    std::cout << "bench_linf: medax " << mx_version() << ", CGAL " << CGAL_VERSION_STR << "; median of " << runs
              << " runs, seconds; n = vertices (= segments)\n";
    std::cout << "\nRandom star polygons (R = 1), medial axis under the square ball (L-infinity)\n\n";
    std::cout << "| n | medax square 1 thread | medax square 2 threads | medax Euclidean 1 thread | CGAL SDG-L∞ | "
                 "CGAL / medax square 1 thread | medax square / Euclidean |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|\n";
    std::mt19937_64 rng(20240611);
    Column sq1, sq2, eu1;
    double last_cgal = 0.0;
    for (size_t size : sizes) {
        const Polygon poly = mt::star(rng, size, 1.0, false);
        const std::vector<double> xyb = mt::bulges(poly);
        const size_t len = poly.size();
        const std::vector<size_t> lens{len};
        sq1.measure("medax square 1 thread", len, runs, [&] { return run_medax_ball(xyb, len, square, 1); });
        sq2.measure("medax square 2 threads", len, runs, [&] { return run_medax_ball(xyb, len, square, 2); });
        eu1.measure("medax Euclidean 1 thread", len, runs, [&] { return mt::run_medax(xyb, lens, 1); });
        const double cgal = last_cgal <= kSkipAfter ? median_seconds(runs, [&] { run_cgal_linf(poly); }) : -1.0;
        if (cgal >= 0.0) last_cgal = cgal;
        const std::string rc = cgal >= 0.0 && sq1.ok() ? ratio(cgal, sq1.t) : "-";
        const std::string re = sq1.ok() && eu1.ok() ? ratio(sq1.t, eu1.t) : "-";
        std::cout << "| " << len << " | " << sq1.text() << " | " << sq2.text() << " | " << eu1.text() << " | "
                  << (cgal >= 0.0 ? cell(cgal) : "not run") << " | " << rc << " | " << re << " |" << std::endl;
    }
    mx_ball_free(square);
    return 0;
}
