// Benchmark, not a test (not registered with CTest, not built by default):
// times on the same random star polygons (mt::star, R = 1, CCW) and plates
// with random polygonal holes (a square with one random convex 5- to
// 11-gon in each cell of a k x k grid)
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

size_t run_cgal(const std::vector<Polygon>& loops) {
    mt::Sdg sdg;
    if (loops.size() == 1) {
        mt::insert_polygon(sdg, loops[0]);
    } else {
        mt::insert_loops(sdg, loops);
    }
    return sdg.number_of_faces();
}

// A square plate of side k with a random convex hole in each unit cell
// (5 to 11 vertices at sorted random angles on a circle of radius 0.2 to
// 0.4 round the cell's centre, clockwise), about n vertices in all.
std::vector<Polygon> plate(std::mt19937_64& rng, size_t n) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const size_t k = std::max<size_t>(1, static_cast<size_t>(std::sqrt(static_cast<double>(n) / 8.0)));
    const double side = static_cast<double>(k);
    std::vector<Polygon> loops{{{0.0, 0.0}, {side, 0.0}, {side, side}, {0.0, side}}};
    for (size_t i = 0; i < k; ++i) {
        for (size_t j = 0; j < k; ++j) {
            const size_t m = 5 + static_cast<size_t>(7.0 * u(rng)) % 7;
            const double r = 0.2 + 0.2 * u(rng);
            Polygon hole;
            for (size_t v = 0; v < m; ++v) {
                // Clockwise: decreasing angles, one per sector.
                const double t = -2.0 * mt::kPi * (static_cast<double>(v) + 0.1 + 0.8 * u(rng)) / static_cast<double>(m);
                hole.emplace_back(static_cast<double>(i) + 0.5 + r * std::cos(t),
                                  static_cast<double>(j) + 0.5 + r * std::sin(t));
            }
            loops.push_back(std::move(hole));
        }
    }
    return loops;
}

size_t vertex_count(const std::vector<Polygon>& loops) {
    size_t n = 0;
    for (const Polygon& p : loops) n += p.size();
    return n;
}

// One table: every size of one family, each peer on the same input.
template <typename Make>
void table(const char* name, const std::vector<size_t>& sizes, size_t runs, Make make) {
    std::cout << "\n" << name << "\n\n";
    std::cout << "| n | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi | medax 1 / 2 threads | "
                 "medax 1 thread / CGAL | medax 1 thread / Boost | CGAL / Boost |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::mt19937_64 rng(20240611);
    double last_medax = 0.0, last_cgal = 0.0;
    for (size_t size : sizes) {
        const std::vector<Polygon> loops = make(rng, size);
        const std::vector<mt::BoostSegment> segments = mt::boost_segments(loops, 1e7);
        std::vector<double> xyb;
        std::vector<size_t> lens;
        for (const Polygon& p : loops) {
            const std::vector<double> b = mt::bulges(p);
            xyb.insert(xyb.end(), b.begin(), b.end());
            lens.push_back(p.size());
        }
        const double cgal = last_cgal <= 10.0 ? median_seconds(runs, [&] { run_cgal(loops); }) : -1.0;
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
        std::cout << "| " << vertex_count(loops) << " | " << m1 << " | " << m2 << " | " << cg << " | " << cell(boost)
                  << " | " << r12 << " | " << rc << " | " << rb << " | " << cb << " |" << std::endl;
    }
}

}  // namespace

int main(int argc, char** argv) {
    const mt::BenchArgs args = mt::bench_args(argc, argv);
    const size_t runs = args.runs;
    const std::vector<size_t>& sizes = args.sizes;

    std::cout << "bench_peers: medax " << mx_version() << ", CGAL " << CGAL_VERSION_STR << ", Boost "
              << BOOST_VERSION / 100000 << "." << BOOST_VERSION / 100 % 1000 << "; median of " << runs
              << " runs, seconds; n = vertices (= segments)\n";
    table("Random star polygons (R = 1)", sizes, runs,
          [](std::mt19937_64& rng, size_t n) { return std::vector<Polygon>{mt::star(rng, n, 1.0, false)}; });
    table("Plates with a random convex hole (5-11 vertices) per unit cell", sizes, runs, plate);
    return 0;
}
