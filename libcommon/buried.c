/* buried.c -- see buried.h */
#include "buried.h"
#include "cm_error.h"
#include "geometry.h"
#include "parallel.h"
#include "topology.h"
#include "winding.h"
#include <stdlib.h>
#include <string.h>

struct job { const double *V; const int *F; int nf; double offset; const double *N; unsigned char *zone; };

/* faces 64 j .. 64 j + 63: is the point just in front of the centroid inside? */
static void test_block(void *ctx, int j)
{
    const struct job *b = ctx;
    int f1 = 64 * j + 64 < b->nf ? 64 * j + 64 : b->nf;
    for (int f = 64 * j; f < f1; f++) {
        const double *n = b->N + 3 * f;
        if (dot3(n, n) == 0) { b->zone[f] = 0; continue; }    /* degenerate face: no front */
        double p[3];
        for (int d = 0; d < 3; d++)
            p[d] = (b->V[3 * b->F[3 * f] + d] + b->V[3 * b->F[3 * f + 1] + d] + b->V[3 * b->F[3 * f + 2] + d]) / 3 +
                   b->offset * n[d];
        b->zone[f] = winding_number(b->V, b->F, b->nf, p) > 0.5;
    }
}

int buried_faces(const double *V, int nv, const int *F, int nf, double offset, int rings,
                 int nthreads, unsigned char *zone)
{
    if (!(offset > 0)) { cm_seterr("buried faces: the offset must be positive"); return -1; }
    double *N = malloc(((size_t)nf * 3 + 1) * sizeof *N);
    unsigned char *vin = calloc((size_t)nv + 1, 1);
    struct topology t = {0};
    int n = -1;
    if (!N || !vin) { cm_seterr("out of memory"); goto done; }
    face_normals(V, F, nf, N);     /* unit normals (0 for a degenerate face) */
    struct job b = {V, F, nf, offset, N, zone};
    parallel_run((nf + 63) / 64, nthreads, test_block, &b);
    n = 0;
    for (int f = 0; f < nf; f++) n += zone[f];
    if (rings > 0 && n > 0) {
        if (topology_build(F, nf, nv, &t) < 0) { n = -1; goto done; }
        for (int g = 0; g < rings; g++) {
            memset(vin, 0, (size_t)nv);
            for (int f = 0; f < nf; f++)
                if (zone[f]) for (int c = 0; c < 3; c++) vin[F[3 * f + c]] = 1;
            for (int v = 0; v < nv; v++)
                if (vin[v]) for (int q = t.VFs[v]; q < t.VFs[v + 1]; q++) zone[t.VF[q]] = 1;
        }
    }
done:
    topology_free(&t);
    free(N); free(vin);
    return n;
}
