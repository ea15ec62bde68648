/* modulus_match.c -- modulus_match_polish:
 *   same_outline: two poses with the same 32-gon, four pinned rows at the
 *     same points and two free rows placed 2 points apart in one pose: the
 *     polish brings them to the same points (the ratio to 1 exactly: the
 *     same mesh), the pinned rows stay, the cyclic order holds;
 *   deterministic: the same input gives the same rows;
 *   stretched: a 2 x 1 rectangle against a 1 x 1 square (both with 8
 *     points a side): the ratio falls and never rises, pinned rows stay;
 *   nothing_to_do: fewer than 4 rows, or every row pinned: no move;
 *   steps_bound: at most the steps asked.
 */
#include "modulus_match.h"
#include "cm_error.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the n-gon on the circle of radius r (counter-clockwise) */
static double *circle(int n, double rx, double ry)
{
    double *P = malloc(2 * n * sizeof *P);
    for (int i = 0; i < n; i++) {
        double a = 2 * M_PI * i / n;
        P[2 * i] = rx * cos(a);
        P[2 * i + 1] = ry * sin(a);
    }
    return P;
}

/* a w x h rectangle with k points a side (4 k corners, counter-clockwise from (0, 0)) */
static double *rect(int k, double w, double h)
{
    double *P = malloc(8 * k * sizeof *P);
    for (int i = 0; i < k; i++) {
        double t = (double)i / k;
        P[2 * i] = t * w; P[2 * i + 1] = 0;
        P[2 * (k + i)] = w; P[2 * (k + i) + 1] = t * h;
        P[2 * (2 * k + i)] = w - t * w; P[2 * (2 * k + i) + 1] = h;
        P[2 * (3 * k + i)] = 0; P[2 * (3 * k + i) + 1] = h - t * h;
    }
    return P;
}

static int cyclic_increasing(const int *corr, int nc, int N, int s, int n)
{
    int base = corr[s], prev = -1;
    for (int k = 0; k < nc; k++) {
        int r = ((corr[k * N + s] - base) % n + n) % n;
        if (k && r <= prev) return 0;
        prev = r;
    }
    return 1;
}

int main(void)
{
    /* same_outline */
    double *C = circle(32, 1, 1);
    double *P[2] = {C, C};
    int n[2] = {32, 32};
    int corr[12] = {0, 0, 4, 2, 8, 8, 16, 16, 20, 22, 24, 24};
    unsigned char pin[6] = {1, 0, 1, 1, 0, 1};
    double before = 0, after = 0;
    int mv = modulus_match_polish(2, P, n, corr, 6, pin, 64, 3, &before, &after);
    ok(mv > 0 && before > 1.05, "same_outline: %d moves, ratio %.4f before", mv, before);
    ok(corr[2] == corr[3] && corr[8] == corr[9], "same_outline: free rows meet (%d %d, %d %d)", corr[2], corr[3],
       corr[8], corr[9]);
    ok(fabs(after - 1) < 1e-12, "same_outline: ratio %.15g after (the same mesh: exactly 1)", after);
    ok(corr[0] == 0 && corr[1] == 0 && corr[4] == 8 && corr[5] == 8 && corr[6] == 16 && corr[7] == 16 &&
       corr[10] == 24 && corr[11] == 24, "same_outline: pinned rows stay");
    ok(cyclic_increasing(corr, 6, 2, 0, 32) && cyclic_increasing(corr, 6, 2, 1, 32), "same_outline: order kept");

    /* deterministic */
    int c2[12] = {0, 0, 4, 2, 8, 8, 16, 16, 20, 22, 24, 24};
    double b2, a2;
    int mv2 = modulus_match_polish(2, P, n, c2, 6, pin, 64, 3, &b2, &a2);
    ok(mv2 == mv && !memcmp(c2, corr, sizeof c2) && b2 == before && a2 == after, "deterministic: the same rows and ratios");

    /* stretched: a rectangle against a square, corners pinned, mid-side rows free and misplaced */
    double *R = rect(8, 2, 1), *S = rect(8, 1, 1);
    double *Q[2] = {R, S};
    int m[2] = {32, 32};
    int cs[16] = {0, 0, 4, 2, 8, 8, 12, 14, 16, 16, 20, 21, 24, 24, 28, 30};
    unsigned char ps[8] = {1, 0, 1, 0, 1, 0, 1, 0};
    double bs, as;
    int mvs = modulus_match_polish(2, Q, m, cs, 8, ps, 64, 3, &bs, &as);
    ok(mvs > 0 && as < bs, "stretched: %d moves, ratio %.4f -> %.4f", mvs, bs, as);
    ok(as >= 2 * 0.9, "stretched: not below the corners' own ratio (2, first-mesh estimate): %.4f", as);
    ok(cs[0] == 0 && cs[4] == 8 && cs[8] == 16 && cs[12] == 24 && cs[1] == 0 && cs[5] == 8 && cs[9] == 16 && cs[13] == 24,
       "stretched: pinned corners stay");
    ok(cyclic_increasing(cs, 8, 2, 0, 32) && cyclic_increasing(cs, 8, 2, 1, 32), "stretched: order kept");

    /* nothing_to_do */
    int c3[6] = {0, 0, 8, 10, 16, 16};
    double b3 = 0, a3 = 0;
    ok(modulus_match_polish(2, P, n, c3, 3, NULL, 64, 3, &b3, &a3) == 0 && b3 == 1 && a3 == 1 && c3[3] == 10,
       "nothing_to_do: 3 rows, no move, ratio 1");
    int c4[12] = {0, 0, 4, 2, 8, 8, 16, 16, 20, 22, 24, 24};
    unsigned char all[6] = {1, 1, 1, 1, 1, 1};
    int mv4 = modulus_match_polish(2, P, n, c4, 6, all, 64, 3, &b3, &a3);
    ok(mv4 == 0 && c4[3] == 2 && a3 == b3 && b3 > 1.05, "nothing_to_do: every row pinned, no move (ratio %.4f stays)", b3);

    /* steps_bound */
    int c5[12] = {0, 0, 4, 1, 8, 8, 16, 16, 20, 23, 24, 24};
    int mv5 = modulus_match_polish(2, P, n, c5, 6, pin, 1, 3, &b3, &a3);
    ok(mv5 == 1 && a3 < b3, "steps_bound: one step asked, one made (ratio %.4f -> %.4f)", b3, a3);

    free(C); free(R); free(S);
    return tap_done();
}
