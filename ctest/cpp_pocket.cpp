// A pocketing job through the C++ layer (include/medax.hpp), checked from
// outside: a 100 x 60 plate with a round hole of radius 10, tool radius 3,
// stepover 2.5. Every point of every ring (its vertices and the middle of
// each element, arcs included) must lie exactly at the ring's offset
// distance from the plate's boundary, measured here from the plate's own
// geometry (the rectangle's sides and the hole's circle), and the ring tree
// must step one level at a time. Options left at their defaults (no tool)
// must throw medax::error carrying MX_ERR_INVALID_ARGUMENT and naming the
// field. Built with -Wall -Wextra -Werror.

#include "test_support.hpp"

#include <medax.hpp>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kWidth = 100, kHeight = 60, kHoleX = 70, kHoleY = 30, kHoleR = 10;

// Distance from an interior point to the plate's boundary.
double boundary_distance(double x, double y) {
    const double sides = std::min(std::min(x, kWidth - x), std::min(y, kHeight - y));
    return std::min(sides, std::hypot(x - kHoleX, y - kHoleY) - kHoleR);
}

medax::Shape plate() {
    // The hole as two half circles (bulge 1), given counter-clockwise: the
    // library stores holes clockwise and says so.
    return medax::Shape::from_bulges({0, 0, 0, kWidth, 0, 0, kWidth, kHeight, 0, 0, kHeight, 0,  //
                                      kHoleX + kHoleR, kHoleY, 1, kHoleX - kHoleR, kHoleY, 1},
                                     {4, 2});
}

void rings_lie_at_their_distance() {
    mt::begin_case("pocket rings at their offset distance");
    const medax::Shape shape = plate();
    MT_CHECK_EQ(shape.loop_count(), size_t{2});
    MT_CHECK_NEAR(shape.area(), kWidth * kHeight - std::acos(-1.0) * kHoleR * kHoleR, 1e-9);
    MT_CHECK_EQ(shape.loop_vertices(1).size(), size_t{6});
    const medax::Offsets offsets = medax::Offsets::compute(shape);
    mx_pocket_options o = medax::pocket_options();
    o.tool_radius = 3;
    o.stepover = 2.5;
    const medax::Pocket pocket = medax::Pocket::compute(offsets, o);
    const mx_pocket_info info = pocket.info();
    MT_CHECK(info.ring_count >= 8);
    size_t points = 0, arcs = 0;
    double worst = 0;
    for (size_t i = 0; i < info.ring_count; ++i) {
        const mx_pocket_ring ring = pocket.ring(i);
        MT_CHECK_NEAR(ring.distance, o.tool_radius + static_cast<double>(ring.level) * o.stepover, 1e-12);
        if (ring.has_parent) MT_CHECK_EQ(pocket.ring(ring.parent).level + 1, ring.level);
        const medax::view<double> xyb(ring.loops.xyb, ring.loops.xyb_len);
        size_t start = 0;
        for (size_t l = 0; l < ring.loops.count; ++l) {
            const size_t n = ring.loops.lengths[l];
            for (size_t k = 0; k < n; ++k) {
                const double* p = &xyb[3 * (start + k)];
                const double* q = &xyb[3 * (start + (k + 1) % n)];
                // The element's middle: the chord's middle pushed out by
                // the sagitta, to the right of the chord for b > 0.
                const double b = p[2], dx = q[0] - p[0], dy = q[1] - p[1];
                const double mx = 0.5 * (p[0] + q[0]) + 0.5 * b * dy, my = 0.5 * (p[1] + q[1]) - 0.5 * b * dx;
                arcs += b != 0.0;
                for (const auto& [x, y] : {std::pair{p[0], p[1]}, std::pair{mx, my}}) {
                    worst = std::max(worst, std::fabs(boundary_distance(x, y) - ring.distance));
                    ++points;
                }
            }
            start += n;
        }
        MT_CHECK_EQ(3 * start, ring.loops.xyb_len);
    }
    MT_CHECK(points > 50);
    MT_CHECK(arcs > 0);  // the rings round the hole and the corners
    MT_CHECK(worst < 1e-9);
    if (worst >= 1e-9) std::printf("worst distance error %g\n", worst);
}

void no_tool_throws() {
    mt::begin_case("no tool radius throws medax::error");
    const medax::Offsets offsets = medax::Offsets::compute(plate());
    mx_pocket_options o = medax::pocket_options();  // tool_radius 0
    o.stepover = 2.5;
    bool thrown = false;
    try {
        medax::Pocket::compute(offsets, o);
    } catch (const medax::error& e) {
        thrown = true;
        MT_CHECK_EQ(e.status(), MX_ERR_INVALID_ARGUMENT);
        MT_CHECK(std::string(e.what()).find("tool_radius") != std::string::npos);
    }
    MT_CHECK(thrown);
}

}  // namespace

int main() {
    rings_lie_at_their_distance();
    no_tool_throws();
    return mt::finish("cpp_pocket");
}
