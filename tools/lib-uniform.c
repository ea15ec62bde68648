/* lib-uniform -- the uniform temporal sampling baseline of StopShop
 * (Sec. 5, Fig. 19): every k-th frame of the animation becomes a piece.
 */
#include "mesh.h"
#include "columns.h"
#include "tool.h"
#include "cm_error.h"
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: lib-uniform [options] [FILE]\n"
"Uniform temporal sampling baseline (StopShop Fig. 19): write a library\n"
"(MESH stream, frames = pieces) made of every K-th frame of the animation\n"
"FILE (default stdin).  Optimal labels for it come from label-expand.\n"
"\n"
"Options:\n"
"  -k, --every K         take frames 0, K, 2K, ... (default: from -d)\n"
"  -d, --pieces D        take D frames evenly spaced: floor(j n / D), j < D\n"
"                        (default 20)\n"
"      --labels-out FILE write the naive \"hold\" labels: every frame mounts the\n"
"                        piece of the last sampled frame at or before it\n"
"  -o, --output FILE     write to FILE instead of stdout\n"
"      --raw             raw (binary) MESH output\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: lib-uniform -d 20 lower.mesh >uniform.lib\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"every", 1, 0, 'k'}, {"pieces", 1, 0, 'd'}, {"labels-out", 1, 0, 'L'},
        {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    long k = 0, d = -1;
    const char *labels_out = NULL, *output = NULL;
    int raw = 0, c;
    while ((c = getopt_long(argc, argv, "k:d:o:h", lo, NULL)) != -1) {
        switch (c) {
        case 'k': k = arg_long(optarg, "--every"); if (k < 1) usage_error("--every must be >= 1"); break;
        case 'd': d = arg_long(optarg, "--pieces"); break;
        case 'L': labels_out = optarg; break;
        case 'o': output = optarg; break;
        case 'R': raw = 1; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1) usage_error("expected at most one input FILE");
    if (k && d >= 0) usage_error("give -k or -d, not both");
    if (!k && d < 0) d = 20;
    if (!k && d < 1) die("-d %ld: the library needs at least one piece", d);
    const char *input = optind < argc ? argv[optind] : NULL;
    struct mesh m;
    if (mesh_read(input, &m) < 0) die("%s", cm_errmsg());
    int n = m.nframes;
    if (d > n) die("-d %ld: only %d frames", d, n);
    if (k) d = (n + k - 1) / k;
    int *src = malloc(sizeof(int) * d);
    for (long j = 0; j < d; j++) src[j] = k ? (int)(j * k) : (int)(j * n / d);
    struct mesh lib;
    if (mesh_alloc(&lib, m.nv, m.nf, (int)d) < 0) die("%s", cm_errmsg());
    memcpy(lib.F, m.F, sizeof(int) * 3 * m.nf);
    for (long j = 0; j < d; j++)
        memcpy(mesh_frame(&lib, (int)j), mesh_frame(&m, src[j]), sizeof(double) * 3 * m.nv);
    if (labels_out) {
        int *l = malloc(sizeof(int) * n);
        for (int f = 0, j = 0; f < n; f++) {
            while (j + 1 < d && src[j + 1] <= f) j++;
            l[f] = j;
        }
        FILE *f = out_open(labels_out);
        if (labels_write(f, l, n) < 0) die("cannot write '%s'", labels_out);
        out_close(f);
        free(l);
    }
    FILE *out = out_open(output);
    if (mesh_write(out, &lib, want_raw(raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    free(src);
    mesh_free(&lib);
    mesh_free(&m);
    return 0;
}
