/* modulus_match.c -- see modulus_match.h. */
#include "modulus_match.h"
#include "quad_modulus.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct state {
    int N, nc, nq;
    const int *n;
    int *corr;
    int (*quad)[4];              /* nq quadruples of rows, increasing */
    double *L;                   /* nq by N: log of the modulus estimate */
    int *byrow, *byrow_start;    /* the quadruples holding each row */
    struct quad_modulus **base;  /* N: each pose meshed once */
};

/* log modulus of quadruple r in pose s with row k at vertex v (k < 0: none moved) */
static int logmod(const struct state *m, int s, const int *r, int k, int v, double *out)
{
    int idx[4];
    for (int j = 0; j < 4; j++) idx[j] = r[j] == k ? v : m->corr[r[j] * m->N + s];
    struct quad_modulus *q = quad_modulus_recorner(m->base[s], idx);
    if (!q) return -1;
    double lo, hi;
    quad_modulus_bracket(q, &lo, &hi, NULL);
    quad_modulus_free(q);
    *out = 0.5 * (log(lo) + log(hi));
    return 0;
}

static double spread(const double *L, int N, int *smax, int *smin)
{
    int a = 0, b = 0;
    for (int s = 1; s < N; s++) {
        if (L[s] > L[a]) a = s;
        if (L[s] < L[b]) b = s;
    }
    if (smax) *smax = a;
    if (smin) *smin = b;
    return L[a] - L[b];
}

/* v strictly between the neighbouring rows of k in pose s (cyclic) */
static int in_order(const struct state *m, int k, int s, int v)
{
    int N = m->N, n = m->n[s], nc = m->nc;
    int a = m->corr[((k + nc - 1) % nc) * N + s], b = m->corr[((k + 1) % nc) * N + s];
    int da = ((v - a) % n + n) % n, db = ((b - a) % n + n) % n;
    return da > 0 && da < db;
}

static void state_free(struct state *m)
{
    if (m->base)
        for (int s = 0; s < m->N; s++) quad_modulus_free(m->base[s]);
    free(m->base); free(m->quad); free(m->L); free(m->byrow); free(m->byrow_start);
}

int modulus_match_polish(int N, double *const *P, const int *n, int *corr, int ncorr,
                         const unsigned char *pinned, int steps, int shift, double *before, double *after)
{
    if (before) *before = 1;
    if (after) *after = 1;
    if (N < 2 || ncorr < 4) return 0;
    long nq = (long)ncorr * (ncorr - 1) * (ncorr - 2) * (ncorr - 3) / 24;
    if (nq > 100000) return cm_seterr("%d correspondence points: too many quadruples to polish the matching", ncorr);
    struct state m = {.N = N, .nc = ncorr, .nq = (int)nq, .n = n, .corr = corr};
    m.quad = malloc(nq * sizeof *m.quad);
    m.L = malloc(nq * N * sizeof *m.L);
    m.byrow = malloc(4 * nq * sizeof *m.byrow);
    m.byrow_start = calloc(ncorr + 1, sizeof *m.byrow_start);
    m.base = calloc(N, sizeof *m.base);
    double *Lk = malloc(nq * sizeof *Lk);
    int *save = malloc(ncorr * N * sizeof *save), rc = -1, moves = 0;
    if (!m.quad || !m.L || !m.byrow || !m.byrow_start || !m.base || !Lk || !save) {
        cm_seterr("out of memory");
        goto out;
    }
    memcpy(save, corr, ncorr * N * sizeof *save);
    int q = 0;
    for (int a = 0; a < ncorr; a++)
        for (int b = a + 1; b < ncorr; b++)
            for (int c = b + 1; c < ncorr; c++)
                for (int d = c + 1; d < ncorr; d++) {
                    m.quad[q][0] = a; m.quad[q][1] = b; m.quad[q][2] = c; m.quad[q][3] = d;
                    for (int j = 0; j < 4; j++) m.byrow_start[m.quad[q][j] + 1]++;
                    q++;
                }
    for (int k = 0; k < ncorr; k++) m.byrow_start[k + 1] += m.byrow_start[k];
    {
        int *fill = calloc(ncorr, sizeof *fill);
        if (!fill) { cm_seterr("out of memory"); goto out; }
        for (q = 0; q < nq; q++)
            for (int j = 0; j < 4; j++) {
                int k = m.quad[q][j];
                m.byrow[m.byrow_start[k] + fill[k]++] = q;
            }
        free(fill);
    }
    for (int s = 0; s < N; s++) {
        int idx[4] = {corr[0 * N + s], corr[1 * N + s], corr[2 * N + s], corr[3 * N + s]};
        if (!(m.base[s] = quad_modulus_new(P[s], n[s], idx))) goto out;
        for (q = 0; q < nq; q++)
            if (logmod(&m, s, m.quad[q], -1, 0, &m.L[(size_t)q * N + s]) < 0) goto out;
    }
    double cur = 0;
    for (q = 0; q < nq; q++) cur = fmax(cur, spread(m.L + (size_t)q * N, N, NULL, NULL));
    if (before) *before = exp(cur);
    while (moves < steps) {
        /* the worst quadruple and its two poses */
        int w = 0, shi = 0, slo = 0;
        for (q = 1; q < nq; q++)
            if (spread(m.L + (size_t)q * N, N, NULL, NULL) > spread(m.L + (size_t)w * N, N, NULL, NULL)) w = q;
        spread(m.L + (size_t)w * N, N, &shi, &slo);
        int done = 0;
        for (int j = 0; j < 4 && !done; j++) {
            int k = m.quad[w][j];
            if (pinned && pinned[k]) continue;
            /* another quadruple as bad without row k: no move of k helps */
            double others = 0;
            for (q = 0; q < nq; q++)
                if (m.quad[q][0] != k && m.quad[q][1] != k && m.quad[q][2] != k && m.quad[q][3] != k)
                    others = fmax(others, spread(m.L + (size_t)q * N, N, NULL, NULL));
            if (others >= cur - 1e-9) continue;
            for (int t = 0; t < 2 && !done; t++) {
                int s = t ? slo : shi;
                for (int dd = 1; dd <= 2 * shift && !done; dd++) {
                    int d = dd % 2 ? (dd + 1) / 2 : -dd / 2, v = ((corr[k * N + s] + d) % n[s] + n[s]) % n[s];
                    if (!in_order(&m, k, s, v)) continue;
                    /* the worst quadruple first: most steps fail there */
                    int ok = 1;
                    double lw;
                    if (logmod(&m, s, m.quad[w], k, v, &lw) < 0) goto out;
                    double keep = m.L[(size_t)w * N + s];
                    m.L[(size_t)w * N + s] = lw;
                    double sw = spread(m.L + (size_t)w * N, N, NULL, NULL);
                    m.L[(size_t)w * N + s] = keep;
                    if (!(sw < cur - 1e-9)) continue;
                    /* then every other quadruple holding row k */
                    for (int i = m.byrow_start[k]; i < m.byrow_start[k + 1] && ok; i++) {
                        int qq = m.byrow[i];
                        if (qq == w) { Lk[i - m.byrow_start[k]] = lw; continue; }
                        double l;
                        if (logmod(&m, s, m.quad[qq], k, v, &l) < 0) goto out;
                        Lk[i - m.byrow_start[k]] = l;
                        double kp = m.L[(size_t)qq * N + s];
                        m.L[(size_t)qq * N + s] = l;
                        if (!(spread(m.L + (size_t)qq * N, N, NULL, NULL) < cur - 1e-9)) ok = 0;
                        m.L[(size_t)qq * N + s] = kp;
                    }
                    if (!ok) continue;
                    /* kept: the row moves, its quadruples take the new moduli */
                    corr[k * N + s] = v;
                    for (int i = m.byrow_start[k]; i < m.byrow_start[k + 1]; i++)
                        m.L[(size_t)m.byrow[i] * N + s] = Lk[i - m.byrow_start[k]];
                    cur = 0;
                    for (q = 0; q < nq; q++) cur = fmax(cur, spread(m.L + (size_t)q * N, N, NULL, NULL));
                    moves++;
                    done = 1;
                }
            }
        }
        if (!done) break;
    }
    if (after) *after = exp(cur);
    rc = moves;
out:
    if (rc < 0) memcpy(corr, save, ncorr * N * sizeof *corr);
    state_free(&m);
    free(Lk);
    free(save);
    return rc;
}
