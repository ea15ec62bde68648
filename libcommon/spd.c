/* spd.c -- see spd.h.  Lifecycle as in CHOLMOD's Demo/cholmod_simple.c:
 * analyze, factorize, check status and L->minor, solve, free. */
#include "spd.h"
#include "cm_error.h"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct spd_solver {
    int n;
    cholmod_factor *L;
};

static int check_factor(cholmod_factor *L, cholmod_common *c)
{
    if (c->status == CHOLMOD_NOT_POSDEF || L->minor < L->n)
        return cm_seterr("matrix is not positive definite (failed at column %d of %d)",
                         (int)L->minor, (int)L->n);
    if (c->status < CHOLMOD_OK)
        return cm_seterr("CHOLMOD factorization failed (status %d)", c->status);
    /* A simplicial LDL' factorization (CHOLMOD's choice for small or very
     * sparse matrices) succeeds on indefinite matrices: only a zero pivot
     * stops it.  SPD means every pivot D(j) > 0, so check them here. */
    if (!L->is_super && !L->is_ll && L->xtype == CHOLMOD_REAL) {
        const int *Lp = L->p;
        const double *Lx = L->x;
        for (size_t j = 0; j < L->n; j++) {
            double d = Lx[Lp[j]];
            if (!(d > 0) || !isfinite(d))
                return cm_seterr("matrix is not positive definite (pivot %g at column %d of %d)",
                                 d, (int)j, (int)L->n);
        }
    }
    /* A positive semi-definite matrix (a Laplacian without a fixed value)
     * factors "successfully" with a last pivot at roundoff level.  CHOLMOD's
     * rcond estimate (smallest over largest pivot of D, or of diag(L)
     * squared) then sits near machine epsilon; call it singular below
     * n * eps.  Well-posed systems of this library stay far above that
     * (a 90k-vertex -L + 1e-8 M: 9e-10, bound 2e-11). */
    double rc = cholmod_rcond(L, c);
    double bound = (double)(L->n > 0 ? L->n : 1) * DBL_EPSILON;
    if (L->n > 1 && !(rc >= bound))
        return cm_seterr("matrix is not positive definite (numerically singular: "
                         "pivot ratio %.3g below %.3g)", rc, bound);
    return 0;
}

/* a symmetric view of A: CHOLMOD wants stype != 0 to treat it as symmetric */
static cholmod_sparse *sym_view(const cholmod_sparse *A, int *copied)
{
    *copied = 0;
    if (A->stype != 0)
        return (cholmod_sparse *)A;
    cholmod_sparse *U = cholmod_copy((cholmod_sparse *)A, 1, 1, cm_cholmod());
    *copied = 1;
    return U;
}

struct spd_solver *spd_factor(const cholmod_sparse *A)
{
    cholmod_common *c = cm_cholmod();
    if (A->nrow != A->ncol) {
        cm_seterr("matrix is not square (%d by %d)", (int)A->nrow, (int)A->ncol);
        return NULL;
    }
    int copied;
    cholmod_sparse *S = sym_view(A, &copied);
    if (!S) { cm_seterr("out of memory"); return NULL; }
    cholmod_factor *L = cholmod_analyze(S, c);
    if (!L) {
        if (copied) cholmod_free_sparse(&S, c);
        cm_seterr("CHOLMOD analysis failed (status %d)", c->status);
        return NULL;
    }
    cholmod_factorize(S, L, c);
    if (copied) cholmod_free_sparse(&S, c);
    if (check_factor(L, c) < 0) {
        cholmod_free_factor(&L, c);
        return NULL;
    }
    struct spd_solver *s = malloc(sizeof *s);
    if (!s) {
        cholmod_free_factor(&L, c);
        cm_seterr("out of memory");
        return NULL;
    }
    s->n = (int)A->nrow;
    s->L = L;
    return s;
}

int spd_refactor(struct spd_solver *s, const cholmod_sparse *A)
{
    cholmod_common *c = cm_cholmod();
    int copied;
    cholmod_sparse *S = sym_view(A, &copied);
    cholmod_factorize(S, s->L, c);
    if (copied) cholmod_free_sparse(&S, c);
    return check_factor(s->L, c);
}

int spd_size(const struct spd_solver *s) { return s->n; }

int spd_solve(struct spd_solver *s, const double *B, double *X, int ncols)
{
    cholmod_common *c = cm_cholmod();
    int n = s->n;
    cholmod_dense *b = cholmod_allocate_dense(n, ncols, n, CHOLMOD_REAL, c);
    if (!b) return cm_seterr("out of memory");
    double *bx = b->x;
    for (int i = 0; i < n; i++)                   /* row-major -> column-major */
        for (int j = 0; j < ncols; j++) bx[(size_t)j * n + i] = B[(size_t)i * ncols + j];
    cholmod_dense *x = cholmod_solve(CHOLMOD_A, s->L, b, c);
    cholmod_free_dense(&b, c);
    if (!x) return cm_seterr("CHOLMOD solve failed (status %d)", c->status);
    double *xx = x->x;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < ncols; j++) X[(size_t)i * ncols + j] = xx[(size_t)j * n + i];
    cholmod_free_dense(&x, c);
    return 0;
}

void spd_free(struct spd_solver *s)
{
    if (!s) return;
    cholmod_free_factor(&s->L, cm_cholmod());
    free(s);
}

/* ---------------- quadratic with fixed values ---------------- */

struct quad_solver {
    int n, nu;
    int *uid;                 /* n: index among unknowns, or -1 if fixed */
    int *urow;                /* nu: original index of unknown k */
    cholmod_sparse *Quk;      /* nu by n-nu coupling block (fixed columns) */
    int *kid;                 /* n: index among fixed, or -1 */
    struct spd_solver *S;
};

struct quad_solver *quad_solver_new(const cholmod_sparse *Q, const unsigned char *fixed)
{
    cholmod_common *c = cm_cholmod();
    int n = (int)Q->nrow;
    struct quad_solver *q = calloc(1, sizeof *q);
    q->n = n;
    q->uid = malloc((n + 1) * sizeof *q->uid);
    q->kid = malloc((n + 1) * sizeof *q->kid);
    q->urow = malloc((n + 1) * sizeof *q->urow);
    int nu = 0, nk = 0;
    for (int i = 0; i < n; i++) {
        if (fixed && fixed[i]) { q->uid[i] = -1; q->kid[i] = nk++; }
        else { q->kid[i] = -1; q->urow[nu] = i; q->uid[i] = nu++; }
    }
    q->nu = nu;
    if (nu == 0)
        return q;
    /* split Q (use all stored entries; expand a symmetric matrix) */
    cholmod_sparse *A = Q->stype ? cholmod_copy((cholmod_sparse *)Q, 0, 1, c)
                                 : (cholmod_sparse *)Q;
    struct triplets Tuu, Tuk;
    triplets_init(&Tuu, nu, nu);
    triplets_init(&Tuk, nu, nk > 0 ? nk : 1);
    const int *p = A->p, *ii = A->i;
    const double *ax = A->x;
    for (int j = 0; j < n; j++)
        for (int k = p[j]; k < p[j + 1]; k++) {
            int i = ii[k];
            if (q->uid[i] < 0) continue;
            if (q->uid[j] >= 0) triplets_add(&Tuu, q->uid[i], q->uid[j], ax[k]);
            else triplets_add(&Tuk, q->uid[i], q->kid[j], ax[k]);
        }
    if (A != Q) cholmod_free_sparse(&A, c);
    cholmod_sparse *Quu = triplets_to_sparse(&Tuu, 1);
    q->Quk = triplets_to_sparse(&Tuk, 0);
    triplets_free(&Tuu);
    triplets_free(&Tuk);
    q->S = spd_factor(Quu);
    cholmod_free_sparse(&Quu, c);
    if (!q->S) {
        char m[600];
        snprintf(m, sizeof m, "%s", cm_errmsg());
        cm_seterr("free block of the quadratic: %s", m);
        quad_solver_free(q);
        return NULL;
    }
    return q;
}

int quad_solver_solve(struct quad_solver *q, const double *b, const double *y, double *x,
                      int ncols)
{
    int n = q->n, nu = q->nu;
    if (y) {
        for (int i = 0; i < n; i++)
            if (q->uid[i] < 0) memcpy(x + (size_t)i * ncols, y + (size_t)i * ncols, ncols * sizeof *x);
    } else {
        for (int i = 0; i < n; i++)
            if (q->uid[i] < 0) memset(x + (size_t)i * ncols, 0, ncols * sizeof *x);
    }
    if (nu == 0)
        return 0;
    double *rhs = calloc((size_t)nu * ncols + 1, sizeof *rhs);
    if (b)
        for (int k = 0; k < nu; k++)
            memcpy(rhs + (size_t)k * ncols, b + (size_t)q->urow[k] * ncols, ncols * sizeof *rhs);
    if (y) {
        /* rhs -= Q_uk y_k */
        const int *p = q->Quk->p, *ii = q->Quk->i;
        const double *ax = q->Quk->x;
        int kcol = 0;
        for (int j = 0; j < n; j++) {
            if (q->uid[j] >= 0) continue;
            for (int k = p[kcol]; k < p[kcol + 1]; k++)
                for (int c = 0; c < ncols; c++)
                    rhs[(size_t)ii[k] * ncols + c] -= ax[k] * y[(size_t)j * ncols + c];
            kcol++;
        }
    }
    int rc = spd_solve(q->S, rhs, rhs, ncols);
    if (rc == 0)
        for (int k = 0; k < nu; k++)
            memcpy(x + (size_t)q->urow[k] * ncols, rhs + (size_t)k * ncols, ncols * sizeof *x);
    free(rhs);
    return rc;
}

void quad_solver_free(struct quad_solver *q)
{
    if (!q) return;
    spd_free(q->S);
    if (q->Quk) cholmod_free_sparse(&q->Quk, cm_cholmod());
    free(q->uid);
    free(q->kid);
    free(q->urow);
    free(q);
}
