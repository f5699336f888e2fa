// Usage example: offsets and pocket rings from C++ through medax.hpp, the
// header-only C++ layer over the C API (RAII handles, exceptions carrying
// the status and error info, option defaults, views over borrowed arrays).
//
// Reads a shape from a medax JSON string, prepares offsets (one medial
// axis for every distance), prints the offsets at a few distances, then
// the rings of a pocket in machining order and the material the tool
// leaves. Build it with the CMakeLists.txt next to this file (../README.md);
// run it without arguments. Exit status 0 on success.
#include <medax.hpp>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

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
    medax::Shape shape = medax::Shape::from_string(plate_json);
    // Negative (outer) distances down to -0.5 need the complement's axis,
    // computed now; 0 keeps to inner offsets.
    mx_offset_options offset_options = medax::offset_options();
    offset_options.outer_reach = 0.5;
    medax::Offsets offsets = medax::Offsets::compute(shape, &offset_options);
    const double deepest = offsets.max_inner_distance();
    std::printf("medax %s: largest inscribed radius %.4f\n", mx_version(), deepest);

    const std::vector<double> distances = {-0.5, 0.25, 0.5, 1.0, deepest + 0.1};
    const std::vector<medax::OffsetLayer> layers = offsets.layers(distances);
    for (const medax::OffsetLayer &layer : layers) {
        const mx_offset_layer_info info = layer.info();
        std::printf("offset %6.3f: %zu loops in %zu regions, area %.4f\n", info.distance, info.loop_count,
                    info.region_count, info.area);
        for (size_t i = 0; i < info.loop_count; ++i) {
            // Loops borrow from the layer: copy what must outlive it.
            const medax::OffsetLoop loop = layer.loop(i);
            std::printf("  loop %zu: %s, %zu vertices (%zu arcs), area %.4f\n", i, loop.info.is_hole ? "hole" : "outer",
                        loop.info.vertex_count, arc_count(loop.xyb.data(), loop.info.vertex_count), loop.info.area);
        }
    }
    // Past the largest inscribed radius nothing is left: a layer without loops.
    if (layers.back().info().loop_count != 0) throw std::runtime_error("something left beyond the largest inscribed radius");

    mx_pocket_options pocket_options = medax::pocket_options();
    pocket_options.tool_radius = 0.2;
    pocket_options.stepover = 0.3;
    pocket_options.order = MX_POCKET_INSIDE_OUT;  // the wall last, as a finishing pass
    const medax::Pocket pocket = medax::Pocket::compute(offsets, pocket_options);
    const mx_pocket_info info = pocket.info();
    std::printf("pocket: %zu rings in %zu levels, uncut area %.6f in %zu regions%s\n", info.ring_count,
                info.level_count, info.uncut_area, info.uncut_count, info.truncated ? " (truncated)" : "");
    const medax::view<size_t> order(info.order, info.ring_count);  // machining order
    for (size_t k = 0; k < order.size(); ++k) {
        const mx_pocket_ring ring = pocket.ring(order[k]);
        // ring.loops has the layout mx_shape2d_from_bulges takes: the outer
        // loop first, then its holes.
        std::printf("  cut %zu: ring %zu, level %zu at %.3f, %zu loops, parent %s\n", k, order[k], ring.level,
                    ring.distance, ring.loops.count,
                    ring.has_parent ? std::to_string(ring.parent).c_str() : "none");
    }
    for (size_t u = 0; u < info.uncut_count; ++u) {
        const mx_uncut_region region = pocket.uncut(u);
        std::printf("  uncut %zu: %s, area %.6f\n", u, region.kind == MX_UNCUT_WALL ? "wall" : "scallop", region.area);
    }
    return 0;
} catch (const medax::error &e) {
    std::fprintf(stderr, "error (status %d): %s\n", static_cast<int>(e.status()), e.what());
    return 1;
} catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
}
