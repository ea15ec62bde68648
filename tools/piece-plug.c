/* piece-plug -- printable pieces that click together (past StopShop Sec. 4,
 * which made its male/female plugs by hand): every piece of every part is
 * closed into a solid by a cap over each boundary loop (loopcap.h: a fan
 * from the centroid, or a constrained Delaunay triangulation where the loop
 * is not star-shaped about it); the cap over a seam is the same in both
 * parts (and in every piece, the seam being constant after seam-homog), so
 * neighbours meet face to face.  Every seam
 * cap gets the same connectors at the same places (magnet pockets, or a
 * keyed plug on one side and its socket on the other) and the piece id is
 * engraved on it, with CGAL corefinement Booleans (solid.h).  One STL file
 * per piece.
 */
#include "mesh.h"
#include "meshio.h"
#include "columns.h"
#include "topology.h"
#include "geometry.h"
#include "solid.h"
#include "connector.h"
#include "loopcap.h"
#include "closest_point.h"
#include "image.h"
#include "tool.h"
#include "cm_error.h"
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: piece-plug [options] -o PATTERN LIB:MAP...\n"
"Closed printable pieces with connectors, one STL file per piece.  LIB: the\n"
"open piece library of one part (dict-learn output, frames = pieces); MAP:\n"
"its part-split vertex map (part vertex -> whole-mesh vertex), which tells\n"
"where parts meet.  Give every part.  Each piece is closed by a cap (a fan\n"
"from the centroid, or a constrained Delaunay triangulation of the loop seen\n"
"along its normal where it is not star-shaped) over every boundary loop; the\n"
"cap over a seam is the same surface in both parts and every piece, the\n"
"mating face.  Every seam cap gets --count connectors placed from the seam\n"
"alone:\n"
"\n"
"  --magnet DxH     round pockets D wide and H deep on both sides, for\n"
"                   magnets; or\n"
"  --plug WxLxH     a keyed plug (trapezoid W wide, L long on one side and L/2\n"
"                   on the other, H tall) on the part listed first, a socket\n"
"                   larger by --clearance in the other: a piece turned half a\n"
"                   turn does not fit\n"
"\n"
"Each pocket or socket keeps at least --wall of material to the piece's\n"
"surface (exact intersection tests on every piece; the error says by how much\n"
"it is too thin).  The id \"PART-PIECE\" is engraved in 5x7 dot-matrix letters\n"
"in the middle of the seam cap (hidden once mounted).  Every solid written\n"
"is checked closed, manifold and free of self-intersections (CGAL).\n"
"\n"
"Options:\n"
"  -o, --output PATTERN   STL file names, a printf pattern of part and piece,\n"
"                         e.g. 'part%d_piece%03d.stl' (required)\n"
"      --mesh PATTERN     also write each solid as a MESH file (exact doubles)\n"
"      --magnet DxH       magnet pockets (sizes in mm with --unit-mm)\n"
"      --plug WxLxH       keyed plugs and sockets\n"
"      --count N          connectors per seam (default 2), on a circle around\n"
"                         the cap's centre\n"
"      --radius F         that circle's radius as a fraction of the distance\n"
"                         from the centre to the nearest seam vertex (0.55)\n"
"      --wall W           least wall around a pocket (default 0.8)\n"
"      --clearance C      socket larger than the plug by C (default 0.1)\n"
"      --unit-mm U        one model unit is U mm; connector sizes, --wall,\n"
"                         --clearance and --label-size are then in mm\n"
"      --label-size S     height of the engraved id (default: what fits)\n"
"      --no-label         no engraved id\n"
"      --density D        g/cm^3 for the report's grams (default 1.2)\n"
"      --report FILE      \"part piece volume grams\" per piece (model units^3;\n"
"                         grams use --unit-mm)\n"
"      --keep-tools PREFIX  also write PREFIX-P-K-{solid,cut,add}.mesh: the\n"
"                         closed piece and the solids cut out and added\n"
"  -v, --verbose          placements and volumes on stderr\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: piece-plug --unit-mm 19 --magnet 3x2 -o 'p%d_%03d.stl' \\\n"
"             lib_0.mesh:part_0.map lib_1.mesh:part_1.map\n";

struct options {
    const char *output, *meshout, *report, *keep;
    double radius;
    int magnet, plug, count, label;
    double D, H, PW, PL, wall, clear, unit, label_size, density;
};

struct part {
    const char *lib, *mapname;
    struct mesh m;
    int *map;             /* #V whole-mesh vertex ids */
    struct topology t;
    int nl, *Ls, *L;
    unsigned char *onb;   /* #V on the boundary */
    int *partner;         /* nl: the part sharing loop l (a seam), -1 for an open hole */
    double *cen;          /* nl by 3 cap centres of the seam loops (the same in every piece) */
    int **capT, *capn;    /* nl: the cap triangles of seam loop l (vertex nv + l = its centre), the
                             same in every piece and, mirrored, in the partner part; NULL for holes */
    struct trimesh add, cut;  /* connector solids shared by every piece */
};

static void parse_size(const char *s, const char *what, int n, double *out)
{
    char *end;
    const char *p = s;
    for (int i = 0; i < n; i++) {
        out[i] = strtod(p, &end);
        if (end == p || !(out[i] > 0) || !isfinite(out[i]) || (i + 1 < n ? *end != 'x' : *end != 0))
            usage_error("%s: '%s' is not %s positive sizes", what, s, n == 2 ? "DxH," : "WxLxH,");
        p = end + 1;
    }
}

static void check_pattern(const char *pat, const char *what)
{
    int n = 0;
    for (const char *p = pat; *p; p++)
        if (*p == '%') {
            if (p[1] == '%') { p++; continue; }
            p++;
            while (*p && strchr("0123456789-+ #", *p)) p++;
            if (*p != 'd') usage_error("%s: '%s': only %%d conversions (part, piece)", what, pat);
            n++;
        }
    if (n != 2) usage_error("%s: '%s' needs two %%d (part and piece)", what, pat);
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"output", 1, 0, 'o'}, {"mesh", 1, 0, 'M'}, {"radius", 1, 0, 'r'}, {"magnet", 1, 0, 'm'}, {"plug", 1, 0, 'p'}, {"count", 1, 0, 'n'},
        {"wall", 1, 0, 'w'}, {"clearance", 1, 0, 'c'}, {"unit-mm", 1, 0, 'U'}, {"label-size", 1, 0, 'S'},
        {"no-label", 0, 0, 'N'}, {"density", 1, 0, 'D'}, {"report", 1, 0, 'R'}, {"keep-tools", 1, 0, 'K'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->radius = 0.55; o->count = 2; o->label = 1;
    o->wall = 0.8; o->clear = 0.1; o->unit = 1; o->label_size = -1; o->density = 1.2;
    int c;
    double sz[3];
    while ((c = getopt_long(argc, argv, "o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'o': o->output = optarg; break;
        case 'M': o->meshout = optarg; break;
        case 'r': o->radius = arg_double(optarg, "--radius");
            if (!(o->radius > 0 && o->radius < 1)) usage_error("--radius must be in (0, 1)");
            break;
        case 'm': parse_size(optarg, "--magnet", 2, sz); o->magnet = 1; o->D = sz[0]; o->H = sz[1]; break;
        case 'p': parse_size(optarg, "--plug", 3, sz); o->plug = 1; o->PW = sz[0]; o->PL = sz[1]; o->H = sz[2]; break;
        case 'n': o->count = (int)arg_long(optarg, "--count");
            if (o->count < 1 || o->count > 64) usage_error("--count must be 1..64");
            break;
        case 'w': o->wall = arg_double(optarg, "--wall");
            if (!(o->wall >= 0) || !isfinite(o->wall)) usage_error("--wall must be >= 0");
            break;
        case 'c': o->clear = arg_double(optarg, "--clearance");
            if (!(o->clear >= 0) || !isfinite(o->clear)) usage_error("--clearance must be >= 0");
            break;
        case 'U': o->unit = arg_double(optarg, "--unit-mm");
            if (!(o->unit > 0) || !isfinite(o->unit)) usage_error("--unit-mm must be > 0");
            break;
        case 'S': o->label_size = arg_double(optarg, "--label-size");
            if (!(o->label_size > 0) || !isfinite(o->label_size)) usage_error("--label-size must be > 0");
            break;
        case 'N': o->label = 0; break;
        case 'D': o->density = arg_double(optarg, "--density");
            if (!(o->density > 0) || !isfinite(o->density)) usage_error("--density must be > 0");
            break;
        case 'R': o->report = optarg; break;
        case 'K': o->keep = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (o->magnet && o->plug) usage_error("--magnet and --plug exclude each other");
    if (!o->output) usage_error("-o PATTERN is required (one STL file per piece)");
    check_pattern(o->output, "-o");
    if (o->meshout) check_pattern(o->meshout, "--mesh");
    if (optind >= argc) usage_error("expected LIB:MAP for every part");
    /* sizes to model units */
    o->D /= o->unit; o->H /= o->unit; o->PW /= o->unit; o->PL /= o->unit;
    o->wall /= o->unit; o->clear /= o->unit;
    if (o->label_size > 0) o->label_size /= o->unit;
}

static void read_part(struct part *P, const char *arg)
{
    char *s = strdup(arg), *colon = strrchr(s, ':');
    if (!colon || colon == s || !colon[1]) usage_error("'%s' is not LIB:MAP", arg);
    *colon = 0;
    P->lib = s; P->mapname = colon + 1;
    if (mesh_read(P->lib, &P->m) < 0) die("%s", cm_errmsg());
    int rows;
    if (labels_read(P->mapname, P->m.nv, "vertices", 0, 1 << 30, &P->map, &rows) < 0) die("%s", cm_errmsg());
    if (topology_build(P->m.F, P->m.nf, P->m.nv, &P->t) < 0) die("cannot read '%s': %s", P->lib, cm_errmsg());
    if (P->t.nnonmanifold > 0) die("cannot read '%s': %d non-manifold edges", P->lib, P->t.nnonmanifold);
    P->nl = boundary_loops(&P->t, P->m.F, &P->Ls, &P->L);
    if (P->nl < 0) die("cannot read '%s': %s", P->lib, cm_errmsg());
    if (P->nl == 0) die("cannot read '%s': the pieces are closed: no seam to put connectors on", P->lib);
    P->onb = calloc(P->m.nv, 1);
    for (int k = 0; k < P->Ls[P->nl]; k++) P->onb[P->L[k]] = 1;
}

/* The seam must be the same in every piece (seam-homog): the connectors are
 * placed once for all of them. */
static void check_seam_constant(const struct part *P, int ip, double tol)
{
    const double *X0 = mesh_frame(&P->m, 0);
    for (int k = 1; k < P->m.nframes; k++) {
        const double *X = mesh_frame(&P->m, k);
        for (int i = 0; i < P->m.nv; i++)
            if (P->onb[i] && dist3(X + 3 * i, X0 + 3 * i) > tol)
                die("cannot read '%s': part %d piece %d: seam vertex %d is %g from piece 0: the seam is not "
                    "the same in every piece (run seam-homog before part-split)", P->lib, ip, k, i,
                    dist3(X + 3 * i, X0 + 3 * i));
    }
}

struct wall_check {
    const double *V; int nv;     /* the closed piece */
    const int *F; int nf;        /* its skin: the piece's faces and the caps of open holes */
};

/* the largest wall (<= want) the prism P (n-gon) offset by it leaves
 * without touching the skin: bisection on exact intersection tests */
static double wall_available(const struct wall_check *wc, const struct connector_frame *fr, const double *P,
                             int n, double z0, double z1, double zsign, double want, int *touches)
{
    double *Q = malloc(sizeof(double) * 2 * n);
    double lo = 0, hi = want;
    *touches = 0;
    for (int it = 0; it < 40; it++) {
        double w = it == 0 ? want : it == 1 ? 0 : 0.5 * (lo + hi);
        convex_offset(P, n, w, Q);
        struct trimesh t = {0};
        /* grow the tool by w away from the seam (z0 or z1 is the open end inside the piece) */
        connector_prism(&t, fr, Q, n, zsign > 0 ? z0 : z0 - w, zsign > 0 ? z1 + w : z1);
        int r = solid_touches_surface(t.V, t.nv, t.F, t.nf, wc->V, wc->nv, wc->F, wc->nf);
        trimesh_free(&t);
        if (r < 0) die("wall check: %s", cm_errmsg());
        if (it == 0 && !r) { free(Q); return want; }
        if (it == 1 && r) { *touches = 1; free(Q); return 0; }
        if (it >= 2) { if (r) hi = w; else lo = w; }
        if (it >= 2 && hi - lo < 1e-4 * want) break;
    }
    free(Q);
    return lo;
}

struct place_ctx { const struct closest_point_tree *T; };
static void place_on(void *ctx, const double p[3], double q[3])
{
    closest_point_query(((struct place_ctx *)ctx)->T, p, q, NULL, NULL);
}

/* centroid of the loop's points, summed in whole-mesh vertex order so both
 * parts at a seam get the same bits */
static void loop_centroid(const struct part *A, int l, const double *X, double c[3])
{
    int n = A->Ls[l + 1] - A->Ls[l];
    int *ord = malloc(sizeof(int) * n);
    for (int k = 0; k < n; k++) ord[k] = A->L[A->Ls[l] + k];
    for (int i = 1; i < n; i++)   /* insertion sort by whole-mesh id */
        for (int j = i; j > 0 && A->map[ord[j - 1]] > A->map[ord[j]]; j--) { int t = ord[j]; ord[j] = ord[j - 1]; ord[j - 1] = t; }
    c[0] = c[1] = c[2] = 0;
    for (int k = 0; k < n; k++) for (int d = 0; d < 3; d++) c[d] += X[3 * ord[k] + d];
    for (int d = 0; d < 3; d++) c[d] /= n;
    free(ord);
}

/* height along a (from o) of the cap over seam loop l at in-plane point
 * o + s u + r w; NAN when the point is off the cap */
static double cap_height(const struct part *A, int l, const double *X, const double cen[3],
                         const struct connector_frame *fr, double s, double r)
{
    double best = NAN;
    int nv = A->m.nv;
    for (int k = 0; k < A->capn[l]; k++) {
        const int *t = A->capT[l] + 3 * k;
        const double *pts[3];
        for (int j = 0; j < 3; j++) pts[j] = t[j] >= nv ? cen : X + 3 * t[j];
        double P2[3][2], Z[3];
        for (int j = 0; j < 3; j++) {
            double d[3];
            sub3(pts[j], fr->o, d);
            P2[j][0] = dot3(d, fr->u) - s; P2[j][1] = dot3(d, fr->w) - r; Z[j] = dot3(d, fr->a);
        }
        double det = (P2[1][0] - P2[0][0]) * (P2[2][1] - P2[0][1]) - (P2[2][0] - P2[0][0]) * (P2[1][1] - P2[0][1]);
        if (det == 0) continue;
        double b1 = ((0 - P2[0][0]) * (P2[2][1] - P2[0][1]) - (P2[2][0] - P2[0][0]) * (0 - P2[0][1])) / det;
        double b2 = ((P2[1][0] - P2[0][0]) * (0 - P2[0][1]) - (0 - P2[0][0]) * (P2[1][1] - P2[0][1])) / det;
        if (b1 < -1e-12 || b2 < -1e-12 || b1 + b2 > 1 + 1e-12) continue;
        double z = (1 - b1 - b2) * Z[0] + b1 * Z[1] + b2 * Z[2];
        if (isnan(best) || fabs(z) < fabs(best)) best = z;
    }
    return best;
}

/* a diagonal of a triangulated cap (no centre vertex) that is an edge of
 * the part's own mesh: that edge would get four faces.  Returns the first
 * such triangle's index, -1 if none. */
static int cap_reuses_edge(const struct part *A, const int *T, int nt, int *ea, int *eb)
{
    for (int k = 0; k < nt; k++)
        for (int j = 0; j < 3; j++) {
            int a = T[3 * k + j], b = T[3 * k + (j + 1) % 3], e;
            if (a >= A->m.nv || b >= A->m.nv || (e = topology_edge(&A->t, a, b)) < 0) continue;
            if (A->t.EFn[e] == 2) { *ea = a; *eb = b; return k; }
        }
    return -1;
}

/* the cap of loop l of A in the positions X with centre c (vertex nv + l) */
static int cap_of(const struct part *A, int l, const double *X, const double c[3], int **T, int *fan)
{
    double a[3];
    int n = A->Ls[l + 1] - A->Ls[l], isfan, ea, eb;
    loop_area_vector(X, A->L + A->Ls[l], n, a);
    int nt = loop_cap(X, A->L + A->Ls[l], n, c, a, A->m.nv + l, T, &isfan);
    if (nt < 0) die("cannot read '%s': loop %d: %s", A->lib, l, cm_errmsg());
    if (!isfan && cap_reuses_edge(A, *T, nt, &ea, &eb) >= 0)
        die("cannot read '%s': loop %d is not star-shaped about its centroid and its triangulated cap would "
            "reuse the interior edge %d-%d of the piece (a triangle with all three corners on the loop): "
            "smooth the seam (seam-smooth) or move it", A->lib, l, ea, eb);
    if (fan) *fan = isfan;
    return nt;
}

static const char *mm(double unit) { return unit != 1 ? " mm" : ""; }

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    int np = argc - optind;
    struct part *P = calloc(np, sizeof *P);
    int nwhole = 0;
    double diag = 0, unit = o.unit;
    for (int p = 0; p < np; p++) {
        read_part(&P[p], argv[optind + p]);
        for (int i = 0; i < P[p].m.nv; i++) if (P[p].map[i] + 1 > nwhole) nwhole = P[p].map[i] + 1;
        double d = bbox_diagonal(mesh_frame(&P[p].m, 0), P[p].m.nv);
        if (d > diag) diag = d;
    }
    for (int p = 0; p < np; p++) check_seam_constant(&P[p], p, 1e-9 * diag);

    /* which part holds each whole-mesh vertex on its boundary, and where */
    int *owner = malloc(sizeof(int) * nwhole), *owner_v = malloc(sizeof(int) * nwhole);
    unsigned char *bnd = calloc((size_t)np * nwhole, 1);
    for (int g = 0; g < nwhole; g++) owner[g] = -1;
    for (int p = 0; p < np; p++)
        for (int i = 0; i < P[p].m.nv; i++) {
            if (!P[p].onb[i]) continue;
            int g = P[p].map[i];
            const double *x = mesh_frame(&P[p].m, 0) + 3 * i;
            if (owner[g] >= 0 && dist3(mesh_frame(&P[owner[g]].m, 0) + 3 * owner_v[g], x) > 1e-9 * diag)
                die("cannot read '%s': seam vertex %d (whole-mesh %d) is not where part %d has it: the parts do "
                    "not come from one part-split", P[p].lib, i, g, owner[g]);
            owner[g] = p; owner_v[g] = i;
            bnd[(size_t)p * nwhole + g] = 1;
        }
    /* every loop: a seam with exactly one other part, or an open hole */
    for (int p = 0; p < np; p++) {
        struct part *A = &P[p];
        A->partner = malloc(sizeof(int) * A->nl);
        A->cen = calloc((size_t)A->nl * 3, sizeof(double));
        A->capT = calloc(A->nl, sizeof *A->capT);
        A->capn = calloc(A->nl, sizeof *A->capn);
        for (int l = 0; l < A->nl; l++) {
            int partner = -2;
            for (int k = A->Ls[l]; k < A->Ls[l + 1]; k++) {
                int g = A->map[A->L[k]], who = -1;
                for (int q = 0; q < np; q++)
                    if (q != p && bnd[(size_t)q * nwhole + g]) {
                        if (who >= 0) die("cannot read '%s': boundary vertex %d is on the seams of parts %d and %d: "
                                          "caps where three parts meet are not supported", A->lib, A->L[k], who, q);
                        who = q;
                    }
                if (partner == -2) partner = who;
                else if (partner != who)
                    die("cannot read '%s': boundary loop %d is shared only in part (with part %d, not at vertex %d): "
                        "a seam must be a whole loop", A->lib, l, partner >= 0 ? partner : who, A->L[k]);
            }
            A->partner[l] = partner;
            if (partner >= 0) loop_centroid(A, l, mesh_frame(&A->m, 0), A->cen + 3 * l);
        }
    }

    /* connectors: frames on every seam cap, z > 0 into the part listed first */
    double circ[64], keyed[8], sock[8];
    int ncircle = 32;
    connector_circle(o.D / 2, ncircle, circ);
    connector_keyed(o.PW, o.PL, keyed);
    convex_offset(keyed, 4, o.clear, sock);
    double foot = o.magnet ? o.D / 2 / cos(M_PI / ncircle) : 0;   /* footprint radius */
    if (o.plug) for (int i = 0; i < 4; i++) { double rr = hypot(sock[2 * i], sock[2 * i + 1]); if (rr > foot) foot = rr; }
    struct conn { int p, q, lp, lq; struct connector_frame fr; double e, m; } *C = NULL;
    struct seam { int p, q, lp, lq; double a[3], e1[3], e2[3], cen[3], rho; } *SM = NULL;
    int nconn = 0, nseam = 0;
    for (int p = 0; p < np; p++)
        for (int l = 0; l < P[p].nl; l++) {
            struct part *A = &P[p];
            int q = A->partner[l];
            if (q < p) continue;
            /* q's loop holding this seam: the one with l's first vertex */
            int lq = -1, g0 = A->map[A->L[A->Ls[l]]];
            for (int j = 0; j < P[q].nl && lq < 0; j++)
                if (P[q].partner[j] == p)
                    for (int k = P[q].Ls[j]; k < P[q].Ls[j + 1]; k++)
                        if (P[q].map[P[q].L[k]] == g0) { lq = j; break; }
            if (lq < 0) die("cannot read '%s': seam loop %d with part %d: part %d has no such loop", A->lib, l, q, q);
            const double *X = mesh_frame(&A->m, 0), *cen = A->cen + 3 * l;
            struct seam s = {p, q, l, lq, {0}, {0}, {0}, {0}, INFINITY};
            memcpy(s.cen, cen, sizeof s.cen);
            int gmin = -1, vmin = 0;
            for (int k = A->Ls[l]; k < A->Ls[l + 1]; k++) {
                int ia = A->L[k], ib = A->L[k + 1 < A->Ls[l + 1] ? k + 1 : A->Ls[l]];
                double d1[3], d2[3], nrm[3];
                sub3(X + 3 * ia, X + 3 * ib, d1);   /* cap face (b, a, c) of p: (a - b) x (c - b) */
                sub3(cen, X + 3 * ib, d2);
                cross3(d1, d2, nrm);
                for (int d = 0; d < 3; d++) s.a[d] -= nrm[d];
                if (gmin < 0 || A->map[ia] < gmin) { gmin = A->map[ia]; vmin = ia; }
            }
            double la = norm3(s.a);
            if (!(la > 0)) die("cannot read '%s': seam loop %d spans no area", A->lib, l);
            for (int d = 0; d < 3; d++) s.a[d] /= la;
            double t[3];
            sub3(X + 3 * vmin, cen, t);
            double ta = dot3(t, s.a);
            for (int d = 0; d < 3; d++) t[d] -= ta * s.a[d];
            double lt = norm3(t);
            for (int d = 0; d < 3; d++) s.e1[d] = t[d] / lt;
            cross3(s.a, s.e1, s.e2);
            for (int k = A->Ls[l]; k < A->Ls[l + 1]; k++) {
                sub3(X + 3 * A->L[k], cen, t);
                double r = hypot(dot3(t, s.e1), dot3(t, s.e2));
                if (r < s.rho) s.rho = r;
            }
            SM = realloc(SM, sizeof *SM * (nseam + 1));
            SM[nseam++] = s;
            /* the seam cap, once: in p, and mirrored (same triangles, reversed) in q */
            int fan, nt = cap_of(A, l, X, cen, &A->capT[l], &fan);
            A->capn[l] = nt;
            struct part *B = &P[q];
            B->capn[lq] = nt;
            B->capT[lq] = malloc(sizeof(int) * 3 * nt);
            for (int k = 0; k < 3 * nt; k++) {
                int v = A->capT[l][k], vq = -1;
                if (v >= A->m.nv) vq = B->m.nv + lq;
                else
                    for (int j = B->Ls[lq]; j < B->Ls[lq + 1] && vq < 0; j++)
                        if (B->map[B->L[j]] == A->map[v]) vq = B->L[j];
                if (vq < 0) die("cannot read '%s': seam %d-%d: vertex %d of part %d is not on the seam of part %d",
                                B->lib, p, q, v, p, q);
                B->capT[lq][k - k % 3 + (k % 3 == 0 ? 0 : 3 - k % 3)] = vq;   /* (a, b, c) -> (a, c, b) */
            }
            int ea, eb;
            if (!fan && cap_reuses_edge(B, B->capT[lq], nt, &ea, &eb) >= 0)
                die("cannot read '%s': loop %d is not star-shaped about its centroid and its triangulated cap would "
                    "reuse the interior edge %d-%d of the piece (a triangle with all three corners on the seam): "
                    "smooth the seam (seam-smooth) or move it", B->lib, lq, ea, eb);
            if (!fan)
                info(1, "seam %d-%d: the loop is not star-shaped about its centroid: capped by a constrained Delaunay "
                     "triangulation (%d triangles)", p, q, nt);
            if (!(o.magnet || o.plug)) continue;
            for (int j = 0; j < o.count; j++) {
                struct connector_frame fr;
                double th = 2 * M_PI * j / o.count, rad = o.radius * s.rho;
                for (int d = 0; d < 3; d++) {
                    fr.o[d] = cen[d] + rad * (cos(th) * s.e1[d] + sin(th) * s.e2[d]);
                    fr.u[d] = s.e2[d]; fr.w[d] = s.e1[d]; fr.a[d] = s.a[d];   /* the same key direction everywhere */
                }
                double z0 = cap_height(A, l, X, cen, &fr, 0, 0);
                if (isnan(z0)) die("cannot read '%s': connector %d of seam %d-%d is off the seam cap (smaller --radius)",
                                   A->lib, j, p, q);
                for (int d = 0; d < 3; d++) fr.o[d] += z0 * fr.a[d];
                /* how far the cap strays from the frame's plane under the footprint */
                double dev = 0, reach = foot + o.wall;
                for (int i = 0; i < 16; i++) {
                    double z = cap_height(A, l, X, cen, &fr, reach * cos(2 * M_PI * i / 16), reach * sin(2 * M_PI * i / 16));
                    if (isnan(z)) {
                        z = cap_height(A, l, X, cen, &fr, foot * cos(2 * M_PI * i / 16), foot * sin(2 * M_PI * i / 16));
                        if (isnan(z))
                            die("cannot read '%s': seam %d-%d: connector %d reaches past the seam cap's edge (smaller "
                                "--radius or connectors)", A->lib, p, q, j);
                    }
                    if (fabs(z) > dev) dev = fabs(z);
                }
                C = realloc(C, sizeof *C * (nconn + 1));
                C[nconn].p = p; C[nconn].q = q; C[nconn].lp = l; C[nconn].lq = lq; C[nconn].fr = fr;
                C[nconn].e = dev + 0.25 * o.H;
                C[nconn].m = dev + (o.wall > 0.25 * o.H ? o.wall : 0.25 * o.H);
                nconn++;
            }
            info(1, "seam %d-%d: cap radius %g (nearest seam vertex), %d connectors at %g", p, q, s.rho, o.count,
                 o.radius * s.rho);
        }
    if (nseam == 0) die("no two parts share a seam loop: check the MAP files (part-split -m)");
    for (int k = 0; k < nconn; k++) {
        struct part *A = &P[C[k].p], *B = &P[C[k].q];
        const struct connector_frame *fr = &C[k].fr;
        double e = C[k].e, m = C[k].m;
        if (o.magnet) {
            connector_prism(&A->cut, fr, circ, ncircle, -e, o.H);
            connector_prism(&B->cut, fr, circ, ncircle, -o.H, e);
        } else {
            connector_prism(&A->add, fr, keyed, 4, -o.H, m);
            connector_prism(&B->cut, fr, sock, 4, -(o.H + o.clear), m + o.clear);
        }
    }

    /* every piece */
    int total_pieces = 0;
    for (int p = 0; p < np; p++) total_pieces += P[p].m.nframes;
    struct result { double *V; int *F; int nv, nf; double vol; } *res = calloc(total_pieces, sizeof *res);
    int r = 0;
    for (int p = 0; p < np; p++) {
        struct part *A = &P[p];
        int nv = A->m.nv, nf = A->m.nf, nl = A->nl, nb = A->Ls[nl];
        int nsv = nv + nl, nsf = nf + nb;
        /* faces: the piece, then the caps; the skin (wall checks) is the piece
         * and the caps of open holes (made per piece: they follow the frame) */
        int *S = malloc(sizeof(int) * 3 * nsf), *skin = malloc(sizeof(int) * 3 * nsf), nskin = nf;
        int *seamcap = malloc(sizeof(int) * 3 * nsf), nseamcap = 0;
        double *O = malloc(sizeof(double) * 3 * nsv);
        for (int k = 0; k < A->m.nframes; k++, r++) {
            char what[64];
            snprintf(what, sizeof what, "part %d piece %d", p, k);
            memcpy(O, mesh_frame(&A->m, k), sizeof(double) * 3 * nv);
            memcpy(S, A->m.F, sizeof(int) * 3 * nf);
            memcpy(skin, A->m.F, sizeof(int) * 3 * nf);
            nsf = nf; nskin = nf; nseamcap = 0;
            for (int l = 0; l < nl; l++) {
                if (A->partner[l] >= 0) {
                    memcpy(O + 3 * (nv + l), A->cen + 3 * l, sizeof(double) * 3);
                    memcpy(S + 3 * nsf, A->capT[l], sizeof(int) * 3 * A->capn[l]);
                    memcpy(seamcap + 3 * nseamcap, A->capT[l], sizeof(int) * 3 * A->capn[l]);
                    nsf += A->capn[l]; nseamcap += A->capn[l];
                } else {
                    loop_centroid(A, l, O, O + 3 * (nv + l));
                    int *T, nt = cap_of(A, l, O, O + 3 * (nv + l), &T, NULL);
                    memcpy(S + 3 * nsf, T, sizeof(int) * 3 * nt);
                    memcpy(skin + 3 * nskin, T, sizeof(int) * 3 * nt);
                    nsf += nt; nskin += nt;
                    free(T);
                }
            }
            struct solid_info si;
            if (solid_check(O, nsv, S, nsf, &si) < 0) die("%s: %s", what, cm_errmsg());
            if (!si.closed || si.self_intersections) {
                struct solid_info pi;
                if (solid_check(O, nv, A->m.F, nf, &pi) == 0 && pi.self_intersections)
                    die("cannot read '%s': %s: the piece intersects itself (%d face pairs)", A->lib, what,
                        pi.self_intersections);
                die("cannot read '%s': %s: the capped piece %s (%d face pairs: a cap crosses "
                    "the surface)", A->lib, what, !si.closed ? "is not closed" : "intersects itself", si.self_intersections);
            }
            if (si.volume < 0)
                die("cannot read '%s': %s: the capped piece has negative volume: its faces point inward", A->lib, what);
            /* walls around this piece's pockets, sockets and plug roots */
            struct wall_check wc = {O, nsv, skin, nskin};
            for (int c = 0; c < nconn; c++) {
                if (C[c].p != p && C[c].q != p) continue;
                const struct connector_frame *fr = &C[c].fr;
                int into_p = C[c].p == p, touches;
                double got, e = C[c].e, m = C[c].m;
                const char *kind = o.magnet ? "magnet pocket" : into_p ? "plug root" : "socket";
                if (o.magnet)
                    got = into_p ? wall_available(&wc, fr, circ, ncircle, -e, o.H, 1, o.wall, &touches)
                                 : wall_available(&wc, fr, circ, ncircle, -o.H, e, -1, o.wall, &touches);
                else
                    got = into_p ? wall_available(&wc, fr, keyed, 4, -e, m, 1, o.wall, &touches)
                                 : wall_available(&wc, fr, sock, 4, -(o.H + o.clear), m + o.clear, -1, o.wall, &touches);
                if (touches)
                    die("cannot read '%s': %s: %s %d breaks through the piece's surface (%.3g%s deep: shorter or "
                        "narrower connectors, or a smaller --radius)", A->lib, what, kind, c, o.H * unit, mm(unit));
                if (got < o.wall)
                    die("cannot read '%s': %s: the wall around %s %d is %.3g%s, --wall asks %.3g%s: the piece is "
                        "%.3g%s too thin there", A->lib, what, kind, c, got * unit, mm(unit), o.wall * unit, mm(unit),
                        (o.wall - got) * unit, mm(unit));
            }
            struct trimesh cut = {0};
            cut.nv = cut.capv = A->cut.nv; cut.nf = cut.capf = A->cut.nf;
            cut.V = malloc(sizeof(double) * 3 * (A->cut.nv + 1)); cut.F = malloc(sizeof(int) * 3 * (A->cut.nf + 1));
            if (A->cut.nv) memcpy(cut.V, A->cut.V, sizeof(double) * 3 * A->cut.nv);
            if (A->cut.nf) memcpy(cut.F, A->cut.F, sizeof(int) * 3 * A->cut.nf);
            if (o.label && nseamcap) {
                /* on the first seam cap of this part, at its centre, read from outside */
                int sj = 0;
                for (int j = 0; j < nseam; j++) if (SM[j].p == p || SM[j].q == p) { sj = j; break; }
                const struct seam *s = &SM[sj];
                double nr[3], x[3];
                for (int d = 0; d < 3; d++) nr[d] = SM[sj].p == p ? -s->a[d] : s->a[d];
                cross3(s->e1, nr, x);
                char text[32];
                snprintf(text, sizeof text, "%d-%d", p, k);
                int len = (int)strlen(text);
                double half = hypot((len * FONT_ADVANCE - 1) / 2.0 + 0.5, FONT_H / 2.0 + 0.5);
                /* a tenth of the cap radius between the id and the pockets */
                double room = (o.magnet || o.plug) ? (o.radius - 0.1) * s->rho - foot : 0.8 * s->rho;
                double pitch = o.label_size > 0 ? o.label_size / FONT_H : room / half;
                if (!(room > 0))
                    die("%s: no room for the id between the connectors (--radius, smaller connectors or --no-label)", what);
                if (pitch * half > room * (1 + 1e-9))
                    die("%s: the id '%s' %.3g%s tall does not fit between the connectors (at most %.3g%s; "
                        "--label-size, --radius or --no-label)", what, text, pitch * FONT_H * unit, mm(unit),
                        room / half * FONT_H * unit, mm(unit));
                struct closest_point_tree *tree = closest_point_tree_new(O, nsv, seamcap, nseamcap);
                if (!tree) die("%s: %s", what, cm_errmsg());
                struct place_ctx pc = {tree};
                double tc[3];   /* off the fan centre, where the cap's spokes meet */
                for (int d = 0; d < 3; d++) tc[d] = s->cen[d] + 0.37 * pitch * x[d] + 0.21 * pitch * s->e1[d];
                connector_text(&cut, text, tc, x, s->e1, nr, pitch, pitch, pitch, place_on, &pc);
                closest_point_tree_free(tree);
            }
            double *V1 = O, *V2 = NULL;
            int *F1 = S, nv1 = nsv, nf1 = nsf, *F2 = NULL, nv2, nf2;
            if (A->add.nf) {
                if (solid_boolean(SOLID_UNION, V1, nv1, F1, nf1, A->add.V, A->add.nv, A->add.F, A->add.nf, what,
                                  &V2, &nv2, &F2, &nf2) < 0)
                    die("%s", cm_errmsg());
                V1 = V2; F1 = F2; nv1 = nv2; nf1 = nf2;
            }
            if (cut.nf) {
                double *V3; int *F3, nv3, nf3;
                if (solid_boolean(SOLID_DIFFERENCE, V1, nv1, F1, nf1, cut.V, cut.nv, cut.F, cut.nf, what,
                                  &V3, &nv3, &F3, &nf3) < 0)
                    die("%s", cm_errmsg());
                if (V2) { free(V2); free(F2); }
                V1 = V3; F1 = F3; nv1 = nv3; nf1 = nf3;
            } else if (!V2) {
                V1 = malloc(sizeof(double) * 3 * nv1); memcpy(V1, O, sizeof(double) * 3 * nv1);
                F1 = malloc(sizeof(int) * 3 * nf1); memcpy(F1, S, sizeof(int) * 3 * nf1);
            }
            double vsolid = si.volume;
            if (solid_check(V1, nv1, F1, nf1, &si) < 0) die("%s: %s", what, cm_errmsg());
            if (!si.manifold || !si.closed || si.self_intersections)
                die("%s: the result is %s (CGAL corefinement)", what,
                    !si.manifold ? "not manifold" : !si.closed ? "not closed" : "self-intersecting");
            res[r].V = V1; res[r].F = F1; res[r].nv = nv1; res[r].nf = nf1; res[r].vol = si.volume;
            info(1, "%s: closed %g, with connectors %g (%+.3g%%), %d faces", what, vsolid, si.volume,
                 100 * (si.volume - vsolid) / vsolid, nf1);
            if (o.keep) {
                char name[4096];
                const char *kind[3] = {"solid", "cut", "add"};
                for (int j = 0; j < 3; j++) {
                    unsigned char cutflag = 0;
                    struct mesh w = {nsv, nsf, 1, S, O, &cutflag};
                    if (j == 1) { w.nv = cut.nv; w.nf = cut.nf; w.V = cut.V; w.F = cut.F; }
                    if (j == 2) { w.nv = A->add.nv; w.nf = A->add.nf; w.V = A->add.V; w.F = A->add.F; }
                    if (w.nf == 0) continue;
                    snprintf(name, sizeof name, "%s-%d-%d-%s.mesh", o.keep, p, k, kind[j]);
                    FILE *f = out_open(name);
                    if (mesh_write(f, &w, 0) < 0) die("cannot write '%s': %s", name, cm_errmsg());
                    out_close(f);
                }
            }
            trimesh_free(&cut);
        }
        free(S); free(skin); free(seamcap); free(O);
    }

    /* everything computed and checked: write */
    char name[4096];
    r = 0;
    double grams = 0;
    FILE *rep = o.report ? out_open(o.report) : NULL;
    if (rep) fprintf(rep, "# part piece volume grams\n");
    for (int p = 0; p < np; p++)
        for (int k = 0; k < P[p].m.nframes; k++, r++) {
            snprintf(name, sizeof name, o.output, p, k);
            FILE *f = out_open(name);
            if (meshio_write(f, name, MESHIO_STL, 0, res[r].nv, res[r].nf, res[r].F, res[r].V) < 0)
                die("%s", cm_errmsg());
            out_close(f);
            if (o.meshout) {
                snprintf(name, sizeof name, o.meshout, p, k);
                unsigned char cutflag = 0;
                struct mesh w = {res[r].nv, res[r].nf, 1, res[r].F, res[r].V, &cutflag};
                f = out_open(name);
                if (mesh_write(f, &w, 0) < 0) die("cannot write '%s': %s", name, cm_errmsg());
                out_close(f);
            }
            double g = res[r].vol * unit * unit * unit / 1000 * o.density;
            grams += g;
            if (rep) fprintf(rep, "%d %d %.10g %.6g\n", p, k, res[r].vol, g);
        }
    if (rep) out_close(rep);
    info(1, "%d pieces, %d connectors, %.4g g", total_pieces, nconn, grams);
    for (r = 0; r < total_pieces; r++) { free(res[r].V); free(res[r].F); }
    free(res);
    for (int p = 0; p < np; p++) {
        mesh_free(&P[p].m); free(P[p].map); topology_free(&P[p].t); free(P[p].Ls); free(P[p].L);
        free(P[p].onb); free(P[p].partner); free(P[p].cen);
        for (int l = 0; l < P[p].nl; l++) free(P[p].capT[l]);
        free(P[p].capT); free(P[p].capn); trimesh_free(&P[p].add); trimesh_free(&P[p].cut);
        free((char *)P[p].lib);
    }
    free(P); free(C); free(SM); free(bnd); free(owner); free(owner_v);
    return 0;
}
