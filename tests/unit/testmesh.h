/* testmesh.h -- small meshes built in C for the unit tests (no files).
 *   grid_mesh:     (n+1) x (m+1) vertices on [0,1]^2, 2nm triangles, every
 *                  cell split along the same diagonal (a regular grid whose
 *                  cot Laplacian is the 5-point stencil); jitter > 0 moves
 *                  interior vertices in the plane (seeded).
 *   cylinder_mesh: n around, m rings, open tube (two boundary loops).
 *   icosahedron:   12 vertices, 20 faces, closed.
 *   pleat_grid:    a grid's vertices pushed sideways into a pleat (the map
 *                  runs backwards around x = 0.5 where y is mid-range), for
 *                  the untangling tests; P is #V by 3, given.
 * Arrays are malloc'd; the caller frees V and F. */
#ifndef STOPMO_TESTMESH_H
#define STOPMO_TESTMESH_H
#include "rng.h"
#include <math.h>
#include <stdlib.h>

static inline void grid_mesh(int n, int m, double jitter, unsigned seed, double **V, int **F,
                      int *nv, int *nf)
{
    struct rng r;
    rng_seed(&r, seed);
    *nv = (n + 1) * (m + 1);
    *nf = 2 * n * m;
    *V = malloc(sizeof(double) * 3 * *nv);
    *F = malloc(sizeof(int) * 3 * *nf);
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++) {
            double *x = *V + 3 * (j * (n + 1) + i);
            x[0] = (double)i / n;
            x[1] = (double)j / m;
            x[2] = 0;
            if (jitter > 0 && i > 0 && i < n && j > 0 && j < m) {
                x[0] += jitter / n * (rng_uniform(&r) - 0.5);
                x[1] += jitter / m * (rng_uniform(&r) - 0.5);
            }
        }
    int *f = *F;
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            f[0] = a; f[1] = b; f[2] = c;
            f[3] = a; f[4] = c; f[5] = d;
            f += 6;
        }
}

static inline void cylinder_mesh(int n, int m, double **V, int **F, int *nv, int *nf)
{
    *nv = n * (m + 1);
    *nf = 2 * n * m;
    *V = malloc(sizeof(double) * 3 * *nv);
    *F = malloc(sizeof(int) * 3 * *nf);
    for (int j = 0; j <= m; j++)
        for (int i = 0; i < n; i++) {
            double *x = *V + 3 * (j * n + i);
            x[0] = cos(2 * M_PI * i / n);
            x[1] = sin(2 * M_PI * i / n);
            x[2] = (double)j / m;
        }
    int *f = *F;
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            int a = j * n + i, b = j * n + (i + 1) % n, c = b + n, d = a + n;
            f[0] = a; f[1] = b; f[2] = c;
            f[3] = a; f[4] = c; f[5] = d;
            f += 6;
        }
}

static inline void icosahedron(double **V, int **F, int *nv, int *nf)
{
    static const int f0[60] = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                               11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                               3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    double t = (1 + sqrt(5)) / 2;
    double v0[36] = {-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t,
                     0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1};
    *nv = 12;
    *nf = 20;
    *V = malloc(sizeof v0);
    *F = malloc(sizeof f0);
    for (int i = 0; i < 36; i++) (*V)[i] = v0[i];
    for (int i = 0; i < 60; i++) (*F)[i] = f0[i];
}
/* x -> x + b(y) g(x): g a sine wave on [0.35, 0.65] steep enough that the
 * map runs backwards around x = 0.5 where b(y) > 0.6 */
static inline void pleat_grid(const double *V, int nv, double *P)
{
    for (int i = 0; i < nv; i++) {
        double x = V[3 * i], y = V[3 * i + 1];
        double g = x > 0.35 && x < 0.65 ? 0.08 * sin(2 * M_PI * (x - 0.35) / 0.3) : 0;
        double b = y > 0.2 && y < 0.8 ? 0.5 - 0.5 * cos(2 * M_PI * (y - 0.2) / 0.6) : 0;
        P[3 * i] = x + b * g;
        P[3 * i + 1] = y;
        P[3 * i + 2] = 0;
    }
}
#endif
