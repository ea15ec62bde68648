/* geometry.c -- see geometry.h */
#include "geometry.h"
#include <math.h>
#include <string.h>

double norm3(const double *a) { return sqrt(dot3(a, a)); }
double dist3(const double *a, const double *b)
{
    double d[3];
    sub3(a, b, d);
    return norm3(d);
}

static void face_cross(const double *V, const int *F, int f, double *n)
{
    const double *a = V + 3 * F[3 * f], *b = V + 3 * F[3 * f + 1], *c = V + 3 * F[3 * f + 2];
    double u[3], v[3];
    sub3(b, a, u);
    sub3(c, a, v);
    cross3(u, v, n);
}

void face_areas(const double *V, const int *F, int nf, double *A)
{
    for (int f = 0; f < nf; f++) {
        double n[3];
        face_cross(V, F, f, n);
        A[f] = 0.5 * norm3(n);
    }
}

void face_normals(const double *V, const int *F, int nf, double *N)
{
    for (int f = 0; f < nf; f++) {
        double *n = N + 3 * f;
        face_cross(V, F, f, n);
        double l = norm3(n);
        if (l > 0) { n[0] /= l; n[1] /= l; n[2] /= l; }
    }
}

void vertex_normals(const double *V, const int *F, int nv, int nf, double *N)
{
    memset(N, 0, (size_t)nv * 3 * sizeof *N);
    for (int f = 0; f < nf; f++) {
        double n[3];
        face_cross(V, F, f, n);      /* length = 2 * area: area weighting */
        for (int c = 0; c < 3; c++)
            for (int d = 0; d < 3; d++) N[3 * F[3 * f + c] + d] += n[d];
    }
    for (int v = 0; v < nv; v++) {
        double l = norm3(N + 3 * v);
        if (l > 0) for (int d = 0; d < 3; d++) N[3 * v + d] /= l;
    }
}

void bounding_box(const double *V, int nv, double lo[3], double hi[3])
{
    for (int d = 0; d < 3; d++) { lo[d] = nv ? V[d] : 0; hi[d] = lo[d]; }
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++) {
            double x = V[3 * v + d];
            if (x < lo[d]) lo[d] = x;
            if (x > hi[d]) hi[d] = x;
        }
}

double bbox_diagonal(const double *V, int nv)
{
    double lo[3], hi[3];
    bounding_box(V, nv, lo, hi);
    return dist3(lo, hi);
}

double mesh_volume(const double *V, const int *F, int nf)
{
    double s = 0;
    for (int f = 0; f < nf; f++) {
        const double *a = V + 3 * F[3 * f], *b = V + 3 * F[3 * f + 1], *c = V + 3 * F[3 * f + 2];
        double n[3];
        cross3(b, c, n);
        s += dot3(a, n);
    }
    return s / 6.0;
}

double mesh_area(const double *V, const int *F, int nf)
{
    double s = 0;
    for (int f = 0; f < nf; f++) {
        double n[3];
        face_cross(V, F, f, n);
        s += 0.5 * norm3(n);
    }
    return s;
}
