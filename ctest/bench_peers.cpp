// Benchmark, not a test (not registered with CTest, not built by default):
// times on the same random star polygons (mt::star, R = 1, CCW)
//   medax   mx_shape2d_from_bulges + mx_axis_compute, threads = 1 and 2
//   CGAL    Segment_Delaunay_graph_2 construction, the polygon's edges
//           inserted as segments (sdg_support.hpp)
//   Boost   boost::polygon::construct_voronoi on the edges as
//           segment_data<int> (coordinates x 1e7, rounded)
// and prints a markdown table of the medians (seconds) and ratios.
//
// Usage: bench_peers [runs] [sizes...]     default: 3 runs; 1000 10000 100000
// medax is not run on a size when its previous size took more than 6 s
// (ten times that would pass a minute), CGAL not when its previous size
// took more than 10 s (it grows faster than linearly on these polygons).
// medax's status is shown when it failed (the time is then the time to
// the failure).
//
// Run with scripts/bench-peers (installs the prefix, builds in Release).

#include "bench_support.hpp"
#include "sdg_support.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {

using mt::cell;
using mt::median_seconds;
using mt::Polygon;
using mt::ratio;

size_t run_cgal(const Polygon& p) {
    mt::Sdg sdg;
    mt::insert_polygon(sdg, p);
    return sdg.number_of_faces();
}

}  // namespace

int main(int argc, char** argv) {
    const size_t runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    std::vector<size_t> sizes;
    for (int i = 2; i < argc; ++i) sizes.push_back(static_cast<size_t>(std::atol(argv[i])));
    if (sizes.empty()) sizes = {1000, 10000, 100000};

    std::cout << "bench_peers: medax " << mx_version() << ", CGAL " << CGAL_VERSION_STR << ", Boost "
              << BOOST_VERSION / 100000 << "." << BOOST_VERSION / 100 % 1000 << "; median of " << runs
              << " runs, seconds; random star polygons (R = 1)\n\n";
    std::cout << "| n | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi | medax 1 / 2 threads | "
                 "medax 1 thread / CGAL | medax 1 thread / Boost | CGAL / Boost |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::mt19937_64 rng(20240611);
    double last_medax = 0.0, last_cgal = 0.0;
    for (size_t n : sizes) {
        const Polygon p = mt::star(rng, n, 1.0, false);
        const std::vector<mt::BoostSegment> segments = mt::boost_segments({p}, 1e7);
        const std::vector<double> xyb = mt::bulges(p);
        const std::vector<size_t> lens{n};
        const double cgal = last_cgal <= 10.0 ? median_seconds(runs, [&] { run_cgal(p); }) : -1.0;
        if (cgal >= 0.0) last_cgal = cgal;
        const double boost = median_seconds(runs, [&] { mt::run_boost(segments); });
        std::string m1 = "not run", m2 = "not run", r12 = "-", rc = "-", rb = "-";
        if (last_medax <= 6.0) {
            mx_status s1 = MX_OK, s2 = MX_OK;
            const double t1 = median_seconds(runs, [&] { s1 = mt::run_medax(xyb, lens, 1); });
            const double t2 = median_seconds(runs, [&] { s2 = mt::run_medax(xyb, lens, 2); });
            m1 = cell(t1, s1), m2 = cell(t2, s2);
            r12 = ratio(t1, t2), rc = cgal >= 0.0 ? ratio(t1, cgal) : "-", rb = ratio(t1, boost);
            last_medax = t1;
        }
        const std::string cg = cgal >= 0.0 ? cell(cgal) : "not run";
        const std::string cb = cgal >= 0.0 ? ratio(cgal, boost) : "-";
        std::cout << "| " << n << " | " << m1 << " | " << m2 << " | " << cg << " | " << cell(boost) << " | " << r12
                  << " | " << rc << " | " << rb << " | " << cb << " |" << std::endl;
    }
    return 0;
}
