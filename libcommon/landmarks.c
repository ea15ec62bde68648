/* landmarks.c -- see landmarks.h */
#include "landmarks.h"
#include "columns.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int is_index(double x) { return x == floor(x) && fabs(x) < 2e9; }

int landmarks_read(const char *path, int nvs, const double *VT, int nvt, struct landmarks *L)
{
    memset(L, 0, sizeof *L);
    struct columns c;
    if (columns_read(path, 0, -1, "landmarks", &c) < 0) return -1;
    const char *name = path && strcmp(path, "-") ? path : "<stdin>";
    if (c.rows == 0) { columns_free(&c); return cm_seterr("cannot read '%s': no landmarks", name); }
    if (c.cols != 2 && c.cols != 4) {
        columns_free(&c);
        return cm_seterr("cannot read '%s': expected rows 'src_vertex dst_vertex' or "
                         "'src_vertex x y z', got %d numbers per row", name, c.cols);
    }
    L->n = c.rows;
    L->src = malloc((size_t)c.rows * sizeof *L->src);
    L->dst = malloc((size_t)c.rows * sizeof *L->dst);
    L->P = malloc((size_t)c.rows * 3 * sizeof *L->P);
    if (!L->src || !L->dst || !L->P) {
        columns_free(&c); landmarks_free(L);
        return cm_seterr("cannot read '%s': out of memory", name);
    }
    for (int r = 0; r < c.rows; r++) {
        const double *x = c.x + (size_t)r * c.cols;
        if (!is_index(x[0]) || x[0] < 0 || x[0] >= nvs) {
            /* the message reads x: set it before the columns are freed */
            cm_seterr("cannot read '%s': landmark %d: source vertex %g out of range 0..%d",
                      name, r + 1, x[0], nvs - 1);
            columns_free(&c); landmarks_free(L);
            return -1;
        }
        L->src[r] = (int)x[0];
        if (c.cols == 2) {
            if (!is_index(x[1]) || x[1] < 0 || x[1] >= nvt || !VT) {
                cm_seterr("cannot read '%s': landmark %d: target vertex %g out of range 0..%d",
                          name, r + 1, x[1], nvt - 1);
                columns_free(&c); landmarks_free(L);
                return -1;
            }
            L->dst[r] = (int)x[1];
            memcpy(L->P + 3 * r, VT + 3 * (size_t)L->dst[r], 3 * sizeof *L->P);
        } else {
            L->dst[r] = -1;
            memcpy(L->P + 3 * r, x + 1, 3 * sizeof *L->P);
        }
    }
    columns_free(&c);
    return 0;
}

void landmarks_free(struct landmarks *L)
{
    free(L->src); free(L->dst); free(L->P);
    memset(L, 0, sizeof *L);
}
