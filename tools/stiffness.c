/* stiffness -- the per-vertex stiffness map of a source mesh from its
 * landmarks (E-StopMotion thesis Eq. 4.56-4.59, Algorithm 1), as a column
 * file for clay-deform (and for colouring).
 */
#include "columns.h"
#include "landmarks.h"
#include "mesh.h"
#include "stiffness.h"
#include "tool.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: stiffness [options] -l LANDMARKS SOURCE [TARGET]\n"
"Per-vertex stiffness of SOURCE from the strain of its landmarks: one number\n"
"per vertex (low = soft, moves freely; high = stiff), a column file.\n"
"\n"
"Options:\n"
"  -l, --landmarks FILE   'src_vertex dst_vertex' (needs TARGET) or 'src_vertex x y z'\n"
"      --kmin K           softest value (default 1)\n"
"      --kmax K           stiffest value (default 100)\n"
"      --gamma G          strain exponent (m-1)/m of Eq. 4.56 (default 0.5)\n"
"      --weights KIND     idw (Eq. 4.58) or gauss (Eq. 4.59) (default idw)\n"
"  -q, --exponent Q       weight exponent (default 2)\n"
"      --spread KIND      global (Eq. 4.57) or radial (Algorithm 1) (default radial)\n"
"      --radius R         distance unit in bounding-box diagonals (default 0.1)\n"
"      --geodesic         geodesic distances (CGAL heat method) instead of Euclidean\n"
"      --landmarks-only   print only the landmark stiffnesses (one per landmark)\n"
"  -o, --output FILE      write to FILE (atomically) instead of stdout\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: stiffness --geodesic -l marks.txt src.mesh dst.mesh > k.txt\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    enum { O_KMIN = 256, O_KMAX, O_GAMMA, O_WEIGHTS, O_SPREAD, O_RADIUS, O_GEO, O_LONLY, O_VERSION };
    static const struct option lo[] = {
        {"landmarks", 1, 0, 'l'}, {"kmin", 1, 0, O_KMIN}, {"kmax", 1, 0, O_KMAX},
        {"gamma", 1, 0, O_GAMMA}, {"weights", 1, 0, O_WEIGHTS}, {"exponent", 1, 0, 'q'},
        {"spread", 1, 0, O_SPREAD}, {"radius", 1, 0, O_RADIUS}, {"geodesic", 0, 0, O_GEO},
        {"landmarks-only", 0, 0, O_LONLY}, {"output", 1, 0, 'o'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, O_VERSION}, {0, 0, 0, 0}};
    struct stiffness_params p;
    stiffness_defaults(&p);
    const char *lmfile = NULL, *output = NULL;
    int lonly = 0, c;
    while ((c = getopt_long(argc, argv, "l:q:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': lmfile = optarg; break;
        case O_KMIN: p.kmin = arg_double(optarg, "--kmin"); break;
        case O_KMAX: p.kmax = arg_double(optarg, "--kmax"); break;
        case O_GAMMA: p.gamma = arg_double(optarg, "--gamma"); break;
        case O_WEIGHTS:
            if (!strcmp(optarg, "idw")) p.weight = STIFF_IDW;
            else if (!strcmp(optarg, "gauss")) p.weight = STIFF_GAUSS;
            else usage_error("--weights must be idw or gauss");
            break;
        case 'q': p.q = arg_double(optarg, "--exponent"); break;
        case O_SPREAD:
            if (!strcmp(optarg, "global")) p.spread = STIFF_GLOBAL;
            else if (!strcmp(optarg, "radial")) p.spread = STIFF_RADIAL;
            else usage_error("--spread must be global or radial");
            break;
        case O_RADIUS: p.radius = arg_double(optarg, "--radius"); break;
        case O_GEO: p.geodesic = 1; break;
        case O_LONLY: lonly = 1; break;
        case 'o': output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!lmfile) usage_error("missing -l LANDMARKS");
    if (argc - optind < 1 || argc - optind > 2) usage_error("expected SOURCE [TARGET]");
    if (!(p.kmin > 0) || !(p.kmax >= p.kmin)) usage_error("need 0 < kmin <= kmax");
    if (!(p.q > 0) || !(p.radius > 0) || p.gamma < 0) usage_error("exponent and radius must be positive");
    const char *sp = argv[optind], *tp = argc - optind == 2 ? argv[optind + 1] : NULL;
    struct mesh S, T = {0};
    if (mesh_read(sp, &S) < 0) die("%s", cm_errmsg());
    if (tp && mesh_read(tp, &T) < 0) die("%s", cm_errmsg());
    struct landmarks L;
    if (landmarks_read(lmfile, S.nv, tp ? T.V : NULL, T.nv, &L) < 0) die("%s", cm_errmsg());
    double *kl = malloc((size_t)L.n * sizeof *kl + 1), *k = malloc((size_t)S.nv * sizeof *k + 1);
    landmark_stiffness(S.V, S.nv, L.src, L.P, L.n, &p, kl);
    if (!lonly && stiffness_map(S.V, S.F, S.nv, S.nf, L.src, kl, L.n, &p, k) < 0)
        die("cannot compute geodesic distances on '%s': %s", sp, cm_errmsg());
    FILE *out = out_open(output);
    if (lonly) columns_write(out, kl, L.n, 1);
    else columns_write(out, k, S.nv, 1);
    out_close(out);
    free(kl); free(k);
    landmarks_free(&L);
    mesh_free(&S);
    mesh_free(&T);
    return 0;
}
