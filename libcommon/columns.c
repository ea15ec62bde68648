/* columns.c -- see columns.h */
#include "columns.h"
#include "cm_error.h"
#include "numparse.h"
#include "textline.h"
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int columns_read(const char *path, int want_cols, int want_rows, const char *what,
                 struct columns *c)
{
    memset(c, 0, sizeof *c);
    const char *name = (!path || !strcmp(path, "-")) ? "<stdin>" : path;
    FILE *f = (!path || !strcmp(path, "-")) ? stdin : fopen(path, "r");
    if (!f)
        return cm_seterr("cannot read '%s': %s", name, strerror(errno));
    char *line = NULL;
    size_t lcap = 0, cap = 0;
    long lineno = 0;
    int cols = want_cols;
    double *row = NULL;
    int rowcap = 0;
    for (;;) {
        long n = textline_read(f, &line, &lcap, name, lineno + 1);
        if (n == -2)
            goto fail;
        if (n < 0)
            break;
        lineno++;
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = 0;              /* messages stay on one line */
        char *s = line;
        while (*s == ' ' || *s == '\t' || *s == '\r') s++;
        if (*s == '#' || *s == '\n' || *s == 0)
            continue;
        int k = 0;
        const char *p = s;
        for (;;) {
            while (*p == ' ' || *p == '\t' || *p == '\r' || *p == ',') p++;
            if (*p == '\n' || *p == 0 || *p == '#')
                break;
            double v;
            const char *q = parse_double(p, &v);
            if (!q || (*q && !strchr(" \t\r\n,#", *q))) {
                cm_seterr("cannot read '%s': line %ld: '%.20s' is not a number", name, lineno, p);
                goto fail;
            }
            if (!isfinite(v)) {
                cm_seterr("cannot read '%s': line %ld: non-finite number", name, lineno);
                goto fail;
            }
            if (k == rowcap) {
                rowcap = rowcap ? 2 * rowcap : 8;
                double *nr = realloc(row, rowcap * sizeof *row);
                if (!nr) { cm_seterr("cannot read '%s': out of memory", name); goto fail; }
                row = nr;
            }
            row[k++] = v;
            p = q;
        }
        if (k == 0) {
            /* separators only (",,"): not a row of zero numbers, which
             * would shift every later row against its element */
            cm_seterr("cannot read '%s': line %ld: no numbers, only separators", name, lineno);
            goto fail;
        }
        if (cols == 0)
            cols = k;
        if (k != cols) {
            cm_seterr("cannot read '%s': line %ld: expected %d number%s, got %d", name, lineno,
                      cols, cols == 1 ? "" : "s", k);
            goto fail;
        }
        if ((size_t)(c->rows + 1) * cols > cap) {
            cap = cap ? 2 * cap : 1024;
            while (cap < (size_t)(c->rows + 1) * cols) cap *= 2;
            double *nx = realloc(c->x, cap * sizeof *nx);
            if (!nx) { cm_seterr("cannot read '%s': out of memory", name); goto fail; }
            c->x = nx;
        }
        memcpy(c->x + (size_t)c->rows * cols, row, (size_t)k * sizeof *row);
        c->rows++;
    }
    if (want_rows >= 0 && c->rows != want_rows) {
        cm_seterr("cannot read '%s': %d rows, but there are %d %s", name, c->rows, want_rows,
                  what ? what : "elements");
        goto fail;
    }
    c->cols = cols;
    free(line);
    free(row);
    if (f != stdin) fclose(f);
    if (!c->x) c->x = malloc(sizeof(double));
    return 0;
fail:
    free(line);
    free(row);
    if (f != stdin) fclose(f);
    columns_free(c);
    return -1;
}

void columns_free(struct columns *c)
{
    free(c->x);
    memset(c, 0, sizeof *c);
}

int labels_read(const char *path, int want_rows, const char *what, int lo, int hi,
                int **L, int *n)
{
    struct columns c;
    if (columns_read(path, 1, want_rows, what, &c) < 0)
        return -1;
    const char *name = (!path || !strcmp(path, "-")) ? "<stdin>" : path;
    int *l = malloc(((size_t)c.rows + 1) * sizeof *l);
    if (!l) {
        columns_free(&c);
        return cm_seterr("cannot read '%s': out of memory", name);
    }
    for (int i = 0; i < c.rows; i++) {
        double v = c.x[i];
        if (v != floor(v) || fabs(v) > 2e9) {
            free(l);
            columns_free(&c);
            return cm_seterr("cannot read '%s': row %d: label %g is not an integer", name, i + 1, v);
        }
        if (v < lo || (hi >= lo && v > hi)) {
            free(l);
            columns_free(&c);
            if (hi >= lo)
                return cm_seterr("cannot read '%s': row %d: label %g out of range %d..%d", name,
                                 i + 1, v, lo, hi);
            return cm_seterr("cannot read '%s': row %d: label %g below %d", name, i + 1, v, lo);
        }
        l[i] = (int)v;
    }
    *n = c.rows;
    *L = l;
    columns_free(&c);
    return 0;
}

int labels_write(FILE *f, const int *L, int n)
{
    for (int i = 0; i < n; i++)
        fprintf(f, "%d\n", L[i]);
    return ferror(f) ? cm_seterr("write error: %s", strerror(errno)) : 0;
}

int columns_write(FILE *f, const double *x, int rows, int cols)
{
    char buf[40];
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < cols; j++) {
            format_double(buf, x[(size_t)i * cols + j]);
            fputs(buf, f);
            fputc(j + 1 < cols ? ' ' : '\n', f);
        }
    return ferror(f) ? cm_seterr("write error: %s", strerror(errno)) : 0;
}
