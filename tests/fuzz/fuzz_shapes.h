/* fuzz_shapes.h -- shared by the harnesses of compat-tri's stages
 * (fuzz_compat.c, fuzz_holes.c): an input of two rings files, and the
 * oracle that every triangle is positive in every shape. */
#ifndef FUZZ_SHAPES_H
#define FUZZ_SHAPES_H
#include "fuzz_common.h"
#include "compat_tri.h"
#include "predicates2.h"
#include "rings.h"

/* The two shapes of an input "FILE0\n--\nFILE1" read into R[0], R[1] (each
 * by rings_read, then keep(R[s]) must hold: the harness's limits; R
 * cleared first, freed by the caller either way).  1 if both read and
 * pass, 0 otherwise (no separator, a reading error, keep false). */
static inline int fuzz_two_shapes(const uint8_t *data, size_t size, struct rings R[2],
                                  int (*keep)(const struct rings *))
{
    memset(R, 0, 2 * sizeof *R);
    const uint8_t *sep = NULL;
    for (size_t i = 0; i + 4 <= size; i++)
        if (!memcmp(data + i, "\n--\n", 4)) { sep = data + i; break; }
    if (!sep) return 0;
    int ok = 1;
    for (int s = 0; s < 2 && ok; s++) {
        const uint8_t *a = s ? sep + 4 : data;
        size_t n = s ? size - (size_t)(sep + 4 - data) : (size_t)(sep - data) + 1;
        char path[64];
        fuzz_file(a, n, ".rings", path);
        ok = rings_read(path, &R[s]) == 0 && keep(&R[s]);
        fuzz_file_done(path);
    }
    return ok;
}

/* every triangle of c counter-clockwise in every shape, exactly */
static inline int fuzz_all_positive(const struct compat *c)
{
    for (int t = 0; t < c->nf; t++)
        for (int s = 0; s < c->N; s++) {
            const int *f = c->F + 3 * t;
            const double *X = c->X[s];
            if (orient2_sign(X + 2 * f[0], X + 2 * f[1], X + 2 * f[2]) <= 0) return 0;
        }
    return 1;
}
#endif
