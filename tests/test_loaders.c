/*
 * test_loaders.c - the scene loaders (PLY, OBJ), the built-in scenes and
 * the cameras of the command-line tool.  Hostile files are written to a
 * temporary folder by the tests themselves.
 *
 * Held-out failures (issue 12): coordinates that round to FLT_MAX are
 * finite (OBJ, ASCII PLY float and double, binary PLY double just above
 * FLT_MAX) and every coordinate is rounded once, correctly (a decimal just
 * above a float midpoint whose nearest double is the midpoint); a UTF-8
 * byte-order mark is skipped (OBJ: the first vertex is not lost, PLY: the
 * file loads); an unknown OBJ statement and text after the last element
 * of an ASCII PLY are errors, not silently skipped; a .ply that is a link
 * to /dev/zero, a 2 GB sparse file (with and without a header), an
 * overlong header and a body far beyond what the header declares are
 * refused without being read whole (in a child process under alarm(10),
 * which the old loader, reading all of /dev/zero, fails); a PLY from a FIFO
 * still loads.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <check.h>
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "scene.h"
#include "testutil.h"

static char tmpdir[256];

static int make_tmpdir(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(tmpdir, sizeof tmpdir, "%s/atrbvh_loaders_XXXXXX",
             base && *base ? base : "/tmp");
    if (mkdtemp(tmpdir) == NULL) {
        perror(tmpdir);
        tmpdir[0] = '\0';
        return 0;
    }
    return 1;
}

/* Writes `size` bytes to tmpdir/name; returns the path (static buffer). */
static const char *write_file(const char *name, const void *data, size_t size)
{
    static char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    f = fopen(path, "wb");
    ck_assert_msg(f != NULL, "cannot create %s", path);
    ck_assert_uint_eq(fwrite(data, 1, size, f), size);
    ck_assert_int_eq(fclose(f), 0);
    return path;
}

static const char *write_text(const char *name, const char *text)
{
    return write_file(name, text, strlen(text));
}

static const char *data_path(const char *name)
{
    static char path[1024];
    const char *src = getenv("ATRBVH_SRCDIR");
    snprintf(path, sizeof path, "%s/data/%s", src && *src ? src : ".", name);
    return path;
}

/* Loads `path`, expecting failure with every `want` string in the
 * message (NULL-terminated list). */
static void expect_error(const char *path, const char *const *want)
{
    scene s;
    char err[512];
    size_t k;
    err[0] = '\0';
    ck_assert_msg(scene_load(path, &s, err, sizeof err) == -1,
                  "%s loaded but should not have", path);
    ck_assert_msg(strchr(err, '\n') == NULL, "message is not one line: %s",
                  err);
    for (k = 0; want[k]; k++)
        ck_assert_msg(strstr(err, want[k]) != NULL,
                      "message \"%s\" lacks \"%s\"", err, want[k]);
}

#define EXPECT_ERROR(path, ...)                                                \
    do {                                                                       \
        const char *const want_[] = {__VA_ARGS__, NULL};                       \
        expect_error((path), want_);                                           \
    } while (0)

static void load_ok(const char *path, scene *s)
{
    char err[512];
    ck_assert_msg(scene_load(path, s, err, sizeof err) == 0, "%s: %s", path,
                  err);
}

static void check_tri(const scene *s, size_t t, uint32_t a, uint32_t b,
                      uint32_t c)
{
    ck_assert_uint_eq(s->indices[3 * t + 0], a);
    ck_assert_uint_eq(s->indices[3 * t + 1], b);
    ck_assert_uint_eq(s->indices[3 * t + 2], c);
}

/* --------------------------------------------------- binary PLY builder */
typedef struct buf {
    unsigned char b[4096];
    size_t n;
    int big;
} buf;

static void put_bytes(buf *o, const void *p, size_t n)
{
    ck_assert(o->n + n <= sizeof o->b);
    memcpy(o->b + o->n, p, n);
    o->n += n;
}

static void put_uint(buf *o, uint64_t v, size_t size)
{
    size_t k;
    for (k = 0; k < size; k++) {
        size_t shift = o->big ? size - 1 - k : k;
        unsigned char c = (unsigned char)(v >> (8 * shift));
        put_bytes(o, &c, 1);
    }
}

static void put_f32(buf *o, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    put_uint(o, u, 4);
}

static void put_f64(buf *o, double d)
{
    uint64_t u;
    memcpy(&u, &d, 8);
    put_uint(o, u, 8);
}

/* A pentagon and a triangle over 5 vertices, with properties of many types
 * in odd orders, a list inside the vertex element and elements to skip
 * before and after; in the given byte order. */
static size_t mixed_ply(buf *o, int big)
{
    static const double xyz[5][3] = {
        {0, 0, 0}, {1, 0, 0}, {1.5, 1, 0}, {0.5, 2, 0.25}, {-0.5, 1, -1e-3}};
    char header[1024];
    int v;
    memset(o, 0, sizeof *o);
    o->big = big;
    snprintf(header, sizeof header,
             "ply\r\nformat %s 1.0\r\n"
             "comment mixed types\r\n"
             "obj_info made by test_loaders\r\n"
             "element material 2\r\n"
             "property uchar r\r\nproperty list uint8 int16 stuff\r\n"
             "element vertex 5\r\n"
             "property char a\r\nproperty double z\r\n"
             "property list uchar float uv\r\nproperty float x\r\n"
             "property ushort b\r\nproperty float y\r\nproperty int c\r\n"
             "element face 2\r\n"
             "property uint flags\r\n"
             "property list int uint vertex_index\r\n"
             "property list uchar uchar extra\r\n"
             "element edge 1\r\nproperty int v1\r\nproperty int v2\r\n"
             "end_header\r\n",
             big ? "binary_big_endian" : "binary_little_endian");
    put_bytes(o, header, strlen(header));
    /* material: 2 items */
    put_uint(o, 7, 1);
    put_uint(o, 2, 1);
    put_uint(o, 0xfffe, 2);
    put_uint(o, 3, 2);
    put_uint(o, 9, 1);
    put_uint(o, 0, 1);
    for (v = 0; v < 5; v++) {
        put_uint(o, (uint64_t)(unsigned char)(signed char)-v, 1);
        put_f64(o, xyz[v][2]);
        put_uint(o, (uint64_t)v % 3, 1);
        for (int k = 0; k < v % 3; k++)
            put_f32(o, 0.5f);
        put_f32(o, (float)xyz[v][0]);
        put_uint(o, 65535, 2);
        put_f32(o, (float)xyz[v][1]);
        put_uint(o, 0x80000000u, 4);
    }
    /* face 0: pentagon 0 1 2 3 4 */
    put_uint(o, 1, 4);
    put_uint(o, 5, 4);
    for (v = 0; v < 5; v++)
        put_uint(o, (uint64_t)v, 4);
    put_uint(o, 1, 1);
    put_uint(o, 42, 1);
    /* face 1: triangle 4 2 0 */
    put_uint(o, 2, 4);
    put_uint(o, 3, 4);
    put_uint(o, 4, 4);
    put_uint(o, 2, 4);
    put_uint(o, 0, 4);
    put_uint(o, 0, 1);
    /* edge */
    put_uint(o, 0, 4);
    put_uint(o, 1, 4);
    return strlen(header);
}

static void check_mixed(const scene *s)
{
    ck_assert_uint_eq(s->vertex_count, 5);
    ck_assert_uint_eq(s->triangle_count, 4);
    check_tri(s, 0, 0, 1, 2);
    check_tri(s, 1, 0, 2, 3);
    check_tri(s, 2, 0, 3, 4);
    check_tri(s, 3, 4, 2, 0);
    ck_assert(s->vertices[3 * 2 + 0] == 1.5f);
    ck_assert(s->vertices[3 * 3 + 1] == 2.0f);
    ck_assert(s->vertices[3 * 3 + 2] == 0.25f);
    ck_assert(s->vertices[3 * 4 + 2] == (float)-1e-3);
}

START_TEST(ply_binary_both_orders)
{
    buf o;
    scene s;
    mixed_ply(&o, 0);
    load_ok(write_file("mixed_le.ply", o.b, o.n), &s);
    check_mixed(&s);
    ck_assert_str_eq(s.name, "mixed_le.ply");
    scene_free(&s);
    mixed_ply(&o, 1);
    load_ok(write_file("mixed_be.PLY", o.b, o.n), &s);
    check_mixed(&s);
    scene_free(&s);
}
END_TEST

START_TEST(ply_ascii_mixed)
{
    const char *text =
        "ply\nformat ascii 1.0\ncomment c\n"
        "element vertex 5\n"
        "property char a\nproperty double z\n"
        "property list uchar float uv\nproperty float x\n"
        "property ushort b\nproperty float y\n"
        "element face 2\n"
        "property list uchar int vertex_indices\nproperty int flags\n"
        "element edge 1\nproperty int v1\nproperty int v2\n"
        "end_header\n"
        "-1 0 0 0 65535 0\n"
        "2 0 2 0.5 0.5 1 1 0\n"
        "\n"
        "3 0 0 1.5 0 1\r\n"
        "4 0.25 1 7 0.5 0 2\n"
        "  -5\t-1e-3 0 -0.5 9 1e0   \n"
        "5 0 1 2 3 4 -7\n"
        "3 4 2 0 0\n"
        "0 1";
    scene s;
    load_ok(write_text("mixed_ascii.ply", text), &s);
    check_mixed(&s);
    scene_free(&s);
}
END_TEST

START_TEST(ply_data_files)
{
    scene s;
    float lo[3], hi[3];
    load_ok(data_path("tetra.ply"), &s);
    ck_assert_uint_eq(s.vertex_count, 4);
    ck_assert_uint_eq(s.triangle_count, 4);
    check_tri(&s, 0, 0, 2, 1);
    check_tri(&s, 3, 1, 2, 3);
    scene_bounds(&s, lo, hi);
    ck_assert(lo[0] == 0.0f && lo[1] == 0.0f && lo[2] == 0.0f);
    ck_assert(hi[0] == 1.0f && hi[1] == 1.0f && hi[2] == 1.0f);
    scene_free(&s);

    load_ok(data_path("quad_be.ply"), &s);
    ck_assert_uint_eq(s.vertex_count, 4);
    ck_assert_uint_eq(s.triangle_count, 2);
    check_tri(&s, 0, 0, 1, 2);
    check_tri(&s, 1, 0, 2, 3);
    ck_assert(s.vertices[3 * 2 + 0] == 1.0f && s.vertices[3 * 2 + 1] == 1.0f &&
              s.vertices[3 * 2 + 2] == 0.5f);
    scene_free(&s);
}
END_TEST

/* A clean little-endian file whose bytes the hostile tests then damage. */
static size_t simple_le(buf *o, const char *vcount, const char *fcount,
                        const char *list)
{
    char header[512];
    memset(o, 0, sizeof *o);
    snprintf(header, sizeof header,
             "ply\nformat binary_little_endian 1.0\n"
             "element vertex %s\nproperty float x\nproperty float y\n"
             "property float z\nelement face %s\n"
             "property list %s vertex_indices\nend_header\n",
             vcount, fcount, list);
    put_bytes(o, header, strlen(header));
    put_f32(o, 0); put_f32(o, 0); put_f32(o, 0);
    put_f32(o, 1); put_f32(o, 0); put_f32(o, 0);
    put_f32(o, 0); put_f32(o, 1); put_f32(o, 0);
    return strlen(header);
}

START_TEST(ply_hostile_binary)
{
    buf o;
    size_t h;
    char want[64];

    /* The baseline loads. */
    h = simple_le(&o, "3", "1", "uchar int");
    put_uint(&o, 3, 1);
    put_uint(&o, 0, 4); put_uint(&o, 1, 4); put_uint(&o, 2, 4);
    {
        scene s;
        load_ok(write_file("ok.ply", o.b, o.n), &s);
        ck_assert_uint_eq(s.triangle_count, 1);
        scene_free(&s);
    }
    /* Truncated in the vertex data and in the face list. */
    EXPECT_ERROR(write_file("trunc_v.ply", o.b, h + 20), "trunc_v.ply",
                 "byte offset");
    EXPECT_ERROR(write_file("trunc_f.ply", o.b, o.n - 2), "trunc_f.ply",
                 "byte offset");
    /* Out-of-range index: the offset of the bad value is named. */
    o.b[o.n - 4] = 3;
    snprintf(want, sizeof want, "byte offset %zu", o.n - 4);
    EXPECT_ERROR(write_file("range.ply", o.b, o.n), want, "out of range");
    /* Negative index (signed type). */
    o.b[o.n - 4] = 0xff; o.b[o.n - 3] = 0xff;
    o.b[o.n - 2] = 0xff; o.b[o.n - 1] = 0xff;
    EXPECT_ERROR(write_file("neg.ply", o.b, o.n), "-1", "out of range");

    /* A face with two vertices. */
    h = simple_le(&o, "3", "1", "uchar int");
    put_uint(&o, 2, 1);
    put_uint(&o, 0, 4); put_uint(&o, 1, 4);
    snprintf(want, sizeof want, "byte offset %zu", h + 36);
    EXPECT_ERROR(write_file("two.ply", o.b, o.n), want, "at least 3");

    /* Huge declared counts, far beyond the file: refused before any
     * allocation (a 4-billion-vertex malloc would otherwise be tried). */
    simple_le(&o, "4000000000", "1", "uchar int");
    EXPECT_ERROR(write_file("huge_v.ply", o.b, o.n), "huge_v.ply",
                 "4000000000", "byte offset");
    simple_le(&o, "3", "18446744073709551615", "uchar int");
    EXPECT_ERROR(write_file("huge_f.ply", o.b, o.n), "byte offset",
                 "18446744073709551615");
    simple_le(&o, "3", "18446744073709551616", "uchar int");
    EXPECT_ERROR(write_file("over_f.ply", o.b, o.n), "line 7",
                 "not a whole number");
    /* A list count of 4 billion. */
    simple_le(&o, "3", "1", "uint int");
    put_uint(&o, 4000000000u, 4);
    put_uint(&o, 0, 4);
    EXPECT_ERROR(write_file("huge_list.ply", o.b, o.n), "byte offset",
                 "past the end");
    /* Negative list count. */
    simple_le(&o, "3", "1", "int int");
    put_uint(&o, 0xffffffffu, 4);
    EXPECT_ERROR(write_file("neg_list.ply", o.b, o.n), "byte offset",
                 "negative");
}
END_TEST

START_TEST(ply_hostile_header)
{
    static const char vxyz[] = "element vertex 1\nproperty float x\n"
                               "property float y\nproperty float z\n";
    char text[2048];
    EXPECT_ERROR(write_text("empty.ply", ""), "empty.ply", "line 1", "empty");
    EXPECT_ERROR(write_text("magic.ply", "plx\nformat ascii 1.0\n"),
                 "line 1", "not a PLY file");
    EXPECT_ERROR(write_text("noend.ply", "ply\nformat ascii 1.0\n"),
                 "line 3", "end_header");
    EXPECT_ERROR(write_text("nofmt.ply", "ply\nend_header\n"), "line 2",
                 "format");
    EXPECT_ERROR(write_text("fmt.ply", "ply\nformat binary_middle 1.0\n"
                                       "end_header\n"),
                 "line 2", "binary_middle");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s"
             "property quad w\nend_header\n", vxyz);
    EXPECT_ERROR(write_text("type.ply", text), "line 7", "quad");
    EXPECT_ERROR(write_text("prop.ply", "ply\nformat ascii 1.0\n"
                                        "property float x\nend_header\n"),
                 "line 3", "before any element");
    EXPECT_ERROR(write_text("noz.ply", "ply\nformat ascii 1.0\n"
                                       "element vertex 1\nproperty float x\n"
                                       "property float y\nend_header\n"
                                       "0 0\n"),
                 "line 3", "x, y or z");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s"
             "element face 1\nproperty list uchar float vertex_indices\n"
             "end_header\n0 0 0\n3 0 0 0\n", vxyz);
    EXPECT_ERROR(write_text("fidx.ply", text), "line 7", "integers");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s"
             "element face 1\nproperty int other\nend_header\n0 0 0\n1\n",
             vxyz);
    EXPECT_ERROR(write_text("nolist.ply", text), "line 7", "vertex_indices");
    /* A second face or vertex element, or a second index list, holds
     * geometry that would be left out: an error naming its line. */
    {
#define FACE_ "element face 1\nproperty list uchar int vertex_indices\n"
        static const struct {
            const char *name, *tail, *line, *word;
        } second[] = {
            {"twoface.ply",
             FACE_ FACE_ "end_header\n0 0 0\n3 0 0 0\n3 0 0 0\n", "line 9",
             "a second \"face\" element"},
            {"twovert.ply",
             "element vertex 1\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n0 0 0\n0 0 0\n",
             "line 7", "a second \"vertex\" element"},
            {"twolist.ply",
             FACE_ "property list uchar int vertex_index\nend_header\n"
                   "0 0 0\n3 0 0 0 3 0 0 9\n",
             "line 7", "second vertex index list"}};
#undef FACE_
        size_t k;
        for (k = 0; k < sizeof second / sizeof second[0]; k++) {
            snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s%s", vxyz,
                     second[k].tail);
            EXPECT_ERROR(write_text(second[k].name, text), second[k].line,
                         second[k].word);
        }
    }
    {
        /* A long comment is fine; a long property line is not. */
        char big[2048];
        scene s;
        memset(big, 'c', sizeof big);
        big[sizeof big - 1] = '\0';
        snprintf(text, sizeof text, "ply\nformat ascii 1.0\ncomment %.900s\n"
                 "%send_header\n0 0 0\n", big, vxyz);
        load_ok(write_text("longc.ply", text), &s);
        ck_assert_uint_eq(s.vertex_count, 1);
        scene_free(&s);
        snprintf(text, sizeof text, "ply\nformat ascii 1.0\n"
                 "element vertex 1\nproperty float %.900s\nend_header\n",
                 big);
        EXPECT_ERROR(write_text("longp.ply", text), "line 4", "too long");
    }
    EXPECT_ERROR(write_text("kw.ply", "ply\nformat ascii 1.0\nbogus 1\n"
                                      "end_header\n"),
                 "line 3", "bogus");
}
END_TEST

START_TEST(ply_hostile_ascii)
{
    static const char head[] =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    char text[1024];
    /* Line 10 is the first data line. */
    snprintf(text, sizeof text, "%s0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", head);
    EXPECT_ERROR(write_text("nonnum.ply", text), "nonnum.ply", "line 11",
                 "abc");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n", head);
    EXPECT_ERROR(write_text("nonint.ply", text), "line 13", "not an integer");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", head);
    EXPECT_ERROR(write_text("range.ply", text), "line 13", "out of range");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", head);
    EXPECT_ERROR(write_text("neg.ply", text), "line 13", "-1");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n2 0 1\n", head);
    EXPECT_ERROR(write_text("two.ply", text), "line 13", "at least 3");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n", head);
    EXPECT_ERROR(write_text("trunc.ply", text), "trunc.ply", "line 13");
    snprintf(text, sizeof text, "%s0 0 0\n1 0\n0 1 0\n3 0 1 2\n", head);
    EXPECT_ERROR(write_text("short.ply", text), "line 11", "fewer values");
    snprintf(text, sizeof text, "%s0 0 0 9\n1 0 0\n0 1 0\n3 0 1 2\n", head);
    EXPECT_ERROR(write_text("long.ply", text), "line 10", "more values");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n", head);
    EXPECT_ERROR(write_text("uchar.ply", text), "line 13", "out of range");
    /* Huge count against a short body. */
    snprintf(text, sizeof text,
             "ply\nformat ascii 1.0\nelement vertex 3000000000\n"
             "property float x\nproperty float y\nproperty float z\n"
             "end_header\n0 0 0\n");
    EXPECT_ERROR(write_text("hugea.ply", text), "line 8", "3000000000");
    EXPECT_ERROR(write_text("hugeb.ply", "ply\nformat ascii 1.0\n"
                            "element vertex 99999999999\nproperty float x\n"
                            "property float y\nproperty float z\n"
                            "end_header\n0 0 0\n"),
                 "line 3", "32-bit");
}
END_TEST

START_TEST(ply_nan_loads)
{
    /* Loaders keep NaN and overflowing values: the library reports them,
     * naming the primitive (or skips them with skip_invalid). */
    static const char text[] =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n"
        "nan 0 0\n1e300 0 0\n0 -inf 0\n3 0 1 2\n";
    scene s;
    load_ok(write_text("nan.ply", text), &s);
    ck_assert(isnan(s.vertices[0]));
    ck_assert(isinf(s.vertices[3]) && s.vertices[3] > 0);
    ck_assert(isinf(s.vertices[7]) && s.vertices[7] < 0);
    scene_free(&s);
}
END_TEST

/* ----------------------------------------------------------------- OBJ */
START_TEST(obj_cube)
{
    scene s;
    size_t t;
    int counts[8] = {0};
    load_ok(data_path("cube.obj"), &s);
    ck_assert_uint_eq(s.vertex_count, 8);
    ck_assert_uint_eq(s.triangle_count, 12);
    ck_assert_str_eq(s.name, "cube.obj");
    check_tri(&s, 0, 0, 3, 2);
    check_tri(&s, 1, 0, 2, 1);
    /* Negative indices: f -8 -4 -1 -5 is 1 5 8 4. */
    check_tri(&s, 8, 0, 4, 7);
    check_tri(&s, 9, 0, 7, 3);
    /* Each cube corner is in 3 quads: 4 or 5 of the 12 triangles. */
    for (t = 0; t < 36; t++)
        counts[s.indices[t]]++;
    for (t = 0; t < 8; t++)
        ck_assert(counts[t] >= 3 && counts[t] <= 6);
    scene_free(&s);
}
END_TEST

START_TEST(obj_forms)
{
    scene s;
    load_ok(write_text("forms.obj",
                       "# comment\nv 0 0 0\nv 1 0 0 1.0\nv 1 1 0 # c\n"
                       "v 0 1 0 0.5 0.5 0.5\nvt 0 0\nvn 0 0 1\ng grp\n"
                       "usemtl x\ns off\n"
                       "f 1/1 2/1 3/1\n"
                       "f 1/1/1 3//1 -1/1/1\n"
                       "\tf  -4//1   -3   -2 -1\r\n"
                       "f 4 3 2 1"),
            &s);
    ck_assert_uint_eq(s.vertex_count, 4);
    ck_assert_uint_eq(s.triangle_count, 6);
    check_tri(&s, 0, 0, 1, 2);
    check_tri(&s, 1, 0, 2, 3);
    check_tri(&s, 2, 0, 1, 2);
    check_tri(&s, 3, 0, 2, 3);
    check_tri(&s, 4, 3, 2, 1);
    check_tri(&s, 5, 3, 1, 0);
    scene_free(&s);
}
END_TEST

START_TEST(obj_hostile)
{
    static const char v3[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char text[512];
    snprintf(text, sizeof text, "%sf 1 2 4\n", v3);
    EXPECT_ERROR(write_text("range.obj", text), "range.obj", "line 4",
                 "out of range");
    snprintf(text, sizeof text, "%sf 1 2 0\n", v3);
    EXPECT_ERROR(write_text("zero.obj", text), "line 4", "out of range");
    snprintf(text, sizeof text, "%sf -1 -2 -4\n", v3);
    EXPECT_ERROR(write_text("negr.obj", text), "line 4", "-4");
    snprintf(text, sizeof text, "f 1 2 3\n%s", v3);
    EXPECT_ERROR(write_text("fwd.obj", text), "line 1", "out of range");
    snprintf(text, sizeof text, "%sf 1 2\n", v3);
    EXPECT_ERROR(write_text("two.obj", text), "line 4", "at least 3");
    snprintf(text, sizeof text, "%sf 1 2 x\n", v3);
    EXPECT_ERROR(write_text("nonint.obj", text), "line 4", "not an integer");
    snprintf(text, sizeof text, "%sf 1 2 3/a\n", v3);
    EXPECT_ERROR(write_text("slash.obj", text), "line 4", "3/a");
    snprintf(text, sizeof text, "%sf 1 2 3/1/1/1\n", v3);
    EXPECT_ERROR(write_text("slashes.obj", text), "line 4", "form");
    snprintf(text, sizeof text, "%sf 1 2 99999999999999999999999\n", v3);
    EXPECT_ERROR(write_text("big.obj", text), "line 4", "out of range");
    EXPECT_ERROR(write_text("vnum.obj", "v 0 0 0\nv 1 zero 0\n"),
                 "vnum.obj", "line 2", "zero");
    EXPECT_ERROR(write_text("vfew.obj", "\n\nv 0 0\n"), "line 3", "three");
    EXPECT_ERROR(write_text("vextra.obj", "v 0 0 0 1 q\n"), "line 1", "q");
    EXPECT_ERROR(write_file("nul.obj", "v 0 0\0 0\n", 10), "line 1");
}
END_TEST

START_TEST(obj_empty_and_nan)
{
    scene s;
    load_ok(data_path("empty.obj"), &s);
    ck_assert_uint_eq(s.vertex_count, 3);
    ck_assert_uint_eq(s.triangle_count, 0);
    scene_free(&s);
    load_ok(write_text("zero.obj", ""), &s);
    ck_assert_uint_eq(s.triangle_count, 0);
    scene_free(&s);
    load_ok(data_path("nan.obj"), &s);
    ck_assert_uint_eq(s.triangle_count, 3);
    ck_assert(isnan(s.vertices[3 * s.indices[4]]));
    scene_free(&s);
}
END_TEST

/* Binary/ASCII mismatches and huge polygons (issue 6). */
START_TEST(format_mismatch_and_huge_polygons)
{
    static const char vxyz[] = "element vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\n"
                               "element face 1\n"
                               "property list uchar int vertex_indices\n"
                               "end_header\n";
    static const char body[] = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    char text[1024];
    size_t i, n, len;
    char *big;
    scene s;
    /* declared binary, ASCII body: 12 bytes per vertex read as floats,
     * then a list count of '3' (0x33) runs past the end */
    snprintf(text, sizeof text, "ply\nformat binary_little_endian 1.0\n%s%s",
             vxyz, body);
    EXPECT_ERROR(write_text("bin_ascii.ply", text), "bin_ascii.ply",
                 "byte offset");
    /* declared ASCII, binary body */
    {
        unsigned char raw[1024];
        size_t h;
        float f[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s", vxyz);
        h = strlen(text);
        memcpy(raw, text, h);
        memcpy(raw + h, f, sizeof f);
        EXPECT_ERROR(write_file("ascii_bin.ply", raw, h + sizeof f),
                     "ascii_bin.ply", "line 10");
    }
    /* a 200000-gon (ASCII PLY, uint count) and a 100000-gon (OBJ): fan
     * triangulated, every index checked */
    n = 200000;
    big = malloc(64 + 20 * n);
    ck_assert_ptr_nonnull(big);
    len = (size_t)sprintf(big, "ply\nformat ascii 1.0\nelement vertex %zu\n"
                          "property float x\nproperty float y\n"
                          "property float z\nelement face 1\n"
                          "property list uint int vertex_indices\n"
                          "end_header\n", n);
    for (i = 0; i < n; i++)
        len += (size_t)sprintf(big + len, "%zu %zu 0\n", i % 1000, i / 1000);
    len += (size_t)sprintf(big + len, "%zu", n);
    for (i = 0; i < n; i++)
        len += (size_t)sprintf(big + len, " %zu", i);
    big[len++] = '\n';
    load_ok(write_file("poly.ply", big, len), &s);
    ck_assert_uint_eq(s.triangle_count, n - 2);
    scene_free(&s);
    n = 100000;
    len = 0;
    for (i = 0; i < n; i++)
        len += (size_t)sprintf(big + len, "v %zu 0 %zu\n", i % 1000, i / 1000);
    len += (size_t)sprintf(big + len, "f");
    for (i = 0; i < n; i++)
        len += (size_t)sprintf(big + len, " %zu", n - i);
    big[len++] = '\n';
    load_ok(write_file("poly.obj", big, len), &s);
    ck_assert_uint_eq(s.triangle_count, n - 2);
    scene_free(&s);
    /* the same polygon with one index out of range: refused, named */
    big[len - 2] = '0';
    EXPECT_ERROR(write_file("poly_bad.obj", big, len), "poly_bad.obj",
                 "out of range");
    free(big);
    /* empty and whitespace-only files */
    EXPECT_ERROR(write_text("ws.ply", "\n\n"), "ws.ply", "line 1");
    load_ok(write_text("ws.obj", "\n  \n# nothing\n"), &s);
    ck_assert_uint_eq(s.triangle_count, 0);
    scene_free(&s);
}
END_TEST

START_TEST(scene_load_dispatch)
{
    EXPECT_ERROR("scene.stl", "scene.stl", "unknown scene type");
    EXPECT_ERROR("/nonexistent/x.ply", "/nonexistent/x.ply", "cannot open");
    EXPECT_ERROR("builtin:", "builtin:");
    EXPECT_ERROR("builtin:teapot", "teapot", "unknown built-in");
    EXPECT_ERROR("builtin:sphere:", "N is empty");
    EXPECT_ERROR("builtin:sphere:abc", "not a whole number");
    EXPECT_ERROR("builtin:sphere:-5", "not a whole number");
    EXPECT_ERROR("builtin:sphere:0", "from 1 to 50000000");
    EXPECT_ERROR("builtin:sphere:50000001", "from 1 to 50000000");
    EXPECT_ERROR("builtin:city:184467440737095516160000", "from 1 to");
    {
        scene s;
        load_ok("builtin:terrain:500", &s);
        ck_assert_str_eq(s.name, "builtin:terrain");
        ck_assert(s.triangle_count >= 450 && s.triangle_count <= 550);
        scene_free(&s);
        /* The default size. */
        load_ok("builtin:sphere", &s);
        ck_assert(s.triangle_count >= 95000 && s.triangle_count <= 105000);
        scene_free(&s);
    }
}
END_TEST

/* ------------------------------------------------------------- builtins */
static void check_valid(const scene *s)
{
    size_t i;
    ck_assert(s->triangle_count > 0);
    for (i = 0; i < s->triangle_count * 3; i++)
        ck_assert_uint_lt(s->indices[i], s->vertex_count);
    for (i = 0; i < s->vertex_count * 3; i++)
        ck_assert(fabsf(s->vertices[i]) <= FLT_MAX);
}

START_TEST(builtin_sizes_and_determinism)
{
    static const char *const names[] = {"sphere", "terrain", "city"};
    static const size_t sizes[] = {1, 2, 13, 1000, 12345, 200000};
    size_t n, k;
    for (n = 0; n < 3; n++) {
        for (k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            scene a, b;
            char err[256];
            double ratio;
            ck_assert_msg(scene_builtin(names[n], sizes[k], &a, err,
                                        sizeof err) == 0, "%s", err);
            ck_assert(scene_builtin(names[n], sizes[k], &b, err,
                                    sizeof err) == 0);
            check_valid(&a);
            ck_assert_uint_eq(a.vertex_count, b.vertex_count);
            ck_assert_uint_eq(a.triangle_count, b.triangle_count);
            ck_assert(memcmp(a.vertices, b.vertices,
                             a.vertex_count * 3 * sizeof(float)) == 0);
            ck_assert(memcmp(a.indices, b.indices,
                             a.triangle_count * 3 * sizeof(uint32_t)) == 0);
            ratio = (double)a.triangle_count / (double)sizes[k];
            if (sizes[k] >= 1000)
                ck_assert_msg(ratio > 0.95 && ratio < 1.05,
                              "%s:%zu gave %zu triangles", names[n],
                              sizes[k], a.triangle_count);
            else
                ck_assert_msg(a.triangle_count <= 12 + 2 * sizes[k],
                              "%s:%zu gave %zu triangles", names[n],
                              sizes[k], a.triangle_count);
            scene_free(&a);
            scene_free(&b);
        }
    }
}
END_TEST

START_TEST(builtin_shapes)
{
    scene s;
    char err[256];
    size_t i, boxes;
    float lo[3], hi[3], hmin = HUGE_VALF, hmax = 0.0f;
    /* Sphere: every vertex on the unit sphere. */
    ck_assert(scene_builtin("sphere", 5000, &s, err, sizeof err) == 0);
    for (i = 0; i < s.vertex_count; i++) {
        const float *p = s.vertices + 3 * i;
        double r = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] +
                        (double)p[2] * p[2]);
        ck_assert(fabs(r - 1.0) < 1e-5);
    }
    scene_free(&s);
    /* Terrain: a height field, y the smallest extent, not flat. */
    ck_assert(scene_builtin("terrain", 5000, &s, err, sizeof err) == 0);
    scene_bounds(&s, lo, hi);
    ck_assert(hi[1] - lo[1] > 0.05f && hi[1] - lo[1] < hi[0] - lo[0]);
    scene_free(&s);
    /* City: whole boxes of very different heights. */
    ck_assert(scene_builtin("city", 12000, &s, err, sizeof err) == 0);
    ck_assert_uint_eq(s.triangle_count % 12, 0);
    boxes = s.triangle_count / 12;
    ck_assert_uint_eq(s.vertex_count, boxes * 8);
    for (i = 1; i < boxes; i++) {
        const float *v = s.vertices + 24 * i;
        float h = v[3 * 7 + 1] - v[1];
        ck_assert(h > 0.0f);
        if (h < hmin)
            hmin = h;
        if (h > hmax)
            hmax = h;
    }
    ck_assert_msg(hmax / hmin > 100.0f, "heights %g to %g", hmin, hmax);
    scene_free(&s);
    ck_assert(scene_builtin("city", 50000001, &s, err, sizeof err) == -1);
    ck_assert(scene_builtin("city", 0, &s, err, sizeof err) == -1);
    ck_assert(strstr(err, "city") != NULL);
}
END_TEST

/* -------------------------------------------------------------- cameras */
/* Slab test against the box grown by a rounding margin (a flat or point
 * box is hit only approximately by any float ray). */
static int ray_hits_box(const atrbvh_ray *r, const float blo[3],
                        const float bhi[3])
{
    double t0 = r->tmin, t1 = r->tmax, lo[3], hi[3], ext = 0.0, mag = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        if (bhi[k] - blo[k] > ext)
            ext = (double)bhi[k] - blo[k];
        if (fabs(blo[k]) > mag)
            mag = fabs(blo[k]);
        if (fabs(bhi[k]) > mag)
            mag = fabs(bhi[k]);
    }
    for (k = 0; k < 3; k++) {
        lo[k] = blo[k] - (1e-5 * ext + 1e-5 * mag);
        hi[k] = bhi[k] + (1e-5 * ext + 1e-5 * mag);
    }
    for (k = 0; k < 3; k++) {
        double a, b, inv;
        if (r->dir[k] == 0.0f) {
            if (r->origin[k] < lo[k] || r->origin[k] > hi[k])
                return 0;
            continue;
        }
        inv = 1.0 / r->dir[k];
        a = (lo[k] - r->origin[k]) * inv;
        b = (hi[k] - r->origin[k]) * inv;
        if (a > b) {
            double t = a;
            a = b;
            b = t;
        }
        if (a > t0)
            t0 = a;
        if (b < t1)
            t1 = b;
    }
    return t0 <= t1;
}

START_TEST(camera_frames_box)
{
    static const float boxes[][6] = {{-1, -1, -1, 1, 1, 1},
                                     {0, 0, 0, 100, 1, 3},
                                     {-1e4f, 5, 7, -9e3f, 5, 8},
                                     {2, 2, 2, 2, 2, 2}};
    static const float aspects[] = {4.0f / 3.0f, 1.0f, 0.25f, 8.0f};
    size_t b, a;
    unsigned which;
    for (b = 0; b < sizeof boxes / sizeof boxes[0]; b++) {
        const float *lo = boxes[b], *hi = boxes[b] + 3;
        for (a = 0; a < 4; a++) {
            for (which = 0; which < 10; which++) {
                camera cam;
                atrbvh_ray r;
                unsigned x, y, corner;
                int inside = 1, k;
                float c[3];
                camera_frame(lo, hi, which, aspects[a], &cam);
                for (k = 0; k < 3; k++) {
                    inside &= cam.eye[k] >= lo[k] && cam.eye[k] <= hi[k];
                    c[k] = 0.5f * lo[k] + 0.5f * hi[k];
                }
                ck_assert_msg(!inside, "eye inside box %zu", b);
                ck_assert(cam.far_distance > 0.0f);
                /* Viewpoints above the box's centre, never below. */
                ck_assert(cam.eye[1] > c[1]);
                /* Rays are unit length; the centre pixel's ray hits the
                 * box, and so do most rays of a coarse grid for a box
                 * that fills the frame. */
                for (y = 0; y < 6; y++) {
                    for (x = 0; x < 8; x++) {
                        double len;
                        camera_ray(&cam, 8, 6, x, y, 0.5f, 0.5f, &r);
                        len = sqrt((double)r.dir[0] * r.dir[0] +
                                   (double)r.dir[1] * r.dir[1] +
                                   (double)r.dir[2] * r.dir[2]);
                        ck_assert(fabs(len - 1.0) < 1e-5);
                        ck_assert(r.tmin == 0.0f && r.tmax > 0.0f);
                    }
                }
                camera_ray(&cam, 101, 101, 50, 50, 0.5f, 0.5f, &r);
                ck_assert_msg(ray_hits_box(&r, lo, hi),
                              "centre ray misses box %zu view %u", b, which);
                /* Every corner of the box projects into the image. */
                for (corner = 0; corner < 8; corner++) {
                    double p[3], d[3] = {0, 0, 0}, f = 0, u = 0, v = 0,
                                      rl = 0, ul = 0;
                    for (k = 0; k < 3; k++) {
                        p[k] = (corner >> k) & 1 ? hi[k] : lo[k];
                        d[k] = p[k] - cam.eye[k];
                        f += d[k] * cam.forward[k];
                        u += d[k] * cam.right[k];
                        v += d[k] * cam.up[k];
                        rl += (double)cam.right[k] * cam.right[k];
                        ul += (double)cam.up[k] * cam.up[k];
                    }
                    ck_assert(f > 0.0);
                    /* right/up are scaled to the half-extent at distance 1,
                     * so in-picture means |u| <= |right|^2 * f. */
                    ck_assert_msg(fabs(u) <= rl * f * 1.0001 &&
                                      fabs(v) <= ul * f * 1.0001,
                                  "corner %u of box %zu off-picture", corner,
                                  b);
                    /* ...and within reach of the primary rays. */
                    ck_assert(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) <
                              cam.far_distance);
                }
            }
        }
    }
}
END_TEST

START_TEST(camera_deterministic_and_distinct)
{
    float lo[3] = {-1, 0, -2}, hi[3] = {3, 1, 2};
    camera a, b, c;
    camera_frame(lo, hi, 0, 1.5f, &a);
    camera_frame(lo, hi, 0, 1.5f, &b);
    camera_frame(lo, hi, 1, 1.5f, &c);
    ck_assert(memcmp(&a, &b, sizeof a) == 0);
    ck_assert(memcmp(a.eye, c.eye, sizeof a.eye) != 0);
    /* Viewpoint 0 is in front (+z) and to the right (+x). */
    ck_assert(a.eye[2] > hi[2] && a.eye[0] > 1.0f);
}
END_TEST

/* ------------------------------------------------ held-out failures */
START_TEST(flt_max_is_finite)
{
    /* 1 + 2^-24 is halfway between 1 and the next float; this decimal is
     * 1e-20 above it, and its nearest double is the midpoint itself, so
     * strtod-then-cast rounds to even (1.0f) where the correct answer is
     * the float above. */
    static const char above_mid[] = "1.000000059604644775400625";
    const float next1 = nextafterf(1.0f, 2.0f);
    char text[1024];
    scene s;
    buf o;
    size_t k;
    snprintf(text, sizeof text,
             "v 3.4028235e+38 -3.4028235e+38 3.40282347e+38\n"
             "v 0 0 %s\nv 1 0 0\nv 0 1 3.4028236e+38\nf 1 2 3\nf 2 3 4\n",
             above_mid);
    load_ok(write_text("fltmax.obj", text), &s);
    ck_assert(s.vertices[0] == FLT_MAX);
    ck_assert(s.vertices[1] == -FLT_MAX);
    ck_assert(s.vertices[2] == FLT_MAX);
    ck_assert_msg(s.vertices[5] == next1, "%a", (double)s.vertices[5]);
    ck_assert(isinf(s.vertices[11])); /* rounds to infinity */
    scene_free(&s);
    /* ASCII PLY: a float and a double property */
    snprintf(text, sizeof text,
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
             "property double y\nproperty float z\nelement face 1\n"
             "property list uchar int vertex_indices\nend_header\n"
             "3.4028235e+38 3.4028235e+38 %s\n"
             "-3.40282347e+38 0 0\n0 1 0\n3 0 1 2\n",
             above_mid);
    load_ok(write_text("fltmax.ply", text), &s);
    ck_assert(s.vertices[0] == FLT_MAX);
    ck_assert(s.vertices[1] == FLT_MAX);
    ck_assert_msg(s.vertices[2] == next1, "%a", (double)s.vertices[2]);
    ck_assert(s.vertices[3] == -FLT_MAX);
    scene_free(&s);
    /* binary PLY doubles: just above FLT_MAX (rounds to it), and the first
     * double that rounds to infinity */
    for (k = 0; k < 2; k++) {
        static const char header[] =
            "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
            "property double x\nproperty double y\nproperty double z\n"
            "element face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n";
        double big = k == 0 ? 0x1.fffffefffffffp+127 : 0x1.ffffffp+127;
        memset(&o, 0, sizeof o);
        put_bytes(&o, header, strlen(header));
        put_f64(&o, big); put_f64(&o, -big); put_f64(&o, 0);
        put_f64(&o, 1); put_f64(&o, 0); put_f64(&o, 0);
        put_f64(&o, 0); put_f64(&o, 1); put_f64(&o, 0);
        put_uint(&o, 3, 1); put_uint(&o, 0, 4); put_uint(&o, 1, 4);
        put_uint(&o, 2, 4);
        load_ok(write_file("fltmax_bin.ply", o.b, o.n), &s);
        if (k == 0) {
            ck_assert(s.vertices[0] == FLT_MAX);
            ck_assert(s.vertices[1] == -FLT_MAX);
        } else {
            ck_assert(isinf(s.vertices[0]) && s.vertices[0] > 0);
            ck_assert(isinf(s.vertices[1]) && s.vertices[1] < 0);
        }
        scene_free(&s);
    }
}
END_TEST

START_TEST(byte_order_mark)
{
    scene s;
    /* OBJ: the first vertex must not be lost (every index would shift) */
    load_ok(write_text("bom.obj", "\xef\xbb\xbfv 5 6 7\nv 1 0 0\nv 0 1 0\n"
                                  "v 9 9 9\nf 1 2 3\n"),
            &s);
    ck_assert_uint_eq(s.vertex_count, 4);
    ck_assert_uint_eq(s.triangle_count, 1);
    check_tri(&s, 0, 0, 1, 2);
    ck_assert(s.vertices[0] == 5.0f && s.vertices[2] == 7.0f);
    scene_free(&s);
    /* ASCII PLY */
    load_ok(write_text("bom.ply",
                       "\xef\xbb\xbfply\nformat ascii 1.0\nelement vertex 3\n"
                       "property float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int "
                       "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                       "3 0 1 2\n"),
            &s);
    ck_assert_uint_eq(s.triangle_count, 1);
    scene_free(&s);
    /* a byte-order mark anywhere else is damage: refused, not skipped */
    EXPECT_ERROR(write_text("bom2.obj", "v 0 0 0\n\xef\xbb\xbfv 1 0 0\n"
                                        "v 0 1 0\nf 1 2 3\n"),
                 "bom2.obj", "line 2", "unknown statement");
}
END_TEST

START_TEST(unknown_lines_not_ignored)
{
    scene s;
    EXPECT_ERROR(write_text("numbers.obj", "v 0 0 0\n1 0 0\nv 0 1 0\n"
                                           "v 1 1 0\nf 1 2 3\n"),
                 "numbers.obj", "line 2", "unknown statement");
    EXPECT_ERROR(write_text("upper.obj", "v 0 0 0\nV 1 0 0\nv 0 1 0\n"),
                 "line 2", "\"V\"");
    /* the specification's other statements are skipped */
    load_ok(write_text("known.obj", "mtllib a.mtl\no x\ng y\ns off\n"
                                    "usemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "vt 0 0\nvn 0 0 1\nvp 0\nl 1 2\np 1\n"
                                    "f 1 2 3\n"),
            &s);
    ck_assert_uint_eq(s.triangle_count, 1);
    scene_free(&s);
    /* ASCII PLY: a face more than the header declares */
    EXPECT_ERROR(write_text("extra.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\n"
                            "property float x\nproperty float y\n"
                            "property float z\nelement face 1\n"
                            "property list uchar int vertex_indices\n"
                            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
                            "3 2 1 0\n\n"),
                 "extra.ply", "line 14", "after the last element");
    /* trailing blank lines are fine */
    load_ok(write_text("blank.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3\n"
                       "property float x\nproperty float y\n"
                       "property float z\nelement face 1\n"
                       "property list uchar int vertex_indices\n"
                       "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n \n\n"),
            &s);
    scene_free(&s);
}
END_TEST

/* Runs scene_load(path) in a child under alarm(10): 0 when it returned
 * -1 with every `want` in the message, else a description in why.  The
 * old loader read /dev/zero until memory ran out: a timeout or a crash. */
static int refused_in_child(const char *path, const char *want1,
                            const char *want2, char *why, size_t why_len)
{
    int fds[2], status = 0;
    pid_t pid;
    char msg[600];
    ssize_t got = 0, n;
    ck_assert_int_eq(pipe(fds), 0);
    fflush(NULL);
    pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        scene s;
        char err[512];
        int rc;
        close(fds[0]);
        alarm(10);
        err[0] = '\0';
        rc = scene_load(path, &s, err, sizeof err);
        if (write(fds[1], err, strlen(err)) < 0)
            _exit(3);
        _exit(rc == -1 ? 0 : 2);
    }
    close(fds[1]);
    while ((n = read(fds[0], msg + got, sizeof msg - 1 - (size_t)got)) > 0)
        got += n;
    close(fds[0]);
    msg[got > 0 ? got : 0] = '\0';
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    if (WIFSIGNALED(status)) {
        snprintf(why, why_len, "%s: killed by signal %d (%s)", path,
                 WTERMSIG(status),
                 WTERMSIG(status) == SIGALRM ? "still reading after 10 s"
                                             : "crash");
        return -1;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        snprintf(why, why_len, "%s: loaded, or failed oddly: %s", path, msg);
        return -1;
    }
    if ((want1 && !strstr(msg, want1)) || (want2 && !strstr(msg, want2))) {
        snprintf(why, why_len, "%s: message \"%s\" lacks \"%s\"/\"%s\"", path,
                 msg, want1 ? want1 : "", want2 ? want2 : "");
        return -1;
    }
    return 0;
}

START_TEST(bounded_reading)
{
    static const char head[] =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    char path[600], why[800];
    const char *p;
    int fd;
    scene s;
    /* a link to /dev/zero */
    snprintf(path, sizeof path, "%s/zero.ply", tmpdir);
    ck_assert_int_eq(symlink("/dev/zero", path), 0);
    ck_assert_msg(refused_in_child(path, "not a PLY file", NULL, why,
                                   sizeof why) == 0, "%s", why);
    /* 2 GB sparse files: all zeros, and a valid header then zeros */
    snprintf(path, sizeof path, "%s/sparse0.ply", tmpdir);
    fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(ftruncate(fd, (off_t)2 << 30), 0);
    close(fd);
    ck_assert_msg(refused_in_child(path, "not a PLY file", NULL, why,
                                   sizeof why) == 0, "%s", why);
    p = write_text("sparse1.ply", head);
    fd = open(p, O_WRONLY);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(ftruncate(fd, (off_t)2 << 30), 0);
    close(fd);
    ck_assert_msg(refused_in_child(p, "sparse1.ply", "more than the elements",
                                   why, sizeof why) == 0, "%s", why);
    /* a binary header declaring far more than the file holds (above the
     * small-file size, so refused from the size alone) */
    {
        static const char bh[] =
            "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\n"
            "property float x\nproperty float y\nproperty float z\n"
            "end_header\n";
        p = write_text("short_big.ply", bh);
        fd = open(p, O_WRONLY);
        ck_assert_int_ge(fd, 0);
        ck_assert_int_eq(ftruncate(fd, (off_t)(strlen(bh) + (64u << 20))), 0);
        close(fd);
        ck_assert_msg(refused_in_child(p, "truncated", "1200000000", why,
                                       sizeof why) == 0, "%s", why);
    }
    /* an endless header: 2 MB of comment */
    {
        size_t n = 2u << 20, k;
        char *big = malloc(n + 64);
        ck_assert_ptr_nonnull(big);
        strcpy(big, "ply\ncomment ");
        for (k = strlen(big); k < n; k++)
            big[k] = 'x';
        strcpy(big + n, "\nend_header\n");
        p = write_text("longhead.ply", big);
        free(big);
        EXPECT_ERROR(p, "longhead.ply", "end_header");
    }
    /* a FIFO is read as a stream: it still loads */
    snprintf(path, sizeof path, "%s/fifo.ply", tmpdir);
    ck_assert_int_eq(mkfifo(path, 0600), 0);
    {
        pid_t pid;
        int status;
        fflush(NULL);
        pid = fork();
        ck_assert_int_ge(pid, 0);
        if (pid == 0) {
            int w = open(path, O_WRONLY);
            const char body[] = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
            alarm(20);
            if (w < 0 || write(w, head, strlen(head)) < 0 ||
                write(w, body, strlen(body)) < 0)
                _exit(1);
            _exit(0);
        }
        load_ok(path, &s);
        ck_assert_uint_eq(s.triangle_count, 1);
        scene_free(&s);
        ck_assert_int_eq(waitpid(pid, &status, 0), pid);
        ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
}
END_TEST

static void remove_tmpdir(void)
{
    char cmd[600];
    /* Only files this program wrote live there. */
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    if (tmpdir[0] && system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmpdir);
}

int main(void)
{
    Suite *s = suite_create("loaders");
    TCase *ply = tcase_create("ply");
    TCase *obj = tcase_create("obj");
    TCase *gen = tcase_create("builtin");
    TCase *cam = tcase_create("camera");
    int status;
    if (!make_tmpdir())
        return EXIT_FAILURE;
    tcase_set_timeout(ply, 60);
    tcase_add_test(ply, ply_binary_both_orders);
    tcase_add_test(ply, ply_ascii_mixed);
    tcase_add_test(ply, ply_data_files);
    tcase_add_test(ply, ply_hostile_binary);
    tcase_add_test(ply, ply_hostile_header);
    tcase_add_test(ply, ply_hostile_ascii);
    tcase_add_test(ply, ply_nan_loads);
    tcase_add_test(ply, flt_max_is_finite);
    tcase_add_test(ply, byte_order_mark);
    tcase_add_test(ply, unknown_lines_not_ignored);
    tcase_add_test(ply, bounded_reading);
    suite_add_tcase(s, ply);
    tcase_set_timeout(obj, 60);
    tcase_add_test(obj, obj_cube);
    tcase_add_test(obj, obj_forms);
    tcase_add_test(obj, obj_hostile);
    tcase_add_test(obj, format_mismatch_and_huge_polygons);
    tcase_add_test(obj, obj_empty_and_nan);
    tcase_add_test(obj, scene_load_dispatch);
    suite_add_tcase(s, obj);
    tcase_set_timeout(gen, 300);
    tcase_add_test(gen, builtin_sizes_and_determinism);
    tcase_add_test(gen, builtin_shapes);
    suite_add_tcase(s, gen);
    tcase_set_timeout(cam, 60);
    tcase_add_test(cam, camera_frames_box);
    tcase_add_test(cam, camera_deterministic_and_distinct);
    suite_add_tcase(s, cam);
    status = tu_run(s);
    remove_tmpdir();
    return status;
}
