/* meshcolor.c -- see meshcolor.h */
#include "meshcolor.h"
#include "cm_error.h"
#include "colormap.h"
#include "columns.h"
#include <stdlib.h>
#include <string.h>

static const char *fname(const char *path)
{
    return (!path || !strcmp(path, "-")) ? "<stdin>" : path;
}

static int count_error(const char *path, int rows, int nv, int nf)
{
    return cm_seterr("cannot read '%s': %d rows, but the mesh has %d faces and %d vertices",
                     fname(path), rows, nf, nv);
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

int mesh_colors_labels(const char *path, int nv, int nf, struct mesh_colors *mc)
{
    memset(mc, 0, sizeof *mc);
    int *L, n;
    if (labels_read(path, -1, NULL, -2000000000, -2000000001, &L, &n) < 0)
        return -1;
    if (n != nf && n != nv) {
        free(L);
        return count_error(path, n, nv, nf);
    }
    mc->per_face = n == nf;
    mc->n = n;
    mc->rgb = malloc((size_t)(n > 0 ? n : 1) * 3);
    int *sorted = malloc((size_t)(n > 0 ? n : 1) * sizeof *sorted);
    if (!mc->rgb || !sorted) {
        free(L);
        free(sorted);
        mesh_colors_free(mc);
        return cm_seterr("out of memory");
    }
    for (int i = 0; i < n; i++) colormap_label(L[i], mc->rgb + 3 * i);
    memcpy(sorted, L, (size_t)n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, cmp_int);
    for (int i = 0; i < n; i++)
        if (i == 0 || sorted[i] != sorted[i - 1]) mc->nlabels++;
    free(sorted);
    free(L);
    return 0;
}

static int scalars_from(const char *path, const double *x, int n, int nf,
                        const double *range, struct mesh_colors *mc)
{
    if (n == 0)
        return cm_seterr("cannot read '%s': no values", fname(path));
    mc->per_face = n == nf;
    mc->n = n;
    if (range) {
        mc->lo = range[0];
        mc->hi = range[1];
    } else
        scalar_range(x, n, &mc->lo, &mc->hi);
    colormap_viridis_table(mc->lut);
    if (mc->per_face) {
        mc->rgb = malloc((size_t)n * 3);
        if (mc->rgb)
            for (int i = 0; i < n; i++)
                colormap_viridis(colormap_t(x[i], mc->lo, mc->hi), mc->rgb + 3 * i);
    } else {
        mc->t = malloc((size_t)n * sizeof *mc->t);
        if (mc->t)
            for (int i = 0; i < n; i++) mc->t[i] = (float)colormap_t(x[i], mc->lo, mc->hi);
    }
    if (!mc->rgb && !mc->t)
        return cm_seterr("out of memory");
    return 0;
}

int mesh_colors_scalars(const char *path, int nv, int nf, const double *range,
                        struct mesh_colors *mc)
{
    memset(mc, 0, sizeof *mc);
    struct columns c;
    if (columns_read(path, 1, -1, NULL, &c) < 0)
        return -1;
    int n = c.rows;
    if (n != nf && n != nv) {
        columns_free(&c);
        return count_error(path, n, nv, nf);
    }
    int rc = scalars_from(path, c.x, n, nf, range, mc);
    columns_free(&c);
    return rc;
}

int mesh_colors_scalars_column(const char *path, int col, int block, int nv, int nf,
                               const double *range, struct mesh_colors *mc)
{
    memset(mc, 0, sizeof *mc);
    struct columns c;
    if (columns_read(path, 0, -1, NULL, &c) < 0)
        return -1;
    if (col < 0 || col >= c.cols) {
        int k = c.cols;
        columns_free(&c);
        return cm_seterr("cannot read '%s': no column %d (it has %d)", fname(path), col + 1, k);
    }
    /* one block of #F (else #V) rows per frame */
    int n = c.rows > 0 && c.rows % nf == 0 ? nf : c.rows > 0 && c.rows % nv == 0 ? nv : -1;
    if (n < 0 || (c.rows != n && (block < 0 || (long)(block + 1) * n > c.rows))) {
        int r = c.rows;
        columns_free(&c);
        if (n < 0) return count_error(path, r, nv, nf);
        return cm_seterr("cannot read '%s': %d rows are %d blocks of %d %s, no block for frame %d",
                         fname(path), r, r / n, n, n == nf ? "faces" : "vertices", block);
    }
    size_t first = c.rows == n ? 0 : (size_t)block * n;
    double *x = malloc((size_t)n * sizeof *x);
    if (!x) { columns_free(&c); return cm_seterr("out of memory"); }
    for (int i = 0; i < n; i++) x[i] = c.x[(first + i) * c.cols + col];
    int rc = scalars_from(path, x, n, nf, range, mc);
    free(x);
    columns_free(&c);
    return rc;
}

void mesh_colors_apply(const struct mesh_colors *mc, struct render_style *s)
{
    s->face_rgb = NULL;
    s->vertex_rgb = NULL;
    s->vertex_t = NULL;
    if (mc->t) {
        s->vertex_t = mc->t;
        s->lut = mc->lut;
    } else if (mc->per_face)
        s->face_rgb = mc->rgb;
    else {
        s->vertex_rgb = mc->rgb;
        s->vertex_nearest = 1;   /* labels: no blended in-between colours */
    }
}

int mesh_colors_check(const struct mesh_colors *mc, int nv, int nf, const char *what)
{
    if (mc->per_face ? mc->n == nf : mc->n == nv)
        return 0;
    return cm_seterr("%s: %d %s colours, but it has %d faces and %d vertices", what, mc->n,
                     mc->per_face ? "face" : "vertex", nf, nv);
}

void mesh_colors_free(struct mesh_colors *mc)
{
    free(mc->rgb);
    free(mc->t);
    mc->rgb = NULL;
    mc->t = NULL;
}
