// Cross-checks medax's shape validation and shape queries against CGAL on
// random polygons. Further shape cross-checks go in here as CrossCheck
// classes, registered in main() (a CGAL translation unit costs about a
// minute and 1.4 GB to compile). The medial axis is cross-checked against
// CGAL::Segment_Delaunay_graph_2 in cgal_axis.cpp, on its own corpus.
//
// Cases (all with bulge 0, i.e. polygons):
//   star        random star polygon (angles jittered around a regular grid,
//               random radii), 10..2000 vertices, CCW or CW as given
//   star+hole   the same with a small regular polygon hole around the centre
//   swapped     a star polygon with two vertices swapped (adjacent or not):
//               CGAL decides whether the result is still simple
//   shuffled    random points in random order (almost never simple)
//
// Checks per case (see the CrossCheck classes):
//   validity    medax accepts the case iff CGAL calls every loop simple (and the
//               loops are properly nested); a rejection of a non-simple polygon
//               is MX_ERR_INTERSECTION naming two elements CGAL finds intersecting
//   area        mx_shape2d_area == |outer.area()| - sum |hole.area()|, 1e-9 relative
//   bbox        mx_shape2d_bbox == outer.bbox(), exactly
//   loops       stored loops are the input loops, oriented (outer CCW, holes CW)
//               with the documented index mapping
//   joints      joint k == CGAL::orientation(prev, v, next) of the stored loop:
//               left turn = MX_JOINT_CONVEX, right turn = MX_JOINT_REFLEX
//
// medax works with tolerances (touching distance 1e-9 x diagonal, angle 1e-6
// rad) where CGAL's predicates are exact. A disagreement that the tolerance
// explains (CGAL-simple polygon with two non-adjacent edges closer than the
// touching tolerance; a turn within the angle tolerance of 0) is counted and
// printed, not failed. With the default seed none occurs.
//
// Usage: cgal_wiring [seed] [cases]      (also MEDAX_CGAL_SEED, MEDAX_CGAL_CASES)

#include "test_support.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Segment = K::Segment_2;
using Polygon = CGAL::Polygon_2<K>;

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// Cases

struct Case {
    std::string name;
    std::vector<Polygon> loops;  // as given to medax: [outer, holes...]
};

struct Generator {
    std::mt19937_64 rng;
    explicit Generator(uint64_t seed) : rng(seed) {}

    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    size_t index(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); }
    bool coin() { return index(2) == 1; }

    // Vertex counts 10..2000, log-uniform so that small and large both occur.
    size_t size() { return static_cast<size_t>(std::lround(std::exp(uniform(std::log(10.0), std::log(2000.0))))); }

    // A star polygon around (cx, cy): one vertex per angular sector, its angle
    // jittered inside the middle 80 % of the sector (so consecutive angles
    // stay at least 0.2 x 2 pi / n apart and spikes stay far from the angle
    // tolerance), radius uniform in [0.3, 1] x R. Counter-clockwise.
    Polygon star(size_t n, double cx, double cy, double R) {
        Polygon p;
        for (size_t k = 0; k < n; ++k) {
            const double a = 2.0 * kPi * (static_cast<double>(k) + uniform(0.1, 0.9)) / static_cast<double>(n);
            const double r = R * uniform(0.3, 1.0);
            p.push_back(Point(cx + r * std::cos(a), cy + r * std::sin(a)));
        }
        return p;
    }

    Polygon regular(size_t n, double cx, double cy, double r, double phase) {
        Polygon p;
        for (size_t k = 0; k < n; ++k) {
            const double a = phase + 2.0 * kPi * static_cast<double>(k) / static_cast<double>(n);
            p.push_back(Point(cx + r * std::cos(a), cy + r * std::sin(a)));
        }
        return p;
    }

    void place(double& cx, double& cy, double& R) {
        cx = uniform(-1000.0, 1000.0);
        cy = uniform(-1000.0, 1000.0);
        R = std::exp(uniform(std::log(0.5), std::log(500.0)));
    }

    Case next(size_t i) {
        double cx, cy, R;
        place(cx, cy, R);
        // Make sure the extremes occur.
        const size_t n = i == 0 ? 10 : i == 1 ? 2000 : size();
        const std::string tag = "#" + std::to_string(i) + " n=" + std::to_string(n);
        Case c;
        switch (i % 6) {
            case 0:
            case 1: {  // plain star, CCW or CW
                Polygon p = star(n, cx, cy, R);
                const bool cw = i % 6 == 1;
                if (cw) p.reverse_orientation();
                c.name = "star " + std::string(cw ? "cw " : "ccw ") + tag;
                c.loops.push_back(p);
                break;
            }
            case 2: {  // star with a hole, either orientation for both
                Polygon p = star(n, cx, cy, R);
                Polygon h = regular(3 + index(10), cx + uniform(-0.02, 0.02) * R, cy + uniform(-0.02, 0.02) * R,
                                    0.1 * R, uniform(0.0, 2.0 * kPi));
                if (coin()) p.reverse_orientation();
                if (coin()) h.reverse_orientation();
                c.name = "star+hole " + tag;
                c.loops = {p, h};
                break;
            }
            case 3:
            case 4: {  // two vertices swapped: adjacent (case 3) or anywhere (case 4)
                Polygon p = star(n, cx, cy, R);
                const size_t a = index(n);
                const size_t b = i % 6 == 3 ? (a + 1) % n : index(n);
                std::swap(*(p.vertices_begin() + static_cast<std::ptrdiff_t>(a)),
                          *(p.vertices_begin() + static_cast<std::ptrdiff_t>(b)));
                c.name = "swapped " + std::to_string(a) + "<->" + std::to_string(b) + " " + tag;
                c.loops.push_back(p);
                break;
            }
            default: {  // random points in random order, small
                const size_t m = 4 + index(12);
                Polygon p;
                for (size_t k = 0; k < m; ++k)
                    p.push_back(Point(cx + R * uniform(-1.0, 1.0), cy + R * uniform(-1.0, 1.0)));
                c.name = "shuffled #" + std::to_string(i) + " n=" + std::to_string(m);
                c.loops.push_back(p);
                break;
            }
        }
        return c;
    }
};

// ---------------------------------------------------------------------------
// What medax said, and what CGAL says

struct Outcome {
    mx_status status = MX_OK;
    mx_error_info info{};
    std::string message;
    mt::ShapePtr shape;
    double tolerance = 0.0;        // the touching tolerance medax used (or would use)
    double angle_tolerance = 0.0;  // the joint angle tolerance
};

struct Truth {
    bool all_simple = true;     // every loop simple per CGAL
    std::vector<bool> simple;   // per loop
    // Oriented copies of the loops as medax documents storing them: outer
    // counter-clockwise, holes clockwise; reversed[l] tells whether loop l
    // had to be reversed.
    std::vector<Polygon> oriented;
    std::vector<bool> reversed;
};

Truth cgal_truth(const Case& c) {
    Truth t;
    for (size_t l = 0; l < c.loops.size(); ++l) {
        const Polygon& p = c.loops[l];
        const bool simple = p.is_simple();
        t.simple.push_back(simple);
        t.all_simple = t.all_simple && simple;
        Polygon o = p;
        bool rev = false;
        if (simple) {
            const bool want_ccw = l == 0;
            rev = (o.orientation() == CGAL::COUNTERCLOCKWISE) != want_ccw;
            if (rev) {
                // medax: stored vertex k = input vertex n - 1 - k.
                std::vector<Point> v(o.vertices_begin(), o.vertices_end());
                std::reverse(v.begin(), v.end());
                o = Polygon(v.begin(), v.end());
            }
        }
        t.oriented.push_back(o);
        t.reversed.push_back(rev);
    }
    return t;
}

Outcome run_medax(const Case& c) {
    std::vector<double> xyb;
    std::vector<size_t> lens;
    CGAL::Bbox_2 box;
    for (const Polygon& p : c.loops) {
        for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) {
            xyb.insert(xyb.end(), {v->x(), v->y(), 0.0});
            box += v->bbox();
        }
        lens.push_back(p.size());
    }
    mx_shape_options opts;
    mx_shape_options_init(&opts, sizeof opts);
    Outcome o;
    o.tolerance = opts.relative_tolerance * std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    o.angle_tolerance = opts.angle_tolerance;
    mx_clear_last_error();
    mx_shape2d* raw = nullptr;
    o.status = mx_shape2d_from_bulges(xyb.data(), xyb.size(), lens.data(), lens.size(), &opts, &raw);
    o.shape.reset(raw);
    mx_last_error_info(&o.info);
    o.message = mt::last_message();
    if (o.shape) mx_shape2d_tolerance(o.shape.get(), &o.tolerance);
    return o;
}

// Smallest distance between two non-adjacent edges of the loops (O(n^2); only
// used to explain a disagreement).
double min_nonadjacent_distance(const std::vector<Polygon>& loops) {
    std::vector<std::pair<size_t, Segment>> edges;
    for (size_t l = 0; l < loops.size(); ++l)
        for (auto e = loops[l].edges_begin(); e != loops[l].edges_end(); ++e) edges.emplace_back(l, *e);
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < edges.size(); ++i)
        for (size_t j = i + 1; j < edges.size(); ++j) {
            const Segment &a = edges[i].second, &b = edges[j].second;
            if (edges[i].first == edges[j].first &&
                (a.source() == b.target() || a.target() == b.source()))
                continue;  // adjacent
            best = std::min(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))));
        }
    return best;
}

// The signed turning angle at v (from prev->v to v->next), for tolerance decisions.
double turning_angle(const Point& prev, const Point& v, const Point& next) {
    const long double ax = v.x() - prev.x(), ay = v.y() - prev.y();
    const long double bx = next.x() - v.x(), by = next.y() - v.y();
    return static_cast<double>(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
}

struct Tally {
    size_t cases = 0, accepted = 0, rejected = 0, explained = 0, ambiguous_joints = 0, joints = 0;
};

// ---------------------------------------------------------------------------
// Cross-checks

class CrossCheck {
public:
    virtual ~CrossCheck() = default;
    virtual const char* name() const = 0;
    // Runs only for cases medax accepted (needs_shape) or for every case.
    virtual bool needs_shape() const { return true; }
    virtual void run(const Case& c, const Truth& t, const Outcome& o, Tally& tally) const = 0;
};

class ValidityCheck final : public CrossCheck {
public:
    const char* name() const override { return "validity"; }
    bool needs_shape() const override { return false; }
    void run(const Case& c, const Truth& t, const Outcome& o, Tally& tally) const override {
        const bool accepted = o.status == MX_OK;
        (accepted ? tally.accepted : tally.rejected)++;
        if (accepted == t.all_simple) {
            if (!accepted) check_rejection(c, t, o);
            return;
        }
        // Disagreement: explained only by medax's touching tolerance.
        if (!accepted && o.status == MX_ERR_INTERSECTION) {
            const double d = min_nonadjacent_distance(c.loops);
            if (d <= o.tolerance * (1.0 + 1e-6)) {
                ++tally.explained;
                std::cout << "  note [" << c.name << "]: CGAL-simple, but non-adjacent edges are " << d
                          << " apart (medax tolerance " << o.tolerance << "): rejected as touching\n";
                return;
            }
        }
        MT_CHECK(accepted == t.all_simple);
        std::cerr << "    CGAL simple: " << t.all_simple << ", medax: " << mt::show(o.status) << " " << o.message
                  << "\n";
    }

private:
    // A non-simple polygon must be rejected as an intersection of two
    // elements that really intersect (or come within the tolerance).
    static void check_rejection(const Case& c, const Truth& t, const Outcome& o) {
        (void)t;
        if (!MT_CHECK(o.status == MX_ERR_INTERSECTION)) {
            std::cerr << "    medax: " << mt::show(o.status) << " " << o.message << "\n";
            return;
        }
        const mx_error_info& i = o.info;
        const auto valid = [&](int64_t l, int64_t e) {
            return l >= 0 && static_cast<size_t>(l) < c.loops.size() && e >= 0 &&
                   static_cast<size_t>(e) < c.loops[static_cast<size_t>(l)].size();
        };
        if (!MT_CHECK(valid(i.loop_index, i.element) && valid(i.other_loop_index, i.other_element))) return;
        const Segment a = c.loops[static_cast<size_t>(i.loop_index)].edge(static_cast<size_t>(i.element));
        const Segment b = c.loops[static_cast<size_t>(i.other_loop_index)].edge(static_cast<size_t>(i.other_element));
        const bool meet = CGAL::do_intersect(a, b) ||
                          std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))) <= o.tolerance * (1.0 + 1e-6);
        if (!MT_CHECK(meet)) std::cerr << "    reported elements: " << o.message << "\n";
        MT_CHECK(i.has_position == 1);
        if (i.has_position == 1) {
            const Point p(i.x, i.y);
            const double slack = 1e-6 * std::max(1.0, std::abs(i.x) + std::abs(i.y));
            MT_CHECK(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, a))) <= slack + o.tolerance);
            MT_CHECK(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, b))) <= slack + o.tolerance);
        }
    }
};

class AreaCheck final : public CrossCheck {
public:
    const char* name() const override { return "area"; }
    void run(const Case&, const Truth& t, const Outcome& o, Tally&) const override {
        double expected = 0.0;
        for (size_t l = 0; l < t.oriented.size(); ++l)
            expected += (l == 0 ? 1.0 : -1.0) * std::abs(CGAL::to_double(t.oriented[l].area()));
        double area = 0.0;
        MT_CHECK_OK(mx_shape2d_area(o.shape.get(), &area));
        MT_CHECK(mt::near_rel(area, expected, 1e-9));
        if (!mt::near_rel(area, expected, 1e-9)) std::cerr << "    medax " << area << ", CGAL " << expected << "\n";
    }
};

class BboxCheck final : public CrossCheck {
public:
    const char* name() const override { return "bbox"; }
    void run(const Case& c, const Truth&, const Outcome& o, Tally&) const override {
        const CGAL::Bbox_2 e = c.loops[0].bbox();  // holes lie inside the outer loop
        mx_bbox b{};
        MT_CHECK_OK(mx_shape2d_bbox(o.shape.get(), &b));
        MT_CHECK_EQ(b.xmin, e.xmin());
        MT_CHECK_EQ(b.ymin, e.ymin());
        MT_CHECK_EQ(b.xmax, e.xmax());
        MT_CHECK_EQ(b.ymax, e.ymax());
    }
};

// The stored loops are the oriented input loops, vertex for vertex.
class LoopCheck final : public CrossCheck {
public:
    const char* name() const override { return "loops"; }
    void run(const Case&, const Truth& t, const Outcome& o, Tally&) const override {
        size_t count = 0;
        MT_CHECK_OK(mx_shape2d_loop_count(o.shape.get(), &count));
        if (!check_size(count, t.oriented.size())) return;
        for (size_t l = 0; l < count; ++l) {
            int32_t rev = 9;
            MT_CHECK_OK(mx_shape2d_loop_reversed(o.shape.get(), l, &rev));
            MT_CHECK_EQ(rev, t.reversed[l] ? 1 : 0);
            const std::vector<double> v = mt::loop_vertices(o.shape.get(), l);
            const Polygon& p = t.oriented[l];
            if (!check_size(v.size(), 3 * p.size())) continue;
            size_t mismatches = 0;
            for (size_t k = 0; k < p.size(); ++k)
                mismatches += v[3 * k] != p[k].x() || v[3 * k + 1] != p[k].y() || v[3 * k + 2] != 0.0;
            MT_CHECK_EQ(mismatches, size_t{0});
        }
    }

private:
    static bool check_size(size_t a, size_t b) {
        return mt::record(a == b, __FILE__, __LINE__, "size " + std::to_string(a) + " vs " + std::to_string(b));
    }
};

class JointCheck final : public CrossCheck {
public:
    const char* name() const override { return "joints"; }
    void run(const Case& c, const Truth& t, const Outcome& o, Tally& tally) const override {
        for (size_t l = 0; l < t.oriented.size(); ++l) {
            const Polygon& p = t.oriented[l];
            const size_t n = p.size();
            size_t wrong = 0;
            for (size_t k = 0; k < n; ++k) {
                const Point& prev = p[(k + n - 1) % n];
                const Point& v = p[k];
                const Point& next = p[(k + 1) % n];
                const CGAL::Orientation turn = CGAL::orientation(prev, v, next);
                const mx_joint_kind cgal = turn == CGAL::LEFT_TURN    ? MX_JOINT_CONVEX
                                           : turn == CGAL::RIGHT_TURN ? MX_JOINT_REFLEX
                                                                      : MX_JOINT_SMOOTH;
                mx_joint_kind got = MX_JOINT_SMOOTH;
                MT_CHECK_OK(mx_shape2d_joint(o.shape.get(), l, k, &got));
                ++tally.joints;
                const double angle = std::abs(turning_angle(prev, v, next));
                const double tol = o.angle_tolerance;
                if (angle > tol * (1.0 + 1e-6)) {
                    wrong += got != cgal;
                } else if (angle < tol * (1.0 - 1e-6)) {
                    wrong += got != MX_JOINT_SMOOTH;  // within the angle tolerance: smooth
                } else {
                    ++tally.ambiguous_joints;
                    wrong += got != cgal && got != MX_JOINT_SMOOTH;
                }
            }
            if (!MT_CHECK_EQ(wrong, size_t{0})) std::cerr << "    in loop " << l << " of " << c.name << "\n";
        }
    }
};

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = mt::from_env_or_arg(argc, argv, 1, "MEDAX_CGAL_SEED", 20240611);
    const size_t cases = static_cast<size_t>(mt::from_env_or_arg(argc, argv, 2, "MEDAX_CGAL_CASES", 400));
    std::cout << "cgal_wiring: CGAL " << CGAL_VERSION_STR << ", medax " << mx_version() << ", seed " << seed << ", "
              << cases << " cases\n";

    std::vector<std::unique_ptr<CrossCheck>> checks;
    checks.push_back(std::make_unique<ValidityCheck>());
    checks.push_back(std::make_unique<AreaCheck>());
    checks.push_back(std::make_unique<BboxCheck>());
    checks.push_back(std::make_unique<LoopCheck>());
    checks.push_back(std::make_unique<JointCheck>());

    Generator gen(seed);
    Tally tally;
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < cases; ++i) {
        const Case c = gen.next(i);
        mt::begin_case(c.name + " (seed " + std::to_string(seed) + ")");
        const Truth t = cgal_truth(c);
        const Outcome o = run_medax(c);
        ++tally.cases;
        for (const auto& check : checks) {
            if (check->needs_shape() && !o.shape) continue;
            check->run(c, t, o, tally);
        }
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "cgal_wiring: " << tally.cases << " cases (" << tally.accepted << " accepted, " << tally.rejected
              << " rejected), " << tally.joints << " joints, " << tally.explained
              << " disagreements explained by tolerance, " << tally.ambiguous_joints << " joints at the angle tolerance, "
              << secs << " s\n";
    return mt::finish("cgal_wiring");
}
