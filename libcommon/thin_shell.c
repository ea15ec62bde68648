/* thin_shell.c -- see thin_shell.h */
#include "thin_shell.h"
#include "cm_error.h"
#include "geometry.h"
#include "polar.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct thin_shell {
    int nv, nf, ne, nb, nh, nres, use_vol;
    int *F;
    int *E;            /* ne by 2 */
    double *L0, *ws;   /* rest length, sqrt stretch weight */
    int *B;            /* nb by 4: a, b (shared edge a->b in face 1), o1, o2 */
    double *th0, *wb;  /* rest angle, sqrt bend weight incl. L/sqrt(A/3) */
    double *fl;        /* nb by 2: floors of |n1|^2, |n2|^2 in the bend gradient */
    double *vol0, o[3], wv;
    double V0, wg;     /* rest enclosed volume, sqrt global volume weight / |V0| */
    int *H;
    double wl;         /* sqrt(lambda kbar) / Lbar */
    double damping, mu, mu0;   /* damping: relative; mu: current, mu0: first */
    struct spd_solver *S;
    cholmod_sparse *A;  /* J^T J + mu I (upper), pattern fixed after the first iteration */
    int *pos;           /* position in A->x of every contribution */
};

void thin_shell_defaults(struct thin_shell_params *p)
{
    *p = (struct thin_shell_params){0};   /* every field set, the ones not named below 0 */
    p->ks = 1; p->kb = 1; p->kv = 0.1; p->kvg = 10; p->lambda = 100; p->damping = 1e-6;
}

static double face_area3(const double *a, const double *b, const double *c)
{
    double u[3], v[3], n[3];
    sub3(b, a, u); sub3(c, a, v); cross3(u, v, n);
    return 0.5 * norm3(n);
}

static double tet_volume(const double *a, const double *b, const double *c, const double *o,
                         double *ga, double *gb, double *gc)
{
    double A[3], B[3], C[3], x[3];
    sub3(a, o, A); sub3(b, o, B); sub3(c, o, C);
    cross3(B, C, x);
    if (ga) {
        for (int d = 0; d < 3; d++) ga[d] = x[d] / 6;
        double y[3];
        cross3(C, A, y); for (int d = 0; d < 3; d++) gb[d] = y[d] / 6;
        cross3(A, B, y); for (int d = 0; d < 3; d++) gc[d] = y[d] / 6;
    }
    return dot3(A, x) / 6;
}

/* Signed dihedral angle of edge x3 -> x4 between triangle (x3, x4, x1) and
 * (x4, x3, x2) (both outward), 0 when flat; gradient (Bridson et al. 2003)
 * g: 4 by 3 for x1, x2, x3, x4 (zero when degenerate). */
static double dihedral(const double *x1, const double *x2, const double *x3, const double *x4,
                       double *g, double f1, double f2)
{
    double p[3], q[3], n1[3], n2[3], E[3];
    sub3(x1, x3, p); sub3(x1, x4, q); cross3(p, q, n1);
    sub3(x2, x4, p); sub3(x2, x3, q); cross3(p, q, n2);
    sub3(x4, x3, E);
    double l1 = dot3(n1, n1), l2 = dot3(n2, n2), le = norm3(E);
    if (g) memset(g, 0, 12 * sizeof *g);
    if (!(l1 > 0 && l2 > 0 && le > 0)) return 0;
    double m = sqrt(l1 * l2), c = dot3(n1, n2) / m, x[3];
    cross3(n1, n2, x);
    double s = dot3(x, E) / (m * le);
    double th = atan2(s, c);
    if (g) {
        double d1[3], d2[3];
        sub3(x1, x4, p); sub3(x2, x4, q);
        double a14 = dot3(p, E) / le, a24 = dot3(q, E) / le;
        sub3(x1, x3, p); sub3(x2, x3, q);
        double a13 = dot3(p, E) / le, a23 = dot3(q, E) / le;
        double c1 = l1 > f1 ? l1 : f1, c2 = l2 > f2 ? l2 : f2;
        for (int d = 0; d < 3; d++) { d1[d] = n1[d] / c1; d2[d] = n2[d] / c2; }
        for (int d = 0; d < 3; d++) {
            g[0 + d] = -le * d1[d];
            g[3 + d] = -le * d2[d];
            g[6 + d] = -(a14 * d1[d] + a24 * d2[d]);
            g[9 + d] = (a13 * d1[d] + a23 * d2[d]);
        }
    }
    return th;
}

static double wrap(double a)
{
    while (a > M_PI) a -= 2 * M_PI;
    while (a <= -M_PI) a += 2 * M_PI;
    return a;
}

struct thin_shell *thin_shell_new(const double *V, const int *F, int nv, int nf,
                                  const double *k, const int *H, int nh,
                                  const struct thin_shell_params *p)
{
    struct thin_shell_params dp;
    if (!p) { thin_shell_defaults(&dp); p = &dp; }
    for (int h = 0; h < nh; h++)
        if (H[h] < 0 || H[h] >= nv) {
            cm_seterr("landmark %d: vertex %d out of range 0..%d", h + 1, H[h], nv - 1);
            return NULL;
        }
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return NULL;
    struct thin_shell *s = calloc(1, sizeof *s);
    s->nv = nv; s->nf = nf; s->ne = t.ne; s->nh = nh;
    s->F = malloc((size_t)nf * 3 * sizeof *s->F + 1);
    memcpy(s->F, F, (size_t)nf * 3 * sizeof *s->F);
    s->E = malloc((size_t)t.ne * 2 * sizeof *s->E + 1);
    memcpy(s->E, t.E, (size_t)t.ne * 2 * sizeof *s->E);
    s->L0 = malloc((size_t)t.ne * sizeof *s->L0 + 1);
    s->ws = malloc((size_t)t.ne * sizeof *s->ws + 1);
    s->B = malloc((size_t)t.ne * 4 * sizeof *s->B + 1);
    s->th0 = malloc((size_t)t.ne * sizeof *s->th0 + 1);
    s->wb = malloc((size_t)t.ne * sizeof *s->wb + 1);
    s->fl = malloc((size_t)t.ne * 2 * sizeof *s->fl + 1);
    double lbar = 0;
    for (int e = 0; e < t.ne; e++) {
        int i = t.E[2 * e], j = t.E[2 * e + 1];
        double ke = k ? 0.5 * (k[i] + k[j]) : 1;
        s->L0[e] = dist3(V + 3 * i, V + 3 * j);
        lbar += s->L0[e] / t.ne;
        s->ws[e] = s->L0[e] > 0 ? sqrt(p->ks * ke) / s->L0[e] : 0;
        if (t.EFn[e] != 2 || !(p->kb > 0)) continue;
        int f1 = t.EF[2 * e], f2 = t.EF[2 * e + 1];
        /* orient: a -> b as in f1, o1 opposite in f1, o2 opposite in f2 */
        int a = -1, b = -1, o1 = -1, o2 = -1, ok = 0;
        for (int q = 0; q < 3; q++) {
            int u = F[3 * f1 + q], w = F[3 * f1 + (q + 1) % 3];
            if ((u == i && w == j) || (u == j && w == i)) { a = u; b = w; o1 = F[3 * f1 + (q + 2) % 3]; }
        }
        for (int q = 0; q < 3; q++) {
            int u = F[3 * f2 + q], w = F[3 * f2 + (q + 1) % 3];
            if (u == b && w == a) { o2 = F[3 * f2 + (q + 2) % 3]; ok = 1; }
        }
        if (!ok || o1 < 0 || o1 == o2) continue;    /* inconsistent orientation: no bending */
        double A = face_area3(V + 3 * F[3 * f1], V + 3 * F[3 * f1 + 1], V + 3 * F[3 * f1 + 2]) +
                   face_area3(V + 3 * F[3 * f2], V + 3 * F[3 * f2 + 1], V + 3 * F[3 * f2 + 2]);
        if (!(A > 0)) continue;
        int *Bq = s->B + 4 * s->nb;
        Bq[0] = a; Bq[1] = b; Bq[2] = o1; Bq[3] = o2;
        s->th0[s->nb] = dihedral(V + 3 * o1, V + 3 * o2, V + 3 * a, V + 3 * b, NULL, 0, 0);
        {
            double p[3], q[3], n1[3];
            sub3(V + 3 * o1, V + 3 * a, p); sub3(V + 3 * o1, V + 3 * b, q); cross3(p, q, n1);
            s->fl[2 * s->nb] = 1e-2 * dot3(n1, n1);
            sub3(V + 3 * o2, V + 3 * b, p); sub3(V + 3 * o2, V + 3 * a, q); cross3(p, q, n1);
            s->fl[2 * s->nb + 1] = 1e-2 * dot3(n1, n1);
        }
        s->wb[s->nb] = sqrt(p->kb * ke) * s->L0[e] / sqrt(A / 3);
        s->nb++;
    }
    topology_free(&t);
    s->use_vol = p->kv > 0;
    s->vol0 = malloc((size_t)nf * sizeof *s->vol0 + 1);
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++) s->o[d] += V[3 * v + d] / nv;
    double vbar = 0;
    for (int f = 0; f < nf; f++) {
        s->vol0[f] = tet_volume(V + 3 * F[3 * f], V + 3 * F[3 * f + 1], V + 3 * F[3 * f + 2], s->o,
                                NULL, NULL, NULL);
        vbar += fabs(s->vol0[f]) / nf;
    }
    double kbar = 0;
    for (int v = 0; v < nv; v++) kbar += (k ? k[v] : 1) / nv;
    s->wv = vbar > 0 ? sqrt(p->kv * kbar) / vbar : 0;
    s->V0 = 0;
    for (int f = 0; f < nf; f++) s->V0 += s->vol0[f];
    s->wg = p->kvg > 0 && s->V0 != 0 ? sqrt(p->kvg * kbar * nf) / fabs(s->V0) : 0;
    if (!(vbar > 0)) s->use_vol = 0;
    s->H = malloc((size_t)nh * sizeof *s->H + 1);
    memcpy(s->H, H, (size_t)nh * sizeof *s->H);
    /* the landmark term scales with the mean stiffness like the volume
     * terms (thesis: "weighted proportional to the stretch and bend
     * stiffnesses"), so only the shape of the stiffness map matters, not
     * its scale: k and 10 k give the same deformation */
    s->wl = lbar > 0 ? sqrt(p->lambda * kbar) / lbar : 0;
    s->damping = p->damping;
    s->nres = s->ne + s->nb + (s->use_vol ? nf : 0) + 3 * nh;
    return s;
}

void thin_shell_free(struct thin_shell *s)
{
    if (!s) return;
    spd_free(s->S);
    sparse_free(&s->A);
    free(s->pos);
    free(s->F); free(s->E); free(s->L0); free(s->ws); free(s->B); free(s->th0); free(s->wb); free(s->fl);
    free(s->vol0); free(s->H);
    free(s);
}

int thin_shell_nres(const struct thin_shell *s) { return s->nres; }

double thin_shell_residuals(const struct thin_shell *s, const double *X, const double *T,
                            double *r, int *idx, double *g)
{
    int q = 0;
    double E = 0;
    if (idx) for (int i = 0; i < 4 * s->nres; i++) idx[i] = -1;
    if (g) memset(g, 0, (size_t)12 * s->nres * sizeof *g);
    for (int e = 0; e < s->ne; e++, q++) {
        int i = s->E[2 * e], j = s->E[2 * e + 1];
        double d[3];
        sub3(X + 3 * i, X + 3 * j, d);
        double l = norm3(d);
        r[q] = s->ws[e] * (l - s->L0[e]);
        if (idx) {
            idx[4 * q] = i; idx[4 * q + 1] = j;
            for (int c = 0; c < 3 && l > 0; c++) {
                g[12 * q + c] = s->ws[e] * d[c] / l;
                g[12 * q + 3 + c] = -s->ws[e] * d[c] / l;
            }
        }
    }
    for (int b = 0; b < s->nb; b++, q++) {
        const int *Bq = s->B + 4 * b;
        double gg[12];
        double th = dihedral(X + 3 * Bq[2], X + 3 * Bq[3], X + 3 * Bq[0], X + 3 * Bq[1], idx ? gg : NULL,
                             s->fl[2 * b], s->fl[2 * b + 1]);
        r[q] = s->wb[b] * wrap(th - s->th0[b]);
        if (idx) {
            idx[4 * q] = Bq[2]; idx[4 * q + 1] = Bq[3]; idx[4 * q + 2] = Bq[0]; idx[4 * q + 3] = Bq[1];
            for (int c = 0; c < 12; c++) g[12 * q + c] = s->wb[b] * gg[c];
        }
    }
    if (s->use_vol)
        for (int f = 0; f < s->nf; f++, q++) {
            const int *Fq = s->F + 3 * f;
            double *gq = g ? g + 12 * q : NULL;
            double v = tet_volume(X + 3 * Fq[0], X + 3 * Fq[1], X + 3 * Fq[2], s->o,
                                  gq, gq ? gq + 3 : NULL, gq ? gq + 6 : NULL);
            r[q] = s->wv * (v - s->vol0[f]);
            if (idx) {
                for (int a = 0; a < 3; a++) idx[4 * q + a] = Fq[a];
                for (int c = 0; c < 9; c++) gq[c] *= s->wv;
            }
        }
    for (int h = 0; h < s->nh; h++)
        for (int d = 0; d < 3; d++, q++) {
            r[q] = s->wl * (X[3 * s->H[h] + d] - T[3 * h + d]);
            if (idx) { idx[4 * q] = s->H[h]; g[12 * q + d] = s->wl; }
        }
    for (int i = 0; i < q; i++) E += 0.5 * r[i] * r[i];
    return E;
}

double thin_shell_volume_residual(const struct thin_shell *s, const double *X, double *grad)
{
    if (grad) memset(grad, 0, (size_t)3 * s->nv * sizeof *grad);
    if (s->wg == 0) return 0;
    double v = 0;
    for (int f = 0; f < s->nf; f++) {
        const int *Fq = s->F + 3 * f;
        double g[9];
        v += tet_volume(X + 3 * Fq[0], X + 3 * Fq[1], X + 3 * Fq[2], s->o, g, g + 3, g + 6);
        if (grad)
            for (int a = 0; a < 3; a++)
                for (int d = 0; d < 3; d++) grad[3 * Fq[a] + d] += s->wg * g[3 * a + d];
    }
    return s->wg * (v - s->V0);
}

double thin_shell_energy(const struct thin_shell *s, const double *X, const double *T)
{
    double *r = malloc((size_t)s->nres * sizeof *r + 1);
    double E = thin_shell_residuals(s, X, T, r, NULL, NULL), rg = thin_shell_volume_residual(s, X, NULL);
    free(r);
    return E + 0.5 * rg * rg;
}

/* J^T J (upper triangle) + mu I, and J^T r.  The contributions come in the
 * same order every iteration: the first time into triplets T, afterwards
 * straight into Ax at the positions pos found for them in the matrix. */
static void normal_equations(const struct thin_shell *s, const double *r, const int *idx,
                             const double *g, double mu, double *b, struct triplets *T,
                             const int *pos, double *Ax)
{
    int n = 3 * s->nv;
    size_t k = 0;
    memset(b, 0, (size_t)n * sizeof *b);
    for (int q = 0; q < s->nres; q++) {
        const int *iq = idx + 4 * q;
        const double *gq = g + 12 * q;
        for (int a = 0; a < 4; a++) {
            if (iq[a] < 0) continue;
            for (int da = 0; da < 3; da++) {
                int row = 3 * iq[a] + da;
                b[row] += gq[3 * a + da] * r[q];
                for (int c = 0; c < 4; c++) {
                    if (iq[c] < 0) continue;
                    for (int dc = 0; dc < 3; dc++) {
                        int col = 3 * iq[c] + dc;
                        if (row > col) continue;
                        double v = gq[3 * a + da] * gq[3 * c + dc];
                        if (T) triplets_add(T, row, col, v);
                        else Ax[pos[k]] += v;
                        k++;
                    }
                }
            }
        }
    }
    for (int i = 0; i < n; i++, k++) {
        if (T) triplets_add(T, i, i, mu);
        else Ax[pos[k]] += mu;
    }
}

/* position of every triplet in the compressed-column matrix A */
static int *triplet_positions(const struct triplets *T, const cholmod_sparse *A)
{
    const int *Ap = A->p, *Ai = A->i;
    int *pos = malloc(T->nnz * sizeof *pos + 1);
    for (size_t k = 0; k < T->nnz; k++) {
        int j = T->j[k], i = T->i[k], lo = Ap[j], hi = Ap[j + 1] - 1, at = -1;
        if (A->sorted)
            while (lo <= hi) {
                int m = (lo + hi) / 2;
                if (Ai[m] == i) { at = m; break; }
                if (Ai[m] < i) lo = m + 1; else hi = m - 1;
            }
        else
            for (int m = lo; m <= hi; m++) if (Ai[m] == i) { at = m; break; }
        if (at < 0) { free(pos); return NULL; }
        pos[k] = at;
    }
    return pos;
}

/* The apex o of the per-face tetrahedra that fits X best: every tetrahedron
 * volume is affine in o, vol_f(X, o) = c_f - o . n_f / 6 with
 * c_f = x_a . (x_b x x_c) / 6 and n_f = x_a x x_b + x_b x x_c + x_c x x_a,
 * so o = argmin wv^2 sum_f (vol_f(X, o) - vol_f(V))^2 (+ the enclosed-volume
 * residual, which depends on o only for open meshes) is a 3 by 3 least
 * squares problem.  Moving o there before every Gauss-Newton iteration
 * (alternating minimization, so E still never increases) makes the volume
 * terms blind to rigid motions: X = R V + t has o = R o0 + t and zero
 * residuals.  With a fixed apex a rigid translation or a rotation about
 * any other point than o changes the tetrahedra and is resisted.
 * A tiny Tikhonov term toward the current o keeps flat meshes determined. */
static void fit_apex(struct thin_shell *s, const double *X)
{
    if (!s->use_vol) return;
    double M[9] = {0}, rhs[3] = {0}, Mi[9], tr = 0;
    double ng[3] = {0}, cg = 0;
    for (int f = 0; f < s->nf; f++) {
        const double *a = X + 3 * s->F[3 * f], *b = X + 3 * s->F[3 * f + 1], *c = X + 3 * s->F[3 * f + 2];
        double x[3], n[3], y[3];
        cross3(b, c, x);
        double cf = dot3(a, x) / 6;
        cross3(a, b, n);
        cross3(c, a, y);
        for (int d = 0; d < 3; d++) n[d] = (n[d] + x[d] + y[d]) / 6;
        double w2 = s->wv * s->wv, res = cf - s->vol0[f];
        for (int r = 0; r < 3; r++) {
            rhs[r] += w2 * n[r] * res;
            for (int q = 0; q < 3; q++) M[3 * r + q] += w2 * n[r] * n[q];
        }
        for (int d = 0; d < 3; d++) ng[d] += n[d];
        cg += cf;
    }
    if (s->wg != 0) {      /* enclosed-volume residual wg (cg - ng . o - V0) */
        double w2 = s->wg * s->wg;
        for (int r = 0; r < 3; r++) {
            rhs[r] += w2 * ng[r] * (cg - s->V0);
            for (int q = 0; q < 3; q++) M[3 * r + q] += w2 * ng[r] * ng[q];
        }
    }
    tr = M[0] + M[4] + M[8];
    if (!(tr > 0)) return;
    for (int d = 0; d < 3; d++) { M[4 * d] += 1e-9 * tr; rhs[d] += 1e-9 * tr * s->o[d]; }
    if (mat3_inverse(M, Mi) < 0) return;
    for (int r = 0; r < 3; r++) s->o[r] = Mi[3 * r] * rhs[0] + Mi[3 * r + 1] * rhs[1] + Mi[3 * r + 2] * rhs[2];
}

int thin_shell_solve(struct thin_shell *s, const double *T, int iters, double *X, double *Eout)
{
    int n = 3 * s->nv, rc = 0;
    double *r = malloc((size_t)s->nres * sizeof *r + 1), *g = malloc((size_t)s->nres * 12 * sizeof *g + 1);
    int *idx = malloc((size_t)s->nres * 4 * sizeof *idx + 1);
    double *b = malloc((size_t)n * sizeof *b + 1), *dx = malloc((size_t)n * sizeof *dx + 1);
    double *Xt = malloc((size_t)n * sizeof *Xt + 1), *gG = malloc((size_t)n * sizeof *gG + 1);
    double *B2 = malloc((size_t)n * 2 * sizeof *B2 + 1);
    fit_apex(s, X);
    double rG = thin_shell_volume_residual(s, X, gG);
    double E = thin_shell_residuals(s, X, T, r, idx, g) + 0.5 * rG * rG;
    if (Eout) Eout[0] = E;
    int done = 0;
    for (int it = 0; it < iters; it++) {
        if (done) { if (Eout) Eout[it + 1] = E; continue; }
        if (s->mu == 0) {
            /* damping scale from the first J^T J's mean diagonal */
            double tr = 0;
            for (int q = 0; q < s->nres; q++)
                for (int c = 0; c < 12; c++) tr += g[12 * q + c] * g[12 * q + c];
            s->mu = s->damping * (tr > 0 ? tr / n : 1);
            if (!(s->mu > 0)) s->mu = 1e-12;
            s->mu0 = s->mu;
        }
        /* Levenberg: a J^T J that CHOLMOD finds numerically singular (a
         * triangle nearly collapsed makes its bend gradient huge) is
         * retried with 100 times the damping, up to 6 times; the damping
         * relaxes back by 10 per accepted step */
        int ok = 0;
        for (int tries = 0; tries < 7 && !ok && rc == 0; tries++) {
            if (tries) s->mu *= 100;
            if (!s->A) {
                struct triplets T;
                triplets_init(&T, n, n);
                normal_equations(s, r, idx, g, s->mu, b, &T, NULL, NULL);
                s->A = triplets_to_sparse(&T, 1);
                s->pos = triplet_positions(&T, s->A);
                triplets_free(&T);
                if (!s->pos) { rc = -1; cm_seterr("thin shell: lost a matrix entry"); break; }
            } else {
                memset(s->A->x, 0, ((int *)s->A->p)[n] * sizeof(double));
                normal_equations(s, r, idx, g, s->mu, b, NULL, s->pos, s->A->x);
            }
            if (!s->S) {
                s->S = spd_factor(s->A);
                ok = s->S != NULL;
            } else
                ok = spd_refactor(s->S, s->A) == 0;
        }
        if (rc < 0) break;
        if (!ok) { rc = -1; break; }
        if (s->wg == 0) {
            if (spd_solve(s->S, b, dx, 1) < 0) { rc = -1; break; }
        } else {
            /* the global volume row is dense: (A + gG gG^T) dx = b + gG rG
             * by Sherman-Morrison from A^-1 [b + gG rG, gG] */
            for (int i = 0; i < n; i++) { B2[2 * i] = b[i] + gG[i] * rG; B2[2 * i + 1] = gG[i]; }
            if (spd_solve(s->S, B2, B2, 2) < 0) { rc = -1; break; }
            double gy = 0, gz = 0;
            for (int i = 0; i < n; i++) { gy += gG[i] * B2[2 * i]; gz += gG[i] * B2[2 * i + 1]; }
            for (int i = 0; i < n; i++) dx[i] = B2[2 * i] - B2[2 * i + 1] * gy / (1 + gz);
        }
        double alpha = 1, En = E;
        int accepted = 0;
        for (int ls = 0; ls < 30; ls++, alpha *= 0.5) {
            for (int i = 0; i < n; i++) Xt[i] = X[i] - alpha * dx[i];
            En = thin_shell_energy(s, Xt, T);
            if (En < E) { accepted = 1; break; }
        }
        if (!accepted) { done = 1; if (Eout) Eout[it + 1] = E; continue; }
        memcpy(X, Xt, (size_t)n * sizeof *X);
        if (s->mu > s->mu0) s->mu = s->mu / 10 > s->mu0 ? s->mu / 10 : s->mu0;
        double Eold = E;
        fit_apex(s, X);
        rG = thin_shell_volume_residual(s, X, gG);
        E = thin_shell_residuals(s, X, T, r, idx, g) + 0.5 * rG * rG;
        if (Eout) Eout[it + 1] = E;
        if (Eold - E <= 1e-6 * Eold) done = 1;
    }
    free(r); free(g); free(idx); free(b); free(dx); free(Xt); free(gG); free(B2);
    return rc;
}
