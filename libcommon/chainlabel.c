/* chainlabel.c -- exact DP, alpha-expansion and swap on chain labelings.
 * See chainlabel.h for the energy. */
#include "chainlabel.h"
#include "big_alloc.h"
#include "graphcut.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static inline int linked(const struct chain *p, int f)
{
    if (f >= p->n - 1) return 0;
    return p->link ? p->link[f] != 0 : 1;
}

/* pair cost of labels (a, b) on pair (f, f+1) */
static inline double pair_cost(const struct chain *p, int f, int a, int b)
{
    if (!p->T && !p->H && !p->c && !(p->swap > 0)) return 0;
    double v = 0;
    if (p->c) v += p->c[f];
    if (p->T) v += p->T[(size_t)a * p->d + b];
    if (p->H) v += p->H[(size_t)f * p->d + b] - p->H[(size_t)f * p->d + a];
    if (p->swap > 0 && a != b) v += p->swap;
    return v;
}

int chain_swaps(const struct chain *p, const int *l)
{
    int s = 0;
    for (int f = 0; f + 1 < p->n; f++) s += linked(p, f) && l[f] != l[f + 1];
    return s;
}

double chain_energy(const struct chain *p, const int *l, double *unary, double *pair)
{
    double eu = 0, ep = 0;
    for (int f = 0; f < p->n; f++) {
        eu += p->U[(size_t)f * p->d + l[f]];
        if (linked(p, f)) ep += pair_cost(p, f, l[f], l[f + 1]);
    }
    if (unary) *unary = eu;
    if (pair) *pair = ep;
    return eu + ep;
}

/* Vn[b] = min_a (h[a] + T[a][b]) for a symmetric T: a vectorizable
 * min-plus product (no argmin in the hot loop; the backtrack recomputes it). */
__attribute__((optimize("tree-vectorize"), target_clones("avx512f", "avx2", "default")))
static void minplus(const double *restrict h, const double *restrict T, int d, double *restrict Vn)
{
    for (int b = 0; b < d; b++) Vn[b] = INFINITY;
    for (int a = 0; a < d; a++) {
        const double *restrict Ta = T + (size_t)a * d;
        double ha = h[a];
        for (int b = 0; b < d; b++) {
            double v = ha + Ta[b];
            Vn[b] = v < Vn[b] ? v : Vn[b];
        }
    }
}

double chain_dp(const struct chain *p, int *l)
{
    int n = p->n, d = p->d;
    double *V = malloc(sizeof(double) * d);
    double *Vn = malloc(sizeof(double) * d);
    double *hs = big_alloc(sizeof(double) * (size_t)n * d);   /* h of every frame, for the backtrack */
    if (!V || !Vn || !hs) {
        free(V); free(Vn); free(hs);
        cm_seterr("chain_dp: out of memory (%d frames, %d labels)", n, d);
        return NAN;
    }
    double total = 0;
    int start = 0;
    while (start < n) {
        int end = start;                       /* clip is start..end */
        while (linked(p, end)) end++;
        for (int a = 0; a < d; a++) V[a] = p->U[(size_t)start * d + a];
        for (int f = start; f < end; f++) {
            /* V'[b] = U[f+1][b] + c + H[f][b] + min_a (V[a] - H[f][a] + T[a][b]) */
            const double *Hf = p->H ? p->H + (size_t)f * d : NULL;
            double *h = hs + (size_t)f * d;
            for (int a = 0; a < d; a++) h[a] = V[a] - (Hf ? Hf[a] : 0);
            double cf = p->c ? p->c[f] : 0;
            if (p->T) minplus(h, p->T, d, Vn);
            else {
                double m = h[0];
                for (int a = 1; a < d; a++) if (h[a] < m) m = h[a];
                for (int b = 0; b < d; b++) Vn[b] = m;
            }
            if (p->swap > 0)    /* staying costs T_bb = 0, any change costs swap more */
                for (int b = 0; b < d; b++) {
                    double v = Vn[b] + p->swap;
                    Vn[b] = h[b] < v ? h[b] : v;
                }
            const double *Un = p->U + (size_t)(f + 1) * d;
            for (int b = 0; b < d; b++) V[b] = Vn[b] + Un[b] + cf + (Hf ? Hf[b] : 0);
        }
        int best = 0;
        for (int a = 1; a < d; a++) if (V[a] < V[best]) best = a;
        total += V[best];
        l[end] = best;
        for (int f = end - 1; f >= start; f--) {
            /* argmin_a h_f[a] + T[a][l_{f+1}], lowest a on ties */
            const double *h = hs + (size_t)f * d;
            int b = l[f + 1], am = 0;
            double m = INFINITY;
            for (int a = 0; a < d; a++) {
                double v = h[a] + (p->T ? p->T[(size_t)a * d + b] : 0);
                if (p->swap > 0 && a != b) v += p->swap;
                if (v < m) { m = v; am = a; }
            }
            l[f] = am;
        }
        start = end + 1;
    }
    free(V); free(Vn); free(hs);
    return total;
}

/* Add the binary term E(x_i, x_j) with table (A, B, C, D) = E00, E01, E10,
 * E11 (x = 1: sink side) to g; requires B + C >= A + D. */
static void add_pair(struct graphcut *g, int i, int j, double A, double B, double C, double D)
{
    /* E = A + (C-A) x_i + (D-C) x_j + (B+C-A-D) (1-x_i) x_j */
    double ui = C - A, uj = D - C, w = B + C - A - D;
    if (ui > 0) graphcut_add_tweights(g, i, ui, 0); else graphcut_add_tweights(g, i, 0, -ui);
    if (uj > 0) graphcut_add_tweights(g, j, uj, 0); else graphcut_add_tweights(g, j, 0, -uj);
    if (w < 0) w = 0;   /* rounding only: callers guarantee B + C >= A + D */
    graphcut_add_edge(g, i, j, w, 0);
}

static void add_unary(struct graphcut *g, int i, double e0, double e1)
{
    /* node on sink side (x = 1) pays cap_source, source side pays cap_sink */
    graphcut_add_tweights(g, i, e1, e0);
}

double chain_expansion(const struct chain *p, int *l, int max_sweeps, long *ntrunc)
{
    int n = p->n, d = p->d;
    if (max_sweeps <= 0) max_sweeps = 20;
    long nt = 0;
    double E = chain_energy(p, l, NULL, NULL);
    int *nl = malloc(sizeof(int) * n);
    if (!nl) { cm_seterr("chain_expansion: out of memory"); return NAN; }
    for (int sweep = 0; sweep < max_sweeps; sweep++) {
        int improved = 0;
        for (int alpha = 0; alpha < d; alpha++) {
            struct graphcut *g = graphcut_new(n, n);
            if (!g) { free(nl); cm_seterr("chain_expansion: out of memory"); return NAN; }
            for (int f = 0; f < n; f++)
                add_unary(g, f, p->U[(size_t)f * d + l[f]], p->U[(size_t)f * d + alpha]);
            for (int f = 0; f + 1 < n; f++) {
                if (!linked(p, f)) continue;
                int a = l[f], b = l[f + 1];
                double A = pair_cost(p, f, a, b), B = pair_cost(p, f, a, alpha);
                double C = pair_cost(p, f, alpha, b), D = pair_cost(p, f, alpha, alpha);
                double excess = A + D - B - C;
                if (excess > 0) {
                    /* truncation: raise E01 and E10 (upper bound, exact at x = 0) */
                    B += 0.5 * excess; C += 0.5 * excess;
                    nt++;
                }
                add_pair(g, f, f + 1, A, B, C, D);
            }
            graphcut_maxflow(g);
            for (int f = 0; f < n; f++) nl[f] = graphcut_side(g, f) ? alpha : l[f];
            graphcut_free(g);
            double En = chain_energy(p, nl, NULL, NULL);
            if (En < E - 1e-12 * fabs(E)) {
                memcpy(l, nl, sizeof(int) * n);
                E = En;
                improved = 1;
            }
        }
        if (!improved) break;
    }
    free(nl);
    if (ntrunc) *ntrunc = nt;
    return E;
}

double chain_swap(const struct chain *p, int *l, int max_sweeps)
{
    int n = p->n, d = p->d;
    if (max_sweeps <= 0) max_sweeps = 20;
    double E = chain_energy(p, l, NULL, NULL);
    int *nl = malloc(sizeof(int) * n), *idx = malloc(sizeof(int) * n);
    if (!nl || !idx) { free(nl); free(idx); cm_seterr("chain_swap: out of memory"); return NAN; }
    for (int sweep = 0; sweep < max_sweeps; sweep++) {
        int improved = 0;
        for (int al = 0; al < d; al++)
            for (int be = al + 1; be < d; be++) {
                int k = 0;
                for (int f = 0; f < n; f++) idx[f] = (l[f] == al || l[f] == be) ? k++ : -1;
                if (k == 0) continue;
                struct graphcut *g = graphcut_new(k, k);
                if (!g) { free(nl); free(idx); cm_seterr("chain_swap: out of memory"); return NAN; }
                /* x = 0: alpha, x = 1: beta */
                for (int f = 0; f < n; f++) {
                    if (idx[f] < 0) continue;
                    double e0 = p->U[(size_t)f * d + al], e1 = p->U[(size_t)f * d + be];
                    if (f > 0 && linked(p, f - 1) && idx[f - 1] < 0) {
                        e0 += pair_cost(p, f - 1, l[f - 1], al);
                        e1 += pair_cost(p, f - 1, l[f - 1], be);
                    }
                    if (linked(p, f) && idx[f + 1] < 0) {
                        e0 += pair_cost(p, f, al, l[f + 1]);
                        e1 += pair_cost(p, f, be, l[f + 1]);
                    }
                    add_unary(g, idx[f], e0, e1);
                    if (linked(p, f) && idx[f + 1] >= 0)
                        add_pair(g, idx[f], idx[f + 1], pair_cost(p, f, al, al), pair_cost(p, f, al, be),
                                 pair_cost(p, f, be, al), pair_cost(p, f, be, be));
                }
                graphcut_maxflow(g);
                memcpy(nl, l, sizeof(int) * n);
                for (int f = 0; f < n; f++)
                    if (idx[f] >= 0) nl[f] = graphcut_side(g, idx[f]) ? be : al;
                graphcut_free(g);
                double En = chain_energy(p, nl, NULL, NULL);
                if (En < E - 1e-12 * fabs(E)) {
                    memcpy(l, nl, sizeof(int) * n);
                    E = En;
                    improved = 1;
                }
            }
        if (!improved) break;
    }
    free(nl); free(idx);
    return E;
}
