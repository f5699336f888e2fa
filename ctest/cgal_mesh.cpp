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
//
// Rays and intersection tests on the same meshes (compare_queries):
// 10^4 random rays (origins in the grown box, isotropic directions),
// mx_mesh3d_first_hits against tree.first_intersection: hit or miss
// agree and the points (and parameters) agree to 1e-9 of the diagonal,
// except where the ray grazes the boundary of the triangle the nearer
// answer lies on (see GRAZE below); 10^3 random segments, triangles and
// boxes, a third of them touching the surface at a mesh vertex or one
// ulp away from it: mx_mesh3d_intersects_* against tree.do_intersect,
// exactly (Epick's do_intersect predicates are exact, as medax's are).

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

#include <algorithm>
#include <array>
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

using Ray = K::Ray_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;
using Vector = K::Vector_3;

Triangle face_triangle(const Mesh& mesh, size_t i) {
    const auto h = mesh.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(i)));
    return Triangle(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                    mesh.point(mesh.target(mesh.next(h))));
}

// Grazing tolerance, as a fraction of the diagonal. medax decides a ray
// against a triangle in f64 (Moller-Trumbore): the sign of a barycentric
// coordinate is the sign of det(d, e, o - a) = |d| |e| sin(phi) * delta,
// delta the distance from the ray to the line of edge e at angle phi,
// computed with an error below 5 eps |d| |e| |o - a|. So medax can only
// be wrong about a triangle the ray passes within 5 eps |o - a| / sin(phi)
// (about 2.2e-15 diagonal / sin(phi) here) of an edge of; CGAL decides each
// triangle exactly but prunes tree boxes by an f64 slab test without
// slack, so it too can only miss where the ray skims a box face, that is
// a triangle's extreme corner or edge. 1e-9 of the diagonal covers rays
// at more than 1e-6 rad to the edge, which a random direction misses with
// probability about 1e-12: in practice no ray grazes at all.
constexpr double GRAZE = 1e-9;

// The ray meets triangle `t` within `tol` of its boundary.
bool grazes(const Ray& ray, const Triangle& t, double tol) {
    for (int i = 0; i < 3; ++i)
        if (CGAL::squared_distance(ray, Segment(t.vertex(i), t.vertex((i + 1) % 3))) <= tol * tol) return true;
    return false;
}

// Rays, segments, triangles and boxes: medax (C API) against CGAL's tree
// on the same surface; returns the number of disagreements.
size_t compare_queries(const mx_mesh3d* m, const Mesh& mesh, const Tree& tree, const mx_mesh3d_info& info,
                       std::mt19937_64& rng, const std::string& path) {
    double diag = 0;
    for (int i = 0; i < 3; ++i) diag += (info.max[i] - info.min[i]) * (info.max[i] - info.min[i]);
    diag = std::sqrt(diag);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    auto in_box = [&] {
        std::array<double, 3> p{};
        for (int a = 0; a < 3; ++a) {
            const double pad = 0.1 * (info.max[a] - info.min[a]);
            p[a] = uniform(info.min[a] - pad, info.max[a] + pad);
        }
        return p;
    };
    // The vertices as medax holds them, which must be CGAL's bit for bit.
    size_t nv = 0;
    MT_CHECK_OK(mx_mesh3d_vertices(m, nullptr, 0, &nv));
    std::vector<double> v(3 * nv);
    MT_CHECK_OK(mx_mesh3d_vertices(m, v.data(), nv, &nv));
    size_t same = 0;
    for (auto vi : mesh.vertices()) {
        const Point& p = mesh.point(vi);
        const size_t i = vi.idx();
        same += i < nv && p.x() == v[3 * i] && p.y() == v[3 * i + 1] && p.z() == v[3 * i + 2];
    }
    MT_CHECK_EQ(same, nv);
    auto vertex = [&] {
        const size_t i = std::uniform_int_distribution<size_t>(0, nv - 1)(rng);
        return std::array<double, 3>{v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    };
    auto pt = [](const std::array<double, 3>& p) { return Point(p[0], p[1], p[2]); };

    // Rays.
    const int n_rays = 10000;
    std::vector<double> rays(6 * n_rays);
    std::normal_distribution<double> gauss;
    for (int i = 0; i < n_rays; ++i) {
        const auto o = in_box();
        for (int a = 0; a < 3; ++a) {
            rays[6 * i + a] = o[a];
            rays[6 * i + 3 + a] = gauss(rng);
        }
    }
    std::vector<mx_ray_hit3> hits(n_rays);
    size_t count = 0;
    MT_CHECK_OK(mx_mesh3d_first_hits(m, rays.data(), rays.size(), hits.data(), hits.size(), &count));
    size_t met = 0, wrong_rays = 0, grazing = 0, off_triangle = 0;
    double worst = 0;
    for (int i = 0; i < n_rays; ++i) {
        const double* r = &rays[6 * i];
        const Point o(r[0], r[1], r[2]);
        const Vector d(r[3], r[4], r[5]);
        const Ray ray(o, d);
        const auto c = tree.first_intersection(ray);
        const mx_ray_hit3& h = hits[i];
        bool cgal_hit = false;
        Point pc(0, 0, 0);
        size_t cgal_face = 0;
        if (c) {
            if (const Point* p = boost::get<Point>(&c->first)) {
                pc = *p;
            } else {
                // The ray along a triangle's plane: its first point.
                const Segment& s = boost::get<Segment>(c->first);
                pc = CGAL::squared_distance(o, s.source()) <= CGAL::squared_distance(o, s.target()) ? s.source()
                                                                                                      : s.target();
            }
            cgal_hit = true;
            cgal_face = c->second.idx();
        }
        const Point pm(h.point[0], h.point[1], h.point[2]);
        if (h.hit) {
            // medax's triangle id names CGAL's face: its point lies on it.
            off_triangle += CGAL::squared_distance(pm, face_triangle(mesh, h.triangle)) > 1e-18 * diag * diag;
        }
        bool agree = cgal_hit == (h.hit == 1);
        if (agree && cgal_hit) {
            ++met;
            const double dp = std::sqrt(CGAL::squared_distance(pm, pc));
            const double tc = (pc - o) * d / d.squared_length();
            const double dt = std::fabs(h.t - tc) * std::sqrt(d.squared_length());
            worst = std::max({worst, dp / diag, dt / diag});
            agree = dp <= 1e-9 * diag && dt <= 1e-9 * diag;
        }
        if (agree) continue;
        // The nearer answer's triangle must be one the ray grazes.
        const double tm = h.hit ? h.t : INFINITY;
        const double tc = cgal_hit ? (pc - o) * d / d.squared_length() : INFINITY;
        const size_t face = tm <= tc ? h.triangle : cgal_face;
        if (grazes(ray, face_triangle(mesh, face), GRAZE * diag)) {
            ++grazing;
            continue;
        }
        if (wrong_rays++ < 3)
            std::printf("    ray %d (%.17g %.17g %.17g; %.17g %.17g %.17g): CGAL %s (%.17g %.17g %.17g), medax %s t %.17g "
                        "(%.17g %.17g %.17g) triangle %zu\n",
                        i, r[0], r[1], r[2], r[3], r[4], r[5], cgal_hit ? "hit" : "miss", pc.x(), pc.y(), pc.z(),
                        h.hit ? "hit" : "miss", h.t, h.point[0], h.point[1], h.point[2], h.triangle);
    }

    // Segments, triangles and boxes: random, short ones (2 % to 30 % of
    // the diagonal), and a third built on a mesh vertex: through it, or
    // with a face on it, or one ulp past it.
    const int n_tests = 1000;
    auto near_to = [&](const std::array<double, 3>& a) {
        const double s = diag * uniform(0.02, 0.3);
        std::array<double, 3> p{};
        for (int k = 0; k < 3; ++k) p[k] = a[k] + s * gauss(rng) / std::sqrt(3.0);
        return p;
    };
    size_t wrong_tests[3] = {0, 0, 0}, touching[3] = {0, 0, 0};
    for (int i = 0; i < n_tests; ++i) {
        const bool on_vertex = i % 3 == 0;
        auto a = on_vertex ? vertex() : in_box();
        // Half of those start one ulp off the vertex.
        if (on_vertex && i % 2) a[i % 3] = std::nextafter(a[i % 3], i % 4 == 1 ? INFINITY : -INFINITY);
        // Segment.
        {
            const auto b = near_to(a);
            int32_t mine = -1;
            MT_CHECK_OK(mx_mesh3d_intersects_segment(m, a.data(), b.data(), &mine));
            const bool cgal = tree.do_intersect(Segment(pt(a), pt(b)));
            wrong_tests[0] += cgal != (mine == 1);
            touching[0] += cgal;
        }
        // Triangle (CGAL wants it non-degenerate).
        {
            const auto b = near_to(a), c = near_to(a);
            if (!CGAL::collinear(pt(a), pt(b), pt(c))) {
                const double xyz9[9] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
                int32_t mine = -1;
                MT_CHECK_OK(mx_mesh3d_intersects_triangle(m, xyz9, &mine));
                const bool cgal = tree.do_intersect(Triangle(pt(a), pt(b), pt(c)));
                wrong_tests[1] += cgal != (mine == 1);
                touching[1] += cgal;
            }
        }
        // Box: around a point, or with its low x face on a vertex (or one
        // ulp beyond it), reaching away from it.
        {
            std::array<double, 3> lo{}, hi{};
            for (int k = 0; k < 3; ++k) {
                const double s = diag * uniform(0.01, 0.15);
                lo[k] = a[k] - s * uniform(0, 1);
                hi[k] = a[k] + s * uniform(0, 1);
            }
            if (on_vertex) {
                lo[0] = i % 2 ? a[0] : std::nextafter(a[0], INFINITY);
                hi[0] = lo[0] + diag * uniform(0.01, 0.15);
            }
            int32_t mine = -1;
            MT_CHECK_OK(mx_mesh3d_intersects_box(m, lo.data(), hi.data(), &mine));
            const bool cgal = tree.do_intersect(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]));
            if (cgal != (mine == 1) && wrong_tests[2] < 3)
                std::printf("    box (%.17g %.17g %.17g) (%.17g %.17g %.17g): CGAL %d, medax %d\n", lo[0], lo[1],
                            lo[2], hi[0], hi[1], hi[2], cgal, mine);
            wrong_tests[2] += cgal != (mine == 1);
            touching[2] += cgal;
        }
    }
    std::printf("  %s: %d rays (%zu hits, %zu grazing, largest difference %.3g diagonal): %zu disagree, %zu hits off "
                "their triangle; segments, triangles, boxes meeting %zu, %zu, %zu of %d: %zu, %zu, %zu disagree\n",
                path.c_str(), n_rays, met, grazing, worst, wrong_rays, off_triangle, touching[0], touching[1],
                touching[2], n_tests, wrong_tests[0], wrong_tests[1], wrong_tests[2]);
    MT_CHECK_EQ(off_triangle, size_t{0});
    return wrong_rays + wrong_tests[0] + wrong_tests[1] + wrong_tests[2];
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
    MT_CHECK_EQ(compare_queries(m, mesh, tree, info, rng, path), size_t{0});
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
