/* mesh-metrics -- per-frame distances and distortions of an animation
 * against a reference mesh: symmetric Hausdorff and RMS surface distance
 * (any connectivity), flipped faces, and, when the connectivity matches,
 * the relative area and volume distortion of thesis Eq. 3.6.
 */
#include "buried.h"
#include "closest_point.h"
#include "distortion.h"
#include "geometry.h"
#include "mesh.h"
#include "mesh_distance.h"
#include "progress.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: mesh-metrics [options] -r REFERENCE [ANIM]\n"
"For every frame of ANIM, one row of metrics against frame 0 of REFERENCE:\n"
"  frame hausdorff hausdorff_rel rms flipped\n"
"and when ANIM has the reference's connectivity also\n"
"  volume_rel area_mean area_sigma vol_mean vol_sigma edge_max area_abs\n"
"and last, the two one-sided distances over the diagonal\n"
"  fit_rel cover_rel\n"
"and with --buried\n"
"  buried flipped_buried cover_clear_rel\n"
"(hausdorff_rel: over the reference's bounding-box diagonal; see mesh-metrics(1)).\n"
"\n"
"Options:\n"
"  -r, --reference FILE  the reference mesh (required)\n"
"      --ref-frame K     use frame K of the reference (default 0)\n"
"      --no-header       omit the '# frame ...' header line\n"
"      --per-face FILE   write one row per face and frame to FILE:\n"
"                        frame face flipped distance distance_rel (the largest\n"
"                        distance of the face's samples to the reference; _rel:\n"
"                        over the diagonal), for mesh-render --color\n"
"      --buried          the reference's own defects apart: its buried faces (front\n"
"                        inside its own volume: parts of a scan passing through each\n"
"                        other), the flipped faces on them or one ring around, and\n"
"                        the cover distance of the reference's other samples\n"
"  -o, --output FILE     write to FILE (atomically) instead of stdout\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: arap-interp a.mesh b.mesh | mesh-metrics -r a.mesh\n";

struct options { const char *input, *ref, *output, *per_face; int ref_frame, no_header, buried; };

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"reference", 1, 0, 'r'}, {"ref-frame", 1, 0, 'K'}, {"no-header", 0, 0, 'N'},
        {"per-face", 1, 0, 'P'}, {"buried", 0, 0, 'B'},
        {"output", 1, 0, 'o'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "r:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'r': o->ref = optarg; break;
        case 'K': o->ref_frame = arg_int(optarg, "--ref-frame"); break;
        case 'N': o->no_header = 1; break;
        case 'P': o->per_face = optarg; break;
        case 'B': o->buried = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!o->ref) usage_error("missing -r REFERENCE");
    if (o->ref_frame < 0) usage_error("--ref-frame must be >= 0");
    if (argc - optind > 1) usage_error("expected at most one input");
    if (o->per_face && o->output && !strcmp(o->per_face, o->output))
        usage_error("--per-face and -o name the same file");
    o->input = optind < argc ? argv[optind] : "-";
}

/* growable text buffer: rows are printed only after the whole input was read */
struct text { char *s; size_t n, cap; };
static void text_add(struct text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
#include <stdarg.h>
static void text_add(struct text *t, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(t->s ? t->s + t->n : NULL, t->s ? t->cap - t->n : 0, fmt, ap);
        va_end(ap);
        if (t->s && t->n + k < t->cap) { t->n += k; return; }
        t->cap = 2 * (t->cap + k + 256);
        t->s = realloc(t->s, t->cap);
    }
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct mesh ref;
    if (mesh_read(o.ref, &ref) < 0) die("%s", cm_errmsg());
    if (o.ref_frame >= ref.nframes)
        die("cannot use '%s': --ref-frame %d but it has %d frames", o.ref, o.ref_frame, ref.nframes);
    const double *R = mesh_frame(&ref, o.ref_frame);
    struct frame_compare *C = frame_compare_new(R, ref.nv, ref.F, ref.nf);
    if (!C) die("cannot use '%s': %s", o.ref, cm_errmsg());
    double diag = bbox_diagonal(R, ref.nv);
    /* --buried: the reference's buried faces and one ring around them */
    int nburied = 0;
    if (o.buried) {
        unsigned char *zone = malloc((size_t)ref.nf + 1);
        double t0 = now_seconds();
        if (!zone || (nburied = buried_faces(R, ref.nv, ref.F, ref.nf, BURIED_OFFSET * diag, 1, 0, zone)) < 0 ||
            frame_compare_set_zone(C, zone) < 0)
            die("cannot use '%s': %s", o.ref, cm_errmsg());
        info(1, "%d buried faces of %d in '%s', %.2f s", nburied, ref.nf, o.ref, now_seconds() - t0);
        free(zone);
    }
    struct mesh_reader rd;
    if (mesh_reader_open(&rd, o.input) < 0) die("%s", cm_errmsg());
    int same = rd.nv == ref.nv && rd.nf == ref.nf &&
               !memcmp(rd.F, ref.F, (size_t)ref.nf * 3 * sizeof(int));
    double *X = malloc((size_t)rd.nv * 3 * sizeof *X + 1);
    double *ffit = o.per_face ? malloc((size_t)rd.nf * sizeof *ffit + 1) : NULL;
    unsigned char *flip = o.per_face ? malloc((size_t)rd.nf + 1) : NULL;
    struct text out = {0}, pf = {0};
    if (!o.no_header)
        text_add(&out, "# frame hausdorff hausdorff_rel rms flipped%s fit_rel cover_rel%s\n",
                 same ? " volume_rel area_mean area_sigma vol_mean vol_sigma edge_max area_abs" : "",
                 o.buried ? " buried flipped_buried cover_clear_rel" : "");
    if (o.per_face && !o.no_header) text_add(&pf, "# frame face flipped distance distance_rel\n");
    int rc;
    while ((rc = mesh_reader_next(&rd, X, NULL)) == 1) {
        int k = rd.frame - 1;
        /* one-sided both ways: the frame's samples to the reference (fit),
         * the reference's samples to the frame (cover) */
        struct frame_distance fd;
        if (frame_compare_run(C, X, rd.nv, rd.F, rd.nf, FLIP_THIN_TOL * diag, &fd, flip, ffit) < 0)
            die("%s: frame %d: %s", rd.name, k, cm_errmsg());
        double h = fd.fit.max > fd.cover.max ? fd.fit.max : fd.cover.max;
        double rms = sqrt((fd.fit.sumsq + fd.cover.sumsq) / (fd.fit.n + fd.cover.n));
        text_add(&out, "%d %.9g %.9g %.9g %d", k, h, diag > 0 ? h / diag : 0, rms, fd.flipped);
        if (same) {
            struct distortion d;
            mesh_distortion(R, X, ref.F, ref.nv, ref.nf, &d);
            text_add(&out, " %.9g %.9g %.9g %.9g %.9g %.9g %.9g", d.volume_rel, d.area_mean,
                     d.area_sigma, d.vol_mean, d.vol_sigma, d.edge_max, d.area_abs);
        }
        text_add(&out, " %.9g %.9g", diag > 0 ? fd.fit.max / diag : 0, diag > 0 ? fd.cover.max / diag : 0);
        if (o.buried)
            text_add(&out, " %d %d %.9g", nburied, fd.flipped_zone, diag > 0 ? fd.cover_clear / diag : 0);
        text_add(&out, "\n");
        for (int f = 0; o.per_face && f < rd.nf; f++)
            text_add(&pf, "%d %d %d %.9g %.9g\n", k, f, flip[f], ffit[f], diag > 0 ? ffit[f] / diag : 0);
    }
    if (rc < 0) die("%s", cm_errmsg());
    mesh_reader_close(&rd);
    /* both outputs open before either is renamed into place */
    FILE *g = o.per_face ? out_open(o.per_face) : NULL, *f = out_open(o.output);
    if (g && pf.n) fwrite(pf.s, 1, pf.n, g);
    if (out.n) fwrite(out.s, 1, out.n, f);
    if (g) out_close(g);
    out_close(f);
    free(out.s); free(pf.s);
    free(X); free(ffit); free(flip);
    frame_compare_free(C);
    mesh_free(&ref);
    return 0;
}
