/* fuzz_compat.c -- compat-tri's stages (compat_tri.h) on two outlines.
 * The input is two rings files separated by a line "--"; each must read
 * and be one simple ring (as compat-tri requires); three correspondences
 * split both at thirds.  Oracle: a triangulation that succeeds is
 * positively oriented in both shapes by the exact predicate, and stays so
 * after compat_improve (a double area can round to zero or below for a
 * sliver at coordinates near 1e17 that is exactly positive). */
#include "fuzz_common.h"
#include "compat_tri.h"
#include "rings.h"
#include "predicates2.h"

/* every triangle counter-clockwise in every shape, exactly */
static int all_positive(const struct compat *c)
{
    for (int t = 0; t < c->nf; t++)
        for (int s = 0; s < c->N; s++) {
            const int *f = c->F + 3 * t;
            const double *X = c->X[s];
            if (orient2_sign(X + 2 * f[0], X + 2 * f[1], X + 2 * f[2]) <= 0) return 0;
        }
    return 1;
}

FUZZ_TARGET(compat)(const uint8_t *data, size_t size)
{
    const uint8_t *sep = NULL;
    for (size_t i = 0; i + 4 <= size; i++)
        if (!memcmp(data + i, "\n--\n", 4)) { sep = data + i; break; }
    if (!sep) return 0;
    struct rings R[2];
    memset(R, 0, sizeof R);
    int ok = 1;
    for (int s = 0; s < 2 && ok; s++) {
        const uint8_t *a = s ? sep + 4 : data;
        size_t n = s ? size - (size_t)(sep + 4 - data) : (size_t)(sep - data) + 1;
        char path[64];
        fuzz_file(a, n, ".rings", path);
        ok = rings_read(path, &R[s]) == 0 && R[s].nrings == 1 && rings_count(&R[s], 0) <= 64 &&
             rings_check_simple(&R[s]) == 0;
        fuzz_file_done(path);
        if (ok) rings_orient(&R[s]);
    }
    if (ok) {
        double *P[2] = {R[0].P, R[1].P};
        int n[2] = {rings_count(&R[0], 0), rings_count(&R[1], 0)};
        int corr[6] = {0, 0, n[0] / 3, n[1] / 3, 2 * n[0] / 3, 2 * n[1] / 3};
        struct compat c;
        unsigned char *keep = NULL;
        memset(&c, 0, sizeof c);
        if (compat_match(2, P, n, corr, 3, &c, &keep) == 0) {
            compat_simplify(&c, 0.01, keep);
            if (compat_triangulate(&c) == 0) {
                if (!all_positive(&c)) fuzz_fail("compat: inverted triangle after compat_triangulate");
                compat_improve(&c, 0, 2);
                if (!all_positive(&c)) fuzz_fail("compat: inverted triangle after compat_improve");
            }
        }
        compat_free(&c);
        free(keep);
    }
    rings_free(&R[0]);
    rings_free(&R[1]);
    return 0;
}
