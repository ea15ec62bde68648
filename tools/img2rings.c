/* img2rings -- outlines of a bitmap: the outer and hole boundaries of the
 * dark regions of a PBM/PGM (netpbm) image, as rings for compat-tri.
 */
#include "bitmap_trace.h"
#include "pnm_gray.h"
#include "rings.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: img2rings [options] [image.pbm|image.pgm]\n"
"Trace the boundaries of the dark (ink) regions of a netpbm image (PBM P1/P4,\n"
"PGM P2/P5; PPM by luminance) and write them as rings (stopmo-rings(5)):\n"
"pixel-edge outlines in pixel units, y up, the largest outer boundary first\n"
"(counter-clockwise), holes clockwise, other pieces counter-clockwise.\n"
"\n"
"  -t, --threshold T    gray images: inside where value < T * maxval (default 0.5)\n"
"  -i, --invert         inside = light pixels\n"
"  -s, --simplify D     Douglas-Peucker tolerance in pixels (default 0.7; 0: exact pixel edges)\n"
"  -a, --min-area A     drop loops smaller than A pixels (default 4)\n"
"  -1, --outer-only     write only the first (largest) outer boundary\n"
"  -o, --output FILE    write to FILE\n"
"  -v, --verbose        counts on stderr\n"
"  -h, --help, --version\n"
"\n"
"Example: pngtopnm drawing.png | ppmtopgm | img2rings -1 >drawing.rings\n";

struct options { const char *input, *output; double thr, tol, minarea; int invert, outer; };

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"threshold", 1, 0, 't'}, {"invert", 0, 0, 'i'}, {"simplify", 1, 0, 's'},
        {"min-area", 1, 0, 'a'}, {"outer-only", 0, 0, '1'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->thr = 0.5; o->tol = 0.7; o->minarea = 4;
    int c;
    while ((c = getopt_long(argc, argv, "t:is:a:1o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 't': o->thr = arg_double(optarg, "--threshold"); break;
        case 'i': o->invert = 1; break;
        case 's': o->tol = arg_double(optarg, "--simplify"); break;
        case 'a': o->minarea = arg_double(optarg, "--min-area"); break;
        case '1': o->outer = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!(o->thr > 0 && o->thr <= 1)) usage_error("--threshold must be in (0, 1]");
    if (!(o->tol >= 0 && o->tol < 1e6)) usage_error("--simplify must be >= 0");
    if (!(o->minarea >= 0)) usage_error("--min-area must be >= 0");
    if (optind < argc - 1) usage_error("expected at most one image");
    o->input = optind < argc ? argv[optind] : NULL;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct gray g;
    if (gray_read(o.input, &g) < 0) die("%s", cm_errmsg());
    const char *name = (!o.input || !strcmp(o.input, "-")) ? "<stdin>" : o.input;
    unsigned char *in = malloc((size_t)g.w * g.h);
    for (size_t i = 0; i < (size_t)g.w * g.h; i++) {
        int ink = g.bitmap ? g.v[i] != 0 : g.v[i] < o.thr * g.maxval;
        in[i] = o.invert ? !ink : ink;
    }
    struct rings r;
    if (bitmap_trace(in, g.w, g.h, o.minarea, o.tol, &r) < 0) die("cannot read '%s': %s", name, cm_errmsg());
    snprintf(r.name, sizeof r.name, "%s (traced)", name);
    if (o.outer) r.nrings = 1;
    if (rings_check_simple(&r) < 0)
        die("cannot read '%s': traced outlines cross after simplification (a hole or piece within --simplify of another outline); try -1 or a smaller --simplify", name);
    info(1, "%dx%d image: %d rings, %d points", g.w, g.h, r.nrings, r.start[r.nrings]);
    FILE *f = out_open(o.output);
    if (rings_write(f, &r) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(f);
    rings_free(&r);
    gray_free(&g);
    free(in);
    return 0;
}
