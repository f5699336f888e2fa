// Offsets, pockets and V-carves through the installed C API, checked with
// geometry computed here from the input arrays: random plates (a rectangle
// whose top is an arc, with round and square holes in grid cells); every
// offset loop's vertices and arc points at distance |d| from the boundary
// within 1e-9 of the diagonal, the layer's area equal to the area of its
// bulge loops, regions that partition the loops (outer counter-clockwise,
// holes clockwise); pocket rings at r + k·s with a consistent tree and a
// machining order that visits children first (inside-out) or last, each
// ring's points at its distance; layer areas decreasing with the distance,
// the shape's own between the outer and inner ones; V-carve
// depths equal to the distance to the boundary over tan(α/2), capped
// (within the paths' chordal tolerance);
// errors leave out-params alone.
//
// Usage: c_api_offset [scenes]   (default 12)

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct P {
    double x, y;
};

double dist(P a, P b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

// The element from a to b with the given bulge: a segment (bulge 0) or an
// arc with centre, radius, start angle and signed sweep.
struct Element {
    P a, b;
    double bulge;
    bool arc() const { return bulge != 0.0; }
    double sweep() const { return 4.0 * std::atan(bulge); }
    P centre() const {
        const double c = dist(a, b), k = 0.5 * c * (1.0 - bulge * bulge) / (2.0 * bulge);
        const P n{-(b.y - a.y) / c, (b.x - a.x) / c};  // left normal of the chord
        return {0.5 * (a.x + b.x) + k * n.x, 0.5 * (a.y + b.y) + k * n.y};
    }
    double radius() const { return dist(centre(), a); }
    P at(double t) const {
        if (!arc()) return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        const P c = centre();
        const double r = radius(), phi = std::atan2(a.y - c.y, a.x - c.x) + t * sweep();
        return {c.x + r * std::cos(phi), c.y + r * std::sin(phi)};
    }
    double distance(P p) const {
        if (!arc()) {
            const double dx = b.x - a.x, dy = b.y - a.y;
            const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
            return dist(p, {a.x + t * dx, a.y + t * dy});
        }
        const P c = centre();
        const double s = sweep(), start = std::atan2(a.y - c.y, a.x - c.x);
        double delta = std::atan2(p.y - c.y, p.x - c.x) - start;
        if (s < 0) delta = -delta;
        delta = std::fmod(delta + 4.0 * kPi, 2.0 * kPi);
        if (delta <= std::fabs(s)) return std::fabs(dist(p, c) - radius());
        return std::min(dist(p, a), dist(p, b));
    }
    // Signed area between the chord and the arc (counter-clockwise positive).
    double segment_area() const {
        if (!arc()) return 0.0;
        const double r = radius(), s = sweep();
        return 0.5 * r * r * (s - std::sin(s));
    }
};

using Loop = std::vector<double>;  // x, y, bulge triples

std::vector<Element> elements(const double* xyb, size_t n) {
    std::vector<Element> out;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        out.push_back({{xyb[3 * i], xyb[3 * i + 1]}, {xyb[3 * j], xyb[3 * j + 1]}, xyb[3 * i + 2]});
    }
    return out;
}

double loop_area(const double* xyb, size_t n) {
    double a = 0.0;
    for (const Element& e : elements(xyb, n)) a += 0.5 * (e.a.x * e.b.y - e.b.x * e.a.y) + e.segment_area();
    return a;
}

struct Scene {
    std::vector<Loop> loops;
    std::vector<Element> boundary;
    double diagonal;
    double distance(P p) const {
        double d = INFINITY;
        for (const Element& e : boundary) d = std::min(d, e.distance(p));
        return d;
    }
};

Scene plate(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int nx = 2 + static_cast<int>(3 * u(rng)), ny = 2 + static_cast<int>(2 * u(rng));
    const double w = 2.0 * nx + 2.0, h = 2.0 * ny + 2.0;
    Scene s;
    // The top runs right to left and bulges up (counter-clockwise arc).
    s.loops.push_back({0, 0, 0, w, 0, 0, w, h, 0.1 + 0.2 * u(rng), 0, h, 0});
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            if (u(rng) < 0.3) continue;
            const double cx = 2.0 + 2.0 * i + 0.4 * (u(rng) - 0.5), cy = 2.0 + 2.0 * j + 0.4 * (u(rng) - 0.5);
            const double r = 0.25 + 0.35 * u(rng);
            if (u(rng) < 0.5) {
                s.loops.push_back({cx - r, cy, 1.0, cx + r, cy, 1.0});
            } else {
                s.loops.push_back({cx - r, cy - r, 0, cx - r, cy + r, 0, cx + r, cy + r, 0, cx + r, cy - r, 0});
            }
        }
    for (const Loop& l : s.loops) {
        const auto e = elements(l.data(), l.size() / 3);
        s.boundary.insert(s.boundary.end(), e.begin(), e.end());
    }
    s.diagonal = std::hypot(w, h * 1.2);
    return s;
}

// Counts the points of a loop (vertices and points along each element)
// that are not at distance |d| from the scene's boundary.
void check_distance(const Scene& s, const double* xyb, size_t n, double d, mt::Failures& far) {
    for (const Element& e : elements(xyb, n))
        for (double t : {0.0, 0.25, 0.5, 0.75}) {
            const P p = e.at(t);
            const double off = std::fabs(s.distance(p) - std::fabs(d));
            if (off > 1e-9 * s.diagonal)
                far.add("d " + mt::show(d) + " at (" + mt::show(p.x) + ", " + mt::show(p.y) + "): " + mt::show(off));
        }
}

// The area of the scene's shape: its outer loop less its holes.
double shape_area(const Scene& s) {
    double a = std::fabs(loop_area(s.loops[0].data(), s.loops[0].size() / 3));
    for (size_t i = 1; i < s.loops.size(); ++i) a -= std::fabs(loop_area(s.loops[i].data(), s.loops[i].size() / 3));
    return a;
}

// One layer against the scene: distances, area, regions.
void check_layer(const Scene& s, const mx_offset_layer* layer, double d) {
    mx_offset_layer_info info{};
    if (!MT_CHECK_OK(mx_offset_layer_get_info(layer, &info))) return;
    MT_CHECK_EQ(info.distance, d);
    mt::Failures far{"loop point off the offset distance"};
    double area = 0.0;
    std::vector<int> seen(info.loop_count, 0);
    for (size_t i = 0; i < info.loop_count; ++i) {
        mx_offset_loop l{};
        if (!MT_CHECK_OK(mx_offset_layer_get_loop(layer, i, &l))) continue;
        const double a = loop_area(l.xyb, l.vertex_count);
        MT_CHECK_NEAR(a, l.area, 1e-9);
        MT_CHECK_EQ(l.is_hole, a < 0 ? 1 : 0);
        area += a;
        check_distance(s, l.xyb, l.vertex_count, d, far);
    }
    MT_CHECK_EQ(far.count, size_t{0});
    MT_CHECK(std::fabs(area - info.area) <= 1e-9 * std::max(1.0, std::fabs(area)));
    for (size_t r = 0; r < info.region_count; ++r) {
        mx_offset_region reg{};
        if (!MT_CHECK_OK(mx_offset_layer_get_region(layer, r, &reg))) continue;
        mx_offset_loop outer{};
        MT_CHECK_OK(mx_offset_layer_get_loop(layer, reg.outer, &outer));
        MT_CHECK_EQ(outer.is_hole, 0);
        MT_CHECK_EQ(outer.region, r);
        ++seen[reg.outer];
        for (size_t k = 0; k < reg.hole_count; ++k) {
            mx_offset_loop hole{};
            MT_CHECK_OK(mx_offset_layer_get_loop(layer, reg.holes[k], &hole));
            MT_CHECK_EQ(hole.is_hole, 1);
            MT_CHECK_EQ(hole.region, r);
            ++seen[reg.holes[k]];
        }
    }
    MT_CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    // The borrowed all-loops view holds the same vertices.
    mx_bulge_loops all{};
    MT_CHECK_OK(mx_offset_layer_loops(layer, &all));
    MT_CHECK_EQ(all.count, info.loop_count);
    size_t sum = 0;
    for (size_t i = 0; i < all.count; ++i) sum += all.lengths[i];
    MT_CHECK_EQ(all.xyb_len, 3 * sum);
}

// The sides of the offsets: the layers' areas strictly decrease as the
// distance grows (outer loops outside the shape, inner ones inside), with
// the shape's own area between the outer and the inner ones.
void check_sides(const Scene& s, std::vector<std::pair<double, double>> distance_area) {
    std::sort(distance_area.begin(), distance_area.end());
    for (size_t k = 1; k < distance_area.size(); ++k) {
        const auto [d0, a0] = distance_area[k - 1];
        const auto [d1, a1] = distance_area[k];
        if (a0 > 0.0) MT_CHECK(a1 < a0);
        const double shape = shape_area(s);
        if (d0 < 0.0 && d1 > 0.0) MT_CHECK(a1 < shape && shape < a0);
    }
}

void check_pocket(const Scene& s, const mx_offsets* offsets, double r, double step, uint32_t order) {
    mx_pocket_options o{};
    MT_CHECK_OK(mx_pocket_options_init(&o, sizeof o));
    o.tool_radius = r;
    o.stepover = step;
    o.order = order;
    mx_pocket* p = nullptr;
    if (!MT_CHECK_OK(mx_pocket_compute(offsets, &o, &p))) return;
    mx_pocket_info info{};
    MT_CHECK_OK(mx_pocket_get_info(p, &info));
    MT_CHECK(info.ring_count > 0);
    MT_CHECK_EQ(info.truncated, 0);
    std::vector<size_t> position(info.ring_count, info.ring_count);
    for (size_t k = 0; k < info.ring_count; ++k)
        if (MT_CHECK(info.order[k] < info.ring_count)) position[info.order[k]] = k;
    MT_CHECK(std::none_of(position.begin(), position.end(), [&](size_t k) { return k == info.ring_count; }));
    for (size_t i = 0; i < info.ring_count; ++i) {
        mx_pocket_ring ring{};
        if (!MT_CHECK_OK(mx_pocket_get_ring(p, i, &ring))) continue;
        MT_CHECK_NEAR(ring.distance, r + step * static_cast<double>(ring.level), 1e-12);
        MT_CHECK(ring.loops.count >= 1);
        mt::Failures far{"ring point off the ring's distance"};
        const double* xyb = ring.loops.xyb;
        for (size_t l = 0; l < ring.loops.count; ++l) {
            check_distance(s, xyb, ring.loops.lengths[l], ring.distance, far);
            xyb += 3 * ring.loops.lengths[l];
        }
        MT_CHECK_EQ(far.count, size_t{0});
        MT_CHECK_EQ(ring.has_parent, ring.level > 0 ? 1 : 0);
        for (size_t c = 0; c < ring.child_count; ++c) {
            mx_pocket_ring child{};
            if (!MT_CHECK_OK(mx_pocket_get_ring(p, ring.children[c], &child))) continue;
            MT_CHECK_EQ(child.level, ring.level + 1);
            MT_CHECK_EQ(child.parent, i);
            const bool child_first = position[ring.children[c]] < position[i];
            MT_CHECK_EQ(child_first, order == MX_POCKET_INSIDE_OUT);
        }
    }
    double uncut = 0.0;
    for (size_t i = 0; i < info.uncut_count; ++i) {
        mx_uncut_region u{};
        if (!MT_CHECK_OK(mx_pocket_get_uncut(p, i, &u))) continue;
        MT_CHECK(u.area > 0.0);
        MT_CHECK(u.kind == MX_UNCUT_SCALLOP || u.kind == MX_UNCUT_WALL);
        uncut += u.area;
    }
    MT_CHECK_NEAR(uncut, info.uncut_area, 1e-9);
    mx_pocket_free(p);
}

void check_vcarve(const mx_axis* axis, const Scene& s, double angle, double max_depth) {
    mx_vcarve_options o{};
    MT_CHECK_OK(mx_vcarve_options_init(&o, sizeof o));
    o.angle_deg = angle;
    o.max_depth = max_depth;
    // Paths are sampled to this chordal tolerance; where a path is cut at
    // the flat radius the cut lies on a chord, off the curve by at most it.
    o.tolerance = 1e-6 * s.diagonal;
    mx_vcarve* v = nullptr;
    if (!MT_CHECK_OK(mx_vcarve_compute(axis, &o, &v))) return;
    mx_vcarve_info info{};
    MT_CHECK_OK(mx_vcarve_get_info(v, &info));
    MT_CHECK(info.path_count > 0);
    const double slope = std::tan(0.5 * angle * kPi / 180.0);
    MT_CHECK_NEAR(info.flat_radius, max_depth * slope, 1e-12);
    mt::Failures off{"v-carve depth off the disk radius"};
    for (size_t i = 0; i < info.path_count; ++i) {
        mx_vcarve_path path{};
        if (!MT_CHECK_OK(mx_vcarve_get_path(v, i, &path))) continue;
        MT_CHECK(path.point_count >= 2);
        for (size_t q = 0; q < path.point_count; ++q) {
            const double* pt = path.xyd + 3 * q;
            const double want = std::min(s.distance({pt[0], pt[1]}) / slope, max_depth);
            if (std::fabs(pt[2] - want) > o.tolerance / slope + 1e-9 * s.diagonal)
                off.add("(" + mt::show(pt[0]) + ", " + mt::show(pt[1]) + "): " + mt::show(pt[2]) + " vs " + mt::show(want));
        }
    }
    MT_CHECK_EQ(off.count, size_t{0});
    const mx_offset_layer* flat = nullptr;
    MT_CHECK_OK(mx_vcarve_flat(v, &flat));
    mx_offset_layer_info fi{};
    MT_CHECK_OK(mx_offset_layer_get_info(flat, &fi));
    MT_CHECK_EQ(fi.loop_count, info.flat_loop_count);
    if (fi.loop_count > 0) check_layer(s, flat, info.flat_radius);
    mx_vcarve_free(v);
}

void scene(std::mt19937_64& rng) {
    const Scene s = plate(rng);
    mx_shape2d* raw = nullptr;
    if (!MT_CHECK_OK(mt::from_loops(s.loops, &raw))) return;
    mt::ShapePtr shape(raw);
    // One axis serves the offsets (inner and outer) and the V-carves.
    mx_axis* axis = nullptr;
    if (!MT_CHECK_OK(mx_axis_compute(shape.get(), nullptr, &axis))) return;
    mx_offset_options o{};
    MT_CHECK_OK(mx_offset_options_init(&o, sizeof o));
    o.outer_reach = 1.0;
    mx_offsets* offsets = nullptr;
    if (MT_CHECK_OK(mx_offsets_from_axis(axis, &o, &offsets))) {
        double max_inner = 0.0;
        MT_CHECK_OK(mx_offsets_max_inner_distance(offsets, &max_inner));
        const std::vector<double> ds = {0.1, 0.35, 0.7, 0.99 * max_inner, -0.3, -1.0};
        std::vector<mx_offset_layer*> layers(ds.size(), nullptr);
        std::vector<std::pair<double, double>> distance_area;
        if (MT_CHECK_OK(mx_offsets_layers(offsets, ds.data(), ds.size(), layers.data())))
            for (size_t k = 0; k < ds.size(); ++k) {
                check_layer(s, layers[k], ds[k]);
                mx_offset_layer_info info{};
                MT_CHECK_OK(mx_offset_layer_get_info(layers[k], &info));
                distance_area.push_back({ds[k], info.area});
                mx_offset_layer_free(layers[k]);
            }
        check_sides(s, distance_area);
        check_pocket(s, offsets, 0.1, 0.15, MX_POCKET_INSIDE_OUT);
        check_pocket(s, offsets, 0.2, 0.3, MX_POCKET_OUTSIDE_IN);
        mx_offsets_free(offsets);
    }
    check_vcarve(axis, s, 90.0, 0.3);
    check_vcarve(axis, s, 60.0, 0.2);
    mx_axis_free(axis);
}

void errors() {
    mt::begin_case("errors leave the handles alone");
    mx_shape2d* raw = nullptr;
    MT_CHECK_OK(mt::from_loops({{0, 0, 0, 4, 0, 0, 4, 3, 0, 0, 3, 0}}, &raw));
    mt::ShapePtr shape(raw);
    mx_offsets* const no_offsets = reinterpret_cast<mx_offsets*>(0x5EE7);
    mx_offsets* offsets = no_offsets;
    mx_offset_options o{};
    MT_CHECK_OK(mx_offset_options_init(&o, sizeof o));
    o.outer_reach = -1.0;
    MT_CHECK_STATUS(mx_offsets_compute(shape.get(), &o, &offsets), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_offsets_compute(nullptr, nullptr, &offsets), MX_ERR_NULL_ARGUMENT);
    MT_CHECK(offsets == no_offsets);
    MT_CHECK_OK(mx_offsets_compute(shape.get(), nullptr, &offsets));
    mx_offset_layer* const no_layer = reinterpret_cast<mx_offset_layer*>(0x5EE7);
    mx_offset_layer* layer = no_layer;
    MT_CHECK_STATUS(mx_offsets_layer(offsets, -0.5, &layer), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_offsets_layer(offsets, NAN, &layer), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK(layer == no_layer);
    mx_pocket* const no_pocket = reinterpret_cast<mx_pocket*>(0x5EE7);
    mx_pocket* p = no_pocket;
    mx_pocket_options po{};
    MT_CHECK_OK(mx_pocket_options_init(&po, sizeof po));
    MT_CHECK_STATUS(mx_pocket_compute(offsets, &po, &p), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK(mt::last_message().find("tool_radius") != std::string::npos);
    MT_CHECK(p == no_pocket);
    mx_vcarve* const no_vcarve = reinterpret_cast<mx_vcarve*>(0x5EE7);
    mx_vcarve* v = no_vcarve;
    mx_vcarve_options vo{};
    MT_CHECK_OK(mx_vcarve_options_init(&vo, sizeof vo));
    vo.angle_deg = 200.0;
    mx_axis* axis = nullptr;
    MT_CHECK_OK(mx_axis_compute(shape.get(), nullptr, &axis));
    MT_CHECK_STATUS(mx_vcarve_compute(axis, &vo, &v), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_vcarve_compute(nullptr, nullptr, &v), MX_ERR_NULL_ARGUMENT);
    MT_CHECK(v == no_vcarve);
    o.outer_reach = -1.0;
    MT_CHECK_STATUS(mx_offsets_from_axis(axis, &o, &offsets), MX_ERR_INVALID_ARGUMENT);
    MT_CHECK_STATUS(mx_offsets_from_axis(nullptr, nullptr, &offsets), MX_ERR_NULL_ARGUMENT);
    mx_axis_free(axis);
    mx_offsets_free(offsets);
    mx_offsets_free(nullptr);
    mx_offset_layer_free(nullptr);
    mx_pocket_free(nullptr);
    mx_vcarve_free(nullptr);
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t scenes = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CTEST_SCENES", 12);
    std::mt19937_64 rng(20261205);
    for (uint64_t i = 0; i < scenes; ++i) {
        mt::begin_case("plate " + std::to_string(i));
        scene(rng);
    }
    errors();
    return mt::finish("c_api_offset");
}
