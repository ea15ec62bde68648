/* compat-tri -- N-way compatible triangulation of outlines (Baxter, Barla,
 * Anjyo, N-way morphing, Sec. 3.1): N ring files + correspondence points ->
 * one MESH animation of N frames sharing one face list.
 */
#include "compat_tri.h"
#include "compat_refine.h"
#include "columns.h"
#include "mesh.h"
#include "rings.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <getopt.h>

static const char help[] =
"Usage: compat-tri -c CORR [options] SHAPE0 SHAPE1 ...\n"
"Compatible triangulation of N outlines (ring files, one outer ring each):\n"
"one MESH stream of N frames with one face list, frame i = shape i.\n"
"\n"
"  -c, --corr FILE       correspondence points: one row per point, N columns,\n"
"                        column i = vertex index (0-based) in SHAPEi's ring;\n"
"                        at least 3 rows, in the same order along every outline\n"
"  -e, --error E         outline tolerance: two-sided Hausdorff distance of\n"
"                        the simplified to the input outline, as a fraction\n"
"                        of each pose's bounding-box diagonal (default 0.005;\n"
"                        0: keep every input point)\n"
"  -l, --edge-length L   --refine none: refine interior edges to L times the\n"
"                        mean boundary edge length (default 3; 0: none)\n"
"  -s, --smooth N        --refine none: smoothing + flip rounds (default 10)\n"
"      --refine MODE     'auto' (default: both of the next two, keeps the\n"
"                        better worst angle), 'refine' (compatible refinement\n"
"                        of the compatible triangulation, Surazhsky-Gotsman:\n"
"                        edge splits in all poses, compatible flips, per-pose\n"
"                        smoothing, until every angle of every pose reaches\n"
"                        --min-angle or --max-vertices is reached), 'remesh'\n"
"                        (a pose's outline meshed alone, carried to the other\n"
"                        poses by ARAP with the outline fixed, then 'refine';\n"
"                        if a triangle stays inverted from every reference\n"
"                        pose, says so and does 'refine') or 'none' (the\n"
"                        edge-length refinement of -l and -s)\n"
"                        (auto tries poses 0 and 1 as the reference)\n"
"  -a, --min-angle DEG   goal of --refine (default 20)\n"
"      --size H          --refine remesh: no edge of the reference mesh longer\n"
"                        than H times the bounding-box diagonal (default\n"
"                        0.05; 0: angle goal only)\n"
"      --max-vertices K  --refine stops splitting at K vertices\n"
"                        (default 10 times the boundary vertex count)\n"
"      --split MODE      pieces that no common diagonal or single Steiner point\n"
"                        splits: 'overlay' (default: overlay of the shapes'\n"
"                        triangulations, always succeeds) or 'linkpath' (the\n"
"                        paper's Steiner paths; can fail on thin pieces)\n"
"      --raw             raw (binary) MESH output (or STOPMO_RAW=1)\n"
"  -o, --output FILE     write to FILE (temporary + rename)\n"
"  -v, --verbose         print counts, Steiner points, minimum angle, time\n"
"  -h, --help, --version\n"
"\n"
"Example: compat-tri -v -c corr.txt pose1.rings pose2.rings | mesh2svg -g >t.svg\n";

enum { REFINE_NONE, REFINE_REFINE, REFINE_REMESH, REFINE_AUTO };

struct options {
    const char *corr, *output;
    double err, edge;
    int smooth, raw, split, refine, max_nv;
    double min_angle, size;
    int nshapes;
    char **shapes;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"corr", 1, 0, 'c'}, {"error", 1, 0, 'e'}, {"edge-length", 1, 0, 'l'},
        {"smooth", 1, 0, 's'}, {"split", 1, 0, 'S'}, {"refine", 1, 0, 'Q'}, {"min-angle", 1, 0, 'a'},
        {"max-vertices", 1, 0, 'K'}, {"size", 1, 0, 'z'}, {"raw", 0, 0, 'R'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->err = 0.005; o->edge = 3; o->smooth = 10; o->refine = REFINE_AUTO; o->min_angle = 20; o->size = 0.05;
    int c;
    while ((c = getopt_long(argc, argv, "c:e:l:s:a:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'c': o->corr = optarg; break;
        case 'e': o->err = arg_double(optarg, "--error"); break;
        case 'l': o->edge = arg_double(optarg, "--edge-length"); break;
        case 's': o->smooth = arg_int(optarg, "--smooth"); break;
        case 'S':
            if (!strcmp(optarg, "overlay")) o->split = COMPAT_OVERLAY;
            else if (!strcmp(optarg, "linkpath")) o->split = COMPAT_LINKPATH;
            else usage_error("--split must be 'overlay' or 'linkpath'");
            break;
        case 'Q':
            if (!strcmp(optarg, "remesh")) o->refine = REFINE_REMESH;
            else if (!strcmp(optarg, "refine")) o->refine = REFINE_REFINE;
            else if (!strcmp(optarg, "none")) o->refine = REFINE_NONE;
            else if (!strcmp(optarg, "auto")) o->refine = REFINE_AUTO;
            else usage_error("--refine must be 'auto', 'remesh', 'refine' or 'none'");
            break;
        case 'a': o->min_angle = arg_double(optarg, "--min-angle"); break;
        case 'z': o->size = arg_double(optarg, "--size"); break;
        case 'K': o->max_nv = arg_int(optarg, "--max-vertices"); break;
        case 'R': o->raw = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!o->corr) usage_error("-c CORR (correspondence points) is required");
    if (!(o->err >= 0 && o->err < 1)) usage_error("--error must be in [0, 1)");
    if (!(o->edge >= 0 && o->edge < 1e6)) usage_error("--edge-length must be >= 0");
    if (o->smooth < 0 || o->smooth > 10000) usage_error("--smooth must be in 0..10000");
    if (!(o->min_angle > 0 && o->min_angle <= 60)) usage_error("--min-angle must be in (0, 60] degrees");
    if (o->max_nv < 0) usage_error("--max-vertices must be >= 0");
    if (!(o->size >= 0 && o->size <= 1)) usage_error("--size must be in [0, 1]");
    o->nshapes = argc - optind;
    o->shapes = argv + optind;
    if (o->nshapes < 1) usage_error("expected at least one SHAPE file");
    for (int i = 0; i < o->nshapes; i++)
        if (!strcmp(o->shapes[i], "-") && o->nshapes > 1)
            usage_error("stdin can be only the single shape");
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    int N = o.nshapes;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);

    /* read and check every outline */
    struct rings *R = calloc(N, sizeof *R);
    double **P = malloc(N * sizeof *P);
    int *n = malloc(N * sizeof *n), *flipped = calloc(N, sizeof *flipped);
    for (int s = 0; s < N; s++) {
        if (rings_read(o.shapes[s], &R[s]) < 0) die("%s", cm_errmsg());
        for (int k = 0; k < R[s].nrings; k++)
            if (rings_degenerate(&R[s], k))
                die("cannot read '%s': line %ld: degenerate outline (ring %d encloses no area)", R[s].name,
                    R[s].line[R[s].start[k]] - 1, k + 1);
        if (rings_check_simple(&R[s]) < 0) die("%s", cm_errmsg());
        if (R[s].nrings != 1)
            die("cannot read '%s': line %ld: %d rings; compat-tri needs one simple outer outline "
                "(holes and pieces are not supported)", R[s].name, R[s].line[R[s].start[1]], R[s].nrings);
        flipped[s] = rings_orient(&R[s]);
        P[s] = R[s].P;
        n[s] = rings_count(&R[s], 0);
        if (flipped[s]) info(1, "%s: clockwise outline reversed (indices refer to the file order)", R[s].name);
    }
    /* correspondences: rows by N columns of integer indices */
    struct columns C;
    if (columns_read(o.corr, 0, -1, NULL, &C) < 0) die("%s", cm_errmsg());
    if (C.cols != N)
        die("cannot read '%s': line 1: %d columns, but there are %d shapes", o.corr, C.cols, N);
    if (C.rows < 3)
        die("cannot read '%s': %d correspondence point%s; at least 3 are needed to match the outlines",
            o.corr, C.rows, C.rows == 1 ? "" : "s");
    int *corr = malloc((size_t)C.rows * N * sizeof *corr);
    for (int k = 0; k < C.rows; k++)
        for (int s = 0; s < N; s++) {
            double x = C.x[(size_t)k * N + s];
            if (x != floor(x) || x < 0 || x >= n[s])
                die("cannot read '%s': row %d: '%g' is not a vertex index of '%s' (0..%d)", o.corr, k + 1,
                    x, o.shapes[s], n[s] - 1);
            int v = (int)x;
            corr[(size_t)k * N + s] = flipped[s] ? n[s] - 1 - v : v;
        }
    /* rows given along a clockwise file order run backwards after reversal */
    if (flipped[0]) {
        for (int a = 0, b = C.rows - 1; a < b; a++, b--)
            for (int s = 0; s < N; s++) {
                int t = corr[(size_t)a * N + s];
                corr[(size_t)a * N + s] = corr[(size_t)b * N + s];
                corr[(size_t)b * N + s] = t;
            }
    }

    struct compat cp;
    unsigned char *keep = NULL;
    int rev = compat_corr_order(N, n, corr, C.rows);
    if (rev < 0) die("cannot read '%s': %s", o.corr, cm_errmsg());
    if (rev) info(1, "%s: points run clockwise along the outlines; using them in reverse order", o.corr);
    if (compat_match(N, P, n, corr, C.rows, &cp, &keep) < 0)
        die("cannot read '%s': %s", o.corr, cm_errmsg());
    int M = cp.nb;
    cp.split_mode = o.split;
    compat_simplify(&cp, o.err, keep);
    /* the outline actually kept, against the input rings */
    double hmax = 0;
    int hs = 0;
    for (int s = 0; s < N; s++) {
        double h = compat_outline_error(&cp, s, P[s], n[s]);
        if (h > hmax) { hmax = h; hs = s; }
    }
    info(1, "boundary: %d matched points, %d after simplification (tolerance %g of the diagonal; "
            "largest two-sided Hausdorff distance %.3g, in %s)", M, cp.nb, o.err, hmax, o.shapes[hs]);
    struct compat_refine_params pa = {o.min_angle * M_PI / 180, o.size, o.max_nv ? o.max_nv : 10 * cp.nb, 200};
    int remeshed = 0;
    struct compat_refine_stats rs;
    struct compat rm;   /* the remeshed result (--refine remesh, auto) */
    memset(&rm, 0, sizeof rm);
    if (o.refine == REFINE_REMESH || o.refine == REFINE_AUTO) {
        /* auto tries the first two poses as the reference, remesh every pose */
        int nref = o.refine == REFINE_AUTO && N > 2 ? 2 : N;
        for (int r = 0; r < nref && !remeshed; r++) {
            if (compat_copy(&cp, &rm) < 0) die("%s", cm_errmsg());
            remeshed = compat_remesh(&rm, r, &pa, &rs);
            if (remeshed < 0) die("%s", cm_errmsg());
            if (remeshed)
                info(1, "remeshed by transfer from %s: %d rounds, %d interior and %d boundary splits, %d flips, "
                        "%d moves; min angle %.2f deg", o.shapes[r], rs.rounds, rs.splits, rs.bsplits, rs.flips,
                     rs.moves, compat_min_angle(&rm, NULL) * 180 / M_PI);
            else compat_free(&rm);
        }
        if (!remeshed)
            info(1, "remeshing by transfer left inverted triangles from %s: "
                    "refining the compatible triangulation instead", nref < N ? "poses 0 and 1 as the reference" : "every reference pose");
    }
    pa.size = 0;   /* the size bound is for the reference mesh only */
    if (remeshed && o.refine == REFINE_REMESH) { compat_free(&cp); cp = rm; memset(&rm, 0, sizeof rm); }
    else remeshed = 0;
    if (!remeshed) {
        if (compat_triangulate(&cp) < 0) die("%s", cm_errmsg());
        double ma0, q0 = compat_min_angle(&cp, &ma0);
        info(1, "triangulation: %d triangles, %d Steiner points (splits: %d stage I, %d stage II, %d %s), "
                "min angle %.2f deg", cp.nf, cp.nsteiner, cp.stage_count[0], cp.stage_count[1],
             cp.stage_count[2], o.split == COMPAT_OVERLAY ? "overlays" : "stage III", q0 * 180 / M_PI);
    }
    if (!remeshed && o.refine == REFINE_NONE) {
        /* target edge length: mean boundary edge, relative to each shape's diagonal */
        double target = 0;
        if (o.edge > 0) {
            for (int s = 0; s < N; s++) {
                double L = 0, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
                for (int i = 0; i < cp.nb; i++) {
                    int j = (i + 1) % cp.nb;
                    L += hypot(cp.X[s][2 * j] - cp.X[s][2 * i], cp.X[s][2 * j + 1] - cp.X[s][2 * i + 1]);
                    for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], cp.X[s][2 * i + d]); hi[d] = fmax(hi[d], cp.X[s][2 * i + d]); }
                }
                target += L / cp.nb / hypot(hi[0] - lo[0], hi[1] - lo[1]);
            }
            target = o.edge * target / N;
        }
        if (compat_improve(&cp, target, o.smooth) < 0) die("%s", cm_errmsg());
    } else if (!remeshed) {
        double q1 = compat_min_angle(&cp, NULL);
        if (compat_refine(&cp, &pa, &rs) < 0) die("%s", cm_errmsg());
        info(1, "refinement: %d rounds, %d interior and %d boundary splits, %d flips, %d moves; "
                "min angle %.2f -> %.2f deg%s", rs.rounds, rs.splits, rs.bsplits, rs.flips, rs.moves,
             q1 * 180 / M_PI, compat_min_angle(&cp, NULL) * 180 / M_PI, rs.kept_input ? " (worse: input kept)" : "");
    }
    if (rm.N) {   /* auto: the better of remeshing and refinement */
        double qr = compat_min_angle(&rm, NULL), qc = compat_min_angle(&cp, NULL);
        info(1, "kept the %s (min angle %.2f deg; the other %.2f deg)", qr > qc ? "remeshed mesh" : "refined mesh",
             fmax(qr, qc) * 180 / M_PI, fmin(qr, qc) * 180 / M_PI);
        if (qr > qc) { struct compat x = cp; cp = rm; rm = x; }
        compat_free(&rm);
    }
    if (o.refine != REFINE_NONE)
        info(1, "sharpest outline corner %.2f deg", compat_sharpest_corner(&cp) * 180 / M_PI);
    for (int s = 0; verbose && s < N; s++) {
        double mn, u10, u20;
        compat_pose_quality(&cp, s, &mn, &u10, &u20);
        info(1, "pose %d (%s): worst angle %.2f deg, %.1f%% of triangles under 10 deg, %.1f%% under 20, "
                "%d vertices, %d triangles", s, o.shapes[s], mn * 180 / M_PI, 100 * u10, 100 * u20, cp.nv, cp.nf);
    }
    double minarea, q = compat_min_angle(&cp, &minarea);
    if (!(minarea > 0))
        die("compatible triangulation failed: a triangle is inverted or degenerate in some shape");
    struct timespec t1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    info(1, "result: %d vertices (%d boundary, %d Steiner, %d refinement), %d triangles, "
            "min angle %.2f deg over %d shapes, %.3f s", cp.nv, cp.nb, cp.nsteiner, cp.nrefine, cp.nf,
         q * 180 / M_PI, N, (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec));

    struct mesh m;
    if (mesh_alloc(&m, cp.nv, cp.nf, N) < 0) die("%s", cm_errmsg());
    memcpy(m.F, cp.F, 3 * (size_t)cp.nf * sizeof *m.F);
    for (int s = 0; s < N; s++) {
        double *X = mesh_frame(&m, s);
        for (int v = 0; v < cp.nv; v++) { X[3 * v] = cp.X[s][2 * v]; X[3 * v + 1] = cp.X[s][2 * v + 1]; X[3 * v + 2] = 0; }
    }
    FILE *out = out_open(o.output);
    if (mesh_write(out, &m, want_raw(o.raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    mesh_free(&m);
    compat_free(&cp);
    free(keep); free(corr); columns_free(&C);
    for (int s = 0; s < N; s++) rings_free(&R[s]);
    free(R); free(P); free(n); free(flipped);
    return 0;
}
