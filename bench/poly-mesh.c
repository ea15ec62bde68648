/* poly-mesh -- bench baseline for compat-tri's refinement: CGAL's 2D
 * Delaunay mesher (refine_Delaunay_mesh_2, shape bound 0.125, about 20.7
 * degrees, no size bound) on the outer ring of one rings file.
 *
 *   poly-mesh FILE   prints "vertices V triangles F minangle A under10 P
 *                    under20 Q cpu C" (A in degrees, P and Q in percent of
 *                    the triangles, C the CPU seconds of the meshing)
 */
#include "cdt2.h"
#include "rings.h"
#include "cm_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc != 2) { fprintf(stderr, "usage: poly-mesh RINGS\n"); return 2; }
    struct rings R;
    if (rings_read(argv[1], &R) < 0) { fprintf(stderr, "poly-mesh: %s\n", cm_errmsg()); return 1; }
    double *V; int *F, nv, nf;
    double t0 = cpu();
    if (cdt2_mesh_polygon(rings_ring(&R, 0), rings_count(&R, 0), 0.125, 0, &V, &nv, &F, &nf) < 0) {
        fprintf(stderr, "poly-mesh: %s\n", cm_errmsg());
        return 1;
    }
    double t1 = cpu(), mn = 180;
    int n10 = 0, n20 = 0;
    for (int f = 0; f < nf; f++) {
        double q = 180;
        for (int k = 0; k < 3; k++) {
            const double *o = V + 2 * F[3 * f + k], *u = V + 2 * F[3 * f + (k + 1) % 3], *v = V + 2 * F[3 * f + (k + 2) % 3];
            double ux = u[0] - o[0], uy = u[1] - o[1], vx = v[0] - o[0], vy = v[1] - o[1];
            q = fmin(q, atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI);
        }
        mn = fmin(mn, q);
        n10 += q < 10;
        n20 += q < 20;
    }
    printf("vertices %d triangles %d minangle %.2f under10 %.1f under20 %.1f cpu %.4f\n", nv, nf, mn,
           100.0 * n10 / nf, 100.0 * n20 / nf, t1 - t0);
    free(V); free(F); rings_free(&R);
    return 0;
}
