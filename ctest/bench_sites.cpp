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
// a cell stops repeating once its runs took 10 s. BENCH_SITES_JSON=DIR
// writes every scene as shape JSON into DIR (for `medax axis`); a scene
// on which medax fails is written to the working directory either way.
//
// Run with scripts/bench-sites (installs the prefix, builds in Release).

#include "bench_support.hpp"
#include "sdg_support.hpp"
#include "sites_support.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using mt::cell;
using mt::ratio;

struct Column {
    double last_secs = 0;
    size_t last_elements = 0;
    std::map<size_t, double> seen;  // elements -> seconds, where it ran and succeeded

    bool within(size_t elements, double budget) const {
        return last_elements == 0 ||
               last_secs * static_cast<double>(elements) / static_cast<double>(last_elements) <= budget;
    }
    void record(size_t elements, double secs) {
        last_secs = secs, last_elements = elements;
        seen[elements] = secs;
    }
};

std::string slope(const Column& c, size_t n0, size_t n1) {
    if (!c.seen.count(n0) || !c.seen.count(n1)) return "-";
    const double t0 = c.seen.at(n0), t1 = c.seen.at(n1);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f",
                  std::log(t1 / t0) / std::log(static_cast<double>(n1) / static_cast<double>(n0)));
    return buf;
}

size_t run_cgal(const std::vector<mt::Polygon>& loops) {
    mt::Sdg sdg;
    mt::insert_loops(sdg, loops);
    return sdg.number_of_faces();
}

void bench(const std::string& table, size_t runs, const std::vector<size_t>& sizes) {
    const double budget = std::getenv("BENCH_SITES_BUDGET") ? std::atof(std::getenv("BENCH_SITES_BUDGET")) : 20.0;
    const double cap = 10.0;
    const char* json_dir = std::getenv("BENCH_SITES_JSON");
    std::cout << "\n### " << table << " (median of up to " << runs << " runs, seconds)\n\n"
              << "| size | sites | elements | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi | "
                 "medax 1 / 2 threads | CGAL / medax 1 thread | Boost / medax 1 thread |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    Column m1, m2, cg, bo;
    std::vector<size_t> elements;
    for (size_t size : sizes) {
        const mt::Scene s = table == "table21" ? mt::table21(size, 21) : mt::table22(size, 22);
        const size_t n = s.elements();
        elements.push_back(n);
        const std::string name = "bench_sites_" + table + "_" + std::to_string(size) + ".json";
        if (json_dir) s.write_json(std::string(json_dir) + "/" + name);
        const std::vector<double> xyb = s.xyb();
        const std::vector<size_t> lens = s.loop_lengths();
        const std::vector<mt::Polygon> chords = s.chords();
        std::string c1 = "not run", c2 = "not run", cc = "not run", cb = "not run";
        double t1 = NAN, t2 = NAN, tc = NAN, tb = NAN;
        mx_status s1 = MX_OK, s2 = MX_OK;
        if (m1.within(n, budget)) {
            t1 = mt::median_seconds(runs, [&] { s1 = mt::run_medax(xyb, lens, 1); }, cap);
            c1 = cell(t1, s1);
            if (s1 == MX_OK) m1.record(n, t1);
        }
        if (m2.within(n, budget)) {
            t2 = mt::median_seconds(runs, [&] { s2 = mt::run_medax(xyb, lens, 2); }, cap);
            c2 = cell(t2, s2);
            if (s2 == MX_OK) m2.record(n, t2);
        }
        if (s1 != MX_OK || s2 != MX_OK) {
            const bool saved = s.write_json(name);
            std::cerr << "medax failed on " << table << " " << size << ": " << mt::last_message()
                      << (saved ? "; scene written to " + name : "; could not write " + name) << "\n";
        }
        if (cg.within(n, budget)) {
            tc = mt::median_seconds(runs, [&] { run_cgal(chords); }, cap);
            cc = cell(tc), cg.record(n, tc);
        }
        if (bo.within(n, budget)) {
            const std::vector<mt::BoostSegment> segments =
                mt::boost_segments(chords, std::ldexp(1.0, 30) / std::max(s.width, s.height));
            tb = mt::median_seconds(runs, [&] { mt::run_boost(segments); }, cap);
            cb = cell(tb), bo.record(n, tb);
        }
        auto r = [](double a, double b) { return std::isnan(a) || std::isnan(b) ? std::string("-") : ratio(a, b); };
        std::cout << "| " << size << " | " << s.loops.size() - 1 << " | " << n << " | " << c1 << " | " << c2 << " | "
                  << cc << " | " << cb << " | " << r(t1, t2) << " | " << r(tc, t1) << " | " << r(tb, t1) << " |"
                  << std::endl;
    }
    std::cout << "\nLog-log slopes (time growth exponent in the element count) between consecutive sizes:\n\n"
              << "| step | medax 1 thread | medax 2 threads | CGAL SDG | Boost voronoi |\n|---|---:|---:|---:|---:|\n";
    for (size_t i = 0; i + 1 < elements.size(); ++i) {
        const size_t a = elements[i], b = elements[i + 1];
        std::cout << "| " << a << " → " << b << " | " << slope(m1, a, b) << " | " << slope(m2, a, b) << " | "
                  << slope(cg, a, b) << " | " << slope(bo, a, b) << " |\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    const size_t runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
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
