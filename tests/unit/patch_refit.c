/* patch_refit: a grid lying on a target plane but for one vertex lifted
 * off it (a tent: its faces' samples stand off the plane, none flipped) is
 * laid back down by the foldover-free solve seeded at the farthest faces:
 * the Hausdorff distance drops, no face flips, vertices away from the seed
 * untouched, same bytes twice; a seed where nothing can get closer (the
 * grid flat on the plane) keeps no patch and leaves the bytes */
#include "patch_unflip.h"
#include "closest_point.h"
#include "mesh_distance.h"
#include "tap.h"
#include "testmesh.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double hausdorff(const double *P, const int *F, int nv, int nf, const double *VT,
                        const int *FT, int nvt, int nft, const struct closest_point_tree *TT)
{
    struct closest_point_tree *TS = closest_point_tree_new(P, nv, F, nf);
    double h = -1, rms;
    if (TS) symmetric_distance(P, nv, F, nf, TS, VT, nvt, FT, nft, TT, &h, &rms);
    closest_point_tree_free(TS);
    return h;
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
    memcpy(P, V, sizeof *P * 3 * nv);
    /* the vertex nearest the middle lifted by a third of an edge */
    int c = 0;
    for (int i = 0; i < nv; i++)
        if (hypot(V[3 * i] - 0.5, V[3 * i + 1] - 0.5) < hypot(V[3 * c] - 0.5, V[3 * c + 1] - 0.5)) c = i;
    P[3 * c + 2] = 1.0 / 23 / 3;
    unsigned char *seed = calloc((size_t)nf, 1);
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) if (F[3 * f + k] == c) seed[f] = 1;
    double h0 = hausdorff(P, F, nv, nf, VT, FT, nvt, nft, TT);
    ok(flipped_faces(P, F, nf, VT, nvt, FT, nft, TT, 1e-3) == 0 && h0 > 0.01,
       "the tent: no flipped face, Hausdorff %.4g", h0);
    struct patch_unflip_params p;
    patch_unflip_defaults(&p);
    p.tol = 1e-3;
    int st[4];
    memcpy(P2, P, sizeof *P * 3 * nv);
    ok(patch_refit(P, V, F, nv, nf, VT, FT, nvt, nft, TT, &p, seed, st) == 0, "refit runs");
    double h1 = hausdorff(P, F, nv, nf, VT, FT, nvt, nft, TT);
    ok(st[2] == 1 && st[3] == 1, "one patch tried and kept (%d, %d)", st[2], st[3]);
    ok(h1 < 0.5 * h0, "closer: Hausdorff %.4g -> %.4g", h0, h1);
    ok(flipped_faces(P, F, nf, VT, nvt, FT, nft, TT, 1e-3) == 0 && st[1] == 0, "no face flipped");
    int far_same = 1;
    for (int i = 0; i < nv; i++)
        if (hypot(V[3 * i] - 0.5, V[3 * i + 1] - 0.5) > 0.3 && memcmp(P + 3 * i, P2 + 3 * i, 3 * sizeof *P))
            far_same = 0;
    ok(far_same, "vertices away from the seed are untouched");
    double *P3 = malloc(sizeof *P3 * 3 * nv);
    memcpy(P3, P2, sizeof *P3 * 3 * nv);
    patch_refit(P3, V, F, nv, nf, VT, FT, nvt, nft, TT, &p, seed, NULL);
    ok(!memcmp(P3, P, sizeof *P * 3 * nv), "the same bytes twice");
    memcpy(P3, V, sizeof *P3 * 3 * nv);
    ok(patch_refit(P3, V, F, nv, nf, VT, FT, nvt, nft, TT, &p, seed, st) == 0 && st[3] == 0 &&
       !memcmp(P3, V, sizeof *P3 * 3 * nv), "flat on the target already: no patch kept, the same bytes");
    closest_point_tree_free(TT);
    free(V); free(F); free(VT); free(FT); free(P); free(P2); free(P3); free(seed);
    return tap_done();
}
