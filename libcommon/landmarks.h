/* landmarks.h -- landmark files: one pair per row, either
 *     src_vertex dst_vertex        (a vertex of the target)
 *     src_vertex x y z             (a point in the target's space)
 * '#' comments allowed (stopmo-columns(5)).  Vertex indices are 0-based.
 */
#ifndef CM_LANDMARKS_H
#define CM_LANDMARKS_H
#ifdef __cplusplus
extern "C" {
#endif

struct landmarks {
    int n;          /* number of pairs */
    int *src;       /* n source vertex indices */
    int *dst;       /* n target vertex indices, -1 for rows given as x y z */
    double *P;      /* n by 3 target positions */
};

/* Read and check against the source (nvs vertices) and the target (nvt
 * vertices with positions VT, #VT by 3; VT may be NULL only if every row is
 * "src x y z").  Errors name the file and the row. */
int landmarks_read(const char *path, int nvs, const double *VT, int nvt, struct landmarks *L);
void landmarks_free(struct landmarks *L);

#ifdef __cplusplus
}
#endif
#endif
