/* head-gen -- the stylized talking head that stopmo's demo animates.
 *
 * A closed head (subdivided icosahedron shaped into a skull with nose, brow,
 * eye bulges and a mouth crease) driven by smooth curves: a talking jaw, lip
 * corners (smile) and pucker, blinking eyelids and brow raises.  The band
 * between the eyes and the mouth and the back of the head barely move, so
 * StopShop's segmentation has a near-motionless cut to find, as on a real
 * face capture.  The project generates its own demo data with this, since it
 * cannot ship third-party captures.
 */
#include "cm_error.h"
#include "mesh.h"
#include "rng.h"
#include "tool.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: head-gen [options]\n"
"Write the stylized talking-head animation (stopmo's demo data) as a MESH stream.\n"
"\n"
"Options:\n"
"  -f, --frames F       number of frames (default 240, i.e. 10 s at 24 fps)\n"
"      --fps R          frames per second of the motion curves (default 24)\n"
"  -s, --subdiv K       icosphere subdivisions of the head (default 4: 2562 vertices)\n"
"      --clips C        split the animation into C clips with cut marks (default 2, 1 for one frame)\n"
"      --seed N         seed of the motion curves (default 1)\n"
"      --raw            raw (binary) MESH output (or STOPMO_RAW=1)\n"
"  -o, --output FILE    write to FILE (temporary + rename) instead of stdout\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"Geometry: y up, the face looks along +z; the head spans y in [-1, 1].\n"
"Landmark faces for seeds: the forehead is near (0, 0.75, 0.55), the chin near\n"
"(0, -0.85, 0.45) (seg-graphcut snaps points to triangles).\n"
"\n"
"Example: head-gen -f 48 | mesh-info\n";

struct options {
    long frames, subdiv, clips;
    int raw;
    double fps;
    const char *output;
    unsigned long seed;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frames", 1, 0, 'f'}, {"fps", 1, 0, 'F'}, {"subdiv", 1, 0, 's'},
        {"clips", 1, 0, 'c'}, {"seed", 1, 0, 'S'}, {"raw", 0, 0, 'R'}, {"output", 1, 0, 'o'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    o->frames = 240; o->fps = 24; o->subdiv = 4; o->clips = -1; o->raw = 0; o->seed = 1;
    o->output = NULL;
    int c;
    while ((c = getopt_long(argc, argv, "f:s:o:h", lo, NULL)) != -1) {
        switch (c) {
        case 'f': o->frames = arg_long(optarg, "--frames"); break;
        case 'F': o->fps = arg_double(optarg, "--fps"); break;
        case 's': o->subdiv = arg_long(optarg, "--subdiv"); break;
        case 'c':
            o->clips = arg_long(optarg, "--clips");
            if (o->clips < 1) usage_error("--clips must be in 1..frames");
            break;
        case 'S': o->seed = (unsigned long)arg_long(optarg, "--seed"); break;
        case 'R': o->raw = 1; break;
        case 'o': o->output = optarg; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind != argc) usage_error("unexpected argument '%s'", argv[optind]);
    if (o->frames < 1 || o->frames > 10000000) usage_error("--frames must be in 1..10000000");
    if (o->subdiv < 1 || o->subdiv > 7) usage_error("--subdiv must be in 1..7");
    if (o->clips < 0) o->clips = o->frames > 1 ? 2 : 1;
    if (o->clips < 1 || o->clips > o->frames) usage_error("--clips must be in 1..frames");
    if (!(o->fps > 0)) usage_error("--fps must be positive");
}

/* ---- base geometry: icosphere ---- */
struct geo { double *V; int *F; int nv, nf, vcap, fcap; };

static int addv(struct geo *g, const double p[3])
{
    if (g->nv == g->vcap) g->V = realloc(g->V, (g->vcap = g->vcap ? 2 * g->vcap : 64) * 3 * sizeof(double));
    double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int d = 0; d < 3; d++) g->V[3 * g->nv + d] = p[d] / l;
    return g->nv++;
}

static void addf(struct geo *g, int a, int b, int c)
{
    if (g->nf == g->fcap) g->F = realloc(g->F, (g->fcap = g->fcap ? 2 * g->fcap : 64) * 3 * sizeof(int));
    g->F[3 * g->nf] = a; g->F[3 * g->nf + 1] = b; g->F[3 * g->nf + 2] = c;
    g->nf++;
}

static int mid(struct geo *g, long *key, int *val, int cap, int i, int j)
{
    long lo = i < j ? i : j, hi = i < j ? j : i, k = lo * 4000037L + hi;
    unsigned h = (unsigned)((unsigned long)k * 2654435761u) & (cap - 1);
    while (key[h] >= 0) {
        if (key[h] == k) return val[h];
        h = (h + 1) & (cap - 1);
    }
    double p[3];
    for (int d = 0; d < 3; d++) p[d] = g->V[3 * i + d] + g->V[3 * j + d];
    key[h] = k;
    return val[h] = addv(g, p);
}

static void icosphere(struct geo *g, int subdiv)
{
    double t = (1 + sqrt(5.0)) / 2;
    double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    static const int f[20][3] = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int i = 0; i < 12; i++) addv(g, v[i]);
    for (int i = 0; i < 20; i++) addf(g, f[i][0], f[i][1], f[i][2]);
    for (int s = 0; s < subdiv; s++) {
        int cap = 1;
        while (cap < 4 * g->nf) cap *= 2;
        long *key = malloc(cap * sizeof *key);
        int *val = malloc(cap * sizeof *val);
        for (int i = 0; i < cap; i++) key[i] = -1;
        int nf = g->nf, *old = malloc((size_t)nf * 3 * sizeof *old);
        memcpy(old, g->F, (size_t)nf * 3 * sizeof *old);
        g->nf = 0;
        for (int k = 0; k < nf; k++) {
            int a = old[3 * k], b = old[3 * k + 1], c = old[3 * k + 2];
            int ab = mid(g, key, val, cap, a, b), bc = mid(g, key, val, cap, b, c),
                ca = mid(g, key, val, cap, c, a);
            addf(g, a, ab, ca); addf(g, b, bc, ab); addf(g, c, ca, bc); addf(g, ab, bc, ca);
        }
        free(old); free(key); free(val);
    }
}

static double gauss2(double dx, double dy, double r) { return exp(-(dx * dx + dy * dy) / (r * r)); }
static double smoothstep(double a, double b, double x)
{
    double t = (x - a) / (b - a);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3 - 2 * t);
}

/* unit sphere point -> rest head position */
static void shape_head(const double s[3], double p[3])
{
    double x = s[0], y = s[1], z = s[2];
    double front = smoothstep(0.0, 0.5, z);          /* 1 on the face side */
    p[0] = 0.72 * x * (1 - 0.22 * smoothstep(-0.2, -1.0, y));   /* narrower jaw */
    p[1] = y;
    p[2] = 0.82 * z;
    /* nose: a ridge from between the eyes to the tip, nostrils at its base */
    double ridge = smoothstep(0.22, -0.05, y) * smoothstep(-0.22, -0.12, y);
    p[2] += front * 0.20 * ridge * exp(-pow(x / (0.05 + 0.1 * smoothstep(0.2, -0.2, y)), 2));
    p[2] += front * 0.05 * gauss2(x, (y - 0.42) / 0.6, 0.12) * (fabs(x) < 0.5);  /* brow ridge */
    for (int e = -1; e <= 1; e += 2) {
        double r = sqrt(pow(x - 0.27 * e, 2) + pow(y - 0.22, 2));
        p[2] -= front * 0.07 * exp(-pow(r / 0.15, 2));                   /* socket */
        p[2] += front * 0.075 * exp(-pow(r / 0.085, 2));                 /* eyeball */
        p[0] += 0.09 * e * smoothstep(0.75, 0.95, e * s[0]) *            /* ears */
                exp(-pow((y - 0.08) / 0.2, 2) - pow((z + 0.05) / 0.25, 2));
    }
    for (int l = -1; l <= 1; l += 2)                                     /* lips */
        p[2] += front * 0.05 * exp(-pow(x / 0.2, 2) - pow((y + 0.45 + 0.05 * l) / 0.045, 2));
    p[2] -= front * 0.04 * exp(-pow((y + 0.45) / 0.02, 2)) * smoothstep(0.26, 0.16, fabs(x));
    p[2] += front * 0.05 * gauss2(x / 0.9, (y + 0.78), 0.16);            /* chin */
}

struct curves { double jaw, smile, pucker, blink, brow; };

/* smooth motion curves at time t seconds */
static void motion(double t, const double *ph, struct curves *c)
{
    /* talking: a band-limited sum of sines, clamped to an open-only jaw */
    double talk = 0.5 * sin(2 * M_PI * 3.1 * t + ph[0]) + 0.3 * sin(2 * M_PI * 4.7 * t + ph[1]) +
                  0.2 * sin(2 * M_PI * 1.3 * t + ph[2]);
    double envelope = 0.5 + 0.5 * sin(2 * M_PI * 0.23 * t + ph[3]);   /* phrases */
    c->jaw = 0.32 * envelope * 0.5 * (1 + talk);
    c->smile = 0.5 + 0.5 * sin(2 * M_PI * 0.17 * t + ph[4]);
    c->pucker = pow(0.5 + 0.5 * sin(2 * M_PI * 0.11 * t + ph[5]), 4);
    c->brow = pow(0.5 + 0.5 * sin(2 * M_PI * 0.29 * t + ph[6]), 3);
    /* blinks: a short smooth bump every ~2.7 s */
    double period = 2.7, u = fmod(t + ph[7], period) / period * period;   /* seconds into cycle */
    c->blink = u < 0.25 ? sin(M_PI * u / 0.25) : 0;
}

static void pose(const double *P, int nv, const struct curves *c, double *X)
{
    for (int i = 0; i < nv; i++) {
        double x = P[3 * i], y = P[3 * i + 1], z = P[3 * i + 2];
        double front = smoothstep(0.0, 0.45, z);
        double nx = x, ny = y, nz = z;
        /* jaw: below the mouth, rotate about a hinge behind the cheeks */
        double wj = smoothstep(-0.40, -0.50, y) * smoothstep(-0.45, 0.1, z);
        if (wj > 0) {
            double a = c->jaw * wj, hy = -0.25, hz = -0.15;
            double ry = y - hy, rz = z - hz;
            ny = hy + cos(a) * ry - sin(a) * rz;
            nz = hz + sin(a) * ry + cos(a) * rz;
        }
        /* lips: corners pull up and out (smile), lips push forward (pucker) */
        for (int e = -1; e <= 1; e += 2) {
            double g = front * gauss2(x - 0.2 * e, y + 0.45, 0.13);
            nx += 0.05 * c->smile * g * e;
            ny += 0.06 * c->smile * g;
        }
        double gl = front * gauss2(x / 1.3, (y + 0.46) / 0.8, 0.14);
        nz += 0.07 * c->pucker * gl;
        nx -= 0.25 * c->pucker * gl * x;
        /* eyelids: the skin above each eye slides down over the bulge */
        for (int e = -1; e <= 1; e += 2) {
            double dy = y - 0.22, g = front * gauss2(x - 0.27 * e, dy * 0.8, 0.12) * smoothstep(0.17, 0.27, y);
            ny -= 0.08 * c->blink * g;
            nz += 0.015 * c->blink * g;
        }
        /* brows */
        double gb = front * gauss2(x / 1.6, y - 0.45, 0.1);
        ny += 0.05 * c->brow * gb;
        X[3 * i] = nx; X[3 * i + 1] = ny; X[3 * i + 2] = nz;
    }
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct geo g = {0};
    icosphere(&g, (int)o.subdiv);
    double *P = malloc((size_t)g.nv * 3 * sizeof *P), *X = malloc((size_t)g.nv * 3 * sizeof *X);
    for (int i = 0; i < g.nv; i++) shape_head(g.V + 3 * i, P + 3 * i);
    struct rng r;
    rng_seed(&r, o.seed);
    double ph[8];
    for (int k = 0; k < 8; k++) ph[k] = 2 * M_PI * rng_uniform(&r);
    ph[7] = 2.7 * rng_uniform(&r);
    struct mesh_writer w;
    FILE *out = out_open(o.output);
    if (mesh_writer_open(&w, out, g.nv, g.nf, g.F, (int)o.frames, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    for (int k = 0; k < o.frames; k++) {
        struct curves c;
        motion(k / o.fps, ph, &c);
        pose(P, g.nv, &c, X);
        int cut = k > 0 && (long)k * o.clips / o.frames != (long)(k - 1) * o.clips / o.frames;
        if (mesh_writer_frame(&w, X, cut) < 0)
            die("cannot write output: %s", cm_errmsg());
    }
    if (mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    free(P); free(X); free(g.V); free(g.F);
    return 0;
}
