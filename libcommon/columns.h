/* columns.h -- column files: one row per element, whitespace separated
 * numbers, '#' comments and blank lines ignored.  Format: man 5 stopmo-columns.
 * Used for per-triangle part labels, per-frame piece labels, per-vertex
 * weights, landmarks, pose-space points.
 */
#ifndef CM_COLUMNS_H
#define CM_COLUMNS_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

struct columns {
    int rows;        /* number of data rows */
    int cols;        /* numbers per row (all rows have the same count) */
    double *x;       /* rows by cols, row-major */
};

/* Read a column file (path NULL or "-" = stdin).
 * want_cols > 0: every row must have exactly that many numbers;
 * want_cols == 0: any count, but the same on every row.
 * want_rows >= 0: the file must have exactly that many rows
 * (`what` names the elements in the message, e.g. "faces").
 * Non-finite numbers are errors. */
int columns_read(const char *path, int want_cols, int want_rows, const char *what,
                 struct columns *c);
void columns_free(struct columns *c);

/* Read one integer label per row into *L (malloc'd, n rows).
 * want_rows >= 0 checks the count; labels must be integers in
 * [lo, hi] (hi < lo: no upper bound). */
int labels_read(const char *path, int want_rows, const char *what, int lo, int hi,
                int **L, int *n);

/* Write n integers, one per line. */
int labels_write(FILE *f, const int *L, int n);
/* Write a rows by cols matrix, shortest round-trip numbers. */
int columns_write(FILE *f, const double *x, int rows, int cols);

#ifdef __cplusplus
}
#endif
#endif
