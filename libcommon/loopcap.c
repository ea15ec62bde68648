/* loopcap.c -- see loopcap.h. */
#include "loopcap.h"
#include "cdt2.h"
#include "cm_error.h"
#include "geometry.h"
#include "predicates2.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void loop_area_vector(const double *X, const int *loop, int n, double a[3])
{
    a[0] = a[1] = a[2] = 0;
    for (int k = 0; k < n; k++) {
        const double *p = X + 3 * (size_t)loop[k], *q = X + 3 * (size_t)loop[(k + 1) % n];
        double c[3];
        cross3(p, q, c);
        for (int d = 0; d < 3; d++) a[d] += 0.5 * c[d];
    }
}

int loop_cap(const double *X, const int *loop, int n, const double c[3], const double a[3], int centre,
             int **T, int *fan)
{
    *T = NULL;
    if (n < 3) return cm_seterr("a boundary loop of %d vertices", n);
    double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(la > 0) || !isfinite(la)) return cm_seterr("a boundary loop that spans no area");
    double z[3] = {a[0] / la, a[1] / la, a[2] / la}, u[3], w[3];
    /* in-plane basis: the axis least aligned with z, made orthogonal */
    int ax = fabs(z[0]) <= fabs(z[1]) && fabs(z[0]) <= fabs(z[2]) ? 0 : fabs(z[1]) <= fabs(z[2]) ? 1 : 2;
    double e[3] = {0, 0, 0};
    e[ax] = 1;
    cross3(z, e, u);
    double lu = sqrt(dot3(u, u));
    for (int d = 0; d < 3; d++) u[d] /= lu;
    cross3(z, u, w);
    double *P = malloc(sizeof(double) * 2 * ((size_t)n + 1));
    int *t = malloc(sizeof(int) * 3 * (size_t)n);
    if (!P || !t) { free(P); free(t); return cm_seterr("out of memory"); }
    for (int k = 0; k < n; k++) {
        const double *x = X + 3 * (size_t)loop[k];
        double d[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
        P[2 * k] = dot3(d, u); P[2 * k + 1] = dot3(d, w);
    }
    P[2 * n] = P[2 * n + 1] = 0;     /* the centre */
    /* the loop runs counter-clockwise about a (the vector area's direction);
     * the fan (loop[k+1], loop[k], c) is valid when every (c, loop[k],
     * loop[k+1]) turns left */
    int star = 1;
    for (int k = 0; k < n && star; k++)
        star = orient2_sign(P + 2 * n, P + 2 * k, P + 2 * ((k + 1) % n)) > 0;
    if (star) {
        for (int k = 0; k < n; k++) {
            t[3 * k] = loop[(k + 1) % n]; t[3 * k + 1] = loop[k]; t[3 * k + 2] = centre;
        }
        free(P);
        *T = t;
        if (fan) *fan = 1;
        return n;
    }
    int *F;
    if (cdt2_polygon(n, P, &F) < 0) {
        free(P); free(t);
        return cm_seterr("the boundary loop of %d vertices, seen along its normal, is %s", n,
                         strstr(cm_errmsg(), "repeat") ? "not simple (a vertex repeats)" : "not simple (it crosses itself)");
    }
    /* F is counter-clockwise in (u, w), i.e. in loop order: reverse it */
    for (int k = 0; k < n - 2; k++) {
        t[3 * k] = loop[F[3 * k]]; t[3 * k + 1] = loop[F[3 * k + 2]]; t[3 * k + 2] = loop[F[3 * k + 1]];
    }
    free(F); free(P);
    *T = t;
    if (fan) *fan = 0;
    return n - 2;
}
