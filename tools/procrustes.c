/* procrustes -- the rigid or similarity transform that best aligns a
 * source mesh to a target: from landmark pairs, or from all vertices when
 * the connectivity matches (Kabsch / Umeyama least squares).
 */
#include "landmarks.h"
#include "mesh.h"
#include "procrustes.h"
#include "tool.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: procrustes [options] SOURCE TARGET\n"
"Least-squares rigid (or similarity) alignment of SOURCE to TARGET.\n"
"Prints the transform x -> s R x + t as three rows 's*R | t' (a 3x4 matrix),\n"
"after comment lines with the scale and the RMS residual; or, with --apply,\n"
"writes SOURCE transformed (every frame) as a MESH stream.\n"
"\n"
"Options:\n"
"  -l, --landmarks FILE  pairs 'src_vertex dst_vertex' or 'src_vertex x y z';\n"
"                        without it, all vertices (same vertex count needed)\n"
"  -s, --scale           allow a uniform scale (similarity)\n"
"  -a, --apply           write the aligned SOURCE instead of the transform\n"
"  -o, --output FILE     write to FILE (atomically) instead of stdout\n"
"      --raw             with --apply: raw MESH output (or STOPMO_RAW=1)\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: procrustes -a -l marks.txt scan-02.mesh scan-01.mesh > scan-02-aligned.mesh\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"landmarks", 1, 0, 'l'}, {"scale", 0, 0, 's'}, {"apply", 0, 0, 'a'},
        {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    const char *lmfile = NULL, *output = NULL;
    int scale = 0, apply = 0, raw = 0, c;
    while ((c = getopt_long(argc, argv, "l:sao:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': lmfile = optarg; break;
        case 's': scale = 1; break;
        case 'a': apply = 1; break;
        case 'o': output = optarg; break;
        case 'R': raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind != 2) usage_error("expected SOURCE and TARGET");
    const char *sp = argv[optind], *tp = argv[optind + 1];
    struct mesh S, T;
    if (mesh_read(sp, &S) < 0) die("%s", cm_errmsg());
    if (mesh_read(tp, &T) < 0) die("%s", cm_errmsg());
    int n;
    double *A, *B;
    if (lmfile) {
        struct landmarks L;
        if (landmarks_read(lmfile, S.nv, T.V, T.nv, &L) < 0) die("%s", cm_errmsg());
        n = L.n;
        A = malloc((size_t)n * 3 * sizeof *A);
        B = malloc((size_t)n * 3 * sizeof *B);
        for (int l = 0; l < n; l++) memcpy(A + 3 * l, S.V + 3 * (size_t)L.src[l], 3 * sizeof *A);
        memcpy(B, L.P, (size_t)n * 3 * sizeof *B);
        landmarks_free(&L);
        if (n < 3) die("cannot align on %d landmark%s: need at least 3", n, n == 1 ? "" : "s");
    } else {
        if (S.nv != T.nv)
            die("cannot align all vertices: '%s' has %d vertices, '%s' %d (give -l LANDMARKS)",
                sp, S.nv, tp, T.nv);
        n = S.nv;
        A = malloc((size_t)n * 3 * sizeof *A);
        B = malloc((size_t)n * 3 * sizeof *B);
        memcpy(A, S.V, (size_t)n * 3 * sizeof *A);
        memcpy(B, T.V, (size_t)n * 3 * sizeof *B);
    }
    double R[9], t[3], s;
    double rms = procrustes(A, B, NULL, n, scale, R, t, &s);
    if (rms < 0) die("%s", cm_errmsg());
    FILE *out = out_open(output);
    if (apply) {
        for (int k = 0; k < S.nframes; k++) similarity_apply(R, t, s, mesh_frame(&S, k), S.nv, mesh_frame(&S, k));
        if (mesh_write(out, &S, want_raw(raw)) < 0) die("cannot write output: %s", cm_errmsg());
    } else {
        fprintf(out, "# procrustes %s on %d points\n# scale %.17g\n# rms %.17g\n",
                scale ? "similarity" : "rigid", n, s, rms);
        for (int r = 0; r < 3; r++)
            fprintf(out, "%.17g %.17g %.17g %.17g\n", s * R[3 * r], s * R[3 * r + 1], s * R[3 * r + 2], t[r]);
    }
    out_close(out);
    free(A); free(B);
    mesh_free(&S); mesh_free(&T);
    return 0;
}
