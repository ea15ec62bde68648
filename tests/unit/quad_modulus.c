/* quad_modulus.c -- the modulus brackets of quad_modulus and the
 * certificate of modulus_cert:
 *   quad_modulus: rectangle_exact (w x h with its corners: h / w, which
 *     P1 elements reproduce), brackets_contain_exact_value on quadrilaterals
 *     whose modulus is 1 by a symmetry exchanging the two pairs of sides
 *     (a square with its edge midpoints: singular points on straight
 *     edges; a plus shape with its arm tips: re-entrant corners; an L shape
 *     with the re-entrant corner as a marked point), conjugate_reciprocal,
 *     similarity_invariant, nested_brackets_shrink, bad_input_fails;
 *   modulus_cert: affine_distortion_max matches the singular values of
 *     random triangles (never above the bound, the bound reached at the
 *     extreme triangle), angle_ceiling inverts it, and the certificate of a
 *     hidden leg is below 20 degrees, of a rectangle and a stretched copy
 *     high, with the pair and the rows named.
 */
#include "quad_modulus.h"
#include "modulus_cert.h"
#include "cm_error.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int brackets(double lo, double hi, double exact) { return lo <= exact * (1 + 1e-12) && exact <= hi * (1 + 1e-12); }

/* singular values ratio of the 2x2 matrix A (row-major) */
static double svratio(const double A[4])
{
    double a = A[0], b = A[1], c = A[2], d = A[3];
    double s = a * a + b * b + c * c + d * d, det = fabs(a * d - b * c);
    double r = sqrt(s * s - 4 * det * det);
    return sqrt((s + r) / (s - r));
}

/* the affine map from the equilateral triangle onto the triangle with angles A, B (and pi - A - B) */
static double tri_distortion(double A, double B)
{
    /* target: (0,0), (1,0), and the apex from the angles at the first two corners */
    double C = M_PI - A - B, c = 1, b = c * sin(B) / sin(C);
    double T[4] = {1, b * cos(A), 0, b * sin(A)};   /* columns: edge 1, edge 2 */
    double E[4] = {1, 0.5, 0, sqrt(3) / 2};
    /* M = T E^-1 */
    double det = E[0] * E[3] - E[1] * E[2];
    double Ei[4] = {E[3] / det, -E[1] / det, -E[2] / det, E[0] / det};
    double M[4] = {T[0] * Ei[0] + T[1] * Ei[2], T[0] * Ei[1] + T[1] * Ei[3], T[2] * Ei[0] + T[3] * Ei[2],
                   T[2] * Ei[1] + T[3] * Ei[3]};
    return svratio(M);
}

int main(void)
{
    double lo = 0, hi = 0;
    int nv, rc;

    /* rectangle_exact */
    double R[] = {0, 1, 0, 0, 2, 0, 2, 1};
    int I[4] = {0, 1, 2, 3};
    rc = quad_modulus(R, 4, I, 0.01, 100000, &lo, &hi);
    ok(rc == 0 && fabs(lo - 0.5) < 1e-12 && fabs(hi - 0.5) < 1e-12,
       "quad_modulus: rectangle_exact 2 x 1: %.15g %.15g (h / w = 0.5)", lo, hi);
    int I2[4] = {1, 2, 3, 0};
    rc = quad_modulus(R, 4, I2, 0.01, 100000, &lo, &hi);
    ok(rc == 0 && fabs(lo - 2) < 1e-12 && fabs(hi - 2) < 1e-12,
       "quad_modulus: rectangle_exact conjugate: %.15g %.15g (w / h = 2)", lo, hi);
    double Sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    rc = quad_modulus(Sq, 4, I, 0.01, 100000, &lo, &hi);
    ok(rc == 0 && fabs(lo - 1) < 1e-12 && fabs(hi - 1) < 1e-12,
       "quad_modulus: rectangle_exact square: %.15g %.15g", lo, hi);

    /* brackets_contain_exact_value: square with edge midpoints */
    double Mid[] = {0.5, 0, 1, 0, 1, 0.5, 1, 1, 0.5, 1, 0, 1, 0, 0.5, 0, 0};
    int J[4] = {0, 2, 4, 6};
    struct quad_modulus *q = quad_modulus_new(Mid, 8, J);
    double plo = 0, phi = INFINITY;
    int nested = 1, okb = q != NULL;
    for (int it = 0; q && it < 5; it++) {
        if (quad_modulus_refine(q, 0.16 / (1 << it), 1000000) < 0) { okb = 0; break; }
        quad_modulus_bracket(q, &lo, &hi, &nv);
        okb &= brackets(lo, hi, 1);
        nested &= lo >= plo && hi <= phi;
        plo = lo; phi = hi;
    }
    ok(okb && hi / lo - 1 <= 0.01, "quad_modulus: brackets_contain_exact_value square with edge midpoints: "
       "%.5f-%.5f (%d vertices)", lo, hi, nv);
    ok(nested, "quad_modulus: nested_brackets_shrink (lower bounds grow, upper bounds shrink)");
    quad_modulus_free(q);

    /* plus shape with its arm tips */
    double X[] = {1, 0, 2, 0, 2, 1, 3, 1, 3, 2, 2, 2, 2, 3, 1, 3, 1, 2, 0, 2, 0, 1, 1, 1};
    int K4[4] = {0, 3, 6, 9};
    rc = quad_modulus(X, 12, K4, 0.02, 1000000, &lo, &hi);
    ok(rc == 0 && brackets(lo, hi, 1) && hi / lo - 1 <= 0.02,
       "quad_modulus: brackets_contain_exact_value plus shape: %.5f-%.5f", lo, hi);

    /* L shape, the re-entrant corner marked: reflection in y = x swaps the side pairs */
    double Ls[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
    int KL[4] = {1, 3, 5, 0};
    rc = quad_modulus(Ls, 6, KL, 0.02, 1000000, &lo, &hi);
    ok(rc == 0 && brackets(lo, hi, 1) && hi / lo - 1 <= 0.02,
       "quad_modulus: brackets_contain_exact_value L shape with its re-entrant corner: %.5f-%.5f", lo, hi);

    /* conjugate_reciprocal and similarity_invariant on an irregular heptagon */
    double H[] = {0, 0, 3, -0.5, 4, 1, 3.5, 2.5, 2, 2, 1, 3.2, -0.5, 1.5};
    int Ka[4] = {0, 2, 4, 5}, Kb[4] = {2, 4, 5, 0};
    double alo, ahi, blo, bhi;
    rc = quad_modulus(H, 7, Ka, 0.02, 1000000, &alo, &ahi);
    rc |= quad_modulus(H, 7, Kb, 0.02, 1000000, &blo, &bhi);
    ok(rc == 0 &&
       alo * bhi <= 1 + 1e-12 && ahi * blo >= 1 - 1e-12 && brackets(1 / bhi, 1 / blo, sqrt(alo * ahi)),
       "quad_modulus: conjugate_reciprocal %.5f-%.5f against 1 / (%.5f-%.5f)", alo, ahi, blo, bhi);
    double H2[14];
    for (int i = 0; i < 7; i++) {   /* rotated by 0.7 rad, scaled by 37, moved */
        double x = H[2 * i], y = H[2 * i + 1];
        H2[2 * i] = 37 * (cos(0.7) * x - sin(0.7) * y) + 1000;
        H2[2 * i + 1] = 37 * (sin(0.7) * x + cos(0.7) * y) - 250;
    }
    rc = quad_modulus(H2, 7, Ka, 0.02, 1000000, &lo, &hi);
    ok(rc == 0 && lo <= ahi && alo <= hi,
       "quad_modulus: similarity_invariant %.5f-%.5f against %.5f-%.5f", lo, hi, alo, ahi);

    /* bad_input_fails */
    int Kr[4] = {0, 1, 1, 2}, Ko[4] = {0, 2, 1, 3}, Kx[4] = {0, 1, 2, 9};
    double Rcw[] = {0, 0, 0, 1, 1, 1, 1, 0};
    ok(!quad_modulus_new(R, 4, Kr) && strstr(cm_errmsg(), "repeat"), "quad_modulus: bad_input_fails repeated corner: %s", cm_errmsg());
    ok(!quad_modulus_new(R, 4, Ko) && strstr(cm_errmsg(), "order"), "quad_modulus: bad_input_fails order: %s", cm_errmsg());
    ok(!quad_modulus_new(R, 4, Kx) && strstr(cm_errmsg(), "range"), "quad_modulus: bad_input_fails range: %s", cm_errmsg());
    ok(!quad_modulus_new(Rcw, 4, I) && strstr(cm_errmsg(), "counter-clockwise"), "quad_modulus: bad_input_fails clockwise: %s", cm_errmsg());

    /* affine_distortion_max against random triangles */
    struct rng g;
    rng_seed(&g, 7);
    int below = 1;
    double th = 20 * M_PI / 180, worst = 0;
    for (int t = 0; t < 20000; t++) {
        double A = th + rng_uniform(&g) * (M_PI - 3 * th), B = th + rng_uniform(&g) * (M_PI - 2 * th - A);
        if (M_PI - A - B < th) continue;
        double k = tri_distortion(A, B);
        double formula = 2 / sqrt(3) * (1 / tan(A) + 1 / tan(B) + 1 / tan(M_PI - A - B));
        below &= k <= affine_distortion_max(th) * (1 + 1e-9) && fabs(k + 1 / k - formula) < 1e-8 * formula;
        if (k > worst) worst = k;
    }
    double kmax = affine_distortion_max(th), kext = tri_distortion(th, th);
    ok(below && fabs(kext - kmax) < 1e-9 * kmax && worst > 0.95 * kmax,
       "modulus_cert: affine_distortion_max at 20 deg %.4f, the (20, 20, 140) triangle %.4f, random up to %.4f", kmax,
       kext, worst);
    ok(fabs(kmax - 4.76) < 0.01 && fabs(affine_distortion_max(M_PI / 3) - 1) < 1e-6,
       "modulus_cert: affine_distortion_max 4.76 at 20 deg, 1 at 60 deg");
    ok(fabs(angle_ceiling(kmax * kmax) - th) < 1e-9 && angle_ceiling(0.5) == M_PI / 3,
       "modulus_cert: angle_ceiling inverts Kmax^2 (%.6f deg)", angle_ceiling(kmax * kmax) * 180 / M_PI);

    /* certificate: hidden leg; rectangle against a stretched rectangle */
    double A[] = {0, 0, 4, 0, 4, -8, 4.25, -8, 4.5, -8, 4.5, 0, 10, 0, 10, 4, 0, 4};
    double B[] = {0, 0, 4, 0, 4.05, 0, 4.25, 0, 4.45, 0, 4.5, 0, 10, 0, 10, 4, 0, 4};
    double *P[2] = {A, B};
    int n[2] = {9, 9};
    int corr[12] = {0, 0, 1, 1, 2, 2, 4, 4, 5, 5, 7, 7};
    struct modulus_cert c;
    rc = modulus_certificate(2, P, n, corr, 6, 0.03, &c);
    ok(rc == 0 && c.ceiling < 20 && c.quads == 15 && c.pose[0] == 0 &&
       c.pose[1] == 1 && c.ratio <= c.lo[0] / c.hi[1] * (1 + 1e-12) && c.ratio_hi >= c.ratio,
       "modulus_cert: hidden leg: ratio >= %.2f (to %.2f), poses %d %d, rows %d %d %d %d, ceiling %.2f deg",
       c.ratio, c.ratio_hi, c.pose[0], c.pose[1], c.row[0], c.row[1], c.row[2], c.row[3], c.ceiling);
    double S1[] = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1}, S2[] = {0, 0, 1.5, 0, 3, 0, 3, 1, 1.5, 1, 0, 1};
    double *Ps[2] = {S1, S2};
    int ns[2] = {6, 6}, cs[10] = {0, 0, 1, 1, 2, 2, 3, 3, 5, 5};
    rc = modulus_certificate(2, Ps, ns, cs, 5, 0.03, &c);
    ok(rc == 0 && fabs(c.ratio - 1.5) < 1e-9 &&
       c.ceiling > 50,
       "modulus_cert: stretched rectangle: ratio %.4f-%.4f (the affine stretch 1.5 is the extremal map), ceiling %.1f deg", c.ratio, c.ratio_hi, c.ceiling);
    rc = modulus_certificate(2, Ps, ns, cs, 3, 0.03, &c);
    ok(rc == 0 && c.ratio == 0 && c.ceiling == 60,
       "modulus_cert: fewer than 4 points: no certificate");
    return tap_done();
}
