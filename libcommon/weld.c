/* weld.c -- see weld.h.  Candidates come from a sweep over frame 0 sorted
 * by x (O(#V log #V) for well-spread data); each candidate pair is then
 * confirmed in every frame and joined with union-find. */
#include "weld.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double *sort_X;

static int by_x(const void *a, const void *b)
{
    double xa = sort_X[3 * *(const int *)a], xb = sort_X[3 * *(const int *)b];
    if (xa < xb) return -1;
    if (xa > xb) return 1;
    return *(const int *)a - *(const int *)b;
}

static int find(int *p, int i)
{
    while (p[i] != i) {
        p[i] = p[p[i]];
        i = p[i];
    }
    return i;
}

static int close_in_all_frames(const struct mesh *m, int a, int b, double eps2)
{
    for (int k = 0; k < m->nframes; k++) {
        const double *X = mesh_frame(m, k);
        double d2 = 0;
        for (int c = 0; c < 3; c++) {
            double d = X[3 * a + c] - X[3 * b + c];
            d2 += d * d;
        }
        if (!(d2 <= eps2))
            return 0;
    }
    return 1;
}

int mesh_weld(struct mesh *m, double eps, int *nmerged, int *ndropped)
{
    int nv = m->nv;
    int *order = malloc((size_t)nv * sizeof *order);
    int *parent = malloc((size_t)nv * sizeof *parent);
    int *newidx = malloc((size_t)nv * sizeof *newidx);
    if (!order || !parent || !newidx) {
        free(order); free(parent); free(newidx);
        return cm_seterr("out of memory welding %d vertices", nv);
    }
    for (int i = 0; i < nv; i++) order[i] = parent[i] = i;
    sort_X = m->V;
    qsort(order, nv, sizeof *order, by_x);
    double eps2 = eps * eps;
    for (int a = 0; a < nv; a++) {
        int i = order[a];
        for (int b = a + 1; b < nv; b++) {
            int j = order[b];
            if (m->V[3 * j] - m->V[3 * i] > eps) break;
            if (close_in_all_frames(m, i, j, eps2)) {
                int ri = find(parent, i), rj = find(parent, j);
                if (ri != rj) {      /* the smaller index represents the group */
                    if (ri < rj) parent[rj] = ri; else parent[ri] = rj;
                }
            }
        }
    }
    int n = 0;
    for (int i = 0; i < nv; i++)
        newidx[i] = find(parent, i) == i ? n++ : -1;
    int merged = nv - n;
    /* positions: compact every frame in place */
    if (merged > 0) {
        for (int k = 0; k < m->nframes; k++) {
            const double *X = mesh_frame(m, k);
            double *Y = m->V + (size_t)k * n * 3;
            for (int i = 0; i < nv; i++)
                if (newidx[i] >= 0)
                    memmove(Y + 3 * newidx[i], X + 3 * i, 3 * sizeof *Y);
        }
    }
    int nf = 0, dropped = 0;
    for (int t = 0; t < m->nf; t++) {
        int v[3];
        for (int c = 0; c < 3; c++) v[c] = newidx[find(parent, m->F[3 * t + c])];
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
            dropped++;
            continue;
        }
        memcpy(m->F + 3 * nf, v, sizeof v);
        nf++;
    }
    m->nv = n;
    m->nf = nf;
    free(order); free(parent); free(newidx);
    if (nmerged) *nmerged = merged;
    if (ndropped) *ndropped = dropped;
    return 0;
}
