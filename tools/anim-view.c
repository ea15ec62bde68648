/* anim-view -- one self-contained HTML page to review animations of one
 * connectivity side by side in a browser: synchronized views, play/pause,
 * frame slider, shared orbit camera, part colours, per-vertex error against
 * a reference, the piece mounted in every frame with the library as
 * thumbnails, scans under registered poses.
 *
 * The page embeds everything: positions quantised to 16 bits over each
 * animation's bounding box, differenced between frames and deflated
 * (anim_pack.h), base64 in the HTML; three.js built into this program
 * (web_assets.h) and inlined as data: URLs in an import map.  Nothing is
 * fetched when the page is opened.
 */
#include "anim_pack.h"
#include "base64.h"
#include "cm_error.h"
#include "columns.h"
#include "colormap.h"
#include "mesh.h"
#include "raster.h"
#include "meshcolor.h"
#include "tool.h"
#include "web_assets.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: anim-view [options] ANIM.mesh... > review.html\n"
"Write one self-contained HTML page showing the animations (same vertices and\n"
"triangles, same frame count) side by side in synchronized views: play/pause,\n"
"frame slider, frame and clip number, one orbit camera for all views, keys\n"
"Left/Right step a frame, Space plays; '#frame=N' in the URL opens frame N.\n"
"Naming a file twice shows it twice but stores it once.\n"
"\n"
"Options:\n"
"  -o, --output FILE     write the page to FILE (default: standard output)\n"
"  -t, --titles LIST     comma separated view titles (default: the file names)\n"
"      --title TEXT      page title (default: stopmo review)\n"
"  -l, --labels FILE     part labels (one per face, or per vertex): colour views\n"
"                        by part (views not coloured by --error)\n"
"      --error REF       colour views by each vertex's distance to the same\n"
"                        vertex of REF (an animation of the same mesh)\n"
"      --error-views LIST  1-based views coloured by error (default: every view\n"
"                        whose file is not REF)\n"
"      --print-height MM  error legend also in millimetres for a print whose\n"
"                        REF is MM tall along --axis (over all frames)\n"
"      --axis x|y|z      height axis for --print-height (default y)\n"
"      --error-max E|pN  top of the error colour scale: E model units, or the\n"
"                        N-th percentile of all errors shown (e.g. p99; larger\n"
"                        errors take the top colour); default: the largest\n"
"      --pieces LABELS[:LIB]  per-frame piece labels of one part (dict-learn\n"
"                        --labels-out); with LIB (its library, one piece per\n"
"                        frame) the library is shown as thumbnails; repeat\n"
"                        once per part\n"
"      --part-names LIST  names of the --pieces parts (default part 0, ...)\n"
"      --scan FRAME:FILE  a scan (any connectivity, one frame) shown at FRAME\n"
"                        (0-based) under the views, wireframe or transparent;\n"
"                        repeat per scan (E-StopMotion review)\n"
"  -a, --azimuth DEG     starting camera azimuth around the up axis (0 = front)\n"
"  -e, --elevation DEG   starting camera elevation (default 0; drag to orbit)\n"
"      --up AXIS         world up axis: x, y, z, -x, -y or -z (default y)\n"
"      --fps N           playback rate (default 24)\n"
"  -v, --verbose         report sizes and the quantisation error on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: anim-view -t input,stop-motion,error --error in.mesh --error-views 3 \\\n"
"           --print-height 40 -o review.html in.mesh stopmo.mesh stopmo.mesh\n";

#define MAXV 64

struct anim {
    const char *path;
    struct mesh m;
    double lo[3], hi[3], qerr;
};

struct options {
    const char *output, *title, *labels, *error, *part_names;
    char *titles[MAXV];
    int ntitles;
    int *error_views, nerror_views;
    double print_height, error_max, error_pct, fps, azimuth, elevation;
    int axis, up;
    const char *pieces[MAXV];
    int npieces;
    const char *scans[MAXV];
    int nscans;
};

static int split_commas(char *s, char **out, int max)
{
    int n = 0;
    for (char *p = s; n < max;) {
        out[n++] = p;
        char *c = strchr(p, ',');
        if (!c) break;
        *c = 0;
        p = c + 1;
    }
    return n;
}

static void parse_args(int argc, char **argv, struct options *o, const char ***files, int *nfiles)
{
    static const struct option lo[] = {
        {"output", 1, 0, 'o'}, {"titles", 1, 0, 't'}, {"title", 1, 0, 'T'},
        {"labels", 1, 0, 'l'}, {"error", 1, 0, 'r'}, {"error-views", 1, 0, 'E'},
        {"print-height", 1, 0, 'H'}, {"axis", 1, 0, 'X'}, {"error-max", 1, 0, 'M'},
        {"pieces", 1, 0, 'p'}, {"part-names", 1, 0, 'P'}, {"scan", 1, 0, 's'},
        {"fps", 1, 0, 'f'}, {"azimuth", 1, 0, 'a'}, {"elevation", 1, 0, 'e'}, {"up", 1, 0, 'U'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->title = "stopmo review";
    o->fps = 24;
    o->axis = 1;
    o->up = 1;
    int c;
    while ((c = getopt_long(argc, argv, "o:t:l:a:e:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'o': o->output = optarg; break;
        case 't': o->ntitles = split_commas(optarg, o->titles, MAXV); break;
        case 'T': o->title = optarg; break;
        case 'l': o->labels = optarg; break;
        case 'r': o->error = optarg; break;
        case 'E': o->nerror_views = arg_intlist(optarg, "--error-views", &o->error_views); break;
        case 'H': o->print_height = arg_double(optarg, "--print-height");
            if (!(o->print_height > 0)) usage_error("--print-height must be positive");
            break;
        case 'X':
            if (strlen(optarg) != 1 || !strchr("xyz", optarg[0])) usage_error("--axis must be x, y or z");
            o->axis = optarg[0] - 'x';
            break;
        case 'M':
            if (optarg[0] == 'p') {
                o->error_pct = arg_double(optarg + 1, "--error-max percentile");
                if (!(o->error_pct > 0 && o->error_pct <= 100))
                    usage_error("--error-max pN wants a percentile N in (0, 100]");
                break;
            }
            o->error_max = arg_double(optarg, "--error-max");
            if (!(o->error_max > 0)) usage_error("--error-max must be positive");
            break;
        case 'p':
            if (o->npieces == MAXV) usage_error("at most %d --pieces", MAXV);
            o->pieces[o->npieces++] = optarg;
            break;
        case 'P': o->part_names = optarg; break;
        case 's':
            if (o->nscans == MAXV) usage_error("at most %d --scan", MAXV);
            o->scans[o->nscans++] = optarg;
            break;
        case 'f': o->fps = arg_double(optarg, "--fps");
            if (!(o->fps > 0 && o->fps <= 240)) usage_error("--fps must be in (0, 240]");
            break;
        case 'a': o->azimuth = arg_double(optarg, "--azimuth"); break;
        case 'e': o->elevation = arg_double(optarg, "--elevation");
            if (fabs(o->elevation) > 90) usage_error("--elevation must be in [-90, 90]");
            break;
        case 'U': {
            static const char *axes[] = {"x", "y", "z", "-x", "-y", "-z"};
            o->up = -1;
            for (int i = 0; i < 6; i++)
                if (!strcmp(optarg, axes[i])) o->up = i;
            if (o->up < 0) usage_error("--up must be x, y, z, -x, -y or -z");
            break;
        }
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    *nfiles = argc - optind;
    *files = (const char **)argv + optind;
    if (*nfiles < 1) usage_error("expected at least one MESH stream");
    if (*nfiles > MAXV) usage_error("at most %d views", MAXV);
    if (o->ntitles && o->ntitles != *nfiles)
        usage_error("--titles names %d views, but there are %d", o->ntitles, *nfiles);
    if ((o->nerror_views || o->print_height > 0 || o->error_max > 0 || o->error_pct > 0) && !o->error)
        usage_error("--error-views, --print-height and --error-max need --error");
    for (int i = 0; i < o->nerror_views; i++)
        if (o->error_views[i] < 1 || o->error_views[i] > *nfiles)
            usage_error("--error-views: view %d does not exist (1..%d)", o->error_views[i], *nfiles);
    if (o->part_names && !o->npieces) usage_error("--part-names needs --pieces");
    int nstdin = o->error && !strcmp(o->error, "-");
    nstdin += o->labels && !strcmp(o->labels, "-");
    for (int i = 0, seen = 0; i < *nfiles; i++)
        if (!strcmp((*files)[i], "-") && !seen++) nstdin++;
    if (nstdin > 1) usage_error("only one input can be standard input");
}

/* ---- writing the page ---- */

static FILE *out;

static void put(const char *s) { fputs(s, out); }

static void put_n(const void *p, size_t n)
{
    if (n && fwrite(p, 1, n, out) != n) die("cannot write output");
}

/* a JSON string; '<' escaped so that no '</script' can close the element */
static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(f, "\\%c", *p);
        else if (*p < 0x20 || *p == '<' || *p == '>' || *p == '&') fprintf(f, "\\u%04x", *p);
        else fputc(*p, f);
    }
    fputc('"', f);
}

static void put_html_text(const char *s)
{
    for (; *s; s++) {
        if (*s == '<') put("&lt;");
        else if (*s == '>') put("&gt;");
        else if (*s == '&') put("&amp;");
        else fputc(*s, out);
    }
}


static int nblobs;
static size_t blob_bytes;

/* deflate n bytes into a <script type=application/octet-stream> element;
 * writes "{"blob":"bK","bytes":n}" into the meta JSON buffer */
struct blob { unsigned char *z; size_t zn, n; };
static struct blob blobs[4 * MAXV + 8];

static void json_blob(FILE *meta, const void *data, size_t n)
{
    if (nblobs == (int)(sizeof blobs / sizeof *blobs)) die("too many data arrays");
    struct blob *b = &blobs[nblobs];
    if (anim_pack_deflate(data, n, &b->z, &b->zn) < 0) die("%s", cm_errmsg());
    b->n = n;
    blob_bytes += base64_len(b->zn);
    fprintf(meta, "{\"blob\":\"b%d\",\"bytes\":%zu}", nblobs++, n);
}

static void json_vec3(FILE *meta, const double v[3])
{
    fprintf(meta, "[%.17g,%.17g,%.17g]", v[0], v[1], v[2]);
}

static void json_faces(FILE *meta, const struct mesh *m)
{
    int32_t *F = malloc((size_t)m->nf * 3 * sizeof *F + 1);
    if (!F) die("out of memory");
    for (size_t i = 0; i < (size_t)m->nf * 3; i++) F[i] = m->F[i];   /* int32, little-endian host */
    json_blob(meta, F, (size_t)m->nf * 3 * sizeof *F);
    free(F);
}

/* positions of a whole mesh: bbox, quantised, packed */
static void json_positions(FILE *meta, struct anim *a)
{
    size_t np = (size_t)a->m.nframes * a->m.nv;
    anim_pack_bbox(a->m.V, np, a->lo, a->hi);
    unsigned char *P = malloc(np * 6 + 1);
    if (!P) die("out of memory");
    anim_pack_positions(a->m.V, a->m.nframes, a->m.nv, a->lo, a->hi, P, &a->qerr);
    fprintf(meta, "\"nv\":%d,\"nframes\":%d,\"lo\":", a->m.nv, a->m.nframes);
    json_vec3(meta, a->lo);
    fputs(",\"hi\":", meta);
    json_vec3(meta, a->hi);
    fprintf(meta, ",\"quant_error\":%.6g,\"pos\":", a->qerr);
    json_blob(meta, P, np * 6);
    free(P);
}

static const struct web_asset *asset(const char *name)
{
    const struct web_asset *a = web_asset(name);
    if (!a) die("internal: no built-in asset '%s'", name);
    return a;
}

/* copy the template up to (not including) the marker; advance *pos past it */
static void put_template_until(const struct web_asset *t, size_t *pos, const char *marker)
{
    const char *s = (const char *)t->data + *pos;
    size_t left = t->size - *pos, ml = strlen(marker);
    for (size_t i = 0; i + ml <= left; i++)
        if (!memcmp(s + i, marker, ml)) {
            put_n(s, i);
            *pos += i + ml;
            return;
        }
    die("internal: the page template has no %s", marker);
}

static void put_data_url(const char *name)
{
    const struct web_asset *a = asset(name);
    put("\"data:text/javascript;base64,");
    if (base64_write(out, a->data, a->size) < 0) die("cannot write output");
    put("\"");
}

/* ---- reading ---- */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int find_anim(struct anim *A, int n, const char *path)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(A[i].path, path)) return i;
    return -1;
}

static int load_anim(struct anim *A, int *n, const char *path)
{
    int i = find_anim(A, *n, path);
    if (i >= 0) return i;
    A[*n].path = path;
    if (mesh_read(path, &A[*n].m) < 0) die("%s", cm_errmsg());
    return (*n)++;
}

static const char *shown_name(const char *path)
{
    if (!strcmp(path, "-")) return "<stdin>";
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    const char **files;
    int nfiles;
    parse_args(argc, argv, &o, &files, &nfiles);
    const char *missing = web_asset_missing();
    if (missing) die("%s", missing);

    /* every animation, once; views point at them */
    static struct anim A[MAXV + 1];
    int na = 0, view_anim[MAXV];
    for (int i = 0; i < nfiles; i++) view_anim[i] = load_anim(A, &na, files[i]);
    int ref = o.error ? load_anim(A, &na, o.error) : -1;
    const struct mesh *m0 = &A[0].m;
    for (int i = 1; i < na; i++) {
        const struct mesh *m = &A[i].m;
        if (m->nv != m0->nv || m->nf != m0->nf)
            die("cannot show '%s' (%d vertices, %d faces) beside '%s' (%d vertices, %d faces): "
                "one connectivity is needed", A[i].path, m->nv, m->nf, A[0].path, m0->nv, m0->nf);
        if (memcmp(m->F, m0->F, (size_t)m->nf * 3 * sizeof *m->F))
            die("cannot show '%s' beside '%s': same counts but different triangles", A[i].path,
                A[0].path);
        if (m->nframes != m0->nframes)
            die("cannot show '%s' (%d frames) beside '%s' (%d frames): the views play in step",
                A[i].path, m->nframes, A[0].path, m0->nframes);
    }
    int nframes = m0->nframes;

    /* error views and the error's range */
    int is_error_view[MAXV] = {0};
    double err_max = 0, err_sum = 0, scale_mm = 0, scale_top = 0;
    if (ref >= 0) {
        if (o.nerror_views)
            for (int i = 0; i < o.nerror_views; i++) is_error_view[o.error_views[i] - 1] = 1;
        else
            for (int i = 0; i < nfiles; i++) is_error_view[i] = view_anim[i] != ref;
        long cnt = 0;
        double *all = NULL;   /* every distance shown, for --error-max pN */
        size_t nall = 0;
        if (o.error_pct > 0) {
            int k = 0;
            for (int i = 0; i < nfiles; i++) k += is_error_view[i];
            all = malloc(((size_t)k * nframes * m0->nv + 1) * sizeof *all);
            if (!all) die("out of memory");
        }
        for (int i = 0; i < nfiles; i++) {
            if (!is_error_view[i]) continue;
            const struct mesh *a = &A[view_anim[i]].m, *r = &A[ref].m;
            for (size_t j = 0; j < (size_t)nframes * a->nv; j++) {
                const double *x = a->V + 3 * j, *y = r->V + 3 * j;
                double d = sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                                (x[2] - y[2]) * (x[2] - y[2]));
                err_sum += d;
                if (d > err_max) err_max = d;
                if (all) all[nall++] = d;
                cnt++;
            }
        }
        if (cnt) err_sum /= cnt;
        if (all) {
            if (nall) {
                qsort(all, nall, sizeof *all, cmp_double);
                /* nearest rank */
                size_t r = (size_t)ceil(o.error_pct / 100 * nall);
                scale_top = all[r ? r - 1 : 0];
            }
            free(all);
        }
        if (o.error_max > 0) scale_top = o.error_max;
        else if (!(scale_top > 0)) scale_top = err_max;
        if (o.print_height > 0) {
            double lo = INFINITY, hi = -INFINITY;
            const struct mesh *r = &A[ref].m;
            for (size_t j = 0; j < (size_t)nframes * r->nv; j++) {
                double y = r->V[3 * j + o.axis];
                if (y < lo) lo = y;
                if (y > hi) hi = y;
            }
            if (!(hi > lo))
                die("cannot read '%s': the reference has zero height along %c, --print-height cannot "
                    "scale it", o.error, 'x' + o.axis);
            scale_mm = o.print_height / (hi - lo);
        }
    }

    /* part colours */
    struct mesh_colors mc = {0};
    if (o.labels && mesh_colors_labels(o.labels, m0->nv, m0->nf, &mc) < 0) die("%s", cm_errmsg());

    /* pieces: labels per frame, optional library */
    struct piece { int *L, n; struct anim lib; int has_lib; char *name; } P[MAXV];
    char *names[MAXV];
    int nnames = 0;
    char *part_names = o.part_names ? strdup(o.part_names) : NULL;
    if (part_names) nnames = split_commas(part_names, names, MAXV);
    if (part_names && nnames != o.npieces)
        usage_error("--part-names names %d parts, but there are %d --pieces", nnames, o.npieces);
    for (int p = 0; p < o.npieces; p++) {
        char *spec = strdup(o.pieces[p]), *colon = strchr(spec, ':');
        P[p].has_lib = colon != NULL;
        if (colon) {
            *colon = 0;
            P[p].lib.path = colon + 1;
            if (mesh_read(colon + 1, &P[p].lib.m) < 0) die("%s", cm_errmsg());
        }
        int hi = P[p].has_lib ? P[p].lib.m.nframes - 1 : -1;
        if (labels_read(spec, nframes, "frames", 0, hi, &P[p].L, &P[p].n) < 0) die("%s", cm_errmsg());
        P[p].name = nnames ? names[p] : NULL;
    }

    /* scans */
    struct scan { int frame; struct anim a; } S[MAXV];
    for (int s = 0; s < o.nscans; s++) {
        char *spec = strdup(o.scans[s]), *colon = strchr(spec, ':');
        if (!colon) usage_error("--scan wants FRAME:FILE, not '%s'", o.scans[s]);
        *colon = 0;
        long k = arg_long(spec, "--scan frame");
        if (k < 0 || k >= nframes) usage_error("--scan frame %ld is not in 0..%d", k, nframes - 1);
        S[s].frame = (int)k;
        S[s].a.path = colon + 1;
        if (mesh_read(colon + 1, &S[s].a.m) < 0) die("%s", cm_errmsg());
        if (S[s].a.m.nframes != 1)
            die("cannot read '%s': a scan is one frame, this has %d", colon + 1, S[s].a.m.nframes);
    }

    /* the meta data (JSON) and the data arrays, built before any output */
    char *metabuf = NULL;
    size_t metalen = 0;
    FILE *meta = open_memstream(&metabuf, &metalen);
    if (!meta) die("out of memory");
    fputs("{\"version\":1,\"title\":", meta);
    json_string(meta, o.title);
    fprintf(meta, ",\"fps\":%.17g,\"nv\":%d,\"nf\":%d,\"nframes\":%d,\"cuts\":[", o.fps, m0->nv,
            m0->nf, nframes);
    for (int k = 0, first = 1; k < nframes; k++)
        if (k == 0 || m0->cut[k]) fprintf(meta, "%s%d", first ? "" : ",", k), first = 0;
    fputs("],\"faces\":", meta);
    json_faces(meta, m0);
    fputs(",\"anims\":[", meta);
    double qworst = 0;
    for (int i = 0; i < na; i++) {
        fputs(i ? ",{\"name\":" : "{\"name\":", meta);
        json_string(meta, shown_name(A[i].path));
        fputc(',', meta);
        json_positions(meta, &A[i]);
        double diag = 131070 * anim_pack_bound(A[i].lo, A[i].hi);
        fprintf(meta, ",\"diag\":%.17g}", diag);
        if (A[i].qerr / diag > qworst) qworst = A[i].qerr / diag;
        info(1, "'%s': quantisation error %.3g (%.3g of the bounding box diagonal %.6g; bound %.3g)",
             A[i].path, A[i].qerr, A[i].qerr / diag, diag, anim_pack_bound(A[i].lo, A[i].hi));
    }
    fputs("],\"views\":[", meta);
    for (int i = 0; i < nfiles; i++) {
        fputs(i ? ",{\"title\":" : "{\"title\":", meta);
        json_string(meta, o.ntitles ? o.titles[i] : shown_name(files[i]));
        fprintf(meta, ",\"anim\":%d,\"colour\":\"%s\"}", view_anim[i],
                is_error_view[i] ? "error" : o.labels ? "labels" : "plain");
    }
    fputc(']', meta);
    if (o.labels) {
        fprintf(meta, ",\"labels\":{\"per_face\":%d,\"count\":%d,\"rgb\":", mc.per_face, mc.nlabels);
        json_blob(meta, mc.rgb, (size_t)mc.n * 3);
        fputc('}', meta);
    }
    if (ref >= 0) {
        unsigned char lut[256 * 3];
        colormap_viridis_table(lut);
        fprintf(meta, ",\"error\":{\"ref\":%d,\"ref_name\":", ref);
        json_string(meta, shown_name(o.error));
        fprintf(meta, ",\"max\":%.17g,\"mean\":%.17g,\"scale_max\":%.17g,\"print_height\":%.17g,"
                "\"mm_per_unit\":%.17g,\"axis\":\"%c\",\"percentile\":%.17g,\"lut\":[", err_max,
                err_sum, scale_top, o.print_height, scale_mm, 'x' + o.axis, o.error_pct);
        for (int i = 0; i < 256 * 3; i++) fprintf(meta, "%s%d", i ? "," : "", lut[i]);
        fputs("]}", meta);
    }
    if (o.npieces) {
        fputs(",\"pieces\":[", meta);
        for (int p = 0; p < o.npieces; p++) {
            fputs(p ? ",{\"name\":" : "{\"name\":", meta);
            char dflt[32];
            snprintf(dflt, sizeof dflt, "part %d", p);
            json_string(meta, P[p].name ? P[p].name : dflt);
            fputs(",\"labels\":[", meta);
            for (int k = 0; k < P[p].n; k++) fprintf(meta, "%s%d", k ? "," : "", P[p].L[k]);
            fputc(']', meta);
            if (P[p].has_lib) {
                fputs(",\"lib\":{\"faces\":", meta);
                json_faces(meta, &P[p].lib.m);
                fprintf(meta, ",\"nf\":%d,", P[p].lib.m.nf);
                json_positions(meta, &P[p].lib);
                fputc('}', meta);
            }
            fputc('}', meta);
        }
        fputc(']', meta);
    }
    if (o.nscans) {
        fputs(",\"scans\":[", meta);
        for (int s = 0; s < o.nscans; s++) {
            fprintf(meta, "%s{\"frame\":%d,\"name\":", s ? "," : "", S[s].frame);
            json_string(meta, shown_name(S[s].a.path));
            fprintf(meta, ",\"nf\":%d,\"faces\":", S[s].a.m.nf);
            json_faces(meta, &S[s].a.m);
            fputc(',', meta);
            json_positions(meta, &S[s].a);
            fputc('}', meta);
        }
        fputc(']', meta);
    }
    struct camera cam;
    camera_init(&cam, o.azimuth, o.elevation, o.up);
    fprintf(meta, ",\"camera\":{\"up\":[%.17g,%.17g,%.17g],\"towards\":[%.17g,%.17g,%.17g]}",
            cam.R[3], cam.R[4], cam.R[5], cam.R[6], cam.R[7], cam.R[8]);
    fprintf(meta, ",\"quant_error_rel\":%.6g,\"three\":\"", qworst);
    const struct web_asset *tv = asset("three.version");
    for (size_t i = 0; i < tv->size; i++)
        if (tv->data[i] > ' ' && tv->data[i] != '"' && tv->data[i] != '\\') fputc(tv->data[i], meta);
    fputs("\"}", meta);
    if (fclose(meta) != 0) die("out of memory");

    /* the page */
    out = out_open(o.output);
    const struct web_asset *t = asset("anim-view.html");
    size_t pos = 0;
    put_template_until(t, &pos, "<!--STOPMO:TITLE-->");
    put_html_text(o.title);
    put_template_until(t, &pos, "<!--STOPMO:IMPORTMAP-->");
    put("<script type=\"importmap\">{\"imports\":{\"three\":");
    put_data_url("three.module.js");
    put(",\n\"three-core\":");
    put_data_url("three.core.js");
    put(",\n\"three/addons/controls/OrbitControls.js\":");
    put_data_url("OrbitControls.js");
    put("}}</script>");
    put_template_until(t, &pos, "<!--STOPMO:DATA-->");
    put("<script type=\"application/json\" id=\"stopmo-meta\">");
    put_n(metabuf, metalen);
    put("</script>\n");
    for (int b = 0; b < nblobs; b++) {
        fprintf(out, "<script type=\"application/octet-stream\" id=\"b%d\">", b);
        if (base64_write(out, blobs[b].z, blobs[b].zn) < 0) die("cannot write output");
        put("</script>\n");
    }
    put_template_until(t, &pos, "<!--STOPMO:SCRIPT-->");
    put("<script type=\"module\">\n");
    const struct web_asset *js = asset("anim-view.js");
    put_n(js->data, js->size);
    put("</script>");
    put_n(t->data + pos, t->size - pos);
    info(1, "%d views of %d vertices x %d frames; %d animations stored; data %.1f MB of base64, "
         "worst quantisation error %.3g of the diagonal", nfiles, m0->nv, nframes, na,
         blob_bytes / 1e6, qworst);
    out_close(out);
    return 0;
}
