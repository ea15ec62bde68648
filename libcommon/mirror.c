/* mirror.c -- see mirror.h. */
#include "mirror.h"
#include "closest_point.h"
#include "cm_error.h"
#include "geometry.h"
#include "procrustes.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK: eigenvalues (ascending) and eigenvectors of a symmetric matrix */
extern void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
                   double *w, double *work, const int *lwork, int *info);

/* M (3x3 symmetric, row-major): w ascending, V columns = eigenvectors
 * (column k is V[k], V[3+k], V[6+k]) */
static int eig3(const double M[9], double w[3], double V[9])
{
    double a[9], work[64];
    int n = 3, lwork = 64, info = 0;
    memcpy(a, M, sizeof a);     /* symmetric: row- and column-major agree */
    dsyev_("V", "U", &n, a, &n, w, work, &lwork, &info);
    if (info != 0) return cm_seterr("mirror: eigen-decomposition failed (LAPACK info %d)", info);
    /* a is column-major: eigenvector k is a[3k .. 3k+2] */
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) V[3 * i + k] = a[3 * k + i];
    return 0;
}

void mirror_point(const double plane[4], const double x[3], double y[3])
{
    double s = 2 * (plane[0] * x[0] + plane[1] * x[1] + plane[2] * x[2] - plane[3]);
    for (int k = 0; k < 3; k++) y[k] = x[k] - s * plane[k];
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* the vertices used by the ICP: all up to 4000, else every k-th */
static int sample_vertices(int nv, int **idx)
{
    int step = nv > 4000 ? (nv + 3999) / 4000 : 1, m = 0;
    int *s = malloc(sizeof(int) * (nv / step + 1));
    if (!s) return cm_seterr("mirror: out of memory");
    for (int v = 0; v < nv; v += step) s[m++] = v;
    *idx = s;
    return m;
}

/* reflect the samples, closest points, trimmed distances: fills P (m x 3
 * reflected), Q (m x 3 closest), w (m weights 0/1); returns the trimmed
 * RMS, *worst the trimming threshold */
static double match(const struct closest_point_tree *T, const double *V, const int *idx, int m,
                    const double plane[4], double *P, double *Q, double *D, double *Ds, double *w,
                    int *hint, double *worst)
{
    for (int i = 0; i < m; i++) mirror_point(plane, V + 3 * (size_t)idx[i], P + 3 * i);
    closest_points_hinted(T, P, m, hint, Q, hint, NULL, D);   /* last answers as hints */
    memcpy(Ds, D, sizeof(double) * m);
    qsort(Ds, m, sizeof(double), cmp_double);
    int keep = (int)ceil(0.9 * m);
    if (keep < 1) keep = 1;
    double thr = Ds[keep - 1], s2 = 0;
    int k = 0;
    for (int i = 0; i < m; i++) {
        w[i] = D[i] <= thr && k < keep;
        if (w[i]) { s2 += D[i] * D[i]; k++; }
    }
    if (worst) *worst = thr;
    return sqrt(s2 / (k ? k : 1));
}

static int refine(const struct closest_point_tree *T, const double *V, const int *idx, int m,
                  int iterations, double diag, double plane[4], double *rms, double *worst)
{
    double *buf = malloc(sizeof(double) * (size_t)m * 9);
    int *hint = malloc(sizeof(int) * (size_t)m);
    if (!buf || !hint) { free(buf); free(hint); return cm_seterr("mirror: out of memory"); }
    for (int i = 0; i < m; i++) hint[i] = -1;
    double *P = buf, *Q = buf + 3 * (size_t)m, *D = buf + 6 * (size_t)m, *Ds = D + m, *w = Ds + m;
    for (int it = 0; it < iterations; it++) {
        match(T, V, idx, m, plane, P, Q, D, Ds, w, hint, NULL);
        double R[9], t[3];
        if (procrustes(P, Q, w, m, 0, R, t, NULL) < 0) { free(buf); free(hint); return -1; }
        const double *n = plane;
        double L[9], A[9], Ms[9], b[3], ev[3], E[9];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) L[3 * i + j] = (i == j) - 2 * n[i] * n[j];
        for (int i = 0; i < 3; i++) {
            b[i] = t[i];
            for (int j = 0; j < 3; j++) {
                A[3 * i + j] = 0;
                for (int k = 0; k < 3; k++) A[3 * i + j] += R[3 * i + k] * L[3 * k + j];
                b[i] += R[3 * i + j] * 2 * plane[3] * n[j];
            }
        }
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) Ms[3 * i + j] = 0.5 * (A[3 * i + j] + A[3 * j + i]);
        if (eig3(Ms, ev, E) < 0) { free(buf); free(hint); return -1; }
        double nn[3] = {E[0], E[3], E[6]};
        double dot = nn[0] * n[0] + nn[1] * n[1] + nn[2] * n[2];
        if (dot < 0) for (int k = 0; k < 3; k++) nn[k] = -nn[k];
        double nd = 0.5 * (nn[0] * b[0] + nn[1] * b[1] + nn[2] * b[2]);
        double change = fabs(nd - plane[3]) / diag;
        for (int k = 0; k < 3; k++) change += fabs(nn[k] - plane[k]);
        memcpy(plane, nn, sizeof nn);
        plane[3] = nd;
        if (change < 1e-10) break;
    }
    double r = match(T, V, idx, m, plane, P, Q, D, Ds, w, hint, worst);
    if (rms) *rms = r;
    free(buf);
    free(hint);
    return 0;
}

static int setup(const double *V, int nv, const int *F, int nf, struct closest_point_tree **T,
                 int **idx, int *m, double *diag)
{
    if (nv < 3 || nf < 1) return cm_seterr("mirror: empty mesh (%d vertices, %d faces)", nv, nf);
    *diag = bbox_diagonal(V, nv);
    if (!(*diag > 0)) return cm_seterr("mirror: the mesh has an empty bounding box");
    if (!(*T = closest_point_tree_new(V, nv, F, nf))) return -1;
    if ((*m = sample_vertices(nv, idx)) < 0) { closest_point_tree_free(*T); return -1; }
    return 0;
}

int mirror_plane_refine(const double *V, int nv, const int *F, int nf, int iterations,
                        double plane[4], double *rms, double *worst)
{
    struct closest_point_tree *T;
    int *idx, m;
    double diag;
    double len = sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
    if (!(len > 0) || !isfinite(len) || !isfinite(plane[3]))
        return cm_seterr("mirror: the plane normal is zero or not finite");
    for (int k = 0; k < 4; k++) plane[k] /= len;
    if (setup(V, nv, F, nf, &T, &idx, &m, &diag) < 0) return -1;
    int rc = refine(T, V, idx, m, iterations > 0 ? iterations : 30, diag, plane, rms, worst);
    free(idx);
    closest_point_tree_free(T);
    return rc;
}

int mirror_plane_find(const double *V, int nv, const int *F, int nf, int iterations,
                      double plane[4], double *rms, double *worst)
{
    struct closest_point_tree *T;
    int *idx, m;
    double diag;
    if (setup(V, nv, F, nf, &T, &idx, &m, &diag) < 0) return -1;
    /* area-weighted centroid and covariance of the face centroids */
    double *A = malloc(sizeof(double) * nf);
    if (!A) { free(idx); closest_point_tree_free(T); return cm_seterr("mirror: out of memory"); }
    face_areas(V, F, nf, A);
    double c[3] = {0, 0, 0}, at = 0, C[9] = {0};
    for (int f = 0; f < nf; f++) {
        for (int k = 0; k < 3; k++)
            c[k] += A[f] * (V[3 * F[3 * f] + k] + V[3 * F[3 * f + 1] + k] + V[3 * F[3 * f + 2] + k]) / 3;
        at += A[f];
    }
    if (!(at > 0)) { free(A); free(idx); closest_point_tree_free(T); return cm_seterr("mirror: the mesh has zero area"); }
    for (int k = 0; k < 3; k++) c[k] /= at;
    for (int f = 0; f < nf; f++) {
        double g[3];
        for (int k = 0; k < 3; k++)
            g[k] = (V[3 * F[3 * f] + k] + V[3 * F[3 * f + 1] + k] + V[3 * F[3 * f + 2] + k]) / 3 - c[k];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) C[3 * i + j] += A[f] * g[i] * g[j];
    }
    free(A);
    double ev[3], E[9];
    int rc = eig3(C, ev, E);
    double best = INFINITY;
    for (int k = 0; k < 3 && rc == 0; k++) {
        double p[4] = {E[k], E[3 + k], E[6 + k], 0}, r, wst;
        p[3] = p[0] * c[0] + p[1] * c[1] + p[2] * c[2];
        if ((rc = refine(T, V, idx, m, iterations > 0 ? iterations : 30, diag, p, &r, &wst)) < 0) break;
        if (r < best) {
            best = r;
            memcpy(plane, p, sizeof p);
            if (rms) *rms = r;
            if (worst) *worst = wst;
        }
    }
    free(idx);
    closest_point_tree_free(T);
    return rc;
}

double mirror_plane_rms(const double *V, int nv, const int *F, int nf, const double plane[4])
{
    struct closest_point_tree *T;
    int *idx, m;
    double diag;
    if (setup(V, nv, F, nf, &T, &idx, &m, &diag) < 0) return NAN;
    double *P = malloc(sizeof(double) * 3 * (size_t)m), r = NAN;
    if (P) {
        double s2 = 0;
        for (int i = 0; i < m; i++) mirror_point(plane, V + 3 * (size_t)idx[i], P + 3 * i);
        double *D = malloc(sizeof(double) * m);
        if (D) {
            closest_points(T, P, m, NULL, NULL, NULL, D);
            for (int i = 0; i < m; i++) s2 += D[i] * D[i];
            r = sqrt(s2 / m);
            free(D);
        }
        free(P);
    }
    free(idx);
    closest_point_tree_free(T);
    return r;
}

int mirror_faces(const double *V, int nv, const int *F, int nf, const double plane[4], int *mf,
                 double *dist)
{
    struct closest_point_tree *T = closest_point_tree_new(V, nv, F, nf);
    if (!T) return -1;
    double *P = malloc(sizeof(double) * 3 * (size_t)(nf ? nf : 1));
    if (!P) { closest_point_tree_free(T); return cm_seterr("mirror: out of memory"); }
    for (int f = 0; f < nf; f++) {
        double g[3];
        for (int k = 0; k < 3; k++)
            g[k] = (V[3 * F[3 * f] + k] + V[3 * F[3 * f + 1] + k] + V[3 * F[3 * f + 2] + k]) / 3;
        mirror_point(plane, g, P + 3 * (size_t)f);
    }
    closest_points(T, P, nf, NULL, mf, NULL, dist);
    free(P);
    closest_point_tree_free(T);
    return 0;
}

/* distance from p to the segment a-b */
static double point_segment(const double p[3], const double a[3], const double b[3])
{
    double ab[3], ap[3], l2 = 0, t = 0;
    for (int k = 0; k < 3; k++) { ab[k] = b[k] - a[k]; ap[k] = p[k] - a[k]; l2 += ab[k] * ab[k]; t += ab[k] * ap[k]; }
    t = l2 > 0 ? t / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double q[3];
    for (int k = 0; k < 3; k++) q[k] = a[k] + t * ab[k];
    return dist3(p, q);
}

double mirror_hausdorff(const double *G, int n, const double plane[4])
{
    double h = 0;
    for (int i = 0; i < n; i++)
        for (int s = 0; s < 3; s++) {
            const double *a = G + 6 * (size_t)i, *b = a + 3;
            double x[3], y[3], m = INFINITY;
            for (int k = 0; k < 3; k++) x[k] = s == 0 ? a[k] : s == 1 ? b[k] : 0.5 * (a[k] + b[k]);
            mirror_point(plane, x, y);
            for (int j = 0; j < n && m > h; j++) {
                double d = point_segment(y, G + 6 * (size_t)j, G + 6 * (size_t)j + 3);
                if (d < m) m = d;
            }
            if (m > h && isfinite(m)) h = m;
        }
    return h;
}
