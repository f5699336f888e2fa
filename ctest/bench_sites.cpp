// Benchmark, not a test (not registered with CTest, not built by default):
// Voronoi diagrams of region sites inside a rectangle Γ (thesis 2.3.2,
// Tables 2.1 and 2.2; generators in sites_support.hpp), timed for
//   medax   mx_shape2d_from_bulges + mx_axis_compute on Γ with the sites as
//           holes, threads = 1 and 2
//   CGAL    Segment_Delaunay_graph_2 of the polygonized scene: every arc
//           replaced by its chord, every element of Γ and of every site
//           inserted as a segment (sdg_support.hpp)
//   Boost   boost::polygon::construct_voronoi on the same segments,
//           coordinates scaled to 2^30 / max(width, height) and rounded
// and prints markdown tables of the medians (seconds), the ratios, and the
// log-log slopes between consecutive sizes.
//
// Usage: bench_sites [runs] [table21|table22] [sizes...]
//   table21: sizes are total site arcs (40 blobs); default 2e3 .. 5e5
//   table22: sizes are site counts (4 arcs each); default 1e2 .. 1e5
//   no table: both, default sizes.
// A tool is skipped at a size when its previous time, scaled linearly to
// the new element count, passes BENCH_SITES_BUDGET seconds (default 20);
// a cell stops repeating once its runs took half that. Wall-clock and
// process CPU times are both printed: the machine may be shared, and a
// single-threaded run's CPU time is close to what it takes alone. BENCH_SITES_JSON=DIR
// writes every scene as shape JSON into DIR (for `medax axis`; 0 runs:
// only that, no timing); a scene on which medax fails is written to the
// working directory either way. BENCH_SITES_SEED=K (default 0) adds K to
// the generators' seeds, for robustness sweeps.
//
// Run with scripts/bench-sites (installs the prefix, builds in Release).

#include "bench_support.hpp"
#include "sdg_support.hpp"
#include "sites_support.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using mt::cell;
using mt::ratio;

// One tool's cells: the last size it ran at (for the budget) and every
// successful timing (for the slopes).
struct Column {
    size_t last_elements = 0;
    double last_wall = 0;
    std::map<size_t, mt::Times> seen;
    bool ran = false;
    mt::Times now;
    mx_status status = MX_OK;

    void measure(size_t n, size_t runs, double budget, const std::function<mx_status()>& f) {
        ran = last_elements == 0 || last_wall * static_cast<double>(n) / static_cast<double>(last_elements) <= budget;
        now = {NAN, NAN}, status = MX_OK;
        if (!ran) return;
        now = mt::median_times(runs, [&] { status = f(); }, budget / 2);
        if (status != MX_OK) return;
        last_elements = n, last_wall = now.wall;
        seen[n] = now;
    }
    std::string wall() const { return ran ? cell(now.wall, status) : "not run"; }
    std::string cpu() const { return ran ? cell(now.cpu, status) : "not run"; }
    std::string slope(size_t n0, size_t n1, double mt::Times::*which) const {
        if (!seen.count(n0) || !seen.count(n1)) return "-";
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2f",
                      std::log(seen.at(n1).*which / seen.at(n0).*which) /
                          std::log(static_cast<double>(n1) / static_cast<double>(n0)));
        return buf;
    }
};

std::string ratio_of(double a, double b) {
    return std::isnan(a) || std::isnan(b) ? std::string("-") : ratio(a, b);
}

size_t run_cgal(const std::vector<mt::Polygon>& loops) {
    mt::Sdg sdg;
    mt::insert_loops(sdg, loops);
    return sdg.number_of_faces();
}

void bench(const std::string& table, size_t runs, const std::vector<size_t>& sizes) {
    const double budget = std::getenv("BENCH_SITES_BUDGET") ? std::atof(std::getenv("BENCH_SITES_BUDGET")) : 20.0;
    const char* json_dir = std::getenv("BENCH_SITES_JSON");
    const char* seed_env = std::getenv("BENCH_SITES_SEED");
    const uint64_t seed = seed_env ? std::strtoull(seed_env, nullptr, 10) : 0;
    auto scene = [&](size_t size) {
        return table == "table21" ? mt::table21(size, 21 + seed) : mt::table22(size, 22 + seed);
    };
    auto name = [&](size_t size) {
        return "bench_sites_" + table + "_" + std::to_string(size) +
               (seed ? "_seed" + std::to_string(seed) : std::string()) + ".json";
    };
    if (runs == 0) {
        for (size_t size : sizes)
            if (json_dir) scene(size).write_json(std::string(json_dir) + "/" + name(size));
        return;
    }
    std::cout << "\n### " << table << ": wall-clock seconds, median of up to " << runs << " runs\n\n"
              << "| size | sites | elements | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi | "
                 "medax 1 / 2 threads | CGAL / medax 1 thread | Boost / medax 1 thread |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::ostringstream cpu;
    cpu << "\nCPU seconds of the same runs (process CPU time; medax 2 threads: both threads together):\n\n"
        << "| size | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi | CGAL / medax 1 thread | "
           "Boost / medax 1 thread |\n|---:|---:|---:|---:|---:|---:|---:|\n";
    Column m1, m2, cg, bo;
    std::vector<size_t> elements;
    for (size_t size : sizes) {
        const mt::Scene s = scene(size);
        const size_t n = s.elements();
        elements.push_back(n);
        if (json_dir) s.write_json(std::string(json_dir) + "/" + name(size));
        const std::vector<double> xyb = s.xyb();
        const std::vector<size_t> lens = s.loop_lengths();
        const std::vector<mt::Polygon> chords = s.chords();
        const std::vector<mt::BoostSegment> segments =
            mt::boost_segments(chords, std::ldexp(1.0, 30) / std::max(s.width, s.height));
        m1.measure(n, runs, budget, [&] { return mt::run_medax(xyb, lens, 1); });
        m2.measure(n, runs, budget, [&] { return mt::run_medax(xyb, lens, 2); });
        if (m1.status != MX_OK || m2.status != MX_OK) {
            const bool saved = s.write_json(name(size));
            std::cerr << "medax failed on " << table << " " << size << ": " << mt::last_message()
                      << (saved ? "; scene written to " : "; could not write ") << name(size) << "\n";
        }
        cg.measure(n, runs, budget, [&] {
            run_cgal(chords);
            return MX_OK;
        });
        bo.measure(n, runs, budget, [&] {
            mt::run_boost(segments);
            return MX_OK;
        });
        std::cout << "| " << size << " | " << s.loops.size() - 1 << " | " << n << " | " << m1.wall() << " | "
                  << m2.wall() << " | " << cg.wall() << " | " << bo.wall() << " | "
                  << ratio_of(m1.now.wall, m2.now.wall) << " | " << ratio_of(cg.now.wall, m1.now.wall) << " | "
                  << ratio_of(bo.now.wall, m1.now.wall) << " |" << std::endl;
        cpu << "| " << size << " | " << m1.cpu() << " | " << m2.cpu() << " | " << cg.cpu() << " | " << bo.cpu()
            << " | " << ratio_of(cg.now.cpu, m1.now.cpu) << " | " << ratio_of(bo.now.cpu, m1.now.cpu) << " |\n";
    }
    std::cout << cpu.str()
              << "\nLog-log slopes (growth exponent of the time in the element count) between consecutive sizes:\n\n"
              << "| step | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi | medax 1 thread CPU | "
                 "CGAL CPU | Boost CPU |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (size_t i = 0; i + 1 < elements.size(); ++i) {
        const size_t a = elements[i], b = elements[i + 1];
        const auto w = &mt::Times::wall, c = &mt::Times::cpu;
        std::cout << "| " << a << " → " << b << " | " << m1.slope(a, b, w) << " | " << m2.slope(a, b, w) << " | "
                  << cg.slope(a, b, w) << " | " << bo.slope(a, b, w) << " | " << m1.slope(a, b, c) << " | "
                  << cg.slope(a, b, c) << " | " << bo.slope(a, b, c) << " |\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    const size_t runs = argc > 1 ? static_cast<size_t>(std::max(0, std::atoi(argv[1]))) : 3;
    const std::string which = argc > 2 ? argv[2] : "";
    std::vector<size_t> sizes;
    for (int i = 3; i < argc; ++i) sizes.push_back(static_cast<size_t>(std::atof(argv[i])));

    std::cout << "bench_sites: medax " << mx_version() << ", CGAL " << CGAL_VERSION_STR << ", Boost "
              << BOOST_VERSION / 100000 << "." << BOOST_VERSION / 100 % 1000
              << "; sizes: table21 = total site arcs, table22 = sites; elements = all arcs and segments, Γ's 4 "
                 "included\n";
    if (which != "table22")
        bench("table21", runs, which == "table21" && !sizes.empty() ? sizes : std::vector<size_t>{2000, 5000, 10000,
                                                                                                    50000, 100000,
                                                                                                    500000});
    if (which != "table21")
        bench("table22", runs, which == "table22" && !sizes.empty() ? sizes : std::vector<size_t>{100, 1000, 10000,
                                                                                                    100000});
    return 0;
}
