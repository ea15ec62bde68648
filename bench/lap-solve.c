/* lap-solve -- benchmark driver: cot Laplacian assembly and a CHOLMOD
 * factor + 3-right-hand-side solve on a MESH (frame 0).
 *
 *   lap-solve MESH [MATRIX_OUT]
 *
 * The system is implicit smoothing, A = M - t L (Voronoi mass M, cot
 * Laplacian L, t = 1e-3 * bounding-box diagonal^2), B = M V: SPD, the shape
 * of every "minimize a quadratic" solve in stopmo.  Prints "key value"
 * lines (CPU seconds, best of 3 runs; run with OPENBLAS_NUM_THREADS=1
 * so that CPU time is the work done).  With MATRIX_OUT, writes A (upper
 * triangle) and B in a small binary format for the Eigen baseline
 * (bench/lap-eigen.cpp): int32 n, int64 nnz, nnz x (int32 i, int32 j,
 * float64 x), n*3 float64 B row-major.
 */
#include "mesh.h"
#include "laplacian.h"
#include "geometry.h"
#include "spd.h"
#include "cm_error.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static cholmod_sparse *assemble(const struct mesh *m, double t, double *M)
{
    struct triplets T;
    triplets_init(&T, m->nv, m->nv);
    cot_laplacian_triplets(m->V, m->F, m->nf, -t, &T);
    mass_diag(m->V, m->F, m->nv, m->nf, MASS_VORONOI, M);
    for (int i = 0; i < m->nv; i++) triplets_add(&T, i, i, M[i]);
    cholmod_sparse *A = triplets_to_sparse(&T, 1);
    triplets_free(&T);
    return A;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: lap-solve MESH [MATRIX_OUT]\n");
        return 2;
    }
    struct mesh m;
    if (mesh_read(argv[1], &m) < 0) { fprintf(stderr, "%s\n", cm_errmsg()); return 1; }
    double d = bbox_diagonal(m.V, m.nv), t = 1e-3 * d * d;
    double *M = malloc(sizeof *M * m.nv);
    double best_lap = 1e9, best_asm = 1e9, best_fac = 1e9, best_sol = 1e9;
    cholmod_sparse *A = NULL;
    for (int rep = 0; rep < 3; rep++) {
        double t0 = now();
        cholmod_sparse *L = cot_laplacian(m.V, m.F, m.nv, m.nf);
        double t1 = now();
        sparse_free(&L);
        if (t1 - t0 < best_lap) best_lap = t1 - t0;
        if (A) sparse_free(&A);
        t0 = now();
        A = assemble(&m, t, M);
        t1 = now();
        if (t1 - t0 < best_asm) best_asm = t1 - t0;
    }
    double *B = malloc(sizeof *B * m.nv * 3), *X = malloc(sizeof *X * m.nv * 3);
    for (int i = 0; i < m.nv; i++)
        for (int c = 0; c < 3; c++) B[3 * i + c] = M[i] * m.V[3 * i + c];
    struct spd_solver *S = NULL;
    for (int rep = 0; rep < 3; rep++) {
        if (S) spd_free(S);
        double t0 = now();
        S = spd_factor(A);
        double t1 = now();
        if (!S) { fprintf(stderr, "%s\n", cm_errmsg()); return 1; }
        if (t1 - t0 < best_fac) best_fac = t1 - t0;
        t0 = now();
        spd_solve(S, B, X, 3);
        t1 = now();
        if (t1 - t0 < best_sol) best_sol = t1 - t0;
    }
    /* relative residual of the 3 columns */
    double num = 0, den = 0, *x = malloc(sizeof *x * m.nv), *y = malloc(sizeof *y * m.nv);
    for (int c = 0; c < 3; c++) {
        for (int i = 0; i < m.nv; i++) x[i] = X[3 * i + c];
        sparse_mul(A, x, y);
        for (int i = 0; i < m.nv; i++) {
            num += (y[i] - B[3 * i + c]) * (y[i] - B[3 * i + c]);
            den += B[3 * i + c] * B[3 * i + c];
        }
    }
    cholmod_factor *Lf = NULL;
    (void)Lf;
    printf("vertices %d\nfaces %d\nnnz_upper %ld\n", m.nv, m.nf, (long)cholmod_nnz(A, cm_cholmod()));
    printf("cot_laplacian %.6f\nassembly %.6f\nfactor %.6f\nsolve3 %.6f\nresidual %.3g\n",
           best_lap, best_asm, best_fac, best_sol, sqrt(num / den));
    if (argc > 2) {
        FILE *f = fopen(argv[2], "wb");
        if (!f) { perror(argv[2]); return 1; }
        int32_t n = m.nv;
        const int *p = A->p, *ii = A->i;
        const double *ax = A->x;
        int64_t nnz = p[m.nv];
        fwrite(&n, sizeof n, 1, f);
        fwrite(&nnz, sizeof nnz, 1, f);
        for (int j = 0; j < m.nv; j++)
            for (int k = p[j]; k < p[j + 1]; k++) {
                int32_t r = ii[k], c = j;
                fwrite(&r, 4, 1, f);
                fwrite(&c, 4, 1, f);
                fwrite(&ax[k], 8, 1, f);
            }
        fwrite(B, sizeof *B, (size_t)m.nv * 3, f);
        if (fclose(f) != 0) { perror(argv[2]); return 1; }
    }
    spd_free(S);
    sparse_free(&A);
    mesh_free(&m);
    free(M); free(B); free(X); free(x); free(y);
    return 0;
}
