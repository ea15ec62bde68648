/* anim_fixture.h -- clustered frames for the dictionary tests: a few
 * poses, each held with jitter and linked by fast transitions (the
 * structure of a performance).  Include after rng.h. */
#ifndef STOPMO_ANIM_FIXTURE_H
#define STOPMO_ANIM_FIXTURE_H
#include <stdlib.h>

/* n frames of nv vertices (n by 3 nv, row-major; caller frees) around
 * `poses` random poses: pose coordinates N(0, spread^2), each frame a pose
 * scaled by 0.5..1.5, offset by 10, plus N(0, noise^2) per coordinate; the
 * pose changes with probability 0.1 per frame */
static double *make_anim(struct rng *r, int n, int nv, int poses, double spread, double noise)
{
    int m3 = 3 * nv;
    double *P = malloc(sizeof(double) * (size_t)poses * m3), *X = malloc(sizeof(double) * (size_t)n * m3);
    for (int k = 0; k < poses * m3; k++) P[k] = spread * rng_normal(r);
    int cur = 0;
    for (int f = 0; f < n; f++) {
        if (rng_uniform(r) < 0.1) cur = rng_int(r, poses);
        double s = 0.5 + rng_uniform(r);
        for (int k = 0; k < m3; k++) X[(size_t)f * m3 + k] = 10 + s * P[(size_t)cur * m3 + k] + noise * rng_normal(r);
    }
    free(P);
    return X;
}
#endif
