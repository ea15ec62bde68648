/* svg2rings -- SVG paths and polygons to outline rings: path data
 * (M L H V C S Q T A Z, absolute and relative) flattened to a tolerance.
 */
#include "rings.h"
#include "tool.h"
#include "cm_error.h"
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: svg2rings [options] [file.svg]\n"
"Read the <path d=...> and <polygon points=...> elements of an SVG drawing and\n"
"write their closed outlines as rings (stopmo-rings(5)): curves (C S Q T A)\n"
"flattened so no point of the curve is farther than the tolerance from the\n"
"polyline; y is flipped (SVG y points down); the largest ring comes first,\n"
"counter-clockwise; holes (inside an odd number of larger rings) clockwise.\n"
"\n"
"  -t, --tolerance T   flattening tolerance in SVG user units (default 0.25)\n"
"      --no-flip       keep SVG's y axis\n"
"  -o, --output FILE   write to FILE\n"
"  -v, --verbose       counts on stderr\n"
"  -h, --help, --version\n"
"\n"
"Transforms (transform=...) are not applied.\n"
"Example: svg2rings -t 0.1 drawing.svg | mesh2svg >check.svg\n";

struct options { const char *input, *output; double tol; int noflip; };

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"tolerance", 1, 0, 't'}, {"no-flip", 0, 0, 'F'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->tol = 0.25;
    int c;
    while ((c = getopt_long(argc, argv, "t:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 't': o->tol = arg_double(optarg, "--tolerance"); break;
        case 'F': o->noflip = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!(o->tol > 0 && o->tol < 1e12)) usage_error("--tolerance must be positive");
    if (optind < argc - 1) usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
}

/* ---- growing point list of the current subpath, finished rings ---- */
static double *pts;
static int npts, cappts;
static struct rings out;
static const char *fname;
static long cur_line;

static void addpt(double x, double y)
{
    if (npts && pts[2 * npts - 2] == x && pts[2 * npts - 1] == y) return;
    if (npts == cappts) { cappts = cappts ? 2 * cappts : 256; pts = realloc(pts, 2 * (size_t)cappts * sizeof *pts); }
    pts[2 * npts] = x; pts[2 * npts + 1] = y; npts++;
}

static long *ring_line; static int nring_line;

static void finish(void)
{
    while (npts > 1 && pts[0] == pts[2 * npts - 2] && pts[1] == pts[2 * npts - 1]) npts--;
    if (npts >= 3) {
        rings_append(&out, pts, npts);
        ring_line = realloc(ring_line, (nring_line + 1) * sizeof *ring_line);
        ring_line[nring_line++] = cur_line;
    }
    npts = 0;
}

static void cubic(double x0, double y0, double x1, double y1, double x2, double y2, double x3,
                  double y3, double tol, int depth)
{
    double dx = x3 - x0, dy = y3 - y0, L = hypot(dx, dy);
    double d1, d2;
    if (L > 0) {
        d1 = fabs((x1 - x0) * dy - (y1 - y0) * dx) / L;
        d2 = fabs((x2 - x0) * dy - (y2 - y0) * dx) / L;
    } else {
        d1 = hypot(x1 - x0, y1 - y0); d2 = hypot(x2 - x0, y2 - y0);
    }
    /* the curve stays within 3/4 of the control polygon's distance */
    if (depth > 18 || 0.75 * fmax(d1, d2) <= tol) { addpt(x3, y3); return; }
    double ax = (x0 + x1) / 2, ay = (y0 + y1) / 2, bx = (x1 + x2) / 2, by = (y1 + y2) / 2;
    double cx = (x2 + x3) / 2, cy = (y2 + y3) / 2, abx = (ax + bx) / 2, aby = (ay + by) / 2;
    double bcx = (bx + cx) / 2, bcy = (by + cy) / 2, mx = (abx + bcx) / 2, my = (aby + bcy) / 2;
    cubic(x0, y0, ax, ay, abx, aby, mx, my, tol, depth + 1);
    cubic(mx, my, bcx, bcy, cx, cy, x3, y3, tol, depth + 1);
}

/* SVG arc (endpoint parametrization, SVG 1.1 F.6.5) */
static void arc(double x1, double y1, double rx, double ry, double phi_deg, int large, int sweep,
                double x2, double y2, double tol)
{
    rx = fabs(rx); ry = fabs(ry);
    if (rx == 0 || ry == 0) { addpt(x2, y2); return; }
    double phi = phi_deg * M_PI / 180, c = cos(phi), s = sin(phi);
    double dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
    double xp = c * dx + s * dy, yp = -s * dx + c * dy;
    double lam = xp * xp / (rx * rx) + yp * yp / (ry * ry);
    if (lam > 1) { rx *= sqrt(lam); ry *= sqrt(lam); }
    double num = rx * rx * ry * ry - rx * rx * yp * yp - ry * ry * xp * xp;
    double den = rx * rx * yp * yp + ry * ry * xp * xp;
    double k = den > 0 ? sqrt(fmax(0, num / den)) : 0;
    if (large == sweep) k = -k;
    double cxp = k * rx * yp / ry, cyp = -k * ry * xp / rx;
    double cx = c * cxp - s * cyp + (x1 + x2) / 2, cy = s * cxp + c * cyp + (y1 + y2) / 2;
    double t1 = atan2((yp - cyp) / ry, (xp - cxp) / rx);
    double t2 = atan2((-yp - cyp) / ry, (-xp - cxp) / rx);
    double dt = t2 - t1;
    if (sweep && dt < 0) dt += 2 * M_PI;
    if (!sweep && dt > 0) dt -= 2 * M_PI;
    double r = fmax(rx, ry);
    double step = tol < r ? 2 * acos(1 - tol / r) : M_PI / 2;
    int n = (int)ceil(fabs(dt) / step);
    if (n < 1) n = 1;
    if (n > 100000) n = 100000;
    for (int i = 1; i < n; i++) {
        double t = t1 + dt * i / n;
        addpt(cx + c * rx * cos(t) - s * ry * sin(t), cy + s * rx * cos(t) + c * ry * sin(t));
    }
    addpt(x2, y2);
}

/* ---- path data parsing ---- */
static const char *skipsep(const char *p)
{
    while (*p && (isspace((unsigned char)*p) || *p == ',')) p++;
    return p;
}

static int number(const char **pp, double *v)
{
    const char *p = skipsep(*pp);
    char *end;
    errno = 0;
    *v = strtod(p, &end);
    if (end == p || !isfinite(*v)) return -1;
    *pp = end;
    return 0;
}

static int flag(const char **pp, int *f)
{
    const char *p = skipsep(*pp);
    if (*p != '0' && *p != '1') return -1;
    *f = *p - '0';
    *pp = p + 1;
    return 0;
}

static int path_data(const char *d, double tol)
{
    const char *p = d;
    double cx = 0, cy = 0, sx = 0, sy = 0, qx = 0, qy = 0;  /* current, subpath start, last control */
    char cmd = 0, prev = 0;
    for (;;) {
        p = skipsep(p);
        if (!*p) break;
        if (isalpha((unsigned char)*p)) cmd = *p++;
        else if (!cmd) return cm_seterr("path data must start with a command, not '%.10s'", p);
        else if (cmd == 'M') cmd = 'L';
        else if (cmd == 'm') cmd = 'l';
        int rel = islower((unsigned char)cmd);
        char C = toupper((unsigned char)cmd);
        double a[7];
        int na = 0;
        switch (C) {
        case 'Z': na = 0; break;
        case 'H': case 'V': na = 1; break;
        case 'M': case 'L': case 'T': na = 2; break;
        case 'S': case 'Q': na = 4; break;
        case 'C': na = 6; break;
        case 'A': na = 7; break;
        default: return cm_seterr("unknown path command '%c'", cmd);
        }
        int fl[2] = {0, 0};
        for (int i = 0; i < na; i++) {
            if (C == 'A' && (i == 3 || i == 4)) {
                if (flag(&p, &fl[i - 3]) < 0) return cm_seterr("arc flag expected after '%c'", cmd);
                continue;
            }
            if (number(&p, &a[i]) < 0) return cm_seterr("number expected after '%c' near '%.12s'", cmd, p);
        }
        double ox = rel ? cx : 0, oy = rel ? cy : 0;
        switch (C) {
        case 'M':
            finish();
            cx = ox + a[0]; cy = oy + a[1]; sx = cx; sy = cy;
            addpt(cx, cy);
            break;
        case 'L': cx = ox + a[0]; cy = oy + a[1]; addpt(cx, cy); break;
        case 'H': cx = ox + a[0]; addpt(cx, cy); break;
        case 'V': cy = oy + a[0]; addpt(cx, cy); break;
        case 'C':
            cubic(cx, cy, ox + a[0], oy + a[1], ox + a[2], oy + a[3], ox + a[4], oy + a[5], tol, 0);
            qx = ox + a[2]; qy = oy + a[3]; cx = ox + a[4]; cy = oy + a[5];
            break;
        case 'S': {
            double x1 = cx, y1 = cy;
            if (strchr("CcSs", prev)) { x1 = 2 * cx - qx; y1 = 2 * cy - qy; }
            cubic(cx, cy, x1, y1, ox + a[0], oy + a[1], ox + a[2], oy + a[3], tol, 0);
            qx = ox + a[0]; qy = oy + a[1]; cx = ox + a[2]; cy = oy + a[3];
            break;
        }
        case 'Q': case 'T': {
            double x1, y1, x2, y2;
            if (C == 'Q') { x1 = ox + a[0]; y1 = oy + a[1]; x2 = ox + a[2]; y2 = oy + a[3]; }
            else {
                x1 = cx; y1 = cy;
                if (strchr("QqTt", prev)) { x1 = 2 * cx - qx; y1 = 2 * cy - qy; }
                x2 = ox + a[0]; y2 = oy + a[1];
            }
            /* quadratic as cubic */
            cubic(cx, cy, cx + 2.0 / 3 * (x1 - cx), cy + 2.0 / 3 * (y1 - cy), x2 + 2.0 / 3 * (x1 - x2),
                  y2 + 2.0 / 3 * (y1 - y2), x2, y2, tol, 0);
            qx = x1; qy = y1; cx = x2; cy = y2;
            break;
        }
        case 'A':
            arc(cx, cy, a[0], a[1], a[2], fl[0], fl[1], ox + a[5], oy + a[6], tol);
            cx = ox + a[5]; cy = oy + a[6];
            break;
        case 'Z':
            finish();
            cx = sx; cy = sy;
            break;
        }
        prev = cmd;
    }
    finish();
    return 0;
}

static int points_attr(const char *s)
{
    const char *p = s;
    double x, y;
    for (;;) {
        p = skipsep(p);
        if (!*p) break;
        if (number(&p, &x) < 0 || number(&p, &y) < 0) return cm_seterr("points: expected pairs of numbers");
        addpt(x, y);
    }
    finish();
    return 0;
}

/* value of attribute name inside the tag [tag, end), malloc'd, or NULL */
static char *attr(const char *tag, const char *end, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = tag; p + n + 1 < end; p++) {
        if ((p == tag || isspace((unsigned char)p[-1])) && !strncmp(p, name, n)) {
            const char *q = p + n;
            while (q < end && isspace((unsigned char)*q)) q++;
            if (q >= end || *q != '=') continue;
            q++;
            while (q < end && isspace((unsigned char)*q)) q++;
            if (q >= end || (*q != '"' && *q != '\'')) continue;
            char quote = *q++;
            const char *e = memchr(q, quote, end - q);
            if (!e) return NULL;
            char *v = malloc(e - q + 1);
            memcpy(v, q, e - q);
            v[e - q] = 0;
            return v;
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    fname = (!o.input || !strcmp(o.input, "-")) ? "<stdin>" : o.input;
    FILE *f = (!o.input || !strcmp(o.input, "-")) ? stdin : fopen(o.input, "r");
    if (!f) die("cannot read '%s': %s", fname, strerror(errno));
    size_t cap = 1 << 16, len = 0, n;
    char *buf = malloc(cap);
    while ((n = fread(buf + len, 1, cap - len - 1, f)) > 0) {
        len += n;
        if (len + 1 == cap) buf = realloc(buf, cap *= 2);
    }
    if (ferror(f)) die("cannot read '%s': %s", fname, strerror(errno));
    buf[len] = 0;
    if (f != stdin) fclose(f);
    if (!strstr(buf, "<svg")) die("cannot read '%s': line 1: not an SVG file (no <svg> element)", fname);
    memset(&out, 0, sizeof out);
    int elements = 0;
    long line = 1;
    const char *lp = buf;
    for (const char *p = buf; (p = strchr(p, '<')) != NULL; p++) {
        for (; lp < p; lp++) if (*lp == '\n') line++;
        int is_path = !strncmp(p, "<path", 5) && (isspace((unsigned char)p[5]) || p[5] == '/');
        int is_poly = !strncmp(p, "<polygon", 8) && isspace((unsigned char)p[8]);
        if (!is_path && !is_poly) continue;
        const char *end = strchr(p, '>');
        if (!end) die("cannot read '%s': line %ld: unterminated element", fname, line);
        cur_line = line;
        char *v = attr(p, end, is_path ? "d" : "points");
        if (!v) continue;
        int rc = is_path ? path_data(v, o.tol) : points_attr(v);
        free(v);
        if (rc < 0) die("cannot read '%s': line %ld: %s", fname, line, cm_errmsg());
        elements++;
    }
    if (out.nrings == 0) die("cannot read '%s': line %ld: no closed outline in any <path> or <polygon>", fname, line);
    if (!o.noflip)
        for (int i = 0; i < out.start[out.nrings]; i++) out.P[2 * i + 1] = 0.0 - out.P[2 * i + 1];   /* 0 - 0 is +0: no "-0" */
    /* a subpath whose points are all on one line (e.g. "M512 72.3 V71.7
     * Z") fills nothing: dropped, and said */
    int R = 0, *order = malloc(out.nrings * sizeof *order);
    for (int k = 0; k < out.nrings; k++)
        if (!rings_collinear(&out, k)) order[R++] = k;
    if (R == 0)
        die("cannot read '%s': line %ld: no closed outline encloses any area (every subpath lies on a line)", fname,
            ring_line[0]);
    for (int k = 0; k < out.nrings; k++)
        if (rings_collinear(&out, k))
            warn("'%s': line %ld: dropped a subpath of %d points on one line (it encloses no area, draws nothing)",
                 fname, ring_line[k], rings_count(&out, k));
    /* order: largest |area| first; orientation: outer CCW, rings inside it CW */
    double *area = malloc(out.nrings * sizeof *area);
    for (int k = 0; k < out.nrings; k++) area[k] = fabs(rings_area(&out, k));
    for (int a = 1; a < R; a++)
        for (int b = a; b > 0 && area[order[b]] > area[order[b - 1]]; b--) { int t = order[b]; order[b] = order[b - 1]; order[b - 1] = t; }
    struct rings sorted;
    memset(&sorted, 0, sizeof sorted);
    snprintf(sorted.name, sizeof sorted.name, "%s", fname);
    for (int k = 0; k < R; k++) {
        int r = order[k];
        rings_append(&sorted, rings_ring(&out, r), rings_count(&out, r));
        for (int i = 0; i < rings_count(&out, r); i++) sorted.line[sorted.start[k] + i] = ring_line[r];
    }
    for (int k = 0; k < R; k++) {
        double a = rings_area(&sorted, k);
        int hole = 0;   /* inside an odd number of larger rings */
        for (int j = 0; j < k; j++)
            hole ^= point_in_ring(rings_ring(&sorted, j), rings_count(&sorted, j), rings_ring(&sorted, k));
        if ((hole && a > 0) || (!hole && a < 0)) {
            double *P = rings_ring(&sorted, k);
            int m = rings_count(&sorted, k);
            for (int i = 0, j = m - 1; i < j; i++, j--) {
                double t0 = P[2 * i], t1 = P[2 * i + 1];
                P[2 * i] = P[2 * j]; P[2 * i + 1] = P[2 * j + 1]; P[2 * j] = t0; P[2 * j + 1] = t1;
            }
        }
    }
    if (rings_check_simple(&sorted) < 0) die("%s", cm_errmsg());
    info(1, "%d elements, %d rings, %d points", elements, sorted.nrings, sorted.start[sorted.nrings]);
    FILE *fo = out_open(o.output);
    if (rings_write(fo, &sorted) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(fo);
    rings_free(&sorted); rings_free(&out);
    free(order); free(area); free(buf); free(pts); free(ring_line);
    return 0;
}
