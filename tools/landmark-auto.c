/* landmark-auto -- corresponding landmarks between two scans of one
 * character in different poses (geodesic extremities matched by their
 * geodesic distances, left and right told apart by orientation, points
 * along the limbs), written as the landmark file nricp -l reads.
 */
#include "cm_error.h"
#include "landmark_auto.h"
#include "mesh.h"
#include "tool.h"
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: landmark-auto [options] SOURCE TARGET > landmarks.txt\n"
"Propose corresponding landmarks of two meshes of one character in different\n"
"poses (any connectivity): rows 'source_vertex target_vertex', the file nricp -l\n"
"reads.  Extremities (tips of limbs, head, tail) are local maxima of the geodesic\n"
"distance from both ends of the diameter; they are matched so that their geodesic\n"
"distances agree, left and right by the orientation of the matched tips, and\n"
"the near-best maps tested by deforming SOURCE onto TARGET; then a point along\n"
"each limb is added.\n"
"\n"
"Options:\n"
"      --radius R        local-maximum radius, fraction of sqrt(area) (default 0.1)\n"
"      --penalty P       distance mismatch beyond which a pair does not count,\n"
"                        fraction of sqrt(area) (default 0.25)\n"
"      --max N           at most N extremities per mesh (default 12, <= 32)\n"
"      --limb T,...      limb points at T times the distance from the tip to the\n"
"                        nearest other tip (default 0.35; 'none'; at most 4)\n"
"      --disc-weight W   cost of unlike geodesic disc areas around a matched pair\n"
"                        (a hoof is not a snout; default 1, 0 off)\n"
"      --second R        leftover tips (a limb stretched far in one pose) pair when\n"
"                        each is the other's best by a factor R (default 1.5, 0 off)\n"
"      --verify 0|1      1 (default): the near-best maps (orientation weighted 1,\n"
"                        1/2, 1/4, 0) are each tested by an as-rigid-as-possible\n"
"                        deformation of SOURCE onto TARGET, the best fit wins;\n"
"                        0: score plus orientation alone (the earlier choice)\n"
"      --core            also pair the cores (least sum of distances to the tips)\n"
"      --extremities     only list SOURCE's extremities (one vertex per row)\n"
"  -o, --output FILE     write to FILE (atomically) instead of stdout\n"
"  -v, --verbose         report the extremities, the match cost and orientation\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: landmark-auto a.mesh b.mesh > marks.txt && nricp -l marks.txt a.mesh b.mesh\n";

enum { O_RADIUS = 256, O_PENALTY, O_MAX, O_LIMB, O_NOCORE, O_EXT, O_VERSION, O_DISC, O_SECOND, O_VERIFY };

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"radius", 1, 0, O_RADIUS}, {"penalty", 1, 0, O_PENALTY}, {"max", 1, 0, O_MAX},
        {"limb", 1, 0, O_LIMB}, {"core", 0, 0, O_NOCORE}, {"extremities", 0, 0, O_EXT},
        {"output", 1, 0, 'o'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"disc-weight", 1, 0, O_DISC}, {"second", 1, 0, O_SECOND}, {"verify", 1, 0, O_VERIFY},
        {"version", 0, 0, O_VERSION}, {0, 0, 0, 0}};
    struct landmark_auto_params p;
    landmark_auto_defaults(&p);
    const char *output = NULL;
    int only_ext = 0, c;
    while ((c = getopt_long(argc, argv, "o:vh", lo, NULL)) != -1) {
        switch (c) {
        case O_RADIUS: p.radius = arg_double(optarg, "--radius"); break;
        case O_PENALTY: p.penalty = arg_double(optarg, "--penalty"); break;
        case O_MAX: p.max_extremities = (int)arg_long(optarg, "--max"); break;
        case O_LIMB:
            p.nlimb = 0;
            if (strcmp(optarg, "none")) {
                char *s = optarg, *end;
                for (;;) {
                    if (p.nlimb == 4) usage_error("--limb: at most 4 fractions");
                    double t = strtod(s, &end);
                    if (end == s || !(t > 0 && t < 1)) usage_error("--limb: '%s' is not fractions in (0, 1)", optarg);
                    p.limb_t[p.nlimb++] = t;
                    if (*end == 0) break;
                    if (*end != ',') usage_error("--limb: '%s' is not T,T,...", optarg);
                    s = end + 1;
                }
            }
            break;
        case O_NOCORE: p.core = 1; break;
        case O_DISC: p.disc_weight = arg_double(optarg, "--disc-weight"); break;
        case O_SECOND: p.second_ratio = arg_double(optarg, "--second"); break;
        case O_VERIFY:
            if (strcmp(optarg, "0") && strcmp(optarg, "1")) usage_error("--verify must be 0 or 1");
            p.verify = optarg[0] == '1';
            break;
        case O_EXT: only_ext = 1; break;
        case 'o': output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!(p.radius > 0 && p.radius < 1)) usage_error("--radius must be in (0, 1)");
    if (!(p.penalty > 0)) usage_error("--penalty must be > 0");
    if (!(p.disc_weight >= 0 && p.disc_weight <= 100)) usage_error("--disc-weight must be in [0, 100]");
    if (!(p.second_ratio == 0 || (p.second_ratio >= 1 && p.second_ratio <= 100)))
        usage_error("--second must be 0 or in [1, 100]");
    if (p.max_extremities < 3 || p.max_extremities > 32) usage_error("--max must be in 3..32");
    if (argc - optind != (only_ext ? 1 : 2))
        usage_error(only_ext ? "expected one mesh with --extremities" : "expected SOURCE and TARGET");
    struct mesh A, B;
    if (mesh_read(argv[optind], &A) < 0) die("%s", cm_errmsg());
    if (A.nframes != 1)
        die("cannot use '%s': %d frames, expected one pose", argv[optind], A.nframes);
    if (only_ext) {
        int *E, n = mesh_extremities(A.V, A.F, A.nv, A.nf, &p, &E);
        if (n < 0) die("cannot use '%s': %s", argv[optind], cm_errmsg());
        FILE *f = out_open(output);
        fprintf(f, "# extremities of %s, farthest first\n", argv[optind]);
        for (int i = 0; i < n; i++) fprintf(f, "%d\n", E[i]);
        out_close(f);
        free(E);
        mesh_free(&A);
        return 0;
    }
    if (mesh_read(argv[optind + 1], &B) < 0) die("%s", cm_errmsg());
    if (B.nframes != 1)
        die("cannot use '%s': %d frames, expected one pose", argv[optind + 1], B.nframes);
    struct landmark_pairs L;
    if (landmark_auto(A.V, A.F, A.nv, A.nf, B.V, B.F, B.nv, B.nf, &p, &L) < 0)
        die("%s and %s: %s", argv[optind], argv[optind + 1], cm_errmsg());
    info(1, "extremities: %d on %s, %d on %s; %d matched (%d by the second chance), distance mismatch %.3g sqrt(area), "
         "orientation %.2f (mirrored competitor %.2f)", L.na, argv[optind], L.nb, argv[optind + 1],
         L.matched, L.second, L.cost, L.orient, L.orient_mirror);
    if (L.verified < 0)
        warn("the near-best maps were not tested by deformation (%s): the map of score and "
             "orientation alone is kept", L.why);
    if (L.verified > 0)
        info(1, "verified by deformation: %d candidate maps, the chosen fits TARGET to %.3g sqrt(area), "
             "the next best %.3g%s", L.verified, L.fit, L.fit_next,
             L.changed ? " (score and orientation alone would have chosen another)" : "");
    FILE *f = out_open(output);
    static const char *kinds[] = {"extremity", "limb", "core"};
    fprintf(f, "# landmark-auto %s -> %s: %d extremities matched of %d and %d, "
            "mismatch %.3g, orientation %.2f", argv[optind], argv[optind + 1], L.matched, L.na,
            L.nb, L.cost, L.orient);
    if (L.verified) fprintf(f, ", fit %.3g of %d maps verified", L.fit, L.verified);
    fprintf(f, "\n");
    for (int i = 0; i < L.n; i++) fprintf(f, "%d %d  # %s\n", L.a[i], L.b[i], kinds[L.kind[i]]);
    out_close(f);
    landmark_pairs_free(&L);
    mesh_free(&A);
    mesh_free(&B);
    return 0;
}
