/* patch_unflip: a pleat laid on a plane (a band of a grid turned over,
 * every vertex on the target) is laid flat by the foldover-free solve: no
 * flipped face left, every vertex still on the target, vertices away from
 * the pleat untouched, same bytes twice; a mesh without flipped faces is
 * left as it is */
#include "patch_unflip.h"
#include "closest_point.h"
#include "mesh_distance.h"
#include "tap.h"
#include "testmesh.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* x -> x + b(y) g(x): g a sine wave on [0.35, 0.65] steep enough that the
 * map runs backwards around x = 0.5 where b(y) > 0.6 (as in nricp_untangle.c) */
static void pleat(const double *V, int nv, double *P)
{
    for (int i = 0; i < nv; i++) {
        double x = V[3 * i], y = V[3 * i + 1];
        double g = x > 0.35 && x < 0.65 ? 0.08 * sin(2 * M_PI * (x - 0.35) / 0.3) : 0;
        double b = y > 0.2 && y < 0.8 ? 0.5 - 0.5 * cos(2 * M_PI * (y - 0.2) / 0.6) : 0;
        P[3 * i] = x + b * g;
        P[3 * i + 1] = y;
        P[3 * i + 2] = 0;
    }
}

int main(void)
{
    double *V, *VT;
    int *F, *FT, nv, nf, nvt, nft;
    grid_mesh(24, 24, 0, 1, &V, &F, &nv, &nf);
    grid_mesh(17, 19, 0.3, 2, &VT, &FT, &nvt, &nft);    /* the target: another meshing */
    struct closest_point_tree *TT = closest_point_tree_new(VT, nvt, FT, nft);
    ok(TT != NULL, "target tree");
    double *P = malloc(sizeof *P * 3 * nv), *P2 = malloc(sizeof *P2 * 3 * nv);
    pleat(V, nv, P);
    int before = flipped_faces(P, F, nf, VT, nvt, FT, nft, TT, 1e-3);
    ok(before >= 10, "the pleat turns faces over (%d)", before);
    struct patch_unflip_params p;
    patch_unflip_defaults(&p);
    p.tol = 1e-3;
    int st[4];
    memcpy(P2, P, sizeof *P * 3 * nv);
    ok(patch_unflip(P, V, F, nv, nf, VT, FT, nvt, nft, TT, &p, st) == 0, "unflip runs");
    ok(st[0] == before, "it counts the same flipped faces before (%d)", st[0]);
    int after = flipped_faces(P, F, nf, VT, nvt, FT, nft, TT, 1e-3);
    ok(after == 0 && st[1] == 0, "no flipped face left (%d, reported %d)", after, st[1]);
    ok(st[2] >= 1 && st[3] >= 1 && st[3] <= st[2], "patches tried %d, kept %d", st[2], st[3]);
    double zmax = 0, out = 0;
    for (int i = 0; i < nv; i++) {
        zmax = fmax(zmax, fabs(P[3 * i + 2]));
        for (int d = 0; d < 2; d++) out = fmax(out, fmax(-P[3 * i + d], P[3 * i + d] - 1));
    }
    ok(zmax < 1e-12 && out < 1e-12, "every vertex on the target (|z| %.3g, outside %.3g)", zmax, out);
    int far_same = 1;
    for (int i = 0; i < nv; i++)
        if (fabs(V[3 * i] - 0.5) > 0.3 && memcmp(P + 3 * i, P2 + 3 * i, 3 * sizeof *P)) far_same = 0;
    ok(far_same, "vertices away from the pleat are untouched");
    double *P3 = malloc(sizeof *P3 * 3 * nv);
    memcpy(P3, P2, sizeof *P3 * 3 * nv);
    patch_unflip(P3, V, F, nv, nf, VT, FT, nvt, nft, TT, &p, NULL);
    ok(!memcmp(P3, P, sizeof *P * 3 * nv), "the same bytes twice");
    memcpy(P3, V, sizeof *P3 * 3 * nv);
    ok(patch_unflip(P3, V, F, nv, nf, VT, FT, nvt, nft, TT, &p, st) == 0 && st[0] == 0 && st[1] == 0 &&
       !memcmp(P3, V, sizeof *P3 * 3 * nv), "a mesh without flipped faces is left as it is");
    closest_point_tree_free(TT);
    free(V); free(F); free(VT); free(FT); free(P); free(P2); free(P3);
    return tap_done();
}
