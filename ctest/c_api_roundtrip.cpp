// Round trip through the medax C API: build shapes from bulge loops, from
// explicit elements, from strings and files; read everything back and
// compare with values computed independently here (closed-form areas, an
// independent bulge-area formula, bounding boxes and joint kinds worked out
// by hand). Also: options, version, status strings, SVG output, and
// concurrent queries of one const handle from four threads.
//
// Usage: c_api_roundtrip [iterations-per-thread]   (default 20000)

#include "test_support.hpp"

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// Independent geometry, written from the definitions in medax.h rather than
// from the library's code: bulge = tan(sweep / 4), positive counter-clockwise.

// Signed area of a closed bulge loop: shoelace over the chords plus, for each
// arc, the signed area of the circular segment between arc and chord.
double bulge_loop_signed_area(const std::vector<double>& xyb) {
    const size_t n = xyb.size() / 3;
    double area = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double x0 = xyb[3 * i], y0 = xyb[3 * i + 1], b = xyb[3 * i + 2];
        const double x1 = xyb[3 * ((i + 1) % n)], y1 = xyb[3 * ((i + 1) % n) + 1];
        area += 0.5 * (x0 * y1 - x1 * y0);
        if (b != 0.0) {
            const double chord = std::hypot(x1 - x0, y1 - y0);
            const double theta = 4.0 * std::atan(b);         // signed sweep
            const double r = chord / (2.0 * std::sin(theta / 2.0));
            area += 0.5 * r * r * (theta - std::sin(theta));  // sign follows theta
        }
    }
    return area;
}

std::string temp_path(const std::string& name) {
    return (fs::temp_directory_path() / ("medax_ctest_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

mt::ShapePtr make(const std::vector<std::vector<double>>& loops, const mx_shape_options* opts = nullptr) {
    mx_shape2d* s = nullptr;
    MT_CHECK_OK(mt::from_loops(loops, &s, opts));
    return mt::ShapePtr(s);
}

// Everything a reader can learn about a shape, for comparisons.
struct Snapshot {
    size_t loops = 0;
    std::vector<std::vector<double>> vertices;
    std::vector<std::vector<mx_element>> elements;
    std::vector<std::vector<uint32_t>> joints;
    std::vector<int32_t> reversed;
    mx_bbox bbox{};
    double area = 0.0;
    double tolerance = 0.0;
};

bool same_element(const mx_element& a, const mx_element& b) {
    return a.kind == b.kind && a.ccw == b.ccw && a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 &&
           a.y1 == b.y1 && a.cx == b.cx && a.cy == b.cy && a.radius == b.radius && a.bulge == b.bulge;
}

bool operator==(const Snapshot& a, const Snapshot& b) {
    if (a.loops != b.loops || a.vertices != b.vertices || a.joints != b.joints || a.reversed != b.reversed ||
        a.area != b.area || a.tolerance != b.tolerance)
        return false;
    if (std::memcmp(&a.bbox, &b.bbox, sizeof a.bbox) != 0) return false;
    for (size_t l = 0; l < a.elements.size(); ++l) {
        if (a.elements[l].size() != b.elements[l].size()) return false;
        for (size_t k = 0; k < a.elements[l].size(); ++k)
            if (!same_element(a.elements[l][k], b.elements[l][k])) return false;
    }
    return true;
}

// Reads a snapshot; returns false (without recording) on any failing call so
// that it can be used from worker threads.
bool snapshot(const mx_shape2d* s, Snapshot& out) {
    Snapshot snap;
    if (mx_shape2d_loop_count(s, &snap.loops) != MX_OK) return false;
    for (size_t l = 0; l < snap.loops; ++l) {
        size_t n = 0;
        int32_t rev = 0;
        if (mx_shape2d_loop_size(s, l, &n) != MX_OK || mx_shape2d_loop_reversed(s, l, &rev) != MX_OK)
            return false;
        std::vector<double> v(3 * n);
        size_t written = 0;
        if (mx_shape2d_loop_vertices(s, l, v.data(), n, &written) != MX_OK || written != n) return false;
        std::vector<mx_element> es(n);
        std::vector<uint32_t> js(n);
        for (size_t k = 0; k < n; ++k) {
            mx_joint_kind j = MX_JOINT_SMOOTH;
            if (mx_shape2d_element(s, l, k, &es[k]) != MX_OK || mx_shape2d_joint(s, l, k, &j) != MX_OK) return false;
            js[k] = j;
        }
        snap.vertices.push_back(std::move(v));
        snap.elements.push_back(std::move(es));
        snap.joints.push_back(std::move(js));
        snap.reversed.push_back(rev);
    }
    if (mx_shape2d_bbox(s, &snap.bbox) != MX_OK || mx_shape2d_area(s, &snap.area) != MX_OK ||
        mx_shape2d_tolerance(s, &snap.tolerance) != MX_OK)
        return false;
    out = std::move(snap);
    return true;
}

void check_bbox(const mx_shape2d* s, double xmin, double ymin, double xmax, double ymax, double rel = 1e-12) {
    mx_bbox b{};
    MT_CHECK_OK(mx_shape2d_bbox(s, &b));
    MT_CHECK_NEAR(b.xmin, xmin, rel);
    MT_CHECK_NEAR(b.ymin, ymin, rel);
    MT_CHECK_NEAR(b.xmax, xmax, rel);
    MT_CHECK_NEAR(b.ymax, ymax, rel);
}

double area_of(const mx_shape2d* s) {
    double a = -1.0;
    MT_CHECK_OK(mx_shape2d_area(s, &a));
    return a;
}

size_t loop_count(const mx_shape2d* s) {
    size_t n = 0;
    MT_CHECK_OK(mx_shape2d_loop_count(s, &n));
    return n;
}

std::vector<uint32_t> joints_of(const mx_shape2d* s, size_t loop) {
    size_t n = 0;
    MT_CHECK_OK(mx_shape2d_loop_size(s, loop, &n));
    std::vector<uint32_t> js(n, 99);
    for (size_t k = 0; k < n; ++k) {
        mx_joint_kind j = MX_JOINT_SMOOTH;
        if (MT_CHECK_OK(mx_shape2d_joint(s, loop, k, &j))) js[k] = j;
    }
    return js;
}

mx_element element_of(const mx_shape2d* s, size_t loop, size_t k) {
    mx_element e{};
    MT_CHECK_OK(mx_shape2d_element(s, loop, k, &e));
    return e;
}

int32_t reversed_of(const mx_shape2d* s, size_t loop) {
    int32_t r = 99;
    MT_CHECK_OK(mx_shape2d_loop_reversed(s, loop, &r));
    return r;
}

// ---------------------------------------------------------------------------

void test_options() {
    mt::begin_case("options");
    mx_shape_options o;
    std::memset(&o, 0xAB, sizeof o);
    MT_CHECK_OK(mx_shape_options_init(&o, sizeof o));
    MT_CHECK_EQ(o.struct_size, sizeof(mx_shape_options));
    MT_CHECK_EQ(o.tolerance, 0.0);
    MT_CHECK_EQ(o.relative_tolerance, 1e-9);
    MT_CHECK_EQ(o.angle_tolerance, 1e-6);
    MT_CHECK(o.flatten_sagitta < 0.0);
    MT_CHECK_EQ(o.chain_tolerance, 0.0);

    // Defaults passed explicitly give the same shape as options == NULL.
    const std::vector<std::vector<double>> square = {{0, 0, 0, 3, 0, 0, 3, 3, 0, 0, 3, 0}};
    auto a = make(square);
    auto b = make(square, &o);
    Snapshot sa, sb;
    MT_CHECK(snapshot(a.get(), sa) && snapshot(b.get(), sb) && sa == sb);

    // A caller compiled against an older, smaller struct is refused.
    mx_shape_options small = o;
    small.struct_size = offsetof(mx_shape_options, max_radius_ratio);
    mx_shape2d* out = mt::sentinel_shape();
    MT_CHECK_STATUS(mt::from_loops(square, &out, &small), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK(out == mt::sentinel_shape());
    small.struct_size = 0;
    MT_CHECK_STATUS(mt::from_loops(square, &out, &small), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK(out == mt::sentinel_shape());
    // A caller of 0.1.0, whose struct ends before `threads`, gets all cores.
    mx_shape_options v010 = o;
    v010.struct_size = offsetof(mx_shape_options, threads);
    v010.threads = 1u << 20;  // not read
    MT_CHECK(make(square, &v010) != nullptr);
    // Checked on one thread: the same shape.
    mx_shape_options one = o;
    one.threads = 1;
    auto on_one = make(square, &one);
    Snapshot s1;
    MT_CHECK(on_one != nullptr && snapshot(on_one.get(), s1) && s1 == sa);
    // A larger struct_size (a newer caller) is fine.
    mx_shape_options bigger = o;
    bigger.struct_size = sizeof(mx_shape_options) + 64;
    auto c = make(square, &bigger);
    MT_CHECK(c != nullptr);

    // Tolerance: default = relative_tolerance x diagonal of the vertices' box.
    double tol = 0.0;
    MT_CHECK_OK(mx_shape2d_tolerance(a.get(), &tol));
    MT_CHECK_NEAR(tol, 1e-9 * std::hypot(3.0, 3.0), 1e-12);
    mx_shape_options abs_tol = o;
    abs_tol.tolerance = 1e-4;
    auto d = make(square, &abs_tol);
    MT_CHECK_OK(mx_shape2d_tolerance(d.get(), &tol));
    MT_CHECK_EQ(tol, 1e-4);
    mx_shape_options rel_tol = o;
    rel_tol.relative_tolerance = 1e-7;
    auto e = make(square, &rel_tol);
    MT_CHECK_OK(mx_shape2d_tolerance(e.get(), &tol));
    MT_CHECK_NEAR(tol, 1e-7 * std::hypot(3.0, 3.0), 1e-12);

    // flatten_sagitta: an arc whose sagitta (b * chord / 2 = 2e-12) is below
    // the default bound (the touching tolerance) is stored as a segment; with
    // flatten_sagitta = 0, and the radius bound (radius 1e12 here) lifted, it
    // stays an arc.
    const std::vector<std::vector<double>> flat = {{0, 0, 1e-12, 4, 0, 0, 4, 2, 0, 0, 2, 0}};
    auto f = make(flat);
    MT_CHECK_EQ(element_of(f.get(), 0, 0).kind, static_cast<uint32_t>(MX_ELEMENT_SEGMENT));
    mx_shape_options keep = o;
    keep.flatten_sagitta = 0.0;
    keep.max_radius_ratio = 1e15;
    auto g = make(flat, &keep);
    const mx_element ge = element_of(g.get(), 0, 0);
    MT_CHECK_EQ(ge.kind, static_cast<uint32_t>(MX_ELEMENT_ARC));
    MT_CHECK(std::fabs(ge.bulge / 1e-12 - 1.0) < 1e-9);
}

void test_version() {
    mt::begin_case("version");
    const std::string expected = std::to_string(MEDAX_VERSION_MAJOR) + "." + std::to_string(MEDAX_VERSION_MINOR) +
                                 "." + std::to_string(MEDAX_VERSION_PATCH);
    const char* v = mx_version();
    MT_CHECK(v != nullptr);
    MT_CHECK_EQ(std::string(v ? v : ""), expected);
    MT_CHECK_EQ(mx_version_number(),
                static_cast<uint32_t>(MEDAX_VERSION_MAJOR * 10000 + MEDAX_VERSION_MINOR * 100 + MEDAX_VERSION_PATCH));
#ifdef MEDAX_PACKAGE_VERSION
    // The version find_package(medax) saw (medaxConfigVersion.cmake) is the
    // version of the library that gets loaded.
    MT_CHECK_EQ(std::string(v ? v : ""), std::string(MEDAX_PACKAGE_VERSION));
#endif
}

void test_status_strings() {
    mt::begin_case("mx_status_str");
    const mx_status all[] = {MX_OK,
                             MX_ERR_NULL_ARGUMENT,
                             MX_ERR_INVALID_ARGUMENT,
                             MX_ERR_BUFFER_TOO_SMALL,
                             MX_ERR_IO,
                             MX_ERR_PARSE,
                             MX_ERR_UNSUPPORTED,
                             MX_ERR_INDEX_OUT_OF_RANGE,
                             MX_ERR_CANCELLED,
                             MX_ERR_NUMERICAL,
                             MX_ERR_EMPTY,
                             MX_ERR_TOO_FEW_ELEMENTS,
                             MX_ERR_NON_FINITE,
                             MX_ERR_OUT_OF_RANGE,
                             MX_ERR_NOT_CLOSED,
                             MX_ERR_DEGENERATE,
                             MX_ERR_INTERSECTION,
                             MX_ERR_HOLE_OUTSIDE,
                             MX_ERR_HOLE_INSIDE_HOLE,
                             MX_ERR_INCONSISTENT_ARC,
                             MX_ERR_INVALID_BALL,
                             MX_ERR_NOT_MANIFOLD,
                             MX_ERR_PANIC};
    std::set<std::string> seen;
    for (mx_status s : all) {
        const char* text = mx_status_str(static_cast<int32_t>(s));
        MT_CHECK(text != nullptr);
        if (!text) continue;
        MT_CHECK(std::strlen(text) > 0);
        MT_CHECK(std::string(text) != "unknown status");
        MT_CHECK(seen.insert(text).second);  // distinct descriptions
    }
    for (int32_t unknown : {-1, 22, 42, 98, 100, 1 << 30}) {
        const char* text = mx_status_str(unknown);
        MT_CHECK_EQ(std::string(text ? text : "NULL"), std::string("unknown status"));
    }
    // Stable values (part of the ABI).
    MT_CHECK_EQ(static_cast<int>(MX_OK), 0);
    MT_CHECK_EQ(static_cast<int>(MX_ERR_CANCELLED), 8);
    MT_CHECK_EQ(static_cast<int>(MX_ERR_NUMERICAL), 9);
    MT_CHECK_EQ(static_cast<int>(MX_ERR_EMPTY), 10);
    MT_CHECK_EQ(static_cast<int>(MX_ERR_INCONSISTENT_ARC), 19);
    MT_CHECK_EQ(static_cast<int>(MX_ERR_PANIC), 99);
}

// A w x h rectangle whose right side is a half circle bulging outwards:
// area = w h + pi r^2 / 2 with r = h / 2.
void test_rectangle_with_half_circle() {
    mt::begin_case("rectangle with half-circle side (bulges)");
    const double w = 4.0, h = 2.0, r = h / 2.0;
    const std::vector<double> input = {0, 0, 0, w, 0, 1, w, h, 0, 0, h, 0};
    auto s = make({input});
    if (!s) return;
    MT_CHECK_EQ(loop_count(s.get()), size_t{1});
    MT_CHECK_EQ(reversed_of(s.get(), 0), 0);
    MT_CHECK_NEAR(area_of(s.get()), w * h + kPi * r * r / 2.0, 1e-14);
    MT_CHECK_NEAR(area_of(s.get()), bulge_loop_signed_area(input), 1e-14);
    check_bbox(s.get(), 0.0, 0.0, w + r, h);

    // Vertices come back exactly as given (already counter-clockwise).
    const std::vector<double> back = mt::loop_vertices(s.get(), 0);
    MT_CHECK_EQ(back.size(), input.size());
    for (size_t i = 0; i < input.size() && i < back.size(); ++i) MT_CHECK_NEAR(back[i], input[i], 1e-15);

    // Elements: three segments and the arc around (w, h/2).
    const mx_element e0 = element_of(s.get(), 0, 0);
    MT_CHECK_EQ(e0.kind, static_cast<uint32_t>(MX_ELEMENT_SEGMENT));
    MT_CHECK_EQ(e0.ccw, 0);
    MT_CHECK_EQ(e0.x0, 0.0);
    MT_CHECK_EQ(e0.y0, 0.0);
    MT_CHECK_EQ(e0.x1, w);
    MT_CHECK_EQ(e0.y1, 0.0);
    MT_CHECK_EQ(e0.radius, 0.0);
    MT_CHECK_EQ(e0.bulge, 0.0);
    const mx_element e1 = element_of(s.get(), 0, 1);
    MT_CHECK_EQ(e1.kind, static_cast<uint32_t>(MX_ELEMENT_ARC));
    MT_CHECK_EQ(e1.ccw, 1);
    MT_CHECK_EQ(e1.x0, w);
    MT_CHECK_EQ(e1.y0, 0.0);
    MT_CHECK_EQ(e1.x1, w);
    MT_CHECK_EQ(e1.y1, h);
    MT_CHECK_NEAR(e1.cx, w, 1e-14);
    MT_CHECK_NEAR(e1.cy, h / 2.0, 1e-14);
    MT_CHECK_NEAR(e1.radius, r, 1e-14);
    MT_CHECK_NEAR(e1.bulge, 1.0, 1e-14);
    const mx_element e3 = element_of(s.get(), 0, 3);
    MT_CHECK_EQ(e3.x0, 0.0);
    MT_CHECK_EQ(e3.y0, h);
    MT_CHECK_EQ(e3.x1, 0.0);
    MT_CHECK_EQ(e3.y1, 0.0);

    // Joints: the half circle meets both horizontal sides tangentially.
    const std::vector<uint32_t> expect = {MX_JOINT_CONVEX, MX_JOINT_SMOOTH, MX_JOINT_SMOOTH, MX_JOINT_CONVEX};
    MT_CHECK(joints_of(s.get(), 0) == expect);

    // A buffer larger than needed (capacity in vertices): only 3n doubles
    // are written.
    std::vector<double> big(3 * 4 + 5, -7.0);
    size_t written = 0;
    MT_CHECK_OK(mx_shape2d_loop_vertices(s.get(), 0, big.data(), big.size() / 3, &written));
    MT_CHECK_EQ(written, size_t{4});
    for (size_t i = 12; i < big.size(); ++i) MT_CHECK_EQ(big[i], -7.0);

    // A closing vertex that repeats the first is dropped.
    std::vector<double> closed = input;
    closed.insert(closed.end(), {0, 0, 0});
    auto c = make({closed});
    size_t n = 0;
    MT_CHECK_OK(mx_shape2d_loop_size(c.get(), 0, &n));
    MT_CHECK_EQ(n, size_t{4});
    MT_CHECK_NEAR(area_of(c.get()), area_of(s.get()), 1e-15);

    mt::begin_case("rectangle with half-circle side (elements)");
    mx_element es[4] = {};
    es[0].kind = MX_ELEMENT_SEGMENT;
    es[0].x1 = w;
    es[1].kind = MX_ELEMENT_ARC;
    es[1].ccw = 1;
    es[1].x0 = w;
    es[1].x1 = w;
    es[1].y1 = h;
    es[1].cx = w;
    es[1].cy = h / 2.0;
    es[1].radius = 12345.0;  // ignored on input
    es[1].bulge = -3.0;      // ignored on input
    es[2].kind = MX_ELEMENT_SEGMENT;
    es[2].x0 = w;
    es[2].y0 = h;
    es[2].y1 = h;
    es[3].kind = MX_ELEMENT_SEGMENT;
    es[3].y0 = h;
    const size_t lens[1] = {4};
    mx_shape2d* raw = nullptr;
    MT_CHECK_OK(mx_shape2d_from_elements(es, 4, lens, 1, nullptr, &raw));
    mt::ShapePtr fe(raw);
    if (!fe) return;
    MT_CHECK_NEAR(area_of(fe.get()), w * h + kPi * r * r / 2.0, 1e-14);
    check_bbox(fe.get(), 0.0, 0.0, w + r, h);
    const std::vector<double> fev = mt::loop_vertices(fe.get(), 0);
    MT_CHECK_EQ(fev.size(), input.size());
    for (size_t i = 0; i < input.size() && i < fev.size(); ++i) MT_CHECK_NEAR(fev[i], input[i], 1e-14);
    MT_CHECK(joints_of(fe.get(), 0) == expect);
}

// A circle of radius R around (cx, cy): two half arcs as bulge loops, two
// half arcs as elements, one full-circle element (start == end).
void test_circles() {
    mt::begin_case("circle from two half arcs");
    const double cx = 3.0, cy = -2.0, R = 1.5;
    auto s = make({{cx + R, cy, 1.0, cx - R, cy, 1.0}});
    if (!s) return;
    MT_CHECK_NEAR(area_of(s.get()), kPi * R * R, 1e-14);
    check_bbox(s.get(), cx - R, cy - R, cx + R, cy + R);
    MT_CHECK(joints_of(s.get(), 0) == std::vector<uint32_t>({MX_JOINT_SMOOTH, MX_JOINT_SMOOTH}));
    for (size_t k = 0; k < 2; ++k) {
        const mx_element e = element_of(s.get(), 0, k);
        MT_CHECK_EQ(e.kind, static_cast<uint32_t>(MX_ELEMENT_ARC));
        MT_CHECK_EQ(e.ccw, 1);
        MT_CHECK_NEAR(e.cx, cx, 1e-14);
        MT_CHECK_NEAR(e.cy, cy, 1e-14);
        MT_CHECK_NEAR(e.radius, R, 1e-14);
    }

    mt::begin_case("circle from two half-arc elements");
    mx_element halves[2] = {};
    halves[0].kind = halves[1].kind = MX_ELEMENT_ARC;
    halves[0].ccw = halves[1].ccw = 1;
    halves[0].x0 = cx + R;
    halves[0].y0 = cy;
    halves[0].x1 = cx - R;
    halves[0].y1 = cy;
    halves[1].x0 = cx - R;
    halves[1].y0 = cy;
    halves[1].x1 = cx + R;
    halves[1].y1 = cy;
    halves[0].cx = halves[1].cx = cx;
    halves[0].cy = halves[1].cy = cy;
    const size_t two[1] = {2};
    mx_shape2d* raw = nullptr;
    MT_CHECK_OK(mx_shape2d_from_elements(halves, 2, two, 1, nullptr, &raw));
    mt::ShapePtr h(raw);
    if (h) {
        MT_CHECK_NEAR(area_of(h.get()), kPi * R * R, 1e-14);
        check_bbox(h.get(), cx - R, cy - R, cx + R, cy + R);
    }

    mt::begin_case("full-circle element");
    for (uint32_t ccw : {1u, 0u}) {
        mx_element full{};
        full.kind = MX_ELEMENT_ARC;
        full.ccw = ccw;
        full.x0 = full.x1 = cx + R;
        full.y0 = full.y1 = cy;
        full.cx = cx;
        full.cy = cy;
        const size_t one[1] = {1};
        raw = nullptr;
        MT_CHECK_OK(mx_shape2d_from_elements(&full, 1, one, 1, nullptr, &raw));
        mt::ShapePtr f(raw);
        if (!f) continue;
        size_t n = 0;
        MT_CHECK_OK(mx_shape2d_loop_size(f.get(), 0, &n));
        MT_CHECK_EQ(n, size_t{2});  // split into two half arcs
        MT_CHECK_NEAR(area_of(f.get()), kPi * R * R, 1e-14);
        check_bbox(f.get(), cx - R, cy - R, cx + R, cy + R);
        MT_CHECK_EQ(reversed_of(f.get(), 0), ccw ? 0 : 1);  // outer loops are stored CCW
    }
}

// Orientation normalisation: outer given clockwise, a hole (with an arc)
// given counter-clockwise; both are reported reversed and the documented
// index mapping holds (stored element k = input element (n - 2 - k) mod n,
// walked backwards).
void test_orientation_and_holes() {
    mt::begin_case("orientation and holes");
    const std::vector<double> outer_cw = {0, 0, 0, 0, 10, 0, 10, 10, 0, 10, 0, 0};
    const std::vector<double> hole_ccw = {3, 3, 0, 7, 3, 0.5, 7, 7, 0, 3, 7, 0};
    auto s = make({outer_cw, hole_ccw});
    if (!s) return;
    MT_CHECK_EQ(loop_count(s.get()), size_t{2});
    MT_CHECK_EQ(reversed_of(s.get(), 0), 1);
    MT_CHECK_EQ(reversed_of(s.get(), 1), 1);

    // Area = outer - hole; the hole's arc (bulge 0.5 on a chord of 4) bulges
    // out of the 4 x 4 square: r = 2.5, sweep = 4 atan(0.5).
    const double theta = 4.0 * std::atan(0.5), rr = 2.5;
    const double hole_area = 16.0 + 0.5 * rr * rr * (theta - std::sin(theta));
    MT_CHECK_NEAR(area_of(s.get()), 100.0 - hole_area, 1e-13);
    MT_CHECK_NEAR(area_of(s.get()),
                  std::fabs(bulge_loop_signed_area(outer_cw)) - std::fabs(bulge_loop_signed_area(hole_ccw)), 1e-13);
    check_bbox(s.get(), 0.0, 0.0, 10.0, 10.0);

    for (size_t l = 0; l < 2; ++l) {
        const std::vector<double>& in = l == 0 ? outer_cw : hole_ccw;
        const size_t n = in.size() / 3;
        // Stored loops are oriented: outer CCW (positive area), holes CW.
        const std::vector<double> stored = mt::loop_vertices(s.get(), l);
        const double a = bulge_loop_signed_area(stored);
        MT_CHECK(l == 0 ? a > 0.0 : a < 0.0);
        for (size_t k = 0; k < n; ++k) {
            const size_t m = (2 * n - 2 - k) % n;  // input element of stored element k
            const mx_element e = element_of(s.get(), l, k);
            MT_CHECK_EQ(e.x0, in[3 * ((m + 1) % n)]);
            MT_CHECK_EQ(e.y0, in[3 * ((m + 1) % n) + 1]);
            MT_CHECK_EQ(e.x1, in[3 * m]);
            MT_CHECK_EQ(e.y1, in[3 * m + 1]);
            MT_CHECK_NEAR(e.bulge, -in[3 * m + 2], 1e-15);
            MT_CHECK_EQ(e.kind, static_cast<uint32_t>(in[3 * m + 2] != 0.0 ? MX_ELEMENT_ARC : MX_ELEMENT_SEGMENT));
            if (stored.size() == in.size()) {
                // ...and stored vertex k is input vertex n - 1 - k.
                MT_CHECK_EQ(stored[3 * k], in[3 * (n - 1 - k)]);
                MT_CHECK_EQ(stored[3 * k + 1], in[3 * (n - 1 - k) + 1]);
            }
        }
    }
    // The hole's arc was CCW as given; stored (reversed) it runs clockwise.
    bool found_arc = false;
    for (size_t k = 0; k < 4; ++k) {
        const mx_element e = element_of(s.get(), 1, k);
        if (e.kind != MX_ELEMENT_ARC) continue;
        found_arc = true;
        MT_CHECK_EQ(e.ccw, 0);
        MT_CHECK_NEAR(e.radius, rr, 1e-14);
        MT_CHECK_NEAR(e.cx, 5.5, 1e-14);
        MT_CHECK_NEAR(e.cy, 5.0, 1e-14);
    }
    MT_CHECK(found_arc);

    // Seen from the shape's interior: the outer square's corners are convex,
    // every corner of the hole (including both ends of its arc) is reflex.
    MT_CHECK(joints_of(s.get(), 0) == std::vector<uint32_t>(4, MX_JOINT_CONVEX));
    MT_CHECK(joints_of(s.get(), 1) == std::vector<uint32_t>(4, MX_JOINT_REFLEX));

    // Given in the normalised orientation, nothing is reversed.
    const std::vector<double> outer_ccw = {0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 10, 0};
    const std::vector<double> hole_cw = {3, 3, 0, 3, 7, 0, 7, 7, -0.5, 7, 3, 0};
    auto t = make({outer_ccw, hole_cw});
    if (!t) return;
    MT_CHECK_EQ(reversed_of(t.get(), 0), 0);
    MT_CHECK_EQ(reversed_of(t.get(), 1), 0);
    MT_CHECK_NEAR(area_of(t.get()), 100.0 - hole_area, 1e-13);
}

constexpr const char* kRectJson = R"({"name": "ignored metadata", "loops": [[[0, 0], [4, 0, 1], [4, 2, 0], [0, 2]]]})";
constexpr const char* kRectSvgPath = "M 0 0 L 4 0 A 1 1 0 0 1 4 2 L 0 2 Z";
constexpr const char* kRectSvgDoc =
    "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">\n"
    "  <path d=\"M 0 0 L 4 0 A 1 1 0 0 1 4 2 L 0 2 Z\"/>\n</svg>\n";
constexpr const char* kRectDxf =
    "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n90\n4\n70\n1\n"
    "10\n0\n20\n0\n10\n4\n20\n0\n42\n1\n10\n4\n20\n2\n10\n0\n20\n2\n0\nENDSEC\n0\nEOF\n";

void test_from_string() {
    struct Case {
        const char* name;
        const char* text;
        uint32_t format;
    };
    const Case cases[] = {
        {"JSON", kRectJson, MX_FORMAT_JSON},          {"JSON (auto)", kRectJson, MX_FORMAT_AUTO},
        {"SVG path data", kRectSvgPath, MX_FORMAT_SVG}, {"SVG path data (auto)", kRectSvgPath, MX_FORMAT_AUTO},
        {"SVG document", kRectSvgDoc, MX_FORMAT_SVG}, {"SVG document (auto)", kRectSvgDoc, MX_FORMAT_AUTO},
        {"DXF LWPOLYLINE", kRectDxf, MX_FORMAT_DXF},  {"DXF LWPOLYLINE (auto)", kRectDxf, MX_FORMAT_AUTO},
    };
    for (const Case& c : cases) {
        mt::begin_case(std::string("mx_shape2d_from_string ") + c.name);
        mx_shape2d* raw = nullptr;
        MT_CHECK_OK(mx_shape2d_from_string(c.text, c.format, nullptr, &raw));
        mt::ShapePtr s(raw);
        if (!s) continue;
        MT_CHECK_EQ(loop_count(s.get()), size_t{1});
        MT_CHECK_NEAR(area_of(s.get()), 8.0 + kPi / 2.0, 1e-14);
        check_bbox(s.get(), 0.0, 0.0, 5.0, 2.0);
        size_t arcs = 0;
        for (size_t k = 0; k < 4; ++k) arcs += element_of(s.get(), 0, k).kind == MX_ELEMENT_ARC;
        MT_CHECK_EQ(arcs, size_t{1});
    }
}

// The CLI's demo plate (an outer loop with arcs, a round hole and a slot).
constexpr const char* kDemoJson = R"({"name": "medax demo plate: arcs, a notch, a step, a round hole and a slot",
 "loops": [
  [[0, 0, 0], [120, 0, 0], [120, 50, 0.41421356237309503], [100, 70, 0], [70, 70, -1],
   [40, 70, 0], [15, 70, 0], [15, 60, 0], [0, 60, 0]],
  [[42, 30, 1], [18, 30, 1]],
  [[70, 22, 0], [95, 22, 1], [95, 34, 0], [70, 34, 1]]
 ]})";

void test_from_file_and_svg() {
    mt::begin_case("mx_shape2d_from_file");
    const std::vector<std::vector<double>> demo = {
        {0, 0, 0, 120, 0, 0, 120, 50, 0.41421356237309503, 100, 70, 0, 70, 70, -1, 40, 70, 0, 15, 70, 0, 15, 60, 0,
         0, 60, 0},
        {42, 30, 1, 18, 30, 1},
        {70, 22, 0, 95, 22, 1, 95, 34, 0, 70, 34, 1}};
    double expected_area = 0.0;
    for (size_t l = 0; l < demo.size(); ++l)
        expected_area += (l == 0 ? 1.0 : -1.0) * std::fabs(bulge_loop_signed_area(demo[l]));
    // Hand check of the independent formula: 120x70 minus the 15x10 notch and
    // the 20x20 corner cut, plus the quarter-circle segment, minus the
    // half-disk notch (r 15), the round hole (r 12) and the slot (25x12 + disk r 6).
    const double by_hand = 120.0 * 70.0 - 15.0 * 10.0 - 0.5 * 20.0 * 20.0 +
                           (kPi * 400.0 / 4.0 - 0.5 * 20.0 * 20.0) - kPi * 225.0 / 2.0 - kPi * 144.0 -
                           (25.0 * 12.0 + kPi * 36.0);
    MT_CHECK_NEAR(expected_area, by_hand, 1e-12);

    const std::string json_path = temp_path("demo.json");
    const std::string txt_path = temp_path("demo.txt");
    write_file(json_path, kDemoJson);
    write_file(txt_path, kDemoJson);
    const std::vector<std::pair<std::string, uint32_t>> inputs = {
        {json_path, MX_FORMAT_AUTO}, {json_path, MX_FORMAT_JSON}, {txt_path, MX_FORMAT_JSON}, {txt_path, MX_FORMAT_AUTO}};
    for (const auto& [path, format] : inputs) {
        mx_shape2d* raw = nullptr;
        MT_CHECK_OK(mx_shape2d_from_file(path.c_str(), format, nullptr, &raw));
        mt::ShapePtr s(raw);
        if (!s) continue;
        MT_CHECK_EQ(loop_count(s.get()), size_t{3});
        MT_CHECK_NEAR(area_of(s.get()), expected_area, 1e-12);
        MT_CHECK_EQ(reversed_of(s.get(), 0), 0);
        MT_CHECK_EQ(reversed_of(s.get(), 1), 1);  // the holes are given CCW
        MT_CHECK_EQ(reversed_of(s.get(), 2), 1);
        check_bbox(s.get(), 0.0, 0.0, 120.0, 70.0);
    }

    mt::begin_case("mx_shape2d_write_svg");
    mx_shape2d* raw = nullptr;
    MT_CHECK_OK(mx_shape2d_from_file(json_path.c_str(), MX_FORMAT_AUTO, nullptr, &raw));
    mt::ShapePtr s(raw);
    const std::string svg_path = temp_path("demo.svg");
    if (s) {
        const double before = area_of(s.get());
        MT_CHECK_OK(mx_shape2d_write_svg(s.get(), svg_path.c_str()));
        MT_CHECK(fs::exists(svg_path));
        const std::string svg = read_file(svg_path);
        MT_CHECK(svg.find("<svg") != std::string::npos);
        MT_CHECK(svg.find("</svg>") != std::string::npos);
        MT_CHECK_EQ(area_of(s.get()), before);
    }
    std::error_code ec;
    fs::remove(json_path, ec);
    fs::remove(txt_path, ec);
    fs::remove(svg_path, ec);
}

// One const handle, four threads querying it at once; every thread must see
// the same values as the main thread. Last errors are thread-local.
void test_threads(int iterations) {
    mt::begin_case("concurrent queries of a const handle");
    const std::vector<std::vector<double>> loops = {
        {0, 0, 0, 120, 0, 0, 120, 50, 0.41421356237309503, 100, 70, 0, 70, 70, -1, 40, 70, 0, 15, 70, 0, 15, 60, 0,
         0, 60, 0},
        {42, 30, 1, 18, 30, 1},
        {70, 22, 0, 95, 22, 1, 95, 34, 0, 70, 34, 1}};
    auto owned = make(loops);
    if (!owned) return;
    const mx_shape2d* shape = owned.get();
    Snapshot baseline;
    MT_CHECK(snapshot(shape, baseline));

    mx_clear_last_error();
    std::atomic<int> mismatches{0}, failures{0}, error_leaks{0}, snapshots{0}, ready{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            // A fresh thread starts with no error recorded.
            mx_error_info info{};
            if (mx_last_error_info(&info) != MX_OK || info.status != MX_OK) ++error_leaks;
            // Start together, so that the queries really overlap.
            ++ready;
            while (ready.load() < 4) std::this_thread::yield();
            for (int i = 0; i < iterations; ++i) {
                Snapshot snap;
                if (!snapshot(shape, snap)) {
                    ++failures;
                    continue;
                }
                if (!(snap == baseline)) ++mismatches;
                ++snapshots;
                // Provoke a thread-local error now and then and read it back.
                if ((i + t) % 16 == 0) {
                    size_t n = 0;
                    if (mx_shape2d_loop_size(shape, 1000 + static_cast<size_t>(t), &n) != MX_ERR_INDEX_OUT_OF_RANGE)
                        ++failures;
                    if (mx_last_error_info(&info) != MX_OK || info.status != MX_ERR_INDEX_OUT_OF_RANGE) ++failures;
                    mx_clear_last_error();
                }
            }
        });
    }
    for (auto& th : threads) th.join();
    MT_CHECK_EQ(snapshots.load(), 4 * iterations);
    MT_CHECK_EQ(mismatches.load(), 0);
    MT_CHECK_EQ(failures.load(), 0);
    MT_CHECK_EQ(error_leaks.load(), 0);
    // The workers' errors never became this thread's error.
    mx_error_info info{};
    MT_CHECK_OK(mx_last_error_info(&info));
    MT_CHECK_EQ(info.status, MX_OK);
    MT_CHECK_EQ(mx_last_error_length(), size_t{0});
}

}  // namespace

int main(int argc, char** argv) {
    const int iterations = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20000;
    std::cout << "medax " << mx_version() << "\n";
    test_options();
    test_version();
    test_status_strings();
    test_rectangle_with_half_circle();
    test_circles();
    test_orientation_and_holes();
    test_from_string();
    test_from_file_and_svg();
    test_threads(iterations);
    return mt::finish("c_api_roundtrip");
}
