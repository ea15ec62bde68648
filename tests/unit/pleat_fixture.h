/* pleat_fixture.h -- the untangling tests' case: a 24 x 24 grid on [0,1]^2
 * pushed into a pleat (pleat_grid) over a target plane meshed another way
 * (17 x 19, jittered), with the target's closest-point tree and the number
 * of faces the pleat turns over (flipped_faces, tolerance 1e-3).  Checks
 * the tree and the pleat with ok(); P2 has room for a copy of P.  The
 * caller frees every array and the tree. */
#ifndef STOPMO_PLEAT_FIXTURE_H
#define STOPMO_PLEAT_FIXTURE_H
#include "closest_point.h"
#include "mesh_distance.h"
#include "tap.h"
#include "testmesh.h"

struct pleat_fixture {
    double *V, *VT, *P, *P2;   /* grid (rest), target, pleated grid, room for a copy */
    int *F, *FT, nv, nf, nvt, nft;
    struct closest_point_tree *TT;
    int before;                /* faces flipped against the target */
};

static inline void pleat_fixture_make(struct pleat_fixture *x)
{
    grid_mesh(24, 24, 0, 1, &x->V, &x->F, &x->nv, &x->nf);
    grid_mesh(17, 19, 0.3, 2, &x->VT, &x->FT, &x->nvt, &x->nft);    /* the target: another meshing */
    x->TT = closest_point_tree_new(x->VT, x->nvt, x->FT, x->nft);
    ok(x->TT != NULL, "target tree");
    x->P = malloc(sizeof *x->P * 3 * x->nv);
    x->P2 = malloc(sizeof *x->P2 * 3 * x->nv);
    pleat_grid(x->V, x->nv, x->P);
    x->before = flipped_faces(x->P, x->F, x->nf, x->VT, x->nvt, x->FT, x->nft, x->TT, 1e-3);
    ok(x->before >= 10, "the pleat turns faces over (%d)", x->before);
}
#endif
