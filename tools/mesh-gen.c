/* mesh-gen -- generate test meshes and animations (the rbox of stopmo).
 *
 * Shapes: grid (open, flat), icosphere (closed), cylinder (open tube, or
 * closed with --caps).  Animations: bend, twist, wave, all smooth in time,
 * so every pipeline can be tested without outside data.
 */
#include "mesh.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: mesh-gen [options] SHAPE\n"
"Generate a test mesh or animation as a MESH stream on stdout.\n"
"\n"
"Shapes:\n"
"  grid        flat n x m grid in the unit square (z = 0), open\n"
"  icosphere   subdivided icosahedron, unit radius, closed\n"
"  cylinder    tube of radius 0.25 along z from 0 to 1, open (--caps: closed)\n"
"\n"
"Options:\n"
"  -n, --resolution N   grid cells per side / cylinder segments around (default 10)\n"
"  -m, --rings M        grid cells in y / cylinder rings along z (default = N)\n"
"  -s, --subdiv K       icosphere subdivisions (default 2)\n"
"      --caps           close the cylinder with fans at both ends\n"
"  -f, --frames F       number of frames (default 1)\n"
"  -a, --anim KIND      bend | twist | wave | none (default bend if F > 1)\n"
"      --amount X       animation amplitude: radians for bend/twist, units for wave (default 1)\n"
"      --cut-every K    mark a clip cut every K frames\n"
"      --raw            write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"Example: mesh-gen -f 20 -a twist cylinder | mesh-info\n";

struct options {
    const char *shape, *anim;
    int n, m, subdiv, caps, frames, cut_every, raw;
    double amount;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"resolution", 1, 0, 'n'}, {"rings", 1, 0, 'm'}, {"subdiv", 1, 0, 's'},
        {"caps", 0, 0, 'C'}, {"frames", 1, 0, 'f'}, {"anim", 1, 0, 'a'},
        {"amount", 1, 0, 'A'}, {"cut-every", 1, 0, 'K'}, {"raw", 0, 0, 'R'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->n = 10; o->m = -1; o->subdiv = 2; o->frames = 1; o->amount = 1;
    int c;
    while ((c = getopt_long(argc, argv, "n:m:s:f:a:h", lo, NULL)) != -1) {
        switch (c) {
        case 'n': o->n = arg_int(optarg, "--resolution"); break;
        case 'm': o->m = arg_int(optarg, "--rings"); break;
        case 's': o->subdiv = arg_int(optarg, "--subdiv"); break;
        case 'C': o->caps = 1; break;
        case 'f': o->frames = arg_int(optarg, "--frames"); break;
        case 'a': o->anim = optarg; break;
        case 'A': o->amount = arg_double(optarg, "--amount"); break;
        case 'K': o->cut_every = arg_int(optarg, "--cut-every"); break;
        case 'R': o->raw = 1; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind != argc - 1)
        usage_error("expected one SHAPE (grid, icosphere, cylinder)");
    o->shape = argv[optind];
    if (o->m < 0) o->m = o->n;
    if (o->n < 1 || o->n > 5000 || o->m < 1 || o->m > 5000)
        usage_error("resolution must be in 1..5000");
    if (o->subdiv < 0 || o->subdiv > 8)
        usage_error("--subdiv must be in 0..8");
    if (o->frames < 1)
        usage_error("--frames must be at least 1");
    if (o->cut_every < 0)
        usage_error("--cut-every must be positive");
    if (!o->anim) o->anim = o->frames > 1 ? "bend" : "none";
    if (strcmp(o->anim, "bend") && strcmp(o->anim, "twist") && strcmp(o->anim, "wave") &&
        strcmp(o->anim, "none"))
        usage_error("unknown animation '%s' (bend, twist, wave, none)", o->anim);
}

/* growable vertex/face lists */
struct build { double *V; int *F; int nv, nf, vcap, fcap; };

static int addv(struct build *b, double x, double y, double z)
{
    if (b->nv == b->vcap) b->V = realloc(b->V, (b->vcap = b->vcap ? 2 * b->vcap : 256) * 3 * sizeof(double));
    b->V[3 * b->nv] = x; b->V[3 * b->nv + 1] = y; b->V[3 * b->nv + 2] = z;
    return b->nv++;
}

static void addf(struct build *b, int i, int j, int k)
{
    if (b->nf == b->fcap) b->F = realloc(b->F, (b->fcap = b->fcap ? 2 * b->fcap : 256) * 3 * sizeof(int));
    b->F[3 * b->nf] = i; b->F[3 * b->nf + 1] = j; b->F[3 * b->nf + 2] = k;
    b->nf++;
}

static void make_grid(struct build *b, int n, int m)
{
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++) addv(b, (double)i / n, (double)j / m, 0);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, c = a + n + 2;
            /* alternate diagonals so the grid has no preferred direction */
            if ((i + j) % 2) { addf(b, a, a + 1, c); addf(b, a, c, c - 1); }
            else { addf(b, a, a + 1, c - 1); addf(b, a + 1, c, c - 1); }
        }
}

static void make_cylinder(struct build *b, int n, int m, int caps)
{
    for (int j = 0; j <= m; j++)
        for (int i = 0; i < n; i++) {
            double t = 2 * M_PI * i / n;
            addv(b, 0.25 * cos(t), 0.25 * sin(t), (double)j / m);
        }
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            int a = j * n + i, bb = j * n + (i + 1) % n;
            addf(b, a, bb, bb + n);
            addf(b, a, bb + n, a + n);
        }
    if (caps) {
        int c0 = addv(b, 0, 0, 0), c1 = addv(b, 0, 0, 1);
        for (int i = 0; i < n; i++) {
            addf(b, c0, (i + 1) % n, i);
            addf(b, c1, m * n + i, m * n + (i + 1) % n);
        }
    }
}

/* midpoint cache for icosphere subdivision: key (min,max) -> vertex */
struct edgemap { long *key; int *val; int cap; };

static int midpoint(struct build *b, struct edgemap *em, int i, int j)
{
    long lo = i < j ? i : j, hi = i < j ? j : i, k = lo * 1000003L + hi;
    unsigned h = (unsigned)(k * 2654435761u) & (em->cap - 1);
    while (em->key[h] >= 0) {
        if (em->key[h] == k) return em->val[h];
        h = (h + 1) & (em->cap - 1);
    }
    double p[3];
    for (int d = 0; d < 3; d++) p[d] = 0.5 * (b->V[3 * i + d] + b->V[3 * j + d]);
    double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    em->key[h] = k;
    return em->val[h] = addv(b, p[0] / l, p[1] / l, p[2] / l);
}

static void make_icosphere(struct build *b, int subdiv)
{
    double t = (1 + sqrt(5.0)) / 2, s = sqrt(1 + t * t);
    static const int ico[20][3] = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (int i = 0; i < 12; i++) addv(b, v[i][0] / s, v[i][1] / s, v[i][2] / s);
    for (int f = 0; f < 20; f++) addf(b, ico[f][0], ico[f][1], ico[f][2]);
    for (int k = 0; k < subdiv; k++) {
        struct edgemap em;
        em.cap = 1;
        while (em.cap < 4 * b->nf) em.cap *= 2;
        em.key = malloc(em.cap * sizeof *em.key);
        em.val = malloc(em.cap * sizeof *em.val);
        for (int i = 0; i < em.cap; i++) em.key[i] = -1;
        int nf = b->nf;
        int *old = malloc((size_t)nf * 3 * sizeof *old);
        memcpy(old, b->F, (size_t)nf * 3 * sizeof *old);
        b->nf = 0;
        for (int f = 0; f < nf; f++) {
            int a = old[3 * f], bb = old[3 * f + 1], c = old[3 * f + 2];
            int ab = midpoint(b, &em, a, bb), bc = midpoint(b, &em, bb, c), ca = midpoint(b, &em, c, a);
            addf(b, a, ab, ca); addf(b, bb, bc, ab); addf(b, c, ca, bc); addf(b, ab, bc, ca);
        }
        free(old); free(em.key); free(em.val);
    }
}

/* deform rest positions P into X at phase t in [0, 1] */
static void animate(const struct options *o, const double *P, int nv, double t, double *X,
                    const double lo[3], const double hi[3])
{
    double amt = o->amount * sin(2 * M_PI * t);
    /* the animation axis is the longest bounding-box side */
    int ax = 0;
    for (int d = 1; d < 3; d++) if (hi[d] - lo[d] > hi[ax] - lo[ax]) ax = d;
    int u = (ax + 1) % 3, w = (ax + 2) % 3;
    if (!strcmp(o->shape, "grid")) { ax = 0; u = 2; w = 1; }   /* bend out of plane */
    double len = hi[ax] - lo[ax] > 0 ? hi[ax] - lo[ax] : 1;
    for (int i = 0; i < nv; i++) {
        const double *p = P + 3 * i;
        double *x = X + 3 * i;
        memcpy(x, p, 3 * sizeof *x);
        double s = (p[ax] - lo[ax]) / len;            /* 0..1 along the axis */
        if (!strcmp(o->anim, "bend")) {
            /* bend the upper half around an axis at s = 0.5, angle amt */
            double th = amt * (s > 0.5 ? (s - 0.5) * 2 : 0);
            double r = p[ax] - (lo[ax] + 0.5 * len);
            if (s > 0.5 && fabs(amt) > 1e-12) {
                double R = 0.5 * len / amt;            /* arc radius */
                double q = p[u];
                x[ax] = lo[ax] + 0.5 * len + (R - q) * sin(r / R);
                x[u] = R - (R - q) * cos(r / R);
                (void)th;
            }
        } else if (!strcmp(o->anim, "twist")) {
            double th = amt * s;
            double cu = p[u] - 0.5 * (lo[u] + hi[u]), cw = p[w] - 0.5 * (lo[w] + hi[w]);
            x[u] = 0.5 * (lo[u] + hi[u]) + cos(th) * cu - sin(th) * cw;
            x[w] = 0.5 * (lo[w] + hi[w]) + sin(th) * cu + cos(th) * cw;
        } else if (!strcmp(o->anim, "wave")) {
            x[u] += 0.1 * len * amt * sin(2 * M_PI * (s - t));
        }
    }
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct build b = {0};
    if (!strcmp(o.shape, "grid")) make_grid(&b, o.n, o.m);
    else if (!strcmp(o.shape, "icosphere")) make_icosphere(&b, o.subdiv);
    else if (!strcmp(o.shape, "cylinder")) make_cylinder(&b, o.n, o.m, o.caps);
    else usage_error("unknown shape '%s' (grid, icosphere, cylinder)", o.shape);

    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) { lo[d] = hi[d] = b.V[d]; }
    for (int i = 0; i < b.nv; i++)
        for (int d = 0; d < 3; d++) {
            if (b.V[3 * i + d] < lo[d]) lo[d] = b.V[3 * i + d];
            if (b.V[3 * i + d] > hi[d]) hi[d] = b.V[3 * i + d];
        }
    struct mesh_writer w;
    double *X = malloc((size_t)b.nv * 3 * sizeof *X);
    if (mesh_writer_open(&w, stdout, b.nv, b.nf, b.F, o.frames, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    for (int k = 0; k < o.frames; k++) {
        double t = o.frames > 1 ? (double)k / (o.frames - 1) : 0;
        animate(&o, b.V, b.nv, t, X, lo, hi);
        int cut = o.cut_every > 0 && k > 0 && k % o.cut_every == 0;
        if (mesh_writer_frame(&w, X, cut) < 0)
            die("cannot write output: %s", cm_errmsg());
    }
    if (mesh_writer_close(&w) < 0 || fclose(stdout) != 0)
        die("cannot write output: %s", cm_errmsg());
    free(X); free(b.V); free(b.F);
    return 0;
}
