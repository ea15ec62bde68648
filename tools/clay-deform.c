/* clay-deform -- deform a closed surface toward landmark positions like
 * clay: the Froehlich-Botsch thin shell (stretch, bend, per-face volume,
 * landmarks; Gauss-Newton) or an ARAP shell, weighted by a local stiffness
 * map (E-StopMotion thesis Sec. 4.4, Algorithm 3's first loop).
 */
#include "blas_tune.h"
#include "clay_deform.h"
#include "thin_shell.h"
#include "closest_point.h"
#include "columns.h"
#include "geometry.h"
#include "landmarks.h"
#include "mesh.h"
#include "mesh_distance.h"
#include "progress.h"
#include "topology.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: clay-deform [options] -l LANDMARKS SOURCE [TARGET]\n"
"Deform SOURCE toward the landmark positions in steps, as a thin shell (or\n"
"as-rigid-as-possible) with a local stiffness map, keeping the enclosed\n"
"volume; writes the result.\n"
"\n"
"Options:\n"
"  -l, --landmarks FILE  'src_vertex dst_vertex' (needs TARGET) or 'src_vertex x y z'\n"
"  -k, --stiffness FILE  per-vertex stiffness column (see stiffness(1)); default uniform\n"
"  -n, --steps S         landmark targets move there in S steps (default 10)\n"
"  -m, --model M         shell (Froehlich-Botsch thin shell, Gauss-Newton; the\n"
"                        default) or arap (ARAP shell + volume restoration)\n"
"  -i, --iters N         Gauss-Newton (shell) or local-global (arap) iterations\n"
"                        per step (default 5)\n"
"      --lambda L        landmark weight relative to the shell (default 100)\n"
"      --stretch S       shell: stretch weight (default 1)\n"
"      --bend B          shell: bend weight (default 1)\n"
"      --volume-weight W shell: enclosed-volume weight (default 10)\n"
"      --face-volume W   shell: per-face tetrahedron volume weight (default 0.1)\n"
"      --hausdorff H     stop once the symmetric Hausdorff distance to TARGET is\n"
"                        below H bounding-box diagonals (default 0: run all steps)\n"
"      --no-volume       no volume term / restoration (open meshes need this)\n"
"      --poses FILE      also write the start and the pose after every step\n"
"  -o, --output FILE     write to FILE (atomically) instead of stdout\n"
"      --raw             write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose         per-step energy, volume change and distance; timing\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: stiffness -l marks.txt src.mesh dst.mesh > k.txt &&\n"
"         clay-deform -k k.txt -l marks.txt --poses steps.mesh src.mesh dst.mesh > deformed.mesh\n";

int main(int argc, char **argv)
{
    blas_tune(argv);             /* CHOLMOD's supernodal factorization runs on BLAS */
    blas_single_thread();        /* small supernodes: more threads only spin */
    tool_init(argc, argv);
    enum { O_LAMBDA = 256, O_HAUS, O_NOVOL, O_POSES, O_RAW, O_VERSION, O_KS, O_KB, O_KV, O_KF };
    static const struct option lo[] = {
        {"landmarks", 1, 0, 'l'}, {"stiffness", 1, 0, 'k'}, {"steps", 1, 0, 'n'},
        {"iters", 1, 0, 'i'}, {"lambda", 1, 0, O_LAMBDA}, {"hausdorff", 1, 0, O_HAUS},
        {"no-volume", 0, 0, O_NOVOL}, {"poses", 1, 0, O_POSES}, {"output", 1, 0, 'o'},
        {"raw", 0, 0, O_RAW}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, O_VERSION}, {"model", 1, 0, 'm'}, {"stretch", 1, 0, O_KS},
        {"bend", 1, 0, O_KB}, {"volume-weight", 1, 0, O_KV},
        {"face-volume", 1, 0, O_KF}, {0, 0, 0, 0}};
    struct thin_shell_params sp_;
    thin_shell_defaults(&sp_);
    int shell = 1;
    const char *lmfile = NULL, *kfile = NULL, *poses = NULL, *output = NULL;
    int steps = 10, iters = 5, keepvol = 1, raw = 0, c;
    double lambda = 100, haus = 0;
    while ((c = getopt_long(argc, argv, "l:k:n:i:o:m:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': lmfile = optarg; break;
        case 'k': kfile = optarg; break;
        case 'n': steps = arg_int(optarg, "--steps"); break;
        case 'i': iters = arg_int(optarg, "--iters"); break;
        case O_LAMBDA: lambda = arg_double(optarg, "--lambda"); break;
        case O_HAUS: haus = arg_double(optarg, "--hausdorff"); break;
        case O_NOVOL: keepvol = 0; break;
        case 'm':
            if (!strcmp(optarg, "shell")) shell = 1;
            else if (!strcmp(optarg, "arap")) shell = 0;
            else usage_error("--model must be shell or arap");
            break;
        case O_KS: sp_.ks = arg_double(optarg, "--stretch"); break;
        case O_KB: sp_.kb = arg_double(optarg, "--bend"); break;
        case O_KV: sp_.kvg = arg_double(optarg, "--volume-weight"); break;
        case O_KF: sp_.kv = arg_double(optarg, "--face-volume"); break;
        case O_POSES: poses = optarg; break;
        case 'o': output = optarg; break;
        case O_RAW: raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!lmfile) usage_error("missing -l LANDMARKS");
    if (argc - optind < 1 || argc - optind > 2) usage_error("expected SOURCE [TARGET]");
    if (steps < 1 || iters < 1) usage_error("--steps and --iters must be >= 1");
    if (!(lambda > 0)) usage_error("--lambda must be positive");
    if (haus < 0) usage_error("--hausdorff must be >= 0");
    if (!(sp_.ks >= 0 && sp_.kb >= 0 && sp_.kv >= 0 && sp_.kvg >= 0))
        usage_error("--stretch, --bend, --volume-weight and --face-volume must be >= 0");
    const char *sp = argv[optind], *tp = argc - optind == 2 ? argv[optind + 1] : NULL;
    if (haus > 0 && !tp) usage_error("--hausdorff needs TARGET");
    struct mesh S, T = {0};
    if (mesh_read(sp, &S) < 0) die("%s", cm_errmsg());
    if (tp && mesh_read(tp, &T) < 0) die("%s", cm_errmsg());
    struct landmarks L;
    if (landmarks_read(lmfile, S.nv, tp ? T.V : NULL, T.nv, &L) < 0) die("%s", cm_errmsg());
    double *k = NULL;
    if (kfile) {
        struct columns col;
        if (columns_read(kfile, 1, S.nv, "vertices", &col) < 0) die("%s", cm_errmsg());
        for (int v = 0; v < S.nv; v++)
            if (!(col.x[v] > 0)) die("cannot read '%s': row %d: stiffness must be positive", kfile, v + 1);
        k = col.x;
    }
    if (keepvol) {
        struct topology t;
        if (topology_build(S.F, S.nf, S.nv, &t) < 0) die("%s", cm_errmsg());
        int open = t.nboundary > 0 || t.nnonmanifold > 0;
        int nb = t.nboundary, nn = t.nnonmanifold;
        topology_free(&t);
        if (open)
            die("cannot keep the volume of '%s': the mesh is not closed (%d boundary edges, "
                "%d non-manifold edges); close it (mesh-clean) or use --no-volume", sp, nb, nn);
    }
    double t0 = now_seconds();
    struct clay_deform *cd = NULL;
    struct thin_shell *ts = NULL;
    if (shell) {
        sp_.lambda = lambda;
        if (!keepvol) sp_.kv = sp_.kvg = 0;
        ts = thin_shell_new(S.V, S.F, S.nv, S.nf, k, L.src, L.n, &sp_);
        if (!ts) die("%s", cm_errmsg());
    } else {
        cd = clay_deform_new(S.V, S.F, S.nv, S.nf, k, L.src, L.n, lambda);
        if (!cd) die("%s", cm_errmsg());
    }
    double *En = malloc((size_t)(iters + 1) * sizeof *En), tgn = 0;
    int ngn = 0;
    double *X = malloc((size_t)S.nv * 3 * sizeof *X + 1), *TL = malloc((size_t)L.n * 3 * sizeof *TL + 1);
    memcpy(X, S.V, (size_t)S.nv * 3 * sizeof *X);
    double *frames = poses ? malloc((size_t)(steps + 1) * S.nv * 3 * sizeof *frames) : NULL;
    int nframes = 0;
    if (frames) memcpy(frames + (size_t)nframes++ * S.nv * 3, X, (size_t)S.nv * 3 * sizeof *X);
    struct closest_point_tree *TT = tp ? closest_point_tree_new(T.V, T.nv, T.F, T.nf) : NULL;
    double diag = tp ? bbox_diagonal(T.V, T.nv) : 0, vol0 = mesh_volume(S.V, S.F, S.nf);
    struct progress pr;
    progress_start(&pr, progname, steps);
    for (int s = 1; s <= steps; s++) {
        double a = (double)s / steps;
        for (int l = 0; l < L.n; l++)
            for (int d = 0; d < 3; d++)
                TL[3 * l + d] = (1 - a) * S.V[3 * (size_t)L.src[l] + d] + a * L.P[3 * l + d];
        if (ts) {
            double t1 = now_seconds();
            if (thin_shell_solve(ts, TL, iters, X, En) < 0) die("step %d: %s", s, cm_errmsg());
            tgn += now_seconds() - t1;
            for (int q = 0; q < iters; q++) ngn += En[q + 1] < En[q];
            info(1, "step %d: shell energy %.6g -> %.6g", s, En[0], En[iters]);
        } else if (clay_deform_solve(cd, TL, iters, keepvol, X) < 0)
            die("step %d: %s", s, cm_errmsg());
        if (frames) memcpy(frames + (size_t)nframes++ * S.nv * 3, X, (size_t)S.nv * 3 * sizeof *X);
        double h = -1;
        if (TT && (haus > 0 || verbose)) {
            struct closest_point_tree *TX = closest_point_tree_new(X, S.nv, S.F, S.nf);
            double rms;
            if (TX) symmetric_distance(X, S.nv, S.F, S.nf, TX, T.V, T.nv, T.F, T.nf, TT, &h, &rms);
            closest_point_tree_free(TX);
        }
        if (h >= 0)
            info(1, "step %d: volume %+.4f%%, Hausdorff %.4g%% of the diagonal", s,
                 vol0 != 0 ? 100 * (mesh_volume(X, S.F, S.nf) / vol0 - 1) : 0, 100 * h / diag);
        else
            info(1, "step %d: volume %+.4f%%", s, vol0 != 0 ? 100 * (mesh_volume(X, S.F, S.nf) / vol0 - 1) : 0);
        progress_step(&pr, s);
        if (haus > 0 && h >= 0 && h < haus * diag) { info(1, "Hausdorff threshold reached"); break; }
    }
    progress_end(&pr);
    info(1, "deformed in %.3f s", now_seconds() - t0);
    if (ts && ngn) info(1, "%.4f s per Gauss-Newton iteration (%d faces)", tgn / ngn, S.nf);
    if (poses) {
        FILE *f = out_open(poses);
        struct mesh_writer w;
        if (mesh_writer_open(&w, f, S.nv, S.nf, S.F, nframes, want_raw(raw)) < 0)
            die("cannot write '%s': %s", poses, cm_errmsg());
        for (int q = 0; q < nframes; q++)
            if (mesh_writer_frame(&w, frames + (size_t)q * S.nv * 3, 0) < 0)
                die("cannot write '%s': %s", poses, cm_errmsg());
        if (mesh_writer_close(&w) < 0) die("cannot write '%s': %s", poses, cm_errmsg());
        out_close(f);
    }
    FILE *out = out_open(output);
    struct mesh R = S;
    R.V = X;
    R.nframes = 1;
    if (mesh_write(out, &R, want_raw(raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    closest_point_tree_free(TT);
    clay_deform_free(cd);
    thin_shell_free(ts);
    free(En);
    free(X); free(TL); free(frames); free(k);
    landmarks_free(&L);
    mesh_free(&S);
    mesh_free(&T);
    return 0;
}
