/* gltf_write.c -- glTF 2.0 writer for morph-target animations; see gltf_write.h. */
#include "gltf_write.h"
#include "base64.h"
#include "cm_error.h"
#include "geometry.h"
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { CT_UINT = 5125, CT_FLOAT = 5126 };
enum { TARGET_NONE = 0, TARGET_ARRAY = 34962, TARGET_ELEMENTS = 34963 };

/* One entry: an accessor over its own buffer view (ACC), a buffer view
 * alone (VIEW: the indices or values of a sparse accessor), or a sparse
 * accessor of zeros without a view (SPARSE).  JSON indices of accessors
 * and views are numbered when the JSON is written. */
enum { ACC = 0, VIEW = 1, SPARSE = 2 };
struct accessor {
    int kind;
    size_t offset, length;      /* bytes in the buffer (ACC, VIEW) */
    int ctype, count, ncomp;    /* component type, elements, 1 or 3 */
    int target;                 /* bufferView.target or 0 */
    int minmax;                 /* write min/max */
    float lo[3], hi[3];
    int nsparse, sidx, sval;    /* SPARSE: non-zeros, entries of their index and value views */
};

struct gmesh {
    char *name;
    int nv, nf;
    int indices, position, normal;   /* accessor indices */
    float *B;                        /* #V by 3 base positions (float32) */
    float *NB;                       /* #V by 3 base normals */
    int *F;                          /* #F by 3 (for the targets' normals) */
    int ntargets, cap;
    int *tpos, *tnrm;                /* per target: accessor indices */
    char **tname;
};

struct channel {
    int mesh, input, output;         /* accessor indices */
};

struct ganim {
    char *name;
    int nch, cap;
    struct channel *ch;
};

struct gltf_writer {
    char *generator;
    FILE *bin;                       /* temporary buffer file */
    size_t binlen;
    struct accessor *acc;
    int nacc, capacc;
    struct gmesh *mesh;
    int nmesh, capmesh;
    struct ganim *anim;
    int nanim, capanim;
    float *fbuf;                     /* scratch: #V by 3 floats */
    double *dbuf;                    /* scratch: #V by 3 doubles */
    size_t scratch;
    int failed;
};

static int grow(void **p, int *cap, int n, size_t size)
{
    if (n < *cap) return 0;
    int c = *cap ? 2 * *cap : 8;
    void *q = realloc(*p, (size_t)c * size);
    if (!q) return cm_seterr("glTF writer: out of memory");
    *p = q;
    *cap = c;
    return 0;
}

static char *dupstr(const char *s)
{
    if (!s) return NULL;
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

int gltf_container_parse(const char *s)
{
    if (!s) return GLTF_NONE;
    if (!strcasecmp(s, "gltf")) return GLTF_JSON;
    if (!strcasecmp(s, "glb")) return GLTF_BINARY;
    return GLTF_NONE;
}

int gltf_container_from_name(const char *path)
{
    if (!path) return GLTF_NONE;
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    return dot ? gltf_container_parse(dot + 1) : GLTF_NONE;
}

struct gltf_writer *gltf_writer_new(const char *generator)
{
    struct gltf_writer *g = calloc(1, sizeof *g);
    if (!g) { cm_seterr("glTF writer: out of memory"); return NULL; }
    g->generator = dupstr(generator ? generator : "stopmo");
    g->bin = tmpfile();
    if (!g->bin) {
        cm_seterr("glTF writer: cannot create a temporary file: %s", strerror(errno));
        free(g->generator);
        free(g);
        return NULL;
    }
    return g;
}

void gltf_writer_free(struct gltf_writer *g)
{
    if (!g) return;
    if (g->bin) fclose(g->bin);
    for (int i = 0; i < g->nmesh; i++) {
        struct gmesh *m = &g->mesh[i];
        free(m->name); free(m->B); free(m->NB); free(m->F); free(m->tpos); free(m->tnrm);
        for (int t = 0; t < m->ntargets; t++) free(m->tname[t]);
        free(m->tname);
    }
    for (int a = 0; a < g->nanim; a++) { free(g->anim[a].name); free(g->anim[a].ch); }
    free(g->mesh); free(g->anim); free(g->acc); free(g->fbuf); free(g->dbuf); free(g->generator);
    free(g);
}

static int scratch(struct gltf_writer *g, size_t n)
{
    if (n <= g->scratch) return 0;
    float *f = realloc(g->fbuf, n * sizeof *f);
    if (f) g->fbuf = f;
    double *d = realloc(g->dbuf, n * sizeof *d);
    if (d) g->dbuf = d;
    if (!f || !d) return cm_seterr("glTF writer: out of memory");
    g->scratch = n;
    return 0;
}

/* Append count elements of ncomp 4-byte components (little-endian) as a
 * new accessor; returns its index. */
static int put_accessor(struct gltf_writer *g, const void *data, int ctype, int count, int ncomp,
                        int target, int minmax)
{
    if (grow((void **)&g->acc, &g->capacc, g->nacc, sizeof *g->acc) < 0) return -1;
    struct accessor *a = &g->acc[g->nacc];
    memset(a, 0, sizeof *a);
    a->offset = g->binlen;
    a->length = (size_t)count * ncomp * 4;
    a->ctype = ctype;
    a->count = count;
    a->ncomp = ncomp;
    a->target = target;
    a->minmax = minmax;
    if (minmax && ctype == CT_FLOAT) {
        const float *f = data;
        for (int c = 0; c < ncomp; c++) { a->lo[c] = FLT_MAX; a->hi[c] = -FLT_MAX; }
        for (int i = 0; i < count; i++)
            for (int c = 0; c < ncomp; c++) {
                float x = f[(size_t)i * ncomp + c];
                if (x < a->lo[c]) a->lo[c] = x;
                if (x > a->hi[c]) a->hi[c] = x;
            }
    }
    /* the buffer is little-endian; so are the machines we build for */
    const unsigned char *b = data;
    size_t n = a->length;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    unsigned char w[4];
    for (size_t i = 0; i < n; i += 4) {
        w[0] = b[i + 3]; w[1] = b[i + 2]; w[2] = b[i + 1]; w[3] = b[i];
        if (fwrite(w, 1, 4, g->bin) != 4) return cm_seterr("glTF writer: temporary file: %s", strerror(errno));
    }
#else
    if (n && fwrite(b, 1, n, g->bin) != n)
        return cm_seterr("glTF writer: temporary file: %s", strerror(errno));
#endif
    g->binlen += n;
    return g->nacc++;
}

/* float32 positions and unit normals of X */
static int frame_floats(struct gltf_writer *g, int nv, int nf, const int *F, const double *X,
                        float *P, float *N)
{
    for (size_t i = 0; i < (size_t)nv * 3; i++) {
        if (!isfinite(X[i])) return cm_seterr("glTF writer: non-finite position at vertex %zu", i / 3);
        if (fabs(X[i]) > FLT_MAX) return cm_seterr("glTF writer: position at vertex %zu beyond float range", i / 3);
        P[i] = (float)X[i];
    }
    if (N) {
        if (scratch(g, (size_t)nv * 3) < 0) return -1;
        vertex_normals(X, F, nv, nf, g->dbuf);
        for (int v = 0; v < nv; v++) {
            double *n = g->dbuf + 3 * v;
            if (n[0] == 0 && n[1] == 0 && n[2] == 0) n[2] = 1;
            for (int c = 0; c < 3; c++) N[3 * v + c] = (float)n[c];
        }
    }
    return 0;
}

int gltf_add_mesh(struct gltf_writer *g, const char *name, int nv, int nf, const int *F,
                  const double *X)
{
    if (nv < 1 || nf < 1) return cm_seterr("glTF writer: a mesh needs vertices and triangles");
    for (size_t i = 0; i < (size_t)nf * 3; i++)
        if (F[i] < 0 || F[i] >= nv) return cm_seterr("glTF writer: vertex index %d out of range", F[i]);
    if (grow((void **)&g->mesh, &g->capmesh, g->nmesh, sizeof *g->mesh) < 0) return -1;
    struct gmesh *m = &g->mesh[g->nmesh];
    memset(m, 0, sizeof *m);
    m->name = dupstr(name ? name : "mesh");
    m->nv = nv;
    m->nf = nf;
    m->B = malloc((size_t)nv * 3 * sizeof *m->B);
    m->NB = malloc((size_t)nv * 3 * sizeof *m->NB);
    m->F = malloc((size_t)nf * 3 * sizeof *m->F);
    if (!m->name || !m->B || !m->NB || !m->F) {
        free(m->name); free(m->B); free(m->NB); free(m->F);
        return cm_seterr("glTF writer: out of memory");
    }
    memcpy(m->F, F, (size_t)nf * 3 * sizeof *F);
    if (frame_floats(g, nv, nf, F, X, m->B, m->NB) < 0) {
        free(m->name); free(m->B); free(m->NB); free(m->F);
        return -1;
    }
    uint32_t *I = malloc((size_t)nf * 3 * sizeof *I);
    if (!I) return cm_seterr("glTF writer: out of memory");
    for (size_t i = 0; i < (size_t)nf * 3; i++) I[i] = (uint32_t)F[i];
    m->indices = put_accessor(g, I, CT_UINT, nf * 3, 1, TARGET_ELEMENTS, 0);
    free(I);
    m->position = m->indices < 0 ? -1 : put_accessor(g, m->B, CT_FLOAT, nv, 3, TARGET_ARRAY, 1);
    m->normal = m->position < 0 ? -1 : put_accessor(g, m->NB, CT_FLOAT, nv, 3, TARGET_ARRAY, 0);
    if (m->normal < 0) { free(m->name); free(m->B); free(m->NB); free(m->F); return -1; }
    return g->nmesh++;
}

int gltf_add_target(struct gltf_writer *g, int mi, const char *name, const double *X)
{
    if (mi < 0 || mi >= g->nmesh) return cm_seterr("glTF writer: no mesh %d", mi);
    struct gmesh *m = &g->mesh[mi];
    int cap = m->cap;
    if (grow((void **)&m->tpos, &cap, m->ntargets, sizeof *m->tpos) < 0) return -1;
    cap = m->cap;
    if (grow((void **)&m->tnrm, &cap, m->ntargets, sizeof *m->tnrm) < 0) return -1;
    cap = m->cap;
    if (grow((void **)&m->tname, &cap, m->ntargets, sizeof *m->tname) < 0) return -1;
    m->cap = cap;
    size_t n3 = (size_t)m->nv * 3;
    float *P = malloc(2 * n3 * sizeof *P);
    if (!P) return cm_seterr("glTF writer: out of memory");
    float *N = P + n3;
    int rc = frame_floats(g, m->nv, m->nf, m->F, X, P, N);
    if (rc == 0) {
        for (size_t i = 0; i < n3; i++) {
            P[i] -= m->B[i];
            N[i] -= m->NB[i];
        }
        m->tpos[m->ntargets] = put_accessor(g, P, CT_FLOAT, m->nv, 3, TARGET_ARRAY, 1);
        m->tnrm[m->ntargets] = m->tpos[m->ntargets] < 0 ? -1 : put_accessor(g, N, CT_FLOAT, m->nv, 3, TARGET_ARRAY, 0);
        rc = m->tnrm[m->ntargets] < 0 ? -1 : 0;
    }
    free(P);
    if (rc < 0) return -1;
    m->tname[m->ntargets] = dupstr(name);
    return m->ntargets++;
}

int gltf_add_animation(struct gltf_writer *g, const char *name)
{
    if (grow((void **)&g->anim, &g->capanim, g->nanim, sizeof *g->anim) < 0) return -1;
    struct ganim *a = &g->anim[g->nanim];
    memset(a, 0, sizeof *a);
    a->name = dupstr(name ? name : "animation");
    return g->nanim++;
}

int gltf_add_onehot_channel(struct gltf_writer *g, int ai, int mi, int nkeys, const double *t,
                            const int *hot)
{
    if (ai < 0 || ai >= g->nanim) return cm_seterr("glTF writer: no animation %d", ai);
    if (mi < 0 || mi >= g->nmesh) return cm_seterr("glTF writer: no mesh %d", mi);
    struct gmesh *m = &g->mesh[mi];
    int nt = m->ntargets;
    if (nkeys < 1) return cm_seterr("glTF writer: a channel needs keys");
    if (nt < 1) return cm_seterr("glTF writer: mesh %d has no morph targets to animate", mi);
    if ((double)nkeys * nt > 2147483647.0) return cm_seterr("glTF writer: %d keys of %d weights are too many", nkeys, nt);
    float *T = malloc((size_t)nkeys * sizeof *T);
    float *W = malloc((size_t)nkeys * sizeof *W);             /* the non-zeros: 1 */
    uint32_t *I = malloc((size_t)nkeys * sizeof *I);          /* and where they are */
    if (!T || !W || !I) { free(T); free(W); free(I); return cm_seterr("glTF writer: out of memory"); }
    int rc = 0;
    for (int k = 0; k < nkeys && rc == 0; k++) {
        T[k] = (float)t[k];
        if (!isfinite(t[k]) || (k > 0 && !(T[k] > T[k - 1])))
            rc = cm_seterr("glTF writer: key times not strictly increasing in float32 at key %d", k);
        else if (hot[k] < 0 || hot[k] >= nt)
            rc = cm_seterr("glTF writer: key %d: target %d out of range (mesh %d has %d)", k, hot[k], mi, nt);
        else {
            W[k] = 1;
            I[k] = (uint32_t)k * (uint32_t)nt + (uint32_t)hot[k];
        }
    }
    struct ganim *a = &g->anim[ai];
    if (rc == 0) rc = grow((void **)&a->ch, &a->cap, a->nch, sizeof *a->ch);
    if (rc == 0) {
        struct channel *c = &a->ch[a->nch];
        c->mesh = mi;
        c->input = put_accessor(g, T, CT_FLOAT, nkeys, 1, TARGET_NONE, 1);
        /* the weights: nkeys * nt values, all 0 but one per key, as a
         * sparse accessor (size O(nkeys), not O(nkeys * nt)) */
        int iv = c->input < 0 ? -1 : put_accessor(g, I, CT_UINT, nkeys, 1, TARGET_NONE, 0);
        int vv = iv < 0 ? -1 : put_accessor(g, W, CT_FLOAT, nkeys, 1, TARGET_NONE, 0);
        c->output = vv < 0 || grow((void **)&g->acc, &g->capacc, g->nacc, sizeof *g->acc) < 0 ? -1 : g->nacc++;
        if (c->output >= 0) {
            g->acc[iv].kind = g->acc[vv].kind = VIEW;
            struct accessor *o = &g->acc[c->output];
            memset(o, 0, sizeof *o);
            o->kind = SPARSE;
            o->ctype = CT_FLOAT;
            o->count = nkeys * nt;
            o->ncomp = 1;
            o->nsparse = nkeys;
            o->sidx = iv;
            o->sval = vv;
        }
        rc = c->output < 0 ? -1 : 0;
        if (rc == 0) a->nch++;
    }
    free(T);
    free(W);
    free(I);
    return rc;
}

/* ---- JSON text ---- */

struct sbuf {
    char *s;
    size_t len, cap;
    int oom;
};

static void sb_printf(struct sbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void sb_printf(struct sbuf *b, const char *fmt, ...)
{
    if (b->oom) return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(b->s ? b->s + b->len : NULL, b->s ? b->cap - b->len : 0, fmt, ap);
        va_end(ap);
        if (n < 0) { b->oom = 1; return; }
        if (b->s && b->len + (size_t)n < b->cap) { b->len += (size_t)n; return; }
        size_t c = b->cap ? 2 * b->cap : 4096;
        while (c < b->len + (size_t)n + 1) c *= 2;
        char *q = realloc(b->s, c);
        if (!q) { b->oom = 1; return; }
        b->s = q;
        b->cap = c;
    }
}

static void sb_string(struct sbuf *b, const char *s)
{
    sb_printf(b, "\"");
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') sb_printf(b, "\\%c", *p);
        else if (*p < 0x20) sb_printf(b, "\\u%04x", *p);
        else sb_printf(b, "%c", *p);
    }
    sb_printf(b, "\"");
}

/* a float32 value, printed so that it parses back to the same float32
 * (and to the same double as the float widened) */
static void sb_float(struct sbuf *b, float x)
{
    if (x == 0) { sb_printf(b, "0"); return; }
    sb_printf(b, "%.9g", (double)x);
}

static void json(const struct gltf_writer *g, struct sbuf *b, const char *uri, size_t buflen)
{
    /* JSON numbers of the entries: A[e] among accessors, V[e] among views */
    int *A = malloc(((size_t)g->nacc + 1) * sizeof *A), *V = malloc(((size_t)g->nacc + 1) * sizeof *V);
    if (!A || !V) { free(A); free(V); b->oom = 1; return; }
    for (int e = 0, na = 0, nw = 0; e < g->nacc; e++) {
        A[e] = g->acc[e].kind != VIEW ? na++ : -1;
        V[e] = g->acc[e].kind != SPARSE ? nw++ : -1;
    }
    sb_printf(b, "{\"asset\":{\"version\":\"2.0\",\"generator\":");
    sb_string(b, g->generator);
    sb_printf(b, "},\"scene\":0,\"scenes\":[{\"nodes\":[");
    for (int i = 0; i < g->nmesh; i++) sb_printf(b, "%s%d", i ? "," : "", i);
    sb_printf(b, "]}],\"nodes\":[");
    for (int i = 0; i < g->nmesh; i++) {
        sb_printf(b, "%s{\"name\":", i ? "," : "");
        sb_string(b, g->mesh[i].name);
        sb_printf(b, ",\"mesh\":%d}", i);
    }
    sb_printf(b, "],\"meshes\":[");
    for (int i = 0; i < g->nmesh; i++) {
        const struct gmesh *m = &g->mesh[i];
        sb_printf(b, "%s{\"name\":", i ? "," : "");
        sb_string(b, m->name);
        sb_printf(b, ",\"primitives\":[{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d},\"indices\":%d,\"mode\":4",
                  A[m->position], A[m->normal], A[m->indices]);
        if (m->ntargets) {
            sb_printf(b, ",\"targets\":[");
            for (int t = 0; t < m->ntargets; t++)
                sb_printf(b, "%s{\"POSITION\":%d,\"NORMAL\":%d}", t ? "," : "", A[m->tpos[t]], A[m->tnrm[t]]);
            sb_printf(b, "]");
        }
        sb_printf(b, "}]");
        if (m->ntargets) {
            sb_printf(b, ",\"weights\":[");
            for (int t = 0; t < m->ntargets; t++) sb_printf(b, "%s0", t ? "," : "");
            sb_printf(b, "],\"extras\":{\"targetNames\":[");
            for (int t = 0; t < m->ntargets; t++) {
                char def[32];
                snprintf(def, sizeof def, "target_%d", t);
                if (t) sb_printf(b, ",");
                sb_string(b, m->tname[t] ? m->tname[t] : def);
            }
            sb_printf(b, "]}");
        }
        sb_printf(b, "}");
    }
    sb_printf(b, "]");
    if (g->nanim) {
        sb_printf(b, ",\"animations\":[");
        for (int a = 0; a < g->nanim; a++) {
            const struct ganim *an = &g->anim[a];
            sb_printf(b, "%s{\"name\":", a ? "," : "");
            sb_string(b, an->name);
            sb_printf(b, ",\"channels\":[");
            for (int c = 0; c < an->nch; c++)
                sb_printf(b, "%s{\"sampler\":%d,\"target\":{\"node\":%d,\"path\":\"weights\"}}", c ? "," : "", c,
                          an->ch[c].mesh);
            sb_printf(b, "],\"samplers\":[");
            for (int c = 0; c < an->nch; c++)
                sb_printf(b, "%s{\"input\":%d,\"output\":%d,\"interpolation\":\"STEP\"}", c ? "," : "",
                          A[an->ch[c].input], A[an->ch[c].output]);
            sb_printf(b, "]}");
        }
        sb_printf(b, "]");
    }
    sb_printf(b, ",\"accessors\":[");
    for (int i = 0; i < g->nacc; i++) {
        const struct accessor *a = &g->acc[i];
        if (a->kind == VIEW) continue;
        sb_printf(b, "%s{", A[i] ? "," : "");
        if (a->kind == ACC) sb_printf(b, "\"bufferView\":%d,", V[i]);
        sb_printf(b, "\"componentType\":%d,\"count\":%d,\"type\":\"%s\"", a->ctype, a->count,
                  a->ncomp == 3 ? "VEC3" : "SCALAR");
        if (a->minmax) {
            sb_printf(b, ",\"min\":[");
            for (int c = 0; c < a->ncomp; c++) { if (c) sb_printf(b, ","); sb_float(b, a->lo[c]); }
            sb_printf(b, "],\"max\":[");
            for (int c = 0; c < a->ncomp; c++) { if (c) sb_printf(b, ","); sb_float(b, a->hi[c]); }
            sb_printf(b, "]");
        }
        if (a->kind == SPARSE)
            sb_printf(b, ",\"sparse\":{\"count\":%d,\"indices\":{\"bufferView\":%d,\"componentType\":%d},"
                      "\"values\":{\"bufferView\":%d}}", a->nsparse, V[a->sidx], CT_UINT, V[a->sval]);
        sb_printf(b, "}");
    }
    sb_printf(b, "],\"bufferViews\":[");
    for (int i = 0; i < g->nacc; i++) {
        const struct accessor *a = &g->acc[i];
        if (a->kind == SPARSE) continue;
        sb_printf(b, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu", V[i] ? "," : "", a->offset, a->length);
        if (a->target) sb_printf(b, ",\"target\":%d", a->target);
        sb_printf(b, "}");
    }
    free(A);
    free(V);
    sb_printf(b, "],\"buffers\":[{\"byteLength\":%zu", buflen);
    if (uri) {
        sb_printf(b, ",\"uri\":");
        sb_string(b, uri);
    }
    sb_printf(b, "}]}");
}

static void put_le32(unsigned char *p, uint32_t v)
{
    p[0] = v & 0xFF; p[1] = (v >> 8) & 0xFF; p[2] = (v >> 16) & 0xFF; p[3] = (v >> 24) & 0xFF;
}

/* copy the temporary buffer to out (base64-encoded if b64) */
static int copy_bin(struct gltf_writer *g, FILE *out, int b64, const char *name)
{
    if (fflush(g->bin) != 0 || fseek(g->bin, 0, SEEK_SET) != 0)
        return cm_seterr("glTF writer: temporary file: %s", strerror(errno));
    unsigned char buf[3 * 4096];      /* a multiple of 3: base64 blocks join */
    size_t left = g->binlen;
    while (left > 0) {
        size_t want = left < sizeof buf ? left : sizeof buf;
        if (fread(buf, 1, want, g->bin) != want)
            return cm_seterr("glTF writer: temporary file: short read");
        left -= want;
        if (b64 ? base64_write(out, buf, want) < 0 : fwrite(buf, 1, want, out) != want)
            return cm_seterr("cannot write '%s': %s", name, strerror(errno));
    }
    return 0;
}

int gltf_write(struct gltf_writer *g, int container, FILE *out, const char *name, FILE *bin_out,
               const char *bin_uri)
{
    if (g->nmesh < 1) return cm_seterr("glTF writer: no mesh to write");
    for (int a = 0; a < g->nanim; a++)
        if (g->anim[a].nch < 1) return cm_seterr("glTF writer: animation %d has no channel", a);
    struct sbuf b = {0};
    int rc = 0;
    if (container == GLTF_BINARY) {
        json(g, &b, NULL, g->binlen);
        while (!b.oom && b.len % 4) sb_printf(&b, " ");
        if (b.oom) { free(b.s); return cm_seterr("glTF writer: out of memory"); }
        size_t binpad = (4 - g->binlen % 4) % 4;     /* always 0: all components are 4 bytes */
        size_t total = 12 + 8 + b.len + 8 + g->binlen + binpad;
        if (total > UINT32_MAX) { free(b.s); return cm_seterr("cannot write '%s': %zu bytes is beyond the 4 GiB of a .glb", name, total); }
        unsigned char h[20];
        memcpy(h, "glTF", 4);
        put_le32(h + 4, 2);
        put_le32(h + 8, (uint32_t)total);
        put_le32(h + 12, (uint32_t)b.len);
        memcpy(h + 16, "JSON", 4);
        unsigned char bh[8];
        put_le32(bh, (uint32_t)(g->binlen + binpad));
        memcpy(bh + 4, "BIN\0", 4);
        if (fwrite(h, 1, 20, out) != 20 || fwrite(b.s, 1, b.len, out) != b.len || fwrite(bh, 1, 8, out) != 8)
            rc = cm_seterr("cannot write '%s': %s", name, strerror(errno));
        if (rc == 0) rc = copy_bin(g, out, 0, name);
        if (rc == 0 && binpad && fwrite("\0\0\0", 1, binpad, out) != binpad)
            rc = cm_seterr("cannot write '%s': %s", name, strerror(errno));
    } else if (bin_out) {
        json(g, &b, bin_uri, g->binlen);
        sb_printf(&b, "\n");
        if (b.oom) { free(b.s); return cm_seterr("glTF writer: out of memory"); }
        rc = copy_bin(g, bin_out, 0, bin_uri);
        if (rc == 0 && fwrite(b.s, 1, b.len, out) != b.len)
            rc = cm_seterr("cannot write '%s': %s", name, strerror(errno));
    } else {
        /* data URI: the buffer object is the JSON's last member, so its
         * "uri" goes before the closing "}]}" */
        json(g, &b, NULL, g->binlen);
        if (b.oom) { free(b.s); return cm_seterr("glTF writer: out of memory"); }
        size_t pre = b.len - 3;
        static const char head[] = ",\"uri\":\"data:application/octet-stream;base64,";
        if (fwrite(b.s, 1, pre, out) != pre || fputs(head, out) < 0)
            rc = cm_seterr("cannot write '%s': %s", name, strerror(errno));
        if (rc == 0) rc = copy_bin(g, out, 1, name);
        if (rc == 0 && fputs("\"}]}\n", out) < 0)
            rc = cm_seterr("cannot write '%s': %s", name, strerror(errno));
    }
    free(b.s);
    return rc;
}
