/* alpha_expansion.c -- see alpha_expansion.h */
#include "alpha_expansion.h"
#include "cm_error.h"
#include "graphcut.h"
#include <math.h>
#include <stdlib.h>

void potts_energy(int n, int s, const double *U, int ne, const int *E, const double *W,
                  const int *L, double *unary, double *binary)
{
    double u = 0, b = 0;
    for (int i = 0; i < n; i++) u += U[(size_t)i * s + L[i]];
    for (int e = 0; e < ne; e++)
        if (L[E[2 * e]] != L[E[2 * e + 1]]) b += W ? W[e] : 1;
    if (unary) *unary = u;
    if (binary) *binary = b;
}

int alpha_expansion(int n, int s, const double *U, int ne, const int *E, const double *W,
                    int *L, int init, int max_cycles, struct alpha_expansion_stats *st)
{
    if (n < 0 || s < 1 || ne < 0) return cm_seterr("alpha-expansion: bad sizes");
    for (int e = 0; e < ne; e++) {
        if (E[2 * e] < 0 || E[2 * e] >= n || E[2 * e + 1] < 0 || E[2 * e + 1] >= n)
            return cm_seterr("alpha-expansion: edge %d: node out of range", e);
        if (W && !(W[e] >= 0 && isfinite(W[e])))
            return cm_seterr("alpha-expansion: edge %d: weight must be finite and >= 0", e);
    }
    /* BIG stands in for INFINITY: more than any finite labeling costs */
    double big = 1;
    for (int i = 0; i < n; i++) {
        double m = 0;
        int any = 0;
        for (int l = 0; l < s; l++) {
            double u = U[(size_t)i * s + l];
            if (isnan(u) || u == -INFINITY)
                return cm_seterr("alpha-expansion: node %d: unary cost is not a number", i);
            if (isfinite(u)) { any = 1; if (fabs(u) > m) m = fabs(u); }
        }
        if (!any) return cm_seterr("alpha-expansion: node %d has no allowed label", i);
        big += 2 * m;
    }
    for (int e = 0; e < ne; e++) big += W ? W[e] : 1;
#define UC(i, l) (isfinite(U[(size_t)(i) * s + (l)]) ? U[(size_t)(i) * s + (l)] : big)
    if (init) {
        for (int i = 0; i < n; i++)
            if (L[i] < 0 || L[i] >= s || !isfinite(U[(size_t)i * s + L[i]]))
                return cm_seterr("alpha-expansion: initial label of node %d not allowed", i);
    } else {
        for (int i = 0; i < n; i++) {
            int b = 0;
            for (int l = 1; l < s; l++) if (UC(i, l) < UC(i, b)) b = l;
            L[i] = b;
        }
    }
    double *e0 = malloc(sizeof(double) * (n ? n : 1)), *e1 = malloc(sizeof(double) * (n ? n : 1));
    if (!e0 || !e1) { free(e0); free(e1); return cm_seterr("alpha-expansion: out of memory"); }
    double eu, eb;
    potts_energy(n, s, U, ne, E, W, L, &eu, &eb);
    double energy = eu + eb;
    int cycles = 0, moves = 0;
    int *Lnew = malloc(sizeof(int) * (n ? n : 1));
    if (!Lnew) { free(e0); free(e1); return cm_seterr("alpha-expansion: out of memory"); }
    int rc = 0;
    for (;;) {
        if (max_cycles > 0 && cycles >= max_cycles) break;
        cycles++;
        double start = energy;
        for (int a = 0; a < s && s > 1; a++) {
            /* x_i = 1 (sink side): switch to a; x_i = 0: keep L[i] */
            struct graphcut *g = graphcut_new(n, ne);
            if (!g) { rc = cm_seterr("alpha-expansion: out of memory"); break; }
            for (int i = 0; i < n; i++) { e0[i] = UC(i, L[i]); e1[i] = UC(i, a); }
            for (int e = 0; e < ne; e++) {
                int i = E[2 * e], j = E[2 * e + 1];
                if (i == j) continue;
                double w = W ? W[e] : 1;
                double A = L[i] != L[j] ? w : 0;      /* keep, keep */
                double B = L[i] != a ? w : 0;         /* keep, switch */
                double C = L[j] != a ? w : 0;         /* switch, keep */
                /* D = 0 (switch, switch) */
                e0[i] += A;                           /* constant A moved onto x_i = 0 */
                e1[i] += C;                           /* (C - A) x_i  + A */
                /* (D - C) x_j: */
                e1[j] -= C;
                double cap = B + C - A;               /* (1 - x_i) x_j, >= 0 for Potts */
                if (cap > 0) graphcut_add_edge(g, i, j, cap, 0);
            }
            for (int i = 0; i < n; i++) graphcut_add_tweights(g, i, e1[i], e0[i]);
            graphcut_maxflow(g);
            for (int i = 0; i < n; i++) Lnew[i] = graphcut_side(g, i) ? a : L[i];
            graphcut_free(g);
            potts_energy(n, s, U, ne, E, W, Lnew, &eu, &eb);
            double en = eu + eb;   /* INFINITY if a forbidden label sneaked in */
            if (en < energy - 1e-12 * fabs(energy)) {
                for (int i = 0; i < n; i++) L[i] = Lnew[i];
                energy = en;
                moves++;
            }
        }
        if (rc < 0 || s == 1 || !(energy < start - 1e-12 * fabs(start))) break;
    }
#undef UC
    free(e0); free(e1); free(Lnew);
    if (rc < 0) return rc;
    if (st) {
        potts_energy(n, s, U, ne, E, W, L, &st->unary, &st->binary);
        st->cycles = cycles;
        st->moves = moves;
    }
    return 0;
}
