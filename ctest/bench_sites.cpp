// Benchmark, not a test (not registered with CTest, not built by default):
// Voronoi diagrams of sites, timed for medax and two peers, as markdown
// tables of the medians (seconds, wall-clock and process CPU), the ratios,
// and the log-log slopes between consecutive sizes.
//
// Tables table21 and table22: region sites inside a rectangle Γ (thesis
// 2.3.2, Tables 2.1 and 2.2; generators in sites_support.hpp), timed for
//   medax   mx_shape2d_from_bulges + mx_axis_compute on Γ with the sites as
//           holes, threads = 1 and 2
//   CGAL    Segment_Delaunay_graph_2 of the polygonized scene: every arc
//           replaced by its chord, every element of Γ and of every site
//           inserted as a segment (sdg_support.hpp)
//   Boost   boost::polygon::construct_voronoi on the same segments,
//           coordinates scaled to 2^30 / max(width, height) and rounded
// Tables points and segments: N random points in a square, N random
// disjoint segments (one per jittered unit cell), timed for
//   medax   mx_voronoi_compute without a boundary (the library chooses and
//           grows its frame), threads = 1 and 2; and once more, 1 thread,
//           with a caller boundary Γ (a square of half-side 64 sites'
//           diagonals round the sites), which computes once: the ratio of
//           the two is about the number of frames the library computed.
//           (Squares of 256 and 1024 diagonals broke down on 3000 and 10^4
//           random points, 4 diagonals on 1000 segments, in the corners.)
//   CGAL    Segment_Delaunay_graph_2: the points inserted at once
//           (insert(first, beyond, Tag_true): spatially sorted), or the
//           segments' endpoints (spatially sorted) and then the segments
//   Boost   construct_voronoi on the points or segments, coordinates
//           scaled to 2^30 / side and rounded
// and the library's frame of the 1-thread run: its radius in sites'
// diagonals (from the farthest axis node, about half the radius away from
// the sites) and so the number of frames computed (4, 64, 1024, ...
// diagonals: each growth is a recomputation).
//
// Usage: bench_sites [runs] [table21|table22|points|segments] [sizes...]
//   table21: sizes are total site arcs (40 blobs); default 2e3 .. 5e5
//   table22: sizes are site counts (4 arcs each); default 1e2 .. 1e5
//   points: sizes are point counts; default 1e3, 1e4, 3e4, 1e5
//   segments: sizes are segment counts; default 1e3, 1e4, 3e4
//   no table: all four, default sizes.
// A tool is skipped at a size when its previous time, scaled linearly to
// the new element count, passes BENCH_SITES_BUDGET seconds (default 20 for
// table21 and table22, 60 for points and segments); a cell stops
// repeating once its runs took half that. Wall-clock and process CPU
// times are both printed: the machine may be shared, and a
// single-threaded run's CPU time is close to what it takes alone. BENCH_SITES_JSON=DIR
// writes every scene as shape JSON (for `medax axis`) or sites JSON (for
// `medax voronoi`) into DIR (0 runs: only that, no timing); a scene on
// which medax fails is written to the working directory either way.
// BENCH_SITES_SEED=K (default 0) adds K to the generators' seeds, for
// robustness sweeps.
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

// A column of the slopes table: its header, the tool, wall or CPU time.
struct SlopeColumn {
    const char* header;
    const Column* tool;
    double mt::Times::*which;
};
constexpr double mt::Times::*W = &mt::Times::wall;
constexpr double mt::Times::*C = &mt::Times::cpu;

// The log-log slopes between consecutive sizes (`counts`, in `unit`s).
void print_slopes(const char* unit, const std::vector<size_t>& counts, const std::vector<SlopeColumn>& columns) {
    std::cout << "\nLog-log slopes (growth exponent of the time in the " << unit
              << ") between consecutive sizes:\n\n| step |";
    for (const SlopeColumn& c : columns) std::cout << " " << c.header << " |";
    std::cout << "\n|---|";
    for (size_t i = 0; i < columns.size(); ++i) std::cout << "---:|";
    std::cout << "\n";
    for (size_t i = 0; i + 1 < counts.size(); ++i) {
        const size_t a = counts[i], b = counts[i + 1];
        std::cout << "| " << a << " → " << b << " |";
        for (const SlopeColumn& c : columns) std::cout << " " << c.tool->slope(a, b, c.which) << " |";
        std::cout << "\n";
    }
}

size_t run_cgal(const std::vector<mt::Polygon>& loops) {
    mt::Sdg sdg;
    mt::insert_loops(sdg, loops);
    return sdg.number_of_faces();
}

// The environment's settings: BENCH_SITES_BUDGET (or `default_budget`),
// BENCH_SITES_JSON, BENCH_SITES_SEED.
struct Settings {
    double budget;
    const char* json_dir;
    uint64_t seed;
    explicit Settings(double default_budget)
        : budget(std::getenv("BENCH_SITES_BUDGET") ? std::atof(std::getenv("BENCH_SITES_BUDGET")) : default_budget),
          json_dir(std::getenv("BENCH_SITES_JSON")),
          seed(std::getenv("BENCH_SITES_SEED") ? std::strtoull(std::getenv("BENCH_SITES_SEED"), nullptr, 10) : 0) {}
};

void bench(const std::string& table, size_t runs, const std::vector<size_t>& sizes) {
    const Settings env(20.0);
    const double budget = env.budget;
    const char* json_dir = env.json_dir;
    const uint64_t seed = env.seed;
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
    std::cout << cpu.str();
    print_slopes("element count", elements,
                 {{"medax 1 thread", &m1, W}, {"medax 2 threads", &m2, W}, {"CGAL SDG", &cg, W},
                  {"Boost voronoi", &bo, W}, {"medax 1 thread CPU", &m1, C}, {"CGAL CPU", &cg, C},
                  {"Boost CPU", &bo, C}});
}

// Frame radius of a diagram from the library's frame in `diag` units,
// estimated as twice the farthest axis node's distance from `centre`
// (the disks touching the frame and two sites near the centre lie about
// half-way out), and the number of frames that means (radii 4 × 16^k).
struct FrameSeen {
    double radius = NAN;  // sites' diagonals
    int frames = 0;
    bool complete = false;
};

FrameSeen frame_of(const mx_voronoi* vd, double cx, double cy, double diag) {
    FrameSeen f;
    mx_voronoi_info info{};
    mx_voronoi_get_info(vd, &info);
    f.complete = info.complete != 0;
    const mx_axis* axis = nullptr;
    size_t nodes = 0;
    if (mx_voronoi_axis(vd, &axis) != MX_OK || mx_axis_node_count(axis, &nodes) != MX_OK) return f;
    double far = 0;
    for (size_t i = 0; i < nodes; ++i) {
        mx_axis_node n{};
        if (mx_axis_get_node(axis, i, &n) == MX_OK) far = std::max(far, std::hypot(n.x - cx, n.y - cy));
    }
    f.radius = 2 * far / diag;
    f.frames = 1 + static_cast<int>(std::lround(std::log(f.radius / 4) / std::log(16.0)));
    return f;
}

// Tables points and segments: mx_voronoi_compute (library frame, 1 and 2
// threads; caller square, 1 thread) against CGAL's SDG and Boost's voronoi.
void bench_voronoi(const std::string& table, size_t runs, const std::vector<size_t>& sizes) {
    const Settings env(60.0);
    const bool points = table == "points";
    auto scene = [&](size_t n) {
        return points ? mt::random_points(n, 31 + env.seed) : mt::random_segments(n, 32 + env.seed);
    };
    auto name = [&](size_t n) {
        return "bench_sites_" + table + "_" + std::to_string(n) +
               (env.seed ? "_seed" + std::to_string(env.seed) : std::string()) + ".json";
    };
    if (runs == 0) {
        for (size_t n : sizes)
            if (env.json_dir) scene(n).write_json(std::string(env.json_dir) + "/" + name(n));
        return;
    }
    std::cout << "\n### " << table << ": wall-clock seconds, median of up to " << runs
              << " runs (medax: mx_voronoi_compute; frame: the library's, radius in sites' diagonals, and "
                 "the frames computed)\n\n"
              << "| sites | medax 1 thread | medax 2 threads | medax 1 thread, caller square | CGAL SDG | "
                 "Boost voronoi | frame | medax 1 / 2 threads | library / caller frame | CGAL / medax 1 thread | "
                 "Boost / medax 1 thread |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::ostringstream cpu;
    cpu << "\nCPU seconds of the same runs (process CPU time; medax 2 threads: both threads together):\n\n"
        << "| sites | medax 1 thread | medax 2 threads | medax 1 thread, caller square | CGAL SDG | Boost voronoi | "
           "library / caller frame | CGAL / medax 1 thread | Boost / medax 1 thread | medax 1 thread µs / site |\n"
           "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    Column m1, m2, mc, cg, bo;
    for (size_t n : sizes) {
        const mt::SiteSet s = scene(n);
        if (env.json_dir) s.write_json(std::string(env.json_dir) + "/" + name(n));
        mt::VoronoiInput in;
        in.points_xy = s.points_xy();
        in.curves_xyb = s.curves_xyb();
        in.curve_lengths = s.curve_lengths();
        // The sites' box is [0, side]^2 up to the segments' margin; the
        // caller's square: 64 diagonals each way (the library's second
        // frame has that radius).
        const double c = s.side / 2, diag = s.side * std::sqrt(2.0), h = 64 * diag;
        mt::VoronoiInput caller = in;
        caller.boundary_xyb = {c - h, c - h, 0, c + h, c - h, 0, c + h, c + h, 0, c - h, c + h, 0};
        const double scale = std::ldexp(1.0, 30) / s.side;
        auto q = [&](const mt::Pt& p) {
            return mt::BoostPoint(static_cast<int>(std::lround(p.first * scale)),
                                  static_cast<int>(std::lround(p.second * scale)));
        };
        std::vector<mt::BoostPoint> bpoints;
        std::vector<mt::BoostSegment> bsegments;
        for (const mt::Pt& p : s.points) bpoints.push_back(q(p));
        for (const auto& [a, b] : s.segments) bsegments.emplace_back(q(a), q(b));
        std::vector<mt::Sdg::Point_2> cpoints;
        for (const mt::Pt& p : s.points) cpoints.emplace_back(p.first, p.second);
        const std::vector<mt::Polygon> chains = s.chains();

        FrameSeen frame;
        m1.measure(n, runs, env.budget, [&] {
            return mt::run_medax_voronoi(in, 1, [&](const mx_voronoi* vd) { frame = frame_of(vd, c, c, diag); });
        });
        m2.measure(n, runs, env.budget, [&] { return mt::run_medax_voronoi(in, 2); });
        mc.measure(n, runs, env.budget, [&] { return mt::run_medax_voronoi(caller, 1); });
        if (m1.status != MX_OK || m2.status != MX_OK || mc.status != MX_OK) {
            const bool saved = s.write_json(name(n));
            std::cerr << "medax failed on " << table << " " << n << ": " << mt::last_message()
                      << (saved ? "; sites written to " : "; could not write ") << name(n) << "\n";
        }
        cg.measure(n, runs, env.budget, [&] {
            mt::Sdg sdg;
            if (points)
                sdg.insert(cpoints.begin(), cpoints.end(), CGAL::Tag_true());
            else
                mt::insert_chains(sdg, chains, false);
            return MX_OK;
        });
        bo.measure(n, runs, env.budget, [&] {
            if (points)
                mt::run_boost(bpoints);
            else
                mt::run_boost(bsegments);
            return MX_OK;
        });
        std::string frame_cell = "-";
        if (m1.ran && m1.status == MX_OK) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.0f: %d%s", frame.radius, frame.frames,
                          frame.complete ? "" : " (incomplete)");
            frame_cell = buf;
        }
        std::cout << "| " << n << " | " << m1.wall() << " | " << m2.wall() << " | " << mc.wall() << " | "
                  << cg.wall() << " | " << bo.wall() << " | " << frame_cell << " | "
                  << ratio_of(m1.now.wall, m2.now.wall) << " | " << ratio_of(m1.now.wall, mc.now.wall) << " | "
                  << ratio_of(cg.now.wall, m1.now.wall) << " | " << ratio_of(bo.now.wall, m1.now.wall) << " |"
                  << std::endl;
        char per_site[32] = "-";
        if (!std::isnan(m1.now.cpu))
            std::snprintf(per_site, sizeof per_site, "%.3g", 1e6 * m1.now.cpu / static_cast<double>(n));
        cpu << "| " << n << " | " << m1.cpu() << " | " << m2.cpu() << " | " << mc.cpu() << " | " << cg.cpu()
            << " | " << bo.cpu() << " | " << ratio_of(m1.now.cpu, mc.now.cpu) << " | "
            << ratio_of(cg.now.cpu, m1.now.cpu) << " | " << ratio_of(bo.now.cpu, m1.now.cpu) << " | " << per_site
            << " |\n";
    }
    std::cout << cpu.str();
    print_slopes("site count", sizes,
                 {{"medax 1 thread", &m1, W}, {"medax 2 threads", &m2, W}, {"medax caller square", &mc, W},
                  {"CGAL SDG", &cg, W}, {"Boost voronoi", &bo, W}, {"medax 1 thread CPU", &m1, C},
                  {"medax caller square CPU", &mc, C}, {"CGAL CPU", &cg, C}, {"Boost CPU", &bo, C}});
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
                 "included; points, segments = sites\n";
    auto pick = [&](const char* table, std::vector<size_t> defaults) {
        return which == table && !sizes.empty() ? sizes : defaults;
    };
    if (which.empty() || which == "table21")
        bench("table21", runs, pick("table21", {2000, 5000, 10000, 50000, 100000, 500000}));
    if (which.empty() || which == "table22") bench("table22", runs, pick("table22", {100, 1000, 10000, 100000}));
    if (which.empty() || which == "points") bench_voronoi("points", runs, pick("points", {1000, 10000, 30000, 100000}));
    if (which.empty() || which == "segments")
        bench_voronoi("segments", runs, pick("segments", {1000, 10000, 30000}));
    if (!which.empty() && which != "table21" && which != "table22" && which != "points" && which != "segments") {
        std::cerr << "bench_sites: unknown table " << which << " (table21, table22, points, segments)\n";
        return 2;
    }
    return 0;
}
