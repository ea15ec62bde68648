/* biharm-weights -- pose-space blend weights by mesh-based biharmonic least
 * squares (Baxter, Barla, Anjyo, N-way morphing Sec. 4.1, Eq. 1-2).
 */
#include "pose_weights.h"
#include "columns.h"
#include "numparse.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: biharm-weights [options] POSES [QUERIES]\n"
"Blend weights of N base poses at query points of a 2D pose space.\n"
"POSES: N rows \"x y\" (the place of base pose i); QUERIES (default stdin):\n"
"rows \"x y\"; output: one row of N weights per query (they sum to 1 and\n"
"equal e_i at pose i).\n"
"\n"
"  -e, --epsilon E      weight of the gradient term (default 1; poses span 1)\n"
"  -m, --margin M       meshed box: poses' extent + M extents on each side (default 3)\n"
"  -s, --size S         mesh edge length bound, fraction of the extent (default 0.1)\n"
"  -g, --grid K         ignore QUERIES; write \"x y w1 .. wN\" on a K by K grid over\n"
"                       the poses' extent plus one extent around (for plotting)\n"
"  -v, --verbose        mesh size and timing on stderr\n"
"  -o, --output FILE    write to FILE\n"
"  -h, --help, --version\n"
"\n"
"Example: printf '0 0\\n1 0\\n0 1\\n' >poses.txt; echo '0.3 0.3' | biharm-weights poses.txt\n";

struct options { const char *poses, *queries, *output; double eps, margin, size; int grid; };

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"epsilon", 1, 0, 'e'}, {"margin", 1, 0, 'm'}, {"size", 1, 0, 's'}, {"grid", 1, 0, 'g'},
        {"verbose", 0, 0, 'v'}, {"output", 1, 0, 'o'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'},
        {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->eps = 1; o->margin = 3; o->size = 0.1;
    int c;
    while ((c = getopt_long(argc, argv, "e:m:s:g:vo:h", lo, NULL)) != -1) {
        switch (c) {
        case 'e': o->eps = arg_double(optarg, "--epsilon"); break;
        case 'm': o->margin = arg_double(optarg, "--margin"); break;
        case 's': o->size = arg_double(optarg, "--size"); break;
        case 'g': o->grid = arg_int(optarg, "--grid"); break;
        case 'v': verbose++; break;
        case 'o': o->output = optarg; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!(o->eps > 0 && o->eps < 1e6)) usage_error("--epsilon must be positive");
    if (!(o->margin > 0 && o->margin <= 100)) usage_error("--margin must be in (0, 100]");
    if (!(o->size >= 0.002 && o->size <= 10)) usage_error("--size must be in [0.002, 10]");
    if (o->grid < 0 || o->grid > 4000 || o->grid == 1) usage_error("--grid must be in 2..4000");
    if (optind >= argc || optind + 2 < argc) usage_error("expected POSES [QUERIES]");
    o->poses = argv[optind];
    o->queries = optind + 1 < argc ? argv[optind + 1] : NULL;
    if (!strcmp(o->poses, "-") && !o->grid && (!o->queries || !strcmp(o->queries, "-")))
        usage_error("POSES and QUERIES cannot both be stdin");
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct columns P, Q = {0};
    if (columns_read(o.poses, 2, -1, NULL, &P) < 0) die("%s", cm_errmsg());
    if (P.rows < 1) die("cannot read '%s': no pose points", o.poses);
    if (!o.grid && columns_read(o.queries, 2, -1, NULL, &Q) < 0) die("%s", cm_errmsg());
    int N = P.rows;
    struct pose_weights pw;
    if (pose_weights_build(&pw, P.x, N, o.margin, o.size, o.eps) < 0)
        die("cannot read '%s': %s", o.poses, cm_errmsg());
    info(1, "pose-space mesh: %d vertices, %d triangles, %d poses", pw.nv, pw.nf, N);
    FILE *out = out_open(o.output);
    double *w = malloc((N + 1) * sizeof *w);
    char buf[32];
    if (o.grid) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int i = 0; i < N; i++)
            for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], P.x[2 * i + d]); hi[d] = fmax(hi[d], P.x[2 * i + d]); }
        double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
        if (!(ext > 0)) ext = 1;
        double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]), h = 1.5 * ext;
        for (int j = 0; j < o.grid; j++) {
            for (int i = 0; i < o.grid; i++) {
                double q[2] = {cx - h + 2 * h * i / (o.grid - 1), cy - h + 2 * h * j / (o.grid - 1)};
                pose_weights_eval(&pw, q, w);
                format_double(buf, q[0]); fputs(buf, out);
                format_double(buf, q[1]); fputc(' ', out); fputs(buf, out);
                for (int k = 0; k < N; k++) { format_double(buf, w[k]); fputc(' ', out); fputs(buf, out); }
                fputc('\n', out);
            }
            fputc('\n', out);   /* gnuplot splot block separator */
        }
    } else {
        for (int r = 0; r < Q.rows; r++) {
            pose_weights_eval(&pw, Q.x + 2 * r, w);
            for (int k = 0; k < N; k++) { format_double(buf, w[k]); if (k) fputc(' ', out); fputs(buf, out); }
            fputc('\n', out);
        }
    }
    out_close(out);
    free(w);
    pose_weights_free(&pw);
    columns_free(&P);
    columns_free(&Q);
    return 0;
}
