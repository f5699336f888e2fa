// Usage example: offsets and pocket rings from C++, with small RAII
// wrappers over the C handles written here (medax ships only the C API).
//
// Reads a shape from a medax JSON string, prepares offsets (one medial
// axis for every distance), prints the offsets at a few distances, then
// the rings of a pocket in machining order and the material the tool
// leaves. Build it with the CMakeLists.txt next to this file (../README.md);
// run it without arguments. Exit status 0 on success.
#include <medax.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// One owning pointer type per handle: the deleter is the handle's _free.
template <typename T, void (*Free)(T *)>
struct Deleter {
    void operator()(T *p) const { Free(p); }
};
using Shape = std::unique_ptr<mx_shape2d, Deleter<mx_shape2d, mx_shape2d_free>>;
using Offsets = std::unique_ptr<mx_offsets, Deleter<mx_offsets, mx_offsets_free>>;
using Layer = std::unique_ptr<mx_offset_layer, Deleter<mx_offset_layer, mx_offset_layer_free>>;
using Pocket = std::unique_ptr<mx_pocket, Deleter<mx_pocket, mx_pocket_free>>;

// medax reports failures as a status plus a per-thread message; turning
// them into exceptions keeps the happy path readable.
void check(mx_status status, const char *call) {
    if (status == MX_OK) return;
    std::string message(mx_last_error_length(), '\0');
    mx_last_error_message(message.data(), message.size());
    message.resize(message.empty() ? 0 : message.size() - 1);  // drop the NUL
    throw std::runtime_error(std::string(call) + ": " + mx_status_str(status) + ": " + message);
}

Shape shape_from_json(const char *json) {
    mx_shape2d *raw = nullptr;
    check(mx_shape2d_from_string(json, MX_FORMAT_JSON, nullptr, &raw), "mx_shape2d_from_string");
    return Shape(raw);
}

Offsets prepare_offsets(const mx_shape2d &shape, double outer_reach) {
    mx_offset_options options;
    mx_offset_options_init(&options, sizeof options);
    // Negative (outer) distances down to -outer_reach need the complement's
    // axis, computed now; 0 keeps to inner offsets.
    options.outer_reach = outer_reach;
    mx_offsets *raw = nullptr;
    check(mx_offsets_compute(&shape, &options, &raw), "mx_offsets_compute");
    return Offsets(raw);
}

// All layers at once, computed in parallel; all or nothing.
std::vector<Layer> layers(const mx_offsets &offsets, const std::vector<double> &distances) {
    std::vector<mx_offset_layer *> raw(distances.size(), nullptr);
    check(mx_offsets_layers(&offsets, distances.data(), distances.size(), raw.data()), "mx_offsets_layers");
    std::vector<Layer> owned;
    for (mx_offset_layer *l : raw) owned.emplace_back(l);
    return owned;
}

Pocket make_pocket(const mx_offsets &offsets, double tool_radius, double stepover) {
    mx_pocket_options options;
    mx_pocket_options_init(&options, sizeof options);
    options.tool_radius = tool_radius;
    options.stepover = stepover;
    options.order = MX_POCKET_INSIDE_OUT;  // the wall last, as a finishing pass
    mx_pocket *raw = nullptr;
    check(mx_pocket_compute(&offsets, &options, &raw), "mx_pocket_compute");
    return Pocket(raw);
}

size_t arc_count(const double *xyb, size_t vertex_count) {
    size_t arcs = 0;
    for (size_t v = 0; v < vertex_count; ++v) arcs += xyb[3 * v + 2] != 0.0;
    return arcs;
}

// An 8 x 5 plate with an arc on its right side, a round hole and a square
// hole (the README's example plate).
const char *const plate_json = R"({"loops": [
  [[0, 0], [8, 0], [8, 5, 0.2], [0, 5]],
  [[2, 2, 1], [3, 2, 1]],
  [[5, 1.5], [6.5, 1.5], [6.5, 3], [5, 3]]
]})";

}  // namespace

int main() try {
    Shape shape = shape_from_json(plate_json);
    Offsets offsets = prepare_offsets(*shape, 0.5);
    double deepest = 0;
    check(mx_offsets_max_inner_distance(offsets.get(), &deepest), "mx_offsets_max_inner_distance");
    std::printf("medax %s: largest inscribed radius %.4f\n", mx_version(), deepest);

    const std::vector<double> distances = {-0.5, 0.25, 0.5, 1.0, deepest + 0.1};
    std::vector<Layer> offset_layers = layers(*offsets, distances);
    for (const Layer &layer : offset_layers) {
        mx_offset_layer_info info;
        check(mx_offset_layer_get_info(layer.get(), &info), "mx_offset_layer_get_info");
        std::printf("offset %6.3f: %zu loops in %zu regions, area %.4f\n", info.distance, info.loop_count,
                    info.region_count, info.area);
        for (size_t i = 0; i < info.loop_count; ++i) {
            // Loops borrow from the layer: copy what must outlive it.
            mx_offset_loop loop;
            check(mx_offset_layer_get_loop(layer.get(), i, &loop), "mx_offset_layer_get_loop");
            std::printf("  loop %zu: %s, %zu vertices (%zu arcs), area %.4f\n", i, loop.is_hole ? "hole" : "outer",
                        loop.vertex_count, arc_count(loop.xyb, loop.vertex_count), loop.area);
        }
    }
    // Past the largest inscribed radius nothing is left: a layer without loops.
    mx_offset_layer_info beyond;
    check(mx_offset_layer_get_info(offset_layers.back().get(), &beyond), "mx_offset_layer_get_info");
    if (beyond.loop_count != 0) throw std::runtime_error("something left beyond the largest inscribed radius");

    Pocket pocket = make_pocket(*offsets, 0.2, 0.3);
    mx_pocket_info info;
    check(mx_pocket_get_info(pocket.get(), &info), "mx_pocket_get_info");
    std::printf("pocket: %zu rings in %zu levels, uncut area %.6f in %zu regions%s\n", info.ring_count,
                info.level_count, info.uncut_area, info.uncut_count, info.truncated ? " (truncated)" : "");
    for (size_t k = 0; k < info.ring_count; ++k) {
        const size_t index = info.order[k];  // machining order
        mx_pocket_ring ring;
        check(mx_pocket_get_ring(pocket.get(), index, &ring), "mx_pocket_get_ring");
        // ring.loops has the layout mx_shape2d_from_bulges takes: the outer
        // loop first, then its holes.
        std::printf("  cut %zu: ring %zu, level %zu at %.3f, %zu loops, parent %s\n", k, index, ring.level,
                    ring.distance, ring.loops.count,
                    ring.has_parent ? std::to_string(ring.parent).c_str() : "none");
    }
    for (size_t u = 0; u < info.uncut_count; ++u) {
        mx_uncut_region region;
        check(mx_pocket_get_uncut(pocket.get(), u, &region), "mx_pocket_get_uncut");
        std::printf("  uncut %zu: %s, area %.6f\n", u, region.kind == MX_UNCUT_WALL ? "wall" : "scallop", region.area);
    }
    return 0;
} catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
}
