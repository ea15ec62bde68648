/* columns: reads_rows_and_comments, bad inputs are reported with file and
 * line (missing file, junk, NaN, ragged rows, wrong column or row count),
 * labels range and integer checks, write/read round trip */
#include "columns.h"
#include "cm_error.h"
#include "tap.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/stopmo-columns-XXXXXX";
static char path[256];

static const char *file(const char *text)
{
    snprintf(path, sizeof path, "%s/c.txt", dir);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

/* columns_read must fail with a message containing `want` */
static void fails(const char *text, int cols, int rows, const char *want, const char *name)
{
    struct columns c;
    int rc = columns_read(file(text), cols, rows, "faces", &c);
    ok(rc < 0 && strstr(cm_errmsg(), want) && strstr(cm_errmsg(), "c.txt") &&
       !strchr(cm_errmsg(), '\n'),
       "columns_read: %s is reported (%s)", name, cm_errmsg());
    if (rc == 0) columns_free(&c);
}

int main(void)
{
    if (!mkdtemp(dir)) { printf("Bail out! cannot make a temporary directory\n"); return 1; }
    struct columns c;
    int rc = columns_read(file("# weights\n1 2 3\n\n  4 5 6  # second\n7,8,9\r\n"), 0, -1, NULL, &c);
    ok(rc == 0 && c.rows == 3 && c.cols == 3 && c.x[0] == 1 && c.x[5] == 6 && c.x[8] == 9,
       "columns_read: rows, comments, blank lines, commas, CRLF");
    columns_free(&c);
    rc = columns_read(file("0 1.5e3\n2 -3\n"), 2, 2, "landmarks", &c);
    ok(rc == 0 && c.x[1] == 1500 && c.x[3] == -3, "columns_read: exact count checks pass");
    columns_free(&c);
    rc = columns_read(file("# nothing\n"), 1, -1, NULL, &c);
    ok(rc == 0 && c.rows == 0, "columns_read: an empty file has zero rows");
    columns_free(&c);

    ok(columns_read("/nonexistent/x.txt", 0, -1, NULL, &c) < 0 &&
       strstr(cm_errmsg(), "/nonexistent/x.txt"), "columns_read: missing file (%s)", cm_errmsg());
    fails("1 2\n3 x\n", 0, -1, "line 2", "junk number");
    fails("1 2\n3 nan\n", 0, -1, "line 2: non-finite", "NaN");
    fails("1 2\ninf 3\n", 0, -1, "line 2: non-finite", "inf");
    fails("1 2\n3 4 5\n", 0, -1, "line 2: expected 2 numbers, got 3", "ragged row");
    fails("1 2\n3 4\n", 3, -1, "line 1: expected 3 numbers, got 2", "wrong column count");
    fails("1\n2\n3\n", 1, 4, "3 rows, but there are 4 faces", "wrong row count");
    fails("1 2\n3 4e\n", 0, -1, "line 2", "truncated exponent");
    fails("1 2\n3 4x5\n", 0, -1, "line 2", "number glued to junk");

    int *L, n;
    rc = labels_read(file("0\n3\n# c\n2\n"), 3, "faces", 0, 3, &L, &n);
    ok(rc == 0 && n == 3 && L[1] == 3 && L[2] == 2, "labels_read: integer labels");
    if (rc == 0) free(L);
    rc = labels_read(file("0\n1.5\n"), -1, "faces", 0, -1, &L, &n);
    ok(rc < 0 && strstr(cm_errmsg(), "row 2: label 1.5 is not an integer"),
       "labels_read: non-integer reported (%s)", cm_errmsg());
    rc = labels_read(file("0\n7\n"), -1, "faces", 0, 5, &L, &n);
    ok(rc < 0 && strstr(cm_errmsg(), "out of range 0..5"), "labels_read: out of range (%s)",
       cm_errmsg());
    rc = labels_read(file("0\n-1\n"), -1, "faces", 0, -1, &L, &n);
    ok(rc < 0 && strstr(cm_errmsg(), "below 0"), "labels_read: below the lower bound (%s)",
       cm_errmsg());
    rc = labels_read(file("1 2\n"), -1, "faces", 0, -1, &L, &n);
    ok(rc < 0, "labels_read: two columns rejected (%s)", cm_errmsg());

    /* round trip */
    double X[6] = {0.1, -2.5e-300, 1.0 / 3, 7, -0.0, 123456789.125};
    snprintf(path, sizeof path, "%s/w.txt", dir);
    FILE *f = fopen(path, "w");
    ok(columns_write(f, X, 3, 2) == 0, "columns_write");
    fclose(f);
    rc = columns_read(path, 2, 3, NULL, &c);
    ok(rc == 0 && !memcmp(c.x, X, sizeof X), "columns_write/columns_read: bit-exact round trip");
    columns_free(&c);
    int Lw[4] = {3, 0, -2, 9};
    f = fopen(path, "w");
    labels_write(f, Lw, 4);
    fclose(f);
    rc = labels_read(path, 4, NULL, -5, -6, &L, &n);
    ok(rc == 0 && !memcmp(L, Lw, sizeof Lw), "labels_write/labels_read: round trip");
    if (rc == 0) free(L);

    unlink(path);
    snprintf(path, sizeof path, "%s/c.txt", dir);
    unlink(path);
    rmdir(dir);
    return tap_done();
}
