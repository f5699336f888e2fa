/* A caller built against the 0.1 header: every options struct passed in its
 * 0.1 layout (frozen copies of the 0.1 fields below, struct_size their 0.1
 * sizeof), each in a heap block of exactly that size so that valgrind sees
 * any read past it. Each must be accepted with every 0.1 field read (the
 * last one included), and a struct_size one byte short of it refused.
 * Strict C11. */

#include <medax.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    size_t struct_size;
    double tolerance, relative_tolerance, angle_tolerance, flatten_sagitta, chain_tolerance, max_radius_ratio;
} shape_options_v01;

typedef struct {
    size_t struct_size;
    uint64_t seed;
    size_t threads;
    mx_progress_fn progress;
    void *user;
} axis_options_v01;

typedef struct {
    size_t struct_size;
    uint64_t seed;
    size_t threads;
    double outer_reach;
    mx_progress_fn progress;
    void *user;
} offset_options_v01;

typedef struct {
    size_t struct_size;
    double tool_radius, stepover;
    uint32_t order;
    size_t max_levels;
} pocket_options_v01;

typedef struct {
    size_t struct_size;
    double angle_deg, max_depth, tolerance;
} vcarve_options_v01;

typedef struct {
    size_t struct_size;
    uint64_t seed;
    size_t threads;
    double tolerance;
    mx_progress_fn progress;
    void *user;
} voronoi_options_v01;

#if UINTPTR_MAX == 0xFFFFFFFFFFFFFFFFu
/* The 0.1 sizes on 64-bit targets, which the library checks against. */
_Static_assert(sizeof(shape_options_v01) == 56, "0.1 mx_shape_options");
_Static_assert(sizeof(axis_options_v01) == 40, "0.1 mx_axis_options");
_Static_assert(sizeof(offset_options_v01) == 48, "0.1 mx_offset_options");
_Static_assert(sizeof(pocket_options_v01) == 40, "0.1 mx_pocket_options");
_Static_assert(sizeof(vcarve_options_v01) == 32, "0.1 mx_vcarve_options");
_Static_assert(sizeof(voronoi_options_v01) == 48, "0.1 mx_voronoi_options");
#endif

static int failures = 0;

static const char *last_message(void) {
    static char msg[512];
    msg[0] = 0;
    mx_last_error_message(msg, sizeof msg);
    return msg;
}

static void expect(int line, const char *what, enum mx_status got, enum mx_status want) {
    if (got != want) {
        fprintf(stderr, "c_options_v1.c:%d: %s -> %d (%s), want %d: %s\n", line, what, (int)got,
                mx_status_str((int32_t)got), (int)want, last_message());
        ++failures;
    }
}

#define EXPECT(call, want) expect(__LINE__, #call, (call), (want))
#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "c_options_v1.c:%d: FAILED: %s\n", __LINE__, #cond);     \
            ++failures;                                                              \
        }                                                                            \
    } while (0)

/* Exactly `size` bytes holding `*v`: nothing past the struct is readable. */
static void *exact_copy(const void *v, size_t size) {
    void *p = malloc(size);
    if (!p) {
        abort();
    }
    memcpy(p, v, size);
    return p;
}

static int count_calls(double fraction, void *user) {
    (void)fraction;
    ++*(int *)user;
    return 0;
}

static enum mx_status rectangle(const mx_shape_options *options, mx_shape2d **out) {
    static const double xyb[] = {0, 0, 0, 4, 0, 0, 4, 2, 0, 0, 2, 0};
    static const size_t lens[] = {4};
    return mx_shape2d_from_bulges(xyb, 12, lens, 1, options, out);
}

static void shape_options(void) {
    shape_options_v01 v = {sizeof v, 1e-6, 1e-9, 1e-6, -1.0, 0.0, -1.0};
    shape_options_v01 *p = exact_copy(&v, sizeof v);
    mx_shape2d *s = NULL;
    /* max_radius_ratio, the last 0.1 field, is read: negative is refused. */
    EXPECT(rectangle((const mx_shape_options *)p, &s), MX_ERR_INVALID_ARGUMENT);
    p->max_radius_ratio = 1e6;
    EXPECT(rectangle((const mx_shape_options *)p, &s), MX_OK);
    double tol = 0;
    EXPECT(mx_shape2d_tolerance(s, &tol), MX_OK);
    CHECK(tol == 1e-6);
    mx_shape2d_free(s);
    s = NULL;
    p->struct_size = sizeof v - 1;
    EXPECT(rectangle((const mx_shape_options *)p, &s), MX_ERR_INVALID_ARGUMENT);
    CHECK(s == NULL);
    free(p);
}

static void axis_and_vcarve_options(void) {
    mx_shape2d *s = NULL;
    EXPECT(rectangle(NULL, &s), MX_OK);
    int calls = 0;
    axis_options_v01 v = {sizeof v, 7, 1, count_calls, &calls};
    axis_options_v01 *p = exact_copy(&v, sizeof v);
    mx_axis *a = NULL;
    EXPECT(mx_axis_compute(s, (const mx_axis_options *)p, &a), MX_OK);
    CHECK(calls == 2); /* progress and user, the last 0.1 fields, are read */
    mx_axis *b = NULL;
    p->struct_size = sizeof v - 1;
    EXPECT(mx_axis_compute(s, (const mx_axis_options *)p, &b), MX_ERR_INVALID_ARGUMENT);
    CHECK(b == NULL);
    free(p);

    vcarve_options_v01 w = {sizeof w, 60.0, 0.5, -1.0};
    vcarve_options_v01 *q = exact_copy(&w, sizeof w);
    mx_vcarve *vc = NULL;
    /* tolerance, the last 0.1 field, is read: negative is refused. */
    EXPECT(mx_vcarve_compute(a, (const mx_vcarve_options *)q, &vc), MX_ERR_INVALID_ARGUMENT);
    q->tolerance = 0.0;
    EXPECT(mx_vcarve_compute(a, (const mx_vcarve_options *)q, &vc), MX_OK);
    mx_vcarve_info info;
    memset(&info, 0, sizeof info);
    EXPECT(mx_vcarve_get_info(vc, &info), MX_OK);
    const double flat = 0.28867513459481288225; /* 0.5 tan 30 degrees */
    CHECK(info.flat_radius > flat - 1e-12 && info.flat_radius < flat + 1e-12);
    mx_vcarve *vc2 = NULL;
    q->struct_size = sizeof w - 1;
    EXPECT(mx_vcarve_compute(a, (const mx_vcarve_options *)q, &vc2), MX_ERR_INVALID_ARGUMENT);
    CHECK(vc2 == NULL);
    free(q);
    mx_vcarve_free(vc);
    mx_axis_free(a);
    mx_shape2d_free(s);
}

static void offset_and_pocket_options(void) {
    mx_shape2d *s = NULL;
    EXPECT(rectangle(NULL, &s), MX_OK);
    int calls = 0;
    offset_options_v01 v = {sizeof v, 7, 1, 1.0, count_calls, &calls};
    offset_options_v01 *p = exact_copy(&v, sizeof v);
    mx_offsets *off = NULL;
    EXPECT(mx_offsets_compute(s, (const mx_offset_options *)p, &off), MX_OK);
    CHECK(calls == 2);
    mx_offset_layer *outer = NULL;
    EXPECT(mx_offsets_layer(off, -0.5, &outer), MX_OK); /* outer_reach is read */
    mx_offsets *off2 = NULL;
    p->struct_size = sizeof v - 1;
    EXPECT(mx_offsets_compute(s, (const mx_offset_options *)p, &off2), MX_ERR_INVALID_ARGUMENT);
    CHECK(off2 == NULL);
    free(p);

    pocket_options_v01 w = {sizeof w, 0.1, 0.1, MX_POCKET_OUTSIDE_IN, 2};
    pocket_options_v01 *q = exact_copy(&w, sizeof w);
    mx_pocket *pk = NULL;
    EXPECT(mx_pocket_compute(off, (const mx_pocket_options *)q, &pk), MX_OK);
    mx_pocket_info info;
    memset(&info, 0, sizeof info);
    EXPECT(mx_pocket_get_info(pk, &info), MX_OK);
    CHECK(info.level_count == 2 && info.truncated == 1); /* max_levels, the last 0.1 field */
    mx_pocket *pk2 = NULL;
    q->struct_size = sizeof w - 1;
    EXPECT(mx_pocket_compute(off, (const mx_pocket_options *)q, &pk2), MX_ERR_INVALID_ARGUMENT);
    CHECK(pk2 == NULL);
    free(q);
    mx_pocket_free(pk);
    mx_offset_layer_free(outer);
    mx_offsets_free(off);
    mx_shape2d_free(s);
}

static void voronoi_options(void) {
    static const double pts[] = {0, 0, 3, 0, 1, 2};
    mx_sites sites;
    memset(&sites, 0, sizeof sites);
    sites.points_xy = pts;
    sites.point_count = 3;
    int calls = 0;
    voronoi_options_v01 v = {sizeof v, 7, 1, 0.0, count_calls, &calls};
    voronoi_options_v01 *p = exact_copy(&v, sizeof v);
    mx_voronoi *vd = NULL;
    EXPECT(mx_voronoi_compute(&sites, (const mx_voronoi_options *)p, &vd), MX_OK);
    CHECK(calls == 2);
    mx_voronoi *vd2 = NULL;
    p->struct_size = sizeof v - 1;
    EXPECT(mx_voronoi_compute(&sites, (const mx_voronoi_options *)p, &vd2), MX_ERR_INVALID_ARGUMENT);
    CHECK(vd2 == NULL);
    free(p);
    mx_voronoi_free(vd);
}

int main(void) {
    shape_options();
    axis_and_vcarve_options();
    offset_and_pocket_options();
    voronoi_options();
    if (failures) {
        fprintf(stderr, "c_options_v1: %d failure(s)\n", failures);
        return 1;
    }
    printf("c_options_v1: the 0.1 layouts of all six options structs are accepted and read\n");
    return 0;
}
