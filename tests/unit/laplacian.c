/* laplacian: symmetric, rows_sum_to_zero, linear_precision_on_flat_meshes,
 * five_point_stencil_on_regular_grid, mass_sums_to_area (barycentric, Voronoi) */
#include "laplacian.h"
#include "geometry.h"
#include "tap.h"
#include "topology.h"
#include <stdlib.h>
#include "testmesh.h"
#include <math.h>
#include <string.h>

/* dense copy of a small stype-0 matrix */
static double *dense(const cholmod_sparse *A)
{
    int n = (int)A->nrow;
    double *D = calloc((size_t)n * n, sizeof *D);
    const int *p = A->p, *i = A->i;
    const double *x = A->x;
    for (int j = 0; j < (int)A->ncol; j++)
        for (int k = p[j]; k < p[j + 1]; k++) D[(size_t)i[k] * n + j] += x[k];
    return D;
}

static void check_symmetric_rowsum(const char *what, const double *V, const int *F, int nv, int nf)
{
    cholmod_sparse *L = cot_laplacian(V, F, nv, nf);
    double *D = dense(L);
    double asym = 0, rowsum = 0, scale = 0;
    int diag_neg = 1;
    for (int i = 0; i < nv; i++) {
        double s = 0;
        for (int j = 0; j < nv; j++) {
            double d = fabs(D[(size_t)i * nv + j] - D[(size_t)j * nv + i]);
            if (d > asym) asym = d;
            s += D[(size_t)i * nv + j];
            if (fabs(D[(size_t)i * nv + j]) > scale) scale = fabs(D[(size_t)i * nv + j]);
        }
        if (fabs(s) > rowsum) rowsum = fabs(s);
        diag_neg &= D[(size_t)i * nv + i] <= 0;
    }
    ok(asym == 0, "cot_laplacian: symmetric on %s (max |L - L^T| %g)", what, asym);
    ok(rowsum <= 1e-13 * scale, "cot_laplacian: rows_sum_to_zero on %s (max %g)", what, rowsum);
    ok(diag_neg, "cot_laplacian: nonpositive diagonal on %s", what);
    /* the per-edge weights are the off-diagonal entries */
    struct topology t;
    topology_build(F, nf, nv, &t);
    double *W = malloc((size_t)t.ne * sizeof *W + 1), werr = 0;
    cot_edge_weights(V, F, nf, &t, W);
    for (int e = 0; e < t.ne; e++) {
        double d = fabs(W[e] - D[(size_t)t.E[2 * e] * nv + t.E[2 * e + 1]]);
        if (d > werr) werr = d;
    }
    ok(werr <= 1e-14 * scale, "cot_edge_weights: equal the Laplacian's off-diagonal on %s (max %g)", what, werr);
    free(W);
    topology_free(&t);
    free(D);
    sparse_free(&L);
}

static void check_mass(const char *what, const double *V, const int *F, int nv, int nf)
{
    double *M = malloc(sizeof *M * nv);
    double area = mesh_area(V, F, nf);
    mass_diag(V, F, nv, nf, MASS_BARYCENTRIC, M);
    double s = 0;
    int pos = 1;
    for (int i = 0; i < nv; i++) { s += M[i]; pos &= M[i] > 0; }
    ok(fabs(s - area) <= 1e-12 * area && pos,
       "mass_diag: barycentric sums to area on %s (%.17g vs %.17g)", what, s, area);
    mass_diag(V, F, nv, nf, MASS_VORONOI, M);
    s = 0;
    pos = 1;
    for (int i = 0; i < nv; i++) { s += M[i]; pos &= M[i] > 0; }
    ok(fabs(s - area) <= 1e-12 * area && pos,
       "mass_diag: voronoi sums to area on %s (%.17g vs %.17g)", what, s, area);
    free(M);
}

int main(void)
{
    double *V;
    int *F, nv, nf;

    /* regular grid: the cot Laplacian is the 5-point stencil */
    int n = 8;
    grid_mesh(n, n, 0, 1, &V, &F, &nv, &nf);
    check_symmetric_rowsum("regular grid", V, F, nv, nf);
    cholmod_sparse *L = cot_laplacian(V, F, nv, nf);
    double *D = dense(L);
    double err = 0;
    for (int j = 1; j < n; j++)
        for (int i = 1; i < n; i++) {
            int v = j * (n + 1) + i;
            for (int w = 0; w < nv; w++) {
                int di = abs(w % (n + 1) - i), dj = abs(w / (n + 1) - j);
                double want = w == v ? -4 : di + dj == 1 ? 1 : 0;
                double e = fabs(D[(size_t)v * nv + w] - want);
                if (e > err) err = e;
            }
        }
    ok(err < 1e-14, "cot_laplacian: five_point_stencil_on_regular_grid (max err %g)", err);
    free(D);
    /* L applied to a linear function vanishes at interior vertices */
    for (int pass = 0; pass < 2; pass++) {
        if (pass) {
            sparse_free(&L);
            free(V); free(F);
            grid_mesh(12, 9, 0.6, 7, &V, &F, &nv, &nf);
            L = cot_laplacian(V, F, nv, nf);
        }
        double *u = malloc(sizeof *u * nv), *Lu = malloc(sizeof *Lu * nv);
        for (int i = 0; i < nv; i++) u[i] = 0.3 + 2 * V[3 * i] - 1.7 * V[3 * i + 1];
        sparse_mul(L, u, Lu);
        double worst = 0;
        int gn = pass ? 12 : n, gm = pass ? 9 : n;
        for (int j = 1; j < gm; j++)
            for (int i = 1; i < gn; i++)
                if (fabs(Lu[j * (gn + 1) + i]) > worst) worst = fabs(Lu[j * (gn + 1) + i]);
        ok(worst < 1e-12, "cot_laplacian: linear_precision at interior vertices, %s grid (max %g)",
           pass ? "jittered" : "regular", worst);
        free(u); free(Lu);
    }
    sparse_free(&L);
    check_symmetric_rowsum("jittered grid", V, F, nv, nf);
    int nobtuse = 0;
    for (int f = 0; f < nf; f++)
        for (int c = 0; c < 3; c++) {
            double e1[3], e2[3];
            sub3(V + 3 * F[3 * f + (c + 1) % 3], V + 3 * F[3 * f + c], e1);
            sub3(V + 3 * F[3 * f + (c + 2) % 3], V + 3 * F[3 * f + c], e2);
            nobtuse += dot3(e1, e2) < 0;
        }
    ok(nobtuse > 10, "setup: the jittered grid has obtuse triangles (%d)", nobtuse);
    check_mass("jittered grid (obtuse triangles)", V, F, nv, nf);
    free(V); free(F);

    grid_mesh(5, 5, 0, 1, &V, &F, &nv, &nf);
    double *M = malloc(sizeof *M * nv);
    mass_diag(V, F, nv, nf, MASS_VORONOI, M);
    /* right isosceles triangles: an interior vertex owns h^2 */
    ok(fabs(M[2 * 6 + 2] - 1.0 / 25) < 1e-15, "mass_diag: voronoi interior vertex of regular grid = h^2 (%g)",
       M[2 * 6 + 2]);
    free(M);
    check_mass("regular grid", V, F, nv, nf);
    free(V); free(F);

    icosahedron(&V, &F, &nv, &nf);
    check_symmetric_rowsum("icosahedron", V, F, nv, nf);
    check_mass("icosahedron", V, F, nv, nf);
    free(V); free(F);

    cylinder_mesh(9, 4, &V, &F, &nv, &nf);
    check_symmetric_rowsum("cylinder", V, F, nv, nf);
    check_mass("cylinder", V, F, nv, nf);
    free(V); free(F);

    /* a degenerate (zero-area) face contributes nothing, not NaN */
    double Vd[9] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    int Fd[3] = {0, 1, 2};
    L = cot_laplacian(Vd, Fd, 3, 1);
    const double *x = L->x;
    int finite = 1;
    for (int k = 0; k < ((int *)L->p)[3]; k++) finite &= isfinite(x[k]);
    ok(finite, "cot_laplacian: degenerate face gives finite entries");
    sparse_free(&L);

    /* umbrella_smooth: a jittered flat grid gets smoother and stays flat;
     * a regular grid's interior is a fixed point; the mask is respected */
    {
        double *Vg, *Vr;
        int *Fg, *Fr, ng, nfg;
        grid_mesh(8, 8, 0.8, 3, &Vg, &Fg, &ng, &nfg);
        grid_mesh(8, 8, 0, 3, &Vr, &Fr, &ng, &nfg);
        struct topology tg;
        topology_build(Fg, nfg, ng, &tg);
        double before = 0, after = 0, z = 0;
        for (int v = 0; v < 3 * ng; v++) before += fabs(Vg[v] - Vr[v]);
        unsigned char *mask = calloc(ng, 1);
        for (int j = 1; j < 8; j++) for (int i = 1; i < 8; i++) mask[j * 9 + i] = 1;
        double *Vb = malloc(sizeof(double) * 3 * ng);
        memcpy(Vb, Vg, sizeof(double) * 3 * ng);
        ok(umbrella_smooth(&tg, mask, 0.5, 20, Vg) == 0, "umbrella_smooth runs");
        int still = 1;
        for (int v = 0; v < ng; v++) {
            for (int d = 0; d < 3; d++) after += fabs(Vg[3 * v + d] - Vr[3 * v + d]);
            z += fabs(Vg[3 * v + 2]);
            if (!mask[v]) still &= !memcmp(Vg + 3 * v, Vb + 3 * v, 3 * sizeof(double));
        }
        ok(after < 0.5 * before && z == 0, "umbrella_smooth: jitter %.3g -> %.3g, flat", before, after);
        ok(still, "umbrella_smooth: unmasked (boundary) vertices stay");
        free(Vg); free(Vr); free(Fg); free(Fr); free(mask); free(Vb);
        topology_free(&tg);
    }
    return tap_done();
}
