/* part-join -- assemble one piece per part into one mesh.
 *
 * Each piece is a frame of a part stream written by part-split, with the
 * part's map file (the input vertex of each part vertex).  Vertices that
 * appear in several maps are seam vertices: their copies are merged (into
 * their average) and the largest distance between copies, the seam gap, is
 * reported.  After seam-homog the gap is zero for any mix of frames.
 */
#include "cm_error.h"
#include "columns.h"
#include "geometry.h"
#include "mesh.h"
#include "tool.h"
#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: part-join [options] MESH MAP [MESH MAP ...]\n"
"Assemble one piece per part (a frame of each part stream written by\n"
"part-split, with its map file) into one mesh; vertices shared by several\n"
"parts (the seams) are merged, and the largest gap between their copies is\n"
"checked.\n"
"\n"
"Options:\n"
"  -f, --frame LIST      frame of each piece: one number for all pieces, or a\n"
"                        comma separated list with one per piece (default 0)\n"
"  -o, --output FILE     write the mesh to FILE (default stdout)\n"
"  -t, --tolerance T     allowed seam gap, relative to the bounding-box\n"
"                        diagonal (default 1e-9)\n"
"      --strict          a seam gap above the tolerance is an error (exit 1)\n"
"      --raw             write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose         vertex counts and the seam gap on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: part-join -f 3,17 part_0.mesh part_0.map part_1.mesh part_1.map > mix.mesh\n";

struct options {
    int npieces, nframesel, raw, strict;
    char **mesh, **map;
    int *frame;
    const char *output;
    double tol;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frame", 1, 0, 'f'}, {"output", 1, 0, 'o'}, {"tolerance", 1, 0, 't'},
        {"strict", 0, 0, 'S'}, {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->tol = 1e-9;
    const char *frames = NULL;
    int c;
    while ((c = getopt_long(argc, argv, "f:o:t:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'f': frames = optarg; break;
        case 'o': o->output = optarg; break;
        case 't': o->tol = arg_double(optarg, "--tolerance"); break;
        case 'S': o->strict = 1; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    int n = argc - optind;
    if (n < 2 || n % 2)
        usage_error("expected pairs of MESH MAP files");
    o->npieces = n / 2;
    o->mesh = malloc(o->npieces * sizeof *o->mesh);
    o->map = malloc(o->npieces * sizeof *o->map);
    int stdin_uses = 0;
    for (int i = 0; i < o->npieces; i++) {
        o->mesh[i] = argv[optind + 2 * i];
        o->map[i] = argv[optind + 2 * i + 1];
        stdin_uses += !strcmp(o->mesh[i], "-") + !strcmp(o->map[i], "-");
    }
    if (stdin_uses > 1)
        usage_error("only one input can come from standard input");
    o->frame = calloc(o->npieces, sizeof *o->frame);
    if (frames) {
        int *l, k = arg_intlist(frames, "--frame", &l);
        if (k != 1 && k != o->npieces)
            usage_error("--frame: %d numbers for %d pieces (give one, or one per piece)", k,
                        o->npieces);
        for (int i = 0; i < o->npieces; i++) {
            o->frame[i] = l[k == 1 ? 0 : i];
            if (o->frame[i] < 0) usage_error("--frame: frames are numbered from 0");
        }
        free(l);
    }
    if (!(o->tol >= 0))
        usage_error("--tolerance must be >= 0");
}

struct piece {
    int nv, nf;
    int *F;          /* nf by 3, piece numbering */
    double *X;       /* nv by 3, the selected frame */
    int *map;        /* nv: input vertex */
};

static void read_piece(const char *mesh, const char *map, int frame, struct piece *p)
{
    struct mesh_reader r;
    if (mesh_reader_open(&r, mesh) < 0)
        die("%s", cm_errmsg());
    p->nv = r.nv;
    p->nf = r.nf;
    p->X = malloc(((size_t)r.nv * 3 + 1) * sizeof *p->X);
    for (int k = 0; k <= frame; k++) {
        int rc = mesh_reader_next(&r, p->X, NULL);
        if (rc < 0)
            die("%s", cm_errmsg());
        if (rc == 0)
            die("cannot read '%s': no frame %d (the stream has %d)", r.name, frame, k);
    }
    p->F = r.F;
    r.F = NULL;
    mesh_reader_close(&r);
    int n;
    if (labels_read(map, p->nv, "vertices in its mesh", 0, -1, &p->map, &n) < 0)
        die("%s", cm_errmsg());
}

static int cmp_face(const void *a, const void *b)
{
    const int64_t *x = a, *y = b;
    for (int i = 0; i < 3; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    int np = o.npieces;
    struct piece *P = calloc(np, sizeof *P);
    int N = 0;
    for (int i = 0; i < np; i++) {
        read_piece(o.mesh[i], o.map[i], o.frame[i], &P[i]);
        for (int j = 0; j < P[i].nv; j++)
            if (P[i].map[j] + 1 > N) N = P[i].map[j] + 1;
    }

    /* inverse maps: inv[i][v] = piece vertex of input vertex v, or -1 */
    int **inv = malloc(np * sizeof *inv);
    int *copies = calloc((size_t)N + 1, sizeof *copies);
    for (int i = 0; i < np; i++) {
        inv[i] = malloc(((size_t)N + 1) * sizeof **inv);
        for (int v = 0; v < N; v++) inv[i][v] = -1;
        for (int j = 0; j < P[i].nv; j++) {
            int v = P[i].map[j];
            if (inv[i][v] >= 0)
                die("cannot read '%s': rows %d and %d both map to input vertex %d", o.map[i],
                    inv[i][v] + 1, j + 1, v);
            inv[i][v] = j;
            copies[v]++;
        }
    }

    /* output vertices: the used input vertices in increasing order, at the
     * average of their copies; the seam gap between copies */
    int *id = malloc(((size_t)N + 1) * sizeof *id);
    int nv = 0, nseam = 0;
    for (int v = 0; v < N; v++) {
        id[v] = copies[v] ? nv++ : -1;
        nseam += copies[v] > 1;
    }
    double *X = calloc((size_t)nv * 3 + 1, sizeof *X);
    double gap = 0;
    int gv = -1, gi = -1, gj = -1;
    for (int v = 0; v < N; v++) {
        if (!copies[v]) continue;
        double *x = X + 3 * (size_t)id[v];
        for (int i = 0; i < np; i++) {
            if (inv[i][v] < 0) continue;
            const double *a = P[i].X + 3 * (size_t)inv[i][v];
            for (int d = 0; d < 3; d++) x[d] += a[d] / copies[v];
            for (int j = i + 1; j < np; j++) {
                if (inv[j][v] < 0) continue;
                double g = dist3(a, P[j].X + 3 * (size_t)inv[j][v]);
                if (g > gap || gv < 0) { gap = g; gv = v; gi = i; gj = j; }
            }
        }
    }

    /* faces, and no triangle twice (two pieces of the same part) */
    int nf = 0;
    for (int i = 0; i < np; i++) nf += P[i].nf;
    int *F = malloc(((size_t)nf * 3 + 1) * sizeof *F);
    int64_t *key = malloc(((size_t)nf + 1) * 4 * sizeof *key);
    for (int i = 0, k = 0; i < np; i++)
        for (int f = 0; f < P[i].nf; f++, k++) {
            int64_t t[3];
            for (int c = 0; c < 3; c++) {
                int v = P[i].map[P[i].F[3 * f + c]];
                F[3 * k + c] = id[v];
                t[c] = v;
            }
            for (int a = 0; a < 2; a++)         /* sort the triple */
                for (int b = 0; b < 2 - a; b++)
                    if (t[b] > t[b + 1]) { int64_t s = t[b]; t[b] = t[b + 1]; t[b + 1] = s; }
            memcpy(key + 4 * (size_t)k, t, sizeof t);
            key[4 * (size_t)k + 3] = i;
        }
    qsort(key, nf, 4 * sizeof *key, cmp_face);
    for (int k = 1; k < nf; k++)
        if (!cmp_face(key + 4 * (size_t)k, key + 4 * (size_t)(k - 1)))
            die("pieces %d and %d overlap: both have the triangle of input vertices %d %d %d",
                (int)key[4 * (size_t)(k - 1) + 3] + 1, (int)key[4 * (size_t)k + 3] + 1,
                (int)key[4 * (size_t)k], (int)key[4 * (size_t)k + 1], (int)key[4 * (size_t)k + 2]);

    double diag = bbox_diagonal(X, nv);
    double rel = diag > 0 ? gap / diag : gap;
    info(1, "%d pieces: %d vertices (%d seam vertices merged), %d faces", np, nv, nseam, nf);
    if (nseam == 0)
        warn("the pieces share no vertex: nothing to merge");
    else
        info(1, "seam gap: max %.3g (%.3g of the bounding-box diagonal) at input vertex %d",
             gap, rel, gv);
    if (nseam > 0 && rel > o.tol) {
        if (o.strict)
            die("seam gap %.3g (%.3g of the bounding-box diagonal) at input vertex %d between "
                "pieces %d and %d exceeds the tolerance %g", gap, rel, gv, gi + 1, gj + 1, o.tol);
        warn("seam gap %.3g (%.3g of the bounding-box diagonal) at input vertex %d between "
             "pieces %d and %d", gap, rel, gv, gi + 1, gj + 1);
    }

    FILE *out = out_open(o.output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, nv, nf, F, 1, want_raw(o.raw)) < 0 ||
        mesh_writer_frame(&w, X, 0) < 0 || mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);

    for (int i = 0; i < np; i++) {
        free(P[i].F); free(P[i].X); free(P[i].map); free(inv[i]);
    }
    free(P); free(inv); free(copies); free(id); free(X); free(F); free(key);
    free(o.mesh); free(o.map); free(o.frame);
    return 0;
}
