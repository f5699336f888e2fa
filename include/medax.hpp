// medax.hpp: a header-only C++17 layer over the medax C API (medax.h).
//
// What it adds, and nothing more: every handle owned by a move-only RAII
// type (its _free in the destructor), every failure a medax::error carrying
// the status, the thread's last-error message and mx_error_info, options
// initialised with their defaults, and arrays as std::vector or as
// read-only views that live as long as the handle they borrow from. Every
// call is the C function of the same name (docs/C_API.md); .get() hands a
// handle to the C API for anything this layer does not wrap.
//
//     medax::Shape shape = medax::Shape::from_file("part.dxf");
//     medax::Ball square = medax::Ball::square();
//     medax::Axis axis = medax::Axis::compute(shape, &square);
//     for (size_t i = 0; i < axis.node_count(); ++i) use(axis.node(i));
#ifndef MEDAX_HPP
#define MEDAX_HPP

#include <medax.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace medax {

// A failed medax call: what(), the status and the structured last error.
class error : public std::runtime_error {
public:
    error(mx_status status, const std::string& message, const mx_error_info& info)
        : std::runtime_error(message), status_(status), info_(info) {}
    mx_status status() const noexcept { return status_; }
    const mx_error_info& info() const noexcept { return info_; }

private:
    mx_status status_;
    mx_error_info info_;
};

// Throws medax::error unless `status` is MX_OK; `call` names the C function.
inline void check(mx_status status, const char* call) {
    if (status == MX_OK) return;
    std::string message(mx_last_error_length(), '\0');
    mx_last_error_message(message.data(), message.size());
    if (!message.empty()) message.pop_back();  // the NUL
    mx_error_info info{};
    mx_last_error_info(&info);
    throw error(status, std::string(call) + ": " + mx_status_str(status) + ": " + message, info);
}

// A read-only view of `size()` items borrowed from a handle.
template <typename T>
class view {
public:
    view(const T* data, size_t size) : data_(data), size_(size) {}
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }
    const T* data() const { return data_; }
    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const T& operator[](size_t i) const { return data_[i]; }

private:
    const T* data_;
    size_t size_;
};

// Owns one C handle; move-only. `Free` is the handle's _free function.
template <typename T, void (*Free)(T*)>
class handle {
public:
    handle() = default;
    explicit handle(T* raw) : raw_(raw) {}
    handle(const handle&) = delete;
    handle& operator=(const handle&) = delete;
    handle(handle&& o) noexcept : raw_(std::exchange(o.raw_, nullptr)) {}
    handle& operator=(handle&& o) noexcept {
        if (this != &o) {
            Free(raw_);
            raw_ = std::exchange(o.raw_, nullptr);
        }
        return *this;
    }
    ~handle() { Free(raw_); }
    T* get() const noexcept { return raw_; }
    explicit operator bool() const noexcept { return raw_ != nullptr; }

private:
    T* raw_ = nullptr;
};

// Options structs filled with their defaults (the size-aware _init).
inline mx_shape_options shape_options() {
    mx_shape_options o;
    mx_shape_options_init(&o, sizeof o);
    return o;
}
inline mx_axis_options axis_options() {
    mx_axis_options o;
    mx_axis_options_init(&o, sizeof o);
    return o;
}
inline mx_offset_options offset_options() {
    mx_offset_options o;
    mx_offset_options_init(&o, sizeof o);
    return o;
}
inline mx_pocket_options pocket_options() {
    mx_pocket_options o;
    mx_pocket_options_init(&o, sizeof o);
    return o;
}
inline mx_voronoi_options voronoi_options() {
    mx_voronoi_options o;
    mx_voronoi_options_init(&o, sizeof o);
    return o;
}

// A validated shape: an outer loop and holes of segments and arcs.
class Shape : public handle<mx_shape2d, mx_shape2d_free> {
public:
    using handle::handle;
    static Shape from_file(const std::string& path, uint32_t format = MX_FORMAT_AUTO,
                           const mx_shape_options* options = nullptr) {
        mx_shape2d* raw = nullptr;
        check(mx_shape2d_from_file(path.c_str(), format, options, &raw), "mx_shape2d_from_file");
        return Shape(raw);
    }
    static Shape from_string(const std::string& text, uint32_t format = MX_FORMAT_JSON,
                             const mx_shape_options* options = nullptr) {
        mx_shape2d* raw = nullptr;
        check(mx_shape2d_from_string(text.c_str(), format, options, &raw), "mx_shape2d_from_string");
        return Shape(raw);
    }
    // `xyb`: x, y, bulge triples of every loop back to back (outer first).
    static Shape from_bulges(const std::vector<double>& xyb, const std::vector<size_t>& loop_lengths,
                             const mx_shape_options* options = nullptr) {
        mx_shape2d* raw = nullptr;
        check(mx_shape2d_from_bulges(xyb.data(), xyb.size(), loop_lengths.data(), loop_lengths.size(), options, &raw),
              "mx_shape2d_from_bulges");
        return Shape(raw);
    }
    size_t loop_count() const {
        size_t n = 0;
        check(mx_shape2d_loop_count(get(), &n), "mx_shape2d_loop_count");
        return n;
    }
    double area() const {
        double a = 0.0;
        check(mx_shape2d_area(get(), &a), "mx_shape2d_area");
        return a;
    }
    // Loop `index` as stored (outer counter-clockwise, holes clockwise):
    // x, y, bulge triples.
    std::vector<double> loop_vertices(size_t index) const {
        size_t n = 0;
        check(mx_shape2d_loop_vertices(get(), index, nullptr, 0, &n), "mx_shape2d_loop_vertices");
        std::vector<double> xyb(3 * n);
        check(mx_shape2d_loop_vertices(get(), index, xyb.data(), n, &n), "mx_shape2d_loop_vertices");
        return xyb;
    }
};

// The unit ball of a polygonal metric (chapter 3).
class Ball : public handle<mx_ball, mx_ball_free> {
public:
    using handle::handle;
    static Ball square() { return make(mx_ball_square, "mx_ball_square"); }
    static Ball diamond() { return make(mx_ball_diamond, "mx_ball_diamond"); }
    static Ball triangle() { return make(mx_ball_triangle, "mx_ball_triangle"); }
    static Ball regular(size_t k, double rotation_radians = 0.0) {
        mx_ball* raw = nullptr;
        check(mx_ball_regular(k, rotation_radians, &raw), "mx_ball_regular");
        return Ball(raw);
    }
    // A preset (`square`, `ngon:12:15`, ...) or ball JSON.
    static Ball parse(const std::string& spec) {
        mx_ball* raw = nullptr;
        check(mx_ball_parse(spec.c_str(), &raw), "mx_ball_parse");
        return Ball(raw);
    }
    // Vertices as x, y pairs, either orientation.
    static Ball from_vertices(const std::vector<double>& xy) {
        mx_ball* raw = nullptr;
        check(mx_ball_from_vertices2(xy.data(), xy.size() / 2, &raw), "mx_ball_from_vertices2");
        return Ball(raw);
    }
    // x, y pairs, counter-clockwise.
    std::vector<double> vertices() const {
        size_t n = 0;
        check(mx_ball_vertex_count(get(), &n), "mx_ball_vertex_count");
        std::vector<double> xy(2 * n);
        size_t written = 0;
        check(mx_ball_vertices(get(), xy.data(), n, &written), "mx_ball_vertices");
        return xy;
    }
    // The least r with `to` in `from` + r·B.
    double distance(double from_x, double from_y, double to_x, double to_y) const {
        const double from[2] = {from_x, from_y}, to[2] = {to_x, to_y};
        double d = 0.0;
        check(mx_ball_distance2(get(), from, to, &d), "mx_ball_distance2");
        return d;
    }

private:
    static Ball make(mx_status (*f)(mx_ball**), const char* call) {
        mx_ball* raw = nullptr;
        check(f(&raw), call);
        return Ball(raw);
    }
};

// One loop of an offset layer and its x, y, bulge triples (borrowed).
struct OffsetLoop {
    mx_offset_loop info;
    view<double> xyb;
};

class OffsetLayer : public handle<mx_offset_layer, mx_offset_layer_free> {
public:
    using handle::handle;
    mx_offset_layer_info info() const {
        mx_offset_layer_info i{};
        check(mx_offset_layer_get_info(get(), &i), "mx_offset_layer_get_info");
        return i;
    }
    OffsetLoop loop(size_t index) const {
        mx_offset_loop l{};
        check(mx_offset_layer_get_loop(get(), index, &l), "mx_offset_layer_get_loop");
        return OffsetLoop{l, view<double>(l.xyb, 3 * l.vertex_count)};
    }
};

// The medial axis, Euclidean or under a ball.
class Axis : public handle<mx_axis, mx_axis_free> {
public:
    using handle::handle;
    // `ball` null: the Euclidean axis.
    static Axis compute(const Shape& shape, const Ball* ball = nullptr, const mx_axis_options* options = nullptr) {
        mx_axis* raw = nullptr;
        check(mx_axis_compute_with_ball(shape.get(), ball ? ball->get() : nullptr, options, &raw),
              "mx_axis_compute_with_ball");
        return Axis(raw);
    }
    size_t node_count() const {
        size_t n = 0;
        check(mx_axis_node_count(get(), &n), "mx_axis_node_count");
        return n;
    }
    size_t edge_count() const {
        size_t n = 0;
        check(mx_axis_edge_count(get(), &n), "mx_axis_edge_count");
        return n;
    }
    mx_axis_node node(size_t i) const {
        mx_axis_node n{};
        check(mx_axis_get_node(get(), i, &n), "mx_axis_get_node");
        return n;
    }
    mx_axis_edge edge(size_t i) const {
        mx_axis_edge e{};
        check(mx_axis_get_edge(get(), i, &e), "mx_axis_get_edge");
        return e;
    }
    // Contact classes of an edge of an axis under a ball.
    mx_axis_contacts contacts(size_t i) const {
        mx_axis_contacts c{};
        check(mx_axis_edge_contacts(get(), i, &c), "mx_axis_edge_contacts");
        return c;
    }
    // Edge `i` as x, y, r triples within `tolerance` (model units).
    std::vector<double> sample(size_t i, double tolerance) const {
        size_t n = 0;
        check(mx_axis_edge_sample(get(), i, tolerance, nullptr, 0, &n), "mx_axis_edge_sample");
        std::vector<double> xyr(3 * n);
        check(mx_axis_edge_sample(get(), i, tolerance, xyr.data(), n, &n), "mx_axis_edge_sample");
        return xyr;
    }
    // The inner offset at `distance` read off this axis.
    OffsetLayer offset(double distance) const {
        mx_offset_layer* raw = nullptr;
        check(mx_axis_offset_layer(get(), distance, &raw), "mx_axis_offset_layer");
        return OffsetLayer(raw);
    }
};

// Euclidean offsets prepared once (one axis) for any number of distances.
class Offsets : public handle<mx_offsets, mx_offsets_free> {
public:
    using handle::handle;
    static Offsets compute(const Shape& shape, const mx_offset_options* options = nullptr) {
        mx_offsets* raw = nullptr;
        check(mx_offsets_compute(shape.get(), options, &raw), "mx_offsets_compute");
        return Offsets(raw);
    }
    OffsetLayer layer(double distance) const {
        mx_offset_layer* raw = nullptr;
        check(mx_offsets_layer(get(), distance, &raw), "mx_offsets_layer");
        return OffsetLayer(raw);
    }
    // All layers at once, computed in parallel; all or nothing.
    std::vector<OffsetLayer> layers(const std::vector<double>& distances) const {
        std::vector<mx_offset_layer*> raw(distances.size(), nullptr);
        check(mx_offsets_layers(get(), distances.data(), distances.size(), raw.data()), "mx_offsets_layers");
        std::vector<OffsetLayer> owned;
        owned.reserve(raw.size());
        for (mx_offset_layer* l : raw) owned.emplace_back(l);
        return owned;
    }
    // The largest inscribed radius: inner offsets beyond it are empty.
    double max_inner_distance() const {
        double d = 0.0;
        check(mx_offsets_max_inner_distance(get(), &d), "mx_offsets_max_inner_distance");
        return d;
    }
};

// Pocketing rings from prepared offsets, with the material left uncut.
class Pocket : public handle<mx_pocket, mx_pocket_free> {
public:
    using handle::handle;
    static Pocket compute(const Offsets& offsets, const mx_pocket_options& options) {
        mx_pocket* raw = nullptr;
        check(mx_pocket_compute(offsets.get(), &options, &raw), "mx_pocket_compute");
        return Pocket(raw);
    }
    // `info().order` borrows from the pocket: `view<size_t>(i.order, i.ring_count)`.
    mx_pocket_info info() const {
        mx_pocket_info i{};
        check(mx_pocket_get_info(get(), &i), "mx_pocket_get_info");
        return i;
    }
    mx_pocket_ring ring(size_t index) const {
        mx_pocket_ring r{};
        check(mx_pocket_get_ring(get(), index, &r), "mx_pocket_get_ring");
        return r;
    }
    mx_uncut_region uncut(size_t index) const {
        mx_uncut_region u{};
        check(mx_pocket_get_uncut(get(), index, &u), "mx_pocket_get_uncut");
        return u;
    }
};

// The shape grown by `distance` under `ball` (null: Euclidean).
inline OffsetLayer outer_offset(const Shape& shape, const Ball* ball, double distance) {
    mx_offset_layer* raw = nullptr;
    check(mx_shape2d_outer_offset_with_ball(shape.get(), ball ? ball->get() : nullptr, distance, &raw),
          "mx_shape2d_outer_offset_with_ball");
    return OffsetLayer(raw);
}

// A Voronoi diagram of point, curve and region sites.
class Voronoi : public handle<mx_voronoi, mx_voronoi_free> {
public:
    using handle::handle;
    // `ball` null: the Euclidean diagram.
    static Voronoi compute(const mx_sites& sites, const Ball* ball = nullptr,
                           const mx_voronoi_options* options = nullptr) {
        mx_voronoi* raw = nullptr;
        check(mx_voronoi_compute_with_ball(&sites, ball ? ball->get() : nullptr, options, &raw),
              "mx_voronoi_compute_with_ball");
        return Voronoi(raw);
    }
    mx_voronoi_info info() const {
        mx_voronoi_info i{};
        check(mx_voronoi_get_info(get(), &i), "mx_voronoi_get_info");
        return i;
    }
    // The diagram's axis (borrowed: valid while this diagram lives).
    const mx_axis* axis() const {
        const mx_axis* a = nullptr;
        check(mx_voronoi_axis(get(), &a), "mx_voronoi_axis");
        return a;
    }
    mx_voronoi_edge edge(size_t i) const {
        mx_voronoi_edge e{};
        check(mx_voronoi_get_edge(get(), i, &e), "mx_voronoi_get_edge");
        return e;
    }
    mx_nearest_site nearest_site(double x, double y) const {
        mx_nearest_site s{};
        check(mx_voronoi_nearest_site(get(), x, y, &s), "mx_voronoi_nearest_site");
        return s;
    }
};

}  // namespace medax

#endif  // MEDAX_HPP
