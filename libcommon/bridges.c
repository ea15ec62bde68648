/* bridges.c -- proximity bridges between mesh components; see bridges.h. */
#include "bridges.h"
#include "closest_point.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct comp_tree {
    struct closest_point_tree *tree;
    int *faces;              /* tree face -> mesh face */
    int n;
    double lo[3], hi[3];
};

static int push(struct bridge **b, int *n, int *cap, int f, int g, double d)
{
    if (*n == *cap) {
        int nc = *cap ? 2 * *cap : 256;
        struct bridge *nb = realloc(*b, (size_t)nc * sizeof *nb);
        if (!nb) return cm_seterr("bridges: out of memory");
        *b = nb;
        *cap = nc;
    }
    (*b)[*n].f = f;
    (*b)[*n].g = g;
    (*b)[*n].d = d;
    (*n)++;
    return 0;
}

static void centroid(const double *V, const int *F, int f, double c[3])
{
    for (int k = 0; k < 3; k++)
        c[k] = (V[3 * F[3 * f] + k] + V[3 * F[3 * f + 1] + k] + V[3 * F[3 * f + 2] + k]) / 3;
}

static int inside(const struct comp_tree *T, const double p[3], double r)
{
    for (int k = 0; k < 3; k++)
        if (p[k] < T->lo[k] - r || p[k] > T->hi[k] + r) return 0;
    return 1;
}

int component_bridges(const double *V, int nv, const int *F, int nf, const int *comp, int nc,
                      double r, struct bridge **out)
{
    *out = NULL;
    if (!(r >= 0)) return cm_seterr("bridges: distance must be >= 0");
    for (int f = 0; f < nf; f++)
        if (comp[f] < 0 || comp[f] >= nc) return cm_seterr("bridges: face %d: bad component", f);
    if (nc < 2) return 0;
    struct comp_tree *T = calloc((size_t)nc, sizeof *T);
    int *Fc = malloc(sizeof(int) * 3 * (size_t)nf);
    int *linked = calloc((size_t)nc, sizeof *linked);
    struct bridge *b = NULL;
    int n = 0, cap = 0, rc = -1;
    if (!T || !Fc || !linked) { cm_seterr("bridges: out of memory"); goto done; }
    for (int f = 0; f < nf; f++) T[comp[f]].n++;
    for (int c = 0; c < nc; c++) {
        T[c].faces = malloc(sizeof(int) * (size_t)(T[c].n ? T[c].n : 1));
        if (!T[c].faces) { cm_seterr("bridges: out of memory"); goto done; }
        T[c].n = 0;
        for (int k = 0; k < 3; k++) { T[c].lo[k] = INFINITY; T[c].hi[k] = -INFINITY; }
    }
    for (int f = 0; f < nf; f++) {
        struct comp_tree *t = &T[comp[f]];
        t->faces[t->n++] = f;
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) {
                double x = V[3 * F[3 * f + j] + k];
                if (x < t->lo[k]) t->lo[k] = x;
                if (x > t->hi[k]) t->hi[k] = x;
            }
    }
    for (int c = 0; c < nc; c++) {
        if (!T[c].n) continue;
        for (int i = 0; i < T[c].n; i++) memcpy(Fc + 3 * i, F + 3 * T[c].faces[i], 3 * sizeof *F);
        if (!(T[c].tree = closest_point_tree_new(V, nv, Fc, T[c].n))) goto done;
    }
    for (int f = 0; f < nf; f++) {
        double p[3], q[3];
        centroid(V, F, f, p);
        for (int c = 0; c < nc; c++) {
            if (c == comp[f] || !T[c].n || !inside(&T[c], p, r)) continue;
            int g;
            double d = closest_point_query(T[c].tree, p, q, &g, NULL);
            if (d <= r) {
                if (push(&b, &n, &cap, f, T[c].faces[g], d) < 0) goto done;
                linked[comp[f]] = linked[c] = 1;
            }
        }
    }
    /* components with nothing within r: one bridge to the nearest other */
    for (int c = 0; c < nc; c++) {
        if (linked[c] || !T[c].n) continue;
        double best = INFINITY;
        int bf = -1, bg = -1;
        for (int i = 0; i < T[c].n; i++) {
            double p[3], q[3];
            centroid(V, F, T[c].faces[i], p);
            for (int c2 = 0; c2 < nc; c2++) {
                if (c2 == c || !T[c2].n) continue;
                int g;
                double d = closest_point_query(T[c2].tree, p, q, &g, NULL);
                if (d < best) { best = d; bf = T[c].faces[i]; bg = T[c2].faces[g]; }
            }
        }
        if (bf >= 0 && push(&b, &n, &cap, bf, bg, best) < 0) goto done;
    }
    rc = n;
done:
    if (T)
        for (int c = 0; c < nc; c++) {
            closest_point_tree_free(T[c].tree);
            free(T[c].faces);
        }
    free(T);
    free(Fc);
    free(linked);
    if (rc < 0) free(b);
    else *out = b;
    return rc;
}
