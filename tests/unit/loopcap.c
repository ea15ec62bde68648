/* loopcap: star_loop_gets_a_fan, c_shaped_loop_gets_a_triangulation,
 * crossing_loop_is_refused */
#include "loopcap.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>

/* signed area of triangle (a, b, c) in the plane z = 0, along +z */
static double tri_area(const double *X, const int *t)
{
    const double *a = X + 3 * t[0], *b = X + 3 * t[1], *c = X + 3 * t[2];
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
}

int main(void)
{
    /* a C: outer arc r = 1, inner arc r = 0.5, open towards +x (|angle| < 40 deg);
     * counter-clockwise seen from +z, 2 x 16 corners, one apex slot at the end */
    enum { M = 16, N = 2 * M };
    double X[3 * (N + 1)];
    int loop[N];
    for (int k = 0; k < M; k++) {
        double t = (40 + 280.0 * k / (M - 1)) * M_PI / 180;
        X[3 * k] = cos(t); X[3 * k + 1] = sin(t); X[3 * k + 2] = 0.1 * sin(3 * t);
        double u = (320 - 280.0 * k / (M - 1)) * M_PI / 180;
        X[3 * (M + k)] = 0.5 * cos(u); X[3 * (M + k) + 1] = 0.5 * sin(u); X[3 * (M + k) + 2] = 0;
    }
    double area = 0;
    for (int k = 0; k < N; k++) {
        loop[k] = k;
        const double *p = X + 3 * k, *q = X + 3 * ((k + 1) % N);
        area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
    double c[3] = {0, 0, 0}, a[3];
    for (int k = 0; k < N; k++) for (int d = 0; d < 3; d++) c[d] += X[3 * k + d] / N;
    X[3 * N] = c[0]; X[3 * N + 1] = c[1]; X[3 * N + 2] = c[2];
    loop_area_vector(X, loop, N, a);
    int *T, fan = -1;
    int nt = loop_cap(X, loop, N, c, a, N, &T, &fan);
    int ok_c = nt == N - 2 && fan == 0, neg = 1;
    double sum = 0;
    for (int k = 0; k < nt && ok_c; k++) {
        double s = tri_area(X, T + 3 * k);
        if (!(s < 0)) neg = 0;     /* reversed loop order: clockwise along +z */
        sum += s;
        for (int j = 0; j < 3; j++) if (T[3 * k + j] == N) ok_c = 0;   /* no centre */
    }
    ok(ok_c, "loopcap: c_shaped_loop_gets_a_triangulation (%d triangles, fan %d)", nt, fan);
    ok(ok_c && neg && fabs(sum + area) < 1e-12, "loopcap: triangulation_covers_the_loop_reversed (area %g of %g)", -sum, area);
    free(T);

    /* a star: the outer arc alone, closed by its chord, about the arc's centre of mass */
    int star[M];
    for (int k = 0; k < M; k++) star[k] = k;
    double cs[3] = {0, 0, 0};
    for (int k = 0; k < M; k++) for (int d = 0; d < 3; d++) cs[d] += X[3 * k + d] / M;
    cs[0] = -0.2;   /* inside the arc's region, off the chord */
    loop_area_vector(X, star, M, a);
    nt = loop_cap(X, star, M, cs, a, N, &T, &fan);
    int ok_s = nt == M && fan == 1;
    for (int k = 0; k < nt && ok_s; k++)
        ok_s = T[3 * k] == star[(k + 1) % M] && T[3 * k + 1] == star[k] && T[3 * k + 2] == N;
    ok(ok_s, "loopcap: star_loop_gets_a_fan (%d triangles, fan %d)", nt, fan);
    free(T);

    /* a bow tie crosses itself */
    double B[3 * 5] = {0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.2, 0};
    int bl[4] = {0, 1, 2, 3};
    double cb[3] = {0.5, 0.2, 0}, ab[3] = {0, 0, 1};
    nt = loop_cap(B, bl, 4, cb, ab, 4, &T, &fan);
    ok(nt < 0, "loopcap: crossing_loop_is_refused");
    return tap_done();
}
