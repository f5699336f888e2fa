// Benchmark, not a test (not registered with CTest, not built by default):
// queries of solids, medax against CGAL 5.5's AABB_tree (issue 19).
//
// Meshes: parametric tori of 2·a·b triangles, a = 2b, R = 3, r = 1 (the
// parametrisation of examples/bench_mesh.rs and cgal_mesh.cpp), sizes from
// the command line. Points: 10^5 from a fixed seed in two families, the
// same points for both libraries:
//   near  a uniform point of a random triangle moved along its normal by
//         at most 0.01 (so within 0.01 of the surface);
//   box   uniform in the mesh's bounding box.
// Timed, medians of `runs` runs (seconds, wall clock):
//   medax build        mx_mesh3d_from_arrays: the WHOLE validation (welding,
//                      topology, orientation, exact self-intersection check,
//                      nesting) plus the AABB tree;
//   medax closest+side mx_mesh3d_query_points without a ball: exact side and
//                      closest point of every point in one call;
//   CGAL build         Surface_mesh from the arrays, AABB_tree over its faces
//                      (built), accelerate_distance_queries (its kd-tree),
//                      and a Side_of_triangle_mesh sharing that tree;
//   CGAL closest       closest_point_and_primitive of every point;
//   CGAL side          Side_of_triangle_mesh of every point;
//   CGAL closest+side  the sum of the two (the work of medax's one call);
//   whole              build + closest + side, CGAL over medax;
//   medax ball         mx_mesh3d_query_points with a ball on the points found
//                      inside (the ball radius is only given there): under
//                      mx_ball_tetrahedron and under the hull of 66 points of
//                      a Fibonacci sphere (128 triangular facets; the
//                      geodesic presets have 80 or 320); ball/Euclidean
//                      divides each by the call without a ball on the same
//                      inside points.
//
// Threads: medax's batched queries run on rayon's global pool, so the
// process runs with RAYON_NUM_THREADS=1 or 2 (scripts/bench-mesh runs
// both) and CGAL gets as many std::threads, each on a contiguous share of
// the points, after the tree, its kd-tree and the side tester were built:
// the queries are then const calls on built structures (CGAL 5.5 guards
// the lazy builds with a mutex and atomics under CGAL_HAS_THREADS; without
// it CGAL may use statics, and its queries run on one thread).
//
// Sanity: on the first 300 points of each family both must give the same
// squared distance (1e-9 relative, plus 64 ε · d · diagonal: both round the
// closest point before squaring) and the same side wherever CGAL decides
// one; any disagreement aborts the run, so that the table cannot compare
// different work.
//
// Usage: bench_mesh [runs] [sizes...]   default: 3 runs; 10000 100000 1000000
// A cell whose runs together pass 20 s is the median of the runs made by
// then (at least one). MEDAX_BENCH_ROWS_ONLY=1 prints the rows without the
// header (scripts/bench-mesh joins the two thread counts into one table).
//
// Run with scripts/bench-mesh (installs the prefix, builds in Release).

#include "bench_support.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
using Side = CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>;

#ifdef CGAL_HAS_THREADS
constexpr bool kCgalThreads = true;
#else
constexpr bool kCgalThreads = false;
#endif

constexpr size_t kPoints = 100000;
constexpr size_t kCheck = 300;
constexpr double kCap = 20.0;  // seconds of runs per cell; see the head comment

struct Soup {
    std::vector<double> xyz;
    std::vector<uint32_t> tri;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
};

// medax::shape::mesh_samples::torus(R, r, n, m): n steps around the axis,
// m around the tube, 2·n·m triangles facing outward.
Soup torus(double big, double small, size_t n, size_t m) {
    Soup s;
    s.xyz.reserve(3 * n * m);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < m; ++j) {
            const double u = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double w = 2 * M_PI * static_cast<double>(j) / static_cast<double>(m);
            const double r = big + small * std::cos(w);
            const double p[3] = {r * std::cos(u), r * std::sin(u), small * std::sin(w)};
            for (int a = 0; a < 3; ++a) {
                s.xyz.push_back(p[a]);
                s.lo[a] = std::min(s.lo[a], p[a]);
                s.hi[a] = std::max(s.hi[a], p[a]);
            }
        }
    auto id = [&](size_t i, size_t j) { return static_cast<uint32_t>((i % n) * m + (j % m)); };
    s.tri.reserve(6 * n * m);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < m; ++j) {
            const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            s.tri.insert(s.tri.end(), {a, b, c, a, c, d});
        }
    return s;
}

std::vector<double> near_points(const Soup& s, std::mt19937_64& rng) {
    std::uniform_int_distribution<size_t> pick(0, s.tri.size() / 3 - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0), off(-0.01, 0.01);
    std::vector<double> out;
    out.reserve(3 * kPoints);
    for (size_t k = 0; k < kPoints; ++k) {
        const size_t t = pick(rng);
        const double* v[3];
        for (int i = 0; i < 3; ++i) v[i] = &s.xyz[3 * s.tri[3 * t + i]];
        double su = std::sqrt(unit(rng)), w = unit(rng);
        const double ba = 1 - su, bb = su * (1 - w), bc = su * w;  // uniform on the triangle
        double e1[3], e2[3], n[3];
        for (int a = 0; a < 3; ++a) e1[a] = v[1][a] - v[0][a], e2[a] = v[2][a] - v[0][a];
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), h = off(rng);
        for (int a = 0; a < 3; ++a) out.push_back(ba * v[0][a] + bb * v[1][a] + bc * v[2][a] + h * n[a] / len);
    }
    return out;
}

std::vector<double> box_points(const Soup& s, std::mt19937_64& rng) {
    std::vector<double> out;
    out.reserve(3 * kPoints);
    for (size_t k = 0; k < kPoints; ++k)
        for (int a = 0; a < 3; ++a) out.push_back(std::uniform_real_distribution<double>(s.lo[a], s.hi[a])(rng));
    return out;
}

// The hull of 66 points of a Fibonacci sphere: 2·66 − 4 = 128 triangles.
mx_ball* fibonacci_ball() {
    const int n = 66;
    std::vector<double> xyz;
    const double golden = M_PI * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1 - (2.0 * i + 1) / n, r = std::sqrt(1 - z * z), phi = golden * i;
        xyz.insert(xyz.end(), {r * std::cos(phi), r * std::sin(phi), z});
    }
    mx_ball* b = nullptr;
    return mx_ball_from_points3(xyz.data(), xyz.size(), &b) == MX_OK ? b : nullptr;
}

// CGAL's structures over one mesh, built in place (the tree and the side
// tester keep pointers to the mesh and the tree).
struct Cgal {
    Mesh mesh;
    Tree tree;
    std::unique_ptr<Side> side;

    explicit Cgal(const Soup& s) {
        mesh.reserve(s.xyz.size() / 3, 3 * s.tri.size() / 6, s.tri.size() / 3);
        std::vector<Mesh::Vertex_index> v;
        v.reserve(s.xyz.size() / 3);
        for (size_t i = 0; i < s.xyz.size(); i += 3) v.push_back(mesh.add_vertex(Point(s.xyz[i], s.xyz[i + 1], s.xyz[i + 2])));
        for (size_t i = 0; i < s.tri.size(); i += 3) mesh.add_face(v[s.tri[i]], v[s.tri[i + 1]], v[s.tri[i + 2]]);
        tree.insert(faces(mesh).first, faces(mesh).second, mesh);
        tree.build();
        tree.accelerate_distance_queries();
        side = std::make_unique<Side>(tree);
    }
};

// f(i) for every i < n, on `threads` threads over contiguous shares.
template <typename F>
void parallel_for(size_t n, size_t threads, F f) {
    auto share = [&](size_t k) {
        for (size_t i = n * k / threads; i < n * (k + 1) / threads; ++i) f(i);
    };
    std::vector<std::thread> pool;
    for (size_t k = 1; k < threads; ++k) pool.emplace_back(share, k);
    share(0);
    for (std::thread& t : pool) t.join();
}

Point point_at(const std::vector<double>& xyz, size_t i) { return Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); }

[[noreturn]] void fail(const std::string& what) {
    std::cerr << "bench_mesh: " << what << "\n";
    std::exit(1);
}

mx_status query(const mx_mesh3d* m, const mx_ball* ball, const std::vector<double>& xyz,
                std::vector<mx_point_query3>& out) {
    out.resize(xyz.size() / 3);
    size_t count = 0;
    return mx_mesh3d_query_points(m, ball, xyz.data(), xyz.size(), out.data(), out.size(), &count);
}

// Aborts unless medax and CGAL agree on the first kCheck points.
void sanity(const Cgal& cg, const std::vector<double>& xyz, const std::vector<mx_point_query3>& mx, double diag,
            const char* family, size_t size) {
    for (size_t i = 0; i < std::min(kCheck, mx.size()); ++i) {
        const Point p = point_at(xyz, i);
        const double cgal = CGAL::to_double(CGAL::squared_distance(p, cg.tree.closest_point_and_primitive(p).first));
        const double mine = mx[i].distance * mx[i].distance;
        const double d = std::sqrt(std::max(cgal, mine));
        if (std::fabs(cgal - mine) > 1e-9 * cgal + 64 * DBL_EPSILON * d * diag)
            fail(std::string(family) + " points, " + std::to_string(size) + " triangles, point " + std::to_string(i) +
                 ": CGAL squared distance " + std::to_string(cgal) + ", medax " + std::to_string(mine));
        const CGAL::Bounded_side s = (*cg.side)(p);
        if (s != CGAL::ON_BOUNDARY && (s == CGAL::ON_BOUNDED_SIDE) != (mx[i].side == MX_INSIDE))
            fail(std::string(family) + " points, " + std::to_string(size) + " triangles, point " + std::to_string(i) +
                 ": CGAL and medax disagree on the side");
    }
}

double seconds(size_t runs, const std::function<void()>& f) { return mt::median_times(runs, f, kCap).wall; }

}  // namespace

int main(int argc, char** argv) {
    mt::BenchArgs args = mt::bench_args(argc, argv);
    if (argc <= 2) args.sizes = {10000, 100000, 1000000};
    const size_t runs = args.runs;
    const char* env = std::getenv("RAYON_NUM_THREADS");
    const size_t threads = env && std::atoi(env) > 0 ? static_cast<size_t>(std::atoi(env)) : 1;
    const size_t cgal_threads = kCgalThreads ? threads : 1;
    const bool header = !std::getenv("MEDAX_BENCH_ROWS_ONLY");

    mx_ball* tetra = nullptr;
    if (mx_ball_tetrahedron(&tetra) != MX_OK) fail("mx_ball_tetrahedron: " + mt::last_message());
    mx_ball* fib = fibonacci_ball();
    size_t facets = 0;
    if (!fib || mx_ball_facet_count(fib, &facets) != MX_OK) fail("the Fibonacci ball: " + mt::last_message());

    if (header) {
        std::cout << "bench_mesh: medax " << mx_version() << ", CGAL " << CGAL_VERSION_STR << "; median of " << runs
                  << " runs, seconds; " << kPoints << " points per family; tori of 2ab triangles, a = 2b; "
                  << "ball facets: tetrahedron 4, Fibonacci hull " << facets << "\n";
        if (!kCgalThreads) std::cout << "CGAL_HAS_THREADS is not defined: CGAL's queries run on one thread\n";
        std::cout << "\n| triangles | threads | points | medax build | CGAL build | medax closest+side | CGAL closest | "
                     "CGAL side | CGAL closest+side | CGAL / medax | whole CGAL / medax | inside | "
                     "medax tetra ball | medax 128-facet ball | ball / Euclidean (tetra, 128) |\n"
                  << "|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    }
    for (size_t size : args.sizes) {
        const size_t b = static_cast<size_t>(std::lround(std::sqrt(static_cast<double>(size / 4))));
        const Soup soup = torus(3.0, 1.0, 2 * b, b);
        const size_t tris = soup.tri.size() / 3;
        double diag = 0;
        for (int a = 0; a < 3; ++a) diag += (soup.hi[a] - soup.lo[a]) * (soup.hi[a] - soup.lo[a]);
        diag = std::sqrt(diag);

        mx_mesh3d* mesh = nullptr;
        mx_status st = MX_OK;
        const double mx_build = seconds(runs, [&] {
            mx_mesh3d_free(mesh);
            mesh = nullptr;
            st = mx_mesh3d_from_arrays(soup.xyz.data(), soup.xyz.size(), soup.tri.data(), soup.tri.size(), nullptr,
                                       &mesh);
        });
        if (st != MX_OK) fail("mx_mesh3d_from_arrays: " + mt::last_message());
        std::unique_ptr<Cgal> cg;
        const double cgal_build = seconds(runs, [&] {
            cg.reset();
            cg = std::make_unique<Cgal>(soup);
        });

        std::mt19937_64 rng(20261207 + size);
        const std::vector<double> near = near_points(soup, rng), box = box_points(soup, rng);
        const std::pair<const char*, const std::vector<double>*> families[] = {{"near", &near}, {"box", &box}};
        for (const auto& fam : families) {
            const char* family = fam.first;
            const std::vector<double>* xyz = fam.second;
            std::vector<mx_point_query3> out;
            const double mx_q = seconds(runs, [&] { st = query(mesh, nullptr, *xyz, out); });
            if (st != MX_OK) fail("mx_mesh3d_query_points: " + mt::last_message());
            sanity(*cg, *xyz, out, diag, family, tris);

            std::vector<double> d2(kPoints);
            std::vector<int> sides(kPoints);
            const double c_closest = seconds(runs, [&] {
                parallel_for(kPoints, cgal_threads, [&](size_t i) {
                    const Point p = point_at(*xyz, i);
                    d2[i] = CGAL::to_double(CGAL::squared_distance(p, cg->tree.closest_point_and_primitive(p).first));
                });
            });
            const double c_side = seconds(runs, [&] {
                parallel_for(kPoints, cgal_threads, [&](size_t i) { sides[i] = (*cg->side)(point_at(*xyz, i)); });
            });

            // The ball radius is given for inside points only: time those.
            std::vector<double> inside;
            for (size_t i = 0; i < out.size(); ++i)
                if (out[i].side == MX_INSIDE) inside.insert(inside.end(), xyz->begin() + 3 * i, xyz->begin() + 3 * i + 3);
            std::vector<mx_point_query3> in_out;
            const double eu_in = seconds(runs, [&] { st = query(mesh, nullptr, inside, in_out); });
            double ball_t[2];
            const mx_ball* balls[2] = {tetra, fib};
            for (int k = 0; k < 2; ++k) {
                ball_t[k] = seconds(runs, [&] { st = query(mesh, balls[k], inside, in_out); });
                if (st != MX_OK) fail("mx_mesh3d_query_points with a ball: " + mt::last_message());
                for (const mx_point_query3& q : in_out)
                    if (!q.has_ball || !(q.ball_radius > 0)) fail("an inside point without a ball radius");
            }
            const double c_sum = c_closest + c_side;
            std::cout << "| " << tris << " | " << threads << " | " << family << " | " << mt::cell(mx_build) << " | "
                      << mt::cell(cgal_build) << " | " << mt::cell(mx_q) << " | " << mt::cell(c_closest) << " | "
                      << mt::cell(c_side) << " | " << mt::cell(c_sum) << " | " << mt::ratio(c_sum, mx_q) << " | "
                      << mt::ratio(cgal_build + c_sum, mx_build + mx_q) << " | " << inside.size() / 3 << " | "
                      << mt::cell(ball_t[0]) << " | " << mt::cell(ball_t[1]) << " | " << mt::ratio(ball_t[0], eu_in)
                      << ", " << mt::ratio(ball_t[1], eu_in) << " |" << std::endl;
        }
        mx_mesh3d_free(mesh);
    }
    mx_ball_free(tetra);
    mx_ball_free(fib);
    return 0;
}
