/* medax.h compiled as strict C11 (-std=c11 -pedantic -Wall -Wextra -Werror):
 * builds a shape from bulge loops, reads it back and prints mx_version().
 * Built twice: against medax::medax_static (proving the static target's
 * native link dependencies) and against medax::medax_shared. */

#include <medax.h>

#include <stdio.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond)                                                       \
    do {                                                                  \
        if (!(cond)) {                                                    \
            fprintf(stderr, "%s:%d: FAILED: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                   \
        }                                                                 \
    } while (0)

#define CHECK_OK(call)                                                    \
    do {                                                                  \
        enum mx_status st_ = (call);                                      \
        if (st_ != MX_OK) {                                               \
            char msg_[256];                                               \
            mx_last_error_message(msg_, sizeof msg_);                     \
            fprintf(stderr, "%s:%d: FAILED: %s -> %d (%s): %s\n", __FILE__, __LINE__, #call, \
                    (int)st_, mx_status_str((int32_t)st_), msg_);         \
            ++failures;                                                   \
        }                                                                 \
    } while (0)

static double absd(double v) { return v < 0 ? -v : v; }

static int near(double a, double b) { return absd(a - b) <= 1e-12 * (1.0 + absd(b)); }

int main(void) {
    /* A 4 x 2 rectangle whose right side is a half circle (r = 1) bulging
     * outwards, with a square hole given counter-clockwise. */
    const double xyb[] = {
        0.0, 0.0, 0.0, 4.0, 0.0, 1.0, 4.0, 2.0, 0.0, 0.0, 2.0, 0.0, /* outer */
        1.0, 0.5, 0.0, 2.0, 0.5, 0.0, 2.0, 1.5, 0.0, 1.0, 1.5, 0.0  /* hole */
    };
    const size_t loop_lengths[] = {4, 4};
    const double pi = 3.14159265358979323846;
    struct mx_shape2d *shape = NULL;
    struct mx_shape_options options;
    struct mx_bbox bbox;
    struct mx_element element;
    size_t loops = 0, n = 0, written = 0;
    int32_t reversed = 9;
    enum mx_joint_kind joint = MX_JOINT_SMOOTH;
    double area = 0.0, back[12];
    const char *version = mx_version();
    char expected_version[32];

    printf("medax %s\n", version);
    snprintf(expected_version, sizeof expected_version, "%d.%d.%d", MEDAX_VERSION_MAJOR, MEDAX_VERSION_MINOR,
             MEDAX_VERSION_PATCH);
    CHECK(strcmp(version, expected_version) == 0);

    CHECK_OK(mx_shape_options_init(&options, sizeof options));
    CHECK(options.struct_size == sizeof options);
    CHECK_OK(mx_shape2d_from_bulges(xyb, sizeof xyb / sizeof xyb[0], loop_lengths, 2, &options, &shape));
    if (shape == NULL) {
        return 1;
    }
    CHECK_OK(mx_shape2d_loop_count(shape, &loops));
    CHECK(loops == 2);
    CHECK_OK(mx_shape2d_loop_size(shape, 0, &n));
    CHECK(n == 4);
    CHECK_OK(mx_shape2d_loop_vertices(shape, 0, back, 4, &written));
    CHECK(written == 4);
    CHECK(memcmp(back, xyb, sizeof back) == 0);
    CHECK_OK(mx_shape2d_loop_reversed(shape, 1, &reversed));
    CHECK(reversed == 1);
    CHECK_OK(mx_shape2d_area(shape, &area));
    CHECK(near(area, 8.0 + pi / 2.0 - 1.0));
    CHECK_OK(mx_shape2d_bbox(shape, &bbox));
    CHECK(near(bbox.xmin, 0.0) && near(bbox.ymin, 0.0) && near(bbox.xmax, 5.0) && near(bbox.ymax, 2.0));
    CHECK_OK(mx_shape2d_element(shape, 0, 1, &element));
    CHECK(element.kind == MX_ELEMENT_ARC && element.ccw == 1);
    CHECK(near(element.cx, 4.0) && near(element.cy, 1.0) && near(element.radius, 1.0));
    CHECK_OK(mx_shape2d_joint(shape, 0, 1, &joint));
    CHECK(joint == MX_JOINT_SMOOTH);
    CHECK_OK(mx_shape2d_joint(shape, 1, 0, &joint));
    CHECK(joint == MX_JOINT_REFLEX);

    /* One error path in C: status, info and message. */
    {
        struct mx_error_info info;
        enum mx_status st = mx_shape2d_loop_size(shape, 7, &n);
        CHECK(st == MX_ERR_INDEX_OUT_OF_RANGE);
        CHECK(n == 4);
        CHECK_OK(mx_last_error_info(&info));
        CHECK(info.status == MX_ERR_INDEX_OUT_OF_RANGE);
        CHECK(mx_last_error_message(NULL, 0) > 1);
    }

    mx_shape2d_free(shape);
    printf("c11_smoke: %s\n", failures == 0 ? "ok" : "FAILED");
    return failures == 0 ? 0 : 1;
}
