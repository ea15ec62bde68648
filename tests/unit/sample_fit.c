/* sample_fit: a coarse cylinder whose vertices lie on a fine one (every
 * vertex on the target, the edges and faces cutting inside it, the
 * target's surface between the vertices uncovered) comes closer by the
 * symmetric Hausdorff distance, measured independently; no face flips; the
 * same bytes twice; with no iteration the pose is left as it is */
#include "sample_fit.h"
#include "closest_point.h"
#include "mesh_distance.h"
#include "tap.h"
#include "testmesh.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double hausdorff(const double *V, const int *F, int nv, int nf, const double *VT,
                        const int *FT, int nvt, int nft, const struct closest_point_tree *TT)
{
    struct closest_point_tree *TS = closest_point_tree_new(V, nv, F, nf);
    double h = -1, rms;
    if (TS) symmetric_distance(V, nv, F, nf, TS, VT, nvt, FT, nft, TT, &h, &rms);
    closest_point_tree_free(TS);
    return h;
}

int main(void)
{
    double *V, *VT;
    int *F, *FT, nv, nf, nvt, nft;
    cylinder_mesh(12, 4, &V, &F, &nv, &nf);
    cylinder_mesh(96, 16, &VT, &FT, &nvt, &nft);
    struct closest_point_tree *TT = closest_point_tree_new(VT, nvt, FT, nft);
    struct sample_fit_params p;
    sample_fit_defaults(&p);
    p.tol = 1e-3;
    double st[4];
    double *P = malloc(sizeof *P * 3 * nv), *P2 = malloc(sizeof *P2 * 3 * nv);
    memcpy(P, V, sizeof *P * 3 * nv);
    double h0 = hausdorff(V, F, nv, nf, VT, FT, nvt, nft, TT);
    ok(sample_fit(P, F, nv, nf, VT, FT, nvt, nft, TT, &p, st) == 0, "sample_fit runs");
    ok(fabs(st[0] - h0) < 1e-12, "Hausdorff before as measured (%.5f, %.5f)", st[0], h0);
    double h1 = hausdorff(P, F, nv, nf, VT, FT, nvt, nft, TT);
    ok(fabs(st[1] - h1) < 1e-12, "Hausdorff after as measured (%.5f, %.5f)", st[1], h1);
    ok(h1 < 0.6 * h0, "closer: %.5f -> %.5f", h0, h1);
    int fl = flipped_faces(P, F, nf, VT, nvt, FT, nft, TT, 1e-3);
    ok(st[2] == 0 && st[3] == 0 && fl == 0, "no face flipped (%g, %g, %d)", st[2], st[3], fl);
    double rmin = INFINITY, rmax = 0, zerr = 0;
    for (int i = 0; i < nv; i++) {
        double r = hypot(P[3 * i], P[3 * i + 1]);
        rmin = fmin(rmin, r);
        rmax = fmax(rmax, r);
        zerr = fmax(zerr, fabs(P[3 * i + 2] - V[3 * i + 2]));
    }
    ok(rmin > 1 && rmax < 1.05, "vertices moved out a little, the chords now cross the target "
       "(radius %.4f-%.4f)", rmin, rmax);
    memcpy(P2, V, sizeof *P2 * 3 * nv);
    sample_fit(P2, F, nv, nf, VT, FT, nvt, nft, TT, &p, NULL);
    ok(!memcmp(P, P2, sizeof *P * 3 * nv), "the same bytes twice");
    p.iters = 0;
    memcpy(P2, V, sizeof *P2 * 3 * nv);
    ok(sample_fit(P2, F, nv, nf, VT, FT, nvt, nft, TT, &p, st) == 0 &&
       !memcmp(P2, V, sizeof *P2 * 3 * nv) && st[0] == st[1], "no iteration: left as it is");
    closest_point_tree_free(TT);
    free(V); free(F); free(VT); free(FT); free(P); free(P2);
    (void)zerr;
    return tap_done();
}
