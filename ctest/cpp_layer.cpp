// The C++ layer (include/medax.hpp) over the C API: RAII handles moved and
// freed (valgrind runs this too), exceptions carrying the status and the
// error info, option defaults, views over borrowed arrays, and the
// results the C tests check by hand (a 6 x 2 rectangle under the square:
// one axis edge from (1, 1) to (5, 1); offset at 0.5 of area 5; grown by
// 0.5 to 7 x 3). Built as C++17 and as C++20 with -Wall -Wextra -Werror.

#include "test_support.hpp"

#include <medax.hpp>

#include <cmath>
#include <utility>

namespace {

medax::Shape rectangle() {
    return medax::Shape::from_bulges({0, 0, 0, 6, 0, 0, 6, 2, 0, 0, 2, 0}, {4});
}

void axis_and_offsets_under_the_square() {
    mt::begin_case("axis and offsets under the square");
    medax::Shape shape = rectangle();
    MT_CHECK_EQ(shape.loop_count(), size_t{1});
    MT_CHECK_NEAR(shape.area(), 12.0, 1e-12);
    medax::Ball square = medax::Ball::square();
    MT_CHECK_EQ(square.vertices().size(), size_t{8});
    MT_CHECK_NEAR(square.distance(0, 0, 2, -1), 2.0, 1e-15);
    medax::Axis axis = medax::Axis::compute(shape, &square);
    MT_CHECK_EQ(axis.edge_count(), size_t{1});
    const mx_axis_edge e = axis.edge(0);
    const mx_axis_node a = axis.node(e.from), b = axis.node(e.to);
    MT_CHECK_NEAR(std::fabs(a.x - b.x), 4.0, 1e-12);
    MT_CHECK_NEAR(a.r, 1.0, 1e-12);
    MT_CHECK_EQ(axis.contacts(0).kind[0], MX_CONTACT_EE);
    MT_CHECK_EQ(axis.sample(0, 1e-3).size(), size_t{6});
    medax::OffsetLayer inner = axis.offset(0.5);
    MT_CHECK_NEAR(inner.info().area, 5.0, 1e-12);
    const medax::OffsetLoop loop = inner.loop(0);
    MT_CHECK_EQ(loop.xyb.size(), 3 * loop.info.vertex_count);
    double bulges = 0.0;
    for (size_t v = 0; v < loop.info.vertex_count; ++v) bulges += std::fabs(loop.xyb[3 * v + 2]);
    MT_CHECK_EQ(bulges, 0.0);
    MT_CHECK_NEAR(medax::outer_offset(shape, &square, 0.5).info().area, 21.0, 1e-9);
    // Euclidean: the same through the prepared offsets.
    medax::Offsets offsets = medax::Offsets::compute(shape);
    MT_CHECK_NEAR(offsets.layer(0.5).info().area, 5.0, 1e-9);
    MT_CHECK_NEAR(medax::outer_offset(shape, nullptr, 0.5).info().area, 20.0 + 0.25 * std::acos(-1.0), 1e-9);
}

void voronoi_and_moves() {
    mt::begin_case("voronoi under a ball, handles moved");
    const double points[] = {0, 0, 2, 0, 1, 1.5};
    mx_sites sites{};
    sites.points_xy = points;
    sites.point_count = 3;
    medax::Ball hexagon = medax::Ball::regular(6, 0.1);
    medax::Voronoi vd = medax::Voronoi::compute(sites, &hexagon);
    MT_CHECK_EQ(vd.info().region_count, size_t{3});
    MT_CHECK(vd.axis() != nullptr);
    const mx_nearest_site near = vd.nearest_site(1.9, 0.1);
    MT_CHECK_EQ(near.site.index, size_t{1});
    MT_CHECK_NEAR(near.distance, hexagon.distance(1.9, 0.1, 2.0, 0.0), 1e-12);
    medax::Voronoi moved = std::move(vd);
    MT_CHECK(!vd);
    MT_CHECK(static_cast<bool>(moved));
    medax::Voronoi other;
    other = std::move(moved);
    MT_CHECK_EQ(other.info().region_count, size_t{3});
}

void errors_are_exceptions() {
    mt::begin_case("errors are exceptions");
    bool thrown = false;
    try {
        medax::Ball::from_vertices({2, 0, 0, 2, 0.5, 0, 0, -2});  // a dart: not convex at vertex 2
    } catch (const medax::error& e) {
        thrown = true;
        MT_CHECK_EQ(e.status(), MX_ERR_INVALID_BALL);
        MT_CHECK_EQ(e.info().element, int64_t{2});
        MT_CHECK(std::string(e.what()).find("mx_ball_from_vertices2") == 0);
    }
    MT_CHECK(thrown);
    thrown = false;
    try {
        medax::Shape arc = medax::Shape::from_bulges({0, 0, 0.5, 4, 0, 0, 4, 4, 0, 0, 4, 0}, {4});
        medax::Ball square = medax::Ball::square();
        medax::Axis::compute(arc, &square);
    } catch (const medax::error& e) {
        thrown = true;
        MT_CHECK_EQ(e.status(), MX_ERR_UNSUPPORTED);
        MT_CHECK_EQ(e.info().element, int64_t{0});
    }
    MT_CHECK(thrown);
    mx_axis_options o = medax::axis_options();
    MT_CHECK_EQ(o.struct_size, sizeof o);
}

}  // namespace

int main() {
    axis_and_offsets_under_the_square();
    voronoi_and_moves();
    errors_are_exceptions();
    return mt::finish("cpp_layer");
}
