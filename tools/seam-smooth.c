/* seam-smooth -- replace the zig-zag part boundaries of a per-triangle
 * labeling by smooth seams (StopShop Sec. 3.1, "Part boundary smoothing").
 *
 * Area-weighted per-vertex part votes, implicit Laplacian smoothing of the
 * votes, then re-meshing along the curves where the maximum vote changes:
 * new vertices on edges (one barycentric position used in every frame) and,
 * where three parts meet or the vote is a saddle, one centre vertex per
 * triangle.  The geometry is unchanged: every output vertex is a fixed
 * convex combination of input vertices of one input triangle.
 * Two streaming passes (average areas, then the frames); memory O(one frame
 * + topology).
 */
#include "cm_error.h"
#include "coincident.h"
#include "columns.h"
#include "geometry.h"
#include "laplacian.h"
#include "mesh.h"
#include "mesh_spool.h"
#include "progress.h"
#include "seam.h"
#include "spd.h"
#include "sparse.h"
#include "tool.h"
#include "topology.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: seam-smooth [options] -l LABELS -L NEWLABELS [FILE]\n"
"Smooth the part seams of a per-triangle labeling of a MESH animation: the\n"
"output animation has new vertices and triangles along smooth seams (same\n"
"geometry in every frame) and NEWLABELS gets one label per new triangle.\n"
"\n"
"Options:\n"
"  -l, --labels FILE       per-triangle part labels of the input (0..s-1)\n"
"  -L, --labels-out FILE   write the labels of the output triangles\n"
"  -a, --amount A          smoothing time in squared mean edge lengths\n"
"                          (default 4; 0: no smoothing, straight cuts only)\n"
"  -i, --iterations N      implicit smoothing steps of that time (default 1)\n"
"      --snap T            keep new vertices at least T (edge fraction) away\n"
"                          from the edge ends, no slivers (default 0.05)\n"
"      --map FILE          write, per output vertex, 'a b c wa wb wc': the\n"
"                          input vertices and weights that make it\n"
"  -o, --output FILE       write the animation to FILE (default stdout)\n"
"      --raw               write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose           seam length and turning angle before and after\n"
"  -h, --help              show this help\n"
"      --version           show the version\n"
"\n"
"Example: seg-graphcut --seed 0:0 --seed 1:399 a.mesh > p.txt &&\n"
"         seam-smooth -l p.txt -L q.txt a.mesh > b.mesh\n";

struct options {
    const char *input, *labels, *labels_out, *output, *map;
    double amount, snap;
    int iterations, raw;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"labels", 1, 0, 'l'}, {"labels-out", 1, 0, 'L'}, {"amount", 1, 0, 'a'},
        {"iterations", 1, 0, 'i'}, {"snap", 1, 0, 'S'}, {"map", 1, 0, 'M'},
        {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->amount = 4;
    o->iterations = 1;
    o->snap = 0.05;
    int c;
    while ((c = getopt_long(argc, argv, "l:L:a:i:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': o->labels = optarg; break;
        case 'L': o->labels_out = optarg; break;
        case 'a': o->amount = arg_double(optarg, "--amount"); break;
        case 'i': o->iterations = arg_int(optarg, "--iterations"); break;
        case 'S': o->snap = arg_double(optarg, "--snap"); break;
        case 'M': o->map = optarg; break;
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1) usage_error("at most one input FILE");
    o->input = optind < argc ? argv[optind] : NULL;
    if (!o->labels) usage_error("need the input labels (-l FILE)");
    if (!o->labels_out) usage_error("need a file for the new labels (-L FILE)");
    if (!(o->amount >= 0) || !isfinite(o->amount)) usage_error("--amount must be >= 0");
    if (o->iterations < 1 || o->iterations > 1000) usage_error("--iterations must be in 1..1000");
    if (!(o->snap >= 0 && o->snap < 0.25)) usage_error("--snap must be in [0, 0.25)");
}

/* ---- growable arrays ---- */
struct ivec { int *x; size_t n, cap; };
struct dvec { double *x; size_t n, cap; };
/* room for one more element of size sz in x (n used, *cap allocated) */
static void *reserve(void *x, size_t n, size_t *cap, size_t sz)
{
    if (n == *cap) {
        *cap = *cap ? 2 * *cap : 1024;
        x = realloc(x, *cap * sz);
        if (!x) die("out of memory");
    }
    return x;
}
static void ipush(struct ivec *v, int a)
{
    v->x = reserve(v->x, v->n, &v->cap, sizeof *v->x);
    v->x[v->n++] = a;
}
static void dpush(struct dvec *v, double a)
{
    v->x = reserve(v->x, v->n, &v->cap, sizeof *v->x);
    v->x[v->n++] = a;
}

/* argmax with ties to the lower label */
static int argmax(const double *p, int s)
{
    int b = 0;
    for (int j = 1; j < s; j++) if (p[j] > p[b]) b = j;
    return b;
}

/* Breakpoints of the maximum vote along the edge u -> v (t from u): the
 * upper envelope of s linear functions.  Intervals shorter than `snap` are
 * merged into their neighbours, and breakpoints closer than `snap` to an
 * end move onto that vertex (the seam then passes through it, no sliver).
 * Out: *first = label at u; t[i], lab[i] (i < return value): breakpoints
 * strictly inside (0, 1) and the label after each. */
static int edge_breaks(const double *pu, const double *pv, int s, int lu, int lv, double snap,
                       int *first, double *t, int *lab)
{
    int n = 0, c = lu;
    double tc = 0;
    for (int guard = 0; guard < 2 * s + 2; guard++) {
        double sc = pv[c] - pu[c], best = INFINITY, bslope = -INFINITY;
        int bj = -1;
        for (int j = 0; j < s; j++) {
            if (j == c) continue;
            double sj = pv[j] - pu[j];
            if (!(sj > sc)) continue;
            double tj = (pu[c] - pu[j]) / (sj - sc);
            if (tj < tc) tj = tc;
            if (tj < best || (tj == best && sj > bslope)) { best = tj; bj = j; bslope = sj; }
        }
        if (bj < 0 || !(best < 1)) break;
        t[n] = best; lab[n] = bj; n++;
        c = bj; tc = best;
    }
    if (c != lv) { t[n] = 1; lab[n] = lv; n++; }   /* a tie at v */
    /* merge interior intervals shorter than snap */
    for (int again = 1; again;) {
        again = 0;
        for (int i = 0; i + 1 < n; i++) {
            if (t[i + 1] - t[i] >= snap) continue;
            int before = i > 0 ? lab[i - 1] : lu, after = lab[i + 1];
            int drop = before == after ? 2 : 1;
            if (drop == 1) { t[i] = 0.5 * (t[i] + t[i + 1]); lab[i] = after; }
            memmove(t + i + 2 - drop, t + i + 2, (n - i - 2) * sizeof *t);
            memmove(lab + i + 2 - drop, lab + i + 2, (n - i - 2) * sizeof *lab);
            n -= drop;
            again = 1;
            break;
        }
    }
    /* near an end: onto the vertex */
    *first = lu;
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (t[i] < snap || t[i] <= 0) { *first = lab[i]; continue; }
        if (t[i] > 1 - snap || t[i] >= 1) break;   /* the rest collapses onto v */
        t[m] = t[i]; lab[m] = lab[i]; m++;
    }
    /* the first kept breakpoint must change the label */
    if (m > 0 && lab[0] == *first) {
        memmove(t, t + 1, (m - 1) * sizeof *t);
        memmove(lab, lab + 1, (m - 1) * sizeof *lab);
        m--;
    }
    return m;
}

/* seam length and summed turning angle of the label boundaries of (V, F, P) */
static void seam_stats(const double *V, const int *F, int nv, int nf, const int *P,
                       double *length, double *turning, int *nseam)
{
    int *rep = malloc(sizeof(int) * (nv ? nv : 1));
    int *Fj = malloc(sizeof(int) * 3 * (nf ? nf : 1));
    if (!rep || !Fj || coincident_find(V, nv, rep) < 0) die("out of memory");
    coincident_faces(F, nf, rep, Fj);
    struct topology t;
    if (topology_build(Fj, nf, nv, &t) < 0) die("%s", cm_errmsg());
    int *deg = calloc(nv + 1, sizeof *deg), *nb = malloc(sizeof(int) * 2 * (nv ? nv : 1));
    double L = 0;
    int ns = 0;
    for (int e = 0; e < t.ne; e++) {
        if (t.EFn[e] != 2 || P[t.EF[2 * e]] == P[t.EF[2 * e + 1]]) continue;
        int a = t.E[2 * e], b = t.E[2 * e + 1];
        L += dist3(V + 3 * a, V + 3 * b);
        ns++;
        if (deg[a] < 2) nb[2 * a + deg[a]] = b;
        if (deg[b] < 2) nb[2 * b + deg[b]] = a;
        deg[a]++; deg[b]++;
    }
    double T = 0;
    for (int v = 0; v < nv; v++) {
        if (deg[v] != 2) continue;
        double d1[3], d2[3];
        sub3(V + 3 * v, V + 3 * nb[2 * v], d1);
        sub3(V + 3 * nb[2 * v + 1], V + 3 * v, d2);
        double n1 = norm3(d1), n2 = norm3(d2);
        if (n1 > 0 && n2 > 0) {
            double c = dot3(d1, d2) / (n1 * n2);
            T += acos(c > 1 ? 1 : c < -1 ? -1 : c);
        }
    }
    *length = L; *turning = T; *nseam = ns;
    topology_free(&t);
    free(rep); free(Fj); free(deg); free(nb);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    double t0 = now_seconds();

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0) die("%s", cm_errmsg());
    int nv = r.nv, nf = r.nf;
    const char *name = r.name;
    int *F = malloc(sizeof(int) * 3 * (nf ? nf : 1));
    if (!F) die("out of memory");
    memcpy(F, r.F, sizeof(int) * 3 * nf);
    int *P, np;
    if (labels_read(o.labels, nf, "faces", 0, 4095, &P, &np) < 0) die("%s", cm_errmsg());
    int s = 1;
    for (int f = 0; f < nf; f++) if (P[f] + 1 > s) s = P[f] + 1;
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) die("%s", cm_errmsg());
    for (int f = 0; f < nf; f++) {
        const int *T = F + 3 * f;
        if (T[0] == T[1] || T[1] == T[2] || T[0] == T[2])
            die("cannot read '%s': face %d repeats a vertex", name, f);
    }
    {   /* a seam through a non-manifold edge has no sides */
        unsigned char *is_seam = malloc(nv + 1);
        seam_vertices(&t, P, is_seam);
        if (seam_check_manifold(&t, is_seam) < 0) die("cannot smooth '%s': %s", name, cm_errmsg());
        free(is_seam);
    }

    /* pass 1: average positions and areas, coincident vertices */
    double *X = malloc(sizeof(double) * 3 * (nv ? nv : 1));
    double *avg = calloc(3 * (size_t)nv + 1, sizeof *avg);
    double *area = calloc((size_t)nf + 1, sizeof *area), *Af = malloc(sizeof(double) * (nf ? nf : 1));
    int *rep = malloc(sizeof(int) * (nv ? nv : 1));
    if (!X || !avg || !area || !Af || !rep) die("out of memory");
    struct mesh_spool sp;
    if (mesh_spool_begin(&sp, o.input, &r) < 0) die("%s", cm_errmsg());
    struct progress pr;
    progress_start(&pr, "seam-smooth: pass 1", r.nframes);
    int n = 0, rc, cut;
    while ((rc = mesh_reader_next(&r, X, &cut)) == 1) {
        n++;
        if (mesh_spool_frame(&sp, X, cut) < 0) die("%s", cm_errmsg());
        if (n == 1) { if (coincident_find(X, nv, rep) < 0) die("out of memory"); }
        else coincident_refine(X, nv, rep);
        for (int i = 0; i < 3 * nv; i++) avg[i] += X[i];
        face_areas(X, F, nf, Af);
        for (int f = 0; f < nf; f++) area[f] += Af[f];
        progress_step(&pr, n);
    }
    progress_end(&pr);
    if (rc < 0) die("%s", cm_errmsg());
    mesh_reader_close(&r);
    for (int i = 0; i < 3 * nv; i++) avg[i] /= n;
    for (int f = 0; f < nf; f++) area[f] /= n;
    double diag = bbox_diagonal(avg, nv);
    double t1 = now_seconds();

    /* votes on the joined mesh (UV-seam duplicates share their votes) */
    int *Fj = malloc(sizeof(int) * 3 * (nf ? nf : 1));
    coincident_faces(F, nf, rep, Fj);
    double *phi = calloc((size_t)nv * s + 1, sizeof *phi), *wsum = calloc((size_t)nv + 1, sizeof *wsum);
    if (!Fj || !phi || !wsum) die("out of memory");
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int v = Fj[3 * f + k];
            phi[(size_t)v * s + P[f]] += area[f];
            wsum[v] += area[f];
        }
    for (int v = 0; v < nv; v++) {
        if (wsum[v] > 0) for (int j = 0; j < s; j++) phi[(size_t)v * s + j] /= wsum[v];
        else if (rep[v] == v) {   /* zero-area fan or isolated: first face's label */
            int lab = 0;
            for (int i = t.VFs[v]; i < t.VFs[v + 1]; i++) { lab = P[t.VF[i]]; break; }
            phi[(size_t)v * s + lab] = 1;
        }
    }
    /* implicit smoothing (M - tau L) phi' = M phi, tau = amount * h^2 */
    int nsmooth = 0;
    double h = 0;
    {
        int ne = 0;
        struct topology tj;
        if (topology_build(Fj, nf, nv, &tj) < 0) die("%s", cm_errmsg());
        for (int e = 0; e < tj.ne; e++) { h += dist3(avg + 3 * tj.E[2 * e], avg + 3 * tj.E[2 * e + 1]); ne++; }
        h = ne ? h / ne : 0;
        topology_free(&tj);
    }
    double tau = o.amount * h * h;
    if (tau > 0 && nf > 0) {
        double *M = malloc(sizeof(double) * (nv ? nv : 1));
        mass_diag(avg, Fj, nv, nf, MASS_VORONOI, M);
        struct triplets T;
        triplets_init(&T, nv, nv);
        cot_laplacian_triplets(avg, Fj, nf, -tau, &T);
        double mmax = 0;
        for (int v = 0; v < nv; v++) if (M[v] > mmax) mmax = M[v];
        for (int v = 0; v < nv; v++) {
            if (!(M[v] > 1e-14 * mmax)) M[v] = mmax > 0 ? mmax : 1;   /* unused vertex: keep */
            triplets_add(&T, v, v, M[v]);
        }
        cholmod_sparse *A = triplets_to_sparse(&T, 0);
        triplets_free(&T);
        struct spd_solver *S = spd_factor(A);
        if (!S) die("cannot smooth '%s': %s", name, cm_errmsg());
        double *B = malloc(sizeof(double) * (size_t)nv * s);
        for (int it = 0; it < o.iterations; it++) {
            for (int v = 0; v < nv; v++)
                for (int j = 0; j < s; j++) B[(size_t)v * s + j] = M[v] * phi[(size_t)v * s + j];
            if (spd_solve(S, B, phi, s) < 0) die("cannot smooth '%s': %s", name, cm_errmsg());
            nsmooth++;
        }
        spd_free(S);
        sparse_free(&A);
        free(B); free(M);
    }
    for (int v = 0; v < nv; v++)     /* duplicates get their representative's votes */
        if (rep[v] != v) memcpy(phi + (size_t)v * s, phi + (size_t)rep[v] * s, sizeof(double) * s);
    /* round the votes to 2^-36: rounding noise must not turn an exact tie
     * (the seam through a vertex, or along an edge) into a crossing */
    for (size_t i = 0; i < (size_t)nv * s; i++) phi[i] = ldexp(nearbyint(ldexp(phi[i], 36)), -36);
    int *lv = malloc(sizeof(int) * (nv ? nv : 1));
    for (int v = 0; v < nv; v++) lv[v] = argmax(phi + (size_t)v * s, s);
    double t2 = now_seconds();

    /* breakpoints per edge (t from E[2e] to E[2e+1]) */
    int *bs = malloc(sizeof(int) * (t.ne + 1)), *efirst = malloc(sizeof(int) * (t.ne + 1));
    struct dvec bt = {0};
    struct ivec bl = {0};
    double *tb = malloc(sizeof(double) * (2 * s + 4));
    int *lb = malloc(sizeof(int) * (2 * s + 4));
    for (int e = 0; e < t.ne; e++) {
        bs[e] = (int)bt.n;
        int a = t.E[2 * e], b = t.E[2 * e + 1];
        int k = edge_breaks(phi + (size_t)a * s, phi + (size_t)b * s, s, lv[a], lv[b], o.snap,
                            &efirst[e], tb, lb);
        for (int i = 0; i < k; i++) { dpush(&bt, tb[i]); ipush(&bl, lb[i]); }
    }
    bs[t.ne] = (int)bt.n;
    int nbp = (int)bt.n;

    /* re-mesh face by face */
    struct ivec Fo = {0}, Po = {0};
    struct ivec cf = {0};          /* centre vertices: parent face */
    struct dvec cw = {0};          /* and barycentric weights (3 each) */
    int maxb = 3 + 3 * (2 * s + 4);
    int *pv = malloc(sizeof(int) * maxb), *pl = malloc(sizeof(int) * maxb);
    double *pw = malloc(sizeof(double) * 3 * maxb);
    int nsplit = 0, ncentre = 0;
    for (int f = 0; f < nf; f++) {
        const int *T = F + 3 * f;
        int m = 0;
        for (int c = 0; c < 3; c++) {
            int a = T[c], b = T[(c + 1) % 3], e = t.FE[3 * f + c];
            int fwd = t.E[2 * e] == a;
            int k = bs[e + 1] - bs[e];
            /* label of the arc leaving corner a along this edge */
            pv[m] = a; pl[m] = fwd ? efirst[e] : (k ? bl.x[bs[e + 1] - 1] : efirst[e]);
            for (int q = 0; q < 3; q++) pw[3 * m + q] = q == c;
            m++;
            for (int i = 0; i < k; i++) {
                int idx = fwd ? bs[e] + i : bs[e + 1] - 1 - i;
                double tt = fwd ? bt.x[idx] : 1 - bt.x[idx];
                /* label after this point, walking a -> b */
                int after = fwd ? bl.x[idx] : (idx > bs[e] ? bl.x[idx - 1] : efirst[e]);
                pv[m] = nv + idx; pl[m] = after;
                for (int q = 0; q < 3; q++) pw[3 * m + q] = 0;
                pw[3 * m + c] = 1 - tt; pw[3 * m + (c + 1) % 3] = tt;
                m++;
            }
            (void)b;
        }
        /* pl[i] = label of the arc from point i to point i+1 */
        int tr[64], R = 0;
        for (int i = 0; i < m; i++)
            if (pl[(i + m - 1) % m] != pl[i] && R < 64) tr[R++] = i;
        if (R == 0) {
            for (int q = 0; q < 3; q++) ipush(&Fo, T[q]);
            ipush(&Po, pl[0]);
            continue;
        }
        nsplit++;
        if (R == 2) {      /* one straight cut: two convex polygons */
            for (int side = 0; side < 2; side++) {
                int i0 = tr[side], i1 = tr[1 - side], lab = pl[i0];
                int cnt = (i1 - i0 + m) % m + 1, q[16];
                for (int k = 0; k < cnt && k < 16; k++) q[k] = (i0 + k) % m;
                if (cnt == 4) {   /* quad: the diagonal with the better smallest angle */
                    double best = -1; int d = 0;
                    for (int dd = 0; dd < 2; dd++) {
                        double worst = 1e300;
                        for (int tri = 0; tri < 2; tri++) {
                            int A = q[dd], B = q[(dd + 1 + tri) % 4], C = q[(dd + 2 + tri) % 4];
                            double P3[3][3];
                            int id[3] = {A, B, C};
                            for (int z = 0; z < 3; z++)
                                for (int k = 0; k < 3; k++)
                                    P3[z][k] = pw[3 * id[z]] * avg[3 * T[0] + k] + pw[3 * id[z] + 1] * avg[3 * T[1] + k] +
                                               pw[3 * id[z] + 2] * avg[3 * T[2] + k];
                            for (int z = 0; z < 3; z++) {
                                double u[3], w[3];
                                sub3(P3[(z + 1) % 3], P3[z], u); sub3(P3[(z + 2) % 3], P3[z], w);
                                double nu = norm3(u), nw = norm3(w);
                                double ang = nu > 0 && nw > 0 ? acos(fmax(-1, fmin(1, dot3(u, w) / (nu * nw)))) : 0;
                                if (ang < worst) worst = ang;
                            }
                        }
                        if (worst > best) { best = worst; d = dd; }
                    }
                    int A = q[d], B = q[(d + 1) % 4], C = q[(d + 2) % 4], D = q[(d + 3) % 4];
                    ipush(&Fo, pv[A]); ipush(&Fo, pv[B]); ipush(&Fo, pv[C]); ipush(&Po, lab);
                    ipush(&Fo, pv[A]); ipush(&Fo, pv[C]); ipush(&Fo, pv[D]); ipush(&Po, lab);
                } else
                    for (int k = 1; k + 1 < cnt; k++) {
                        ipush(&Fo, pv[q[0]]); ipush(&Fo, pv[q[k]]); ipush(&Fo, pv[q[k + 1]]);
                        ipush(&Po, lab);
                    }
            }
            continue;
        }
        /* three or more runs: a centre vertex, fans around it */
        double w[3] = {0, 0, 0};
        int labs[3], nl = 0, ok = 0;
        for (int i = 0; i < R && nl < 4; i++) {
            int l = pl[tr[i]], seen = 0;
            for (int k = 0; k < nl && k < 3; k++) seen |= labs[k] == l;
            if (!seen) { if (nl < 3) labs[nl] = l; nl++; }
        }
        if (nl == 3) {     /* the triple point phi_j = phi_k = phi_l, if inside */
            const double *pa = phi + (size_t)T[0] * s, *pb = phi + (size_t)T[1] * s, *pc = phi + (size_t)T[2] * s;
            int j = labs[0], k = labs[1], l = labs[2];
            /* g(w) = pa + w1 (pb - pa) + w2 (pc - pa); g_j - g_k = 0, g_j - g_l = 0 */
            double a11 = (pb[j] - pa[j]) - (pb[k] - pa[k]), a12 = (pc[j] - pa[j]) - (pc[k] - pa[k]);
            double a21 = (pb[j] - pa[j]) - (pb[l] - pa[l]), a22 = (pc[j] - pa[j]) - (pc[l] - pa[l]);
            double b1 = pa[k] - pa[j], b2 = pa[l] - pa[j], det = a11 * a22 - a12 * a21;
            if (fabs(det) > 1e-300) {
                double w1 = (b1 * a22 - a12 * b2) / det, w2 = (a11 * b2 - a21 * b1) / det;
                double lim = o.snap > 0 ? o.snap / 2 : 1e-6;
                if (w1 >= lim && w2 >= lim && 1 - w1 - w2 >= lim) {
                    w[0] = 1 - w1 - w2; w[1] = w1; w[2] = w2;
                    ok = 1;
                }
            }
        }
        if (!ok) {         /* centroid of the transition points */
            for (int i = 0; i < R; i++)
                for (int q = 0; q < 3; q++) w[q] += pw[3 * tr[i] + q] / R;
            /* keep it off the triangle's edges */
            for (int q = 0; q < 3; q++) w[q] = 0.8 * w[q] + 0.2 / 3;
        }
        int cv = nv + nbp + (int)cf.n;
        ipush(&cf, f);
        for (int q = 0; q < 3; q++) dpush(&cw, w[q]);
        ncentre++;
        for (int i = 0; i < m; i++) {
            ipush(&Fo, cv); ipush(&Fo, pv[i]); ipush(&Fo, pv[(i + 1) % m]);
            ipush(&Po, pl[i]);
        }
    }
    int nvo = nv + nbp + (int)cf.n, nfo = (int)(Po.n);
    double t3 = now_seconds();

    /* output vertices as combinations of input vertices */
    int *mi = malloc(sizeof(int) * 3 * (size_t)nvo);
    double *mw = malloc(sizeof(double) * 3 * (size_t)nvo);
    if (!mi || !mw) die("out of memory");
    for (int v = 0; v < nv; v++) { mi[3 * v] = mi[3 * v + 1] = mi[3 * v + 2] = v; mw[3 * v] = 1; mw[3 * v + 1] = mw[3 * v + 2] = 0; }
    for (int e = 0; e < t.ne; e++)
        for (int i = bs[e]; i < bs[e + 1]; i++) {
            int v = nv + i;
            mi[3 * v] = t.E[2 * e]; mi[3 * v + 1] = mi[3 * v + 2] = t.E[2 * e + 1];
            mw[3 * v] = 1 - bt.x[i]; mw[3 * v + 1] = bt.x[i]; mw[3 * v + 2] = 0;
        }
    for (size_t c = 0; c < cf.n; c++) {
        int v = nv + nbp + (int)c;
        for (int q = 0; q < 3; q++) { mi[3 * v + q] = F[3 * cf.x[c] + q]; mw[3 * v + q] = cw.x[3 * c + q]; }
    }

    if (verbose) {
        double *Ao = malloc(sizeof(double) * 3 * (size_t)nvo);
        for (int v = 0; v < nvo; v++)
            for (int k = 0; k < 3; k++)
                Ao[3 * v + k] = mw[3 * v] * avg[3 * mi[3 * v] + k] + mw[3 * v + 1] * avg[3 * mi[3 * v + 1] + k] +
                                mw[3 * v + 2] * avg[3 * mi[3 * v + 2] + k];
        double L0, T0, L1, T1;
        int n0, n1;
        seam_stats(avg, F, nv, nf, P, &L0, &T0, &n0);
        seam_stats(Ao, Fo.x, nvo, nfo, Po.x, &L1, &T1, &n1);
        free(Ao);
        info(1, "%d parts, %d frames; smoothing: %d step(s) of time %g (%g mean edge lengths squared)",
             s, n, nsmooth, tau, o.amount);
        info(1, "seam length %.6g -> %.6g (ratio %.4f, in bbox diagonals %.6g -> %.6g)", L0, L1,
             L0 > 0 ? L1 / L0 : 1, L0 / diag, L1 / diag);
        info(1, "summed turning angle %.4f -> %.4f rad (ratio %.4f), seam edges %d -> %d", T0, T1,
             T0 > 0 ? T1 / T0 : 1, n0, n1);
        info(1, "%d -> %d vertices (%d on edges, %d triangle centres), %d -> %d triangles (%d split)",
             nv, nvo, nbp, ncentre, nf, nfo, nsplit);
        int *c0 = calloc(s, sizeof *c0), *c1 = calloc(s, sizeof *c1);
        for (int f = 0; f < nf; f++) c0[P[f]]++;
        for (int f = 0; f < nfo; f++) c1[Po.x[f]]++;
        for (int j = 0; j < s; j++) {
            info(1, "part %d: %d -> %d triangles", j, c0[j], c1[j]);
            if (c0[j] && !c1[j]) warn("part %d vanished in the smoothing (lower --amount)", j);
        }
        free(c0); free(c1);
    }

    /* outputs: labels and map first (small), then stream the frames */
    FILE *lf = out_open(o.labels_out);
    if (labels_write(lf, Po.x, nfo) < 0) die("cannot write '%s': %s", o.labels_out, cm_errmsg());
    if (o.map) {
        FILE *mf = out_open(o.map);
        for (int v = 0; v < nvo; v++)
            fprintf(mf, "%d %d %d %.17g %.17g %.17g\n", mi[3 * v], mi[3 * v + 1], mi[3 * v + 2],
                    mw[3 * v], mw[3 * v + 1], mw[3 * v + 2]);
        out_close(mf);
    }
    struct mesh_reader r2;
    if (mesh_spool_rewind(&sp, &r2) < 0) die("%s", cm_errmsg());
    FILE *out = out_open(o.output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, nvo, nfo, Fo.x, n, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    double *Y = malloc(sizeof(double) * 3 * (size_t)nvo);
    progress_start(&pr, "seam-smooth: pass 2", n);
    int k = 0;
    while ((rc = mesh_reader_next(&r2, X, &cut)) == 1) {
        memcpy(Y, X, sizeof(double) * 3 * nv);
        for (int v = nv; v < nvo; v++)
            for (int c = 0; c < 3; c++)
                Y[3 * v + c] = mw[3 * v] * X[3 * mi[3 * v] + c] + mw[3 * v + 1] * X[3 * mi[3 * v + 1] + c] +
                               mw[3 * v + 2] * X[3 * mi[3 * v + 2] + c];
        if (mesh_writer_frame(&w, Y, cut) < 0) die("cannot write output: %s", cm_errmsg());
        progress_step(&pr, ++k);
    }
    progress_end(&pr);
    if (rc < 0) die("%s", cm_errmsg());
    if (mesh_writer_close(&w) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    out_close(lf);
    mesh_reader_close(&r2);
    mesh_spool_free(&sp);
    double t4 = now_seconds();
    info(1, "time: pass 1 %.3f s, votes %.3f s, re-mesh %.3f s, pass 2 %.3f s, total %.3f s",
         t1 - t0, t2 - t1, t3 - t2, t4 - t3, t4 - t0);
    free(X); free(Y); free(avg); free(area); free(Af); free(rep); free(Fj); free(phi); free(wsum);
    free(lv); free(bs); free(efirst); free(bt.x); free(bl.x); free(tb); free(lb); free(Fo.x); free(Po.x);
    free(cf.x); free(cw.x); free(pv); free(pl); free(pw); free(mi); free(mw); free(P); free(F);
    topology_free(&t);
    return 0;
}
