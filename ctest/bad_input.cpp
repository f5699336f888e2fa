// Every way to hand medax bad input through the C API, with the exact status
// and the structured details (mx_error_info: loop/element indices, second
// loop/element, position, parse line/column). Also: failing calls leave
// out-parameters untouched, _free(NULL) is a no-op for every handle type,
// and the last-error message API (size query, copy, truncation).
//
// Indices are the caller's input indices (header: "Loop and element indices
// are the caller's input indices"); element i runs from vertex i to vertex
// i + 1. Where an input has two equally valid culprits (e.g. two crossing
// pairs) the test accepts either, and says so.

#include "test_support.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using Loops = std::vector<std::vector<double>>;

// What a failing call must report.
struct Err {
    mx_status status;
    int64_t loop = -1, element = -1, other_loop = -1, other_element = -1;
    bool has_position = false;
    double x = 0.0, y = 0.0;
    int64_t line = -1, column = -1;
    std::vector<std::string> message_parts;
    // Alternatives for (element, other_loop, other_element, x, y) when the
    // input has more than one equally valid culprit.
    struct Alt {
        int64_t element, other_loop, other_element;
        double x, y;
    };
    std::vector<Alt> alternatives;
    bool check_indices = true;

    explicit Err(mx_status s) : status(s) {}
    Err& at(int64_t l, int64_t e) {
        loop = l;
        element = e;
        return *this;
    }
    Err& in_loop(int64_t l) {
        loop = l;
        return *this;
    }
    Err& other(int64_t l, int64_t e) {
        other_loop = l;
        other_element = e;
        return *this;
    }
    Err& other_loop_only(int64_t l) {
        other_loop = l;
        return *this;
    }
    Err& pos(double px, double py) {
        has_position = true;
        x = px;
        y = py;
        return *this;
    }
    Err& parse_at(int64_t l, int64_t c) {
        line = l;
        column = c;
        return *this;
    }
    Err& says(std::string part) {
        message_parts.push_back(std::move(part));
        return *this;
    }
    Err& or_at(int64_t e, int64_t ol, int64_t oe, double px, double py) {
        alternatives.push_back({e, ol, oe, px, py});
        return *this;
    }
    Err& status_only() {
        check_indices = false;
        return *this;
    }
};

// Checks the status returned, mx_error_info and the message against `e`.
void expect(mx_status got, const Err& e, const char* what, int line) {
    const std::string where = std::string(what) + " (bad_input.cpp:" + std::to_string(line) + ")";
    const std::string msg = mt::last_message();
    if (!mt::record(got == e.status, __FILE__, line,
                    where + ": status " + mt::show(got) + ", expected " + mt::show(e.status) +
                        (got != MX_OK ? " -- " + msg : ""))) {
        if (got == MX_OK) return;
    }
    const mx_error_info info = mt::last_info();
    mt::record(info.status == got, __FILE__, line, where + ": mx_error_info.status " + mt::show(info.status));
    // Every failure carries a message: size query == mx_last_error_length.
    const size_t len = mx_last_error_message(nullptr, 0);
    mt::record(len > 1 && len == mx_last_error_length() && len == msg.size() + 1, __FILE__, line,
               where + ": message length " + std::to_string(len));
    for (const std::string& part : e.message_parts)
        mt::record(msg.find(part) != std::string::npos, __FILE__, line,
                   where + ": message \"" + msg + "\" lacks \"" + part + "\"");
    if (!e.check_indices || got != e.status) return;

    const auto describe = [&] {
        std::ostringstream os;
        os.precision(17);
        os << "loop " << info.loop_index << " element " << info.element << ", other loop " << info.other_loop_index
           << " element " << info.other_element << ", has_position " << info.has_position << " (" << info.x << ", "
           << info.y << "), line " << info.line << " column " << info.column;
        return os.str();
    };
    const auto pos_ok = [&](double px, double py) {
        return info.has_position == 1 && mt::near_rel(info.x, px, 1e-9, 1e-9) && mt::near_rel(info.y, py, 1e-9, 1e-9);
    };
    bool ok = info.loop_index == e.loop && info.line == e.line && info.column == e.column;
    bool main_ok = info.element == e.element && info.other_loop_index == e.other_loop &&
                   info.other_element == e.other_element && (e.has_position ? pos_ok(e.x, e.y) : info.has_position == 0);
    for (const Err::Alt& a : e.alternatives)
        main_ok = main_ok || (info.element == a.element && info.other_loop_index == a.other_loop &&
                              info.other_element == a.other_element && pos_ok(a.x, a.y));
    ok = ok && main_ok;
    std::ostringstream want;
    want.precision(17);
    want << "loop " << e.loop << " element " << e.element << ", other loop " << e.other_loop << " element "
         << e.other_element << ", has_position " << e.has_position << " (" << e.x << ", " << e.y << "), line "
         << e.line << " column " << e.column;
    for (const Err::Alt& a : e.alternatives)
        want << " | or element " << a.element << ", other " << a.other_loop << "/" << a.other_element << " at ("
             << a.x << ", " << a.y << ")";
    mt::record(ok, __FILE__, line, where + ": error info " + describe() + "; expected " + want.str());
}

#define EXPECT_ERROR(call, err) expect((call), (err), #call, __LINE__)

// Creation wrappers that also check the out-parameter is untouched on failure.
mx_status bulges(const Loops& loops, const mx_shape_options* opts = nullptr) {
    mx_clear_last_error();
    mx_shape2d* out = mt::sentinel_shape();
    const mx_status s = mt::from_loops(loops, &out, opts);
    if (s == MX_OK) {
        mx_shape2d_free(out);
    } else {
        MT_CHECK(out == mt::sentinel_shape());
    }
    return s;
}

mx_status raw_bulges(const double* xyb, size_t xyb_len, const size_t* lens, size_t count) {
    mx_clear_last_error();
    mx_shape2d* out = mt::sentinel_shape();
    const mx_status s = mx_shape2d_from_bulges(xyb, xyb_len, lens, count, nullptr, &out);
    if (s == MX_OK) {
        mx_shape2d_free(out);
    } else {
        MT_CHECK(out == mt::sentinel_shape());
    }
    return s;
}

mx_status elements(const std::vector<mx_element>& es, const std::vector<size_t>& lens,
                   const mx_shape_options* opts = nullptr) {
    mx_clear_last_error();
    mx_shape2d* out = mt::sentinel_shape();
    const mx_status s = mx_shape2d_from_elements(es.data(), es.size(), lens.data(), lens.size(), opts, &out);
    if (s == MX_OK) {
        mx_shape2d_free(out);
    } else {
        MT_CHECK(out == mt::sentinel_shape());
    }
    return s;
}

mx_status from_string(const char* text, uint32_t format) {
    mx_clear_last_error();
    mx_shape2d* out = mt::sentinel_shape();
    const mx_status s = mx_shape2d_from_string(text, format, nullptr, &out);
    if (s == MX_OK) {
        mx_shape2d_free(out);
    } else {
        MT_CHECK(out == mt::sentinel_shape());
    }
    return s;
}

mx_status from_file(const char* path, uint32_t format) {
    mx_clear_last_error();
    mx_shape2d* out = mt::sentinel_shape();
    const mx_status s = mx_shape2d_from_file(path, format, nullptr, &out);
    if (s == MX_OK) {
        mx_shape2d_free(out);
    } else {
        MT_CHECK(out == mt::sentinel_shape());
    }
    return s;
}

mx_element seg(double x0, double y0, double x1, double y1) {
    mx_element e{};
    e.kind = MX_ELEMENT_SEGMENT;
    e.x0 = x0;
    e.y0 = y0;
    e.x1 = x1;
    e.y1 = y1;
    return e;
}

mx_element arc(double x0, double y0, double x1, double y1, double cx, double cy, bool ccw) {
    mx_element e = seg(x0, y0, x1, y1);
    e.kind = MX_ELEMENT_ARC;
    e.cx = cx;
    e.cy = cy;
    e.ccw = ccw ? 1 : 0;
    return e;
}

const std::vector<double> kSquare10 = {0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 10, 0};
const std::vector<double> kUnitSquare = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

mt::ShapePtr good_shape() {
    mx_shape2d* s = nullptr;
    MT_CHECK_OK(mt::from_loops({kSquare10, {3, 3, 0, 3, 7, 0, 7, 7, 0, 7, 3, 0}}, &s));
    return mt::ShapePtr(s);
}

// ---------------------------------------------------------------------------

void test_null_arguments() {
    mt::begin_case("NULL arguments");
    const double xyb[] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
    const size_t lens[] = {3};
    const Err null_arg = Err(MX_ERR_NULL_ARGUMENT);
    EXPECT_ERROR(raw_bulges(nullptr, 9, lens, 1), Err(null_arg).says("xyb"));
    EXPECT_ERROR(raw_bulges(xyb, 9, nullptr, 1), Err(null_arg).says("loop_lengths"));
    mx_clear_last_error();
    EXPECT_ERROR(mx_shape2d_from_bulges(xyb, 9, lens, 1, nullptr, nullptr), Err(null_arg).says("out"));

    const mx_element es[3] = {seg(0, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 0)};
    mx_shape2d* out = mt::sentinel_shape();
    EXPECT_ERROR(mx_shape2d_from_elements(nullptr, 3, lens, 1, nullptr, &out), Err(null_arg).says("elements"));
    EXPECT_ERROR(mx_shape2d_from_elements(es, 3, nullptr, 1, nullptr, &out), Err(null_arg).says("loop_lengths"));
    EXPECT_ERROR(mx_shape2d_from_elements(es, 3, lens, 1, nullptr, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_from_string(nullptr, MX_FORMAT_AUTO, nullptr, &out), Err(null_arg).says("text"));
    EXPECT_ERROR(mx_shape2d_from_string("M 0 0 L 1 0 L 1 1 Z", MX_FORMAT_AUTO, nullptr, nullptr),
                 Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_from_file(nullptr, MX_FORMAT_AUTO, nullptr, &out), Err(null_arg).says("path"));
    EXPECT_ERROR(mx_shape2d_from_file("x.json", MX_FORMAT_AUTO, nullptr, nullptr), Err(null_arg).says("out"));
    MT_CHECK(out == mt::sentinel_shape());
    // options == NULL means defaults (not an error).
    out = nullptr;
    MT_CHECK_OK(mx_shape2d_from_bulges(xyb, 9, lens, 1, nullptr, &out));
    mx_shape2d_free(out);

    auto shape = good_shape();
    const mx_shape2d* s = shape.get();
    size_t n = 777;
    int32_t u = 777;
    mx_joint_kind joint = MX_JOINT_REFLEX;
    double d = 777.0;
    mx_bbox bb{7, 7, 7, 7};
    mx_element el{};
    el.x0 = 777.0;
    double buf[24];
    EXPECT_ERROR(mx_shape2d_loop_count(nullptr, &n), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_loop_count(s, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_loop_size(nullptr, 0, &n), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_loop_size(s, 0, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_loop_reversed(nullptr, 0, &u), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_loop_reversed(s, 0, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_loop_vertices(nullptr, 0, buf, 8, &n), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_loop_vertices(s, 0, buf, 8, nullptr), Err(null_arg).says("count"));
    EXPECT_ERROR(mx_shape2d_loop_vertices(s, 0, nullptr, 8, &n), Err(null_arg).says("xyb"));
    EXPECT_ERROR(mx_shape2d_element(nullptr, 0, 0, &el), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_element(s, 0, 0, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_joint(nullptr, 0, 0, &joint), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_joint(s, 0, 0, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_bbox(nullptr, &bb), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_bbox(s, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_area(nullptr, &d), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_area(s, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_tolerance(nullptr, &d), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_tolerance(s, nullptr), Err(null_arg).says("out"));
    EXPECT_ERROR(mx_shape2d_write_svg(nullptr, "never-written.svg"), Err(null_arg).says("shape"));
    EXPECT_ERROR(mx_shape2d_write_svg(s, nullptr), Err(null_arg).says("path"));
    EXPECT_ERROR(mx_shape_options_init(nullptr, sizeof(mx_shape_options)), Err(null_arg).says("out"));
    MT_CHECK(!fs::exists("never-written.svg"));
    // Out-params of failed queries are untouched.
    MT_CHECK_EQ(n, size_t{777});
    MT_CHECK_EQ(u, 777);
    MT_CHECK(joint == MX_JOINT_REFLEX);
    MT_CHECK_EQ(d, 777.0);
    MT_CHECK(bb.xmin == 7 && bb.ymin == 7 && bb.xmax == 7 && bb.ymax == 7);
    MT_CHECK_EQ(el.x0, 777.0);
    // mx_last_error_info(NULL) reports NULL_ARGUMENT (and cannot record it).
    MT_CHECK_EQ(mx_last_error_info(nullptr), MX_ERR_NULL_ARGUMENT);

    // _free(NULL) is a no-op for all four handle types.
    mx_shape2d_free(nullptr);
    mx_axis_free(nullptr);
    mx_ball_free(nullptr);
    mx_mesh3d_free(nullptr);
    MT_CHECK(true);
}

void test_invalid_arguments() {
    mt::begin_case("invalid arguments");
    const double xyb[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const size_t lens[] = {4};
    const Err invalid = Err(MX_ERR_INVALID_ARGUMENT);
    EXPECT_ERROR(raw_bulges(xyb, 11, lens, 1), invalid);  // not 3 x 4
    const size_t five[] = {5};
    EXPECT_ERROR(raw_bulges(xyb, 12, five, 1), invalid);
    const size_t two_one[] = {2, 1};
    EXPECT_ERROR(raw_bulges(xyb, 12, two_one, 2), invalid);
    const size_t huge[] = {std::numeric_limits<size_t>::max(), 5};  // sum overflows
    EXPECT_ERROR(raw_bulges(xyb, 12, huge, 2), invalid);
    const size_t third[] = {std::numeric_limits<size_t>::max() / 3 + 1};  // 3 x n overflows
    EXPECT_ERROR(raw_bulges(xyb, 12, third, 1), invalid);

    const std::vector<mx_element> tri = {seg(0, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 0)};
    EXPECT_ERROR(elements(tri, {4}), invalid);  // element_count != sum of loop_lengths
    std::vector<mx_element> bad_kind = tri;
    bad_kind[1].kind = 7;
    EXPECT_ERROR(elements(bad_kind, {3}), Err(invalid).says("7"));

    EXPECT_ERROR(from_string("M 0 0 L 1 0 L 1 1 Z", 4), invalid);  // unknown format
    EXPECT_ERROR(from_string("M 0 0 L 1 0 L 1 1 Z", 0xFFFFFFFFu), invalid);
    EXPECT_ERROR(from_file("x.json", 9), invalid);
    EXPECT_ERROR(from_string("M 0 0 L 1 0 \xff\xfe L 1 1 Z", MX_FORMAT_SVG), invalid);  // not UTF-8
    EXPECT_ERROR(from_file("/tmp/medax-\xff\xfe.json", MX_FORMAT_AUTO), invalid);

    mx_shape_options o;
    MT_CHECK_OK(mx_shape_options_init(&o, sizeof o));
    mx_shape_options small = o;
    small.struct_size = offsetof(mx_shape_options, threads) - 1;  // short of 0.1.0
    EXPECT_ERROR(bulges({kUnitSquare}, &small), Err(invalid).says("struct_size"));
    small.struct_size = 0;
    EXPECT_ERROR(bulges({kUnitSquare}, &small), invalid);
    mx_shape_options bad = o;
    bad.threads = 100000;
    EXPECT_ERROR(bulges({kUnitSquare}, &bad), Err(invalid).says("mx_shape_options.threads"));
    bad = o;
    bad.relative_tolerance = -1.0;
    EXPECT_ERROR(bulges({kUnitSquare}, &bad), Err(invalid).says("relative_tolerance"));
    bad = o;
    bad.relative_tolerance = kNaN;
    EXPECT_ERROR(bulges({kUnitSquare}, &bad), invalid);
    bad = o;
    bad.angle_tolerance = 2.0;  // must be below pi/2
    EXPECT_ERROR(bulges({kUnitSquare}, &bad), Err(invalid).says("angle_tolerance"));
    bad = o;
    bad.angle_tolerance = -0.1;
    EXPECT_ERROR(bulges({kUnitSquare}, &bad), invalid);
    bad = o;
    bad.flatten_sagitta = kNaN;
    EXPECT_ERROR(bulges({kUnitSquare}, &bad), invalid);
    bad = o;
    bad.relative_tolerance = -1.0;
    EXPECT_ERROR(elements(tri, {3}, &bad), invalid);
    mx_shape2d* out = mt::sentinel_shape();
    EXPECT_ERROR(mx_shape2d_from_string("M 0 0 L 1 0 L 1 1 Z", MX_FORMAT_AUTO, &small, &out), invalid);
    EXPECT_ERROR(mx_shape2d_from_file("x.json", MX_FORMAT_AUTO, &small, &out), invalid);
    MT_CHECK(out == mt::sentinel_shape());
}

void test_empty_and_too_few() {
    mt::begin_case("empty / too few elements");
    EXPECT_ERROR(raw_bulges(nullptr, 0, nullptr, 0), Err(MX_ERR_EMPTY));
    EXPECT_ERROR(bulges({}), Err(MX_ERR_EMPTY));
    EXPECT_ERROR(elements({}, {}), Err(MX_ERR_EMPTY));
    EXPECT_ERROR(from_string(R"({"loops": []})", MX_FORMAT_JSON), Err(MX_ERR_EMPTY));
    EXPECT_ERROR(from_string("<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>", MX_FORMAT_SVG), Err(MX_ERR_EMPTY));
    EXPECT_ERROR(from_string("0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n", MX_FORMAT_DXF), Err(MX_ERR_EMPTY));

    const Err few = Err(MX_ERR_TOO_FEW_ELEMENTS);
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0}}), Err(few).in_loop(0));  // two segments
    EXPECT_ERROR(bulges({{0, 0, 1}}), Err(few).in_loop(0));           // one arc
    EXPECT_ERROR(bulges({kSquare10, {}}), Err(few).in_loop(1));       // empty hole
    EXPECT_ERROR(bulges({kSquare10, {4, 4, 0, 5, 5, 0}}), Err(few).in_loop(1));
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), seg(1, 0, 0, 0)}, {2}), Err(few).in_loop(0));
    // Two elements are enough when one is an arc (a "D").
    MT_CHECK_OK(bulges({{0, 0, 1, 2, 0, 0}}));
}

void test_non_finite_and_range() {
    mt::begin_case("non-finite / out of range");
    const Err nf = Err(MX_ERR_NON_FINITE);
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, kNaN, 1, 0, 0, 1, 0}}), Err(nf).at(0, 2).says("loop 0").says("element 2"));
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 1, kInf, 0, 0, 1, 0}}), Err(nf).at(0, 2));
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, kNaN, 1, 1, 0, 0, 1, 0}}), Err(nf).at(0, 1));  // bulge
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, -kInf}}), Err(nf).at(0, 3));
    EXPECT_ERROR(bulges({kSquare10, {3, 3, 0, 3, 7, 0, 7, kNaN, 0, 7, 3, 0}}), Err(nf).at(1, 2).says("loop 1"));
    // Explicit elements: a NaN centre, and a NaN segment end point.
    EXPECT_ERROR(elements({seg(0, 0, 2, 0), arc(2, 0, 0, 0, kNaN, 1, true)}, {2}), Err(nf).at(0, 1));
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), seg(1, 0, kNaN, 1), seg(kNaN, 1, 0, 0)}, {3}), Err(nf).at(0, 1));
    // From files: JSON cannot spell NaN, DXF can.
    EXPECT_ERROR(from_string("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n90\n3\n70\n1\n"
                             "10\n0\n20\n0\n10\nnan\n20\n0\n10\n1\n20\n1\n0\nENDSEC\n0\nEOF\n",
                             MX_FORMAT_DXF),
                 Err(nf).status_only());

    const Err oor = Err(MX_ERR_OUT_OF_RANGE);
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 1e12, 1, 0, 0, 1, 0}}), Err(oor).at(0, 2).says("element 2"));
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 1, -1e12, 0, 0, 1, 0}}), Err(oor).at(0, 2));
    EXPECT_ERROR(bulges({kSquare10, {3, 3, 0, 3, 7, 0, 7, 7, 0, 1e12, 3, 0}}), Err(oor).at(1, 3));
    // Vertices within +-1e9, but the half circle on element 1 reaches x = 1.35e9.
    EXPECT_ERROR(bulges({{0, 0, 0, 9e8, 0, 1, 9e8, 9e8, 0, 0, 9e8, 0}}), Err(oor).at(0, 1));
    // The limit itself is fine.
    MT_CHECK_OK(bulges({{-MX_MAX_COORDINATE, -MX_MAX_COORDINATE, 0, MX_MAX_COORDINATE, -MX_MAX_COORDINATE, 0, MX_MAX_COORDINATE,
                         MX_MAX_COORDINATE, 0, -MX_MAX_COORDINATE, MX_MAX_COORDINATE, 0}}));
}

void test_degenerate() {
    mt::begin_case("degenerate");
    const Err deg = Err(MX_ERR_DEGENERATE);
    // Zero-length element 1 (vertex 2 repeats vertex 1).
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}}), Err(deg).at(0, 1).pos(1, 0));
    EXPECT_ERROR(bulges({kSquare10, {3, 3, 0, 3, 7, 0, 3, 7, 0, 7, 7, 0, 7, 3, 0}}), Err(deg).at(1, 1).pos(3, 7));
    // Shorter than the tolerance counts as zero length.
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 1, 1e-12, 0, 1, 1, 0, 0, 1, 0}}), Err(deg).at(0, 1).pos(1, 0));
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), seg(1, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 0)}, {4}),
                 Err(deg).at(0, 1).pos(1, 0));
    // A closing vertex equal to the first is not a zero-length element.
    MT_CHECK_OK(bulges({{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0}}));

    // Spike: the boundary runs up to (2, 4) and straight back (a cusp at the
    // start vertex of element 4).
    EXPECT_ERROR(bulges({{0, 0, 0, 4, 0, 0, 4, 2, 0, 2, 2, 0, 2, 4, 0, 2, 2, 0, 0, 2, 0}}),
                 Err(deg).at(0, 4).pos(2, 4).says("cusp"));
    // Cusp between two arcs: a lens whose second arc retraces the first.
    EXPECT_ERROR(bulges({{0, 0, 0.5, 1, 0, -0.5}}), Err(deg).in_loop(0).status_only());
    // Zero area: three collinear points (cusps at both ends; either is a valid culprit).
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 2, 0, 0}}), Err(deg).at(0, 0).pos(0, 0).or_at(2, -1, -1, 2, 0));
    // Zero area relative to the tolerance: an equilateral triangle of side 1
    // (area 0.43) with tolerance 0.2 (area <= tolerance x perimeter = 0.6).
    mx_shape_options o;
    MT_CHECK_OK(mx_shape_options_init(&o, sizeof o));
    o.tolerance = 0.2;
    EXPECT_ERROR(bulges({{0, 0, 0, 1, 0, 0, 0.5, std::sqrt(0.75), 0}}, &o), Err(deg).at(0, 0).pos(0, 0).says("area"));
    // The same for a hole: a sliver triangle inside a 10 x 10 square.
    EXPECT_ERROR(bulges({kSquare10, {1, 1, 0, 2, 1, 0, 1.5, 1.2, 0}}, &o), Err(deg).at(1, 0).pos(1, 1));
}

void test_intersections() {
    mt::begin_case("intersections");
    const Err x = Err(MX_ERR_INTERSECTION);
    // Bow-tie: element 0 (0,0)-(2,2) crosses element 2 (2,0)-(0,2) at (1, 1).
    EXPECT_ERROR(bulges({{0, 0, 0, 2, 2, 0, 2, 0, 0, 0, 2, 0}}),
                 Err(x).at(0, 0).other(0, 2).pos(1, 1).says("element 0").says("element 2"));
    // A vertex touching a non-adjacent element: vertex 3 = (2, 0) lies on
    // element 0 from (0, 0) to (4, 0); elements 2 and 3 both end there.
    EXPECT_ERROR(bulges({{0, 0, 0, 4, 0, 0, 4, 3, 0, 2, 0, 0, 0, 3, 0}}),
                 Err(x).at(0, 0).other(0, 2).pos(2, 0).or_at(0, 0, 3, 2, 0));
    // Two holes overlapping: hole 1's right side x = 5 crosses hole 2's bottom
    // (at (5, 2)) and top (at (5, 4)).
    EXPECT_ERROR(bulges({kSquare10, {1, 1, 0, 5, 1, 0, 5, 5, 0, 1, 5, 0}, {4, 2, 0, 8, 2, 0, 8, 4, 0, 4, 4, 0}}),
                 Err(x).at(1, 1).other(2, 0).pos(5, 2).or_at(1, 2, 2, 5, 4));
    // A hole crossing the outer loop (x = 10) at (10, 2) and (10, 4).
    EXPECT_ERROR(bulges({kSquare10, {8, 2, 0, 12, 2, 0, 12, 4, 0, 8, 4, 0}}),
                 Err(x).at(0, 1).other(1, 0).pos(10, 2).or_at(1, 1, 2, 10, 4));
    // A hole touching the outer loop in one point (its vertex (10, 5)).
    EXPECT_ERROR(bulges({kSquare10, {8, 4, 0, 10, 5, 0, 8, 6, 0}}),
                 Err(x).at(0, 1).other(1, 0).pos(10, 5).or_at(1, 1, 1, 10, 5));
    // Segments crossing an arc of the same loop: the half circle on element 0
    // (centre (2, 0), radius 2, down to y = -2) is crossed by elements 2 and 3.
    EXPECT_ERROR(bulges({{0, 0, 1, 4, 0, 0, 4, 1, 0, 2, -3, 0, 0, 1, 0}}), Err(x).in_loop(0).status_only());
}

void test_holes() {
    mt::begin_case("hole placement");
    // The reported position is the hole's rightmost point (where medax casts
    // its containment ray from): the first vertex of largest x here.
    EXPECT_ERROR(bulges({kSquare10, {20, 20, 0, 22, 20, 0, 22, 22, 0, 20, 22, 0}}),
                 Err(MX_ERR_HOLE_OUTSIDE).in_loop(1).pos(22, 20).says("loop 1"));
    // The second hole is outside; the first is fine.
    EXPECT_ERROR(bulges({kSquare10, {1, 1, 0, 2, 1, 0, 2, 2, 0, 1, 2, 0}, {-5, 1, 0, -4, 1, 0, -4, 2, 0, -5, 2, 0}}),
                 Err(MX_ERR_HOLE_OUTSIDE).in_loop(2).pos(-4, 1));
    // Hole 2 inside hole 1, and the same with the order swapped.
    const std::vector<double> big = {1, 1, 0, 9, 1, 0, 9, 9, 0, 1, 9, 0};
    const std::vector<double> small = {3, 3, 0, 5, 3, 0, 5, 5, 0, 3, 5, 0};
    EXPECT_ERROR(bulges({kSquare10, big, small}), Err(MX_ERR_HOLE_INSIDE_HOLE).in_loop(2).other_loop_only(1).pos(5, 3));
    EXPECT_ERROR(bulges({kSquare10, small, big}), Err(MX_ERR_HOLE_INSIDE_HOLE).in_loop(1).other_loop_only(2).pos(5, 3));
    // Holes must not be the outer loop's outside even when the "outer" loop is smaller.
    EXPECT_ERROR(bulges({small, big}), Err(MX_ERR_HOLE_OUTSIDE).in_loop(1).pos(9, 1));
}

void test_elements_input() {
    mt::begin_case("explicit elements");
    const Err nc = Err(MX_ERR_NOT_CLOSED);
    // Last element ends at (0, 0.5) instead of (0, 0).
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 1), seg(0, 1, 0, 0.5)}, {4}),
                 Err(nc).at(0, 3).pos(0, 0.5).says("element 3"));
    // Gap after element 1.
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), seg(1, 0, 1, 0.9), seg(1, 1, 0, 1), seg(0, 1, 0, 0)}, {4}),
                 Err(nc).at(0, 1).pos(1, 0.9));
    // In a hole.
    EXPECT_ERROR(elements({seg(0, 0, 10, 0), seg(10, 0, 10, 10), seg(10, 10, 0, 10), seg(0, 10, 0, 0),
                           seg(3, 3, 3, 7), seg(3, 7, 7, 7), seg(7, 7, 3.5, 3)},
                          {4, 3}),
                 Err(nc).at(1, 2).pos(3.5, 3));
    // Elements given out of order do not chain.
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), seg(1, 1, 0, 1), seg(1, 0, 1, 1), seg(0, 1, 0, 0)}, {4}),
                 Err(nc).at(0, 0).pos(1, 0));

    const Err ia = Err(MX_ERR_INCONSISTENT_ARC);
    // Arc around (0, 0) from (1, 0) (radius 1) to (0, 2) (radius 2).
    EXPECT_ERROR(elements({seg(0, 0, 1, 0), arc(1, 0, 0, 2, 0, 0, true), seg(0, 2, 0, 0)}, {3}),
                 Err(ia).at(0, 1).says("element 1"));
    EXPECT_ERROR(elements({seg(0, 0, 10, 0), seg(10, 0, 10, 10), seg(10, 10, 0, 10), seg(0, 10, 0, 0),
                           arc(4, 5, 6.5, 5, 5, 5, true), arc(6.5, 5, 4, 5, 5, 5, true)},
                          {4, 2}),
                 Err(ia).at(1, 0));
}

void test_parse_errors() {
    mt::begin_case("parse errors");
    const Err pe = Err(MX_ERR_PARSE);
    // JSON: line and column (1-based) of the bad token `x`.
    EXPECT_ERROR(from_string("{\"loops\": [[[0, 0],\n [1, x]]]}", MX_FORMAT_JSON),
                 Err(pe).parse_at(2, 6).says("line 2"));
    EXPECT_ERROR(from_string("{\"loops\": [[[0, 0],\n [1, x]]]}", MX_FORMAT_AUTO), Err(pe).parse_at(2, 6));
    // Unexpected end: the position of the last character read.
    EXPECT_ERROR(from_string("{\"loops\": [[[0, 0], [1, 0], [1, 1]]", MX_FORMAT_JSON), Err(pe).parse_at(1, 35));
    EXPECT_ERROR(from_string(R"({"loops": [[[0, 0, 1, 2], [1, 0], [1, 1]]]})", MX_FORMAT_JSON),
                 Err(pe).parse_at(1, 24).says("expected [x, y] or [x, y, bulge]"));
    // DXF: 1-based line of the offending group code or value, column 1.
    EXPECT_ERROR(from_string("0\nSECTION\nxyz\nENTITIES\n", MX_FORMAT_DXF), Err(pe).parse_at(3, 1));
    EXPECT_ERROR(from_string("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nabc\n20\n0\n11\n1\n21\n0\n0\nENDSEC\n0\nEOF\n",
                             MX_FORMAT_DXF),
                 Err(pe).parse_at(8, 1).says("line 8"));
    EXPECT_ERROR(from_string("0\nSECTION\n2\nENTITIES\n0\nLINE\n10", MX_FORMAT_DXF), Err(pe).parse_at(7, 1));
    // SVG: line 0 and the byte offset in `column`.
    EXPECT_ERROR(from_string("M 0 0 L 1 x", MX_FORMAT_SVG), Err(pe).parse_at(0, 10).says("byte 10"));
    EXPECT_ERROR(from_string("M 0 0 L 1 x", MX_FORMAT_AUTO), Err(pe).parse_at(0, 10));
    EXPECT_ERROR(from_string("L 1 1", MX_FORMAT_SVG), Err(pe).parse_at(0, 0));  // no moveto
    EXPECT_ERROR(from_string("<svg><path d=\"M0 0 L1 0 L1 1 Z\"", MX_FORMAT_SVG), Err(pe).parse_at(0, 5));
    // Offsets are in the whole document, not in the `d` attribute.
    EXPECT_ERROR(from_string("<svg><path d=\"M 0 0 L 1 x\"/></svg>", MX_FORMAT_SVG), Err(pe).parse_at(0, 24));

    // Bézier curves and elliptical arcs are valid SVG that medax does not
    // support (header: MX_ERR_UNSUPPORTED "The input uses a feature medax does
    // not support (Bézier, ellipse)").
    const Err un = Err(MX_ERR_UNSUPPORTED);
    EXPECT_ERROR(from_string("M 0 0 C 1 1 2 2 3 3 Z", MX_FORMAT_SVG), Err(un).status_only().says("zier"));
    EXPECT_ERROR(from_string("M 0 0 L 4 0 Q 5 1 4 2 L 0 2 Z", MX_FORMAT_SVG), Err(un).status_only());
    EXPECT_ERROR(from_string("M 0 0 L 4 0 A 1 2 0 0 1 4 2 L 0 2 Z", MX_FORMAT_SVG),
                 Err(un).status_only().says("elliptical"));
}

void test_io() {
    mt::begin_case("I/O errors");
    const std::string missing = "/nonexistent-medax-dir/shape.json";
    EXPECT_ERROR(from_file(missing.c_str(), MX_FORMAT_AUTO), Err(MX_ERR_IO).says("shape.json"));
    EXPECT_ERROR(from_file(missing.c_str(), MX_FORMAT_JSON), Err(MX_ERR_IO));
    EXPECT_ERROR(from_file("/", MX_FORMAT_AUTO), Err(MX_ERR_IO));  // a directory
    auto shape = good_shape();
    mx_clear_last_error();
    EXPECT_ERROR(mx_shape2d_write_svg(shape.get(), "/nonexistent-medax-dir/out.svg"), Err(MX_ERR_IO));
    // A parse error inside a file is still a parse error (with its position).
    const std::string path =
        (fs::temp_directory_path() / ("medax_bad_input_" + std::to_string(::getpid()) + ".json")).string();
    {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        MT_CHECK(f != nullptr);
        if (f) {
            std::fputs("{\"loops\":\n\n  [[[0, 0], [1, 0], [1, 1]],]}", f);
            std::fclose(f);
        }
    }
    // The trailing comma is detected at the `]` after it (line 3, column 29).
    EXPECT_ERROR(from_file(path.c_str(), MX_FORMAT_AUTO), Err(MX_ERR_PARSE).parse_at(3, 29));
    std::error_code ec;
    fs::remove(path, ec);
}

void test_queries_out_of_range() {
    mt::begin_case("index out of range / buffer too small");
    auto shape = good_shape();
    const mx_shape2d* s = shape.get();
    if (!s) return;
    const Err ior = Err(MX_ERR_INDEX_OUT_OF_RANGE);
    size_t n = 777;
    int32_t u = 777;
    mx_joint_kind joint = MX_JOINT_SMOOTH;
    mx_element el{};
    el.x0 = 777.0;
    std::vector<double> buf(64, -1.0);
    mx_clear_last_error();
    EXPECT_ERROR(mx_shape2d_loop_size(s, 2, &n), Err(ior).says("2"));
    EXPECT_ERROR(mx_shape2d_loop_size(s, static_cast<size_t>(-1), &n), ior);
    EXPECT_ERROR(mx_shape2d_loop_reversed(s, 2, &u), ior);
    EXPECT_ERROR(mx_shape2d_loop_vertices(s, 2, buf.data(), buf.size() / 3, &n), ior);
    EXPECT_ERROR(mx_shape2d_element(s, 2, 0, &el), ior);
    EXPECT_ERROR(mx_shape2d_element(s, 0, 4, &el), Err(ior).says("4"));
    EXPECT_ERROR(mx_shape2d_element(s, 1, 100, &el), ior);
    EXPECT_ERROR(mx_shape2d_joint(s, 0, 4, &joint), ior);
    EXPECT_ERROR(mx_shape2d_joint(s, 5, 0, &joint), ior);
    MT_CHECK_EQ(n, size_t{777});
    MT_CHECK_EQ(u, 777);
    MT_CHECK(joint == MX_JOINT_SMOOTH);
    MT_CHECK_EQ(el.x0, 777.0);
    for (double v : buf) MT_CHECK_EQ(v, -1.0);

    // Buffer too small (capacity in vertices): nothing is written.
    const Err small = Err(MX_ERR_BUFFER_TOO_SMALL);
    EXPECT_ERROR(mx_shape2d_loop_vertices(s, 0, buf.data(), 3, &n), Err(small).says("4 vertices"));
    EXPECT_ERROR(mx_shape2d_loop_vertices(s, 1, buf.data(), 1, &n), small);
    MT_CHECK_EQ(n, size_t{777});
    for (double v : buf) MT_CHECK_EQ(v, -1.0);
    // Size query: capacity 0 writes only the count.
    MT_CHECK_OK(mx_shape2d_loop_vertices(s, 0, nullptr, 0, &n));
    MT_CHECK_EQ(n, size_t{4});
    n = 777;
    MT_CHECK_OK(mx_shape2d_loop_vertices(s, 0, buf.data(), 4, &n));
    MT_CHECK_EQ(n, size_t{4});
    MT_CHECK_EQ(buf[12], -1.0);
}

void test_last_error_message() {
    mt::begin_case("mx_last_error_message");
    mx_clear_last_error();
    MT_CHECK_EQ(mx_last_error_length(), size_t{0});
    MT_CHECK_EQ(mx_last_error_message(nullptr, 0), size_t{0});
    char untouched[4] = {'a', 'b', 'c', '\0'};
    MT_CHECK_EQ(mx_last_error_message(untouched, sizeof untouched), size_t{0});
    mx_error_info info;
    std::memset(&info, 0x55, sizeof info);
    MT_CHECK_OK(mx_last_error_info(&info));
    MT_CHECK_EQ(info.status, MX_OK);
    MT_CHECK(info.loop_index == -1 && info.element == -1 && info.other_loop_index == -1 && info.other_element == -1);
    MT_CHECK(info.has_position == 0 && info.line == -1 && info.column == -1);

    // Provoke a NaN error: "loop 0 element 2 ..."
    MT_CHECK_EQ(bulges({{0, 0, 0, 1, 0, 0, kNaN, 1, 0, 0, 1, 0}}), MX_ERR_NON_FINITE);
    const size_t len = mx_last_error_message(nullptr, 0);  // size query
    MT_CHECK(len > 10);
    MT_CHECK_EQ(mx_last_error_length(), len);
    std::vector<char> full(len, 'X');
    MT_CHECK_EQ(mx_last_error_message(full.data(), full.size()), len);
    MT_CHECK_EQ(full[len - 1], '\0');
    MT_CHECK_EQ(std::strlen(full.data()), len - 1);
    const std::string text(full.data());
    MT_CHECK(text.find("loop 0") != std::string::npos && text.find("element 2") != std::string::npos);

    // Truncation: always NUL-terminated, returns the full length, no overrun.
    for (size_t cap : {size_t{1}, size_t{2}, size_t{8}, len - 1}) {
        std::vector<char> small(cap + 8, 'Z');
        MT_CHECK_EQ(mx_last_error_message(small.data(), cap), len);
        MT_CHECK_EQ(small[cap - 1], '\0');
        MT_CHECK_EQ(std::strlen(small.data()), cap - 1);
        MT_CHECK(std::string(small.data()) == text.substr(0, cap - 1));
        for (size_t i = cap; i < small.size(); ++i) MT_CHECK_EQ(small[i], 'Z');
    }
    // A NULL buffer with a non-zero length is still only a size query.
    MT_CHECK_EQ(mx_last_error_message(nullptr, 100), len);
    // Reading does not clear; mx_clear_last_error does.
    MT_CHECK_EQ(mx_last_error_length(), len);
    mx_clear_last_error();
    MT_CHECK_EQ(mx_last_error_length(), size_t{0});
    MT_CHECK_OK(mx_last_error_info(&info));
    MT_CHECK_EQ(info.status, MX_OK);
}

}  // namespace

int main() {
    test_null_arguments();
    test_invalid_arguments();
    test_empty_and_too_few();
    test_non_finite_and_range();
    test_degenerate();
    test_intersections();
    test_holes();
    test_elements_input();
    test_parse_errors();
    test_io();
    test_queries_out_of_range();
    test_last_error_message();
    return mt::finish("bad_input");
}
