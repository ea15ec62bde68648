/* anim-avg -- the average frame of a MESH animation.
 *
 * Streams: memory O(one frame); the single output frame is written only
 * after the whole input was read and validated.
 */
#include "mesh.h"
#include "tool.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: anim-avg [options] [FILE]\n"
"Write the average of all frames of a MESH animation as a one-frame MESH\n"
"stream (same connectivity): X = (1/K) sum_k X_k.\n"
"\n"
"Options:\n"
"  -o, --output FILE  write to FILE (temporary + rename) instead of stdout\n"
"      --raw          write the raw (binary) variant (or STOPMO_RAW=1)\n"
"  -v, --verbose      print the frame count on stderr\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Example: mesh-gen -f 30 -a wave grid | anim-avg | mesh-info\n";

struct options {
    const char *input, *output;
    int raw;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    size_t n3 = (size_t)r.nv * 3;
    double *X = malloc((n3 + 1) * sizeof *X);
    double *S = calloc(n3 + 1, sizeof *S);
    if (!X || !S)
        die("out of memory");
    long k = 0;
    int rc;
    /* plain summation is exact enough here: K frames of O(1) coordinates
     * lose about log2(K) bits of 53 */
    while ((rc = mesh_reader_next(&r, X, NULL)) > 0) {
        for (size_t i = 0; i < n3; i++)
            S[i] += X[i];
        k++;
    }
    if (rc < 0)
        die("%s", cm_errmsg());
    for (size_t i = 0; i < n3; i++)
        S[i] /= (double)k;
    info(1, "averaged %ld frames", k);

    FILE *out = out_open(o.output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, r.nv, r.nf, r.F, 1, want_raw(o.raw)) < 0 ||
        mesh_writer_frame(&w, S, 0) < 0 || mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    mesh_reader_close(&r);
    free(X);
    free(S);
    return 0;
}
