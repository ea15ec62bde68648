/* spd: factor_solve_residual, multiple_rhs, refactor, not_spd_is_reported,
 * quad_solver_reproduces_harmonic_linear_function, quad_solver_rejects_singular */
#include "spd.h"
#include "laplacian.h"
#include "cm_error.h"
#include "tap.h"
#include "testmesh.h"
#include <math.h>
#include <string.h>

/* A = -L + M (SPD) on a jittered grid, stype 1 or 0 */
static cholmod_sparse *poisson_system(const double *V, const int *F, int nv, int nf, int stype,
                                      double mass_scale)
{
    struct triplets T;
    triplets_init(&T, nv, nv);
    cot_laplacian_triplets(V, F, nf, -1.0, &T);
    double *M = malloc(sizeof *M * nv);
    mass_diag(V, F, nv, nf, MASS_VORONOI, M);
    for (int i = 0; i < nv; i++) triplets_add(&T, i, i, mass_scale * M[i]);
    free(M);
    cholmod_sparse *A = triplets_to_sparse(&T, stype);
    triplets_free(&T);
    return A;
}

static double rel_residual(const cholmod_sparse *A, const double *X, const double *B, int n, int nc)
{
    double *x = malloc(sizeof *x * n), *y = malloc(sizeof *y * n), num = 0, den = 0;
    for (int c = 0; c < nc; c++) {
        for (int i = 0; i < n; i++) x[i] = X[(size_t)i * nc + c];
        sparse_mul(A, x, y);
        for (int i = 0; i < n; i++) {
            double r = y[i] - B[(size_t)i * nc + c];
            num += r * r;
            den += B[(size_t)i * nc + c] * B[(size_t)i * nc + c];
        }
    }
    free(x); free(y);
    return sqrt(num / den);
}

int main(void)
{
    double *V;
    int *F, nv, nf;
    grid_mesh(40, 30, 0.5, 3, &V, &F, &nv, &nf);
    struct rng r;
    rng_seed(&r, 11);

    for (int stype = 0; stype <= 1; stype++) {
        cholmod_sparse *A = poisson_system(V, F, nv, nf, stype, 1.0);
        struct spd_solver *S = spd_factor(A);
        ok(S != NULL, "spd_factor: -L + M is SPD (stype %d) %s", stype, S ? "" : cm_errmsg());
        if (!S) { sparse_free(&A); continue; }
        double *B = malloc(sizeof *B * nv * 3), *X = malloc(sizeof *X * nv * 3);
        for (int i = 0; i < 3 * nv; i++) B[i] = rng_normal(&r);
        ok(spd_solve(S, B, X, 3) == 0, "spd_solve: 3 right-hand sides");
        double res = rel_residual(A, X, B, nv, 3);
        ok(res < 1e-10, "spd_solve: residual_below_1e-10 (stype %d, %g)", stype, res);
        memcpy(X, B, sizeof *X * nv * 3);
        spd_solve(S, X, X, 3);
        res = rel_residual(A, X, B, nv, 3);
        ok(res < 1e-10, "spd_solve: B and X may alias (%g)", res);
        ok(spd_size(S) == nv, "spd_size");
        /* refactor with other values of the same pattern */
        cholmod_sparse *A2 = poisson_system(V, F, nv, nf, stype, 5.0);
        ok(spd_refactor(S, A2) == 0, "spd_refactor: same pattern");
        spd_solve(S, B, X, 3);
        res = rel_residual(A2, X, B, nv, 3);
        ok(res < 1e-10, "spd_refactor: residual_below_1e-10 (%g)", res);
        cholmod_sparse *A3 = poisson_system(V, F, nv, nf, stype, -50.0);
        ok(spd_refactor(S, A3) < 0, "spd_refactor: indefinite values reported: %s", cm_errmsg());
        sparse_free(&A2); sparse_free(&A3);
        spd_free(S);
        free(B); free(X);
        sparse_free(&A);
    }

    /* not SPD: reported, not solved */
    {
        /* the Laplacian alone: -L is only semi-definite (constants) */
        cholmod_sparse *A = poisson_system(V, F, nv, nf, 0, 0.0);
        cm_seterr("%s", "");
        struct spd_solver *S = spd_factor(A);
        ok(S == NULL && strstr(cm_errmsg(), "not positive definite"),
           "spd_factor: singular -L is reported (%s)", cm_errmsg());
        spd_free(S);
        sparse_free(&A);
        /* -L - c M with c above the smallest eigenvalue: indefinite */
        A = poisson_system(V, F, nv, nf, 0, -30.0);
        S = spd_factor(A);
        ok(S == NULL && strstr(cm_errmsg(), "not positive definite"),
           "spd_factor: indefinite -L - 30 M is reported (%s)", cm_errmsg());
        spd_free(S);
        sparse_free(&A);
        /* small indefinite matrix (CHOLMOD picks simplicial LDL' here) */
        struct triplets T;
        triplets_init(&T, 3, 3);
        double D[9] = {1, 2, 0, 2, 1, 0, 0, 0, 3};
        for (int i = 0; i < 9; i++) if (D[i] != 0) triplets_add(&T, i / 3, i % 3, D[i]);
        A = triplets_to_sparse(&T, 0);
        triplets_free(&T);
        S = spd_factor(A);
        ok(S == NULL && strstr(cm_errmsg(), "not positive definite"),
           "spd_factor: small indefinite 3x3 is reported (%s)", cm_errmsg());
        spd_free(S);
        sparse_free(&A);
        triplets_init(&T, 2, 3);
        triplets_add(&T, 0, 0, 1);
        A = triplets_to_sparse(&T, 0);
        triplets_free(&T);
        S = spd_factor(A);
        ok(S == NULL && strstr(cm_errmsg(), "not square"), "spd_factor: non-square reported");
        sparse_free(&A);
    }

    /* quad_solver: minimize x^T (-L) x with the boundary fixed to a linear
     * function; the harmonic solution is that linear function everywhere
     * (linear precision of the cot Laplacian on flat meshes) */
    {
        struct triplets T;
        triplets_init(&T, nv, nv);
        cot_laplacian_triplets(V, F, nf, -1.0, &T);
        cholmod_sparse *Q = triplets_to_sparse(&T, 1);
        triplets_free(&T);
        unsigned char *fixed = calloc(nv, 1);
        double *y = calloc(sizeof *y, (size_t)nv * 2), *x = calloc(sizeof *x, (size_t)nv * 2);
        int nfix = 0;
        for (int i = 0; i < nv; i++) {
            double px = V[3 * i], py = V[3 * i + 1];
            if (px == 0 || px == 1 || py == 0 || py == 1) { fixed[i] = 1; nfix++; }
            y[2 * i] = fixed[i] ? 1 + 2 * px - 3 * py : 1e9;       /* free rows must be ignored */
            y[2 * i + 1] = fixed[i] ? -0.5 * px + 4 * py : -1e9;
        }
        struct quad_solver *qs = quad_solver_new(Q, fixed);
        ok(qs != NULL, "quad_solver_new: boundary fixed (%d of %d) %s", nfix, nv, qs ? "" : cm_errmsg());
        if (qs) {
            ok(quad_solver_solve(qs, NULL, y, x, 2) == 0, "quad_solver_solve: 2 columns");
            double err = 0;
            int fixed_exact = 1;
            for (int i = 0; i < nv; i++) {
                double px = V[3 * i], py = V[3 * i + 1];
                err = fmax(err, fabs(x[2 * i] - (1 + 2 * px - 3 * py)));
                err = fmax(err, fabs(x[2 * i + 1] - (-0.5 * px + 4 * py)));
                if (fixed[i]) fixed_exact &= x[2 * i] == y[2 * i] && x[2 * i + 1] == y[2 * i + 1];
            }
            ok(err < 1e-10, "quad_solver: reproduces_harmonic_linear_function (max err %g)", err);
            ok(fixed_exact, "quad_solver: fixed rows equal their values exactly");
            /* a linear term: b = -L u for some u with u = 0 on the boundary
             * must give x = u back */
            double *u = calloc(nv, sizeof *u), *b = calloc(nv, sizeof *b), *x1 = calloc(nv, sizeof *x1);
            for (int i = 0; i < nv; i++)
                if (!fixed[i]) u[i] = sin(3 * V[3 * i]) * V[3 * i + 1];
            sparse_mul(Q, u, b);
            ok(quad_solver_solve(qs, b, NULL, x1, 1) == 0, "quad_solver_solve: linear term, zero y");
            double e1 = 0;
            for (int i = 0; i < nv; i++) e1 = fmax(e1, fabs(x1[i] - u[i]));
            ok(e1 < 1e-10, "quad_solver: Q x = b on the free rows (max err %g)", e1);
            free(u); free(b); free(x1);
            quad_solver_free(qs);
        }
        /* nothing fixed: the free block is singular -> reported */
        memset(fixed, 0, nv);
        qs = quad_solver_new(Q, fixed);
        ok(qs == NULL && strstr(cm_errmsg(), "not positive definite"),
           "quad_solver_new: singular free block is reported (%s)", cm_errmsg());
        /* everything fixed: x = y */
        memset(fixed, 1, nv);
        qs = quad_solver_new(Q, fixed);
        ok(qs && quad_solver_solve(qs, NULL, y, x, 2) == 0 && !memcmp(x, y, sizeof *x * nv * 2),
           "quad_solver: all fixed gives x = y");
        quad_solver_free(qs);
        free(fixed); free(y); free(x);
        sparse_free(&Q);
    }
    free(V); free(F);
    return tap_done();
}
