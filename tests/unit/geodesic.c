/* geodesic: plane_distance_is_euclidean, sphere_distance_is_arc,
 * face_point_source, disconnected_component_infinite, bad_input_refused */
#include "geodesic.h"
#include "cm_error.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>

/* n x n grid of the unit square, alternating diagonals */
static void grid(int n, double **V, int **F, int *nv, int *nf)
{
    *nv = (n + 1) * (n + 1); *nf = 2 * n * n;
    *V = malloc(sizeof(double) * 3 * *nv); *F = malloc(sizeof(int) * 3 * *nf);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double *p = *V + 3 * (j * (n + 1) + i);
            p[0] = (double)i / n; p[1] = (double)j / n; p[2] = 0;
        }
    int f = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, c = a + n + 2;
            int *t = *F + 6 * f++;
            if ((i + j) % 2) { t[0] = a; t[1] = a + 1; t[2] = c; t[3] = a; t[4] = c; t[5] = c - 1; }
            else { t[0] = a; t[1] = a + 1; t[2] = c - 1; t[3] = a + 1; t[4] = c; t[5] = c - 1; }
        }
}

int main(void)
{
    int n = 30, nv, nf;
    double *V; int *F;
    grid(n, &V, &F, &nv, &nf);
    double *D = malloc(sizeof(double) * (nv + 10));
    int src = (n / 2) * (n + 1) + n / 2;      /* centre vertex */
    int r = geodesic_distance(V, F, nv, nf, &src, 1, NULL, NULL, 0, D);
    double err = 0;
    for (int v = 0; v < nv; v++) {
        double e = fabs(D[v] - hypot(V[3 * v] - 0.5, V[3 * v + 1] - 0.5));
        if (e > err) err = e;
    }
    ok(r == 0 && D[src] == 0, "geodesic: solve succeeds, source distance 0");
    ok(err < 0.05, "geodesic: plane distance is euclidean (max error %.4f < 0.05 of side 1)", err);

    /* a point source inside a face: distance to the point, not the corners */
    int sf = 2 * ((n / 3) * n + n / 3);
    double sb[3] = {0.2, 0.3, 0.5}, p[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) p[d] += sb[k] * V[3 * F[3 * sf + k] + d];
    r = geodesic_distance(V, F, nv, nf, NULL, 0, &sf, sb, 1, D);
    err = 0;
    for (int v = 0; v < nv; v++) {
        double e = fabs(D[v] - hypot(V[3 * v] - p[0], V[3 * v + 1] - p[1]));
        if (e > err) err = e;
    }
    ok(r == 0 && err < 0.05, "geodesic: face point source (max error %.4f)", err);
    /* a point on an edge (one zero coordinate) */
    double eb[3] = {0.5, 0.5, 0};
    r = geodesic_distance(V, F, nv, nf, NULL, 0, &sf, eb, 1, D);
    ok(r == 0, "geodesic: edge point source accepted (%s)", r ? cm_errmsg() : "ok");

    /* the precomputed solver answers several source sets */
    struct geodesic *g = geodesic_new(V, F, nv, nf);
    int s2[2] = {0, nv - 1};
    r = geodesic_solve(g, s2, 2, D);
    double mid = D[src], want = hypot(0.5, 0.5);
    ok(r == 0 && fabs(mid - want) < 0.05, "geodesic: two sources, centre %.4f ~ %.4f", mid, want);
    int bad = nv;
    ok(geodesic_solve(g, &bad, 1, D) < 0, "geodesic: source out of range refused (%s)", cm_errmsg());
    geodesic_free(g);

    /* two copies of the grid: the copy without a source is unreachable */
    double *V2 = malloc(sizeof(double) * 6 * nv); int *F2 = malloc(sizeof(int) * 6 * nf);
    for (int i = 0; i < 3 * nv; i++) { V2[i] = V[i]; V2[3 * nv + i] = V[i] + (i % 3 == 2 ? 1 : 0); }
    for (int i = 0; i < 3 * nf; i++) { F2[i] = F[i]; F2[3 * nf + i] = F[i] + nv; }
    double *D2 = malloc(sizeof(double) * 2 * nv);
    r = geodesic_distance(V2, F2, 2 * nv, 2 * nf, &src, 1, NULL, NULL, 0, D2);
    ok(r == 0 && isinf(D2[nv + src]) && fabs(D2[0] - want) < 0.05,
       "geodesic: component without a source is INFINITY");

    /* non-manifold: a third face on an edge */
    int Fn[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    double Vn[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    ok(geodesic_new(Vn, Fn, 5, 3) == NULL, "geodesic: non-manifold refused (%s)", cm_errmsg());
    free(V); free(F); free(D); free(V2); free(F2); free(D2);
    return tap_done();
}
