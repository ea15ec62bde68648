/* mesh2svg -- draw 2D meshes (MESH streams with z = 0) or outline rings as SVG.
 *
 * One frame, all frames as an animated SVG (SMIL <animate> of the path
 * data), or all frames side by side in a grid, so every result of the 2D
 * morphing pipeline (compat-tri, arap-morph) can be looked at in a browser.
 */
#include "mesh.h"
#include "rings.h"
#include "columns.h"
#include "topology.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: mesh2svg [options] [file]\n"
"Draw a 2D mesh (MESH stream, z = 0) or an outline file (rings) as SVG.\n"
"The input kind is detected from its first word (MESH or ring).\n"
"\n"
"Options:\n"
"  -f, --frame K        draw frame K (default 0)\n"
"  -a, --animate        all frames in one animated SVG (SMIL), looping\n"
"      --fps F          frames per second of the animation (default 12)\n"
"  -g, --grid           all frames side by side in a grid\n"
"  -c, --columns C      grid columns (default: about sqrt of the frame count)\n"
"  -w, --width W        width of one drawing in pixels (default 400)\n"
"      --fill COLOR     fill of the triangles / outer rings (default #cfe0f5)\n"
"      --no-edges       draw only the outline, not the triangle edges\n"
"      --points         mark the vertices and label each with its 0-based index\n"
"                       (the index compat-tri -c expects; for outlines the\n"
"                       index in the file's ring, ring number first if several)\n"
"      --points-file FILE  mark and number (1, 2, ... in row order) the vertices\n"
"                       named in column 1 of FILE, e.g. a compat-tri -c file\n"
"      --points-column N   take the vertex indices from column N (1-based)\n"
"  -o, --output FILE    write to FILE (temporary + rename) instead of stdout\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"Example: compat-tri -c corr.txt a.rings b.rings | mesh2svg -g >both.svg\n";

struct options {
    const char *input, *output, *fill;
    int frame, animate, grid, columns, no_edges, points, points_col;
    const char *points_file;
    double width, fps;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frame", 1, 0, 'f'}, {"animate", 0, 0, 'a'}, {"fps", 1, 0, 'F'}, {"grid", 0, 0, 'g'},
        {"columns", 1, 0, 'c'}, {"width", 1, 0, 'w'}, {"fill", 1, 0, 'L'}, {"no-edges", 0, 0, 'E'},
        {"points", 0, 0, 'P'}, {"points-file", 1, 0, 'Q'}, {"points-column", 1, 0, 'K'},
        {"output", 1, 0, 'o'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'},
        {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->width = 400; o->fps = 12; o->fill = "#cfe0f5";
    int c;
    while ((c = getopt_long(argc, argv, "f:agc:w:o:h", lo, NULL)) != -1) {
        switch (c) {
        case 'f': o->frame = arg_int(optarg, "--frame"); break;
        case 'a': o->animate = 1; break;
        case 'F': o->fps = arg_double(optarg, "--fps"); break;
        case 'g': o->grid = 1; break;
        case 'c': o->columns = arg_int(optarg, "--columns"); break;
        case 'w': o->width = arg_double(optarg, "--width"); break;
        case 'L': o->fill = optarg; break;
        case 'E': o->no_edges = 1; break;
        case 'P': o->points = 1; break;
        case 'Q': o->points_file = optarg; break;
        case 'K':
            o->points_col = arg_int(optarg, "--points-column");
            if (o->points_col < 1) usage_error("--points-column must be >= 1");
            break;
        case 'o': o->output = optarg; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1) usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
    if (o->animate && o->grid) usage_error("--animate and --grid exclude each other");
    if (o->frame < 0) usage_error("--frame must be >= 0");
    if (!(o->width > 0 && o->width < 1e6)) usage_error("--width must be positive");
    if (!(o->fps > 0 && o->fps < 1000)) usage_error("--fps must be positive");
    if (o->columns < 0) usage_error("--columns must be positive");
    if (o->points_col && !o->points_file) usage_error("--points-column needs --points-file");
    if (!o->points_col) o->points_col = 1;
    if (o->animate && (o->points || o->points_file))
        usage_error("--points and --points-file draw on still pictures, not with --animate");
    for (const char *s = o->fill; *s; s++)
        if (*s == '"' || *s == '<' || *s == '&') usage_error("--fill: bad color '%s'", o->fill);
}

/* first significant character of the input: 'M' (MESH) or 'r' (rings) */
static int sniff(const char *path)
{
    FILE *f = (!path || !strcmp(path, "-")) ? stdin : fopen(path, "r");
    if (!f) return -1;
    int ch, bol = 1;
    while ((ch = getc(f)) != EOF) {
        if (bol && ch == '#') { while ((ch = getc(f)) != EOF && ch != '\n') ; bol = 1; continue; }
        if (ch == '\n') { bol = 1; continue; }
        if (ch == ' ' || ch == '\t' || ch == '\r') continue;
        break;
    }
    if (f == stdin) { if (ch != EOF) ungetc(ch, f); }
    else fclose(f);
    return ch;
}

struct view { double x0, y1, s; };   /* svg = ((x - x0) s, (y1 - y) s) */

static void pt(FILE *out, const struct view *v, double x, double y, double ox, double oy)
{
    fprintf(out, "%.2f %.2f", ox + (x - v->x0) * v->s, oy + (v->y1 - y) * v->s);
}

/* path data of all triangles (or only boundary edges) of one frame */
static void mesh_path(FILE *out, const struct mesh *m, const double *X, const struct view *v,
                      double ox, double oy, const struct topology *t, int boundary)
{
    if (!boundary) {
        for (int f = 0; f < m->nf; f++) {
            const int *F = m->F + 3 * f;
            for (int c = 0; c < 3; c++) {
                fputc(c ? 'L' : 'M', out);
                pt(out, v, X[3 * F[c]], X[3 * F[c] + 1], ox, oy);
            }
            fputc('Z', out);
        }
    } else {
        for (int e = 0; e < t->ne; e++)
            if (t->EFn[e] == 1) {
                int a = t->E[2 * e], b = t->E[2 * e + 1];
                fputc('M', out); pt(out, v, X[3 * a], X[3 * a + 1], ox, oy);
                fputc('L', out); pt(out, v, X[3 * b], X[3 * b + 1], ox, oy);
            }
    }
}

/* a marked vertex at svg position (x, y) with a label (NULL: none) */
static void mark(FILE *out, double x, double y, double rad, const char *color, const char *label, double fs)
{
    fprintf(out, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"/>\n", x, y, rad, color);
    if (label)
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"%.2f\" "
                     "fill=\"%s\" stroke=\"white\" stroke-width=\"%.2f\" paint-order=\"stroke\">%s</text>\n",
                x + rad, y - rad, fs, color, 0.25 * fs, label);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    int kind = sniff(o.input);
    if (kind < 0)
        die("cannot read '%s': cannot open", o.input);
    struct mesh m = {0};
    struct rings r = {0};
    int is_mesh = kind == 'M';
    if (is_mesh) {
        if (mesh_read(o.input, &m) < 0) die("%s", cm_errmsg());
    } else {
        if (rings_read(o.input, &r) < 0 || rings_check_simple(&r) < 0) die("%s", cm_errmsg());
        /* present the rings as a one-frame "mesh" of points for the bbox */
        m.nv = r.start[r.nrings]; m.nframes = 1;
        m.V = calloc(3 * (size_t)m.nv, sizeof *m.V);
        for (int i = 0; i < m.nv; i++) { m.V[3 * i] = r.P[2 * i]; m.V[3 * i + 1] = r.P[2 * i + 1]; }
    }
    if (o.frame >= m.nframes)
        die("cannot read '%s': frame %d asked, the stream has %d", o.input ? o.input : "<stdin>",
            o.frame, m.nframes);
    /* numbered points: vertex indices from a column of a file */
    struct columns pts = {0};
    if (o.points_file) {
        if (columns_read(o.points_file, 0, -1, NULL, &pts) < 0) die("%s", cm_errmsg());
        if (pts.rows > 0 && o.points_col > pts.cols)
            die("cannot read '%s': no column %d (it has %d)", o.points_file, o.points_col, pts.cols);
        int lim = is_mesh ? m.nv : (r.nrings == 1 ? m.nv : 0);
        if (!is_mesh && r.nrings != 1)
            die("cannot read '%s': --points-file numbers vertices of one ring; '%s' has %d rings",
                o.points_file, o.input ? o.input : "<stdin>", r.nrings);
        for (int i = 0; i < pts.rows; i++) {
            double x = pts.x[(size_t)i * pts.cols + o.points_col - 1];
            if (x != floor(x) || x < 0 || x >= lim)
                die("cannot read '%s': row %d: %g is not a vertex index 0..%d", o.points_file, i + 1, x, lim - 1);
        }
    }
    int f0 = o.frame, f1 = o.frame + 1;
    if (o.animate || o.grid) { f0 = 0; f1 = m.nframes; }
    /* common bounding box of the shown frames */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = f0; k < f1; k++) {
        const double *X = mesh_frame(&m, k);
        for (int i = 0; i < m.nv; i++)
            for (int d = 0; d < 2; d++) {
                if (X[3 * i + d] < lo[d]) lo[d] = X[3 * i + d];
                if (X[3 * i + d] > hi[d]) hi[d] = X[3 * i + d];
            }
    }
    if (m.nv == 0) { lo[0] = lo[1] = 0; hi[0] = hi[1] = 1; }
    double span = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(span > 0)) span = 1;
    double pad = 0.03 * span;
    struct view v = {lo[0] - pad, hi[1] + pad, 0};
    double W = o.width;
    v.s = W / (hi[0] - lo[0] + 2 * pad > 0 ? hi[0] - lo[0] + 2 * pad : 1);
    double H = (hi[1] - lo[1] + 2 * pad) * v.s;
    if (H < 1) H = 1;
    int ncell = o.grid ? m.nframes : 1;
    int cols = o.columns ? o.columns : (int)ceil(sqrt((double)ncell));
    if (cols > ncell) cols = ncell;
    int rows = (ncell + cols - 1) / cols;
    struct topology t = {0};
    if (is_mesh && topology_build(m.F, m.nf, m.nv, &t) < 0) die("%s", cm_errmsg());
    double sw = 0.0025 * W;   /* stroke width */

    FILE *out = out_open(o.output);
    fprintf(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                 "viewBox=\"0 0 %.2f %.2f\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            W * cols, H * rows, W * cols, H * rows);
    if (!is_mesh) {
        fprintf(out, "<path fill=\"%s\" fill-rule=\"evenodd\" stroke=\"black\" stroke-width=\"%.2f\" d=\"",
                o.fill, 2 * sw);
        for (int k = 0; k < r.nrings; k++) {
            const double *P = rings_ring(&r, k);
            for (int i = 0; i < rings_count(&r, k); i++) {
                fputc(i ? 'L' : 'M', out);
                pt(out, &v, P[2 * i], P[2 * i + 1], 0, 0);
            }
            fputc('Z', out);
        }
        fprintf(out, "\"/>\n");
        if (o.points) {
            char lab[32];
            for (int k = 0; k < r.nrings; k++)
                for (int i = r.start[k]; i < r.start[k + 1]; i++) {
                    if (r.nrings > 1) snprintf(lab, sizeof lab, "%d:%d", k, i - r.start[k]);
                    else snprintf(lab, sizeof lab, "%d", i);
                    mark(out, (m.V[3 * i] - v.x0) * v.s, (v.y1 - m.V[3 * i + 1]) * v.s, 3 * sw,
                         i == r.start[k] ? "red" : "black", lab, 5 * sw);
                }
        }
        for (int i = 0; i < pts.rows; i++) {
            char lab[32];
            int p = (int)pts.x[(size_t)i * pts.cols + o.points_col - 1];
            snprintf(lab, sizeof lab, "%d", i + 1);
            mark(out, (m.V[3 * p] - v.x0) * v.s, (v.y1 - m.V[3 * p + 1]) * v.s, 5 * sw, "#d01c1c", lab, 10 * sw);
        }
    } else if (o.animate) {
        double dur = m.nframes / o.fps;
        for (int layer = 0; layer < 2; layer++) {
            if (layer == 0)
                fprintf(out, "<path fill=\"%s\" stroke=\"%s\" stroke-width=\"%.2f\" stroke-linejoin=\"round\" d=\"",
                        o.fill, o.no_edges ? "none" : "#5a6f8c", sw);
            else
                fprintf(out, "<path fill=\"none\" stroke=\"black\" stroke-width=\"%.2f\" stroke-linecap=\"round\" d=\"",
                        2 * sw);
            mesh_path(out, &m, mesh_frame(&m, 0), &v, 0, 0, &t, layer);
            fprintf(out, "\">\n<animate attributeName=\"d\" dur=\"%gs\" repeatCount=\"indefinite\" "
                         "calcMode=\"discrete\" values=\"", dur);
            for (int k = 0; k < m.nframes; k++) {
                if (k) fputc(';', out);
                mesh_path(out, &m, mesh_frame(&m, k), &v, 0, 0, &t, layer);
            }
            fprintf(out, "\"/>\n</path>\n");
        }
    } else {
        for (int k = f0; k < f1; k++) {
            int cell = k - f0;
            double ox = (cell % cols) * W, oy = (cell / cols) * H;
            const double *X = mesh_frame(&m, k);
            fprintf(out, "<path fill=\"%s\" stroke=\"%s\" stroke-width=\"%.2f\" stroke-linejoin=\"round\" d=\"",
                    o.fill, o.no_edges ? "none" : "#5a6f8c", sw);
            mesh_path(out, &m, X, &v, ox, oy, &t, 0);
            fprintf(out, "\"/>\n<path fill=\"none\" stroke=\"black\" stroke-width=\"%.2f\" stroke-linecap=\"round\" d=\"", 2 * sw);
            mesh_path(out, &m, X, &v, ox, oy, &t, 1);
            fprintf(out, "\"/>\n");
            if (o.points) {
                char lab[32];
                for (int i = 0; i < m.nv; i++) {
                    snprintf(lab, sizeof lab, "%d", i);
                    mark(out, ox + (X[3 * i] - v.x0) * v.s, oy + (v.y1 - X[3 * i + 1]) * v.s, 2.5 * sw, "black",
                         lab, 5 * sw);
                }
            }
            for (int i = 0; i < pts.rows; i++) {
                char lab[32];
                int p = (int)pts.x[(size_t)i * pts.cols + o.points_col - 1];
                snprintf(lab, sizeof lab, "%d", i + 1);
                mark(out, ox + (X[3 * p] - v.x0) * v.s, oy + (v.y1 - X[3 * p + 1]) * v.s, 5 * sw, "#d01c1c", lab,
                     10 * sw);
            }
            if (o.grid)
                fprintf(out, "<text x=\"%.1f\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"%.1f\">%d</text>\n",
                        ox + 4 * sw, oy + 12 * sw, 10 * sw, k);
        }
    }
    fprintf(out, "</svg>\n");
    out_close(out);
    if (is_mesh) topology_free(&t);
    mesh_free(&m);
    rings_free(&r);
    columns_free(&pts);
    return 0;
}
