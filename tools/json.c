/*
 * json.c - see json.h.  Output is indented two spaces per level so that a
 * human can read it and line-based tools can grep it.
 */
#include "config.h"

#include "json.h"

#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void json_init(json_writer *w, FILE *f)
{
    memset(w, 0, sizeof *w);
    w->f = f;
}

static void indent(json_writer *w)
{
    int i;
    fputc('\n', w->f);
    for (i = 0; i < w->depth; i++)
        fputs("  ", w->f);
}

/* Separator and indentation before a value or key. */
static void before_value(json_writer *w)
{
    if (w->after_key) {
        w->after_key = 0;
        return;
    }
    if (w->depth > 0) {
        if (w->count[w->depth - 1] > 0)
            fputc(',', w->f);
        w->count[w->depth - 1]++;
        indent(w);
    }
}

/* Objects and arrays: the opening character, one more level; the closing
 * one after the last member's line. */
static void begin_level(json_writer *w, int open)
{
    before_value(w);
    fputc(open, w->f);
    if (w->depth < JSON_MAX_DEPTH) {
        w->count[w->depth] = 0;
        w->depth++;
    }
}

static void end_level(json_writer *w, int close)
{
    int had = 0;
    if (w->depth > 0) {
        had = w->count[w->depth - 1] > 0;
        w->depth--;
    }
    if (had)
        indent(w);
    fputc(close, w->f);
}

void json_begin_object(json_writer *w)
{
    begin_level(w, '{');
}

void json_end_object(json_writer *w)
{
    end_level(w, '}');
    if (w->depth == 0)
        fputc('\n', w->f);
}

/* Arrays: the same layout as objects, without keys. */
void json_begin_array(json_writer *w)
{
    begin_level(w, '[');
}

void json_end_array(json_writer *w)
{
    end_level(w, ']');
}

/* Length of the valid UTF-8 sequence at s (1..4), or 0 if invalid. */
static size_t utf8_len(const unsigned char *s)
{
    unsigned c = s[0];
    size_t n, k;
    unsigned cp;
    if (c < 0x80)
        return 1;
    if (c >= 0xc2 && c <= 0xdf) {
        n = 2;
        cp = c & 0x1f;
    } else if (c >= 0xe0 && c <= 0xef) {
        n = 3;
        cp = c & 0x0f;
    } else if (c >= 0xf0 && c <= 0xf4) {
        n = 4;
        cp = c & 0x07;
    } else {
        return 0;
    }
    for (k = 1; k < n; k++) {
        if ((s[k] & 0xc0) != 0x80)
            return 0;
        cp = (cp << 6) | (s[k] & 0x3fu);
    }
    /* Overlong forms, surrogates and beyond U+10FFFF are not UTF-8. */
    if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) ||
        (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff)
        return 0;
    return n;
}

static void write_string(FILE *f, const char *str)
{
    const unsigned char *s = (const unsigned char *)(str ? str : "");
    fputc('"', f);
    while (*s) {
        unsigned c = *s;
        size_t n;
        if (c == '"' || c == '\\') {
            fputc('\\', f);
            fputc((int)c, f);
            s++;
        } else if (c < 0x20 || c == 0x7f) {
            switch (c) {
            case '\n': fputs("\\n", f); break;
            case '\r': fputs("\\r", f); break;
            case '\t': fputs("\\t", f); break;
            case '\b': fputs("\\b", f); break;
            case '\f': fputs("\\f", f); break;
            default: fprintf(f, "\\u%04x", c); break;
            }
            s++;
        } else if ((n = utf8_len(s)) == 0) {
            fputs("\\ufffd", f);
            s++;
        } else {
            fwrite(s, 1, n, f);
            s += n;
        }
    }
    fputc('"', f);
}

void json_key(json_writer *w, const char *key)
{
    before_value(w);
    write_string(w->f, key);
    fputs(": ", w->f);
    w->after_key = 1;
}

void json_string(json_writer *w, const char *s)
{
    before_value(w);
    write_string(w->f, s);
}

void json_uint(json_writer *w, uint64_t v)
{
    before_value(w);
    fprintf(w->f, "%" PRIu64, v);
}

void json_int(json_writer *w, int64_t v)
{
    before_value(w);
    fprintf(w->f, "%" PRId64, v);
}

/* The shorter of 15 and 17 significant digits that reads back as the same
 * double (17 always does), so 0.1 prints as 0.1. */
void json_double(json_writer *w, double v)
{
    char buf[40];
    before_value(w);
    if (!isfinite(v)) {
        fputs("null", w->f);
        return;
    }
    snprintf(buf, sizeof buf, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, sizeof buf, "%.17g", v);
    fputs(buf, w->f);
}

void json_bool(json_writer *w, int v)
{
    before_value(w);
    fputs(v ? "true" : "false", w->f);
}

void json_null(json_writer *w)
{
    before_value(w);
    fputs("null", w->f);
}

void json_kv_string(json_writer *w, const char *key, const char *s)
{
    json_key(w, key);
    json_string(w, s);
}

void json_kv_uint(json_writer *w, const char *key, uint64_t v)
{
    json_key(w, key);
    json_uint(w, v);
}

void json_kv_int(json_writer *w, const char *key, int64_t v)
{
    json_key(w, key);
    json_int(w, v);
}

void json_kv_double(json_writer *w, const char *key, double v)
{
    json_key(w, key);
    json_double(w, v);
}

void json_kv_bool(json_writer *w, const char *key, int v)
{
    json_key(w, key);
    json_bool(w, v);
}
