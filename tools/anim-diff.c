/* anim-diff -- per-frame vertex error between two animations with the same
 * connectivity (e.g. the input and its stop-motion replacement).
 *
 * For each frame: mean and max Euclidean distance between corresponding
 * vertices.  With --height H the errors are scaled to a print in which the
 * reference's bounding box (over all frames) is H tall (millimetres, say),
 * the number an animator cares about.  Streams both inputs frame by frame.
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
"Per-frame mean and max vertex distance between two animations (same #V).\n"
"\n"
"Output (stdout): one line per frame 'frame mean max', then summary lines\n"
"'# mean M', '# max X', '# rms R' (or only the summary with --summary).\n"
"\n"
"Options:\n"
"      --height H     scale errors to a print whose reference height (bounding\n"
"                     box extent along --axis over all frames) is H (e.g. mm);\n"
"                     needs REFERENCE to be a file (read twice)\n"
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
    double scale = 1;
    if (height > 0) {
        if (!strcmp(pa, "-")) usage_error("--height needs REFERENCE to be a file");
        struct mesh_reader r;
        if (mesh_reader_open(&r, pa) < 0) die("%s", cm_errmsg());
        double *X = malloc((size_t)r.nv * 3 * sizeof *X), lo = INFINITY, hi = -INFINITY;
        int rc;
        while ((rc = mesh_reader_next(&r, X, NULL)) == 1)
            for (int v = 0; v < r.nv; v++) {
                if (X[3 * v + axis] < lo) lo = X[3 * v + axis];
                if (X[3 * v + axis] > hi) hi = X[3 * v + axis];
            }
        if (rc < 0) die("%s", cm_errmsg());
        if (!(hi > lo)) die("cannot read '%s': reference has zero height", pa);
        scale = height / (hi - lo);
        free(X);
        mesh_reader_close(&r);
    }
    struct mesh_reader a, b;
    if (mesh_reader_open(&a, pa) < 0 || mesh_reader_open(&b, pb) < 0)
        die("%s", cm_errmsg());
    if (a.nv != b.nv)
        die("cannot compare '%s' (%d vertices) with '%s' (%d vertices)", pa, a.nv, pb, b.nv);
    double *X = malloc((size_t)a.nv * 3 * sizeof *X), *Y = malloc((size_t)a.nv * 3 * sizeof *Y);
    double sum = 0, sum2 = 0, mx = 0;
    long n = 0;
    int k = 0;
    /* rows are buffered so that nothing is printed if a stream is bad */
    size_t cap = 1024, len = 0;
    double *rows = malloc(cap * 2 * sizeof *rows);
    for (;;) {
        int ra = mesh_reader_next(&a, X, NULL), rb = mesh_reader_next(&b, Y, NULL);
        if (ra < 0 || rb < 0) die("%s", cm_errmsg());
        if (ra != rb)
            die("'%s' has %d frames, '%s' has more", ra ? pb : pa, k, ra ? pa : pb);
        if (ra == 0) break;
        double fs = 0, fm = 0;
        for (int v = 0; v < a.nv; v++) {
            double d = scale * sqrt(pow(X[3 * v] - Y[3 * v], 2) + pow(X[3 * v + 1] - Y[3 * v + 1], 2) +
                                    pow(X[3 * v + 2] - Y[3 * v + 2], 2));
            fs += d;
            sum2 += d * d;
            if (d > fm) fm = d;
        }
        if (len == cap) rows = realloc(rows, (cap *= 2) * 2 * sizeof *rows);
        rows[2 * len] = a.nv ? fs / a.nv : 0;
        rows[2 * len + 1] = fm;
        len++;
        sum += fs;
        n += a.nv;
        if (fm > mx) mx = fm;
        k++;
    }
    if (!summary)
        for (size_t i = 0; i < len; i++) printf("%zu %.6g %.6g\n", i, rows[2 * i], rows[2 * i + 1]);
    printf("%smean %.6g\n%smax %.6g\n%srms %.6g\n%sframes %d\n", summary ? "" : "# ",
           n ? sum / n : 0, summary ? "" : "# ", mx, summary ? "" : "# ",
           n ? sqrt(sum2 / n) : 0, summary ? "" : "# ", k);
    if (fclose(stdout) != 0) die("cannot write output");
    return 0;
}
