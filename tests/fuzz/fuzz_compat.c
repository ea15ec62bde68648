/* fuzz_compat.c -- compat-tri's stages (compat_tri.h) on two outlines.
 * The input is two rings files separated by a line "--"; each must read
 * and be one simple ring (as compat-tri requires); three correspondences
 * split both at thirds.  Oracle: a triangulation that succeeds is
 * positively oriented in both shapes by the exact predicate, and stays so
 * after compat_improve (a double area can round to zero or below for a
 * sliver at coordinates near 1e17 that is exactly positive). */
#include "fuzz_shapes.h"

/* one simple ring of at most 64 points */
static int compat_keep(const struct rings *r)
{
    return r->nrings == 1 && rings_count(r, 0) <= 64 && rings_check_simple(r) == 0;
}

FUZZ_TARGET(compat)(const uint8_t *data, size_t size)
{
    struct rings R[2];
    int ok = fuzz_two_shapes(data, size, R, compat_keep);
    if (ok) {
        rings_orient(&R[0]);
        rings_orient(&R[1]);
        double *P[2] = {R[0].P, R[1].P};
        int n[2] = {rings_count(&R[0], 0), rings_count(&R[1], 0)};
        int corr[6] = {0, 0, n[0] / 3, n[1] / 3, 2 * n[0] / 3, 2 * n[1] / 3};
        struct compat c;
        unsigned char *keep = NULL;
        memset(&c, 0, sizeof c);
        if (compat_match(2, P, n, corr, 3, &c, &keep) == 0) {
            compat_simplify(&c, 0.01, keep);
            if (compat_triangulate(&c) == 0) {
                if (!fuzz_all_positive(&c)) fuzz_fail("compat: inverted triangle after compat_triangulate");
                compat_improve(&c, 0, 2);
                if (!fuzz_all_positive(&c)) fuzz_fail("compat: inverted triangle after compat_improve");
            }
        }
        compat_free(&c);
        free(keep);
    }
    rings_free(&R[0]);
    rings_free(&R[1]);
    return 0;
}
