/* boundary_match.c -- bmatch_map and bmatch_corr give the same maps, the
 * same points and the same costs whatever the number of threads (the start
 * search's alignments and the maps onto each shape run as parallel jobs),
 * and the start search finds a rotated copy's start; without a given point
 * bmatch_corr's maps (whose start searches share the threads) have the
 * costs of bmatch_map's; a failing map names its shape with any number of
 * threads. */
#include "boundary_match.h"
#include "cm_error.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a five-lobed star of n points, lobes bent by `bend`, starting `shift`
 * points round (counter-clockwise) */
static double *star(int n, double bend, int shift)
{
    double *P = malloc(2 * (size_t)n * sizeof *P);
    for (int k = 0; k < n; k++) {
        double t = 2 * M_PI * ((k + shift) % n) / n;
        double r = 1 + 0.35 * cos(5 * t + bend * sin(t)) + 0.1 * sin(2 * t);
        P[2 * k] = r * cos(t);
        P[2 * k + 1] = r * sin(t);
    }
    return P;
}

int main(void)
{
    enum { N = 4 };
    int n[N] = {90, 110, 75, 130};
    double *P[N];
    for (int s = 0; s < N; s++) P[s] = star(n[s], 0.3 * s, 7 * s);
    struct bmatch_params prm;
    bmatch_defaults(&prm);
    ok(prm.threads == 1, "one thread by default");

    /* bmatch_map with no pair given: the start search */
    double *t1 = malloc(n[0] * sizeof *t1), *t3 = malloc(n[0] * sizeof *t3), c1, c3;
    prm.threads = 1;
    int r1 = bmatch_map(P[0], n[0], P[3], n[3], NULL, 0, &prm, t1, &c1);
    prm.threads = 3;
    int r3 = bmatch_map(P[0], n[0], P[3], n[3], NULL, 0, &prm, t3, &c3);
    ok(r1 == 0 && r3 == 0, "start search: maps on 1 and 3 threads");
    ok(c1 == c3 && !memcmp(t1, t3, n[0] * sizeof *t1), "start search: the same cost and map bit for bit");

    /* a copy of shape 0 started 20 points on: vertex 0 maps near vertex 70 */
    double *R = star(n[0], 0, 20);
    prm.threads = 2;
    bmatch_map(P[0], n[0], R, n[0], NULL, 0, &prm, t1, &c1);
    double L = 0;
    for (int k = 0; k < n[0]; k++) L += hypot(R[2 * ((k + 1) % n[0])] - R[2 * k], R[2 * ((k + 1) % n[0]) + 1] - R[2 * k + 1]);
    double arc70 = 0;
    for (int k = 0; k < 70; k++) arc70 += hypot(R[2 * (k + 1)] - R[2 * k], R[2 * (k + 1) + 1] - R[2 * k + 1]);
    double d = fabs(t1[0] - arc70);
    ok(fmin(d, L - d) < 0.02 * L, "rotated copy: vertex 0 lands within 2%% of the perimeter of its copy (%.4f)",
       fmin(d, L - d) / L);
    free(R);

    /* bmatch_corr: maps onto shapes 1..3 as jobs */
    int given[N] = {0, 5, 3, 9};   /* one given row */
    int *cA, *cB, nA, nB;
    double costA[N], costB[N];
    prm.threads = 1;
    int ra = bmatch_corr(N, P, n, given, 1, NULL, 0, 8, &prm, &cA, &nA, costA);
    prm.threads = 0;
    int rb = bmatch_corr(N, P, n, given, 1, NULL, 0, 8, &prm, &cB, &nB, costB);
    ok(ra == 0 && rb == 0, "corr: 1 thread and one per processor");
    ok(nA == nB && !memcmp(cA, cB, (size_t)nA * N * sizeof *cA), "corr: the same %d rows", nA);
    ok(!memcmp(costA, costB, sizeof costA), "corr: the same costs");
    free(cA); free(cB);

    /* no given point: the start searches of the three maps run on the
     * threads together; the same rows and costs on 1 and 3 threads, and
     * each cost is bmatch_map's */
    for (int t = 1; t <= 3; t += 2) {
        prm.threads = t;
        int *cc = t == 1 ? &nA : &nB;
        int rc = bmatch_corr(N, P, n, NULL, 0, NULL, 0, 8, &prm, t == 1 ? &cA : &cB, cc, t == 1 ? costA : costB);
        ok(rc == 0, "corr without a given point: %d thread%s", t, t == 1 ? "" : "s");
    }
    ok(nA == nB && !memcmp(cA, cB, (size_t)nA * N * sizeof *cA), "corr without a given point: the same %d rows", nA);
    ok(!memcmp(costA, costB, sizeof costA), "corr without a given point: the same costs");
    int same = 1;
    prm.threads = 1;
    for (int s = 1; s < N; s++) {
        double c;
        same &= bmatch_map(P[0], n[0], P[s], n[s], NULL, 0, &prm, t1, &c) == 0 && c == costA[s];
    }
    ok(same, "corr without a given point: each cost is bmatch_map's");
    free(cA); free(cB);

    /* a bad given row fails in the shape it names, on any number of threads */
    int bad[2 * N] = {0, 5, 3, 9, 10, 200, 20, 30};   /* 200 is out of range in shape 1 */
    for (int t = 1; t <= 2; t++) {
        prm.threads = t;
        int *cc = NULL, nc;
        int rc = bmatch_corr(N, P, n, bad, 2, NULL, 0, 8, &prm, &cc, &nc, NULL);
        ok(rc < 0 && strstr(cm_errmsg(), "shape 1") && strstr(cm_errmsg(), "out of range"),
           "%d thread%s: bad row refused naming shape 1 (%s)", t, t == 1 ? "" : "s", cm_errmsg());
        free(cc);
    }
    for (int s = 0; s < N; s++) free(P[s]);
    free(t1); free(t3);
    return tap_done();
}
