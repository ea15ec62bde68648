/* cert-boundary -- the certificate (modulus_cert.h) of a compatible mesh's
 * own boundary map: what the pairing of the outline vertices that the mesh
 * uses (matching, simplification, boundary splits) forces, as against what
 * the outlines and the given points force (compat-tri --bound).
 *
 *   cert-boundary [K] < mesh      (a compat-tri MESH stream, one outline)
 *
 * Every frame's boundary polygon (the boundary edges walked
 * counter-clockwise) is a pose, its vertices paired across the poses by
 * index.  Searched, not exhaustive: the best quadruple of K (default 16)
 * boundary vertices evenly spaced by index (modulus_certificate), then
 * coordinate ascent of its four corners (steps of nb/8, nb/16, ..., 1
 * vertices, each kept while the lower bound of the ratio grows, at a
 * bracket width of 0.1), then the final bracket at 0.03.  Any quadruple's
 * lower bound is a valid certificate of that boundary map; a better
 * search could only lower the ceiling.  Prints one line: the ratio, the
 * poses, the four boundary vertices, both brackets and the ceiling.
 * Used for the survey in compat-tri(1), CERTIFICATE.
 */
#include "mesh.h"
#include "modulus_cert.h"
#include "quad_modulus.h"
#include "cm_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int N, nb;
static struct quad_modulus **base;
static long solved;

/* the lower bound of the largest ratio between two poses of quadruple idx */
static double ratio(const int idx[4], double tol, int *pi, int *pj, double lo[2], double hi[2])
{
    double *L = malloc(2 * N * sizeof *L), *H = L + N, best = 0;
    for (int s = 0; s < N; s++) {
        struct quad_modulus *q = quad_modulus_recorner(base[s], idx);
        if (!q || quad_modulus_refine(q, tol, 400000) < 0) { fprintf(stderr, "cert-boundary: %s\n", cm_errmsg()); exit(1); }
        quad_modulus_bracket(q, &L[s], &H[s], NULL);
        quad_modulus_free(q);
        solved++;
    }
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            if (i != j && L[i] / H[j] > best) {
                best = L[i] / H[j];
                if (pi) { *pi = i; *pj = j; lo[0] = L[i]; hi[0] = H[i]; lo[1] = L[j]; hi[1] = H[j]; }
            }
    free(L);
    return best;
}

static int ccw_order(const int idx[4])
{
    int span = 0;
    for (int k = 0; k < 4; k++) {
        int d = ((idx[(k + 1) % 4] - idx[k]) % nb + nb) % nb;
        if (d == 0) return 0;
        span += d;
    }
    return span == nb;
}

int main(int argc, char **argv)
{
    int K = argc > 1 ? atoi(argv[1]) : 16;
    struct mesh m;
    if (K < 4 || mesh_read(argc > 2 ? argv[2] : NULL, &m) < 0) {
        fprintf(stderr, "cert-boundary: %s\n", K < 4 ? "K must be >= 4" : cm_errmsg());
        return 1;
    }
    N = m.nframes;
    /* the boundary loop: next[a] = b for every edge a -> b without its twin */
    int *next = malloc(m.nv * sizeof *next), nbe = 0, start = -1;
    for (int v = 0; v < m.nv; v++) next[v] = -1;
    for (int f = 0; f < m.nf; f++)
        for (int k = 0; k < 3; k++) {
            int a = m.F[3 * f + k], b = m.F[3 * f + (k + 1) % 3], twin = 0;
            for (int g = 0; g < m.nf && !twin; g++)
                for (int l = 0; l < 3; l++)
                    if (m.F[3 * g + l] == b && m.F[3 * g + (l + 1) % 3] == a) twin = 1;
            if (!twin) { next[a] = b; nbe++; if (start < 0 || a < start) start = a; }
        }
    int *loop = malloc(m.nv * sizeof *loop);
    nb = 0;
    for (int v = start; nb <= nbe; v = next[v]) {
        loop[nb++] = v;
        if (next[v] == start) break;
    }
    if (nb != nbe) { fprintf(stderr, "cert-boundary: the mesh's boundary is not one loop\n"); return 1; }
    double **P = malloc(N * sizeof *P);
    int *n = malloc(N * sizeof *n);
    base = malloc(N * sizeof *base);
    for (int s = 0; s < N; s++) {
        P[s] = malloc(2 * (size_t)nb * sizeof **P);
        n[s] = nb;
        for (int i = 0; i < nb; i++) {
            P[s][2 * i] = mesh_frame(&m, s)[3 * loop[i]];
            P[s][2 * i + 1] = mesh_frame(&m, s)[3 * loop[i] + 1];
        }
        int i0[4] = {0, nb / 4, nb / 2, 3 * nb / 4};
        if (!(base[s] = quad_modulus_new(P[s], nb, i0))) { fprintf(stderr, "cert-boundary: pose %d: %s\n", s, cm_errmsg()); return 1; }
    }
    int *corr = malloc((size_t)K * N * sizeof *corr);
    for (int k = 0; k < K; k++)
        for (int s = 0; s < N; s++) corr[k * N + s] = (int)((long)k * nb / K);
    struct modulus_cert c;
    if (modulus_certificate(N, P, n, corr, K, 0.03, &c) < 0) { fprintf(stderr, "cert-boundary: %s\n", cm_errmsg()); return 1; }
    int idx[4];
    for (int t = 0; t < 4; t++) idx[t] = corr[c.row[t] * N];
    double cur = ratio(idx, 0.1, NULL, NULL, NULL, NULL);
    for (int improved = 1; improved;) {
        improved = 0;
        for (int t = 0; t < 4; t++)
            for (int step = nb / 8; step >= 1; step /= 2)
                for (int sg = -1; sg <= 1; sg += 2)
                    for (;;) {
                        int j[4] = {idx[0], idx[1], idx[2], idx[3]};
                        j[t] = ((j[t] + sg * step) % nb + nb) % nb;
                        if (!ccw_order(j)) break;
                        double r = ratio(j, 0.1, NULL, NULL, NULL, NULL);
                        if (!(r > cur * 1.001)) break;
                        cur = r;
                        idx[t] = j[t];
                        improved = 1;
                    }
    }
    int pi = 0, pj = 1;
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    double R = ratio(idx, 0.03, &pi, &pj, lo, hi);
    if (R < c.ratio) {   /* the ascent never ends below its start; the sample's tighter bracket may */
        R = c.ratio; pi = c.pose[0]; pj = c.pose[1];
        for (int t = 0; t < 4; t++) idx[t] = corr[c.row[t] * N];
        lo[0] = c.lo[0]; hi[0] = c.hi[0]; lo[1] = c.lo[1]; hi[1] = c.hi[1];
    }
    printf("boundary map of %d vertices, %d poses: sample of %d: %.3gx (%.2f deg); searched: stretch >= %.3gx between "
           "poses %d and %d (boundary vertices %d %d %d %d: modulus %.4g-%.4g against %.4g-%.4g): ceiling %.2f deg "
           "(%ld quadrilaterals solved after the sample)\n",
           nb, N, K, c.ratio, c.ceiling, R, pj, pi, loop[idx[0]], loop[idx[1]], loop[idx[2]], loop[idx[3]], lo[1], hi[1],
           lo[0], hi[0], angle_ceiling(R > 1 ? R : 1) * 180 / M_PI, solved);
    return 0;
}
