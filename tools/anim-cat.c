/* anim-cat -- join MESH animations with the same connectivity, marking a
 * clip cut at each join.
 *
 * Every header and face list is read and compared before the first byte is
 * written, so mismatched inputs fail cleanly.  Then the frames stream
 * through: memory O(one frame + topology per input).
 */
#include "mesh.h"
#include "tool.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: anim-cat [options] FILE...\n"
"Concatenate MESH animations that share one connectivity (same vertex\n"
"count and identical face list) into one stream.  The first frame of every\n"
"input after the first starts a new clip (a cut mark); cut marks inside the\n"
"inputs are kept.  '-' reads standard input (at most once).\n"
"\n"
"Options:\n"
"      --no-cut       do not mark the joins as cuts\n"
"  -o, --output FILE  write to FILE (temporary + rename) instead of stdout\n"
"      --raw          write the raw (binary) variant (or STOPMO_RAW=1)\n"
"  -v, --verbose      print frame counts on stderr\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Example: anim-cat walk.mesh jump.mesh | mesh-info\n";

struct options {
    const char *output;
    char **inputs;
    int ninputs, raw, nocut;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"no-cut", 0, 0, 'N'}, {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'N': o->nocut = 1; break;
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind >= argc)
        usage_error("expected at least one input file");
    o->inputs = argv + optind;
    o->ninputs = argc - optind;
    int nstdin = 0;
    for (int i = 0; i < o->ninputs; i++)
        nstdin += !strcmp(o->inputs[i], "-");
    if (nstdin > 1)
        usage_error("standard input ('-') can be read only once");
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    int n = o.ninputs;
    struct mesh_reader *r = calloc((size_t)n, sizeof *r);
    if (!r)
        die("out of memory");
    long total = 0;
    for (int i = 0; i < n; i++) {
        if (mesh_reader_open(&r[i], o.inputs[i]) < 0)
            die("%s", cm_errmsg());
        if (i == 0) {
            total = r[0].nframes;
            continue;
        }
        if (r[i].nv != r[0].nv || r[i].nf != r[0].nf)
            die("cannot join '%s' (%d vertices, %d faces) to '%s' (%d vertices, %d faces): "
                "different connectivity", r[i].name, r[i].nv, r[i].nf, r[0].name, r[0].nv,
                r[0].nf);
        for (size_t j = 0; j < (size_t)r[0].nf * 3; j++)
            if (r[i].F[j] != r[0].F[j])
                die("cannot join '%s' to '%s': face %zu differs (different connectivity)",
                    r[i].name, r[0].name, j / 3);
        if (total >= 0 && r[i].nframes >= 0)
            total += r[i].nframes;
        else
            total = -1;
    }
    if (total > 2000000000L)
        total = -1;

    size_t n3 = (size_t)r[0].nv * 3;
    double *X = malloc((n3 + 1) * sizeof *X);
    if (!X)
        die("out of memory");
    FILE *out = out_open(o.output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, r[0].nv, r[0].nf, r[0].F, (int)total, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    for (int i = 0; i < n; i++) {
        int cut, rc, k = 0;
        while ((rc = mesh_reader_next(&r[i], X, &cut)) > 0) {
            if (k == 0 && i > 0 && !o.nocut)
                cut = 1;
            if (mesh_writer_frame(&w, X, cut) < 0)
                die("cannot write output: %s", cm_errmsg());
            k++;
        }
        if (rc < 0)
            die("%s", cm_errmsg());
        info(1, "%s: %d frames", r[i].name, k);
        mesh_reader_close(&r[i]);
    }
    if (mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    free(X);
    free(r);
    return 0;
}
