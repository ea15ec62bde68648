/* seg-graphcut -- cut a mesh animation into parts along a short, motionless
 * seam (StopShop Sec. 3.1, Eq. 1-3): per-triangle part labels from seeds.
 *
 * Two streaming passes over the frames (memory O(one frame + topology); a
 * pipe is spooled to a temporary raw file, see mesh_spool.h): the first
 * accumulates the average mesh, the second the per-edge motion cost of
 * Eq. 3.  Geodesic distances to the seeds on the average mesh give the
 * unary cost (Eq. 2); alpha-expansion on BK max-flow minimizes Eq. 1.
 */
#include "alpha_expansion.h"
#include "bridges.h"
#include "closest_point.h"
#include "cm_error.h"
#include "geodesic.h"
#include "geometry.h"
#include "mesh.h"
#include "mesh_spool.h"
#include "mirror.h"
#include "columns.h"
#include "progress.h"
#include "tool.h"
#include "topology.h"
#include "coincident.h"
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: seg-graphcut [options] [FILE]\n"
"Per-triangle part labels (one integer 0..s-1 per line) for a MESH animation,\n"
"cut along a short seam where the mesh moves little (StopShop Eq. 1-3).\n"
"\n"
"Seeds (at least one per part; parts are numbered 0..s-1):\n"
"      --seed PART:FACE     a seed triangle (repeatable)\n"
"      --seeds FILE         lines 'PART FACE' or 'PART X Y Z' (a point, snapped\n"
"                           to the nearest triangle of the average mesh)\n"
"\n"
"Options:\n"
"  -g, --gamma G            weight of the seam cost (default 100, for the model\n"
"                           scaled to a unit bounding-box diagonal)\n"
"  -m, --motion K           weight of motion in the seam cost: an edge costs its\n"
"                           length times 1 + K (d_a + d_b) / d_max, d = mean\n"
"                           displacement from the average (default 3)\n"
"  -b, --band B             no unary cost where a triangle's distances to two\n"
"                           parts' seeds differ by less than B D; D = distance\n"
"                           between the nearest seeds of two parts (default 0.6,\n"
"                           narrowed in steps of 0.2 while a part collapses to\n"
"                           its seed; a given --band is kept)\n"
"  -r, --seed-radius R      triangles within R D of a seed are fixed to its part\n"
"                           (default 0.06); -b 0 -r 0: the paper's Eq. 2\n"
"  -p, --parts S            number of parts (default: largest seed part + 1)\n"
"      --bridge R           components (eyes, teeth) are linked where they come\n"
"                           within R bbox diagonals of each other (default 0.01;\n"
"                           one without, to its nearest component): distances\n"
"                           and labels pass through these bridges\n"
"      --seed-snap T        a seed point farther than T bbox diagonals from the\n"
"                           surface is an error (default 0.05)\n"
"      --one-pass           one pass, RMS displacement instead of Eq. 3's sum\n"
"                           (no second read, no temporary file for pipes)\n"
"      --max-cycles N       limit alpha-expansion cycles (default: to convergence)\n"
"      --symmetric          a seam symmetric about a mirror plane (--mirror, or\n"
"                           found by PCA + ICP of the average mesh with its\n"
"                           reflection): seam costs and seed distances averaged\n"
"                           with their mirror's, each triangle tied to its mirror\n"
"      --mirror A,B,C,D     the mirror plane A x + B y + C z = D; without\n"
"                           --symmetric only the seam's asymmetry is measured (-v)\n"
"      --sym-weight K       weight of the tie of a triangle to its mirror, in mean\n"
"                           seam-edge costs (default 1; 0: costs averaged only)\n"
"      --no-weld            do not join vertices that share a position in every\n"
"                           frame (UV-seam duplicates; joined by default)\n"
"  -o, --output FILE        write the labels to FILE instead of stdout\n"
"  -v, --verbose            print energies (unary, binary) and timings\n"
"  -h, --help               show this help\n"
"      --version            show the version\n"
"\n"
"Example: mesh-gen -f 20 -m 20 cylinder | seg-graphcut --seed 0:0 --seed 1:399 > parts.txt\n";

/* The unary term is area-weighted and scaled as if the model had this many
 * triangles of equal area, so gamma means the same on coarse and fine
 * meshes of one shape (Eq. 1 sums over triangles: its balance would
 * otherwise change with the resolution).  5000 is facecap's resolution. */
#define UNARY_TRIANGLES 5000.0
#define DEFAULT_MOTION 3.0
/* Unary dead band and fixed seed disks (see the unary below), in units of
 * the distance D between the nearest seeds of two parts.  Measured on
 * facecap (seeds 1539/1034 and 36 pairs jittered within two rings of
 * them, gamma 100): with radius 0.06 every band in 0.5..0.8 gives one and
 * the same labeling for all 36 pairs (band 0.9: the seam leaves the face;
 * 0.4: 32/36), and so does every radius in 0.03..0.1 at band 0.6 (0.02:
 * some seeds are cut out alone; 0.15: the seam touches a disk); band 0.6,
 * radius 0.1 also at gamma 50, 200 and 400. */
#define DEFAULT_BAND 0.6
/* When a part collapses to its seed (below) and --band was not given, the
 * cut is redone with the band narrowed by this step (down to 0) until no
 * part collapses: forehead + chin alone on head-gen's head keep less of
 * their region at 0.6 (24%, 27% with eyeballs) and 135% at 0.4. */
#define BAND_STEP 0.2
#define DEFAULT_SEED_RADIUS 0.06
/* Components closer than this (bbox diagonals) are bridged.  facecap's
 * eyeballs come within 0.0009 of the eyelids, its teeth within 0.0018 of
 * the face (closest vertices): 0.01 links them with margin. */
#define DEFAULT_BRIDGE 0.01
#define DEFAULT_SEED_SNAP 0.05
/* A part that keeps less than this share of the area its seeds' geodesic
 * distances claim (the triangles nearest to its seeds) has collapsed: its
 * seam closed around the seed disk.  Measured with forehead + chin seeds:
 * the collapsed caps of head-gen's head keep 0.24 and 0.27 (alone and
 * with eyeballs), the good cuts of facecap and of head-gen with four seeds
 * keep 0.68 or more of their region. */
#define COLLAPSE_SHARE 0.5

struct seed { int part, face; double p[3]; int is_point; long line; };

struct options {
    const char *input, *seeds_file, *output;
    double gamma, motion, band, seed_radius, bridge, seed_snap, sym_weight, mirror[4];
    int parts, one_pass, max_cycles, no_weld, band_set, symmetric, mirror_set;
    struct seed *seeds;
    int nseeds, cap;
};

static void add_seed(struct options *o, struct seed s)
{
    if (o->nseeds == o->cap) {
        o->cap = o->cap ? 2 * o->cap : 16;
        o->seeds = realloc(o->seeds, o->cap * sizeof *o->seeds);
        if (!o->seeds) die("out of memory");
    }
    o->seeds[o->nseeds++] = s;
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"seed", 1, 0, 'S'}, {"seeds", 1, 0, 'F'}, {"gamma", 1, 0, 'g'}, {"motion", 1, 0, 'm'},
        {"band", 1, 0, 'b'}, {"seed-radius", 1, 0, 'r'}, {"parts", 1, 0, 'p'},
        {"bridge", 1, 0, 'B'}, {"seed-snap", 1, 0, 'T'}, {"symmetric", 0, 0, 'Y'},
        {"mirror", 1, 0, 'X'}, {"sym-weight", 1, 0, 'K'},
        {"one-pass", 0, 0, '1'}, {"no-weld", 0, 0, 'W'}, {"max-cycles", 1, 0, 'M'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->gamma = 100;
    o->motion = DEFAULT_MOTION;
    o->band = DEFAULT_BAND;
    o->seed_radius = DEFAULT_SEED_RADIUS;
    o->bridge = DEFAULT_BRIDGE;
    o->seed_snap = DEFAULT_SEED_SNAP;
    o->sym_weight = 1;
    int c;
    while ((c = getopt_long(argc, argv, "g:m:b:r:p:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'S': {
            char *colon = strchr(optarg, ':');
            if (!colon) usage_error("--seed wants PART:FACE, got '%s'", optarg);
            *colon = 0;
            struct seed s = {0};
            s.part = arg_int(optarg, "--seed PART");
            s.face = arg_int(colon + 1, "--seed FACE");
            if (s.part < 0) usage_error("--seed: part must be >= 0");
            add_seed(o, s);
            break;
        }
        case 'F': o->seeds_file = optarg; break;
        case 'g': o->gamma = arg_double(optarg, "--gamma"); break;
        case 'm': o->motion = arg_double(optarg, "--motion"); break;
        case 'b': o->band = arg_double(optarg, "--band"); o->band_set = 1; break;
        case 'r': o->seed_radius = arg_double(optarg, "--seed-radius"); break;
        case 'B': o->bridge = arg_double(optarg, "--bridge"); break;
        case 'T': o->seed_snap = arg_double(optarg, "--seed-snap"); break;
        case 'Y': o->symmetric = 1; break;
        case 'K': o->sym_weight = arg_double(optarg, "--sym-weight");
            if (!(o->sym_weight >= 0)) usage_error("--sym-weight must be >= 0");
            break;
        case 'X': {
            double *v;
            if (arg_doublelist(optarg, "--mirror", &v) != 4) usage_error("--mirror wants A,B,C,D (4 numbers), got '%s'", optarg);
            double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (!(len > 0) || !isfinite(len)) usage_error("--mirror: the normal A,B,C is zero");
            for (int k = 0; k < 4; k++) o->mirror[k] = v[k] / len;
            free(v);
            o->mirror_set = 1;
            break;
        }
        case 'p': o->parts = arg_int(optarg, "--parts"); break;
        case '1': o->one_pass = 1; break;
        case 'W': o->no_weld = 1; break;
        case 'M': o->max_cycles = arg_int(optarg, "--max-cycles"); break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1) usage_error("at most one input FILE");
    o->input = optind < argc ? argv[optind] : NULL;
    if (!(o->gamma >= 0) || !isfinite(o->gamma)) usage_error("--gamma must be >= 0");
    if (!(o->motion >= 0) || !isfinite(o->motion)) usage_error("--motion must be >= 0");
    if (!(o->band >= 0) || !isfinite(o->band)) usage_error("--band must be >= 0");
    if (!(o->seed_radius >= 0 && o->seed_radius < 0.5)) usage_error("--seed-radius must be in [0, 0.5)");
    if (!(o->bridge >= 0) || !isfinite(o->bridge)) usage_error("--bridge must be >= 0");
    if (!(o->seed_snap > 0) || !isfinite(o->seed_snap)) usage_error("--seed-snap must be > 0");
    if (o->parts && o->parts < 2) usage_error("--parts must be at least 2");
    if (o->max_cycles < 0) usage_error("--max-cycles must be >= 0");
    if (!o->seeds_file && o->nseeds == 0) usage_error("no seeds (--seed PART:FACE or --seeds FILE)");
}

/* "PART FACE" or "PART X Y Z" per line, '#' comments */
static void read_seeds(const char *path, struct options *o)
{
    FILE *f = !strcmp(path, "-") ? stdin : fopen(path, "r");
    if (!f) die("cannot read '%s': %s", path, strerror(errno));
    char line[1024];
    long ln = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        char *h = strchr(line, '#');
        if (h) *h = 0;
        double x[5];
        int n = 0;
        char *p = line, *e;
        while (n < 5) {
            while (isspace((unsigned char)*p)) p++;
            if (!*p) break;
            x[n] = strtod(p, &e);
            if (e == p || !isfinite(x[n]))
                die("cannot read '%s': line %ld: expected numbers 'PART FACE' or 'PART X Y Z'", path, ln);
            n++; p = e;
        }
        while (isspace((unsigned char)*p)) p++;
        if (n == 0) continue;
        if ((n != 2 && n != 4) || *p)
            die("cannot read '%s': line %ld: expected 'PART FACE' or 'PART X Y Z'", path, ln);
        struct seed s = {0};
        s.line = ln;
        if (x[0] != floor(x[0]) || x[0] < 0 || x[0] > 1e6)
            die("cannot read '%s': line %ld: part must be an integer >= 0", path, ln);
        s.part = (int)x[0];
        if (n == 2) {
            if (x[1] != floor(x[1]) || fabs(x[1]) > 2e9)
                die("cannot read '%s': line %ld: face must be an integer", path, ln);
            s.face = (int)x[1];
        } else {
            s.is_point = 1;
            s.p[0] = x[1]; s.p[1] = x[2]; s.p[2] = x[3];
        }
        add_seed(o, s);
    }
    if (ferror(f)) die("cannot read '%s': %s", path, strerror(errno));
    if (f != stdin) fclose(f);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    if (o.seeds_file) read_seeds(o.seeds_file, &o);
    if (o.nseeds == 0) die("cannot read '%s': no seeds", o.seeds_file);
    double t0 = now_seconds();

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0) die("%s", cm_errmsg());
    int nv = r.nv, nf = r.nf;
    const char *name = r.name;
    int *F = malloc(sizeof(int) * 3 * (nf ? nf : 1));
    if (!F) die("out of memory");
    memcpy(F, r.F, sizeof(int) * 3 * nf);

    /* everything that can be checked before reading frames */
    int s = 0;
    for (int i = 0; i < o.nseeds; i++) {
        if (o.seeds[i].part + 1 > s) s = o.seeds[i].part + 1;
        if (!o.seeds[i].is_point && (o.seeds[i].face < 0 || o.seeds[i].face >= nf))
            die("seed face %d out of range (the mesh has faces 0..%d)", o.seeds[i].face, nf - 1);
    }
    if (o.parts) {
        if (s > o.parts) die("seed part %d out of range (--parts %d)", s - 1, o.parts);
        s = o.parts;
    }
    if (s < 2) die("need seeds for at least 2 parts (parts are 0..s-1), got only part 0");
    int *nseed_of = calloc(s, sizeof *nseed_of);
    for (int i = 0; i < o.nseeds; i++) nseed_of[o.seeds[i].part]++;
    for (int p = 0; p < s; p++)
        if (!nseed_of[p]) die("part %d has no seed (parts are 0..%d)", p, s - 1);
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) die("%s", cm_errmsg());
    if (t.nnonmanifold > 0) {
        int e = 0;
        while (t.EFn[e] <= 2) e++;
        die("cannot segment '%s': non-manifold edge %d-%d (%d faces)", name, t.E[2 * e],
            t.E[2 * e + 1], t.EFn[e]);
    }

    /* pass 1: average (and, for --one-pass, variance and mean edge lengths) */
    double *X = malloc(sizeof(double) * 3 * (nv ? nv : 1));
    double *avg = calloc(3 * (size_t)nv + 1, sizeof *avg);
    double *m2 = o.one_pass ? calloc((size_t)nv + 1, sizeof *m2) : NULL;
    /* --one-pass: mean lengths of the input's edges, and each face corner's
     * input edge (the joined topology below may renumber the edges) */
    double *elen = o.one_pass ? calloc((size_t)t.ne + 1, sizeof *elen) : NULL;
    int *FE0 = o.one_pass ? malloc(sizeof(int) * 3 * (nf ? nf : 1)) : NULL;
    if (o.one_pass && FE0) memcpy(FE0, t.FE, sizeof(int) * 3 * nf);
    int *rep = malloc(sizeof(int) * (nv ? nv : 1));
    if (!X || !avg || !rep || (o.one_pass && (!m2 || !elen || !FE0))) die("out of memory");
    struct mesh_spool sp;
    if (!o.one_pass && mesh_spool_begin(&sp, o.input, &r) < 0) die("%s", cm_errmsg());
    struct progress pr;
    progress_start(&pr, "seg-graphcut: pass 1", r.nframes);
    int n = 0, rc, cut;
    while ((rc = mesh_reader_next(&r, X, &cut)) == 1) {
        n++;
        if (n == 1) {
            if (coincident_find(X, nv, rep) < 0) die("out of memory");
        } else
            coincident_refine(X, nv, rep);
        if (!o.one_pass) {
            if (mesh_spool_frame(&sp, X, cut) < 0) die("%s", cm_errmsg());
            for (int i = 0; i < 3 * nv; i++) avg[i] += X[i];
        } else {   /* Welford: stable running mean and squared deviation */
            double inv = 1.0 / n;
            for (int v = 0; v < nv; v++) {
                double d[3], d2 = 0;
                for (int k = 0; k < 3; k++) {
                    d[k] = X[3 * v + k] - avg[3 * v + k];
                    avg[3 * v + k] += d[k] * inv;
                    d2 += d[k] * (X[3 * v + k] - avg[3 * v + k]);
                }
                m2[v] += d2;
            }
            for (int e = 0; e < t.ne; e++)
                elen[e] += dist3(X + 3 * t.E[2 * e], X + 3 * t.E[2 * e + 1]);
        }
        progress_step(&pr, n);
    }
    progress_end(&pr);
    if (rc < 0) die("%s", cm_errmsg());
    mesh_reader_close(&r);
    if (!o.one_pass)
        for (int i = 0; i < 3 * nv; i++) avg[i] /= n;
    double diag = bbox_diagonal(avg, nv);
    if (!(diag > 0)) die("cannot segment '%s': the average mesh has an empty bounding box", name);
    double t1 = now_seconds();

    /* join UV-seam duplicates (same position in every frame) so geodesics
     * and the seam can cross texture seams; keep the input faces when the
     * joined mesh would not be a manifold */
    int *Fw = malloc(sizeof(int) * 3 * (nf ? nf : 1));
    if (!Fw) die("out of memory");
    int nwelded = 0;
    for (int v = 0; v < nv; v++) nwelded += rep[v] != v;
    if (o.no_weld || nwelded == 0) {
        memcpy(Fw, F, sizeof(int) * 3 * nf);
    } else {
        coincident_faces(F, nf, rep, Fw);
        struct topology tw;
        int built = topology_build(Fw, nf, nv, &tw) == 0, bad = !built;
        for (int f = 0; f < nf && !bad; f++)
            bad = Fw[3 * f] == Fw[3 * f + 1] || Fw[3 * f + 1] == Fw[3 * f + 2] || Fw[3 * f] == Fw[3 * f + 2];
        if (!bad) bad = tw.nnonmanifold > 0 || nonmanifold_vertices(&tw, Fw) > 0;
        if (bad) {
            info(1, "joining %d coincident vertices would make the mesh non-manifold: not joined", nwelded);
            memcpy(Fw, F, sizeof(int) * 3 * nf);
            nwelded = 0;
            if (built) topology_free(&tw);
        } else {
            info(1, "joined %d vertices that coincide in every frame (UV seams)", nwelded);
            topology_free(&t);
            t = tw;
        }
    }

    /* seed points -> nearest triangle of the average mesh; a point on an
     * edge or a vertex (a seed on the mirror plane of a symmetric head)
     * seeds every triangle that is as near, to 1e-12 of the diagonal, so
     * that no side is preferred */
    struct closest_point_tree *tree = NULL;
    int npoint = o.nseeds;
    for (int i = 0; i < npoint; i++) {
        if (!o.seeds[i].is_point) continue;
        if (!tree && !(tree = closest_point_tree_new(avg, nv, F, nf)))
            die("%s", cm_errmsg());
        double c[3], d = closest_point_query(tree, o.seeds[i].p, c, &o.seeds[i].face, NULL);
        info(2, "seed point line %ld -> face %d (distance %g)", o.seeds[i].line, o.seeds[i].face, d);
        if (!(d <= o.seed_snap * diag))
            die("cannot read '%s': line %ld: seed point %g %g %g is %.3g bbox diagonals from the surface "
                "(more than --seed-snap %g): wrong units or axes?", o.seeds_file, o.seeds[i].line,
                o.seeds[i].p[0], o.seeds[i].p[1], o.seeds[i].p[2], d / diag, o.seed_snap);
        int near[32], k = closest_point_faces_within(tree, o.seeds[i].p, d + 1e-12 * diag, near, 32);
        for (int j = 0; j < k && j < 32; j++)
            if (near[j] != o.seeds[i].face) {
                struct seed x = o.seeds[i];
                x.face = near[j];
                add_seed(&o, x);
            }
    }
    closest_point_tree_free(tree);
    int *seed_part = malloc(sizeof(int) * (nf ? nf : 1));
    for (int f = 0; f < nf; f++) seed_part[f] = -1;
    for (int i = 0; i < o.nseeds; i++) {
        int f = o.seeds[i].face, p = o.seeds[i].part;
        if (seed_part[f] >= 0 && seed_part[f] != p)
            die("face %d is a seed of both part %d and part %d", f, seed_part[f], p);
        seed_part[f] = p;
    }

    /* pass 2: Eq. 3 per interior edge, normalized to a unit bbox diagonal and
     * averaged over frames:
     *   w_e = 1/n sum_f |e_f| (1 + |x_fa - avg_a| + |x_fb - avg_b|) */
    double *w = calloc((size_t)t.ne + 1, sizeof *w);
    double *wm = calloc((size_t)t.ne + 1, sizeof *wm);
    double *dmean = calloc((size_t)nv + 1, sizeof *dmean);   /* per vertex */
    if (!w || !wm || !dmean) die("out of memory");
    if (!o.one_pass) {
        struct mesh_reader r2;
        if (mesh_spool_rewind(&sp, &r2) < 0) die("%s", cm_errmsg());
        double *dv = malloc(sizeof(double) * (nv ? nv : 1));
        if (!dv) die("out of memory");
        progress_start(&pr, "seg-graphcut: pass 2", n);
        int k = 0;
        while ((rc = mesh_reader_next(&r2, X, NULL)) == 1) {
            for (int v = 0; v < nv; v++) {
                dv[v] = dist3(X + 3 * v, avg + 3 * v) / diag;
                dmean[v] += dv[v];
            }
            for (int e = 0; e < t.ne; e++) {
                int a = t.E[2 * e], b = t.E[2 * e + 1];
                {
                    double l = dist3(X + 3 * a, X + 3 * b) / diag;
                    w[e] += l;
                    wm[e] += l * (dv[a] + dv[b]);
                }
            }
            progress_step(&pr, ++k);
        }
        progress_end(&pr);
        if (rc < 0) die("%s", cm_errmsg());
        if (k != n) die("cannot read '%s' again: %d frames, first pass had %d", name, k, n);
        mesh_reader_close(&r2);
        mesh_spool_free(&sp);
        free(dv);
        for (int e = 0; e < t.ne; e++) { w[e] /= n; wm[e] /= n; }
        for (int v = 0; v < nv; v++) dmean[v] /= n;
    } else {
        for (int v = 0; v < nv; v++) dmean[v] = sqrt(m2[v] / n) / diag;
        /* sum_f |x_f - avg| ~ n * rms (equal when the displacement magnitude
         * is constant in time; larger motions weigh more) */
        for (int f = 0; f < nf; f++)
            for (int c = 0; c < 3; c++) {
                int e = t.FE[3 * f + c], a = t.E[2 * e], b = t.E[2 * e + 1];
                double ra = sqrt(m2[a] / n), rb = sqrt(m2[b] / n);
                w[e] = elen[FE0[3 * f + c]] / n / diag;
                wm[e] = w[e] * (ra + rb) / diag;
            }
    }
    double t2 = now_seconds();
    double dmax = 0, dsum = 0;
    for (int v = 0; v < nv; v++) { dsum += dmean[v]; if (dmean[v] > dmax) dmax = dmean[v]; }
    info(2, "displacement from the average (bbox diagonals): mean %g, max %g", dsum / nv, dmax);
    /* the motion term, normalized by the largest mean displacement */
    double mu = dmax > 0 ? o.motion / dmax : 0;
    info(1, "largest mean displacement %g bbox diagonals (Eq. 3 literally = --motion %g)", dmax, dmax);
    for (int e = 0; e < t.ne; e++) w[e] += mu * wm[e];

    /* unary (Eq. 2): geodesic distance on the average mesh from each
     * triangle (mean of its corner distances) to the part's seed triangles,
     * in units of the bbox diagonal; seed triangles are fixed to their part */
    int *fcomp = malloc(sizeof(int) * (nf ? nf : 1));
    if (!fcomp) die("out of memory");
    int ncomp = connected_components(&t, Fw, fcomp);
    struct bridge *br = NULL;
    int nbr = component_bridges(avg, nv, Fw, nf, fcomp, ncomp, o.bridge * diag, &br);
    if (nbr < 0) die("cannot segment '%s': %s", name, cm_errmsg());
    /* bridge edges for the distances: every corner of f to every corner of g */
    int *BV = malloc(sizeof(int) * 18 * (nbr ? nbr : 1));
    if (!BV) die("out of memory");
    for (int i = 0; i < nbr; i++)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                BV[18 * i + 6 * a + 2 * b] = Fw[3 * br[i].f + a];
                BV[18 * i + 6 * a + 2 * b + 1] = Fw[3 * br[i].g + b];
            }
    if (ncomp > 1) {
        double far = 0;
        for (int i = 0; i < nbr; i++) if (br[i].d > far) far = br[i].d;
        info(1, "%d components, %d bridges (--bridge %g; longest %.3g bbox diagonals)", ncomp, nbr,
             o.bridge, far / diag);
    }
    struct geodesic *g = geodesic_new(avg, Fw, nv, nf);
    if (!g) die("cannot segment '%s': %s", name, cm_errmsg());
    double *U = malloc(sizeof(double) * (size_t)nf * s);
    double *D = malloc(sizeof(double) * (nv ? nv : 1));
    int *S = malloc(sizeof(int) * 3 * o.nseeds);
    if (!U || !D || !S) die("out of memory");
    for (int p = 0; p < s; p++) {
        int ns = 0;
        for (int f = 0; f < nf; f++)
            if (seed_part[f] == p)
                for (int k = 0; k < 3; k++) S[ns++] = Fw[3 * f + k];
        if (geodesic_solve(g, S, ns, D) < 0) die("cannot segment '%s': %s", name, cm_errmsg());
        /* components without a seed of p: through the bridges */
        int left = geodesic_extend(avg, Fw, nv, nf, BV, 9 * nbr, D);
        if (left < 0) die("cannot segment '%s': %s", name, cm_errmsg());
        for (int f = 0; f < nf && left; f++)
            if (!isfinite(D[Fw[3 * f]]))
                die("cannot segment '%s': face %d is in a group of components that no bridge links to a "
                    "seed of part %d: add a seed there or raise --bridge", name, f, p);
        for (int f = 0; f < nf; f++) {
            const int *T = Fw + 3 * f;
            U[(size_t)f * s + p] = (D[T[0]] + D[T[1]] + D[T[2]]) / 3 / diag;
        }
    }
    geodesic_free(g);

    /* Robustness to the seed placement (Fig. 4).  With Eq. 2 literally, a
     * triangle's preference between parts p and q is d_p - d_q: it changes
     * sign on the bisector of the seeds, so wherever the bisector crosses
     * cheap-to-cut, motionless geometry (facecap's ears) a seed moved by one
     * triangle moves the seam (20 of 36 jittered pairs differed, by up to
     * 399 triangles).  Larger gamma (200..1000) does not help here: the
     * chin seed triangle is cut out alone by its 3 short edges.  Measured
     * and rejected as well: a truncated unary min(d_p, T) (T 0.2..0.7 D: a
     * seed cut out alone, or the seam leaves the face), a band relative to
     * d_p + d_q, a band only off the seeds' axis (d_p + d_q > 1.3..1.7 D),
     * and any slope left in the band (0.2..0.5 of Eq. 2: 8..16 of 36).  The seeds should only pick the sides, the seam goes
     * where the motion is small and the cut short.  So:
     *  - dead band: u_p = max(0, d_p - min_q d_q - B D), i.e. no preference
     *    where the distances to two parts differ by less than B D; there the
     *    binary term alone places the seam, whatever the seeds' exact spot;
     *  - seed disks: triangles within R D of a seed of part p are fixed to
     *    p.  Without them, a single seed triangle is cut out by its 3 short
     *    edges as soon as the unary is weak near it (what larger gamma did);
     *  D = the distance between the nearest seeds of two different parts.
     * Subtracting min_q d_q (a per-triangle constant) does not change the
     * minimizer, so -b 0 -r 0 is Eq. 2 exactly.  Components without seeds
     * (eyes, teeth) have their distances through the bridges (above), and
     * the bridges join the dual graph below: such a component takes the
     * part of the surface it touches, not that of the nearest seed in a
     * straight line (which put half of a production head's triangles where
     * the seam left them). */
    /* raw distances, kept for a retry with a narrower band */
    double *U0 = malloc(sizeof(double) * (size_t)nf * s + 1);
    int *disk = malloc(sizeof(int) * (nf ? nf : 1));
    int *nearest = malloc(sizeof(int) * (nf ? nf : 1));    /* part of the nearest seed */
    double *A = malloc(sizeof(double) * (nf ? nf : 1)), atot = 0;
    if (!U0 || !disk || !nearest || !A) die("out of memory");
    memcpy(U0, U, sizeof(double) * (size_t)nf * s);
    /* --symmetric: the mirror plane, every triangle's mirror triangle; the
     * seam costs (w) and seed distances (U0) averaged with their mirror's */
    double plane[4];
    int *mf = NULL;
    double tm0 = now_seconds();
    if (o.mirror_set || o.symmetric) {
        double prms, pworst;
        if (o.mirror_set) {
            memcpy(plane, o.mirror, sizeof plane);
            prms = mirror_plane_rms(avg, nv, Fw, nf, plane);
            if (isnan(prms)) die("cannot segment '%s': %s", name, cm_errmsg());
            info(1, "mirror plane %.6g %.6g %.6g %.6g (given): reflected vertices %.3g%% of the diagonal "
                 "from the surface (RMS)", plane[0], plane[1], plane[2], plane[3], 100 * prms / diag);
        } else {
            if (mirror_plane_find(avg, nv, Fw, nf, 0, plane, &prms, &pworst) < 0)
                die("cannot segment '%s': %s", name, cm_errmsg());
            info(1, "mirror plane %.6g,%.6g,%.6g,%.6g (found): reflected vertices %.3g%% of the diagonal "
                 "from the surface (RMS of the closest 90%%, largest %.3g%%)", plane[0], plane[1], plane[2],
                 plane[3], 100 * prms / diag, 100 * pworst / diag);
        }
        if (o.symmetric && prms > 0.05 * diag)
            die("cannot segment '%s': the mesh is not mirror symmetric about the %s plane (reflected vertices "
                "%.3g%% of the diagonal from the surface, RMS)%s", name, o.mirror_set ? "given" : "found",
                100 * prms / diag, o.mirror_set ? "" : "; give --mirror if the plane is known");
        if (prms > 0.01 * diag)
            warn("the mesh is only roughly symmetric about the mirror plane: reflected vertices %.3g%% of the "
                 "diagonal from the surface (RMS)", 100 * prms / diag);
    }
    if (o.symmetric) {
        mf = malloc(sizeof(int) * (nf ? nf : 1));
        double *tmp = malloc(sizeof(double) * ((size_t)nf * s + t.ne + 1));
        if (!mf || !tmp) die("out of memory");
        if (mirror_faces(avg, nv, Fw, nf, plane, mf, NULL) < 0) die("cannot segment '%s': %s", name, cm_errmsg());
        for (size_t k = 0; k < (size_t)nf * s; k++) {
            size_t f = k / s, p = k % s, g = (size_t)mf[f] * s + p;
            tmp[k] = isfinite(U0[k]) && isfinite(U0[g]) ? 0.5 * (U0[k] + U0[g]) : U0[k];
        }
        memcpy(U0, tmp, sizeof(double) * (size_t)nf * s);
        int paired = 0;
        for (int e = 0; e < t.ne; e++) {
            tmp[e] = w[e];
            if (t.EFn[e] != 2) continue;
            int h1 = mf[t.EF[2 * e]], h2 = mf[t.EF[2 * e + 1]];
            for (int c = 0; c < 3; c++) {
                int e2 = t.FE[3 * h1 + c];
                if (t.EFn[e2] == 2 && (t.EF[2 * e2] == h2 || t.EF[2 * e2 + 1] == h2)) {
                    tmp[e] = 0.5 * (w[e] + w[e2]);
                    paired++;
                    break;
                }
            }
        }
        memcpy(w, tmp, sizeof(double) * t.ne);
        free(tmp);
        info(1, "--symmetric: %d of %d interior edges averaged with their mirror edge (plane and mirror map %.3f s)",
             paired, t.ne - t.nboundary, now_seconds() - tm0);
    }
    face_areas(avg, F, nf, A);
    for (int f = 0; f < nf; f++) atot += A[f];
    if (!(atot > 0)) die("cannot segment '%s': the average mesh has zero area", name);
    double band = o.band, band0 = o.band, share0 = 0;
    int collapsed0 = -1;
retry:
    memcpy(U, U0, sizeof(double) * (size_t)nf * s);
    double dseeds = INFINITY;
    for (int f = 0; f < nf; f++)
        if (seed_part[f] >= 0)
            for (int p = 0; p < s; p++)
                if (p != seed_part[f] && U[(size_t)f * s + p] < dseeds) dseeds = U[(size_t)f * s + p];
    int ndisk = 0;
    for (int f = 0; f < nf; f++) {
        double *u = U + (size_t)f * s, m = INFINITY;
        disk[f] = -1;
        nearest[f] = 0;
        for (int p = 0; p < s; p++)
            if (u[p] < m) {
                m = u[p];
                nearest[f] = p;
                if (isfinite(dseeds) && m < o.seed_radius * dseeds) disk[f] = p;
            }
        ndisk += disk[f] >= 0 && seed_part[f] < 0;
        for (int p = 0; p < s; p++)
            if (isfinite(u[p])) u[p] = fmax(0, u[p] - m - band * dseeds);
    }
    if (isfinite(dseeds))
        info(1, "seed distance D %g bbox diagonals: band %g D, %d triangles in seed disks of radius %g D",
             dseeds, band, ndisk, o.seed_radius);
    else
        info(1, "the parts' seeds lie in different components: no band, no seed disks");
    for (int f = 0; f < nf; f++) {
        /* area weight: as if the surface had UNARY_TRIANGLES equal triangles */
        for (int p = 0; p < s; p++) U[(size_t)f * s + p] *= UNARY_TRIANGLES * A[f] / atot;
        int fix = seed_part[f] >= 0 ? seed_part[f] : disk[f];
        if (fix >= 0)
            for (int p = 0; p < s; p++) U[(size_t)f * s + p] = p == fix ? 0 : INFINITY;
    }
    double t3 = now_seconds();

    /* Eq. 1 by alpha-expansion over the dual graph (interior edges) */
    int ne = 0;
    int *E = malloc(sizeof(int) * 2 * ((size_t)t.ne + nbr + (mf ? nf : 0) + 1));
    double *W = malloc(sizeof(double) * ((size_t)t.ne + nbr + (mf ? nf : 0) + 1));
    if (!E || !W) die("out of memory");
    for (int e = 0; e < t.ne; e++)
        if (t.EFn[e] == 2) {
            E[2 * ne] = t.EF[2 * e]; E[2 * ne + 1] = t.EF[2 * e + 1];
            W[ne++] = o.gamma * w[e];
        }
    /* a bridge costs what cutting one edge of its two triangles costs on
     * average (Eq. 3 with the motion of those edges) */
    for (int i = 0; i < nbr; i++) {
        double c = 0;
        for (int k = 0; k < 3; k++) c += w[t.FE[3 * br[i].f + k]] + w[t.FE[3 * br[i].g + k]];
        E[2 * ne] = br[i].f; E[2 * ne + 1] = br[i].g;
        W[ne++] = o.gamma * c / 6;
    }
    /* --symmetric: each triangle tied to its mirror (a Potts term: cutting
     * the pair costs sym_weight mean seam-edge costs) */
    if (mf && o.sym_weight > 0) {
        double wsum = 0;
        int nin = 0;
        for (int e = 0; e < t.ne; e++) if (t.EFn[e] == 2) { wsum += w[e]; nin++; }
        double tie = o.sym_weight * o.gamma * (nin ? wsum / nin : 0);
        for (int f = 0; f < nf; f++)
            if (mf[f] != f) {
                E[2 * ne] = f; E[2 * ne + 1] = mf[f];
                W[ne++] = tie;
            }
    }
    int *L = malloc(sizeof(int) * (nf ? nf : 1));
    struct alpha_expansion_stats st;
    if (alpha_expansion(nf, s, U, ne, E, W, L, 0, o.max_cycles, &st) < 0)
        die("cannot segment '%s': %s", name, cm_errmsg());
    double t4 = now_seconds();
    int *count = calloc(s, sizeof *count);
    for (int f = 0; f < nf; f++) count[L[f]]++;
    for (int p = 0; p < s; p++)
        if (!count[p]) warn("part %d is empty", p);
    /* a part far smaller than the region nearest to its seeds: its seam
     * closed around the seed disk, a short loop in still skin */
    double *areq = calloc(2 * (size_t)s, sizeof *areq);   /* nearest area, labeled area */
    if (!areq) die("out of memory");
    for (int f = 0; f < nf; f++) {
        areq[2 * nearest[f]] += A[f];
        areq[2 * L[f] + 1] += A[f];
    }
    for (int p = 0; p < s; p++)
        info(1, "part %d: %.1f%% of the area, %.1f%% nearest to its seeds", p, 100 * areq[2 * p + 1] / atot,
             100 * areq[2 * p] / atot);
    int collapsed = -1;
    for (int p = 0; p < s && collapsed < 0; p++)
        if (count[p] && areq[2 * p + 1] < COLLAPSE_SHARE * areq[2 * p]) collapsed = p;
    if (collapsed >= 0 && !o.band_set && band > 0) {
        /* the dead band left the seam free to close a short loop around
         * the seed: a narrower band ties the parts to their regions */
        if (collapsed0 < 0) {
            collapsed0 = collapsed;
            share0 = areq[2 * collapsed + 1] / areq[2 * collapsed];
        }
        info(1, "part %d collapsed with band %g: trying a narrower band", collapsed, band);
        band = band > BAND_STEP + 1e-9 ? band - BAND_STEP : 0;
        free(E); free(W); free(L); free(count); free(areq);
        goto retry;
    }
    if (collapsed >= 0)
        warn("part %d collapsed to its seed: %.0f%% of the area nearest to its seeds (%.1f%% of the "
             "model%s); add seeds of part %d on the far side of the intended seam (for a head: back of "
             "the skull for the upper part, nape for the lower part) or lower --gamma",
             collapsed, 100 * areq[2 * collapsed + 1] / areq[2 * collapsed],
             100 * areq[2 * collapsed + 1] / atot, o.band_set ? "" : ", down to band 0", collapsed);
    else if (collapsed0 >= 0)
        warn("part %d collapsed to its seed with band %g (%.0f%% of the area nearest to its seeds): cut "
             "with --band %g instead, where it keeps %.0f%%; seeds on the far side of the seam (back of "
             "the skull, nape) keep the default band", collapsed0, band0, 100 * share0, band,
             100 * areq[2 * collapsed0 + 1] / areq[2 * collapsed0]);
    free(areq);
    free(A);
    free(nearest);
    free(disk);
    free(U0);

    info(1, "%d vertices, %d triangles, %d frames, %d parts, bbox diagonal %g", nv, nf, n, s, diag);
    info(1, "energy %.9g = unary %.9g + binary %.9g (gamma %g), %d cycles, %d moves",
         st.unary + st.binary, st.unary, st.binary, o.gamma, st.cycles, st.moves);
    for (int p = 0; p < s; p++) info(1, "part %d: %d triangles", p, count[p]);
    info(1, "time: frames %.3f s, edge costs %.3f s, geodesics %.3f s, alpha-expansion %.3f s, total %.3f s",
         t1 - t0, t2 - t1, t3 - t2, t4 - t3, t4 - t0);

    if (o.mirror_set || o.symmetric) {
        /* the seam's asymmetry: Hausdorff distance between the seam (its
         * edges on the average mesh) and its mirror */
        double *P = malloc(sizeof(double) * 6 * ((size_t)t.ne + 1));
        int nseam = 0, unlike = 0;
        if (!P) die("out of memory");
        for (int e = 0; e < t.ne; e++) {
            if (t.EFn[e] != 2 || L[t.EF[2 * e]] == L[t.EF[2 * e + 1]]) continue;
            const double *a = avg + 3 * t.E[2 * e], *b = avg + 3 * t.E[2 * e + 1];
            for (int k = 0; k < 3; k++) { P[6 * nseam + k] = a[k]; P[6 * nseam + 3 + k] = b[k]; }
            nseam++;
        }
        double h = mirror_hausdorff(P, nseam, plane);
        free(P);
        if (mf) for (int f = 0; f < nf; f++) unlike += L[f] != L[mf[f]];
        info(1, "seam asymmetry: Hausdorff distance to its mirror %.4g%% of the bbox diagonal (%d seam edges)%s",
             100 * h / diag, nseam, o.symmetric ? "" : " [measured only: add --symmetric]");
        if (mf) info(1, "--symmetric: %d of %d triangles labelled unlike their mirror triangle", unlike, nf);
    }
    free(mf);

    FILE *out = out_open(o.output);
    if (labels_write(out, L, nf) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    free(X); free(avg); free(m2); free(elen); free(FE0); free(rep); free(Fw); free(w); free(wm); free(dmean); free(U); free(D); free(S);
    free(E); free(W); free(fcomp); free(br); free(BV); free(L); free(count); free(seed_part); free(nseed_of);
    free(o.seeds); free(F);
    topology_free(&t);
    return 0;
}
