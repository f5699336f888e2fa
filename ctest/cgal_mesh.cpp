// Cross-checks medax's solids against CGAL 5.5 on the same meshes:
// closest points (AABB_tree with AABB_face_graph_triangle_primitive and
// accelerate_distance_queries), inside/outside
// (Side_of_triangle_mesh), and self-intersections
// (Polygon_mesh_processing::does_self_intersect).
//
// Meshes: generated tori and a box with a cavity (written here as OFF),
// and CGAL's own closed sample meshes when Debian's libcgal-demo data are
// unpacked (the first argument: a directory of .off files; the ones medax
// accepts as solids are used, the ones it refuses must be ones CGAL calls
// not closed or self-intersecting). For each mesh, 10^4 random points in
// its box grown by 10 %: squared distances agree to 1e-12 relative (plus
// 64 ε · d · diagonal: both round the closest point before squaring the
// difference, which near the surface is all the difference), sides agree
// wherever CGAL says inside or outside. Two interpenetrating boxes and a box with a corner
// pushed through: medax says MX_ERR_INTERSECTION, CGAL says
// does_self_intersect.

#include "test_support.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <medax.h>

#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

struct Soup {
    std::vector<double> xyz;
    std::vector<uint32_t> tri;
};

Soup torus(double big, double small, int n, int m, double shift = 0) {
    Soup s;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = 2 * M_PI * i / n, w = 2 * M_PI * j / m, r = big + small * std::cos(w);
            s.xyz.insert(s.xyz.end(), {r * std::cos(u) + shift, r * std::sin(u), small * std::sin(w)});
        }
    auto id = [&](int i, int j) { return static_cast<uint32_t>((i % n) * m + (j % m)); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            s.tri.insert(s.tri.end(), {a, b, c, a, c, d});
        }
    return s;
}

Soup box(double lo, double hi, bool inward = false) {
    Soup s;
    for (int i = 0; i < 8; ++i) s.xyz.insert(s.xyz.end(), {i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
    const uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : q) {
        if (inward)
            s.tri.insert(s.tri.end(), {f[0], f[2], f[1], f[0], f[3], f[2]});
        else
            s.tri.insert(s.tri.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    }
    return s;
}

Soup join(const Soup& a, const Soup& b) {
    Soup s = a;
    const uint32_t base = static_cast<uint32_t>(a.xyz.size() / 3);
    s.xyz.insert(s.xyz.end(), b.xyz.begin(), b.xyz.end());
    for (uint32_t v : b.tri) s.tri.push_back(v + base);
    return s;
}

std::string write_off(const Soup& s, const std::string& name) {
    const std::string path = (std::filesystem::temp_directory_path() / ("medax-cgal-mesh-" + name + ".off")).string();
    std::ofstream f(path);
    f.precision(17);
    f << "OFF\n" << s.xyz.size() / 3 << " " << s.tri.size() / 3 << " 0\n";
    for (size_t i = 0; i < s.xyz.size(); i += 3) f << s.xyz[i] << " " << s.xyz[i + 1] << " " << s.xyz[i + 2] << "\n";
    for (size_t i = 0; i < s.tri.size(); i += 3) f << "3 " << s.tri[i] << " " << s.tri[i + 1] << " " << s.tri[i + 2] << "\n";
    return path;
}

// Compares medax and CGAL on the solid in `path`; returns false when medax
// refused it (then CGAL must call it not closed or self-intersecting).
bool compare(const std::string& path, unsigned seed) {
    Mesh mesh;
    if (!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty()) {
        std::printf("  %s: CGAL cannot read it, skipped\n", path.c_str());
        return false;
    }
    mx_mesh3d* m = nullptr;
    const mx_status st = mx_mesh3d_from_file(path.c_str(), MX_FORMAT_AUTO, nullptr, &m);
    if (st != MX_OK) {
        CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
        const bool bad = !CGAL::is_closed(mesh) || CGAL::Polygon_mesh_processing::does_self_intersect(mesh) ||
                         !CGAL::is_valid_polygon_mesh(mesh);
        if (!bad) {
            char msg[512];
            mx_last_error_message(msg, sizeof msg);
            std::printf("  %s: medax refused a closed mesh without self-intersections: %s\n", path.c_str(), msg);
        }
        MT_CHECK(bad || st == MX_ERR_NOT_MANIFOLD || st == MX_ERR_DEGENERATE);
        return false;
    }
    // CGAL reads the triangles medax made (welded, polygons cut by its
    // own diagonals), so that both answer about the same surface: two
    // triangulations of a non-planar quad are two different surfaces.
    const std::string same = path + ".medax.off";
    MT_CHECK_OK(mx_mesh3d_write(m, same.c_str(), MX_FORMAT_OFF));
    mesh.clear();
    MT_CHECK(CGAL::IO::read_polygon_mesh(same, mesh));
    std::filesystem::remove(same);
    if (CGAL::Polygon_mesh_processing::does_self_intersect(mesh)) {
        std::printf("  %s: CGAL finds a self-intersection medax does not\n", path.c_str());
        MT_CHECK(false);
    }
    Tree tree(faces(mesh).first, faces(mesh).second, mesh);
    tree.accelerate_distance_queries();
    CGAL::Side_of_triangle_mesh<Mesh, K> side(mesh);
    mx_mesh3d_info info{};
    MT_CHECK_OK(mx_mesh3d_get_info(m, &info));
    double diag2 = 0;
    for (int i = 0; i < 3; ++i) diag2 += (info.max[i] - info.min[i]) * (info.max[i] - info.min[i]);
    std::mt19937_64 rng(seed);
    const int n = 10000;
    std::vector<double> xyz(3 * n);
    for (int i = 0; i < 3 * n; ++i) {
        const int a = i % 3;
        const double pad = 0.1 * (info.max[a] - info.min[a]);
        xyz[i] = std::uniform_real_distribution<double>(info.min[a] - pad, info.max[a] + pad)(rng);
    }
    std::vector<mx_point_query3> out(n);
    size_t count = 0;
    MT_CHECK_OK(mx_mesh3d_query_points(m, nullptr, xyz.data(), xyz.size(), out.data(), out.size(), &count));
    size_t far = 0, sides = 0, sides_checked = 0;
    for (int i = 0; i < n; ++i) {
        const Point p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        const double cgal = tree.squared_distance(p);
        const double mine = out[i].distance * out[i].distance;
        // Both round the closest point's coordinates (size ~ the diagonal)
        // before squaring the difference: near the surface that costs
        // about eps · d · diagonal in d², whatever the relative 1e-12.
        const double d = std::sqrt(std::max(cgal, mine));
        if (std::fabs(cgal - mine) > 1e-12 * cgal + 64 * DBL_EPSILON * d * std::sqrt(diag2)) {
            if (far < 3)
                std::printf("    point %d: CGAL %.17g, medax %.17g (relative %.3g)\n", i, cgal, mine,
                            (mine - cgal) / cgal);
            ++far;
        }
        const CGAL::Bounded_side s = side(p);
        if (s == CGAL::ON_BOUNDARY) continue;
        ++sides_checked;
        const bool in = s == CGAL::ON_BOUNDED_SIDE;
        if (in != (out[i].side == MX_INSIDE)) ++sides;
    }
    std::printf("  %s: %zu triangles, %d points: %zu distances and %zu of %zu sides disagree\n", path.c_str(),
                info.triangle_count, n, far, sides, sides_checked);
    MT_CHECK_EQ(far, size_t{0});
    MT_CHECK_EQ(sides, size_t{0});
    mx_mesh3d_free(m);
    return true;
}

void generated() {
    mt::begin_case("generated solids vs CGAL");
    MT_CHECK(compare(write_off(torus(3, 1, 120, 60), "torus"), 1));
    MT_CHECK(compare(write_off(join(box(0, 10), box(3, 7, true)), "cavity"), 2));
    MT_CHECK(compare(write_off(join(torus(3, 1.2, 40, 24, 0), torus(3, 1.2, 40, 24, 10)), "two-tori"), 3));
}

void crossings() {
    mt::begin_case("self-intersections vs does_self_intersect");
    const Soup crossing[] = {join(box(0, 2), box(1, 3)), join(torus(3, 1, 24, 12, -3), box(-1.5, 1.5))};
    int k = 0;
    for (const Soup& s : crossing) {
        const std::string path = write_off(s, "crossing" + std::to_string(k++));
        mx_mesh3d* m = nullptr;
        MT_CHECK_EQ(mx_mesh3d_from_file(path.c_str(), MX_FORMAT_AUTO, nullptr, &m), MX_ERR_INTERSECTION);
        Mesh mesh;
        MT_CHECK(CGAL::IO::read_polygon_mesh(path, mesh));
        MT_CHECK(CGAL::Polygon_mesh_processing::does_self_intersect(mesh));
    }
}

void cgal_samples(const char* dir) {
    mt::begin_case("CGAL sample meshes");
    if (!dir || !std::filesystem::is_directory(dir)) {
        std::printf("  no sample directory given: skipped\n");
        return;
    }
    size_t solids = 0, refused = 0;
    unsigned seed = 10;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        if (e.path().extension() != ".off" || std::filesystem::file_size(e.path()) > (20u << 20)) continue;
        (compare(e.path().string(), seed++) ? solids : refused)++;
    }
    std::printf("  %zu solids compared, %zu meshes refused by medax\n", solids, refused);
    MT_CHECK(solids >= 10);
}

}  // namespace

int main(int argc, char** argv) {
    generated();
    crossings();
    cgal_samples(argc > 1 ? argv[1] : nullptr);
    return mt::finish("cgal_mesh");
}
