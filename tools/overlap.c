/* overlap -- how much two aligned closed meshes overlap: the intersection
 * volume over the source volume (CGAL corefinement), and the thesis'
 * deformation scale (Sec. 2.2): small, intermediate or large.
 */
#include "landmarks.h"
#include "mesh.h"
#include "overlap.h"
#include "procrustes.h"
#include "winding.h"
#include "tool.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: overlap [options] SOURCE TARGET\n"
"Print 'overlap R SCALE': R = vol(SOURCE n TARGET) / vol(SOURCE) of two closed,\n"
"aligned meshes, SCALE = small (R >= 0.8), intermediate (>= 0.4) or large.\n"
"\n"
"Options:\n"
"  -l, --landmarks FILE  first align SOURCE rigidly on these pairs (procrustes)\n"
"  -s, --sample N        estimate the volumes on an N^3 grid by winding numbers\n"
"                        instead (robust to self-intersections and small holes)\n"
"  -v, --verbose         also print the volumes\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: overlap -l marks.txt scan-01.mesh scan-05.mesh\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"landmarks", 1, 0, 'l'}, {"sample", 1, 0, 's'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    const char *lmfile = NULL;
    int c, sample = 0;
    while ((c = getopt_long(argc, argv, "l:s:vh", lo, NULL)) != -1) {
        switch (c) {
        case 's': sample = arg_int(optarg, "--sample"); break;
        case 'l': lmfile = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind != 2) usage_error("expected SOURCE and TARGET");
    if (sample < 0 || sample > 1000) usage_error("--sample must be in 1..1000");
    const char *sp = argv[optind], *tp = argv[optind + 1];
    struct mesh S, T;
    if (mesh_read(sp, &S) < 0) die("%s", cm_errmsg());
    if (mesh_read(tp, &T) < 0) die("%s", cm_errmsg());
    if (lmfile) {
        struct landmarks L;
        if (landmarks_read(lmfile, S.nv, T.V, T.nv, &L) < 0) die("%s", cm_errmsg());
        if (L.n < 3) die("cannot align on %d landmarks: need at least 3", L.n);
        double *A = malloc((size_t)L.n * 3 * sizeof *A), R[9], t[3], s;
        for (int l = 0; l < L.n; l++) memcpy(A + 3 * l, S.V + 3 * (size_t)L.src[l], 3 * sizeof *A);
        if (procrustes(A, L.P, NULL, L.n, 0, R, t, &s) < 0) die("%s", cm_errmsg());
        similarity_apply(R, t, s, S.V, S.nv, S.V);
        free(A);
        landmarks_free(&L);
    }
    double r, va, vb = 0, vi;
    if (sample) {
        winding_volumes(S.V, S.nv, S.F, S.nf, T.V, T.F, T.nf, sample, &va, &vi);
        if (!(va > 0)) die("cannot measure the overlap: '%s' encloses no grid point", sp);
        r = vi / va;
    } else if (volume_overlap(S.V, S.nv, S.F, S.nf, T.V, T.nv, T.F, T.nf, &r, &va, &vb, &vi) < 0)
        die("cannot measure the overlap of '%s' and '%s': %s (try --sample)", sp, tp, cm_errmsg());
    printf("overlap %.6g %s\n", r, overlap_scale(r));
    if (verbose) printf("# volume source %.9g intersection %.9g%s\n", va, vi, sample ? " (sampled)" : "");
    if (fflush(stdout) != 0) die("cannot write output");
    mesh_free(&S);
    mesh_free(&T);
    return 0;
}
