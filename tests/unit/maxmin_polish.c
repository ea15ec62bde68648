/* maxmin_polish.c -- the global max-min polish of one planar mesh: on a
 * jittered grid (interior vertices free, the bottom side's inner vertices
 * sliding along it, the rest fixed) the smallest angle rises, every
 * triangle stays positive by the exact predicate, fixed vertices keep
 * their bits, sliding ones stay on their side, the same bytes twice; a
 * mesh with no free vertex is left alone.  maxmin_polish_curve on the same
 * grid with its left, top and right sides' vertices jittered along the
 * sides and sliding along the square (the input outline B): the smallest
 * angle rises above what maxmin_polish reaches from the same start, every
 * outline vertex stays on its side in order, corners keep their bits. */
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

    /* the curve mode: the square's outline B, counter-clockwise from (0, 0) */
    int M = 4 * (K - 1), bsucc[K * K], home[K * K];
    double B[2 * 4 * (K - 1)];
    unsigned char sl[K * K];
    for (int i = 0; i < K - 1; i++) {
        B[2 * i] = i; B[2 * i + 1] = 0;
        B[2 * (K - 1 + i)] = K - 1; B[2 * (K - 1 + i) + 1] = i;
        B[2 * (2 * (K - 1) + i)] = K - 1 - i; B[2 * (2 * (K - 1) + i) + 1] = K - 1;
        B[2 * (3 * (K - 1) + i)] = 0; B[2 * (3 * (K - 1) + i) + 1] = K - 1 - i;
    }
    for (int v = 0; v < nv; v++) { bsucc[v] = home[v] = -1; sl[v] = 0; }
    for (int i = 0; i < K - 1; i++) {
        bsucc[i] = i + 1;                                   /* bottom */
        bsucc[i * K + K - 1] = (i + 1) * K + K - 1;         /* right, up */
        bsucc[(K - 1) * K + K - 1 - i] = (K - 1) * K + K - 2 - i;   /* top, leftwards */
        bsucc[(K - 1 - i) * K] = (K - 2 - i) * K;           /* left, down */
    }
    home[0] = 0; home[K - 1] = K - 1; home[K * K - 1] = 2 * (K - 1); home[(K - 1) * K] = 3 * (K - 1);
    memcpy(X, X0, sizeof X0);
    for (int j = 1; j < K - 1; j++) {   /* right and left sides, jittered along them */
        int r = j * K + K - 1, l = j * K;
        home[r] = K - 1 + j; home[l] = 3 * (K - 1) + (K - 1 - j);
        sl[r] = sl[l] = 1;
        X[2 * r + 1] = j + 0.6 * (rnd() - 0.5);
        X[2 * l + 1] = j + 0.6 * (rnd() - 0.5);
    }
    for (int i = 1; i < K - 1; i++) {   /* top */
        int t = (K - 1) * K + i;
        home[t] = 2 * (K - 1) + (K - 1 - i);
        sl[t] = 1;
        X[2 * t] = i + 0.6 * (rnd() - 0.5);
    }
    double Xc[2 * K * K], Xp[2 * K * K], b1, a1, b2, a2;
    memcpy(Xc, X, sizeof X);
    memcpy(Xp, X, sizeof X);
    maxmin_polish(Xp, nv, F, nf, fixed, seg, &p, &b1, &a1);
    struct maxmin_curve cv = {.B = B, .M = M, .bsucc = bsucc, .home = home, .slides = sl, .tol = 0.01};
    rc = maxmin_polish_curve(Xc, nv, F, nf, fixed, seg, &cv, &p, &b2, &a2);
    diag("sides jittered: smallest angle %.3f -> %.3f deg with the outline fixed, -> %.3f sliding",
         b1 * 180 / M_PI, a1 * 180 / M_PI, a2 * 180 / M_PI);
    ok(rc == 1 && fabs(a2 - min_angle(Xc, F, nf)) < 1e-12, "sliding: moved, after is the mesh's smallest angle");
    ok(a2 > a1 + 1 * M_PI / 180, "sliding: the smallest angle more than 1 degree above the fixed outline's");
    pos = 1;
    for (int k = 0; k < nf; k++) pos &= orient2_sign(Xc + 2 * F[3 * k], Xc + 2 * F[3 * k + 1], Xc + 2 * F[3 * k + 2]) > 0;
    ok(pos, "sliding: every triangle positive (exact)");
    int corners = 1, onb = 1, order = 1;
    slid = 0;
    for (int v = 0; v < nv; v++) {
        if (!fixed[v]) continue;
        if (home[v] >= 0 && !sl[v]) corners &= Xc[2 * v] == X[2 * v] && Xc[2 * v + 1] == X[2 * v + 1];
        slid += sl[v] && (Xc[2 * v] != X[2 * v] || Xc[2 * v + 1] != X[2 * v + 1]);
    }
    for (int j = 1; j < K - 1; j++) {
        int r = j * K + K - 1, l = j * K;
        onb &= Xc[2 * r] == K - 1 && Xc[2 * l] == 0 && Xc[2 * r + 1] > 0 && Xc[2 * l + 1] < K - 1;
        order &= Xc[2 * r + 1] < Xc[2 * (r + K) + 1] && Xc[2 * l + 1] < Xc[2 * (l + K) + 1];
        int t = (K - 1) * K + j;
        onb &= Xc[2 * t + 1] == K - 1;
        order &= Xc[2 * t] > Xc[2 * (t - 1)];
        onb &= Xc[2 * j + 1] == 0;   /* bottom: on its chord */
    }
    ok(corners, "sliding: the fixed corners keep their bits");
    ok(onb && order, "sliding: every outline vertex on its side of B, in order");
    diag("%d of %d outline vertices slid", slid, 3 * (K - 2));
    memcpy(X2, X, sizeof X);
    maxmin_polish_curve(X2, nv, F, nf, fixed, seg, &cv, &p, NULL, NULL);
    ok(!memcmp(Xc, X2, sizeof X), "sliding: the same bytes twice");
    return tap_done();
}
