/* bilaplacian.c -- see bilaplacian.h */
#include "bilaplacian.h"
#include "cm_error.h"
#include <stdlib.h>

cholmod_sparse *bilaplacian(const double *V, const int *F, int nv, int nf,
                            enum mass_type type)
{
    cholmod_common *c = cm_cholmod();
    cholmod_sparse *L = cot_laplacian(V, F, nv, nf);
    if (!L) { cm_seterr("out of memory building the Laplacian"); return NULL; }
    double *M = malloc(((size_t)nv + 1) * sizeof *M);
    mass_diag(V, F, nv, nf, type, M);
    /* A = M^-1 L (row scaling); zero mass -> zero row */
    cholmod_sparse *A = cholmod_copy_sparse(L, c);
    if (!A) { free(M); cholmod_free_sparse(&L, c); cm_seterr("out of memory"); return NULL; }
    const int *ap = A->p, *ai = A->i;
    double *ax = A->x;
    for (int j = 0; j < nv; j++)
        for (int k = ap[j]; k < ap[j + 1]; k++)
            ax[k] = M[ai[k]] > 0 ? ax[k] / M[ai[k]] : 0;
    free(M);
    /* Q = L^T (M^-1 L) = L A since L is symmetric; keep the upper triangle */
    cholmod_sparse *Q = cholmod_ssmult(L, A, 1, 1, 1, c);
    cholmod_free_sparse(&A, c);
    cholmod_free_sparse(&L, c);
    if (!Q) { cm_seterr("out of memory building L^T M^-1 L (status %d)", c->status); return NULL; }
    if (Q->stype != 1) {        /* ssmult may hand back the lower triangle */
        cholmod_sparse *U = cholmod_copy(Q, 1, 1, c);
        cholmod_free_sparse(&Q, c);
        if (!U) { cm_seterr("out of memory building L^T M^-1 L"); return NULL; }
        Q = U;
    }
    return Q;
}

double quadratic_energy(const cholmod_sparse *Q, const double *D, int ncols)
{
    const int *p = Q->p, *ii = Q->i;
    const double *qx = Q->x;
    double e = 0;
    for (size_t j = 0; j < Q->ncol; j++)
        for (int k = p[j]; k < p[j + 1]; k++) {
            int i = ii[k];
            if (Q->stype > 0 && i > (int)j) continue;
            if (Q->stype < 0 && i < (int)j) continue;
            double s = 0;
            for (int c = 0; c < ncols; c++)
                s += D[(size_t)i * ncols + c] * D[j * ncols + c];
            e += (Q->stype != 0 && i != (int)j ? 2 : 1) * qx[k] * s;
        }
    return e;
}
