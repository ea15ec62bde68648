/* anim-diff -- per-frame vertex error between two animations with the same
 * connectivity (e.g. the input and its stop-motion replacement).
 *
 * For each frame: mean and max Euclidean distance between corresponding
 * vertices.  With --height H the errors are scaled to a print in which the
 * reference's bounding box (over all frames) is H tall (millimetres, say),
 * the number an animator cares about.  Streams both inputs frame by frame
 * (one pass: either may be a pipe).
 */
#include "cm_error.h"
#include "mesh.h"
#include "tool.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: anim-diff [options] REFERENCE.mesh OTHER.mesh\n"
"Per-frame mean and max vertex distance between two animations (same #V),\n"
"read in lockstep; one of them may be '-' (standard input).\n"
"\n"
"Output (stdout): one line per frame 'frame mean max', then summary lines\n"
"'# mean M', '# max X', '# rms R', '# frames K' (mean and rms over all vertices\n"
"of all frames); --summary prints only the summary lines, without '# '.\n"
"\n"
"Options:\n"
"      --height H     scale errors to a print whose reference height (bounding\n"
"                     box extent along --axis over all frames) is H (e.g. mm)\n"
"      --axis x|y|z   height axis (default y)\n"
"  -s, --summary      print only the summary lines, as 'key value'\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Example: anim-diff --height 40 --summary head.mesh stopmo.mesh\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"height", 1, 0, 'H'}, {"axis", 1, 0, 'a'}, {"summary", 0, 0, 's'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    double height = 0;
    int axis = 1, summary = 0, c;
    while ((c = getopt_long(argc, argv, "sh", lo, NULL)) != -1) {
        switch (c) {
        case 'H': height = arg_double(optarg, "--height");
            if (!(height > 0)) usage_error("--height must be positive");
            break;
        case 'a':
            if (strlen(optarg) != 1 || !strchr("xyz", optarg[0])) usage_error("--axis must be x, y or z");
            axis = optarg[0] - 'x';
            break;
        case 's': summary = 1; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind != 2)
        usage_error("expected two MESH streams");
    const char *pa = argv[optind], *pb = argv[optind + 1];
    if (!strcmp(pa, "-") && !strcmp(pb, "-"))
        usage_error("only one of the two streams can be standard input");
    struct mesh_reader a, b;
    if (mesh_reader_open(&a, pa) < 0 || mesh_reader_open(&b, pb) < 0)
        die("%s", cm_errmsg());
    if (a.nv != b.nv)
        die("cannot compare '%s' (%d vertices) with '%s' (%d vertices)", a.name, a.nv, b.name, b.nv);
    double *X = malloc((size_t)a.nv * 3 * sizeof *X), *Y = malloc((size_t)a.nv * 3 * sizeof *Y);
    if (!X || !Y) die("out of memory");
    /* distances are measured unscaled while the reference's extent along
     * the axis is gathered in the same pass; every figure is linear in the
     * scale, so --height multiplies them at the end (one pass, pipes work) */
    double sum = 0, sum2 = 0, mx = 0, zlo = INFINITY, zhi = -INFINITY;
    long n = 0;
    int k = 0;
    /* rows are buffered so that nothing is printed if a stream is bad */
    size_t cap = 1024, len = 0;
    double *rows = malloc(cap * 2 * sizeof *rows);
    for (;;) {
        int ra = mesh_reader_next(&a, X, NULL), rb = mesh_reader_next(&b, Y, NULL);
        if (ra < 0 || rb < 0) die("%s", cm_errmsg());
        if (ra != rb)
            die("cannot compare: '%s' has %d frames, '%s' has more", ra ? b.name : a.name, k,
                ra ? a.name : b.name);
        if (ra == 0) break;
        double fs = 0, fm = 0;
        for (int v = 0; v < a.nv; v++) {
            double d = sqrt(pow(X[3 * v] - Y[3 * v], 2) + pow(X[3 * v + 1] - Y[3 * v + 1], 2) +
                            pow(X[3 * v + 2] - Y[3 * v + 2], 2));
            fs += d;
            sum2 += d * d;
            if (d > fm) fm = d;
            if (X[3 * v + axis] < zlo) zlo = X[3 * v + axis];
            if (X[3 * v + axis] > zhi) zhi = X[3 * v + axis];
        }
        if (len == cap) rows = realloc(rows, (cap *= 2) * 2 * sizeof *rows);
        if (!rows) die("out of memory");
        rows[2 * len] = a.nv ? fs / a.nv : 0;
        rows[2 * len + 1] = fm;
        len++;
        sum += fs;
        n += a.nv;
        if (fm > mx) mx = fm;
        k++;
    }
    double scale = 1;
    if (height > 0) {
        if (!(zhi > zlo))
            die("cannot read '%s': the reference has zero height along %c, --height cannot scale it",
                a.name, 'x' + axis);
        scale = height / (zhi - zlo);
    }
    if (!summary)
        for (size_t i = 0; i < len; i++) printf("%zu %.6g %.6g\n", i, scale * rows[2 * i], scale * rows[2 * i + 1]);
    printf("%smean %.6g\n%smax %.6g\n%srms %.6g\n%sframes %d\n", summary ? "" : "# ",
           n ? scale * sum / n : 0, summary ? "" : "# ", scale * mx, summary ? "" : "# ",
           n ? scale * sqrt(sum2 / n) : 0, summary ? "" : "# ", k);
    free(rows);
    free(X);
    free(Y);
    mesh_reader_close(&a);
    mesh_reader_close(&b);
    if (fclose(stdout) != 0) die("cannot write output");
    return 0;
}
