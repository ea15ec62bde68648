/* patch_unflip: a pleat laid on a plane (a band of a grid turned over,
 * every vertex on the target) is laid flat by the foldover-free solve: no
 * flipped face left, every vertex still on the target, vertices away from
 * the pleat untouched, same bytes twice; a mesh without flipped faces is
 * left as it is */
#include "patch_unflip.h"
#include "closest_point.h"
#include "mesh_distance.h"
#include "tap.h"
#include "pleat_fixture.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int main(void)
{
    struct pleat_fixture x;
    pleat_fixture_make(&x);
    double *V = x.V, *VT = x.VT, *P = x.P, *P2 = x.P2;
    int *F = x.F, *FT = x.FT, nv = x.nv, nf = x.nf, nvt = x.nvt, nft = x.nft, before = x.before;
    struct closest_point_tree *TT = x.TT;
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
