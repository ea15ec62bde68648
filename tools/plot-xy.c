/* plot-xy -- a line chart of columns of a column file, as PNG or PPM.
 *
 * Enough plotting for the pipelines to show their curves without outside
 * software: dict-learn --sweep's error against library size (StopShop
 * Fig. 8), per-frame errors from anim-diff, energies per iteration.  Axes
 * with "nice" ticks, one colour per series, a legend, optional log scale.
 */
#include "cm_error.h"
#include "colormap.h"
#include "columns.h"
#include "image.h"
#include "tool.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: plot-xy [options] [FILE] > plot.png\n"
"Draw columns of a column file (whitespace separated numbers, '#' comments)\n"
"as lines: column X against one or more Y columns.\n"
"\n"
"Options:\n"
"  -x, --x COL          column of the x values, 1-based (default 1)\n"
"  -y, --y LIST         comma separated y columns (default 2)\n"
"  -n, --names LIST     comma separated series names for the legend\n"
"  -t, --title TEXT     title above the plot\n"
"      --xlabel TEXT    --ylabel TEXT   axis labels\n"
"      --logy           logarithmic y axis (values must be > 0)\n"
"  -s, --size WxH       image size (default 640x400)\n"
"  -f, --format FMT     png or ppm (default from -o's extension, else png)\n"
"  -o, --output FILE    write to FILE (atomically) instead of stdout\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"Example: dict-learn --sweep 2:40:2 part.mesh | plot-xy -y 3,4 -n mean,max --logy > err.png\n";

struct options {
    const char *input, *output, *format, *title, *xlabel, *ylabel;
    int xcol, *ycols, ny, logy, w, h;
    char **names;
    int nnames;
};

/* split "a,,c" into {"a", "", "c"}: an empty name keeps its place (the
 * series gets the default "column N") */
static char **split_names(const char *s, int *n)
{
    char *copy = strdup(s), **v = NULL;
    *n = 0;
    for (char *tok = copy;;) {
        char *comma = strchr(tok, ',');
        if (comma) *comma = 0;
        v = realloc(v, (*n + 1) * sizeof *v);
        v[(*n)++] = tok;
        if (!comma) break;
        tok = comma + 1;
    }
    return v;
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"x", 1, 0, 'x'}, {"y", 1, 0, 'y'}, {"names", 1, 0, 'n'}, {"title", 1, 0, 't'},
        {"xlabel", 1, 0, 'X'}, {"ylabel", 1, 0, 'Y'}, {"logy", 0, 0, 'L'}, {"size", 1, 0, 's'},
        {"format", 1, 0, 'f'}, {"output", 1, 0, 'o'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->xcol = 1;
    o->w = 640;
    o->h = 400;
    int c;
    while ((c = getopt_long(argc, argv, "x:y:n:t:s:f:o:h", lo, NULL)) != -1) {
        switch (c) {
        case 'x': o->xcol = arg_int(optarg, "--x"); break;
        case 'y': o->ny = arg_intlist(optarg, "--y", &o->ycols); break;
        case 'n': o->names = split_names(optarg, &o->nnames); break;
        case 't': o->title = optarg; break;
        case 'X': o->xlabel = optarg; break;
        case 'Y': o->ylabel = optarg; break;
        case 'L': o->logy = 1; break;
        case 's':
            if (image_parse_size(optarg, &o->w, &o->h) < 0 || o->w < 160 || o->h < 120)
                usage_error("--size: '%s' is not WxH with W >= 160, H >= 120", optarg);
            break;
        case 'f': o->format = optarg; break;
        case 'o': o->output = optarg; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind > 1) usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
    if (!o->ny) { o->ycols = malloc(sizeof(int)); o->ycols[0] = 2; o->ny = 1; }
    if (o->xcol < 1) usage_error("--x: columns are numbered from 1");
    for (int i = 0; i < o->ny; i++)
        if (o->ycols[i] < 1) usage_error("--y: columns are numbered from 1");
    if (o->format && strcmp(o->format, "png") && strcmp(o->format, "ppm"))
        usage_error("--format must be png or ppm");
    if (!o->format) {
        const char *dot = o->output ? strrchr(o->output, '.') : NULL;
        o->format = dot && !strcmp(dot, ".ppm") ? "ppm" : "png";
    }
}

/* a "nice" tick step for the range (1, 2 or 5 times a power of ten) */
static double nice_step(double range, int want)
{
    double raw = range / want, p = pow(10, floor(log10(raw))), m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

/* make [*lo, *hi] a range of positive width that floating point can
 * resolve: an all-equal column (or one whose spread is below the precision
 * of its values) gets a margin around its value, so the scale never
 * divides by zero and the tick loop always advances */
static void widen(double *lo, double *hi)
{
    double m = fmax(fabs(*lo), fabs(*hi)), min_w = fmax(1e-300, 1e-9 * m);
    if (*hi - *lo >= min_w) return;
    double c = 0.5 * (*lo + *hi), h = fmax(0.5, 1e-6 * m);
    *lo = c - h;
    *hi = c + h;
}

static void line(struct image *im, double x0, double y0, double x1, double y1,
                 const unsigned char rgb[3], int thick)
{
    int n = (int)(fmax(fabs(x1 - x0), fabs(y1 - y0)) + 1);
    for (int i = 0; i <= n; i++) {
        double t = n ? (double)i / n : 0;
        int x = (int)lround(x0 + t * (x1 - x0)), y = (int)lround(y0 + t * (y1 - y0));
        image_fill_rect(im, x - thick / 2, y - thick / 2, thick, thick, rgb);
    }
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct columns c;
    if (columns_read(o.input, 0, -1, "rows", &c) < 0)
        die("%s", cm_errmsg());
    const char *name = o.input && strcmp(o.input, "-") ? o.input : "<stdin>";
    if (c.rows < 1)
        die("cannot read '%s': no data rows", name);
    int maxcol = o.xcol;
    for (int i = 0; i < o.ny; i++) if (o.ycols[i] > maxcol) maxcol = o.ycols[i];
    if (maxcol > c.cols)
        die("cannot read '%s': column %d requested, rows have %d", name, maxcol, c.cols);
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int r = 0; r < c.rows; r++) {
        double x = c.x[(size_t)r * c.cols + o.xcol - 1];
        xmin = fmin(xmin, x); xmax = fmax(xmax, x);
        for (int i = 0; i < o.ny; i++) {
            double y = c.x[(size_t)r * c.cols + o.ycols[i] - 1];
            if (o.logy) {
                if (!(y > 0)) die("cannot read '%s': data row %d, column %d: %g cannot go on a log axis",
                                     name, r + 1, o.ycols[i], y);
                y = log10(y);
            }
            ymin = fmin(ymin, y); ymax = fmax(ymax, y);
        }
    }
    widen(&xmin, &xmax);
    widen(&ymin, &ymax);
    if (o.logy) { ymin = floor(ymin); ymax = ceil(ymax); }
    else { double pad = 0.05 * (ymax - ymin); ymin -= ymin >= 0 && ymin - pad < 0 ? ymin : pad; ymax += pad; }

    const unsigned char white[3] = {255, 255, 255}, black[3] = {0, 0, 0}, grid[3] = {225, 225, 225};
    struct image im;
    if (image_alloc(&im, o.w, o.h, white) < 0) die("%s", cm_errmsg());
    int L = 70, R = 20, T = o.title ? 30 : 14, B = 46;
    int pw = o.w - L - R, ph = o.h - T - B;
#define PX(x) (L + ((x) - xmin) / (xmax - xmin) * pw)
#define PY(y) (T + ph - ((y) - ymin) / (ymax - ymin) * ph)
    char buf[64];
    double xs = nice_step(xmax - xmin, 8), x0 = ceil(xmin / xs);
    for (int i = 0; i < 100 && (x0 + i) * xs <= xmax + 1e-9 * xs; i++) {
        double x = (x0 + i) * xs;
        line(&im, PX(x), T, PX(x), T + ph, grid, 1);
        snprintf(buf, sizeof buf, "%g", fabs(x) < 1e-12 * xs ? 0.0 : x);
        image_text(&im, (int)PX(x) - text_width(buf, 1) / 2, T + ph + 6, buf, 1, black, NULL);
    }
    /* log axis: a tick per decade, or per k decades when there are many */
    double ys = o.logy ? fmax(1, ceil((ymax - ymin) / 10)) : nice_step(ymax - ymin, 6);
    double y0 = ceil(ymin / ys);
    for (int i = 0; i < 100 && (y0 + i) * ys <= ymax + 1e-9 * ys; i++) {
        double y = (y0 + i) * ys;
        line(&im, L, PY(y), L + pw, PY(y), grid, 1);
        if (o.logy) snprintf(buf, sizeof buf, "1e%d", (int)lround(y));
        else snprintf(buf, sizeof buf, "%g", fabs(y) < 1e-12 * ys ? 0.0 : y);
        image_text(&im, L - 6 - text_width(buf, 1), (int)PY(y) - text_height(1) / 2, buf, 1, black, NULL);
    }
    line(&im, L, T, L, T + ph, black, 1);
    line(&im, L, T + ph, L + pw, T + ph, black, 1);
    for (int i = 0; i < o.ny; i++) {
        unsigned char col[3];
        colormap_label(i, col);
        double px = 0, py = 0;
        for (int r = 0; r < c.rows; r++) {
            double x = c.x[(size_t)r * c.cols + o.xcol - 1], y = c.x[(size_t)r * c.cols + o.ycols[i] - 1];
            if (o.logy) y = log10(y);
            double qx = PX(x), qy = PY(y);
            if (r) line(&im, px, py, qx, qy, col, 2);
            image_fill_rect(&im, (int)qx - 2, (int)qy - 2, 5, 5, col);
            px = qx; py = qy;
        }
        const char *nm = i < o.nnames && *o.names[i] ? o.names[i] : NULL;
        if (!nm) { snprintf(buf, sizeof buf, "column %d", o.ycols[i]); nm = buf; }
        int ly = T + 8 + i * (text_height(1) + 6);
        image_fill_rect(&im, L + pw - 150, ly + 2, 16, 3, col);
        image_text(&im, L + pw - 128, ly - 1, nm, 1, black, NULL);
    }
    if (o.title) image_text(&im, L + pw / 2 - text_width(o.title, 2) / 2, 6, o.title, 2, black, NULL);
    if (o.xlabel) image_text(&im, L + pw / 2 - text_width(o.xlabel, 1) / 2, o.h - 18, o.xlabel, 1, black, NULL);
    if (o.ylabel) image_text(&im, 4, T - 12 > 2 ? T - 12 : 2, o.ylabel, 1, black, NULL);
    FILE *f = out_open(o.output);
    if (image_write(f, &im, o.format) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(f);
    image_free(&im);
    columns_free(&c);
    free(o.ycols);
    return 0;
}
