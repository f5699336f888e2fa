// Unit balls through the medax C API (thesis chapter 3): presets, a ball
// from vertices in either orientation, distances worked out here by hand
// (L-infinity, L1, the mirrored triangle), the vertices copied out, and
// polygons that are not balls refused with the vertex named and the
// out-params left alone.

#include "test_support.hpp"

#include <cmath>

namespace {

double distance(const mx_ball* b, double x0, double y0, double x1, double y1) {
    const double from[2] = {x0, y0}, to[2] = {x1, y1};
    double d = -1.0;
    MT_CHECK_OK(mx_ball_distance2(b, from, to, &d));
    return d;
}

void presets() {
    mt::begin_case("presets");
    mx_ball* square = nullptr;
    MT_CHECK_OK(mx_ball_square(&square));
    size_t dim = 0;
    size_t n = 0;
    MT_CHECK_OK(mx_ball_dimension(square, &dim));
    MT_CHECK_EQ(dim, size_t{2});
    MT_CHECK_OK(mx_ball_vertex_count(square, &n));
    MT_CHECK_EQ(n, size_t{4});
    double xy[8] = {0};
    size_t count = 0;
    MT_CHECK_OK(mx_ball_vertices(square, nullptr, 0, &count));  // size query
    MT_CHECK_EQ(count, size_t{4});
    count = 0;
    MT_CHECK_OK(mx_ball_vertices(square, xy, 4, &count));
    MT_CHECK_EQ(count, size_t{4});
    const double ccw[8] = {1, -1, 1, 1, -1, 1, -1, -1};
    for (int i = 0; i < 8; ++i) MT_CHECK_EQ(xy[i], ccw[i]);
    double small[6] = {7, 7, 7, 7, 7, 7};
    count = 77;
    MT_CHECK_STATUS(mx_ball_vertices(square, small, 3, &count), MX_ERR_BUFFER_TOO_SMALL);
    MT_CHECK_EQ(small[0], 7.0);
    MT_CHECK_EQ(count, size_t{77});
    MT_CHECK_NEAR(distance(square, 1, 1, 4, -1), 3.0, 1e-15);
    int32_t sym = 0;
    MT_CHECK_OK(mx_ball_is_symmetric(square, &sym));
    MT_CHECK_EQ(sym, 1);
    mx_ball_free(square);

    mx_ball* diamond = nullptr;
    MT_CHECK_OK(mx_ball_diamond(&diamond));
    MT_CHECK_NEAR(distance(diamond, 1, 1, 4, -1), 5.0, 1e-15);
    mx_ball_free(diamond);

    // The triangle (a vertex up) is not symmetric: straight up costs 1 per
    // unit, straight down 2; its mirror swaps the two.
    mx_ball *tri = nullptr, *mirror = nullptr;
    MT_CHECK_OK(mx_ball_triangle(&tri));
    MT_CHECK_OK(mx_ball_mirrored(tri, &mirror));
    MT_CHECK_NEAR(distance(tri, 0, 0, 0, 3), 3.0, 1e-15);
    MT_CHECK_NEAR(distance(tri, 0, 0, 0, -3), 6.0, 1e-15);
    MT_CHECK_NEAR(distance(mirror, 0, 0, 0, -3), 3.0, 1e-15);
    MT_CHECK_OK(mx_ball_is_symmetric(tri, &sym));
    MT_CHECK_EQ(sym, 0);
    mx_ball_free(tri);
    mx_ball_free(mirror);

    // A 64-gon is within cos(pi/64) of the Euclidean distance.
    mx_ball* round = nullptr;
    MT_CHECK_OK(mx_ball_regular(64, 0.1, &round));
    const double d = distance(round, 0, 0, 3, 4);
    MT_CHECK(d >= 5.0 * (1 - 1e-12) && d <= 5.0 / std::cos(3.14159265358979323846 / 64) * (1 + 1e-12));
    mx_ball_free(round);
}

void from_vertices_and_bad_balls() {
    mt::begin_case("from vertices");
    // Clockwise: stored counter-clockwise.
    const double cw[8] = {1, 1, 1, -1, -1, -1, -1, 1};
    mx_ball* b = nullptr;
    MT_CHECK_OK(mx_ball_from_vertices2(cw, 4, &b));
    MT_CHECK_NEAR(distance(b, 0, 0, -2, 0.5), 2.0, 1e-15);
    mx_ball_free(b);

    mx_ball* untouched = reinterpret_cast<mx_ball*>(0x1);
    const double dart[8] = {2, 0, 0, 2, 0.5, 0, 0, -2};
    MT_CHECK_STATUS(mx_ball_from_vertices2(dart, 4, &untouched), MX_ERR_INVALID_BALL);
    mx_error_info info{};
    MT_CHECK_OK(mx_last_error_info(&info));
    MT_CHECK_EQ(info.element, int64_t{2});
    const double outside[6] = {1, 1, 2, 1, 1, 2};
    MT_CHECK_STATUS(mx_ball_from_vertices2(outside, 3, &untouched), MX_ERR_INVALID_BALL);
    const double nan[6] = {1, 0, 0, 1, NAN, -1};
    MT_CHECK_STATUS(mx_ball_from_vertices2(nan, 3, &untouched), MX_ERR_INVALID_BALL);
    MT_CHECK_OK(mx_last_error_info(&info));
    MT_CHECK_EQ(info.element, int64_t{2});
    MT_CHECK_STATUS(mx_ball_from_vertices2(cw, 2, &untouched), MX_ERR_INVALID_BALL);
    MT_CHECK_STATUS(mx_ball_from_vertices2(nullptr, 3, &untouched), MX_ERR_NULL_ARGUMENT);
    MT_CHECK_STATUS(mx_ball_regular(2, 0.0, &untouched), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK(untouched == reinterpret_cast<mx_ball*>(0x1));
    size_t n = 0;
    MT_CHECK_STATUS(mx_ball_vertex_count(nullptr, &n), MX_ERR_NULL_ARGUMENT);
    double out = 0;
    MT_CHECK_STATUS(mx_ball_distance2(nullptr, cw, cw, &out), MX_ERR_NULL_ARGUMENT);
    mx_ball_free(nullptr);
}

void parsed() {
    mt::begin_case("parse");
    mx_ball* b = nullptr;
    MT_CHECK_OK(mx_ball_parse("ngon:6:30", &b));
    size_t n = 0;
    MT_CHECK_OK(mx_ball_vertex_count(b, &n));
    MT_CHECK_EQ(n, size_t{6});
    mx_ball_free(b);
    MT_CHECK_OK(mx_ball_parse("{\"vertices\": [[0, 1], [-1, -1], [1, -1]]}", &b));
    MT_CHECK_NEAR(distance(b, 0, 0, 0, 2), 2.0, 1e-15);
    mx_ball_free(b);
    mx_ball* untouched = reinterpret_cast<mx_ball*>(0x1);
    MT_CHECK_STATUS(mx_ball_parse("{\"vertices\": [[0, 1]", &untouched), MX_ERR_PARSE);
    MT_CHECK_STATUS(mx_ball_parse("circle", &untouched), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_ball_parse(nullptr, &untouched), MX_ERR_NULL_ARGUMENT);
    MT_CHECK(untouched == reinterpret_cast<mx_ball*>(0x1));
}

}  // namespace

int main() {
    presets();
    from_vertices_and_bad_balls();
    parsed();
    return mt::finish("c_api_ball");
}
