/* mesh-info -- validate a MESH stream and print its counts, extent and
 * topology as "key value" lines.
 *
 * Streams: memory O(one frame + topology).  The whole stream is read and
 * validated before anything is printed, so an invalid stream prints only
 * the reason on stderr and exits 1.
 */
#include "mesh.h"
#include "solid.h"
#include "topology.h"
#include "geometry.h"
#include "numparse.h"
#include "tool.h"
#include "cm_error.h"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: mesh-info [options] [FILE]\n"
"Validate a MESH stream (plain or raw) and print its properties as\n"
"'key value' lines: counts, frames, clips, bounding box, diagonal, area,\n"
"volume (closed meshes), edges, boundary loops, connected components,\n"
"manifoldness, closedness, Euler characteristic and genus.\n"
"\n"
"Options:\n"
"  -c, --check PROP   print nothing; exit 1 with the reason unless PROP holds:\n"
"                     manifold, closed, oriented, or solid (closed, manifold\n"
"                     and, first frame, no two faces intersect: CGAL's\n"
"                     self_intersections) (may be repeated)\n"
"  -q, --quiet        validate only: print nothing, exit 0 on a valid stream\n"
"  -v, --verbose      timings on stderr\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Exit status: 0 valid (and every --check holds), 1 invalid stream or a\n"
"failed check, 2 usage error.\n"
"\n"
"Example: mesh-gen -n 4 cylinder | mesh-info\n";

enum { CHECK_MANIFOLD = 1, CHECK_CLOSED = 2, CHECK_ORIENTED = 4, CHECK_SOLID = 8 };

struct options {
    const char *input;
    int checks, quiet;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"check", 1, 0, 'c'}, {"quiet", 0, 0, 'q'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "c:qvh", lo, NULL)) != -1) {
        switch (c) {
        case 'c':
            if (!strcmp(optarg, "manifold")) o->checks |= CHECK_MANIFOLD;
            else if (!strcmp(optarg, "closed")) o->checks |= CHECK_CLOSED;
            else if (!strcmp(optarg, "oriented")) o->checks |= CHECK_ORIENTED;
            else if (!strcmp(optarg, "solid")) o->checks |= CHECK_SOLID | CHECK_CLOSED;
            else usage_error("--check: unknown property '%s' (manifold, closed, oriented, solid)", optarg);
            break;
        case 'q': o->quiet = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
}

/* everything mesh-info reports about the topology */
struct topo_report {
    int ne, nboundary_edges, nnonmanifold_edges, nnonmanifold_vertices;
    int ndegenerate, nisolated, nloops, ncomponents, oriented;
    int nused;            /* vertices referenced by a face */
    long euler;
};

static int find(int *p, int x)
{
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
}

static int analyze_topology(const int *F, int nf, int nv, struct topo_report *r)
{
    memset(r, 0, sizeof *r);
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0)
        return -1;
    r->ne = t.ne;
    r->nboundary_edges = t.nboundary;
    r->nnonmanifold_edges = t.nnonmanifold;
    r->nisolated = t.nisolated;
    r->nused = nv - t.nisolated;
    for (int f = 0; f < nf; f++) {
        const int *x = F + 3 * f;
        r->ndegenerate += x[0] == x[1] || x[1] == x[2] || x[2] == x[0];
    }
    r->nnonmanifold_vertices = nonmanifold_vertices(&t, F);
    r->ncomponents = connected_components(&t, F, NULL);
    r->euler = (long)r->nused - t.ne + nf;
    /* boundary loops: components of the graph of boundary edges (independent
     * of orientation, so it also counts on badly oriented meshes) */
    int *p = malloc(((size_t)nv + 1) * sizeof *p);
    unsigned char *onb = calloc((size_t)nv + 1, 1);
    if (!p || !onb) { free(p); free(onb); topology_free(&t); return cm_seterr("out of memory"); }
    for (int v = 0; v < nv; v++) p[v] = v;
    for (int e = 0; e < t.ne; e++)
        if (t.EFn[e] == 1) {
            int a = find(p, t.E[2 * e]), b = find(p, t.E[2 * e + 1]);
            onb[t.E[2 * e]] = onb[t.E[2 * e + 1]] = 1;
            if (a != b) p[a] = b;
        }
    for (int v = 0; v < nv; v++)
        r->nloops += onb[v] && find(p, v) == v;
    free(p);
    free(onb);
    /* consistently oriented: the two faces of every interior edge traverse
     * it in opposite directions */
    r->oriented = 1;
    for (int e = 0; e < t.ne && r->oriented; e++) {
        if (t.EFn[e] != 2) continue;
        int dir[2];
        for (int s = 0; s < 2; s++) {
            int f = t.EF[2 * e + s];
            dir[s] = 0;
            for (int c = 0; c < 3; c++)
                if (F[3 * f + c] == t.E[2 * e] && F[3 * f + (c + 1) % 3] == t.E[2 * e + 1])
                    dir[s] = 1;
        }
        if (dir[0] == dir[1]) r->oriented = 0;
    }
    topology_free(&t);
    return 0;
}

static void put(const char *key, double x)
{
    char b[40];
    format_double(b, x);
    printf("%s %s\n", key, b);
}

/* A derived quantity (diagonal, area, volume) of finite coordinates that
 * double arithmetic over- or underflowed (extents near 1e308 or 1e-300):
 * computed again in long double (range 1e+-4932) and printed from it. */
static void put_robust(const char *key, double x, long double exact)
{
    if (isfinite(x) && (x == 0 ? exact == 0 : fabs(x) >= DBL_MIN)) {
        put(key, x);
        return;
    }
    printf("%s %.17Lg\n", key, exact);
}

static long double diag_ld(const double *lo, const double *hi)
{
    long double s = 0;
    for (int d = 0; d < 3; d++) {
        long double e = (long double)hi[d] - lo[d];
        s += e * e;
    }
    return sqrtl(s);
}

/* area (what = 0) or volume (what = 1) of the triangles */
static long double measure_ld(const double *X, const int *F, int nf, int what)
{
    long double sum = 0;
    for (int f = 0; f < nf; f++) {
        const double *a = X + 3 * F[3 * f], *b = X + 3 * F[3 * f + 1], *c = X + 3 * F[3 * f + 2];
        if (what) {   /* signed tetrahedron volumes against the origin */
            sum += ((long double)a[0] * ((long double)b[1] * c[2] - (long double)b[2] * c[1]) -
                    (long double)a[1] * ((long double)b[0] * c[2] - (long double)b[2] * c[0]) +
                    (long double)a[2] * ((long double)b[0] * c[1] - (long double)b[1] * c[0])) / 6;
            continue;
        }
        long double u[3], v[3];
        for (int d = 0; d < 3; d++) { u[d] = (long double)b[d] - a[d]; v[d] = (long double)c[d] - a[d]; }
        long double n0 = u[1] * v[2] - u[2] * v[1], n1 = u[2] * v[0] - u[0] * v[2],
                    n2 = u[0] * v[1] - u[1] * v[0];
        sum += 0.5L * sqrtl(n0 * n0 + n1 * n1 + n2 * n2);
    }
    return sum;
}

static void put3(const char *key, const double *x)
{
    char b[3][40];
    for (int d = 0; d < 3; d++) format_double(b[d], x[d]);
    printf("%s %s %s %s\n", key, b[0], b[1], b[2]);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    double *X = malloc(((size_t)r.nv * 3 + 1) * sizeof *X);
    double *X0 = malloc(((size_t)r.nv * 3 + 1) * sizeof *X0);
    if (!X || !X0)
        die("out of memory");
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int nframes = 0, nclips = 0, cut, rc;
    while ((rc = mesh_reader_next(&r, X, &cut)) > 0) {
        if (nframes == 0) {
            memcpy(X0, X, (size_t)r.nv * 3 * sizeof *X);
            if (r.nv > 0) bounding_box(X, r.nv, lo, hi);
            nclips = 1;
        } else {
            double l[3] = {0, 0, 0}, h[3] = {0, 0, 0};
            if (r.nv > 0) bounding_box(X, r.nv, l, h);
            for (int d = 0; d < 3 && r.nv > 0; d++) {
                if (l[d] < lo[d]) lo[d] = l[d];
                if (h[d] > hi[d]) hi[d] = h[d];
            }
            nclips += cut != 0;
        }
        nframes++;
    }
    if (rc < 0)
        die("%s", cm_errmsg());
    int nv = r.nv, nf = r.nf, raw = r.raw;
    const char *name = r.name;

    struct topo_report t;
    if (analyze_topology(r.F, nf, nv, &t) < 0)
        die("%s", cm_errmsg());
    int manifold = t.nnonmanifold_edges == 0 && t.nnonmanifold_vertices == 0 &&
                   t.ndegenerate == 0 && nf > 0;
    int closed = manifold && t.nboundary_edges == 0;

    if (o.checks) {
        if ((o.checks & (CHECK_MANIFOLD | CHECK_CLOSED | CHECK_ORIENTED)) && !manifold) {
            if (nf == 0)
                die("'%s': not manifold: no faces", name);
            die("'%s': not manifold: %d non-manifold edges, %d non-manifold vertices, "
                "%d degenerate faces", name, t.nnonmanifold_edges, t.nnonmanifold_vertices,
                t.ndegenerate);
        }
        if ((o.checks & CHECK_CLOSED) && !closed)
            die("'%s': not closed: %d boundary edges in %d boundary loops", name,
                t.nboundary_edges, t.nloops);
        if ((o.checks & CHECK_ORIENTED) && !t.oriented)
            die("'%s': not consistently oriented", name);
        if (o.checks & CHECK_SOLID) {
            struct solid_info si;
            if (solid_check(X0, nv, r.F, nf, &si) < 0) die("'%s': %s", name, cm_errmsg());
            if (si.self_intersections)
                die("'%s': not a solid: %d pairs of faces intersect", name, si.self_intersections);
        }
        mesh_reader_close(&r);
        free(X);
        free(X0);
        return 0;
    }
    if (o.quiet) {
        mesh_reader_close(&r);
        free(X);
        free(X0);
        return 0;
    }

    printf("format %s\n", raw ? "raw" : "plain");
    printf("vertices %d\n", nv);
    printf("faces %d\n", nf);
    printf("frames %d\n", nframes);
    printf("clips %d\n", nclips);
    put3("bbox_min", lo);
    put3("bbox_max", hi);
    double diag[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    put_robust("diagonal", norm3(diag), diag_ld(lo, hi));
    double area = mesh_area(X0, r.F, nf);
    put_robust("area", area, isfinite(area) && area >= DBL_MIN ? area : measure_ld(X0, r.F, nf, 0));
    if (closed) {
        double vol = mesh_volume(X0, r.F, nf);
        put_robust("volume", vol, isfinite(vol) && fabs(vol) >= DBL_MIN ? vol : measure_ld(X0, r.F, nf, 1));
    }
    printf("edges %d\n", t.ne);
    printf("boundary_edges %d\n", t.nboundary_edges);
    printf("boundary_loops %d\n", t.nloops);
    printf("components %d\n", t.ncomponents);
    printf("isolated_vertices %d\n", t.nisolated);
    printf("degenerate_faces %d\n", t.ndegenerate);
    printf("nonmanifold_edges %d\n", t.nnonmanifold_edges);
    printf("nonmanifold_vertices %d\n", t.nnonmanifold_vertices);
    printf("manifold %s\n", manifold ? "yes" : "no");
    printf("closed %s\n", closed ? "yes" : "no");
    printf("oriented %s\n", t.oriented ? "yes" : "no");
    printf("euler %ld\n", t.euler);
    /* chi = 2c - 2g - b for an orientable manifold with c components */
    long g2 = 2L * t.ncomponents - t.nloops - t.euler;
    if (manifold && t.oriented && g2 >= 0 && g2 % 2 == 0)
        printf("genus %ld\n", g2 / 2);
    else
        printf("genus -\n");
    mesh_reader_close(&r);
    free(X);
    free(X0);
    if (fflush(stdout) != 0 || ferror(stdout))
        die("cannot write output");
    return 0;
}
