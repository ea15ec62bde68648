/* coincident.c -- see coincident.h */
#include "coincident.h"
#include <stdlib.h>

static const double *gV;

static int cmp_pos(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    for (int d = 0; d < 3; d++) {
        double x = gV[3 * i + d], y = gV[3 * j + d];
        if (x < y) return -1;
        if (x > y) return 1;
    }
    return (i > j) - (i < j);
}

int coincident_find(const double *V, int nv, int *rep)
{
    int *o = malloc(sizeof(int) * (nv > 0 ? nv : 1));
    if (!o) return -1;
    for (int v = 0; v < nv; v++) o[v] = v;
    gV = V;
    qsort(o, nv, sizeof *o, cmp_pos);
    int welded = 0;
    for (int k = 0; k < nv; k++) {
        int v = o[k];
        if (k > 0 && V[3 * v] == V[3 * o[k - 1]] && V[3 * v + 1] == V[3 * o[k - 1] + 1] &&
            V[3 * v + 2] == V[3 * o[k - 1] + 2]) {
            rep[v] = rep[o[k - 1]];      /* sorted by index within a class */
            welded++;
        } else
            rep[v] = v;
    }
    free(o);
    return welded;
}

int coincident_refine(const double *V, int nv, int *rep)
{
    int n = 0;
    for (int v = 0; v < nv; v++) {
        int r = rep[v];
        if (r == v) continue;
        if (V[3 * v] != V[3 * r] || V[3 * v + 1] != V[3 * r + 1] || V[3 * v + 2] != V[3 * r + 2]) {
            rep[v] = v;
            n++;
        }
    }
    return n;
}

void coincident_faces(const int *F, int nf, const int *rep, int *Fw)
{
    for (int i = 0; i < 3 * nf; i++) Fw[i] = rep[F[i]];
}
