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

/* The first layout of mx_drawing_select (keep_duplicates became int32_t
 * in 0.2.0, within the 0.1 struct's padding: the layout ends at byte 44 of
 * its 48). */
typedef struct {
    size_t struct_size;
    const char *const *layers;
    size_t layer_count;
    const int16_t *colours;
    size_t colour_count;
    int32_t keep_duplicates;
} drawing_select_v01;

#if UINTPTR_MAX == 0xFFFFFFFFFFFFFFFFu
/* The 0.1 sizes on 64-bit targets, which the library checks against. */
_Static_assert(sizeof(shape_options_v01) == 56, "0.1 mx_shape_options");
_Static_assert(sizeof(axis_options_v01) == 40, "0.1 mx_axis_options");
_Static_assert(sizeof(offset_options_v01) == 48, "0.1 mx_offset_options");
_Static_assert(sizeof(pocket_options_v01) == 40, "0.1 mx_pocket_options");
_Static_assert(sizeof(vcarve_options_v01) == 32, "0.1 mx_vcarve_options");
_Static_assert(sizeof(voronoi_options_v01) == 48, "0.1 mx_voronoi_options");
_Static_assert(sizeof(drawing_select_v01) == 48, "0.1 mx_drawing_select");
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

/* A drawing of the same square drawn twice: one copy is left out as a
 * duplicate unless keep_duplicates (then both are kept, and meet). */
static size_t duplicates_reported(const mx_drawing *d) {
    size_t n = 0, dups = 0;
    EXPECT(mx_drawing_ignored_count(d, &n), MX_OK);
    for (size_t i = 0; i < n; ++i) {
        mx_ignored ig;
        memset(&ig, 0, sizeof ig);
        EXPECT(mx_drawing_get_ignored(d, i, &ig), MX_OK);
        dups += ig.kind == MX_IGNORED_DUPLICATE_LOOP;
    }
    return dups;
}

static void drawing_select(void) {
    static const char svg[] = "<svg xmlns='http://www.w3.org/2000/svg'>"
                              "<rect x='0' y='0' width='4' height='2'/><rect x='0' y='0' width='4' height='2'/></svg>";
    drawing_select_v01 v = {sizeof v, NULL, 0, NULL, 0, 1};
    drawing_select_v01 *p = exact_copy(&v, sizeof v);
    size_t dups[2] = {9, 9};
    for (int keep = 0; keep < 2; ++keep) {
        p->keep_duplicates = keep;
        mx_drawing *d = NULL;
        EXPECT(mx_drawing_from_memory((const uint8_t *)svg, sizeof svg - 1, MX_FORMAT_SVG, NULL,
                                      (const mx_drawing_select *)p, &d),
               MX_OK);
        dups[keep] = duplicates_reported(d);
        mx_drawing_free(d);
    }
    /* keep_duplicates, the last field of the first layout, is read. */
    if (!(dups[0] == 1 && dups[1] == 0)) {
        fprintf(stderr, "c_options_v1.c: keep_duplicates 0 / 1 reported %zu / %zu duplicates, want 1 / 0\n", dups[0],
                dups[1]);
        ++failures;
    }
    mx_drawing *d = NULL;
    p->struct_size = 43;
    EXPECT(mx_drawing_from_memory((const uint8_t *)svg, sizeof svg - 1, MX_FORMAT_SVG, NULL,
                                  (const mx_drawing_select *)p, &d),
           MX_ERR_INVALID_ARGUMENT);
    CHECK(d == NULL);
    free(p);
}

/* _init into a block of exactly the first layout's size followed by guard
 * bytes: the library writes that many bytes and no more (valgrind sees a
 * write past the block too). */
typedef enum mx_status (*init_fn)(void *, size_t);
static void init_guarded(const char *name, init_fn init, size_t size, int first_layout_end) {
    unsigned char *block = malloc(size + 16);
    if (!block) {
        abort();
    }
    memset(block, 0xAB, size + 16);
    EXPECT(init(block, size), MX_OK);
    size_t written = 0;
    memcpy(&written, block, sizeof written);
    if (written != size) {
        fprintf(stderr, "c_options_v1.c: %s: struct_size %zu, want %zu\n", name, written, size);
        ++failures;
    }
    for (size_t i = size; i < size + 16; ++i) {
        if (block[i] != 0xAB) {
            fprintf(stderr, "c_options_v1.c: %s wrote byte %zu past a %zu-byte struct\n", name, i, size);
            ++failures;
            break;
        }
    }
    if (first_layout_end) {
        EXPECT(init(block, size - 1), MX_ERR_INVALID_ARGUMENT); /* below the first layout: refused */
    }
    free(block);
}

/* Each _init behind one signature (calling through a cast pointer would be
 * undefined behaviour). */
#define INIT_WRAPPER(fn, T) \
    static enum mx_status wrap_##fn(void *p, size_t n) { return fn((T *)p, n); }
INIT_WRAPPER(mx_shape_options_init, mx_shape_options)
INIT_WRAPPER(mx_axis_options_init, mx_axis_options)
INIT_WRAPPER(mx_offset_options_init, mx_offset_options)
INIT_WRAPPER(mx_pocket_options_init, mx_pocket_options)
INIT_WRAPPER(mx_vcarve_options_init, mx_vcarve_options)
INIT_WRAPPER(mx_voronoi_options_init, mx_voronoi_options)
INIT_WRAPPER(mx_drawing_select_init, mx_drawing_select)
INIT_WRAPPER(mx_mesh_options_init, mx_mesh_options)
#define INIT_GUARDED(fn, size) init_guarded(#fn, wrap_##fn, size, 1)

static void inits_never_overrun(void) {
    INIT_GUARDED(mx_shape_options_init, sizeof(shape_options_v01));
    INIT_GUARDED(mx_axis_options_init, sizeof(axis_options_v01));
    INIT_GUARDED(mx_offset_options_init, sizeof(offset_options_v01));
    INIT_GUARDED(mx_pocket_options_init, sizeof(pocket_options_v01));
    INIT_GUARDED(mx_vcarve_options_init, sizeof(vcarve_options_v01));
    INIT_GUARDED(mx_voronoi_options_init, sizeof(voronoi_options_v01));
    init_guarded("mx_drawing_select_init", wrap_mx_drawing_select_init, sizeof(drawing_select_v01), 0);
    INIT_GUARDED(mx_drawing_select_init, 44); /* the first layout's end */
    INIT_GUARDED(mx_mesh_options_init, 24);   /* first layout: 0.3 (weld_tolerance, threads) */
}

int main(void) {
    inits_never_overrun();
    drawing_select();
    shape_options();
    axis_and_vcarve_options();
    offset_and_pocket_options();
    voronoi_options();
    if (failures) {
        fprintf(stderr, "c_options_v1: %d failure(s)\n", failures);
        return 1;
    }
    printf("c_options_v1: every _init writes within the first layout; the seven older structs are read in it\n");
    return 0;
}
