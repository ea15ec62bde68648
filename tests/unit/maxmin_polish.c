/* maxmin_polish.c -- the global max-min polish of one planar mesh: on a
 * jittered grid (interior vertices free, the bottom side's inner vertices
 * sliding along it, the rest fixed) the smallest angle rises, every
 * triangle stays positive by the exact predicate, fixed vertices keep
 * their bits, sliding ones stay on their side, the same bytes twice; a
 * mesh with no free vertex is left alone. */
#include "maxmin_polish.h"
#include "predicates2.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define K 9   /* vertices per side */

static unsigned long long rs = 12345;
static double rnd(void)   /* deterministic, in [0, 1) */
{
    rs = rs * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rs >> 11) / 9007199254740992.0;
}

static double min_angle(const double *X, const int *F, int nf)
{
    double m = INFINITY;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            const double *o = X + 2 * F[3 * f + k], *u = X + 2 * F[3 * f + (k + 1) % 3], *w = X + 2 * F[3 * f + (k + 2) % 3];
            double ax = u[0] - o[0], ay = u[1] - o[1], bx = w[0] - o[0], by = w[1] - o[1];
            m = fmin(m, atan2(fabs(ax * by - ay * bx), ax * bx + ay * by));
        }
    return m;
}

int main(void)
{
    int nv = K * K, nf = 2 * (K - 1) * (K - 1);
    double X[2 * K * K], X0[2 * K * K], X2[2 * K * K];
    int F[6 * (K - 1) * (K - 1)], seg[2 * K * K];
    unsigned char fixed[K * K];
    int f = 0;
    for (int j = 0; j < K; j++)
        for (int i = 0; i < K; i++) {
            int v = j * K + i;
            int side = i == 0 || j == 0 || i == K - 1 || j == K - 1;
            X[2 * v] = i + (side ? 0 : 0.7 * (rnd() - 0.5));
            X[2 * v + 1] = j + (side ? 0 : 0.7 * (rnd() - 0.5));
            fixed[v] = side;
            seg[2 * v] = seg[2 * v + 1] = -1;
            if (j == 0 && i > 0 && i < K - 1) { seg[2 * v] = 0; seg[2 * v + 1] = K - 1; }
            if (i < K - 1 && j < K - 1) {   /* alternate diagonals */
                int a = v, b = v + 1, c = v + K + 1, d = v + K;
                if ((i + j) & 1) { int t[6] = {a, b, d, b, c, d}; memcpy(F + 3 * f, t, sizeof t); }
                else { int t[6] = {a, b, c, a, c, d}; memcpy(F + 3 * f, t, sizeof t); }
                f += 2;
            }
        }
    memcpy(X0, X, sizeof X);
    struct maxmin_params p;
    maxmin_defaults(&p);
    double before, after;
    int rc = maxmin_polish(X, nv, F, nf, fixed, seg, &p, &before, &after);
    diag("jittered grid: smallest angle %.3f -> %.3f deg", before * 180 / M_PI, after * 180 / M_PI);
    ok(rc == 1, "the jittered grid moved");
    ok(fabs(before - min_angle(X0, F, nf)) < 1e-12 && fabs(after - min_angle(X, F, nf)) < 1e-12,
       "before and after are the meshes' smallest angles");
    ok(after > before + 5 * M_PI / 180, "the smallest angle rose by more than 5 degrees");
    int pos = 1;
    for (int k = 0; k < nf; k++) pos &= orient2_sign(X + 2 * F[3 * k], X + 2 * F[3 * k + 1], X + 2 * F[3 * k + 2]) > 0;
    ok(pos, "every triangle positive (exact)");
    int same = 1, onside = 1, slid = 0;
    for (int v = 0; v < nv; v++) {
        if (!fixed[v]) continue;
        if (seg[2 * v] < 0) same &= X[2 * v] == X0[2 * v] && X[2 * v + 1] == X0[2 * v + 1];
        else {
            onside &= fabs(X[2 * v + 1]) < 1e-12 && X[2 * v] > 0 && X[2 * v] < K - 1;
            slid += X[2 * v] != X0[2 * v];
        }
    }
    ok(same, "fixed vertices keep their bits");
    ok(onside, "sliding vertices stay inside their side");
    diag("%d of %d sliding vertices moved", slid, K - 2);
    memcpy(X2, X0, sizeof X0);
    maxmin_polish(X2, nv, F, nf, fixed, seg, &p, NULL, NULL);
    ok(!memcmp(X, X2, sizeof X), "the same bytes twice");
    /* nothing free: unchanged */
    unsigned char all[K * K];
    memset(all, 1, sizeof all);
    memcpy(X2, X0, sizeof X0);
    rc = maxmin_polish(X2, nv, F, nf, all, NULL, &p, &before, &after);
    ok(rc == 0 && !memcmp(X2, X0, sizeof X0) && before == after, "no free vertex: unchanged");
    return tap_done();
}
