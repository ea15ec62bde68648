/* mesh_distance.c -- see mesh_distance.h */
#include "mesh_distance.h"
#include "cm_error.h"
#include "geometry.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>

int one_sided_distance(const double *V, int nv, const int *F, int nf,
                       const struct closest_point_tree *B, struct one_sided *out)
{
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return -1;
    int ns = nv + nf + t.ne;
    double *P = malloc((size_t)ns * 3 * sizeof *P + 1), *D = malloc((size_t)ns * sizeof *D + 1);
    int k = 0;
    for (int v = 0; v < nv; v++, k++)
        for (int d = 0; d < 3; d++) P[3 * k + d] = V[3 * v + d];
    for (int f = 0; f < nf; f++, k++)
        for (int d = 0; d < 3; d++)
            P[3 * k + d] = (V[3 * F[3 * f] + d] + V[3 * F[3 * f + 1] + d] + V[3 * F[3 * f + 2] + d]) / 3;
    for (int e = 0; e < t.ne; e++, k++)
        for (int d = 0; d < 3; d++) P[3 * k + d] = 0.5 * (V[3 * t.E[2 * e] + d] + V[3 * t.E[2 * e + 1] + d]);
    topology_free(&t);
    closest_points(B, P, ns, NULL, NULL, NULL, D);
    out->max = 0; out->sumsq = 0; out->n = ns;
    for (int i = 0; i < ns; i++) {
        if (D[i] > out->max) out->max = D[i];
        out->sumsq += D[i] * D[i];
    }
    free(P);
    free(D);
    return 0;
}

int symmetric_distance(const double *VA, int nva, const int *FA, int nfa,
                       const struct closest_point_tree *TA,
                       const double *VB, int nvb, const int *FB, int nfb,
                       const struct closest_point_tree *TB, double *hausdorff, double *rms)
{
    struct one_sided ab, ba;
    if (one_sided_distance(VA, nva, FA, nfa, TB, &ab) < 0) return -1;
    if (one_sided_distance(VB, nvb, FB, nfb, TA, &ba) < 0) return -1;
    *hausdorff = ab.max > ba.max ? ab.max : ba.max;
    *rms = sqrt((ab.sumsq + ba.sumsq) / (ab.n + ba.n));
    return 0;
}

int flipped_faces(const double *VA, const int *FA, int nfa, const double *VB, const int *FB,
                  const struct closest_point_tree *TB)
{
    return flipped_face_flags(VA, FA, nfa, VB, FB, TB, NULL);
}

int flipped_face_flags(const double *VA, const int *FA, int nfa, const double *VB, const int *FB,
                       const struct closest_point_tree *TB, unsigned char *flip)
{
    double *P = malloc((size_t)nfa * 3 * sizeof *P + 1), *N = malloc((size_t)nfa * 3 * sizeof *N + 1);
    int *I = malloc((size_t)nfa * sizeof *I + 1);
    face_normals(VA, FA, nfa, N);
    for (int f = 0; f < nfa; f++)
        for (int d = 0; d < 3; d++)
            P[3 * f + d] = (VA[3 * FA[3 * f] + d] + VA[3 * FA[3 * f + 1] + d] + VA[3 * FA[3 * f + 2] + d]) / 3;
    closest_points(TB, P, nfa, NULL, I, NULL, NULL);
    int flipped = 0;
    for (int f = 0; f < nfa; f++) {
        const int *g = FB + 3 * I[f];
        double e1[3], e2[3], n[3];
        sub3(VB + 3 * g[1], VB + 3 * g[0], e1);
        sub3(VB + 3 * g[2], VB + 3 * g[0], e2);
        cross3(e1, e2, n);
        int fl = dot3(n, N + 3 * f) < 0;
        flipped += fl;
        if (flip) flip[f] = (unsigned char)fl;
    }
    free(P); free(N); free(I);
    return flipped;
}
