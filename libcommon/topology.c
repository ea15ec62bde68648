/* topology.c -- see topology.h */
#include "topology.h"
#include "cm_error.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int topology_build(const int *F, int nf, int nv, struct topology *t)
{
    memset(t, 0, sizeof *t);
    t->nv = nv;
    t->nf = nf;
    size_t nh = (size_t)nf * 3;
    /* half-edge keys (min << 32 | max) with the corner id, sorted by key
     * and, among equal keys, by corner: a counting sort by min (stable),
     * then each min's few entries by max (insertion sort, stable) */
    uint64_t *key = malloc((nh + 1) * 2 * sizeof *key);
    size_t *start = calloc((size_t)nv + 2, sizeof *start);
    if (!key || !start) { free(key); free(start); return cm_seterr("out of memory"); }
    for (size_t h = 0; h < nh; h++) {
        int a = F[h], b = F[h - h % 3 + (h % 3 + 1) % 3];
        start[(a < b ? a : b) + 1]++;
    }
    for (int v = 0; v < nv; v++) start[v + 1] += start[v];
    for (size_t h = 0; h < nh; h++) {
        uint32_t a = (uint32_t)F[h], b = (uint32_t)F[h - h % 3 + (h % 3 + 1) % 3];
        uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
        size_t i = start[lo]++;
        key[2 * i] = (uint64_t)lo << 32 | hi;
        key[2 * i + 1] = h;
    }
    for (size_t i = 1; i < nh; i++) {
        uint64_t k = key[2 * i], c = key[2 * i + 1];
        size_t j = i;
        for (; j > 0 && key[2 * (j - 1)] > k; j--) {
            key[2 * j] = key[2 * (j - 1)];
            key[2 * j + 1] = key[2 * (j - 1) + 1];
        }
        key[2 * j] = k;
        key[2 * j + 1] = c;
    }
    free(start);
    t->FE = malloc((nh + 1) * sizeof *t->FE);
    t->E = malloc((nh + 1) * 2 * sizeof *t->E);
    t->EF = malloc((nh + 1) * 2 * sizeof *t->EF);
    t->EFn = malloc((nh + 1) * sizeof *t->EFn);
    int ne = 0;
    for (size_t i = 0; i < nh;) {
        size_t j = i;
        while (j < nh && key[2 * j] == key[2 * i]) j++;
        t->E[2 * ne] = (int)(key[2 * i] >> 32);
        t->E[2 * ne + 1] = (int)(key[2 * i] & 0xffffffffu);
        t->EF[2 * ne] = (int)(key[2 * i + 1] / 3);
        t->EF[2 * ne + 1] = j - i > 1 ? (int)(key[2 * i + 3] / 3) : -1;
        t->EFn[ne] = (int)(j - i);
        if (j - i == 1) t->nboundary++;
        if (j - i > 2) t->nnonmanifold++;
        for (size_t k = i; k < j; k++)
            t->FE[key[2 * k + 1]] = ne;
        ne++;
        i = j;
    }
    t->ne = ne;
    free(key);
    /* vertex -> faces */
    t->VFs = calloc((size_t)nv + 1, sizeof *t->VFs);
    t->VF = malloc((nh + 1) * sizeof *t->VF);
    for (size_t h = 0; h < nh; h++) t->VFs[F[h] + 1]++;
    for (int v = 0; v < nv; v++) t->VFs[v + 1] += t->VFs[v];
    int *fill = malloc(((size_t)nv + 1) * sizeof *fill);
    memcpy(fill, t->VFs, (size_t)nv * sizeof *fill);
    for (size_t h = 0; h < nh; h++) t->VF[fill[F[h]]++] = (int)(h / 3);
    /* vertex -> vertices, sorted since edges are sorted by (lo, hi) */
    t->VVs = calloc((size_t)nv + 1, sizeof *t->VVs);
    t->VV = malloc(((size_t)ne * 2 + 1) * sizeof *t->VV);
    for (int e = 0; e < ne; e++) { t->VVs[t->E[2 * e] + 1]++; t->VVs[t->E[2 * e + 1] + 1]++; }
    for (int v = 0; v < nv; v++) t->VVs[v + 1] += t->VVs[v];
    memcpy(fill, t->VVs, (size_t)nv * sizeof *fill);
    /* neighbours smaller than v come from edges (u,v) with u<v, in order of u;
     * larger ones from (v,w) in order of w: two passes keep them sorted */
    for (int e = 0; e < ne; e++) t->VV[fill[t->E[2 * e + 1]]++] = t->E[2 * e];
    for (int e = 0; e < ne; e++) t->VV[fill[t->E[2 * e]]++] = t->E[2 * e + 1];
    free(fill);
    t->ES = calloc((size_t)nv + 1, sizeof *t->ES);
    for (int e = 0; e < ne; e++) t->ES[t->E[2 * e] + 1]++;
    for (int v = 0; v < nv; v++) t->ES[v + 1] += t->ES[v];
    for (int v = 0; v < nv; v++) t->nisolated += t->VFs[v] == t->VFs[v + 1];
    return 0;
}

void topology_free(struct topology *t)
{
    free(t->E); free(t->EF); free(t->EFn); free(t->FE);
    free(t->VFs); free(t->VF); free(t->VVs); free(t->VV); free(t->ES);
    memset(t, 0, sizeof *t);
}

int topology_edge(const struct topology *t, int a, int b)
{
    int lo = a < b ? a : b, hi = a < b ? b : a;
    if (lo < 0 || hi >= t->nv) return -1;
    /* the edges (lo, w) are sorted by w */
    int l = t->ES[lo], r = t->ES[lo + 1] - 1;
    while (l <= r) {
        int m = (l + r) / 2, w = t->E[2 * m + 1];
        if (w == hi) return m;
        if (w < hi) l = m + 1;
        else r = m - 1;
    }
    return -1;
}

int boundary_loops(const struct topology *t, const int *F, int **Ls, int **L)
{
    /* next[v] = w for each boundary half-edge v->w (face orientation) */
    int *next = malloc(((size_t)t->nv + 1) * sizeof *next);
    for (int v = 0; v < t->nv; v++) next[v] = -1;
    int bad = 0;
    for (int f = 0; f < t->nf; f++)
        for (int c = 0; c < 3; c++) {
            int e = t->FE[3 * f + c];
            if (t->EFn[e] != 1) continue;
            int a = F[3 * f + c], b = F[3 * f + (c + 1) % 3];
            if (next[a] != -1) bad = 1;
            next[a] = b;
        }
    if (bad) {
        free(next);
        return cm_seterr("boundary passes twice through one vertex (non-manifold vertex)");
    }
    int *ls = malloc(((size_t)t->nboundary + 2) * sizeof *ls);
    int *l = malloc(((size_t)t->nboundary + 1) * sizeof *l);
    int nl = 0, n = 0;
    ls[0] = 0;
    for (int v = 0; v < t->nv; v++) {
        if (next[v] < 0) continue;
        int u = v;
        while (next[u] >= 0) {
            int w = next[u];
            l[n++] = u;
            next[u] = -1;
            u = w;
        }
        ls[++nl] = n;
    }
    free(next);
    *Ls = ls;
    *L = l;
    return nl;
}

static int find(int *p, int x)
{
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
}

int connected_components(const struct topology *t, const int *F, int *comp_of_face)
{
    int *p = malloc(((size_t)t->nv + 1) * sizeof *p);
    for (int v = 0; v < t->nv; v++) p[v] = v;
    for (int f = 0; f < t->nf; f++)
        for (int c = 1; c < 3; c++) {
            int a = find(p, F[3 * f]), b = find(p, F[3 * f + c]);
            if (a != b) p[a] = b;
        }
    int *id = malloc(((size_t)t->nv + 1) * sizeof *id);
    for (int v = 0; v < t->nv; v++) id[v] = -1;
    int n = 0;
    for (int f = 0; f < t->nf; f++) {
        int r = find(p, F[3 * f]);
        if (id[r] < 0) id[r] = n++;
        if (comp_of_face) comp_of_face[f] = id[r];
    }
    free(p);
    free(id);
    return n;
}

int nonmanifold_vertices(const struct topology *t, const int *F)
{
    /* a manifold vertex's faces form one fan: count fans by union-find on
     * faces around v linked through edges incident to v */
    int bad = 0;
    int cap = 64;
    int *par = malloc(cap * sizeof *par);
    for (int v = 0; v < t->nv; v++) {
        int s = t->VFs[v], n = t->VFs[v + 1] - s;
        if (n == 0) continue;
        if (n > cap) { cap = 2 * n; par = realloc(par, cap * sizeof *par); }
        for (int i = 0; i < n; i++) par[i] = i;
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++) {
                int fi = t->VF[s + i], fj = t->VF[s + j];
                /* share an edge through v? */
                int shared = 0;
                for (int a = 0; a < 3; a++)
                    for (int b = 0; b < 3; b++)
                        if (F[3 * fi + a] == F[3 * fj + b] && F[3 * fi + a] != v) shared = 1;
                if (shared) {
                    int x = find(par, i), y = find(par, j);
                    if (x != y) par[x] = y;
                }
            }
        int fans = 0;
        for (int i = 0; i < n; i++) fans += find(par, i) == i;
        bad += fans > 1;
    }
    free(par);
    return bad;
}
