/* thin_shell: jacobian_matches_finite_differences (stretch, bend, volume,
 * landmark rows, enclosed-volume gradient), energy_decreases_monotonically, rest_shape_has_zero_energy,
 * bad_landmark_is_reported */
#include "thin_shell.h"
#include "cm_error.h"
#include "rng.h"
#include "tap.h"
#include "testmesh.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int main(void)
{
    double *V;
    int *F, nv, nf;
    icosahedron(&V, &F, &nv, &nf);
    struct rng rg;
    rng_seed(&rg, 7);
    double k[12];
    for (int v = 0; v < nv; v++) k[v] = 1 + 9 * rng_uniform(&rg);
    int H[2] = {0, 5};
    struct thin_shell_params p;
    thin_shell_defaults(&p);
    p.kb = 2; p.kv = 3; p.kvg = 2;
    struct thin_shell *s = thin_shell_new(V, F, nv, nf, k, H, 2, &p);
    ok(s != NULL, "thin_shell_new on an icosahedron");
    int m = thin_shell_nres(s);
    ok(m == 30 + 30 + 20 + 6, "residual count: 30 stretch + 30 bend + 20 volume + 6 landmark (%d)", m);
    double T[6];
    for (int d = 0; d < 3; d++) { T[d] = V[d]; T[3 + d] = V[15 + d]; }
    ok(thin_shell_energy(s, V, T) < 1e-24, "rest shape with targets at rest: zero energy");

    /* finite differences at a perturbed pose */
    double *X = malloc(sizeof *X * 3 * nv), *Xp = malloc(sizeof *Xp * 3 * nv);
    for (int i = 0; i < 3 * nv; i++) X[i] = V[i] + 0.15 * rng_normal(&rg);
    T[0] += 0.3; T[4] -= 0.2;
    double *r = malloc(sizeof *r * m), *rp = malloc(sizeof *rp * m), *rm = malloc(sizeof *rm * m);
    double *g = malloc(sizeof *g * 12 * m);
    int *idx = malloc(sizeof *idx * 4 * m);
    thin_shell_residuals(s, X, T, r, idx, g);
    double worst = 0, scale = 0, h = 1e-6;
    for (int i = 0; i < 3 * nv; i++) {
        memcpy(Xp, X, sizeof *X * 3 * nv);
        Xp[i] += h; thin_shell_residuals(s, Xp, T, rp, NULL, NULL);
        Xp[i] -= 2 * h; thin_shell_residuals(s, Xp, T, rm, NULL, NULL);
        for (int q = 0; q < m; q++) {
            double fd = (rp[q] - rm[q]) / (2 * h), an = 0;
            for (int a = 0; a < 4; a++)
                if (idx[4 * q + a] == i / 3) an += g[12 * q + 3 * a + i % 3];
            if (fabs(fd - an) > worst) worst = fabs(fd - an);
            if (fabs(an) > scale) scale = fabs(an);
        }
    }
    ok(worst < 1e-6 * scale, "Jacobian matches central differences (max err %.3g, max entry %.3g)",
       worst, scale);

    double *gv = malloc(sizeof *gv * 3 * nv), vworst = 0, vscale = 0;
    thin_shell_volume_residual(s, X, gv);
    for (int i = 0; i < 3 * nv; i++) {
        memcpy(Xp, X, sizeof *X * 3 * nv);
        Xp[i] += h; double a = thin_shell_volume_residual(s, Xp, NULL);
        Xp[i] -= 2 * h; double b = thin_shell_volume_residual(s, Xp, NULL);
        if (fabs((a - b) / (2 * h) - gv[i]) > vworst) vworst = fabs((a - b) / (2 * h) - gv[i]);
        if (fabs(gv[i]) > vscale) vscale = fabs(gv[i]);
    }
    ok(vscale > 0 && vworst < 1e-6 * vscale,
       "enclosed-volume gradient matches central differences (max err %.3g, max entry %.3g)", vworst, vscale);
    free(gv);

    /* Gauss-Newton: monotone energy decrease toward moved targets */
    memcpy(X, V, sizeof *X * 3 * nv);
    double E[21];
    ok(thin_shell_solve(s, T, 20, X, E) == 0, "thin_shell_solve runs");
    int mono = 1;
    for (int i = 0; i < 20; i++) mono &= E[i + 1] <= E[i];
    ok(mono && E[20] < 0.5 * E[0], "energy decreases monotonically (%.4g -> %.4g)", E[0], E[20]);
    thin_shell_free(s);

    int bad[1] = {99};
    ok(thin_shell_new(V, F, nv, nf, NULL, bad, 1, NULL) == NULL && strstr(cm_errmsg(), "out of range"),
       "bad landmark index is reported: %s", cm_errmsg());
    free(V); free(F); free(X); free(Xp); free(r); free(rp); free(rm); free(g); free(idx);
    return tap_done();
}
