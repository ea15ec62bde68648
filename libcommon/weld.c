/* weld.c -- see weld.h.  Candidates come from frame 0: every vertex gets a
 * cell key (its exact position when eps = 0, else floor(p / eps) per
 * coordinate); keys are sorted, and each vertex looks up its own and (for
 * eps > 0) the 26 neighbouring cells by binary search, so the cost is
 * O(#V log #V) whatever the shape (a sweep along one axis is quadratic on a
 * grid aligned with it).  Each candidate pair is then confirmed in every
 * frame and joined with union-find. */
#include "weld.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct key { double c[3]; int v; };

static int key_cmp3(const double *a, const double *b)
{
    for (int d = 0; d < 3; d++) {
        if (a[d] < b[d]) return -1;
        if (a[d] > b[d]) return 1;
    }
    return 0;
}

static int by_key(const void *pa, const void *pb)
{
    const struct key *a = pa, *b = pb;
    int c = key_cmp3(a->c, b->c);
    return c ? c : a->v - b->v;
}

/* first index in K[0..n) whose cell is >= c */
static int lower(const struct key *K, int n, const double *c)
{
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (key_cmp3(K[mid].c, c) < 0) lo = mid + 1; else hi = mid;
    }
    return lo;
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
    struct key *K = malloc((size_t)nv * sizeof *K + 1);
    int *parent = malloc((size_t)nv * sizeof *parent + 1);
    int *newidx = malloc((size_t)nv * sizeof *newidx + 1);
    if (!K || !parent || !newidx) {
        free(K); free(parent); free(newidx);
        return cm_seterr("out of memory welding %d vertices", nv);
    }
    for (int i = 0; i < nv; i++) {
        parent[i] = i;
        K[i].v = i;
        for (int d = 0; d < 3; d++) {
            double x = m->V[3 * i + d];
            K[i].c[d] = eps > 0 ? floor(x / eps) : x;
        }
    }
    qsort(K, nv, sizeof *K, by_key);
    double eps2 = eps * eps;
    int span = eps > 0 ? 1 : 0;
    for (int a = 0; a < nv; a++) {
        int i = K[a].v;
        for (int dx = -span; dx <= span; dx++)
            for (int dy = -span; dy <= span; dy++)
                for (int dz = -span; dz <= span; dz++) {
                    double c[3] = {K[a].c[0] + dx, K[a].c[1] + dy, K[a].c[2] + dz};
                    for (int b = lower(K, nv, c); b < nv && !key_cmp3(K[b].c, c); b++) {
                        int j = K[b].v;
                        if (j <= i || !close_in_all_frames(m, i, j, eps2)) continue;
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
    free(K); free(parent); free(newidx);
    if (nmerged) *nmerged = merged;
    if (ndropped) *ndropped = dropped;
    return 0;
}
