/* arap-deform2d -- as-rigid-as-possible handle deformation of a 2D mesh
 * (Igarashi, Moscovich, Hughes 2005): pose variations of one drawing for
 * N-way morphing (Baxter, Barla, Anjyo, Sec. 3.2).
 */
#include "arap_deform2d.h"
#include "columns.h"
#include "mesh.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: arap-deform2d [options] MESH HANDLES\n"
"Deform frame 0 of a 2D mesh as rigidly as possible so that handle vertices\n"
"reach their targets.  HANDLES: one row per handle, \"vertex x1 y1 [x2 y2 ...]\":\n"
"K target pairs give K output frames (one pose each).  At least 2 handles.\n"
"\n"
"  -r, --with-rest      write the rest shape as frame 0 before the K poses\n"
"                       (ready as base poses for arap-morph)\n"
"      --raw            raw MESH output (or STOPMO_RAW=1)\n"
"  -o, --output FILE    write to FILE\n"
"  -h, --help, --version\n"
"\n"
"Example: printf '0 0 0\\n10 1.2 0.5\\n' >h.txt; arap-deform2d -r bar.mesh h.txt | mesh2svg -g\n";

struct options { const char *mesh, *handles, *output; int rest, raw; };

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"with-rest", 0, 0, 'r'}, {"raw", 0, 0, 'R'}, {"output", 1, 0, 'o'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "ro:h", lo, NULL)) != -1) {
        switch (c) {
        case 'r': o->rest = 1; break;
        case 'R': o->raw = 1; break;
        case 'o': o->output = optarg; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind != 2) usage_error("expected MESH HANDLES");
    o->mesh = argv[optind];
    o->handles = argv[optind + 1];
    if (!strcmp(o->mesh, "-") && !strcmp(o->handles, "-")) usage_error("MESH and HANDLES cannot both be stdin");
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct mesh m;
    if (mesh_read(o.mesh, &m) < 0) die("%s", cm_errmsg());
    struct columns C;
    if (columns_read(o.handles, 0, -1, NULL, &C) < 0) die("%s", cm_errmsg());
    if (C.rows < 2) die("cannot read '%s': %d handle%s; at least 2 are needed", o.handles, C.rows, C.rows == 1 ? "" : "s");
    if (C.cols < 3 || C.cols % 2 != 1)
        die("cannot read '%s': line 1: expected \"vertex x y [x y ...]\" (an odd count >= 3), got %d numbers", o.handles, C.cols);
    int K = (C.cols - 1) / 2, nh = C.rows;
    int *H = malloc(nh * sizeof *H);
    for (int h = 0; h < nh; h++) {
        double v = C.x[(size_t)h * C.cols];
        if (v != floor(v) || v < 0 || v >= m.nv)
            die("cannot read '%s': row %d: '%g' is not a vertex index (0..%d)", o.handles, h + 1, v, m.nv - 1);
        H[h] = (int)v;
    }
    struct arap_deform2d *D = arap_deform2d_new(m.V, m.nv, m.F, m.nf, H, nh);
    if (!D) die("cannot read '%s': %s", o.handles, cm_errmsg());
    struct mesh out;
    if (mesh_alloc(&out, m.nv, m.nf, K + o.rest) < 0) die("%s", cm_errmsg());
    memcpy(out.F, m.F, 3 * (size_t)m.nf * sizeof *m.F);
    if (o.rest)
        for (int v = 0; v < m.nv; v++) {
            out.V[3 * v] = m.V[3 * v]; out.V[3 * v + 1] = m.V[3 * v + 1]; out.V[3 * v + 2] = 0;
        }
    double *P = malloc(2 * (size_t)nh * sizeof *P);
    for (int k = 0; k < K; k++) {
        for (int h = 0; h < nh; h++) {
            P[2 * h] = C.x[(size_t)h * C.cols + 1 + 2 * k];
            P[2 * h + 1] = C.x[(size_t)h * C.cols + 2 + 2 * k];
        }
        if (arap_deform2d_solve(D, P, mesh_frame(&out, k + o.rest)) < 0) die("%s", cm_errmsg());
    }
    FILE *f = out_open(o.output);
    if (mesh_write(f, &out, want_raw(o.raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(f);
    arap_deform2d_free(D);
    mesh_free(&out); mesh_free(&m); columns_free(&C);
    free(H); free(P);
    return 0;
}
