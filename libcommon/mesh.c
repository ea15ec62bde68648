/* mesh.c -- MESH stream reading and writing; see mesh.h and man 5 stopmo-mesh. */
#include "mesh.h"
#include "cm_error.h"
#include "numparse.h"
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#ifndef MADV_POPULATE_READ
#define MADV_POPULATE_READ 22      /* Linux 5.14 */
#endif
#include <sys/stat.h>
#include <pthread.h>
#include <unistd.h>

#define MAX_COUNT 200000000
/* the longest text line accepted, '\n' not counted (stopmo-mesh(5)) */
#define MESH_LINE_MAX (1 << 20)
/* a regular file whose header announces more than this many bytes of data
 * beyond the file's size fails at once instead of allocating for them */
#define SIZE_CHECK_MIN (16u << 20)

int mesh_alloc(struct mesh *m, int nv, int nf, int nframes)
{
    memset(m, 0, sizeof *m);
    m->nv = nv;
    m->nf = nf;
    m->nframes = nframes;
    m->F = calloc((size_t)nf * 3 + 1, sizeof *m->F);
    m->V = calloc((size_t)nframes * nv * 3 + 1, sizeof *m->V);
    m->cut = calloc((size_t)nframes + 1, 1);
    if (!m->F || !m->V || !m->cut) {
        mesh_free(m);
        return cm_seterr("out of memory for %d vertices x %d frames", nv, nframes);
    }
    return 0;
}

void mesh_free(struct mesh *m)
{
    free(m->F);
    free(m->V);
    free(m->cut);
    memset(m, 0, sizeof *m);
}

int mesh_nclips(const struct mesh *m)
{
    int c = m->nframes > 0;
    for (int k = 1; k < m->nframes; k++)
        c += m->cut[k] != 0;
    return c;
}

/* ---------------- buffered input ---------------- */

/* The buffer stays readable (and initialized) BUF_PAD bytes past its
 * capacity, so numbers parse with parse_double_padded (8 bytes at once). */
#define BUF_PAD 16
#define RAW_FILL 4096   /* bytes read into the buffer at a time once a stream is known raw */

static int fill(struct mesh_reader *r)
{
    if (r->eof)
        return 0;
    if (r->pos > 0) {
        memmove(r->buf, r->buf + r->pos, r->len - r->pos);
        r->len -= r->pos;
        r->pos = 0;
    }
    if (r->len + 1 >= r->cap) {
        char *nb = realloc(r->buf, 2 * r->cap + BUF_PAD);
        if (!nb)
            return cm_seterr("cannot read '%s': out of memory", r->name);
        memset(nb + r->cap, 0, r->cap + BUF_PAD);
        r->cap *= 2;
        r->buf = nb;
    }
    /* a raw stream's blocks are read straight into place (read_bytes):
     * only its text lines ("frame 17 cut") go through this buffer, so it
     * reads little at a time; a full buffer would hold the next frames'
     * blocks, which read_bytes would then copy out (every byte twice: 5% of
     * dict-learn's CPU at the Monkey size, perf) */
    size_t want = r->cap - 1 - r->len;
    if (r->raw && want > RAW_FILL) want = RAW_FILL;
    size_t n;
    if (r->map) {
        n = r->map_len - r->map_pos < want ? r->map_len - r->map_pos : want;
        memcpy(r->buf + r->len, r->map + r->map_pos, n);
        r->map_pos += n;
    } else
        n = fread(r->buf + r->len, 1, want, r->f);
    if (n == 0) {
        if (ferror(r->f))
            return cm_seterr("cannot read '%s': %s", r->name, strerror(errno));
        r->eof = 1;
        return 0;
    }
    r->len += n;
    r->buf[r->len] = 0;        /* sentinel: parsing stops at the data's end */
    return 1;
}

/* Next line (NUL terminated, without '\n'), or NULL at end of input
 * (check cm_errmsg via *err).  Skips blank and '#' comment lines. */
static char *next_line(struct mesh_reader *r, int *err)
{
    *err = 0;
    for (;;) {
        char *nl = r->pos < r->len ? memchr(r->buf + r->pos, '\n', r->len - r->pos) : NULL;
        if (!nl) {
            if (r->len - r->pos > MESH_LINE_MAX) {
                *err = 1;
                cm_seterr("cannot read '%s': line %ld: line longer than %d bytes", r->name,
                          r->line + 1, MESH_LINE_MAX);
                return NULL;
            }
            int rc = fill(r);
            if (rc < 0) { *err = 1; return NULL; }
            if (rc > 0) continue;
            if (r->pos >= r->len) return NULL;
            /* last line without newline */
            r->buf[r->len] = 0;
            nl = r->buf + r->len;
        }
        char *s = r->buf + r->pos;
        if ((size_t)(nl - s) > MESH_LINE_MAX) {
            *err = 1;
            cm_seterr("cannot read '%s': line %ld: line longer than %d bytes", r->name,
                      r->line + 1, MESH_LINE_MAX);
            return NULL;
        }
        *nl = 0;
        r->pos = (size_t)(nl - r->buf) + (nl < r->buf + r->len ? 1 : 0);
        if (nl == r->buf + r->len) r->pos = r->len;
        r->line++;
        if (memchr(s, 0, (size_t)(nl - s))) {
            /* a NUL is never text: binary data, or the zero-filled tail
             * of a write that crashed */
            *err = 1;
            cm_seterr("cannot read '%s': line %ld: NUL byte in a text line", r->name, r->line);
            return NULL;
        }
        char *t = s;
        while (*t == ' ' || *t == '\t' || *t == '\r') t++;
        if (*t == 0 || *t == '#')
            continue;
        return t;
    }
}

static int read_bytes(struct mesh_reader *r, void *dst, size_t n)
{
    char *d = dst;
    /* a big block (a raw frame): empty the buffer, then read the rest
     * straight into dst instead of copying it through the buffer */
    if (n >= 65536 && !r->eof) {
        size_t k = r->len - r->pos < n ? r->len - r->pos : n;
        memcpy(d, r->buf + r->pos, k);
        r->pos += k;
        d += k;
        n -= k;
        if (n > 0 && r->map) {
            if (r->map_len - r->map_pos < n) { r->map_pos = r->map_len; r->eof = 1; return 0; }
            memcpy(d, r->map + r->map_pos, n);
            r->map_pos += n;
            return 1;
        }
        if (n > 0) {
            size_t got = fread(d, 1, n, r->f);
            if (got < n) {
                if (ferror(r->f))
                    return cm_seterr("cannot read '%s': %s", r->name, strerror(errno));
                r->eof = 1;
                return 0;
            }
            n = 0;
        }
        return 1;
    }
    while (n > 0) {
        if (r->pos >= r->len) {
            int rc = fill(r);
            if (rc < 0) return -1;
            if (rc == 0) return 0;
        }
        size_t k = r->len - r->pos < n ? r->len - r->pos : n;
        memcpy(d, r->buf + r->pos, k);
        r->pos += k;
        d += k;
        n -= k;
    }
    return 1;
}

static int at_end(const char *p)
{
    while (*p == ' ' || *p == '\t' || *p == '\r') p++;
    return *p == 0 || *p == '#';
}

#define RERR(...) do { char m_[512]; snprintf(m_, sizeof m_, __VA_ARGS__); \
    return cm_seterr("cannot read '%s': line %ld: %s", r->name, r->line, m_); } while (0)

static int header_count(struct mesh_reader *r, const char *key, int allow_q, long min, int *out)
{
    int err;
    char *s = next_line(r, &err);
    if (err) return -1;
    if (!s) RERR("truncated header: expected '%s N'", key);
    size_t kl = strlen(key);
    if (strncmp(s, key, kl) != 0 || (s[kl] != ' ' && s[kl] != '\t'))
        RERR("expected '%s N', got '%.40s'", key, s);
    const char *p = s + kl;
    while (*p == ' ' || *p == '\t') p++;
    if (allow_q && *p == '?' && at_end(p + 1)) { *out = -1; return 0; }
    long v;
    const char *e = parse_long(p, &v);
    if (!e || !at_end(e) || v < 0 || v > MAX_COUNT)
        RERR("bad %s count '%.40s'", key, p);
    if (v < min)
        RERR("stream has no %s ('%s %ld'; at least %ld)", key, key, v, min);
    *out = (int)v;
    return 0;
}

/* double the face storage (up to `most` faces) */
static int grow_faces(struct mesh_reader *r, size_t *cap, size_t most)
{
    size_t n = 2 * *cap > most ? most : 2 * *cap;
    if (n < most && n < 16) n = most < 16 ? most : 16;
    int *nf = realloc(r->F, (n * 3 + 1) * sizeof *nf);
    if (!nf)
        return cm_seterr("cannot read '%s': out of memory for %zu faces", r->name, n);
    r->F = nf;
    *cap = n;
    return 0;
}

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* Refuse, for a regular file, a header whose counts need far more bytes
 * than the file has (a lie that would otherwise allocate gigabytes before
 * the reading finds the truncation).  Plain: at least 8 bytes a face line,
 * 8 a frame header, 6 a vertex line; raw: 12 a face, 24 a vertex. */
static int check_size(struct mesh_reader *r, long long avail)
{
    double frames = r->nframes > 0 ? r->nframes : 1;
    double need = r->raw ? 12.0 * r->nf + frames * (24.0 * r->nv + 9)
                         : 8.0 * r->nf + frames * (6.0 * r->nv + 8);
    if (avail >= 0 && need > (double)avail && need > SIZE_CHECK_MIN)
        RERR("truncated: the header announces %d vertices, %d faces, %d frames (at least %.0f bytes), "
             "but the file has %lld bytes", r->nv, r->nf, r->nframes, need, avail);
    return 0;
}

int mesh_reader_open(struct mesh_reader *r, const char *path)
{
    if (!path || !strcmp(path, "-"))
        return mesh_reader_open_stream(r, stdin, "<stdin>", 0);
    FILE *f = fopen(path, "rb");
    if (!f) {
        memset(r, 0, sizeof *r);
        return cm_seterr("cannot read '%s': %s", path, strerror(errno));
    }
    return mesh_reader_open_stream(r, f, path, 1);
}

int mesh_reader_open_stream(struct mesh_reader *r, FILE *f, const char *name, int own)
{
    memset(r, 0, sizeof *r);
    r->name = name;
    r->f = f;
    r->own = own;
    long long avail = -1;      /* bytes left in a regular file */
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode)) {
        long at = ftell(f);
        avail = (long long)st.st_size - (at > 0 ? at : 0);
    }
    r->cap = 1 << 20;
    r->buf = calloc(r->cap + BUF_PAD, 1);
    if (!r->buf) { mesh_reader_close(r); return cm_seterr("out of memory"); }
    int err;
    char *s = next_line(r, &err);
    if (err) goto fail;
    if (!s) { cm_seterr("cannot read '%s': empty input, expected a MESH stream", r->name); goto fail; }
    if (!strncmp(s, "MESH 1", 6) && at_end(s + 6)) r->raw = 0;
    else if (!strncmp(s, "MESH 1 raw", 10) && at_end(s + 10)) r->raw = 1;
    else if (!strncmp(s, "MESH", 4) && (s[4] == ' ')) {
        cm_seterr("cannot read '%s': line %ld: unsupported MESH version '%.20s'", r->name, r->line, s);
        goto fail;
    } else {
        cm_seterr("cannot read '%s': line %ld: not a MESH stream (bad magic '%.20s'); "
                  "use mesh-import for OBJ/OFF/PLY/STL/glTF", r->name, r->line, s);
        goto fail;
    }
    if (header_count(r, "vertices", 0, 0, &r->nv) < 0 ||
        header_count(r, "faces", 0, 0, &r->nf) < 0 ||
        header_count(r, "frames", 1, 1, &r->nframes) < 0 ||
        check_size(r, avail) < 0)
        goto fail;
    /* the faces' storage grows as they arrive: a header count is a claim,
     * not memory to reserve before the data are seen */
    size_t fcap = r->nf < 65536 ? (size_t)r->nf : 65536;
    r->F = malloc((fcap * 3 + 1) * sizeof *r->F);
    if (!r->F) { cm_seterr("cannot read '%s': out of memory", r->name); goto fail; }
    if (r->raw) {
        unsigned char *tmp = malloc(65536 * 12);
        if (!tmp) { cm_seterr("cannot read '%s': out of memory", r->name); goto fail; }
        for (size_t at = 0; at < (size_t)r->nf; at += 65536) {
            size_t n = (size_t)r->nf - at < 65536 ? (size_t)r->nf - at : 65536;
            if (at + n > fcap && grow_faces(r, &fcap, at + n) < 0) { free(tmp); goto fail; }
            int rc = read_bytes(r, tmp, n * 12);
            if (rc <= 0) {
                free(tmp);
                if (rc == 0) cm_seterr("cannot read '%s': truncated face block", r->name);
                goto fail;
            }
            for (size_t i = 0; i < n * 3; i++) {
                uint32_t v = le32(tmp + 4 * i);
                if (v >= (uint32_t)r->nv) {
                    free(tmp);
                    cm_seterr("cannot read '%s': face %zu: vertex index %u out of range (0..%d)",
                              r->name, (at * 3 + i) / 3, v, r->nv - 1);
                    goto fail;
                }
                r->F[at * 3 + i] = (int)v;
            }
        }
        free(tmp);
    } else {
        for (int i = 0; i < r->nf; i++) {
            if ((size_t)i == fcap && grow_faces(r, &fcap, (size_t)r->nf) < 0)
                goto fail;
            s = next_line(r, &err);
            if (err) goto fail;
            if (!s) { cm_seterr("cannot read '%s': line %ld: truncated: expected %d faces, got %d",
                                r->name, r->line, r->nf, i); goto fail; }
            if (s[0] != 'f' || (s[1] != ' ' && s[1] != '\t')) {
                cm_seterr("cannot read '%s': line %ld: expected face 'f a b c' (%d of %d), got '%.30s'",
                          r->name, r->line, i, r->nf, s);
                goto fail;
            }
            const char *p = s + 1;
            for (int c = 0; c < 3; c++) {
                long v;
                p = parse_long(p, &v);
                if (!p) { cm_seterr("cannot read '%s': line %ld: expected 3 vertex indices",
                                    r->name, r->line); goto fail; }
                if (v < 0 || v >= r->nv) {
                    cm_seterr("cannot read '%s': line %ld: vertex index %ld out of range (0..%d)",
                              r->name, r->line, v, r->nv - 1);
                    goto fail;
                }
                r->F[3 * i + c] = (int)v;
            }
            if (!at_end(p)) {
                cm_seterr("cannot read '%s': line %ld: a face needs exactly 3 indices "
                          "(triangulate with mesh-import)", r->name, r->line);
                goto fail;
            }
        }
    }
    return 0;
fail:
    mesh_reader_close(r);
    return -1;
}

/* The next frame's header line: 1 (and *cut), 0 at the proper end, -1 */
static int frame_header(struct mesh_reader *r, int *cut)
{
    int err;
    char *s = next_line(r, &err);
    if (err) return -1;
    if (!s) {
        if (r->nframes >= 0 && r->frame < r->nframes)
            return cm_seterr("cannot read '%s': line %ld: truncated: expected %d frames, got %d",
                             r->name, r->line, r->nframes, r->frame);
        if (r->nframes < 0 && r->frame == 0)
            return cm_seterr("cannot read '%s': line %ld: stream has no frames", r->name, r->line);
        return 0;
    }
    if (r->nframes >= 0 && r->frame >= r->nframes)
        RERR("more frames than the %d announced in the header", r->nframes);
    long k;
    const char *p = NULL;
    if (!strncmp(s, "frame", 5) && (s[5] == ' ' || s[5] == '\t'))
        p = parse_long(s + 5, &k);
    if (!p)
        RERR("expected 'frame %d', got '%.30s'", r->frame, s);
    if (k != r->frame)
        RERR("expected frame %d, got frame %ld", r->frame, k);
    while (*p == ' ' || *p == '\t') p++;
    int c = 0;
    if (!strncmp(p, "cut", 3) && at_end(p + 3)) c = 1;
    else if (!at_end(p))
        RERR("unexpected '%.20s' after frame number", p);
    if (cut) *cut = c;
    return 1;
}
int mesh_reader_next(struct mesh_reader *r, double *X, int *cut)
{
    int rc0 = frame_header(r, cut), err;
    char *s;
    if (rc0 <= 0) return rc0;
    size_t n3 = (size_t)r->nv * 3;
    if (r->raw) {
        long fl = r->line;
        /* read the block in cache-sized pieces straight into X and check
         * each piece while it is still in cache.  Non-finite <=> all
         * exponent bits set <=> adding one unit of the exponent carries into
         * the sign bit: a branch-free test the compiler vectorizes. */
        const uint64_t expo = 0x7ff0000000000000ULL, one = 0x0010000000000000ULL;
        uint64_t a0 = 0, a1 = 0, a2 = 0, a3 = 0;
        const size_t piece = 32768;             /* doubles: 256 KiB */
        for (size_t at = 0; at < n3; at += piece) {
            size_t m = n3 - at < piece ? n3 - at : piece;
            int rc = read_bytes(r, X + at, m * sizeof(double));
            if (rc < 0) return -1;
            if (rc == 0)
                return cm_seterr("cannot read '%s': frame %d (header line %ld): truncated vertex block",
                                 r->name, r->frame, fl);
#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
            for (size_t i = at; i < at + m; i++) {
                uint64_t u;
                memcpy(&u, X + i, sizeof u);
                u = __builtin_bswap64(u);
                memcpy(X + i, &u, sizeof u);
            }
#endif
            const uint64_t *U = (const uint64_t *)(void *)(X + at);
            size_t i = 0;
            for (; i + 4 <= m; i += 4) {
                a0 |= (U[i] & expo) + one;
                a1 |= (U[i + 1] & expo) + one;
                a2 |= (U[i + 2] & expo) + one;
                a3 |= (U[i + 3] & expo) + one;
            }
            for (; i < m; i++)
                a0 |= (U[i] & expo) + one;
        }
        if ((a0 | a1 | a2 | a3) >> 63)
            for (size_t i = 0; i < n3; i++)
                if (!isfinite(X[i]))
                    return cm_seterr("cannot read '%s': frame %d: vertex %zu: non-finite coordinate",
                                     r->name, r->frame, i / 3);
        /* the block is followed by a newline so the next header is a line */
        char nl;
        int rc = read_bytes(r, &nl, 1);
        if (rc < 0) return -1;
        if (rc == 0 || nl != '\n')
            return cm_seterr("cannot read '%s': frame %d: missing newline after vertex block",
                             r->name, r->frame);
    } else {
        for (int i = 0; i < r->nv; i++) {
            /* fast path for the common line "x y z\n": parse in place; any
             * other shape (comment, blank line, CR, junk, a line not yet
             * in the buffer) falls back to the general path below, which
             * parses the line again with every check */
            if (r->pos < r->len) {
                const char *q = r->buf + r->pos;
                double *x = X + 3 * (size_t)i;
                if ((q = parse_double_padded(q, &x[0])) && *q == ' ' &&
                    (q = parse_double_padded(q + 1, &x[1])) && *q == ' ' &&
                    (q = parse_double_padded(q + 1, &x[2])) && *q == '\n' &&
                    isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2])) {
                    r->pos = (size_t)(q + 1 - r->buf);
                    r->line++;
                    continue;
                }
            }
            s = next_line(r, &err);
            if (err) return -1;
            if (!s)
                return cm_seterr("cannot read '%s': line %ld: truncated: frame %d has %d of %d vertices",
                                 r->name, r->line, r->frame, i, r->nv);
            const char *q = s;
            double *x = X + 3 * (size_t)i;
            for (int d = 0; d < 3; d++) {
                q = parse_double_padded(q, &x[d]);
                if (!q)
                    RERR("expected 3 numbers (frame %d, vertex %d)", r->frame, i);
            }
            if (!at_end(q))
                RERR("expected 3 numbers (frame %d, vertex %d), got more", r->frame, i);
            if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
                RERR("non-finite coordinate (frame %d, vertex %d)", r->frame, i);
        }
    }
    r->frame++;
    return 1;
}

int mesh_reader_map(struct mesh_reader *r)
{
#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
    (void)r;
    return 0;
#else
    struct stat st;
    if (!r->raw || r->map || !r->f || fstat(fileno(r->f), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size <= 0)
        return 0;
    off_t at = ftello(r->f);
    if (at < 0 || at > st.st_size || (uintmax_t)st.st_size > SIZE_MAX) return 0;
    void *p = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fileno(r->f), 0);
    if (p == MAP_FAILED) return 0;
    /* the buffer holds what was read up to `at`; it fills from there on */
    r->map = p;
    r->map_len = (size_t)st.st_size;
    r->map_pos = (size_t)at;
    r->map_owned = 1;
    return 1;
#endif
}

const void *mesh_reader_take_map(struct mesh_reader *r, size_t *len)
{
    if (len) *len = r->map_len;
    r->map_owned = 0;
    return r->map;
}

int mesh_reader_next_ref(struct mesh_reader *r, const mapped_double **X, int *cut)
{
    if (!r->map || !r->raw) return cm_seterr("cannot read '%s': not a mapped raw stream", r->name);
    int rc = frame_header(r, cut);
    if (rc <= 0) return rc;
    size_t n3 = (size_t)r->nv * 3, nb = n3 * sizeof(double);
    /* the block starts at the buffer's unread bytes, which the mapping
     * holds too: it ends map_pos - (len - pos) + nb */
    size_t at = r->map_pos - (r->len - r->pos);
    if (r->map_len - at < nb)
        return cm_seterr("cannot read '%s': frame %d (header line %ld): truncated vertex block",
                         r->name, r->frame, r->line);
    /* the block's page tables in one call, not a fault per 64 KB (Linux
     * 5.14; an older kernel refuses and the pages fault as they are read) */
    uintptr_t p0 = (uintptr_t)(r->map + at) & ~(uintptr_t)4095, p1 = (uintptr_t)(r->map + at + nb);
    madvise((void *)p0, p1 - p0, MADV_POPULATE_READ);
    const mapped_double *x = (const mapped_double *)(const void *)(r->map + at);
    typedef uint64_t u64u __attribute__((aligned(1)));
    const u64u *U = (const u64u *)(const void *)(r->map + at);
    /* non-finite test of mesh_reader_next */
    const uint64_t expo = 0x7ff0000000000000ULL, one = 0x0010000000000000ULL;
    uint64_t a0 = 0, a1 = 0, a2 = 0, a3 = 0;
    size_t i = 0;
    for (; i + 4 <= n3; i += 4) {
        a0 |= (U[i] & expo) + one;
        a1 |= (U[i + 1] & expo) + one;
        a2 |= (U[i + 2] & expo) + one;
        a3 |= (U[i + 3] & expo) + one;
    }
    for (; i < n3; i++)
        a0 |= (U[i] & expo) + one;
    if ((a0 | a1 | a2 | a3) >> 63)
        for (size_t j = 0; j < n3; j++)
            if (!isfinite(x[j]))
                return cm_seterr("cannot read '%s': frame %d: vertex %zu: non-finite coordinate",
                                 r->name, r->frame, j / 3);
    if (r->map_len - at == nb || r->map[at + nb] != '\n')
        return cm_seterr("cannot read '%s': frame %d: missing newline after vertex block",
                         r->name, r->frame);
    /* consumed through the newline: the buffer refills from there */
    r->pos = r->len = 0;
    r->buf[0] = 0;
    r->map_pos = at + nb + 1;
    r->eof = 0;
    *X = x;
    r->frame++;
    return 1;
}

void mesh_reader_close(struct mesh_reader *r)
{
    if (r->map && r->map_owned)
        munmap((void *)r->map, r->map_len);
    r->map = NULL;
    if (r->own && r->f)
        fclose(r->f);
    free(r->buf);
    free(r->F);
    r->f = NULL;
    r->buf = NULL;
    r->F = NULL;
}

int mesh_read(const char *path, struct mesh *m)
{
    struct mesh_reader r;
    memset(m, 0, sizeof *m);
    if (mesh_reader_open(&r, path) < 0)
        return -1;
    size_t fs = (size_t)r.nv * 3;
    /* reserve the announced frames, but at most 64 MiB before they are
     * seen (the storage doubles as frames arrive) */
    size_t most = ((size_t)64 << 20) / ((fs + 1) * sizeof(double)) + 1;
    size_t cap = r.nframes > 0 ? (size_t)r.nframes : 16;
    if (cap > most) cap = most;
    m->nv = r.nv;
    m->nf = r.nf;
    m->F = r.F;
    r.F = NULL;
    m->V = malloc((cap * fs + 1) * sizeof *m->V);
    m->cut = malloc(cap + 1);
    if (!m->V || !m->cut) goto oom;
    for (;;) {
        if ((size_t)m->nframes == cap) {
            cap *= 2;
            if (r.nframes > 0 && cap > (size_t)r.nframes) cap = (size_t)r.nframes + 1;
            double *nv = realloc(m->V, (cap * fs + 1) * sizeof *m->V);
            unsigned char *nc = realloc(m->cut, cap + 1);
            if (nv) m->V = nv;
            if (nc) m->cut = nc;
            if (!nv || !nc) goto oom;
        }
        int c;
        int rc = mesh_reader_next(&r, m->V + m->nframes * fs, &c);
        if (rc < 0) goto fail;
        if (rc == 0) break;
        m->cut[m->nframes++] = (unsigned char)c;
    }
    if (m->nframes == 0) {
        cm_seterr("cannot read '%s': stream has no frames", r.name);
        goto fail;
    }
    mesh_reader_close(&r);
    return 0;
oom:
    cm_seterr("cannot read '%s': out of memory", r.name);
fail:
    mesh_reader_close(&r);
    mesh_free(m);
    return -1;
}

/* ---------------- writing ---------------- */

static int werr(void)
{
    return cm_seterr("write error: %s", strerror(errno));
}

int mesh_writer_open(struct mesh_writer *w, FILE *f, int nv, int nf,
                     const int *F, int nframes, int raw)
{
    memset(w, 0, sizeof *w);
    w->f = f;
    w->raw = raw;
    w->nv = nv;
    w->nf = nf;
    w->nframes = nframes;
    if (fprintf(f, "MESH 1%s\nvertices %d\nfaces %d\n", raw ? " raw" : "", nv, nf) < 0)
        return werr();
    if (nframes < 0) fputs("frames ?\n", f);
    else fprintf(f, "frames %d\n", nframes);
    if (raw) {
        /* little-endian int32, in blocks (one fwrite per index was most of
         * the cost of writing a raw stream's header) */
        unsigned char b[4096];
        size_t k = 0;
        for (size_t i = 0; i < (size_t)nf * 3; i++) {
            uint32_t v = (uint32_t)F[i];
            b[k] = v & 255; b[k + 1] = (v >> 8) & 255; b[k + 2] = (v >> 16) & 255; b[k + 3] = v >> 24;
            if ((k += 4) == sizeof b) { fwrite(b, 1, k, f); k = 0; }
        }
        if (k) fwrite(b, 1, k, f);
    } else {
        char line[64];
        for (int i = 0; i < nf; i++) {
            int n = snprintf(line, sizeof line, "f %d %d %d\n", F[3 * i], F[3 * i + 1], F[3 * i + 2]);
            fwrite(line, 1, (size_t)n, f);
        }
    }
    return ferror(f) ? werr() : 0;
}

int mesh_writer_frame(struct mesh_writer *w, const double *X, int cut)
{
    if (w->nframes >= 0 && w->written >= w->nframes)
        return cm_seterr("internal: more frames written than announced (%d)", w->nframes);
    fprintf(w->f, "frame %d%s\n", w->written, cut && w->written > 0 ? " cut" : "");
    size_t n3 = (size_t)w->nv * 3;
    if (w->raw) {
#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "raw MESH output assumes a little-endian host"
#endif
        fwrite(X, sizeof(double), n3, w->f);
        fputc('\n', w->f);
    } else {
        char line[128];
        for (int i = 0; i < w->nv; i++) {
            int n = 0;
            for (int d = 0; d < 3; d++) {
                n += format_double(line + n, X[3 * i + d]);
                line[n++] = d < 2 ? ' ' : '\n';
            }
            fwrite(line, 1, (size_t)n, w->f);
        }
    }
    w->written++;
    return ferror(w->f) ? werr() : 0;
}

int mesh_writer_close(struct mesh_writer *w)
{
    if (w->nframes >= 0 && w->written != w->nframes)
        return cm_seterr("internal: %d frames announced, %d written", w->nframes, w->written);
    if (fflush(w->f) != 0 || ferror(w->f))
        return werr();
    return 0;
}

/* ---- whole-mesh text output, formatted on several threads ----
 * The frames are cut into jobs of up to TEXT_JOB vertex lines (the first
 * job of a frame carries its header); up to TEXT_SLOTS jobs ahead of the
 * writer are formatted by helper threads into a ring of buffers, and the
 * calling thread writes them in order (formatting jobs itself while the
 * next one is not ready).  Each number is formatted by format_double as
 * mesh_writer_frame does: the same bytes for any number of threads. */
#define TEXT_JOB 4096
#define TEXT_SLOTS 8
#define TEXT_THREADS 4

struct text_pool {
    const struct mesh *m;
    int per_frame;              /* jobs per frame */
    long total, claimed, written;
    char *buf[TEXT_SLOTS];
    size_t len[TEXT_SLOTS];
    long ready[TEXT_SLOTS];     /* job formatted in the slot, -1 none */
    int stop;
    pthread_mutex_t lock;
    pthread_cond_t cond;
};

static void text_job(struct text_pool *p, long j)
{
    const struct mesh *m = p->m;
    int k = (int)(j / p->per_frame), part = (int)(j % p->per_frame);
    int i0 = part * TEXT_JOB, i1 = i0 + TEXT_JOB < m->nv ? i0 + TEXT_JOB : m->nv;
    char *o = p->buf[j % TEXT_SLOTS];
    if (part == 0)
        o += sprintf(o, "frame %d%s\n", k, m->cut && m->cut[k] && k > 0 ? " cut" : "");
    const double *X = mesh_frame(m, k);
    for (int i = i0; i < i1; i++)
        for (int d = 0; d < 3; d++) {
            o += format_double(o, X[3 * (size_t)i + d]);
            *o++ = d < 2 ? ' ' : '\n';
        }
    p->len[j % TEXT_SLOTS] = (size_t)(o - p->buf[j % TEXT_SLOTS]);
}

/* claim the next job that fits the ring (lock held); -1 if none */
static long text_claim(struct text_pool *p)
{
    if (p->stop || p->claimed >= p->total || p->claimed >= p->written + TEXT_SLOTS) return -1;
    return p->claimed++;
}

static void *text_worker(void *arg)
{
    struct text_pool *p = arg;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        long j;
        while ((j = text_claim(p)) < 0 && !p->stop && p->claimed < p->total)
            pthread_cond_wait(&p->cond, &p->lock);
        if (j < 0) break;
        pthread_mutex_unlock(&p->lock);
        text_job(p, j);
        pthread_mutex_lock(&p->lock);
        p->ready[j % TEXT_SLOTS] = j;
        pthread_cond_broadcast(&p->cond);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

static int write_text_frames(FILE *f, const struct mesh *m)
{
    struct text_pool p;
    memset(&p, 0, sizeof p);
    p.m = m;
    p.per_frame = m->nv > 0 ? (m->nv + TEXT_JOB - 1) / TEXT_JOB : 1;
    p.total = (long)p.per_frame * m->nframes;
    /* a number is at most 24 characters (format_double), a header 32 */
    size_t cap = (size_t)TEXT_JOB * 3 * 25 + 64;
    int nslots = p.total < TEXT_SLOTS ? (int)p.total : TEXT_SLOTS, rc = 0;
    for (int i = 0; i < TEXT_SLOTS; i++) p.ready[i] = -1;
    for (int i = 0; i < nslots; i++)
        if (!(p.buf[i] = malloc(cap))) {
            for (int t = 0; t < i; t++) free(p.buf[t]);
            return cm_seterr("out of memory for the output buffers");
        }
    pthread_mutex_init(&p.lock, NULL);
    pthread_cond_init(&p.cond, NULL);
    long c = sysconf(_SC_NPROCESSORS_ONLN);
    int nth = c > 1 ? (int)c - 1 : 0;
    if (nth > TEXT_THREADS - 1) nth = TEXT_THREADS - 1;
    if (p.total < 2) nth = 0;
    pthread_t th[TEXT_THREADS];
    int started = 0;
    for (int t = 0; t < nth; t++)
        if (pthread_create(&th[started], NULL, text_worker, &p) == 0) started++;
    pthread_mutex_lock(&p.lock);
    for (long j = 0; j < p.total; j++) {
        while (p.ready[j % TEXT_SLOTS] != j) {
            long mine = text_claim(&p);
            if (mine >= 0) {
                pthread_mutex_unlock(&p.lock);
                text_job(&p, mine);
                pthread_mutex_lock(&p.lock);
                p.ready[mine % TEXT_SLOTS] = mine;
            } else
                pthread_cond_wait(&p.cond, &p.lock);
        }
        pthread_mutex_unlock(&p.lock);
        if (fwrite(p.buf[j % TEXT_SLOTS], 1, p.len[j % TEXT_SLOTS], f) != p.len[j % TEXT_SLOTS] || ferror(f))
            rc = werr();
        pthread_mutex_lock(&p.lock);
        p.ready[j % TEXT_SLOTS] = -1;
        p.written = j + 1;
        if (rc < 0) p.stop = 1;
        pthread_cond_broadcast(&p.cond);
        if (rc < 0) break;
    }
    p.stop = 1;
    pthread_cond_broadcast(&p.cond);
    pthread_mutex_unlock(&p.lock);
    for (int t = 0; t < started; t++) pthread_join(th[t], NULL);
    pthread_mutex_destroy(&p.lock);
    pthread_cond_destroy(&p.cond);
    for (int i = 0; i < nslots; i++) free(p.buf[i]);
    return rc;
}

int mesh_write(FILE *f, const struct mesh *m, int raw)
{
    struct mesh_writer w;
    if (mesh_writer_open(&w, f, m->nv, m->nf, m->F, m->nframes, raw) < 0)
        return -1;
    if (!raw && (size_t)m->nv * m->nframes >= 2 * TEXT_JOB) {
        /* big text output: formatted on the helper threads */
        if (write_text_frames(f, m) < 0) return -1;
        w.written = m->nframes;
    } else
        for (int k = 0; k < m->nframes; k++)
            if (mesh_writer_frame(&w, mesh_frame(m, k), m->cut ? m->cut[k] : 0) < 0)
                return -1;
    return mesh_writer_close(&w);
}
