/* bilaplacian / seam unit tests: Q = L^T M^-1 L is symmetric with the
 * constants in its null space; the seam and its roles are found; the
 * constrained minimizer of tr(D^T Q D) is minimal (any perturbation of the
 * free vertices raises the energy) and has zero gradient on the free rows. */
#include "bilaplacian.h"
#include "cm_error.h"
#include "rng.h"
#include "seam.h"
#include "spd.h"
#include "tap.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* n x n grid (bumpy), plus one separate triangle when `extra` */
static void grid(int n, int extra, double **V, int **F, int *nv, int *nf)
{
    *nv = (n + 1) * (n + 1) + 3 * extra;
    *nf = 2 * n * n + extra;
    *V = malloc(*nv * 3 * sizeof **V);
    *F = malloc(*nf * 3 * sizeof **F);
    int k = 0;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++, k++) {
            double x = (double)i / n, y = (double)j / n;
            (*V)[3 * k] = x; (*V)[3 * k + 1] = y; (*V)[3 * k + 2] = 0.1 * sin(3 * x) * cos(2 * y);
        }
    int f = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, c = a + n + 2;
            int t[6] = {a, a + 1, c, a, c, c - 1};
            memcpy(*F + 3 * f, t, sizeof t);
            f += 2;
        }
    if (extra) {
        double p[9] = {2, 0, 0, 3, 0, 0, 2, 1, 0};
        memcpy(*V + 3 * k, p, sizeof p);
        int t[3] = {k, k + 1, k + 2};
        memcpy(*F + 3 * f, t, sizeof t);
    }
}

int main(void)
{
    int n = 12, nv, nf;
    double *V;
    int *F;
    grid(n, 1, &V, &F, &nv, &nf);
    struct topology t;
    topology_build(F, nf, nv, &t);

    /* Q: symmetric upper storage, constants in the null space */
    cholmod_sparse *Q = bilaplacian(V, F, nv, nf, MASS_VORONOI);
    ok(Q != NULL && Q->stype == 1, "bilaplacian: upper symmetric storage (stype %d)", Q ? Q->stype : -9);
    double *one = malloc(nv * sizeof *one), *Qo = malloc(nv * sizeof *Qo);
    for (int i = 0; i < nv; i++) one[i] = 1;
    sparse_mul(Q, one, Qo);
    double mx = 0, qmax = 0;
    for (int i = 0; i < nv; i++) if (fabs(Qo[i]) > mx) mx = fabs(Qo[i]);
    for (size_t k = 0; k < (size_t)((int *)Q->p)[nv]; k++)
        if (fabs(((double *)Q->x)[k]) > qmax) qmax = fabs(((double *)Q->x)[k]);
    ok(mx < 1e-9 * qmax, "bilaplacian: constant_in_null_space (|Q 1| = %g, max |Q| = %g)", mx, qmax);

    /* energy: >= 0, and the energy of a constant field is 0 */
    struct rng g;
    rng_seed(&g, 7);
    double *D = malloc(nv * 3 * sizeof *D), *C = malloc(nv * 3 * sizeof *C);
    for (int i = 0; i < 3 * nv; i++) D[i] = rng_normal(&g);
    for (int i = 0; i < nv; i++) { C[3 * i] = 1; C[3 * i + 1] = -2; C[3 * i + 2] = 0.5; }
    ok(quadratic_energy(Q, D, 3) > 0, "quadratic_energy: positive for a random field");
    ok(fabs(quadratic_energy(Q, C, 3)) < 1e-9 * qmax * nv, "quadratic_energy: zero for a constant field");

    /* seam: labels left (x < 0.5) / right of the grid */
    int *P = malloc(nf * sizeof *P);
    for (int f = 0; f < nf; f++) {
        double cx = (V[3 * F[3 * f]] + V[3 * F[3 * f + 1]] + V[3 * F[3 * f + 2]]) / 3;
        P[f] = f == nf - 1 ? 0 : cx > 0.5;
    }
    unsigned char *seam = malloc(nv), *role = malloc(nv);
    int ns = seam_vertices(&t, P, seam);
    ok(ns == n + 1, "seam_vertices: one grid column (%d, want %d)", ns, n + 1);
    int col_ok = 1;
    for (int v = 0; v < (n + 1) * (n + 1); v++)
        if (seam[v] != (v % (n + 1) == n / 2)) col_ok = 0;
    ok(col_ok, "seam_vertices: exactly the column x = 0.5");
    ok(seam_check_manifold(&t, seam) == 0, "seam_check_manifold: a grid is fine");
    int nfix = seam_roles(&t, F, seam, 1, role);
    ok(nfix == 3 * (n + 1), "seam_roles: seam and one-ring fixed (%d, want %d)", nfix, 3 * (n + 1));
    ok(role[nv - 1] == SEAM_KEEP && role[nv - 2] == SEAM_KEEP,
       "seam_roles: a component without seam is kept");

    /* minimize with random fixed values: perturbations raise the energy */
    unsigned char *fixed = malloc(nv);
    for (int v = 0; v < nv; v++) fixed[v] = role[v] != SEAM_FREE;
    struct quad_solver *S = quad_solver_new(Q, fixed);
    ok(S != NULL, "quad_solver: free block of Q is positive definite");
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++)
            D[3 * v + d] = role[v] == SEAM_FIXED ? rng_normal(&g) : 0;
    quad_solver_solve(S, NULL, D, D, 3);
    double E = quadratic_energy(Q, D, 3);
    int worse = 1;
    double *Pd = malloc(nv * 3 * sizeof *Pd);
    for (int trial = 0; trial < 50; trial++) {
        double eps = pow(10, -(trial % 7));
        memcpy(Pd, D, nv * 3 * sizeof *Pd);
        for (int v = 0; v < nv; v++)
            if (role[v] == SEAM_FREE)
                for (int d = 0; d < 3; d++) Pd[3 * v + d] += eps * rng_normal(&g);
        if (!(quadratic_energy(Q, Pd, 3) > E)) worse = 0;
    }
    ok(worse, "minimizer: 50 perturbations of the free vertices all raise the energy %g", E);
    /* gradient (Q D) on the free rows vanishes */
    double *col = malloc(nv * sizeof *col), *qc = malloc(nv * sizeof *qc), gmax = 0, dmax = 0;
    for (int d = 0; d < 3; d++) {
        for (int v = 0; v < nv; v++) col[v] = D[3 * v + d];
        sparse_mul(Q, col, qc);
        for (int v = 0; v < nv; v++) {
            if (role[v] == SEAM_FREE && fabs(qc[v]) > gmax) gmax = fabs(qc[v]);
            if (fabs(col[v]) > dmax) dmax = fabs(col[v]);
        }
    }
    ok(gmax < 1e-9 * qmax * dmax, "minimizer: gradient on free rows %g", gmax);
    quad_solver_free(S);

    /* non-manifold edge on the seam is reported */
    int Fn[9] = {0, 1, 2, 0, 1, 3, 0, 1, 4}, Pn[3] = {0, 1, 1};
    struct topology tn;
    topology_build(Fn, 3, 5, &tn);
    unsigned char sn[5];
    seam_vertices(&tn, Pn, sn);
    ok(seam_check_manifold(&tn, sn) < 0 && strstr(cm_errmsg(), "non-manifold edge 0-1"),
       "seam_check_manifold: non-manifold edge 0-1 reported (%s)", cm_errmsg());
    topology_free(&tn);

    topology_free(&t);
    cholmod_free_sparse(&Q, cm_cholmod());
    free(V); free(F); free(one); free(Qo); free(D); free(C); free(P); free(seam); free(role);
    free(fixed); free(Pd); free(col); free(qc);
    return tap_done();
}
