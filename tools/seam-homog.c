/* seam-homog -- make the part seams of an animation the same in every frame
 * (StopShop Sec. 3.2, Eq. 4-9).
 *
 * Seam vertices (incident faces with different part labels) and their
 * one-ring are set to their average over all frames; every other vertex
 * moves by the displacement of least squared-Laplacian energy
 * tr(D^T L^T M^-1 L D) (L, M: cot Laplacian and mass of the average mesh).
 * The free block of Q = L^T M^-1 L is factored once (CHOLMOD) and the
 * frames are solved in small batches and written while streaming.  Two
 * passes: the average, then the solves; a regular file is read twice,
 * anything else (a pipe) is spooled to a temporary raw MESH file first
 * (mesh_spool.h).  UV-seam duplicates (coincident in every frame) are
 * joined for the math and follow their representative.
 */
#include "bilaplacian.h"
#include "blas_tune.h"
#include "cm_error.h"
#include "coincident.h"
#include "columns.h"
#include "geometry.h"
#include "mesh.h"
#include "mesh_spool.h"
#include "progress.h"
#include "rng.h"
#include "seam.h"
#include "spd.h"
#include "tool.h"
#include "topology.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

static const char help[] =
"Usage: seam-homog [options] -l LABELS [file]\n"
"Deform every frame of a MESH animation minimally (squared-Laplacian energy of\n"
"the displacement) so that the part seams given by per-triangle LABELS, and\n"
"their one-ring, are identical in every frame (StopShop Eq. 4-9).\n"
"\n"
"Options:\n"
"  -l, --labels FILE     per-triangle part labels, one integer >= 0 per line\n"
"  -o, --output FILE     write the animation to FILE (default stdout)\n"
"      --rings K         rings of neighbours fixed around the seam (default 1)\n"
"  -m, --model M         band: the correction fades to zero across a band\n"
"                        around the seam; beyond it the input is kept exactly\n"
"                        (default); paper: Eq. 4-9 over the whole part\n"
"  -w, --width W         band width, geodesic, in bbox diagonals of the\n"
"                        average mesh (default from the data: 4 times the\n"
"                        seam's largest excursion, at least 3 mean edges)\n"
"      --report FILE     write 'key value' lines: seam identity, drift of still\n"
"                        vertices (moving < 0.1% of the diagonal in the input),\n"
"                        mean and max change, all relative to the diagonal\n"
"      --mass TYPE       voronoi | barycentric mass matrix (default voronoi)\n"
"      --energy FILE     write the energy tr(D^T Q D) of each frame, one per line\n"
"      --batch K         frames solved together (default 8; memory O(K frames))\n"
"      --no-weld         do not join vertices that share a position in every\n"
"                        frame (UV-seam duplicates; joined by default)\n"
"      --raw             write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose         per-frame energy, factor time and frames/s on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"Debugging:\n"
"      --check N         after each solve, verify that N random perturbations of\n"
"                        the free vertices raise the energy (exit 1 if not)\n"
"      --seed S          seed of the --check perturbations (default 1)\n"
"      --refactor-each-frame  factor the system again for every frame (baseline)\n"
"\n"
"A regular input file is read twice; standard input is spooled to a\n"
"temporary file in $TMPDIR (default /tmp) first.\n"
"\n"
"Example: seam-homog -l labels.txt walk.mesh > homog.mesh\n";

/* Band width from the data (see the man page for the measurements): this
 * many times the seam's largest excursion, at least this many mean edge
 * lengths. */
#define WIDTH_PER_MOTION 4.0
#define WIDTH_EDGES 3.0
/* "still": moving less than this (bbox diagonals) from its average */
#define STILL 0.001

struct options {
    const char *input, *labels, *output, *energy, *report;
    int paper;
    double width;
    int rings, raw, check, refactor, batch, no_weld;
    long seed;
    enum mass_type mass;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"labels", 1, 0, 'l'}, {"output", 1, 0, 'o'}, {"rings", 1, 0, 'r'},
        {"mass", 1, 0, 'M'}, {"energy", 1, 0, 'E'}, {"raw", 0, 0, 'R'},
        {"verbose", 0, 0, 'v'}, {"check", 1, 0, 'C'}, {"seed", 1, 0, 'S'},
        {"refactor-each-frame", 0, 0, 'F'}, {"model", 1, 0, 'm'}, {"width", 1, 0, 'w'},
        {"report", 1, 0, 'P'}, {"batch", 1, 0, 'B'}, {"no-weld", 0, 0, 'W'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'},
        {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->rings = 1;
    o->batch = 8;
    o->seed = 1;
    o->mass = MASS_VORONOI;
    int c;
    while ((c = getopt_long(argc, argv, "l:o:m:w:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': o->labels = optarg; break;
        case 'o': o->output = optarg; break;
        case 'r': o->rings = arg_int(optarg, "--rings"); break;
        case 'M':
            if (!strcmp(optarg, "voronoi")) o->mass = MASS_VORONOI;
            else if (!strcmp(optarg, "barycentric")) o->mass = MASS_BARYCENTRIC;
            else usage_error("--mass: '%s' is not voronoi or barycentric", optarg);
            break;
        case 'E': o->energy = optarg; break;
        case 'P': o->report = optarg; break;
        case 'm':
            if (!strcmp(optarg, "band")) o->paper = 0;
            else if (!strcmp(optarg, "paper")) o->paper = 1;
            else usage_error("--model: '%s' is not band or paper", optarg);
            break;
        case 'w':
            o->width = arg_double(optarg, "--width");
            if (!(o->width > 0) || !isfinite(o->width)) usage_error("--width must be > 0");
            break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'C': o->check = arg_int(optarg, "--check"); break;
        case 'S': o->seed = arg_long(optarg, "--seed"); break;
        case 'F': o->refactor = 1; break;
        case 'W': o->no_weld = 1; break;
        case 'B': o->batch = arg_int(optarg, "--batch"); break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    o->input = arg_labels_and_input(argc, argv, o->labels);
    if (o->rings < 0 || o->rings > 100)
        usage_error("--rings must be in 0..100");
    if (o->batch < 1 || o->batch > 1024)
        usage_error("--batch must be in 1..1024");
    if (o->check < 0)
        usage_error("--check must be >= 0");
    if (o->output && o->energy && !strcmp(o->output, o->energy))
        usage_error("--output and --energy name the same file");
    if (o->output && o->report && !strcmp(o->output, o->report))
        usage_error("--output and --report name the same file");
}

/* process CPU seconds (all threads) */
static double cpu_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* Pass 1: read every frame (validating the whole stream) and sum the
 * positions into S (#V by 3); the spool keeps a copy when the input is not
 * a regular file.  Returns the number of frames. */
static int pass_average(struct mesh_reader *r, struct mesh_spool *sp, double *S, int *rep,
                        double *lo, double *hi)
{
    size_t n3 = (size_t)r->nv * 3;
    double *X = malloc((n3 + 1) * sizeof *X);
    memset(S, 0, n3 * sizeof *S);
    struct progress p;
    progress_start(&p, "seam-homog: average", r->nframes);
    int n = 0, cut, rc;
    while ((rc = mesh_reader_next(r, X, &cut)) > 0) {
        for (size_t i = 0; i < n3; i++) {
            S[i] += X[i];
            if (n == 0 || X[i] < lo[i]) lo[i] = X[i];
            if (n == 0 || X[i] > hi[i]) hi[i] = X[i];
        }
        if (n == 0 ? coincident_find(X, r->nv, rep) < 0 : coincident_refine(X, r->nv, rep) < 0)
            die("out of memory");
        if (mesh_spool_frame(sp, X, cut) < 0)
            die("%s", cm_errmsg());
        progress_step(&p, ++n);
    }
    progress_end(&p);
    if (rc < 0)
        die("%s", cm_errmsg());
    free(X);
    return n;
}

/* The solver of the free block, built from Q and the vertex roles. */
static struct quad_solver *factor(const cholmod_sparse *Q, const unsigned char *role, int nv)
{
    unsigned char *fixed = malloc((size_t)nv + 1);
    for (int v = 0; v < nv; v++) fixed[v] = role[v] != SEAM_FREE;
    struct quad_solver *S = quad_solver_new(Q, fixed);
    free(fixed);
    if (!S)
        die("cannot factor the squared Laplacian of the average mesh: %s", cm_errmsg());
    return S;
}

/* --check: E(D + eps R) >= E(D) for random R on the free vertices.
 * Returns the smallest relative increase seen. */
static double check_minimal(const cholmod_sparse *Q, const double *D, const unsigned char *role,
                            int nv, double E, double scale, int tries, struct rng *g, int frame)
{
    size_t n3 = (size_t)nv * 3;
    double *P = malloc((n3 + 1) * sizeof *P), worst = INFINITY;
    for (int t = 0; t < tries; t++) {
        double eps = scale * pow(10, -(t % 6));      /* 1e-3 .. 1e-8 of the bbox */
        memcpy(P, D, n3 * sizeof *P);
        for (int v = 0; v < nv; v++)
            if (role[v] == SEAM_FREE)
                for (int d = 0; d < 3; d++) P[3 * v + d] += eps * rng_normal(g);
        double Ep = quadratic_energy(Q, P, 3);
        if (!(Ep >= E))
            die("--check: frame %d: a perturbation of size %g lowers the energy from %.17g to %.17g",
                frame, eps, E, Ep);
        double rel = (Ep - E) / (E > 0 ? E : 1);
        if (rel < worst) worst = rel;
    }
    free(P);
    return worst;
}

int main(int argc, char **argv)
{
    blas_tune(argv);            /* CHOLMOD's supernodal kernels are BLAS */
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    /* header, labels, seam: everything checkable before reading frames */
    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    int nv = r.nv, nf = r.nf, *P, np;
    if (labels_read(o.labels, nf, "faces", 0, -1, &P, &np) < 0)
        die("%s", cm_errmsg());
    int *F = malloc(((size_t)nf * 3 + 1) * sizeof *F);
    memcpy(F, r.F, (size_t)nf * 3 * sizeof *F);
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0)
        die("%s", cm_errmsg());
    /* fail fast: a non-manifold edge at a seam stays one after the
     * UV-seam weld below (welding only adds faces around edges) */
    unsigned char *is_seam = malloc((size_t)nv + 1), *role = malloc((size_t)nv + 1);
    seam_vertices(&t, P, is_seam);
    if (seam_check_manifold(&t, is_seam) < 0)
        die("%s", cm_errmsg());

    /* pass 1: average (and validate every frame before writing anything) */
    double t0 = now_seconds(), c0 = cpu_seconds();
    struct mesh_spool sp;
    if (mesh_spool_begin(&sp, o.input, &r) < 0)
        die("%s", cm_errmsg());
    int spool = sp.temp;
    size_t n3 = (size_t)nv * 3;
    double *A = malloc((n3 + 1) * sizeof *A);
    int *rep = malloc(((size_t)nv + 1) * sizeof *rep);
    double *lo = malloc((n3 + 1) * sizeof *lo), *hi = malloc((n3 + 1) * sizeof *hi);
    if (!A || !rep || !lo || !hi) die("out of memory");
    int nframes = pass_average(&r, &sp, A, rep, lo, hi);
    mesh_reader_close(&r);
    for (size_t i = 0; i < n3; i++) A[i] /= nframes;
    double t1 = now_seconds();
    info(1, "pass 1: %d frames averaged in %.3f s%s", nframes, t1 - t0,
         spool ? " (spooled to a temporary file)" : "");

    /* UV-seam duplicates (the same position in every frame) are joined so
     * the seam and the Laplacian cross texture seams; the duplicates follow
     * their representative.  Kept apart if joining breaks manifoldness. */
    int nwelded = 0;
    for (int v = 0; v < nv; v++) nwelded += rep[v] != v;
    int *W = F;                 /* the faces the math works on */
    if (o.no_weld || nwelded == 0) {
        nwelded = 0;
    } else {
        int *Fw = malloc(((size_t)nf * 3 + 1) * sizeof *Fw);
        coincident_faces(F, nf, rep, Fw);
        struct topology tw;
        int built = topology_build(Fw, nf, nv, &tw) == 0, bad = !built;
        for (int f = 0; f < nf && !bad; f++)
            bad = Fw[3 * f] == Fw[3 * f + 1] || Fw[3 * f + 1] == Fw[3 * f + 2] ||
                  Fw[3 * f] == Fw[3 * f + 2];
        if (!bad) bad = tw.nnonmanifold > 0 || nonmanifold_vertices(&tw, Fw) > 0;
        if (bad) {
            info(1, "joining %d coincident vertices would make the mesh non-manifold: not joined",
                 nwelded);
            nwelded = 0;
            free(Fw);
            if (built) topology_free(&tw);
        } else {
            info(1, "joined %d vertices that coincide in every frame (UV seams)", nwelded);
            topology_free(&t);
            t = tw;
            W = Fw;
        }
    }
    int nseam = seam_vertices(&t, P, is_seam);
    if (seam_check_manifold(&t, is_seam) < 0)
        die("%s", cm_errmsg());
    int nfixed = seam_roles(&t, W, is_seam, o.rings, role);
    int nfree = 0;
    for (int v = 0; v < nv; v++) nfree += role[v] == SEAM_FREE;
    double diag = bbox_diagonal(A, nv), width = 0;
    if (!o.paper && nseam > 0) {
        if (o.width > 0) {
            width = o.width * diag;
        } else {
            /* from the data: the seam's largest excursion (the diagonal of
             * a seam vertex's box over all frames) times WIDTH_PER_MOTION,
             * at least WIDTH_EDGES mean edge lengths */
            double m = 0, el = 0;
            for (int v = 0; v < nv; v++)
                if (is_seam[v]) {
                    double b = dist3(lo + 3 * v, hi + 3 * v);
                    if (b > m) m = b;
                }
            for (int e = 0; e < t.ne; e++) el += dist3(A + 3 * t.E[2 * e], A + 3 * t.E[2 * e + 1]);
            el /= t.ne > 0 ? t.ne : 1;
            width = fmax(WIDTH_PER_MOTION * m, WIDTH_EDGES * el);
            info(1, "band width from the data: seam excursion %.3g, mean edge %.3g bbox diagonals",
                 m / diag, el / diag);
        }
        int npin = seam_band(A, W, &t, is_seam, width, role, NULL);
        if (npin < 0)
            die("cannot measure the band around the seam: %s", cm_errmsg());
        nfree -= npin;
        info(1, "band model: width %.3g bbox diagonals; %d vertices beyond it kept as they are",
             width / diag, npin);
    }
    free(lo);
    free(hi);
    info(1, "%d vertices, %d faces: %d seam vertices, %d fixed (%d ring%s), %d free",
         nv, nf, nseam, nfixed, o.rings, o.rings == 1 ? "" : "s", nfree);
    if (nseam == 0)
        warn("the labels have no seam (one part): the animation passes unchanged");

    /* Q = L^T M^-1 L of the average mesh; factor the free block once */
    cholmod_sparse *Q = bilaplacian(A, W, nv, nf, o.mass);
    if (!Q)
        die("%s", cm_errmsg());
    struct quad_solver *S = factor(Q, role, nv);
    double t2 = now_seconds(), c2 = cpu_seconds();
    info(1, "Q = L^T M^-1 L: %zu stored nonzeros; built and factored in %.3f s",
         (size_t)((int *)Q->p)[nv], t2 - t1);

    /* pass 2: solve each frame and stream it out */
    if (mesh_spool_rewind(&sp, &r) < 0)
        die("%s", cm_errmsg());
    if (r.nv != nv || r.nf != nf || memcmp(r.F, F, (size_t)nf * 3 * sizeof *F))
        die("cannot read '%s': the file changed between the two passes", o.input);
    FILE *out = out_open(o.output);
    FILE *ef = o.energy ? out_open(o.energy) : NULL;
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, nv, nf, F, nframes, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    /* frames are solved in batches of B: one pass through the factor for
     * 3B right-hand sides (the solve is memory-bound, so this is nearly B
     * times faster than one frame at a time); memory O(B frames) */
    int B = o.refactor ? 1 : o.batch;
    double *Yb = malloc((n3 * B + 1) * sizeof *Yb), *Db = malloc((n3 * B + 1) * sizeof *Db);
    double *Y = malloc((n3 + 1) * sizeof *Y), *D = malloc((n3 + 1) * sizeof *D);
    int *cuts = malloc(((size_t)B + 1) * sizeof *cuts);
    double scale = 1e-3 * bbox_diagonal(A, nv);
    if (!(scale > 0)) scale = 1e-3;
    struct rng g;
    rng_seed(&g, (uint64_t)o.seed);
    double worst = INFINITY, Esum = 0, Emax = 0;
    /* per vertex: largest input motion from the average, largest change */
    double *motion = calloc(nv + 1, sizeof *motion), *change = calloc(nv + 1, sizeof *change);
    double change_sum = 0, seam_dev = 0;
    if (!motion || !change) die("out of memory");
    struct progress p;
    progress_start(&p, "seam-homog", nframes);
    int k = 0, rc = 1;
    while (rc > 0) {
        int nb = 0;
        while (nb < B && (rc = mesh_reader_next(&r, Yb + n3 * nb, &cuts[nb])) > 0) nb++;
        if (rc < 0)
            die("%s", cm_errmsg());
        if (nb == 0)
            break;
        if (k + nb > nframes)
            die("cannot read '%s': the file changed between the two passes", o.input);
        if (o.refactor) {
            quad_solver_free(S);
            S = factor(Q, role, nv);
        }
        /* D: #V by 3nb; fixed rows: average - frame (Eq. 9); kept rows: 0 */
        for (int v = 0; v < nv; v++)
            for (int b = 0; b < nb; b++)
                for (int d = 0; d < 3; d++)
                    Db[((size_t)v * nb + b) * 3 + d] =
                        role[v] == SEAM_FIXED ? A[3 * v + d] - Yb[n3 * b + 3 * v + d] : 0;
        if (quad_solver_solve(S, NULL, Db, Db, 3 * nb) < 0)
            die("frames %d-%d: %s", k, k + nb - 1, cm_errmsg());
        for (int b = 0; b < nb; b++, k++) {
            for (int v = 0; v < nv; v++)
                for (int d = 0; d < 3; d++) {
                    D[3 * v + d] = Db[((size_t)v * nb + b) * 3 + d];
                    Y[3 * v + d] = Yb[n3 * b + 3 * v + d];
                }
            double E = quadratic_energy(Q, D, 3);
            if (o.check > 0) {
                double wr = check_minimal(Q, D, role, nv, E, scale, o.check, &g, k);
                if (wr < worst) worst = wr;
            }
            /* Z = Y + D, and exactly the average on the fixed vertices */
            for (int v = 0; v < nv; v++)
                for (int d = 0; d < 3; d++)
                    Y[3 * v + d] = role[v] == SEAM_FIXED ? A[3 * v + d] : Y[3 * v + d] + D[3 * v + d];
            if (nwelded)            /* rep[v] <= v: one forward sweep */
                for (int v = 0; v < nv; v++)
                    if (rep[v] != v) memcpy(Y + 3 * v, Y + 3 * rep[v], 3 * sizeof *Y);
            for (int v = 0; v < nv; v++) {
                const double *x = Yb + n3 * b + 3 * v;
                double m = dist3(x, A + 3 * v), c = dist3(x, Y + 3 * v);
                if (m > motion[v]) motion[v] = m;
                if (c > change[v]) change[v] = c;
                change_sum += c;
                if (is_seam[v]) {
                    double sd = dist3(Y + 3 * v, A + 3 * v);
                    if (sd > seam_dev) seam_dev = sd;
                }
            }
            if (mesh_writer_frame(&w, Y, cuts[b]) < 0)
                die("cannot write output: %s", cm_errmsg());
            if (ef) {
                char buf[40];
                snprintf(buf, sizeof buf, "%.17g\n", E);
                fputs(buf, ef);
            }
            info(1, "frame %d: energy %.10g", k, E);
            Esum += E;
            if (E > Emax) Emax = E;
            progress_step(&p, k + 1);
        }
    }
    progress_end(&p);
    if (rc < 0)
        die("%s", cm_errmsg());
    if (k != nframes)
        die("cannot read '%s': the file changed between the two passes", o.input);
    if (mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    if (ef) out_close(ef);
    double t3 = now_seconds(), c3 = cpu_seconds();
    info(1, "energy: mean %.6g, max %.6g", Esum / nframes, Emax);
    {
        int nstill = 0;
        double still_max = 0, cmax = 0, dg = diag > 0 ? diag : 1;
        for (int v = 0; v < nv; v++) {
            if (motion[v] < STILL * dg) {
                nstill++;
                if (change[v] > still_max) still_max = change[v];
            }
            if (change[v] > cmax) cmax = change[v];
        }
        double cmean = change_sum / ((double)nv * nframes) / dg;
        info(1, "change (bbox diagonals): mean %.3g, max %.3g; %d still vertices (input motion < %g): "
             "max change %.3g; seam: largest distance from its average %.3g",
             cmean, cmax / dg, nstill, STILL, still_max / dg, seam_dev / dg);
        if (o.report) {
            FILE *rf = out_open(o.report);
            fprintf(rf, "model %s\nwidth %.17g\nframes %d\nvertices %d\nseam_vertices %d\n"
                    "seam_max_deviation %.17g\nstill_threshold %g\nstill_vertices %d\n"
                    "still_max_change %.17g\nmean_change %.17g\nmax_change %.17g\n",
                    o.paper ? "paper" : "band", width / dg, nframes, nv, nseam,
                    seam_dev / dg, STILL, nstill, still_max / dg, cmean, cmax / dg);
            out_close(rf);
        }
    }
    free(motion);
    free(change);
    if (o.check > 0)
        info(1, "--check: %d perturbations per frame, smallest relative energy increase %.3g",
             o.check, worst);
    info(1, "pass 2: %d frames solved and written in %.3f s (cpu %.3f s): %.2f frames/s, "
         "%.2f frames per cpu second%s", nframes, t3 - t2, c3 - c2,
         nframes / (t3 - t2 > 0 ? t3 - t2 : 1e-9), nframes / (c3 - c2 > 0 ? c3 - c2 : 1e-9),
         o.refactor ? " (refactoring every frame)" : "");
    info(1, "total %.3f s (cpu %.3f s): %.2f frames/s", t3 - t0, c3 - c0,
         nframes / (t3 - t0 > 0 ? t3 - t0 : 1e-9));
    struct rusage ru;
    if (verbose && getrusage(RUSAGE_SELF, &ru) == 0)
        info(1, "peak memory (max resident set): %.1f MB", ru.ru_maxrss / 1024.0);
    mesh_reader_close(&r);
    mesh_spool_free(&sp);
    quad_solver_free(S);
    cholmod_free_sparse(&Q, cm_cholmod());
    topology_free(&t);
    if (W != F) free(W);
    free(rep);
    free(A); free(Y); free(D); free(Yb); free(Db); free(cuts); free(F); free(P); free(is_seam); free(role);
    return 0;
}
