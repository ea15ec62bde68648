/* dict-tile -- real full-rank test animations of a given size for the
 * dict-learn benchmarks (Table 1 sizes), from real MESH animations:
 *
 *   dict-tile V FRAMES SEED SRC.mesh [SRC2.mesh ...] > out.mesh (raw)
 *
 * Vertices: the sources' vertex sets side by side (cycled, the last block
 * cut to V; each block offset along x), like a multi-mesh character.
 * Frames: frame f of block b is source frame p(f + 37 b), p ping-pong over
 * the source's frames (the performance repeated back and forth), plus
 * Gaussian noise of 0.1% of the source's RMS motion per coordinate (every
 * repetition differs: the animation is full rank), rounded to 6 decimals
 * as an OBJ export stores them.  Writes a raw MESH stream.
 */
#include "mesh.h"
#include "rng.h"
#include "cm_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc < 5) { fprintf(stderr, "usage: dict-tile V FRAMES SEED SRC.mesh...\n"); return 2; }
    int V = atoi(argv[1]), F = atoi(argv[2]), ns = argc - 4;
    struct rng r;
    rng_seed(&r, strtoull(argv[3], NULL, 10));
    struct mesh *src = calloc(ns, sizeof *src);
    double *sig = calloc(ns, sizeof(double)), *width = calloc(ns, sizeof(double));
    for (int s = 0; s < ns; s++) {
        if (mesh_read(argv[4 + s], &src[s]) < 0) { fprintf(stderr, "dict-tile: %s\n", cm_errmsg()); return 1; }
        struct mesh *m = &src[s];
        size_t m3 = 3 * (size_t)m->nv;
        double ss = 0, lo = INFINITY, hi = -INFINITY;
        for (size_t k = 0; k < m3; k++) {
            double mu = 0;
            for (int f = 0; f < m->nframes; f++) mu += m->V[f * m3 + k];
            mu /= m->nframes;
            for (int f = 0; f < m->nframes; f++) ss += (m->V[f * m3 + k] - mu) * (m->V[f * m3 + k] - mu);
            if (k % 3 == 0) { if (m->V[k] < lo) lo = m->V[k]; if (m->V[k] > hi) hi = m->V[k]; }
        }
        sig[s] = 1e-3 * sqrt(ss / ((double)m->nframes * m3));
        width[s] = 1.1 * (hi - lo);
    }
    /* blocks */
    int nb = 0, cnt = 0, nfc = 0;
    int *bs = NULL, *b0 = NULL;
    while (cnt < V) {
        bs = realloc(bs, sizeof(int) * (nb + 1)); b0 = realloc(b0, sizeof(int) * (nb + 1));
        bs[nb] = nb % ns; b0[nb] = cnt;
        cnt += src[nb % ns].nv;
        nb++;
    }
    int *Fc = NULL;
    for (int b = 0; b < nb; b++) {
        struct mesh *m = &src[bs[b]];
        for (int t = 0; t < m->nf; t++) {
            int a = m->F[3 * t] + b0[b], c = m->F[3 * t + 1] + b0[b], e = m->F[3 * t + 2] + b0[b];
            if (a >= V || c >= V || e >= V) continue;
            Fc = realloc(Fc, sizeof(int) * 3 * (nfc + 1));
            Fc[3 * nfc] = a; Fc[3 * nfc + 1] = c; Fc[3 * nfc + 2] = e;
            nfc++;
        }
    }
    struct mesh_writer w;
    if (mesh_writer_open(&w, stdout, V, nfc, Fc, F, 1) < 0) { fprintf(stderr, "dict-tile: %s\n", cm_errmsg()); return 1; }
    double *X = malloc(sizeof(double) * 3 * (size_t)V);
    double xoff = 0;
    for (int f = 0; f < F; f++) {
        xoff = 0;
        for (int b = 0; b < nb; b++) {
            struct mesh *m = &src[bs[b]];
            int n = m->nframes, per = n > 1 ? 2 * (n - 1) : 1, t = (f + 37 * b) % per;
            int sf = t < n ? t : per - t;
            for (int i = 0; i < m->nv && b0[b] + i < V; i++)
                for (int c = 0; c < 3; c++) {
                    double v = m->V[((size_t)sf * m->nv + i) * 3 + c] + (c == 0 ? xoff : 0) + sig[bs[b]] * rng_normal(&r);
                    X[3 * (size_t)(b0[b] + i) + c] = round(v * 1e6) / 1e6;
                }
            xoff += width[bs[b]];
        }
        if (mesh_writer_frame(&w, X, 0) < 0) { fprintf(stderr, "dict-tile: %s\n", cm_errmsg()); return 1; }
    }
    if (mesh_writer_close(&w) < 0) { fprintf(stderr, "dict-tile: %s\n", cm_errmsg()); return 1; }
    return 0;
}
