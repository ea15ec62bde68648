/* mesh_distance.c -- see mesh_distance.h */
#include "mesh_distance.h"
#include "cm_error.h"
#include "geometry.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

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

int flipped_faces(const double *VA, const int *FA, int nfa, const double *VB, int nvb,
                  const int *FB, int nfb, const struct closest_point_tree *TB, double tol)
{
    return flipped_face_flags(VA, FA, nfa, VB, nvb, FB, nfb, TB, tol, NULL);
}

int flipped_face_flags(const double *VA, const int *FA, int nfa, const double *VB, int nvb,
                       const int *FB, int nfb, const struct closest_point_tree *TB,
                       double tol, unsigned char *flip)
{
    int near[64];
    double *P = malloc((size_t)nfa * 3 * sizeof *P + 1), *N = malloc((size_t)nfa * 3 * sizeof *N + 1);
    double *Bc = malloc((size_t)nfa * 3 * sizeof *Bc + 1);
    double *NF = malloc((size_t)nfb * 3 * sizeof *NF + 1);
    double *D = malloc((size_t)nfa * sizeof *D + 1);
    int *I = malloc((size_t)nfa * sizeof *I + 1);
    struct topology t = {0};
    int flipped = -1;
    if (topology_build(FB, nfb, nvb, &t) < 0) goto done;
    face_normals(VA, FA, nfa, N);
    face_normals(VB, FB, nfb, NF);
    for (int f = 0; f < nfa; f++)
        for (int d = 0; d < 3; d++)
            P[3 * f + d] = (VA[3 * FA[3 * f] + d] + VA[3 * FA[3 * f + 1] + d] + VA[3 * FA[3 * f + 2] + d]) / 3;
    closest_points(TB, P, nfa, NULL, I, Bc, D);
    flipped = 0;
    for (int f = 0; f < nfa; f++) {
        /* the normal cone of the closest feature: the face's normal inside a
         * face, both face normals on an edge, all of them at a vertex; the
         * face is flipped when it points against every one of them */
        const double eps = 1e-9, *b = Bc + 3 * f;
        int g = I[f], zeros = (b[0] < eps) + (b[1] < eps) + (b[2] < eps);
        const double *nf = N + 3 * f;
        int fl = dot3(NF + 3 * g, nf) < 0;
        if (fl && zeros >= 2) {
            int c = b[0] >= b[1] && b[0] >= b[2] ? 0 : b[1] >= b[2] ? 1 : 2, v = FB[3 * g + c];
            for (int q = t.VFs[v]; q < t.VFs[v + 1] && fl; q++)
                if (dot3(NF + 3 * t.VF[q], nf) >= 0) fl = 0;
        } else if (fl && zeros == 1) {
            int c = b[0] < eps ? 0 : b[1] < eps ? 1 : 2;
            int e = t.FE[3 * g + (c + 1) % 3];        /* the edge opposite corner c */
            for (int q = 0; q < 2 && fl; q++)
                if (t.EF[2 * e + q] >= 0 && dot3(NF + 3 * t.EF[2 * e + q], nf) >= 0) fl = 0;
        }
        if (fl && tol > 0) {
            /* a thin part of B (an ear, a fin): is a side facing this way near too? */
            int m = closest_point_faces_within(TB, P + 3 * f, D[f] + tol, near, 64);
            for (int q = 0; q < m && q < 64 && fl; q++)
                if (dot3(NF + 3 * near[q], N + 3 * f) > 0) fl = 0;
        }
        flipped += fl;
        if (flip) flip[f] = (unsigned char)fl;
    }
done:
    topology_free(&t);
    free(P); free(D); free(N); free(Bc); free(NF); free(I);
    return flipped;
}
