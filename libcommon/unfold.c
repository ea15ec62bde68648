/* unfold.c -- see unfold.h */
#include "unfold.h"
#include "cm_error.h"
#include "geometry.h"
#include "laplacian.h"
#include "topology.h"
#include <stdlib.h>
#include <string.h>

/* mark the corners of fold-overs; returns their number */
static int find_folds(const double *V, const int *F, int nf, const struct topology *t, double *N,
                      double min_cos, unsigned char *mark, int nv)
{
    face_normals(V, F, nf, N);
    memset(mark, 0, (size_t)nv);
    int n = 0;
    for (int f = 0; f < nf; f++) {
        int against = 0, nb = 0;
        for (int c = 0; c < 3; c++) {
            int e = t->FE[3 * f + c];
            if (t->EFn[e] != 2) continue;
            int g = t->EF[2 * e] == f ? t->EF[2 * e + 1] : t->EF[2 * e];
            nb++;
            against += dot3(N + 3 * f, N + 3 * g) < min_cos;
        }
        if (against >= 2) {
            n++;
            for (int c = 0; c < 3; c++) mark[F[3 * f + c]] = 1;
        }
    }
    return n;
}

int unfold_faces(double *V, const int *F, int nv, int nf, double min_cos, int max_sweeps,
                 int *found)
{
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return -1;
    double *N = malloc(((size_t)nf * 3 + 1) * sizeof *N);
    unsigned char *mark = malloc((size_t)nv + 1);
    if (!N || !mark) {
        free(N); free(mark); topology_free(&t);
        return cm_seterr("out of memory");
    }
    int n = find_folds(V, F, nf, &t, N, min_cos, mark, nv);
    if (found) *found = n;
    for (int s = 0; s < max_sweeps && n > 0; s++) {
        if (umbrella_smooth(&t, mark, 1, 1, V) < 0) { n = -1; break; }
        n = find_folds(V, F, nf, &t, N, min_cos, mark, nv);
    }
    free(N); free(mark);
    topology_free(&t);
    return n;
}
