/* nricp_untangle: a pleat laid on a plane (a band of a grid turned over,
 * every vertex on the target) is ironed out: no flipped face left, every
 * vertex still on the target, vertices away from the pleat untouched, same
 * bytes twice; a mesh without flipped faces is left as it is */
#include "nricp_untangle.h"
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
    struct nricp_untangle_params p;
    nricp_untangle_defaults(&p);
    p.tol = 1e-3;
    int fl[2];
    memcpy(P2, P, sizeof *P * 3 * nv);
    ok(nricp_untangle(P, F, nv, nf, VT, FT, nvt, nft, TT, &p, fl) == 0, "untangle runs");
    ok(fl[0] == before, "it counts the same flipped faces before (%d)", fl[0]);
    int after = flipped_faces(P, F, nf, VT, nvt, FT, nft, TT, 1e-3);
    ok(after == 0 && fl[1] == 0, "no flipped face left (%d, reported %d)", after, fl[1]);
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
    nricp_untangle(P3, F, nv, nf, VT, FT, nvt, nft, TT, &p, NULL);
    ok(!memcmp(P3, P, sizeof *P * 3 * nv), "the same bytes twice");
    memcpy(P3, V, sizeof *P3 * 3 * nv);
    ok(nricp_untangle(P3, F, nv, nf, VT, FT, nvt, nft, TT, &p, fl) == 0 && fl[0] == 0 && fl[1] == 0 &&
       !memcmp(P3, V, sizeof *P3 * 3 * nv), "a mesh without flipped faces is left as it is");
    closest_point_tree_free(TT);
    free(V); free(F); free(VT); free(FT); free(P); free(P2); free(P3);
    return tap_done();
}
