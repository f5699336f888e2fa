/* Usage example: the medial axis of a plate with a hole, from C.
 *
 * Builds the shape from bulge loops, computes its medial axis, walks the
 * nodes and edges (with the maximal-disk radius along each edge), shows
 * how a failed call reports what went wrong, and frees every handle.
 * Build it against the installed package with the CMakeLists.txt next to
 * this file (see ../README.md); run it as `medax_example_axis [SHAPE.svg]`
 * (a picture of the shape goes there). Exit status 0 on success. */
#include <medax.h>

#include <stdio.h>
#include <stdlib.h>

/* Prints the failing call, its status and the thread's last error message
 * with the structured details (loop, element, position) when there are
 * any. Every medax call that returns mx_status leaves these behind. */
static void report_error(const char *call, enum mx_status status) {
    char message[512];
    mx_error_info info;
    mx_last_error_message(message, sizeof message);
    fprintf(stderr, "%s failed: %s (%d): %s\n", call, mx_status_str(status), (int)status, message);
    if (mx_last_error_info(&info) == MX_OK) {
        if (info.loop_index >= 0)
            fprintf(stderr, "  at loop %lld element %lld\n", (long long)info.loop_index, (long long)info.element);
        if (info.has_position)
            fprintf(stderr, "  near (%g, %g)\n", info.x, info.y);
    }
}

static const char *node_kind(enum mx_node_kind kind) {
    switch (kind) {
    case MX_NODE_BRANCH: return "branch";
    case MX_NODE_CORNER: return "corner";
    case MX_NODE_LEAF: return "leaf";
    case MX_NODE_JOINT: return "joint";
    case MX_NODE_PSEUDO_BRANCH: return "pseudo-branch";
    }
    return "?";
}

/* An invalid shape is refused with a status and a message naming the
 * elements at fault: here a bow tie whose first and third sides cross at
 * (1.2, 1.2). */
static int show_validation_error(void) {
    const double bow_tie[] = {0, 0, 0, 2, 2, 0, 2, 0, 0, 0, 3, 0};
    const size_t lengths[] = {4};
    mx_shape2d *shape = NULL;
    enum mx_status status = mx_shape2d_from_bulges(bow_tie, 12, lengths, 1, NULL, &shape);
    if (status == MX_OK) {
        fprintf(stderr, "a crossing loop was accepted\n");
        mx_shape2d_free(shape);
        return 0;
    }
    printf("as expected, the bow tie is refused:\n");
    report_error("mx_shape2d_from_bulges", status);
    /* On failure the out-parameter is untouched: nothing to free. */
    return 1;
}

int main(int argc, char **argv) {
    /* Loop 0 is the outer boundary: an 8 x 5 plate whose top side is an arc
     * (bulge 0.2 = tan(sweep / 4) on the vertex where it starts). Loop 1 is
     * a hole: a circle of diameter 1 as two half circles (bulge 1). Each
     * vertex is x, y, bulge; loops follow each other in one array. */
    const double xyb[] = {
        0, 0, 0,   8, 0, 0,   8, 5, 0.2,   0, 5, 0,
        2, 2, 1,   3, 2, 1,
    };
    const size_t lengths[] = {4, 2};
    int ok = 0;
    mx_shape2d *shape = NULL;
    mx_axis *axis = NULL;
    double *samples = NULL;
    enum mx_status status;

    if (!show_validation_error())
        return 1;

    status = mx_shape2d_from_bulges(xyb, sizeof xyb / sizeof xyb[0], lengths, 2, NULL, &shape);
    if (status != MX_OK) {
        report_error("mx_shape2d_from_bulges", status);
        goto done;
    }

    /* Options structs carry their size: always start from the defaults. */
    mx_axis_options options;
    mx_axis_options_init(&options, sizeof options);
    options.seed = 1;    /* the same seed gives the same axis, bit for bit */
    options.threads = 2; /* 0 = the shared pool (all cores) */
    status = mx_axis_compute(shape, &options, &axis);
    if (status != MX_OK) {
        report_error("mx_axis_compute", status);
        goto done;
    }

    size_t node_count = 0, edge_count = 0;
    mx_axis_node_count(axis, &node_count);
    mx_axis_edge_count(axis, &edge_count);
    printf("medax %s: %zu nodes, %zu edges\n", mx_version(), node_count, edge_count);
    /* With h holes the axis has h independent cycles: edges = nodes - 1 + h. */
    const size_t holes = 1;
    if (edge_count + 1 != node_count + holes) {
        fprintf(stderr, "expected one cycle round the hole\n");
        goto done;
    }

    mx_axis_node largest = {0};
    for (size_t i = 0; i < node_count; i++) {
        mx_axis_node node;
        status = mx_axis_get_node(axis, i, &node);
        if (status != MX_OK) {
            report_error("mx_axis_get_node", status);
            goto done;
        }
        if (node.kind == MX_NODE_BRANCH || node.kind == MX_NODE_CORNER)
            printf("node %zu: %s at (%.4f, %.4f), disk radius %.4f\n", i, node_kind(node.kind), node.x, node.y, node.r);
        if (node.r > largest.r)
            largest = node;
    }
    printf("largest inscribed circle: centre (%.4f, %.4f), radius %.4f\n", largest.x, largest.y, largest.r);

    /* Edges are conics; sample them to a chordal tolerance in model units.
     * The first call with capacity 0 asks for the sample count. */
    const double tolerance = 1e-3;
    for (size_t i = 0; i < edge_count; i++) {
        mx_axis_edge edge;
        size_t count = 0;
        status = mx_axis_get_edge(axis, i, &edge);
        if (status == MX_OK)
            status = mx_axis_edge_sample(axis, i, tolerance, NULL, 0, &count);
        if (status != MX_OK) {
            report_error("mx_axis_get_edge / mx_axis_edge_sample", status);
            goto done;
        }
        double *grown = realloc(samples, 3 * count * sizeof *samples);
        if (grown == NULL) {
            fprintf(stderr, "out of memory\n");
            goto done;
        }
        samples = grown;
        status = mx_axis_edge_sample(axis, i, tolerance, samples, count, &count);
        if (status != MX_OK) {
            report_error("mx_axis_edge_sample", status);
            goto done;
        }
        double rmin = samples[2], rmax = samples[2];
        for (size_t k = 1; k < count; k++) {
            double r = samples[3 * k + 2];
            rmin = r < rmin ? r : rmin;
            rmax = r > rmax ? r : rmax;
        }
        /* sites[]: the two boundary primitives the edge is equidistant from,
         * in the input's numbering (an element, or a reflex vertex). */
        printf("edge %zu: %zu -> %zu, %zu samples, radius %.4f..%.4f, between loop %zu %s %zu and loop %zu %s %zu\n", i,
               edge.from, edge.to, count, rmin, rmax, edge.sites[0].loop_index,
               edge.sites[0].is_vertex ? "vertex" : "element", edge.sites[0].index, edge.sites[1].loop_index,
               edge.sites[1].is_vertex ? "vertex" : "element", edge.sites[1].index);
    }

    /* A picture of the shape, for a quick look. */
    status = mx_shape2d_write_svg(shape, argc > 1 ? argv[1] : "axis_example_shape.svg");
    if (status != MX_OK) {
        report_error("mx_shape2d_write_svg", status);
        goto done;
    }
    ok = 1;

done:
    /* _free(NULL) is a no-op, so one exit path frees whatever exists. */
    free(samples);
    mx_axis_free(axis);
    mx_shape2d_free(shape);
    return ok ? 0 : 1;
}
