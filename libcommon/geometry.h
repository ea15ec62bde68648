/* geometry.h -- per-face and per-vertex geometric quantities of one frame.
 * V: #V by 3 positions (row-major), F: #F by 3 indices.
 */
#ifndef CM_GEOMETRY_H
#define CM_GEOMETRY_H
#ifdef __cplusplus
extern "C" {
#endif

/* A: #F areas (out). */
void face_areas(const double *V, const int *F, int nf, double *A);
/* N: #F by 3 unit normals (out; zero for degenerate faces). */
void face_normals(const double *V, const int *F, int nf, double *N);
/* N: #V by 3 area-weighted unit vertex normals (out). */
void vertex_normals(const double *V, const int *F, int nv, int nf, double *N);
/* lo, hi: 3 each (out). */
void bounding_box(const double *V, int nv, double lo[3], double hi[3]);
/* Length of the bounding-box diagonal. */
double bbox_diagonal(const double *V, int nv);
/* Signed enclosed volume (divergence theorem); meaningful for closed meshes. */
double mesh_volume(const double *V, const int *F, int nf);
/* Total surface area. */
double mesh_area(const double *V, const int *F, int nf);

/* small vector helpers */
static inline double dot3(const double *a, const double *b) { return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]; }
static inline void sub3(const double *a, const double *b, double *o) { o[0] = a[0]-b[0]; o[1] = a[1]-b[1]; o[2] = a[2]-b[2]; }
static inline void cross3(const double *a, const double *b, double *o)
{
    double x = a[1]*b[2] - a[2]*b[1], y = a[2]*b[0] - a[0]*b[2], z = a[0]*b[1] - a[1]*b[0];
    o[0] = x; o[1] = y; o[2] = z;
}
double norm3(const double *a);
double dist3(const double *a, const double *b);

#ifdef __cplusplus
}
#endif
#endif
