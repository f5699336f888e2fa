// The 3D medial axis through the installed C API: a box with a turned
// box-shaped cavity (concave corners: a ball facet rests on them) under a
// turned tetrahedron. Every axis vertex lies in the material with a
// positive radius below the wall thickness bound, every triangle in
// exactly one sheet, the cavity's corners give FV classes, and a progress
// callback that answers nonzero cancels with the out-param left alone.

#include "test_support.hpp"

#include <cmath>

namespace {

// The eight corners of a box [lo, hi], turned about y by `angle`.
void box(std::vector<double>& xyz, std::vector<uint32_t>& tri, const double lo[3], const double hi[3], double angle,
         bool inward) {
    const uint32_t base = static_cast<uint32_t>(xyz.size() / 3);
    const double c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < 8; ++i) {
        const double x = (i & 1) ? hi[0] : lo[0], y = (i & 2) ? hi[1] : lo[1], z = (i & 4) ? hi[2] : lo[2];
        xyz.insert(xyz.end(), {c * x - s * z, y, s * x + c * z});
    }
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        const uint32_t a[2][3] = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
        for (const auto& t : a) {
            if (inward) {
                tri.insert(tri.end(), {base + t[0], base + t[2], base + t[1]});
            } else {
                tri.insert(tri.end(), {base + t[0], base + t[1], base + t[2]});
            }
        }
    }
}

int cancel_now(double, void* user) {
    ++*static_cast<int*>(user);
    return 1;
}

int count_calls(double fraction, void* user) {
    MT_CHECK(fraction >= 0.0 && fraction <= 1.0);
    ++*static_cast<int*>(user);
    return 0;
}

void cavity() {
    mt::begin_case("box with a turned cavity");
    std::vector<double> xyz;
    std::vector<uint32_t> tri;
    const double lo[3] = {-6, -6, -6}, hi[3] = {6, 6, 6}, ilo[3] = {-2, -2.5, -3}, ihi[3] = {3, 2, 1.5};
    box(xyz, tri, lo, hi, 0.0, false);
    box(xyz, tri, ilo, ihi, 0.4, true);
    mx_mesh3d* mesh = nullptr;
    MT_CHECK_OK(mx_mesh3d_from_arrays(xyz.data(), xyz.size(), tri.data(), tri.size(), nullptr, &mesh));
    mx_ball *tetra = nullptr, *ball = nullptr;
    MT_CHECK_OK(mx_ball_tetrahedron(&tetra));
    const double turn[3] = {0.2, 0.4, -0.3};
    MT_CHECK_OK(mx_ball_rotated3(tetra, turn, &ball));

    mx_axis3d_options o;
    MT_CHECK_OK(mx_axis3d_options_init(&o, sizeof o));
    int calls = 0;
    o.progress = count_calls;
    o.user = &calls;
    mx_axis3d* axis = nullptr;
    MT_CHECK_OK(mx_mesh3d_axis(mesh, ball, &o, &axis));
    MT_CHECK(calls >= 2);

    size_t n = 0, t = 0, s = 0;
    MT_CHECK_OK(mx_axis3d_vertices(axis, nullptr, 0, &n));
    MT_CHECK_OK(mx_axis3d_triangles(axis, nullptr, 0, &t));
    MT_CHECK_OK(mx_axis3d_sheet_count(axis, &s));
    MT_CHECK(n > 0 && t > 0 && s > 0);
    std::vector<double> xyzr(4 * n);
    MT_CHECK_OK(mx_axis3d_vertices(axis, xyzr.data(), n, &n));
    for (size_t i = 0; i < n; ++i) {
        const double p[3] = {xyzr[4 * i], xyzr[4 * i + 1], xyzr[4 * i + 2]};
        mx_point_side side = MX_OUTSIDE;
        MT_CHECK_OK(mx_mesh3d_side(mesh, p, &side));
        MT_CHECK(side == MX_INSIDE);
        // Positive, and no ball of the tetrahedron (inradius 1/√3 of its
        // circumradius √3) fits with radius beyond the box's half-width
        // times √3.
        MT_CHECK(xyzr[4 * i + 3] > 0.0 && xyzr[4 * i + 3] < 6.0 * std::sqrt(3.0));
    }
    std::vector<int> seen(t, 0);
    int fv = 0;
    for (size_t k = 0; k < s; ++k) {
        mx_axis3d_sheet sheet;
        MT_CHECK_OK(mx_axis3d_get_sheet(axis, k, &sheet));
        std::vector<uint32_t> ids(sheet.triangle_count);
        size_t got = 0;
        MT_CHECK_OK(mx_axis3d_sheet_triangles(axis, k, ids.data(), ids.size(), &got));
        MT_CHECK_EQ(got, sheet.triangle_count);
        for (uint32_t id : ids) {
            if (id < t) ++seen[id];
        }
        for (const auto& c : sheet.classes) {
            if (c.kind == MX_CONTACT3_FV) {
                MT_CHECK(c.ball_part == MX_BALL_FACET && c.surface_part == MX_SURFACE_VERTEX);
                ++fv;
            }
        }
    }
    MT_CHECK(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
    MT_CHECK(fv > 0);
    mx_axis3d_free(axis);

    // Cancelled at once: MX_ERR_CANCELLED, the out-param left alone.
    calls = 0;
    o.progress = cancel_now;
    mx_axis3d* untouched = reinterpret_cast<mx_axis3d*>(0x10);
    MT_CHECK_STATUS(mx_mesh3d_axis(mesh, ball, &o, &untouched), MX_ERR_CANCELLED);
    MT_CHECK(untouched == reinterpret_cast<mx_axis3d*>(0x10));
    MT_CHECK_EQ(calls, 1);
    mx_axis3d_free(nullptr);
    mx_ball_free(ball);
    mx_ball_free(tetra);
    mx_mesh3d_free(mesh);
}

}  // namespace

int main() {
    cavity();
    return mt::finish("c_api_axis3d");
}
