/* compat-tri -- N-way compatible triangulation of outlines (Baxter, Barla,
 * Anjyo, N-way morphing, Sec. 3.1): N ring files + correspondence points ->
 * one MESH animation of N frames sharing one face list.
 */
#include "compat_tri.h"
#include "compat_holes.h"
#include "compat_refine.h"
#include "boundary_match.h"
#include "modulus_match.h"
#include "modulus_cert.h"
#include "procrustes.h"
#include "columns.h"
#include "mesh.h"
#include "rings.h"
#include "topology.h"
#include "tool.h"
#include "progress.h"
#include "parallel.h"
#include "cm_error.h"
#include "blas_tune.h"
#include <limits.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <getopt.h>

static const char help[] =
"Usage: compat-tri [-c CORR] [options] SHAPE0 SHAPE1 ...\n"
"Compatible triangulation of N outlines (ring files): one MESH stream of N\n"
"frames with one face list, frame i = shape i.  Outlines may have holes and\n"
"several pieces, matched ring by ring (same rings in the same order).\n"
"\n"
"  -c, --corr FILE       correspondence points (- : stdin): one row per point,\n"
"                        N columns, column i = vertex index (0-based) in\n"
"                        SHAPEi's file\n"
"                        (points of all rings counted in file order); one\n"
"                        outer ring: at least 3 rows, in the same order along\n"
"                        every outline (0 rows or no -c, 1 or 2 rows: the rest\n"
"                        are found by --match); several rings: each row on one ring,\n"
"                        a ring with 0-2 rows is matched on its own (-m off:\n"
"                        from its first vertex), one with 3 or more is kept;\n"
"                        a round ring without rows turns as the rings around it\n"
"  -i, --interior FILE   interior correspondence points: one row per point,\n"
"                        2N columns x0 y0 x1 y1 ... (the point in SHAPE0,\n"
"                        SHAPE1, ...); each becomes one vertex at exactly\n"
"                        those positions\n"
"      --layers[=MODE]   every ring is a layer of the drawing, triangulated on\n"
"                        its own: rings may overlap (a leg drawn over the body\n"
"                        in one pose and apart in another), no ring is a hole;\n"
"                        the faces are written layer by layer, the first ring's\n"
"                        first (drawn first, at the back); not with -i.  MODE\n"
"                        'each' (default: every layer meshed as one outline,\n"
"                        with the rows of -c on its ring and the race of\n"
"                        matchings) or 'joint' (one matching and refinement\n"
"                        of all rings, as for pieces)\n"
"      --match-rings M   how rings are paired across shapes: 'order' (default:\n"
"                        ring k with ring k) or 'nearest' (each shape's rings\n"
"                        reordered to SHAPE0's by nesting and nearest mean\n"
"                        vertex, e.g. for frames traced by img2rings)\n"
"  -m, --match MODE      'multiscale' (default: Baxter et al.'s optimized\n"
"                        boundary mapping by dynamic programming, stretch plus a\n"
"                        multi-scale turning term so legs, ears and notches meet\n"
"                        their like; it passes through the given rows, and\n"
"                        without rows the start is found by trying every cyclic\n"
"                        shift), 'elastic' (the paper's cost: stretch and\n"
"                        bending, Sebastian et al.), 'arclength' (baseline: the\n"
"                        same points placed by arc length from the given rows) or\n"
"                        'off' (3 or more rows: only the given rows, arc length\n"
"                        between them: the earlier default); no -m and the\n"
"                        matched points not at --min-angle after 3 rounds:\n"
"                        'off' (3 or more rows) is refined beside them, and\n"
"                        once no first pass is at the goal the matching with\n"
"                        twice --match-points and the same with --spread 3;\n"
"                        the least work first, one falling behind dropped,\n"
"                        the first at the goal kept (-v); all below it: (3 or\n"
"                        more rows) the matched points moved by\n"
"                        --match-polish 64 too, the best kept (beside 'off'\n"
"                        from the start where the given rows force a stretch\n"
"                        of 4x or more: CERTIFICATE in man compat-tri)\n"
"      --match-points K  correspondence points placed by the matching: the given\n"
"                        rows plus SHAPE0's most salient corners (default 12;\n"
"                        given, no matching with twice K is tried)\n"
"      --bend R          weight of the bending term of the matching (default 0.03)\n"
"      --feature F       weight of the multi-scale turning term (default 10)\n"
"      --spread S        weight of the matching's spread term: each step's\n"
"                        stretch ratio against its segment's mean ratio, so a\n"
"                        segment's stretch is spread along it (default 0: off;\n"
"                        given, no candidate with --spread 3 is tried)\n"
"      --match-polish N  move the points the matching placed (not the given\n"
"                        rows) along the outlines, at most N steps of up to 3\n"
"                        input points, each lowering the largest ratio of\n"
"                        quadrilateral moduli between poses (the stretch they\n"
"                        force: see CERTIFICATE in man compat-tri); default:\n"
"                        none, but a default run with 3 or more rows still\n"
"                        below --min-angle tries the matched points with 64\n"
"                        steps (last, or early: see -m); given, every matching\n"
"                        of the run is polished and that candidate left out\n"
"                        (0: no polish)\n"
"      --points-out FILE write the correspondence points used (a -c file, indices\n"
"                        in file order) to FILE, to look at (mesh2svg\n"
"                        --points-file) and edit\n"
"  -e, --error E         outline tolerance: two-sided Hausdorff distance of\n"
"                        the simplified to the input outline, as a fraction\n"
"                        of each pose's bounding-box diagonal (default 0.005;\n"
"                        0: keep every input point)\n"
"  -l, --edge-length L   refine interior edges to L times the mean boundary\n"
"                        edge length (default 3; 0: no refinement)\n"
"  -s, --smooth N        smoothing + flip rounds (default 10; 0: none)\n"
"                        (-l and -s: --refine none, and holes/pieces)\n"
"      --refine MODE     'refine' (default: compatible refinement, Surazhsky-\n"
"                        Gotsman: edge splits in all poses, compatible flips,\n"
"                        per-pose MIPS and smallest-angle smoothing, a\n"
"                        max-min polish of the worst angles, until\n"
"                        every angle of every pose reaches --min-angle,\n"
"                        --max-vertices is reached or the splitting stalls\n"
"                        (then back to the best round; -v says why and where;\n"
"                        edge collapses coarsen the result),\n"
"                        'sg' (the same without the MIPS smoothing,\n"
"                        collapses and stall detection: the paper's local\n"
"                        smoothing only) or 'none' (-l and -s)\n"
"  -a, --min-angle DEG   goal of --refine (default 20; capped by the sharpest\n"
"                        outline corner; a mesh below it gets a warning)\n"
"      --max-vertices K  --refine stops splitting at K vertices (default: the\n"
"                        triangulation's vertices plus 10 times the simplified\n"
"                        outline's vertex count)\n"
"      --split-share F   a --refine that ends below --min-angle is run again\n"
"                        from its start, splitting after 3 rounds only the\n"
"                        worst share F of the triangles below the goal each\n"
"                        round, and if that too ends below it, a third time\n"
"                        the same with each bad triangle split at the edge\n"
"                        whose halves are best over every pose; the best\n"
"                        pass is kept (default 0.2; 1: one pass only)\n"
"      --slide WHEN      in the max-min polish of --refine, outline vertices\n"
"                        that are not given points slide along their own\n"
"                        pose's input outline (within -e, pose by pose):\n"
"                        'rerun' (default: in the passes of --split-share run\n"
"                        again after a first pass below the goal; a mesh at\n"
"                        the goal after its first pass is unchanged; a result\n"
"                        still below the goal also gets a global polish in\n"
"                        which they slide all at once), 'all' (every pass,\n"
"                        and the global polish), 'local' (as 'rerun' without\n"
"                        the global polish with slides) or 'off' (outline\n"
"                        vertices stay where the matching put them)\n"
"      --threads N       the boundary matching, the triangulation's split\n"
"                        search and the refinement's smoothing run on N\n"
"                        threads (default 0: one per core); the output does\n"
"                        not depend on N\n"
"      --split MODE      pieces that no common diagonal or single Steiner point\n"
"                        splits: 'overlay' (default: overlay of the shapes'\n"
"                        Delaunay triangulations, always succeeds),\n"
"                        'overlay-fewest' (the same with the triangulations\n"
"                        chosen to cross least: fewer Steiner points) or\n"
"                        'linkpath' (the paper's Steiner paths; can fail on\n"
"                        thin pieces)\n"
"      --bound           print the certificate of the given points (-c, one\n"
"                        outer ring per shape, 4 or more rows) on stdout and\n"
"                        exit without meshing: a proven upper bound on the\n"
"                        worst angle any compatible triangulation can reach\n"
"                        (also printed by -v; man compat-tri, CERTIFICATE)\n"
"      --raw             raw (binary) MESH output (or STOPMO_RAW=1)\n"
"  -o, --output FILE     write to FILE (temporary + rename)\n"
"  -v, --verbose         print counts, Steiner points, minimum angle, time\n"
"  -h, --help, --version\n"
"\n"
"Example: compat-tri -v -c corr.txt pose1.rings pose2.rings | mesh2svg -g >t.svg\n";

enum { LAYERS_EACH = 1, LAYERS_JOINT = 2 };
/* the rows --points-out would write (write_points): n by N, file order */
struct kept_points { int *rows, n; };

struct options {
    const char *corr, *output, *interior, *points_out;
    int match, match_points, match_default, match_auto;   /* match_auto: no -m (the matching by default) */
    int match_points_given;   /* --match-points on the command line: no denser candidate */
    int mpolish;              /* --match-polish: steps of modulus_match_polish on the matched points */
    int mpolish_given;        /* on the command line: no polish candidate (0: none at all) */
    int mpolish_soft;         /* the candidate: a polish that fails leaves it out, not an error */
    int spread_given;         /* --spread on the command line: no spread candidate */
    double bend, feature, spread;
    double err, edge;
    int smooth, raw, split, nearest, refine, max_nv, threads, bound;
    int layers;               /* --layers: every ring a layer (compat_layers): LAYERS_EACH, LAYERS_JOINT */
    const struct columns *corr_rows;   /* non-NULL: the rows of -c (corr_read), o->corr only names them */
    struct kept_points *points_mem;    /* non-NULL: --points-out's rows kept here, not written (write_points) */
    int layer;                         /* mesh_layers: the ring (1-based) being meshed, for messages; 0: none */
    double min_angle, split_share;
    double sharp_in;      /* degrees: the input outlines' sharpest corner (one ring each; else 0) */
    int slide;        /* --slide: 0 off, 1 in the passes run again, 2 in every pass, 3 as 1
                         without the global polish with slides */
    int nshapes;
    char **shapes;
    char *log;             /* non-NULL: build_single's -v lines go here (LOG_SIZE bytes) */
    const int *flipped;    /* one outer ring: per shape, 1 if its file runs clockwise (reversed in R) */
    double forced;         /* the certificate's lower bound of the stretch the given points force
                            * (certify; 0: fewer than 4 rows, -1: not computed) */
    long cert_meshes;      /* its cost: quadruples of given rows times shapes (certify) */
};
#define LOG_SIZE 4096
/* relative width of the certificate's modulus brackets */
#define CERT_TOL 0.03

/* a -v line of build_single: on stderr, or kept in o->log for later */
static void __attribute__((format(printf, 2, 3))) binfo(const struct options *o, const char *fmt, ...)
{
    char line[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (!o->log) { info(1, "%s", line); return; }
    size_t n = strlen(o->log);
    snprintf(o->log + n, LOG_SIZE - n, "%s\n", line);
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"corr", 1, 0, 'c'}, {"interior", 1, 0, 'i'}, {"error", 1, 0, 'e'}, {"edge-length", 1, 0, 'l'},
        {"smooth", 1, 0, 's'}, {"split", 1, 0, 'S'}, {"match-rings", 1, 0, 'M'},
        {"refine", 1, 0, 'Q'}, {"min-angle", 1, 0, 'a'}, {"max-vertices", 1, 0, 'X'}, {"threads", 1, 0, 'T'}, {"raw", 0, 0, 'R'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {"match", 1, 0, 'm'},
        {"match-points", 1, 0, 'K'}, {"bend", 1, 0, 'B'}, {"points-out", 1, 0, 'P'}, {"feature", 1, 0, 'F'}, {"bound", 0, 0, 'b'},
        {"spread", 1, 0, 'W'}, {"match-polish", 1, 0, 'G'},
        {"split-share", 1, 0, 'H'}, {"slide", 1, 0, 'L'}, {"layers", 2, 0, 'Y'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->err = 0.005; o->edge = 3; o->smooth = 10; o->refine = 1; o->min_angle = 20; o->split_share = 0.2;
    o->slide = 1;
    o->forced = -1;
    o->match = -1; o->match_points = 12; o->bend = 0.03; o->feature = 10;
    int c;
    while ((c = getopt_long(argc, argv, "c:i:e:l:s:a:o:m:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'c': o->corr = optarg; break;
        case 'i': o->interior = optarg; break;
        case 'Y':
            if (!optarg || !strcmp(optarg, "each")) o->layers = LAYERS_EACH;
            else if (!strcmp(optarg, "joint")) o->layers = LAYERS_JOINT;
            else usage_error("--layers: '%s' is not 'each' or 'joint'", optarg);
            break;
        case 'e': o->err = arg_double(optarg, "--error"); break;
        case 'l': o->edge = arg_double(optarg, "--edge-length"); break;
        case 's': o->smooth = arg_int(optarg, "--smooth"); break;
        case 'S':
            if (!strcmp(optarg, "overlay")) o->split = COMPAT_OVERLAY;
            else if (!strcmp(optarg, "overlay-fewest")) o->split = COMPAT_OVERLAY_FEWEST;
            else if (!strcmp(optarg, "linkpath")) o->split = COMPAT_LINKPATH;
            else usage_error("--split must be 'overlay', 'overlay-fewest' or 'linkpath'");
            break;
        case 'M':
            if (!strcmp(optarg, "order")) o->nearest = 0;
            else if (!strcmp(optarg, "nearest")) o->nearest = 1;
            else usage_error("--match-rings must be 'order' or 'nearest'");
            break;
        case 'Q':
            if (!strcmp(optarg, "refine")) o->refine = 1;
            else if (!strcmp(optarg, "sg")) o->refine = 2;
            else if (!strcmp(optarg, "none")) o->refine = 0;
            else usage_error("--refine must be 'refine', 'sg' or 'none'");
            break;
        case 'a': o->min_angle = arg_double(optarg, "--min-angle"); break;
        case 'X': o->max_nv = arg_int(optarg, "--max-vertices"); break;
        case 'H': o->split_share = arg_double(optarg, "--split-share"); break;
        case 'L':
            if (!strcmp(optarg, "off")) o->slide = 0;
            else if (!strcmp(optarg, "rerun")) o->slide = 1;
            else if (!strcmp(optarg, "all")) o->slide = 2;
            else if (!strcmp(optarg, "local")) o->slide = 3;
            else usage_error("--slide must be 'off', 'local', 'rerun' or 'all'");
            break;
        case 'T': o->threads = arg_int(optarg, "--threads"); break;
        case 'R': o->raw = 1; break;
        case 'm':
            if (!strcmp(optarg, "multiscale")) o->match = BMATCH_MULTISCALE;
            else if (!strcmp(optarg, "elastic")) o->match = BMATCH_ELASTIC;
            else if (!strcmp(optarg, "arclength")) o->match = BMATCH_ARCLENGTH;
            else if (!strcmp(optarg, "off")) o->match = -2;
            else usage_error("--match must be 'multiscale', 'elastic', 'arclength' or 'off'");
            break;
        case 'K': o->match_points = arg_int(optarg, "--match-points"); o->match_points_given = 1; break;
        case 'B': o->bend = arg_double(optarg, "--bend"); break;
        case 'F': o->feature = arg_double(optarg, "--feature"); break;
        case 'W': o->spread = arg_double(optarg, "--spread"); o->spread_given = 1; break;
        case 'G': o->mpolish = arg_int(optarg, "--match-polish"); o->mpolish_given = 1; break;
        case 'P': o->points_out = optarg; break;
        case 'b': o->bound = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (o->match_points < 3 || o->match_points > 1000) usage_error("--match-points must be in 3..1000");
    if (!(o->bend >= 0 && o->bend < 1e6)) usage_error("--bend must be >= 0");
    if (!(o->feature >= 0 && o->feature < 1e6)) usage_error("--feature must be >= 0");
    if (!(o->spread >= 0 && o->spread < 1e6)) usage_error("--spread must be >= 0");
    if (o->mpolish < 0 || o->mpolish > 100000) usage_error("--match-polish must be in 0..100000");
    if (o->mpolish > 0 && o->match == -2) usage_error("--match-polish moves the matched points: not with --match off");
    if (!o->corr && o->match == -2) usage_error("--match off needs -c CORR with at least 3 rows");
    if (!o->corr && o->match == BMATCH_ARCLENGTH) usage_error("--match arclength needs -c CORR (a start point)");
    if (o->bound && !o->corr) usage_error("--bound needs -c CORR (the given points)");
    if (!(o->err >= 0 && o->err < 1)) usage_error("--error must be in [0, 1)");
    if (!(o->edge >= 0 && o->edge < 1e6)) usage_error("--edge-length must be >= 0");
    if (o->smooth < 0 || o->smooth > 10000) usage_error("--smooth must be in 0..10000");
    if (!(o->min_angle > 0 && o->min_angle <= 60)) usage_error("--min-angle must be in (0, 60] degrees");
    if (o->max_nv < 0) usage_error("--max-vertices must be >= 0");
    if (!(o->split_share > 0 && o->split_share <= 1)) usage_error("--split-share must be in (0, 1]");
    if (o->threads < 0) usage_error("--threads must be >= 0");
    o->nshapes = argc - optind;
    o->shapes = argv + optind;
    if (o->nshapes < 1) usage_error("expected at least one SHAPE file");
    int stdins = 0;
    for (int i = 0; i < o->nshapes; i++)
        if (!strcmp(o->shapes[i], "-")) {
            if (o->nshapes > 1) usage_error("stdin can be only the single shape");
            stdins++;
        }
    stdins += o->corr && !strcmp(o->corr, "-");
    stdins += o->interior && !strcmp(o->interior, "-");
    if (stdins > 1) usage_error("stdin ('-') can be only one of the SHAPE, -c and -i files");
    /* a point inside two overlapping layers has no one piece */
    if (o->layers && o->interior) usage_error("--layers and -i cannot be combined");
}

/* file line of data row k (1-based) of a column file, for messages;
 * 0 if the file cannot be read again (stdin) */
static long data_line(const char *path, int k)
{
    FILE *f = path && strcmp(path, "-") ? fopen(path, "r") : NULL;
    if (!f) return 0;
    char buf[4096];
    long line = 0, ans = 0;
    int row = 0, fresh = 1;
    while (fgets(buf, sizeof buf, f)) {
        if (fresh) {
            line++;
            const char *p = buf + strspn(buf, " \t\r");
            if (*p && *p != '\n' && *p != '#' && ++row == k) { ans = line; break; }
        }
        fresh = strchr(buf, '\n') != NULL;
    }
    fclose(f);
    return ans;
}

/* "row K: ..." from libcommon -> die naming the file and line */
static void die_row(const char *path)
{
    const char *m = cm_errmsg();
    int k;
    long line;
    if (sscanf(m, "row %d:", &k) == 1 && (line = data_line(path, k)) > 0)
        die("cannot read '%s': line %ld:%s", path, line, strchr(m, ':') + 1);
    die("cannot read '%s': %s", path, m);
}

/* The rows of -c as columns_read gives them.  Every candidate of the race
 * reads them again, so "-c -" (stdin) is read once, by corr_stdin before
 * any thread starts, and each read gets a copy. */
static struct columns corr_kept;
static int corr_kept_ok;

static void corr_stdin(const struct options *o)
{
    if (!o->corr || strcmp(o->corr, "-")) return;
    if (columns_read("-", 0, -1, NULL, &corr_kept) < 0) die("%s", cm_errmsg());
    corr_kept_ok = 1;
}

/* the rows of -c into C: read from o->corr, or a copy of o->corr_rows
 * (--layers: a layer's) or of the rows read from stdin */
static int corr_read(const struct options *o, int want_cols, struct columns *C)
{
    const struct columns *K = o->corr_rows ? o->corr_rows : &corr_kept;
    if (!o->corr_rows && (strcmp(o->corr, "-") || !corr_kept_ok)) return columns_read(o->corr, want_cols, -1, NULL, C);
    if (want_cols > 0 && K->rows > 0 && K->cols != want_cols)
        return cm_seterr("cannot read '<stdin>': its first row: expected %d number%s, got %d", want_cols,
                         want_cols == 1 ? "" : "s", K->cols);
    *C = *K;
    size_t sz = (size_t)K->rows * K->cols * sizeof *C->x;
    if (!(C->x = malloc(sz ? sz : 1))) return cm_seterr("out of memory");
    memcpy(C->x, K->x, sz);
    return 0;
}

/* seconds since the start (the -v lines say when each stage ended) */
static double t_start;
static double elapsed(void) { return now_seconds() - t_start; }

/* The certificate of nc correspondence rows (corr: nc by N, counter-
 * clockwise; row[k]: their 1-based rows in the file named name; who: what
 * they are, for the line) as one line into line (size len); the cost goes
 * to -v.  Returns the ceiling in degrees (60: none; -1: not computed, the
 * line says why: -v goes on without it, --bound refuses) */
static double cert_line(int N, double **P, const int *n, const int *corr, int nc, const int *row, const char *name,
                        const char *who, char *line, size_t len, double *ratio)
{
    struct modulus_cert mc;
    *ratio = 0;
    if (modulus_certificate(N, P, n, corr, nc, CERT_TOL, &mc) < 0) {
        snprintf(line, len, "certificate: not computed: %s", cm_errmsg());
        return -1;
    }
    if (nc < 4) {
        snprintf(line, len, "certificate: %d point%s given in every shape; 4 are needed for a bound on the angles",
                 nc, nc == 1 ? "" : "s");
        return mc.ceiling;
    }
    *ratio = mc.ratio;
    int wl = (int)strcspn(who, "(");   /* without the parenthesis */
    while (wl > 0 && who[wl - 1] == ' ') wl--;
    info(1, "certificate: %d quadruples of %.*s in %d shapes, brackets to %g, largest mesh %d vertices; at %.3f s",
         mc.quads, wl, who, N, CERT_TOL, mc.nv, elapsed());
    int r[4];
    for (int t = 0; t < 4; t++) r[t] = row[mc.row[t]];
    for (int a = 0; a < 4; a++)   /* increasing file rows */
        for (int b = a + 1; b < 4; b++)
            if (r[b] < r[a]) { int t = r[a]; r[a] = r[b]; r[b] = t; }
    snprintf(line, len, "certificate: %s force a map stretch of at least %.3gx between poses %d and %d "
             "(rows %d %d %d %d of %s: modulus %.4g-%.4g against %.4g-%.4g): no compatible triangulation%s keeps "
             "more than %.1f deg in both", who, mc.ratio > 1 ? mc.ratio : 1, mc.pose[1], mc.pose[0], r[0], r[1], r[2], r[3], name,
             mc.lo[1], mc.hi[1], mc.lo[0], mc.hi[0], strcmp(who, "the given points") ? " through them" : "",
             floor(mc.ceiling * 10 + 1e-6) / 10);
    return mc.ceiling;
}

/* --points-out into path: nc rows by N of 0-based vertex indices in each
 * file's order (all: of every ring of the files) */
static void points_file(const char *path, int N, const int *rows, int nc, int all)
{
    FILE *f = out_open(path);
    fprintf(f, "# compat-tri --points-out: %d correspondence points (rows) of %d shapes (columns),\n"
               "# 0-based vertex indices in each file's order%s; usable as compat-tri -c\n", nc, N,
            all ? " (all rings counted)" : "");
    for (int r = 0; r < nc; r++)
        for (int s = 0; s < N; s++) fprintf(f, "%d%c", rows[(size_t)r * N + s], s + 1 < N ? ' ' : '\n');
    out_close(f);
}

/* the correspondence points used (nc rows, counter-clockwise index order)
 * to --points-out (or o->points_mem), in file order */
static void write_points(const struct options *o, int N, const int *n, const int *flipped, const int *corr, int nc)
{
    if (!o->points_out && !o->points_mem) return;
    int *rows = malloc(((size_t)nc + 1) * N * sizeof *rows);
    if (!rows) die("out of memory");
    for (int a = 0; a < nc; a++) {
        int k = flipped[0] ? (nc - a) % nc : a;   /* increasing along shape 0's file */
        for (int s = 0; s < N; s++) {
            int v = corr[(size_t)k * N + s];
            rows[(size_t)a * N + s] = flipped[s] ? n[s] - 1 - v : v;
        }
    }
    if (o->points_mem) {   /* kept: a layer's (mesh_layers) */
        free(o->points_mem->rows);
        o->points_mem->rows = rows;
        o->points_mem->n = nc;
        return;
    }
    points_file(o->points_out, N, rows, nc, 0);
    free(rows);
}

/* the polish candidate's --match-polish steps (see main) and the largest
 * step of a row (input points) */
#ifndef MPOLISH_STEPS
#define MPOLISH_STEPS 64
#endif
#define MPOLISH_SHIFT 3
/* the candidate runs on at most this many rows: C(24, 4) = 10626
 * quadruples in each pose (the five given rows and twelve placed points of
 * the default: 2380, 1.0 s on two flamingo poses, 2.0 s on six) */
#define MPOLISH_MAX_ROWS 24

/* The correspondence points after boundary matching to shape 0 (given:
 * ncorr rows in counter-clockwise index order); written to --points-out in
 * file order.  Returns the new rows (replacing given), count in *ncorr. */
static int *match_points(const struct options *o, int N, double **P, const int *n, const int *flipped,
                         int *given, int *ncorr, const int *want, int nwant)
{
    struct bmatch_params prm;
    bmatch_defaults(&prm);
    prm.mode = o->match;
    prm.bend = o->bend;
    prm.feature = o->feature;
    prm.spread = o->spread;
    prm.threads = o->threads;
    int *corr, nc, K = o->match_points;
    double *cost = malloc(N * sizeof *cost);
    if (bmatch_corr(N, P, n, given, *ncorr, want, nwant, K, &prm, &corr, &nc, cost) < 0)
        die("boundary matching failed: %s", cm_errmsg());
    for (int s = 1; s < N; s++)
        binfo(o, "%s: matched to %s (%s, cost %.4g)", o->shapes[s], o->shapes[0],
             o->match == BMATCH_ARCLENGTH ? "arc length" : o->match == BMATCH_ELASTIC ? "elastic" : "multiscale",
             cost[s]);
    binfo(o, "boundary matching: %d point%s given in every shape, %d in %s only, %d correspondence points "
            "placed", *ncorr, *ncorr == 1 ? "" : "s", nwant, o->shapes[0], nc);
    free(cost);
    if (o->mpolish_soft && nc > MPOLISH_MAX_ROWS) {   /* the candidate's cost grows as the rows^4 */
        cm_seterr("%d correspondence points, more than %d: the polish is left to --match-polish", nc, MPOLISH_MAX_ROWS);
        free(given);
        free(corr);
        return NULL;
    }
    if (o->mpolish > 0 && (nc < 4 || N < 2))   /* said, not skipped silently */
        binfo(o, "matching polish: nothing to move (%d correspondence point%s, %d shape%s: a ratio needs 4 points "
                "and 2 shapes)", nc, nc == 1 ? "" : "s", N, N == 1 ? "" : "s");
    if (o->mpolish > 0 && nc >= 4 && N >= 2) {   /* the placed points moved to force less stretch */
        unsigned char *pin = calloc(nc, 1);
        if (!pin) die("out of memory");
        for (int k = 0; k < nc; k++)   /* the given rows stay */
            for (int g = 0; g < *ncorr && !pin[k]; g++) {
                int same = 1;
                for (int s = 0; s < N && same; s++) same = corr[(size_t)k * N + s] == given[(size_t)g * N + s];
                pin[k] = same;
            }
        double before, after, t0 = now_seconds();
        int mv = modulus_match_polish(N, P, n, corr, nc, pin, o->mpolish, MPOLISH_SHIFT, &before, &after);
        free(pin);
        if (mv < 0) {
            if (!o->mpolish_soft) die("--match-polish: %s", cm_errmsg());
            free(given);
            free(corr);
            return NULL;   /* the candidate is left out (cm_errmsg says why) */
        }
        binfo(o, "matching polish: %d step%s, the stretch the points force %.3gx -> %.3gx (estimates of the first "
                "mesh; --match-polish %d); %.3f s", mv, mv == 1 ? "" : "s", before, after, o->mpolish,
             now_seconds() - t0);
    }
    free(given);
    write_points(o, N, n, flipped, corr, nc);
    if (verbose >= 2 && !o->log) {   /* -v -v: the certificate of the points the matching placed */
        int *row = malloc(nc * sizeof *row);
        if (!row) die("out of memory");
        for (int k = 0; k < nc; k++) row[k] = (flipped[0] ? (nc - k) % nc : k) + 1;   /* rows of --points-out */
        char line[1024];
        double ratio;
        cert_line(N, P, n, corr, nc, row, o->points_out ? o->points_out : "--points-out",
                  "the matched points (chosen by the matching, not given: this speaks of that matching only)",
                  line, sizeof line, &ratio);
        info(1, "%s", line);
        free(row);
    }
    *ncorr = nc;
    return corr;
}

/* one outer ring per shape: the paper's pipeline */
/* the outline of every shape matched and simplified into cp; input errors
 * die, a failed boundary matching returns -1 (cm_errmsg set) so that the
 * second build of the default (-m off) can give up and keep the first */
static int build_single(struct options *o, struct rings *R, struct compat *cp)
{
    int N = o->nshapes;
    double **P = malloc(N * sizeof *P);
    int *n = malloc(N * sizeof *n), *flipped = malloc(N * sizeof *flipped);
    for (int s = 0; s < N; s++) {
        flipped[s] = o->flipped[s];
        P[s] = R[s].P;
        n[s] = rings_count(&R[s], 0);
    }
    /* correspondences: rows by N columns of integer indices */
    struct columns C = {0};
    if (o->corr && corr_read(o, 0, &C) < 0) die("%s", cm_errmsg());
    if (o->corr && C.rows > 0 && C.cols != N)
        die("cannot read '%s': line 1: %d columns, but there are %d shapes", o->corr, C.cols, N);
    /* full rows; rows "v -1 -1 ...": a point on SHAPE0 only, to be placed by the matching */
    int *corr = malloc(((size_t)C.rows + 1) * N * sizeof *corr), *want = malloc((C.rows + 1) * sizeof *want);
    int ncorr = 0, nwant = 0;
    for (int k = 0; k < C.rows; k++) {
        const double *row = C.x + (size_t)k * N;
        int unknown = 0;
        for (int s = 1; s < N; s++) unknown += row[s] == -1;
        if (unknown && unknown != N - 1)
            die("cannot read '%s': row %d: give the point in every shape, or in %s only (-1 in the other "
                "columns)", o->corr, k + 1, o->shapes[0]);
        for (int s = 0; s < (unknown ? 1 : N); s++) {
            double x = row[s];
            if (x != floor(x) || x < 0 || x >= n[s])
                die("cannot read '%s': row %d: '%g' is not a vertex index of '%s' (0..%d)", o->corr, k + 1,
                    x, o->shapes[s], n[s] - 1);
            int v = (int)x;
            if (unknown) want[nwant] = flipped[0] ? n[0] - 1 - v : v;
            else corr[(size_t)ncorr * N + s] = flipped[s] ? n[s] - 1 - v : v;
        }
        if (unknown) nwant++; else ncorr++;
    }
    if (o->match == -1) { o->match = BMATCH_MULTISCALE; o->match_default = ncorr >= 3 && !nwant; o->match_auto = 1; }
    if (o->match == -2 && (ncorr < 3 || nwant))
        die("cannot read '%s': %d correspondence point%s%s; at least 3 are needed without --match",
            o->corr, ncorr, ncorr == 1 ? "" : "s", nwant ? " given in every shape" : "");
    if (o->match == BMATCH_ARCLENGTH && ncorr < 1)
        die("cannot read '%s': no correspondence point in every shape; --match arclength needs a start", o->corr);
    /* rows given along a clockwise file order run backwards after reversal */
    if (flipped[0]) {
        for (int a = 0, b = ncorr - 1; a < b; a++, b--)
            for (int s = 0; s < N; s++) {
                int t = corr[(size_t)a * N + s];
                corr[(size_t)a * N + s] = corr[(size_t)b * N + s];
                corr[(size_t)b * N + s] = t;
            }
    }

    unsigned char *keep = NULL;
    int rev = compat_corr_order(N, n, corr, ncorr);
    if (rev < 0) die("cannot read '%s': %s", o->corr, cm_errmsg());
    if (rev) binfo(o, "%s: points run clockwise along the outlines; using them in reverse order", o->corr);
    /* the given rows never slide along the outline (--slide) */
    int ngiven = ncorr, *given = malloc(((size_t)ncorr + 1) * N * sizeof *given);
    if (!given) die("out of memory");
    memcpy(given, corr, (size_t)ncorr * N * sizeof *given);
    if (o->match >= 0) {
        if (!(corr = match_points(o, N, P, n, flipped, corr, &ncorr, want, nwant))) {
            free(given); free(want); columns_free(&C);   /* a polish that could not run (o->mpolish_soft) */
            free(P); free(n); free(flipped);
            return -1;
        }
    } else write_points(o, N, n, flipped, corr, ncorr);
    const char *corr_name = o->match >= 0 ? "the matched points" : o->corr;
    if (compat_match(N, P, n, corr, ncorr, cp, &keep) < 0) {
        cm_seterr("cannot read '%s': %s", corr_name, cm_errmsg());
        free(keep); free(corr); free(want); free(given); columns_free(&C);
        free(P); free(n); free(flipped);
        return -1;
    }
    int M = cp->nb;
    cp->split_mode = o->split;
    cp->threads = o->threads;
    /* B indices of the given rows: the points of P they name, in every shape */
    unsigned char *pinB = calloc(M ? M : 1, 1);
    if (!pinB) die("out of memory");
    for (int k = 0; k < ngiven; k++) {
        int found = 0;
        for (int i = 0; i < M && !found; i++) {
            if (!keep || !keep[i]) continue;
            int all = 1;
            for (int s = 0; s < N && all; s++) {
                const double *q = P[s] + 2 * given[(size_t)k * N + s];
                all = cp->B[s][2 * i] == q[0] && cp->B[s][2 * i + 1] == q[1];
            }
            if (all) pinB[i] = found = 1;
        }
        if (!found) die("internal error: given row %d is not a point of the matched outline", k + 1);
    }
    free(given);
    compat_simplify(cp, o->err, keep);
    if (!cp->bidx && cp->nb > 3) die("out of memory");
    if (cp->bidx) {
        cp->bpin = malloc(cp->nb ? cp->nb : 1);
        if (!cp->bpin) die("out of memory");
        for (int v = 0; v < cp->nb; v++) cp->bpin[v] = pinB[cp->bidx[v]];
    }
    free(pinB);
    /* the outline actually kept, against the input rings */
    double hmax = 0;
    int hs = 0;
    for (int s = 0; s < N; s++) {
        double h = compat_outline_error(cp, s, P[s], n[s]);
        if (h > hmax) { hmax = h; hs = s; }
    }
    binfo(o, "boundary: %d matched points, %d after simplification (tolerance %g of the diagonal; "
            "largest two-sided Hausdorff distance %.3g, in %s)", M, cp->nb, o->err, hmax, o->shapes[hs]);
    free(keep); free(corr); free(want); columns_free(&C);
    free(P); free(n); free(flipped);
    return 0;
}

/* The certificate of the given rows (one outer ring per shape; R oriented
 * counter-clockwise, flipped[s] set where the file ran clockwise): the
 * largest ratio of conformal moduli of a quadrilateral (four given points)
 * between two poses, which bounds the worst angle of any compatible
 * triangulation honouring the points (modulus_cert.h).  Written as one
 * line into line (size len); returns the ceiling in degrees (-1: fewer than
 * 4 rows, no certificate).  Sets o->forced and o->cert_meshes; with
 * budget > 0 a certificate of more meshes (one per quadruple and shape)
 * is not computed (-1, o->forced left as it was). */
static double certify(struct options *o, struct rings *R, const int *flipped, char *line, size_t len, long budget)
{
    int N = o->nshapes;
    struct columns C = {0};
    if (corr_read(o, 0, &C) < 0) die("%s", cm_errmsg());
    if (C.rows > 0 && C.cols != N)
        die("cannot read '%s': line 1: %d columns, but there are %d shapes", o->corr, C.cols, N);
    int *n = malloc(N * sizeof *n), *corr = malloc(((size_t)C.rows + 1) * N * sizeof *corr);
    int *row = malloc((C.rows + 1) * sizeof *row), nc = 0;
    double **P = malloc(N * sizeof *P);
    if (!n || !corr || !row || !P) die("out of memory");
    for (int s = 0; s < N; s++) { n[s] = rings_count(&R[s], 0); P[s] = R[s].P; }
    for (int k = 0; k < C.rows; k++) {
        const double *x = C.x + (size_t)k * N;
        int unknown = 0;
        for (int s = 1; s < N; s++) unknown += x[s] == -1;
        if (unknown) continue;   /* a point in SHAPE0 only: placed by the matching, not given */
        for (int s = 0; s < N; s++) {
            if (x[s] != floor(x[s]) || x[s] < 0 || x[s] >= n[s])
                die("cannot read '%s': row %d: '%g' is not a vertex index of '%s' (0..%d)", o->corr, k + 1,
                    x[s], o->shapes[s], n[s] - 1);
            int v = (int)x[s];
            corr[(size_t)nc * N + s] = flipped[s] ? n[s] - 1 - v : v;
        }
        row[nc++] = k + 1;
    }
    for (int pass = 0; pass < 2; pass++) {   /* reversed: a clockwise file, then rows listed clockwise */
        if (pass == 1) {
            int rev = compat_corr_order(N, n, corr, nc);
            if (rev < 0) die("cannot read '%s': %s", o->corr, cm_errmsg());
            if (!rev) break;
        } else {
            if (!flipped[0]) continue;
            for (int a = 0, b = nc - 1; a < b; a++, b--)
                for (int s = 0; s < N; s++) {
                    int t = corr[(size_t)a * N + s];
                    corr[(size_t)a * N + s] = corr[(size_t)b * N + s];
                    corr[(size_t)b * N + s] = t;
                }
        }
        for (int a = 0, b = nc - 1; a < b; a++, b--) { int t = row[a]; row[a] = row[b]; row[b] = t; }
    }
    o->cert_meshes = (long)nc * (nc - 1) * (nc - 2) * (nc - 3) / 24 * N;
    double ceiling = -1;
    if (budget > 0 && o->cert_meshes > budget) snprintf(line, len, "certificate: not computed");
    else ceiling = cert_line(N, P, n, corr, nc, row, o->corr, "the given points", line, len, &o->forced);
    columns_free(&C);
    free(n); free(corr); free(row); free(P);
    return nc >= 4 ? ceiling : -1;   /* -1 also where it was not computed */
}

/* index i of ring k of shape s in file order <-> counter-clockwise order
 * (compat_nest oriented the ring in place, reversing it where flipped; a
 * hole, clockwise, is read backwards for the matching); its own inverse */
static int ring_ccw(const struct rings *R, const unsigned char *flipped, int nr, int s, int k, int hole, int i)
{
    int n = rings_count(&R[s], k);
    int v = flipped[(size_t)s * nr + k] ? n - 1 - i : i;
    return hole ? n - 1 - v : v;
}

/* the point of file-order index g (all rings counted) of shape s, R oriented by compat_nest */
static const double *ring_point(const struct rings *R, const unsigned char *flipped, int nr, int s, int g)
{
    int k = 0;
    while (k + 1 < nr && g >= R[s].start[k + 1]) k++;
    int i = g - R[s].start[k], n = rings_count(&R[s], k);
    return R[s].P + 2 * ((size_t)R[s].start[k] + (flipped[(size_t)s * nr + k] ? n - 1 - i : i));
}

/* A ring matched without a given row starts where its shape says; for a
 * round eye or a circular head every start costs about the same, and the
 * start search's choice turns the ring by any angle between the poses (a
 * face of five poses with two round eyes: turns of 25-125 degrees, and
 * then no two straight cuts to the outline were inside every pose, so
 * the triangulation failed).  Such a ring is turned as its surroundings.
 * In each shape s the similarity that maps the other rings' rows from
 * shape 0 to shape s (procrustes2, each row weighted by 1 / (d^2 + r^2),
 * d its distance from the ring's centre and r the ring's mean radius in
 * shape 0, so the nearest rows -- a hole's own outline -- count most),
 * applied to the ring's first matched vertex about the ring's centre,
 * places its start; the vertex of shape s's ring nearest to that is the
 * placed start.  It is used
 *   - always for a round hole (round: polygon_roundness at least
 *     TURN_ROUND in every shape; bent copies of Font Awesome's round eyes
 *     became ovals whose matching cost was 1.6-3.4 times lower at a wrong
 *     start than at the true one, and a hole turns with its piece), and
 *     otherwise, with c the matching's cost (bmatch_map with that one
 *     pair) from the start search's start and c' from the placed one,
 *   - where it is within TURN_STEP degrees (about the ring's centre) of
 *     the start search's and c' <= (1 + TURN_NEAR) c, or
 *   - where it is farther and c' <= (1 + TURN_TOL) c and some start
 *     TURN_STEP, 2 TURN_STEP, ... degrees away from the start search's
 *     costs at most (1 + TURN_TOL) c too: the shape does not tell its
 *     turn (a circular head, an oval's two ends).
 * A piece whose shape does tell (an arm swung differently from the body)
 * keeps its start.  The ring is then matched again from the starts.
 * P, n: the ring's counter-clockwise copies; round: see above; mc, nmc:
 * its rows (ccw indices; replaced); ctx, nctx: the other rings' rows,
 * file order.
 * Returns the number of shapes whose start changed (0: mc unchanged), -1
 * out of memory, -2 if matching from the changed starts failed (cm_errmsg;
 * mc unchanged). */
#ifndef TURN_TOL
#define TURN_TOL 0.5
#endif
#define TURN_STEP 30   /* degrees */
#define TURN_NEAR 0.02
#define TURN_ROUND 0.75   /* polygon_roundness: a noisy circle 0.96-0.99, an oval of 17 points 2.2:1 0.79, a square 0.785 */

/* the vertex of P (n by 2) nearest to (x, y) */
static int ring_nearest(const double *P, int n, double x, double y)
{
    int near = 0;
    double dn = INFINITY;
    for (int j = 0; j < n; j++) {
        double d = hypot(P[2 * j] - x, P[2 * j + 1] - y);
        if (d < dn) { dn = d; near = j; }
    }
    return near;
}
static int turn_ring(const struct options *o, int N, const struct rings *R, const unsigned char *flipped, double **P,
                     const int *n, int round, const int *ctx, int nctx, const struct bmatch_params *prm, int **mc,
                     int *nmc)
{
    int nr = R[0].nrings, changed = 0;
    double *A = malloc(((size_t)nctx + 1) * 4 * sizeof *A), *B = A + 2 * ((size_t)nctx + 1);
    double *w = malloc(((size_t)nctx + 1) * sizeof *w), *tB = malloc((size_t)n[0] * sizeof *tB);
    int *start = malloc(N * sizeof *start);
    if (!A || !w || !tB || !start) { free(A); free(w); free(tB); free(start); return -1; }
    double c0[2] = {0, 0}, r0 = 0;
    for (int j = 0; j < n[0]; j++) { c0[0] += P[0][2 * j] / n[0]; c0[1] += P[0][2 * j + 1] / n[0]; }
    for (int j = 0; j < n[0]; j++) r0 += hypot(P[0][2 * j] - c0[0], P[0][2 * j + 1] - c0[1]) / n[0];
    for (int r = 0; r < nctx; r++) {
        const double *p = ring_point(R, flipped, nr, 0, ctx[(size_t)r * N]);
        double d2 = (p[0] - c0[0]) * (p[0] - c0[0]) + (p[1] - c0[1]) * (p[1] - c0[1]);
        A[2 * r] = p[0]; A[2 * r + 1] = p[1];
        w[r] = 1 / (d2 + r0 * r0);
    }
    int v0 = (*mc)[0];
    const double *p0 = P[0] + 2 * v0;
    start[0] = v0;
    for (int s = 1; s < N; s++) {
        start[s] = (*mc)[s];
        for (int r = 0; r < nctx; r++) {
            const double *p = ring_point(R, flipped, nr, s, ctx[(size_t)r * N + s]);
            B[2 * r] = p[0]; B[2 * r + 1] = p[1];
        }
        double an, sc, t[2];
        if (procrustes2(A, B, w, nctx, &an, &sc, t) < 0) continue;
        double cs[2] = {0, 0};
        for (int j = 0; j < n[s]; j++) { cs[0] += P[s][2 * j] / n[s]; cs[1] += P[s][2 * j + 1] / n[s]; }
        double ux = p0[0] - c0[0], uy = p0[1] - c0[1];
        double q[2] = {cs[0] + sc * (cos(an) * ux - sin(an) * uy), cs[1] + sc * (sin(an) * ux + cos(an) * uy)};
        int placed = ring_nearest(P[s], n[s], q[0], q[1]);
        if (placed == start[s]) continue;
        if (round) { start[s] = placed; changed++; continue; }
        int pair[2] = {v0, start[s]};
        double cf, cp;
        if (bmatch_map(P[0], n[0], P[s], n[s], pair, 1, prm, tB, &cf) < 0) continue;
        pair[1] = placed;
        if (bmatch_map(P[0], n[0], P[s], n[s], pair, 1, prm, tB, &cp) < 0) continue;
        if (!(cp <= cf * (1 + TURN_TOL))) continue;
        /* does the shape tell?  near the matching's start (within
         * TURN_STEP) only if the placed start costs more than TURN_NEAR
         * above it; farther, unless a start TURN_STEP or more away from the
         * matching's costs as little as the placed one may */
        const double *pf = P[s] + 2 * start[s], *pp = P[s] + 2 * placed;
        double af = atan2(pf[1] - cs[1], pf[0] - cs[0]), rf = hypot(pf[0] - cs[0], pf[1] - cs[1]);
        if (fabs(remainder(atan2(pp[1] - cs[1], pp[0] - cs[0]) - af, 2 * M_PI)) < TURN_STEP * M_PI / 180) {
            if (cp <= cf * (1 + TURN_NEAR)) { start[s] = placed; changed++; }
            continue;
        }
        int ambiguous = 0;
        for (int m = 1; m * TURN_STEP < 360 - 0.5 * TURN_STEP && !ambiguous; m++) {
            double a = af + m * TURN_STEP * M_PI / 180, cm;
            pair[1] = ring_nearest(P[s], n[s], cs[0] + rf * cos(a), cs[1] + rf * sin(a));
            ambiguous = pair[1] != start[s] && bmatch_map(P[0], n[0], P[s], n[s], pair, 1, prm, tB, &cm) == 0 &&
                        cm <= cf * (1 + TURN_TOL);
        }
        if (ambiguous) { start[s] = placed; changed++; }
    }
    int rc = changed;
    if (changed) {
        int *m2 = NULL, n2 = 0;
        if (bmatch_corr(N, P, n, start, 1, NULL, 0, o->match_points, prm, &m2, &n2, NULL) == 0) {
            free(*mc);
            *mc = m2;
            *nmc = n2;
        } else rc = -2;   /* the start search's rows stay (the caller says so) */
    }
    free(A); free(w); free(tB); free(start);
    return rc;
}

/* Several rings: every ring with fewer than 3 rows (0, 1 or 2: kept among
 * them) gets the boundary matching of one outline (bmatch_corr, the same
 * parameters and --match-points), on its own; a ring matched without any
 * row then starts as its surroundings turn where its shape cannot tell
 * (turn_ring); a ring with 3 or more rows, or every ring with -m off,
 * keeps its rows (a ring without any then starts at its first vertex).
 * R oriented by compat_nest.  Returns the rows (malloc'd, *nout of them,
 * file-order indices), ring by ring: a matched ring's rows in its cyclic
 * order, the others' as given; where a given row is not on one ring in
 * every shape, the given rows as they are (compat_multi names the row). */
static int *match_rings(const struct options *o, int N, const struct rings *R, const int *parent,
                        const unsigned char *flipped, const int *corr, int ncorr, int *nout)
{
    int nr = R[0].nrings;
    int *out = malloc(((size_t)ncorr + 1) * N * sizeof *out), *ring = malloc(((size_t)ncorr + 1) * sizeof *ring);
    double **P = calloc(N, sizeof *P);
    int *n = malloc(N * sizeof *n), *given = malloc(((size_t)ncorr + 1) * N * sizeof *given);
    int **rows = calloc(nr, sizeof *rows), *nrows = calloc(nr, sizeof *nrows);   /* each ring's, file order */
    int **free_mc = calloc(nr, sizeof *free_mc), *free_n = calloc(nr, sizeof *free_n);   /* matched without rows: ccw */
    if (!out || !ring || !P || !n || !given || !rows || !nrows || !free_mc || !free_n) die("out of memory");
    int ok = 1;   /* every row on one ring, the same in every shape */
    for (int r = 0; r < ncorr && ok; r++) {
        ring[r] = -1;
        for (int k = 0; k < nr; k++)
            if (corr[(size_t)r * N] >= R[0].start[k] && corr[(size_t)r * N] < R[0].start[k + 1]) ring[r] = k;
        for (int s = 0; s < N && ok; s++)
            ok = ring[r] >= 0 && corr[(size_t)r * N + s] >= R[s].start[ring[r]] &&
                 corr[(size_t)r * N + s] < R[s].start[ring[r] + 1];
    }
    if (!ok || o->match == -2) {
        memcpy(out, corr, (size_t)ncorr * N * sizeof *out);
        free(ring); free(P); free(n); free(given); free(rows); free(nrows); free(free_mc); free(free_n);
        *nout = ncorr;
        return out;
    }
    struct bmatch_params prm;
    bmatch_defaults(&prm);
    prm.mode = o->match < 0 ? BMATCH_MULTISCALE : o->match;
    prm.bend = o->bend;
    prm.feature = o->feature;
    prm.spread = o->spread;
    prm.threads = o->threads;
    for (int k = 0; k < nr; k++) {
        int hole = compat_is_hole(parent, k), nk = 0, *mc = NULL, nmc = 0;
        for (int s = 0; s < N; s++) n[s] = rings_count(&R[s], k);
        for (int r = 0; r < ncorr; r++)   /* its given rows, counter-clockwise indices */
            if (ring[r] == k) {
                for (int s = 0; s < N; s++)
                    given[(size_t)nk * N + s] = ring_ccw(R, flipped, nr, s, k, hole, corr[(size_t)r * N + s] - R[s].start[k]);
                nk++;
            }
        /* 3 or more rows, or rows compat_multi will refuse: as given */
        if (nk < 3 && compat_corr_order(N, n, given, nk) >= 0) {
            for (int s = 0; s < N; s++)
                if (!(P[s] = compat_ring_ccw(&R[s], k, hole))) die("out of memory");
            if (bmatch_corr(N, P, n, given, nk, NULL, 0, o->match_points, &prm, &mc, &nmc, NULL) < 0) {
                /* said without -v too: that ring's correspondence is the coarse one */
                warn("ring %d: boundary matching failed (%s): %s", k + 1, cm_errmsg(),
                     nk ? "its given rows alone are used" : "matched from its first vertex by arc length");
                mc = NULL;
            }
            for (int s = 0; s < N; s++) { free(P[s]); P[s] = NULL; }
        }
        if (mc) {
            info(1, "ring %d (%s): %d correspondence points placed by the boundary matching (%d given)", k + 1,
                 hole ? "a hole" : o->layers ? "a layer" : "a piece", nmc - nk, nk);
            if (!nk) { free_mc[k] = mc; free_n[k] = nmc; continue; }   /* its rows after turn_ring */
        }
        nrows[k] = mc ? nmc : nk;
        if (!(rows[k] = malloc(((size_t)nrows[k] + 1) * N * sizeof *rows[k]))) die("out of memory");
        if (mc) {   /* the matched rows (the given ones among them), in cyclic order */
            for (int a = 0; a < nmc; a++)
                for (int s = 0; s < N; s++)
                    rows[k][(size_t)a * N + s] = R[s].start[k] + ring_ccw(R, flipped, nr, s, k, hole, mc[(size_t)a * N + s]);
            free(mc);
        } else
            for (int r = 0, g = 0; r < ncorr; r++)
                if (ring[r] == k) memcpy(rows[k] + (size_t)g++ * N, corr + (size_t)r * N, N * sizeof *out);
    }
    /* the rings matched without a row: their start as the others' rows
     * turn (turn_ring); outer rings before the rings inside them (a hole
     * turns as its piece, not the other way round), and among the same
     * nesting depth the least round first: the first one without a row
     * keeps its own start */
    int nfree = 0, *ord = malloc(((size_t)nr + 1) * sizeof *ord);
    double *rnd = malloc(((size_t)nr + 1) * sizeof *rnd), *key = malloc(((size_t)nr + 1) * sizeof *key);
    if (!ord || !rnd || !key) die("out of memory");
    for (int k = 0; k < nr; k++) {
        if (!free_mc[k]) continue;
        rnd[k] = 1;   /* the smallest over the shapes */
        for (int s = 0; s < N; s++) {
            double x = polygon_roundness(rings_ring(&R[s], k), rings_count(&R[s], k));
            if (x < 0) die("out of memory");
            rnd[k] = fmin(rnd[k], x);
        }
        int depth = 0;
        for (int j = parent[k]; j >= 0; j = parent[j]) depth++;
        key[k] = depth + rnd[k] / 2;   /* roundness is in [0, 1] */
        int a = nfree++;
        for (; a > 0 && key[ord[a - 1]] > key[k]; a--) ord[a] = ord[a - 1];
        ord[a] = k;
    }
    for (int f = 0; f < nfree; f++) {
        int k = ord[f];
        int hole = compat_is_hole(parent, k), nctx = 0, cap = 0;
        for (int j = 0; j < nr; j++) cap += j != k && rows[j] ? nrows[j] : 0;
        int *ctx = malloc(((size_t)cap + 1) * N * sizeof *ctx);
        if (!ctx) die("out of memory");
        for (int j = 0; j < nr; j++)
            if (j != k && rows[j]) {
                memcpy(ctx + (size_t)nctx * N, rows[j], (size_t)nrows[j] * N * sizeof *ctx);
                nctx += nrows[j];
            }
        int *mc = free_mc[k], nmc = free_n[k], round = hole && rnd[k] >= TURN_ROUND;
        if (nctx >= 2) {
            for (int s = 0; s < N; s++) {
                n[s] = rings_count(&R[s], k);
                if (!(P[s] = compat_ring_ccw(&R[s], k, hole))) die("out of memory");
            }
            int t = turn_ring(o, N, R, flipped, P, n, round, ctx, nctx, &prm, &mc, &nmc);
            if (t == -1) die("out of memory");
            if (t == -2)   /* said without -v: that ring may turn in the morph */
                warn("ring %d: matching it from the start its surroundings give failed (%s): it keeps the start "
                     "search's", k + 1, cm_errmsg());
            else if (t)
                info(1, "ring %d (%s): its shape does not tell how it turns (%s): started as its surroundings turn in "
                        "%d shape%s, %d correspondence points", k + 1, hole ? "a hole" : o->layers ? "a layer" : "a piece",
                     round ? "round" : "as cheap turned", t, t == 1 ? "" : "s", nmc);
            for (int s = 0; s < N; s++) { free(P[s]); P[s] = NULL; }
        }
        free(ctx);
        nrows[k] = nmc;
        if (!(rows[k] = malloc(((size_t)nmc + 1) * N * sizeof *rows[k]))) die("out of memory");
        for (int a = 0; a < nmc; a++)
            for (int s = 0; s < N; s++)
                rows[k][(size_t)a * N + s] = R[s].start[k] + ring_ccw(R, flipped, nr, s, k, hole, mc[(size_t)a * N + s]);
        free(mc);
        free_mc[k] = NULL;
    }
    free(ord); free(rnd); free(key);
    int no = 0;
    for (int k = 0; k < nr; k++) no += nrows[k];
    if (!(out = realloc(out, ((size_t)no + 1) * N * sizeof *out))) die("out of memory");
    no = 0;
    for (int k = 0; k < nr; k++) {
        if (nrows[k]) memcpy(out + (size_t)no * N, rows[k], (size_t)nrows[k] * N * sizeof *out);
        no += nrows[k];
        free(rows[k]);
    }
    free(ring); free(P); free(n); free(given); free(rows); free(nrows); free(free_mc); free(free_n);
    *nout = no;
    return out;
}

/* "P piece(s), H hole(s)" of one shape's rings by their nesting (a ring
 * inside an odd number of rings is a hole); r's rings may be reversed */
static void ring_kinds(struct rings *r, char *out, size_t size)
{
    int nr = r->nrings, *parent = malloc((nr ? nr : 1) * sizeof *parent), holes = 0;
    unsigned char *flipped = malloc(nr ? nr : 1);
    if (!parent || !flipped || compat_nest(1, r, parent, flipped) < 0) {
        snprintf(out, size, "?");
    } else {
        for (int k = 0; k < nr; k++) holes += compat_is_hole(parent, k);
        snprintf(out, size, "%d piece%s, %d hole%s", nr - holes, nr - holes == 1 ? "" : "s", holes,
                 holes == 1 ? "" : "s");
    }
    free(parent);
    free(flipped);
}

/* Several rings (R, N shapes): the same count in every shape, else die;
 * the rows of -c read into C (global vertex indices: every ring of a file
 * counted), checked, and with --match-rings nearest every shape's rings
 * put in shape 0's order (the rows follow; *order, N by the ring count,
 * malloc'd, names the file's ring now at each place, for rows_to_files;
 * NULL without).  Returns the rows, C.rows by N (malloc'd). */
static int *multi_rows(const struct options *o, struct rings *R, struct columns *C, int **order)
{
    int N = o->nshapes, nr = R[0].nrings;
    for (int s = 1; s < N; s++)
        if (R[s].nrings != nr) {
            /* traced frames: a gap between two legs that closes in some
             * frames is a hole in the others only */
            char ka[64], k0[64];
            ring_kinds(&R[s], ka, sizeof ka);
            ring_kinds(&R[0], k0, sizeof k0);
            die("cannot read '%s': %d ring%s (%s), but '%s' has %d (%s); every shape needs the same rings "
                "(matched by order): where a hole shows in some frames only, trace the outer outlines alone "
                "(img2rings -1)", R[s].name, R[s].nrings, R[s].nrings == 1 ? "" : "s", ka, R[0].name, nr, k0);
        }
    memset(C, 0, sizeof *C);
    if (o->corr && corr_read(o, N, C) < 0) die("%s", cm_errmsg());
    int *corr = malloc(((size_t)C->rows + 1) * N * sizeof *corr);
    if (!corr) die("out of memory");
    for (size_t k = 0; k < (size_t)C->rows * N; k++) {
        double x = C->x[k];
        if (x != floor(x) || x < 0 || x > 1e9)
            die("cannot read '%s': line %ld: '%g' is not a vertex index", o->corr,
                data_line(o->corr, (int)(k / N) + 1), x);
        corr[k] = (int)x;
    }
    int moved = 0;
    *order = NULL;
    if (o->nearest && !(*order = malloc(((size_t)N * nr + 1) * sizeof **order))) die("out of memory");
    if (o->nearest && compat_order_rings(N, R, corr, C->rows, &moved, *order) < 0)
        die("rings do not match: %s", cm_errmsg());
    if (o->nearest) info(1, "--match-rings nearest: rings of %d shape%s reordered", moved, moved == 1 ? "" : "s");
    return corr;
}

/* rows (n by N) of indices over the rings of R as --match-rings nearest
 * put them (order: from multi_rows, NULL: as in the files) back to the
 * files' numbering, for --points-out */
static void rows_to_files(int N, const struct rings *R, const int *order, int *rows, int n)
{
    int nr = R[0].nrings, *fstart = malloc(((size_t)nr + 1) * sizeof *fstart);
    if (!fstart) die("out of memory");
    for (int s = 0; order && s < N; s++) {
        const int *ord = order + (size_t)s * nr;
        for (int j = 0; j <= nr; j++) fstart[j] = 0;   /* the file's ring j: its count at j + 1, then its start */
        for (int k = 0; k < nr; k++) fstart[ord[k] + 1] = rings_count(&R[s], k);
        for (int j = 0; j < nr; j++) fstart[j + 1] += fstart[j];
        for (int r = 0; r < n; r++) {
            int g = rows[(size_t)r * N + s], k = 0;
            while (g >= R[s].start[k + 1]) k++;
            rows[(size_t)r * N + s] = fstart[ord[k]] + g - R[s].start[k];
        }
    }
    free(fstart);
}

/* several rings or interior points: compat_holes.h */
static void build_multi(const struct options *o, struct rings *R, struct compat *cp)
{
    int N = o->nshapes, nr = R[0].nrings;
    struct columns C, I = {0};
    int *order, *corr = multi_rows(o, R, &C, &order);
    int *parent = malloc(nr * sizeof *parent);
    unsigned char *flipped = malloc((size_t)N * nr);
    if ((o->layers ? compat_layers(N, R, parent, flipped) : compat_nest(N, R, parent, flipped)) < 0)
        die("rings do not match: %s", cm_errmsg());
    int nholes = 0, nflip = 0;
    for (int k = 0; k < nr; k++) nholes += compat_is_hole(parent, k);
    for (size_t k = 0; k < (size_t)N * nr; k++) nflip += flipped[k];
    info(1, "%d ring%s per shape: %d %s%s, %d hole%s; %d ring%s reversed (indices refer to the file order)",
         nr, nr == 1 ? "" : "s", nr - nholes, o->layers ? "layer" : "piece", nr - nholes == 1 ? "" : "s", nholes,
         nholes == 1 ? "" : "s", nflip, nflip == 1 ? "" : "s");
    if (o->interior && columns_read(o->interior, 2 * N, -1, NULL, &I) < 0) die("%s", cm_errmsg());
    int nrows;
    int *rows = match_rings(o, N, R, parent, flipped, corr, C.rows, &nrows);
    if (o->points_out) {   /* the rows used, numbered as in the files */
        int *fr = malloc(((size_t)nrows + 1) * N * sizeof *fr);
        if (!fr) die("out of memory");
        memcpy(fr, rows, (size_t)nrows * N * sizeof *fr);
        rows_to_files(N, R, order, fr, nrows);
        points_file(o->points_out, N, fr, nrows, 1);
        free(fr);
    }
    double st[4];
    if (compat_multi(N, R, parent, flipped, rows, nrows, I.x, I.rows, o->err, cp, st) < 0) {
        const char *m = cm_errmsg();
        /* point rows come after every correspondence check */
        die_row(o->interior && (strstr(m, "point") || strstr(m, "same as")) ? o->interior : o->corr);
    }
    if (st[3] > 0) info(1, "%g ring%s without a correspondence row: matched from the first vertex", st[3],
                        st[3] == 1 ? "" : "s");
    if (st[0] < o->err) info(1, "tolerance halved to %g so that no two rings touch and every point stays "
                                "inside its piece", st[0]);
    info(1, "boundary: %d points on %d rings and %d interior points (tolerance %g of the diagonal; largest "
            "two-sided Hausdorff distance %.3g, in %s)", cp->ring_start[nr], nr, cp->npts, st[0], st[1],
         o->shapes[(int)st[2]]);
    cp->split_mode = o->split;
    cp->threads = o->threads;
    if (compat_multi_triangulate(cp) < 0) die("%s", cm_errmsg());
    if (cp->nbent)
        info(1, "%d cut%s joining holes to their pieces bend%s (no two straight cuts fit): %d bend points", cp->nbent,
             cp->nbent == 1 ? "" : "s", cp->nbent == 1 ? "s" : "", cp->nbend);
    free(parent); free(flipped); free(corr); free(rows); free(order);
    columns_free(&C);
    if (o->interior) columns_free(&I);
}


/* the refinement's parameters for cp (compat_refine_params) */
static struct compat_refine_params refine_params(const struct options *o, const struct compat *cpp)
{
    struct compat_refine_params pa = {o->min_angle * M_PI / 180, 0, o->max_nv ? o->max_nv : cpp->nv + 10 * cpp->nb, 200,
                                      o->refine == 2 ? 0 : 200, o->threads, o->split_share, 1, 0, 0, 0, 1};
    pa.slide = o->slide ? o->err : 0;
    pa.slide_first = o->slide == 2;
    pa.slide_global = o->slide == 1 || o->slide == 2;
    return pa;
}

/* -v lines of a finished refinement of cpp (q0: its worst angle before,
 * radians; rs, pa: its counts and parameters); returns the worst angle
 * after over every pose (degrees) */
static double refine_report(const struct options *o, const struct compat *cpp, double q0,
                            const struct compat_refine_stats *rs, const struct compat_refine_params *pa,
                            const char *who)
{
    const char *sep = who ? ": " : "";
    if (!who) who = "";
    double q1 = compat_min_angle(cpp, NULL) * 180 / M_PI;
    char grown[128] = "";
    if (rs->grown)
        snprintf(grown, sizeof grown, " (the first pass cut short after %d rounds: its triangles below the goal grew "
                 "with the vertices)", rs->grown);
    info(1, "%s%srefinement: %d rounds%s, %d interior and %d boundary splits, %d collapses (%d coarsening), "
            "%d flips, %d moves; min angle %.2f -> %.2f deg%s; sharpest outline corner %.2f deg; at %.3f s", who, sep,
         rs->rounds, grown, rs->splits, rs->bsplits, rs->collapses, rs->coarsened, rs->flips, rs->moves, q0 * 180 / M_PI,
         q1, rs->kept_input ? " (worse: input kept)" : "", compat_sharpest_corner(cpp) * 180 / M_PI, elapsed());
    if (rs->stop != COMPAT_REFINE_GOAL && !rs->kept_input) {
        char why[560];
        if (rs->cycles > 0) {   /* a stall answered by the final polish and more rounds */
            char again[96];
            if (rs->stop == COMPAT_REFINE_STALLED) snprintf(again, sizeof again, "stalled again");
            else if (rs->stop == COMPAT_REFINE_MAXNV) snprintf(again, sizeof again, "--max-vertices %d reached", pa->max_nv);
            else if (rs->stop == COMPAT_REFINE_NOSPLIT) snprintf(again, sizeof again, "no split keeps every pose positive");
            else snprintf(again, sizeof again, "%d rounds used up", pa->rounds);
            snprintf(why, sizeof why, "neither the worst angle nor the number of triangles below the goal improved in %d rounds, "
                     "then the best round polished and refined again: %s%s", COMPAT_REFINE_STALL, again,
                     rs->restored ? " (back to the best round's mesh)" : "");
        } else if (rs->stop == COMPAT_REFINE_STALLED)
            snprintf(why, sizeof why, "neither the worst angle nor the number of triangles below the goal improved in %d rounds%s", rs->stalled,
                     rs->restored ? " (back to the best round's mesh)" : "");
        else if (rs->stop == COMPAT_REFINE_MAXNV)
            snprintf(why, sizeof why, "--max-vertices %d reached%s", pa->max_nv,
                     rs->restored ? " (back to the best round's mesh)" : "");
        else if (rs->stop == COMPAT_REFINE_NOSPLIT) snprintf(why, sizeof why, "no split keeps every pose positive");
        else if (rs->stop == COMPAT_REFINE_GROWING)
            snprintf(why, sizeof why, "the triangles below the goal grew with the vertices (half of them or more)");
        else snprintf(why, sizeof why, "%d rounds used up", pa->rounds);
        if (rs->rerun) {   /* the second and third passes of --split-share */
            size_t n = strlen(why);
            const char *third = pa->lookahead ? ", and the third, splits chosen over every pose," : "";
            if (rs->rerun == 3)
                snprintf(why + n, sizeof why - n, " in the third pass (from the start, --split-share %g, each bad triangle "
                         "split at the edge whose halves are best over every pose), kept", pa->split_share);
            else if (rs->rerun == 1)
                snprintf(why + n, sizeof why - n, " in the second pass (from the start, --split-share %g), kept%s",
                         pa->split_share, pa->lookahead ? " (the third, splits chosen over every pose, was not better)" : "");
            else
                snprintf(why + n, sizeof why - n, " in the first pass, kept (the second, --split-share %g%s %s not better)",
                         pa->split_share, third, pa->lookahead ? "were" : "was");
        }
        if (rs->gpolish[1] > rs->gpolish[0]) {   /* the global max-min polish of the result */
            size_t n = strlen(why);
            snprintf(why + n, sizeof why - n, "; the global max-min polish raised the worst angle from %.2f deg",
                     rs->gpolish[0] * 180 / M_PI);
        }
        if (rs->gslide[1] > rs->gslide[0]) {   /* and its outline slides (--slide) */
            size_t n = strlen(why);
            if (rs->gpolish[1] > rs->gpolish[0])
                snprintf(why + n, sizeof why - n, ", then with the outline sliding (--slide) from %.2f to %.2f deg",
                         rs->gslide[0] * 180 / M_PI, rs->gslide[1] * 180 / M_PI);
            else
                snprintf(why + n, sizeof why - n, "; the global max-min polish with the outline sliding (--slide) "
                         "raised the worst angle from %.2f to %.2f deg", rs->gslide[0] * 180 / M_PI,
                         rs->gslide[1] * 180 / M_PI);
        }
        info(1, "%s%srefinement stopped below the goal of %g deg: %s; worst angle %.2f deg; the poses' maps are "
                "stretched %.1fx at (%.4g, %.4g) in pose %d (%s)", who, sep, o->min_angle, why, q1, rs->stretch,
             rs->worst_at[0], rs->worst_at[1], rs->worst_shape, o->shapes[rs->worst_shape]);
    }
    return q1;
}

/* smoothing or compatible refinement of cp (q0: its worst angle before, radians),
 * reported with -v; returns the worst angle after over every pose (degrees),
 * or -1 if the refinement failed (cm_errmsg set) */
static double improve(const struct options *opt, struct compat *cpp, double q0)
{
    const struct options o = *opt;
    /* target edge length: mean boundary edge, relative to each shape's diagonal */
    double target = 0;
    if (o.edge > 0) {
        for (int s = 0; s < o.nshapes; s++) {
            double L = 0, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
            int ne = 0;
            for (int i = 0; i < cpp->nb; i++) {
                int j = compat_boundary_next(cpp, i);   /* along the vertex's ring */
                if (j < 0) continue;
                L += hypot(cpp->X[s][2 * j] - cpp->X[s][2 * i], cpp->X[s][2 * j + 1] - cpp->X[s][2 * i + 1]);
                ne++;
                for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], cpp->X[s][2 * i + d]); hi[d] = fmax(hi[d], cpp->X[s][2 * i + d]); }
            }
            target += L / ne / hypot(hi[0] - lo[0], hi[1] - lo[1]);
        }
        target = o.edge * target / o.nshapes;
    }
    if (!o.refine) {
        if (compat_improve(cpp, target, o.smooth) < 0) return -1;
        return compat_min_angle(cpp, NULL) * 180 / M_PI;
    }
    struct compat_refine_params pa = refine_params(&o, cpp);
    struct compat_refine_stats rs;
    /* compat_refine, a round at a time for the progress count */
    struct compat_refiner *r = compat_refine_begin(cpp, &pa, &rs);
    if (!r) return -1;
    struct progress pr;
    progress_start(&pr, "compat-tri: refinement rounds", 0);
    int k;
    long done = 0;
    while ((k = compat_refine_step(r)) > 0) progress_step(&pr, ++done);
    progress_end(&pr);
    if (k < 0) { compat_refine_abandon(r); return -1; }
    if (compat_refine_finish(r) < 0) return -1;
    return refine_report(&o, cpp, q0, &rs, &pa, NULL);
}

/* The candidates of a default run, in their order of preference on a tie:
 * the points the matching placed (built by main), the given rows alone
 * (-m off; 3 or more rows), the matching with twice --match-points, the
 * same with the spread term (--spread SPREAD_RETRY, where the stretch of
 * a leg bunched at one end is what keeps the mesh below the goal), and
 * (3 or more rows) the matched points moved by --match-polish
 * MPOLISH_STEPS.  Which one reaches the goal changes from subset to subset
 * of the same poses, and no count of the triangulations told them apart
 * in advance (see race). */
enum { C_MATCHED, C_ROWS, C_DENSE, C_SPREAD, C_POLISH, NCAND };
#define RACE_ROUNDS 3
/* rounds a candidate may step ahead of the race in all (cand_prestep) */
#define PRE_MAX 16
#define RACE_BEHIND 2
/* the work of a round (struct candidate): its accepted smoothing moves
 * (vertex x shape) plus ROUND_WORK per vertex and shape for the rest
 * (flips, quality, splits); a count, not a clock, so the race's decisions
 * and output do not depend on the machine or its load */
#define ROUND_WORK 10
/* what the race reads of a candidate's refinement after a round
 * (compat_refine_pass, compat_refine_progress): kept per round, so that a
 * round stepped ahead (struct ahead) is judged when the race takes it, as
 * if it ran then */
struct cand_state {
    int pass, prounds, pnbad;         /* the pass, its rounds, its last round's triangles below the goal */
    double pworst;                    /* and worst angle (radians) */
    double worst;                     /* the best kept so far (radians) */
    int nbad, fewest;                 /* compat_refine_progress's counts */
};

static void cand_state_read(const struct compat_refiner *r, struct cand_state *s)
{
    compat_refine_pass(r, &s->pass, &s->prounds, &s->pworst, &s->pnbad);
    compat_refine_progress(r, &s->worst, &s->nbad, &s->fewest);
}

struct candidate {
    const char *name;                 /* for -v */
    struct options opt;               /* its options (C_MATCHED: main's) */
    struct compat cp;
    struct compat_refiner *r;         /* NULL once finished or dropped */
    struct compat_refine_params pa;
    struct compat_refine_stats rs;
    double q0, q;                     /* worst angle before (radians), after (degrees; -1: none) */
    int want;                         /* a candidate of this run */
    int built;                        /* started (or tried: then r NULL and q -1) */
    int rounds, moves;                /* rounds run; rs.moves when the last was counted */
    double work;                      /* of its rounds so far (ROUND_WORK) */
    int pre, used;                    /* rounds stepped ahead (struct ahead, cand_prestep), of them taken */
    int status[PRE_MAX];              /* what those steps returned */
    double prework[PRE_MAX];          /* and their work */
    struct cand_state prestate[PRE_MAX];   /* and the state after them */
    struct cand_state now;            /* the state after the last round taken */
    struct rings *R;                  /* cand_build: the outlines, */
    int ok;                           /* built and triangulated, */
    char log[LOG_SIZE], err[512];     /* its -v lines and error */
};

/* the work of the round k just ran (ROUND_WORK) */
static double round_work(struct candidate *k)
{
    double w = (k->rs.moves > k->moves ? k->rs.moves - k->moves : 0) + (double)ROUND_WORK * k->cp.nv * k->cp.N;
    k->moves = k->rs.moves;
    return w;
}

/* a round of candidate k (one stepped ahead if there is one); finishes it
 * when its splitting stops; 0 or -1 */
static int cand_step(const struct options *o, struct candidate *k, struct progress *pr, long *rounds)
{
    int st;
    if (k->used < k->pre) {
        k->work += k->prework[k->used];
        k->now = k->prestate[k->used];
        st = k->status[k->used++];
    } else if ((st = compat_refine_step(k->r)) >= 0) {
        k->work += round_work(k);
        cand_state_read(k->r, &k->now);
    }
    k->rounds++;
    progress_step(pr, ++*rounds);
    if (st < 0) return -1;
    if (st == 0) {
        int rc = compat_refine_finish(k->r);
        k->r = NULL;
        if (rc < 0) return -1;
        k->q = refine_report(o, &k->cp, k->q0, &k->rs, &k->pa, k->name);
    }
    return 0;
}

/* the goal a mesh is held to, in degrees: --min-angle, or the sharpest
 * corner of its outline where that is smaller (a triangle in that corner
 * has no larger angle, so a run whose mesh is there tries no other
 * candidate) -- unless the input has no corner that sharp: a corner the
 * simplification made sharper than the drawing is not a goal (another
 * candidate's outline may not have it) */
static double mesh_goal(const struct options *o, const struct compat *cp)
{
    return fmin(o->min_angle, fmax(o->sharp_in, compat_sharpest_corner(cp) * 180 / M_PI));
}

/* worst angle q (degrees) of cp below its goal (mesh_goal, to rounding) */
static int below_goal(const struct options *o, const struct compat *cp, double q)
{
    return q < mesh_goal(o, cp) * (1 - 1e-6);
}

/* the largest worst angle (degrees) of the finished candidates (-1: none) */
static double best_q(struct candidate *const *K)
{
    double q = -1;
    for (int a = 0; a < NCAND; a++)
        if (K[a]->built && K[a]->q > q) q = K[a]->q;
    return q;
}

/* the largest worst angle (degrees) a candidate has kept so far: a
 * finished one's, or a running one's best (compat_refine_progress; 0:
 * none) */
static double best_sofar(struct candidate *const *K)
{
    double q = 0;
    for (int a = 0; a < NCAND; a++) {
        if (!K[a]->built) continue;
        double w = K[a]->q;
        if (K[a]->r) w = K[a]->now.worst * 180 / M_PI;
        if (w > q) q = w;
    }
    return q;
}

/* a is behind b (both running; b RACE_ROUNDS rounds or more into the
 * current pass of its refinement after no more work or no more rounds
 * than a, a one round or more into its own): a's last round
 * has RACE_BEHIND times b's triangles below the goal or more and a
 * smaller worst angle than b's last round -- smaller by RACE_MARGIN
 * degrees or more, and the best a kept (an earlier pass's result
 * included) too, where either is in a later pass, and b within
 * RACE_MARGIN of the goal (radians) where a is.  The second and third passes split only the
 * worst share of those triangles, and their result gains most in the
 * final polish, so their last round says less (measured: t0587 horse
 * poses 2 5 with --spread 0 kept 15.49 deg instead of 16.17 without the
 * margin, the rows alone dropped at 10.41 deg against 11.09; the traced
 * camel's side frames 1 4 5 kept 18.10 instead of 19.08 without the
 * nearness to the goal, the spread candidate dropped at 11.84 against
 * 16.74).  The -v words for it in why (wsize bytes). */
#define RACE_MARGIN 3
static int cand_behind(const struct candidate *a, const struct candidate *b, double goal, char *why, size_t wsize)
{
    int pa = a->now.pass, pb = b->now.pass, ra = a->now.prounds, rb = b->now.prounds, na = a->now.pnbad,
        nb = b->now.pnbad;
    double wa = a->now.pworst, wb = b->now.pworst, best = a->now.worst;
    if (ra < 1 || rb < RACE_ROUNDS || (b->work > a->work && b->rounds > a->rounds) || (double)na < RACE_BEHIND * (double)nb)
        return 0;
    double margin = pa || pb ? RACE_MARGIN * M_PI / 180 : 0;
    if (!(wa < wb - margin && (margin == 0 || best < wb - margin))) return 0;
    if (pa && wb < goal - margin) return 0;   /* a in a later pass, b not near the goal yet */
    snprintf(why, wsize, "%s dropped after %d rounds: worst angle %.2f deg with %d triangles below the goal (%s after %d: "
             "%.2f deg, %d)", a->name, a->rounds, wa * 180 / M_PI, na, b->name, b->rounds, wb * 180 / M_PI, nb);
    return 1;
}

/* one round of candidate k stepped ahead of the race: what it returned,
 * its work and its state kept for cand_step to take in order; returns
 * what compat_refine_step returned */
static int cand_ahead_round(struct candidate *k)
{
    int st = compat_refine_step(k->r);
    k->status[k->pre] = st;
    if (st >= 0) cand_state_read(k->r, &k->prestate[k->pre]);
    k->prework[k->pre++] = st >= 0 ? round_work(k) : 0;
    return st;
}

/* The given rows alone (C_ROWS) built ahead: with 2 or more threads it is
 * built, triangulated and refined up to RACE_ROUNDS rounds on a thread of
 * its own while the matched points are triangulated and refined on the
 * other, so both cores work where the triangulations are serial; the race
 * takes it once its build is done and the round running ends.  Its
 * rounds are the same whenever they run, so the race below decides on
 * the same numbers and the output is the one of the sequential order; its
 * -v lines are kept and printed where the race takes it. */
struct ahead {
    pthread_t th;
    int started;
    atomic_int done, stop, wait;      /* set by the thread at its end; ask it to stop early;
                                       * the caller waits for it: no more rounds after the one
                                       * running (the race steps the rest in its order) */
    struct options off;
    struct rings *R;
    struct candidate *k;
    int ok;                           /* built and triangulated */
    char err[512];
    char log[LOG_SIZE];
};

static void *ahead_run(void *arg)
{
    struct ahead *a = arg;
    struct candidate *k = a->k;
    a->off.log = a->log;
    int built = build_single(&a->off, a->R, &k->cp) == 0;
    k->cp.threads = 1;   /* the caller's triangulation has the other threads */
    if (!built || (atomic_load(&a->stop) ? 0 : compat_triangulate(&k->cp) < 0)) {
        snprintf(a->err, sizeof a->err, "%s", cm_errmsg());
        goto out;
    }
    if (atomic_load(&a->stop)) goto out;
    a->ok = 1;
    k->q0 = compat_min_angle(&k->cp, NULL);
    k->pa = refine_params(&a->off, &k->cp);
    k->pa.threads = 1;
    if (!(k->r = compat_refine_begin(&k->cp, &k->pa, &k->rs))) { a->ok = 0; snprintf(a->err, sizeof a->err, "%s", cm_errmsg()); goto out; }
    cand_state_read(k->r, &k->now);
    while (k->pre < RACE_ROUNDS && !atomic_load(&a->stop) && !atomic_load(&a->wait))
        if (cand_ahead_round(k) <= 0) break;
out:
    atomic_store(&a->done, 1);
    return NULL;
}

/* rounds of candidate k stepped ahead on one thread (up to PRE_MAX in
 * all, taken by cand_step in order) until *until is set: the race waiting
 * for the thread of struct ahead steps the rounds it will take next */
static void cand_prestep(struct candidate *k, atomic_int *until, int threads)
{
    if (!k->r) return;
    compat_refine_threads(k->r, 1);
    while (k->pre < PRE_MAX && !atomic_load(until))
        if (cand_ahead_round(k) <= 0) break;
    compat_refine_threads(k->r, threads);
}

/* starts the thread (a zeroed, k: the candidate to fill); 0 if it did not start */
static int ahead_start(struct ahead *a, const struct options *o, struct rings *R, struct candidate *k)
{
    a->off = *o;
    a->off.match = -2;
    a->off.points_out = NULL;
    a->off.points_mem = NULL;
    a->R = R;
    a->k = k;
    a->started = pthread_create(&a->th, NULL, ahead_run, a) == 0;
    return a->started;
}

/* waits for it; stop: it is not needed */
static void ahead_join(struct ahead *a, int stop)
{
    if (!a->started) return;
    atomic_store(stop ? &a->stop : &a->wait, 1);
    pthread_join(a->th, NULL);
    a->started = 0;
}

/* Candidate k (not C_MATCHED) built from k->opt and triangulated, its -v
 * lines kept in k->log and an error in k->err (k->ok: built); on a thread
 * of its own (cand_build_run) beside the others where there are threads:
 * every build is serial, and each one's result does not depend on the
 * others' */
static void cand_build(struct candidate *k, struct rings *R)
{
    k->opt.log = k->log;
    k->ok = build_single(&k->opt, R, &k->cp) == 0 && compat_triangulate(&k->cp) == 0;
    k->opt.log = NULL;
    if (!k->ok) snprintf(k->err, sizeof k->err, "%s", cm_errmsg());
}

static void *cand_build_run(void *arg)
{
    cand_build(arg, ((struct candidate *)arg)->R);
    return NULL;
}

/* Candidate k after cand_build (C_ROWS: taken from the thread ah if it was
 * started there) started: its -v lines printed, its refinement begun.  0,
 * or -1 (said with -v, k left out) if it could not be built. */
static int cand_start(struct candidate *k, struct ahead *ah, int threads)
{
    k->built = 1;
    if (ah && ah->started) {   /* the rows alone, built ahead */
        ahead_join(ah, 0);
        snprintf(k->log, sizeof k->log, "%s", ah->log);
        snprintf(k->err, sizeof k->err, "%s", ah->err);
        k->ok = ah->ok && k->r;
        if (k->ok) compat_refine_threads(k->r, threads);
    } else if (k->ok) {
        k->q0 = compat_min_angle(&k->cp, NULL);
        k->pa = refine_params(&k->opt, &k->cp);
        if (!(k->r = compat_refine_begin(&k->cp, &k->pa, &k->rs))) {
            k->ok = 0;
            snprintf(k->err, sizeof k->err, "%s", cm_errmsg());
        } else cand_state_read(k->r, &k->now);
    }
    for (char *l = k->log, *e; *l && (e = strchr(l, '\n')); l = e + 1) {   /* its -v lines */
        *e = 0;
        info(1, "%s: %s", k->name, l);
    }
    if (k->ok) return 0;
    info(1, "%s: %s; left out", k->name, k->err);
    if (k->r) compat_refine_abandon(k->r);
    k->r = NULL;
    compat_free(&k->cp);   /* compat_match clears it first */
    memset(&k->cp, 0, sizeof k->cp);
    k->q = -1;
    return -1;
}

/* The default matching (cp: the matched points, built and triangulated,
 * q0 its worst angle, radians) against the other candidates of the run
 * (C_MATCHED..C_POLISH, those its options leave), in stages:
 *   0  the matched points alone, while their triangles below the goal
 *      keep falling;
 *   1  not at the goal after RACE_ROUNDS rounds (or finished below it):
 *      the rows alone beside them (3 or more rows);
 *   2  no candidate left in its first pass (every first pass ended below
 *      the goal): the matching with twice --match-points and the spread
 *      candidate as well -- where a first pass reaches the goal they are
 *      never built (the traced elephant walk without rows, the six shared
 *      elephant poses: measured in compat-tri(1));
 *   3  every one finished below the goal: the polished matching.
 * Every live candidate is refined a round at a time, the one with the
 * least work (ROUND_WORK) so far first; the first to finish at the goal is
 * kept and the others stopped, so a candidate whose maps are stretched
 * does not run to --max-vertices before the one that reaches the goal in
 * a few rounds starts (t0587's six horse poses: 8.75 -> 1.8 s).  A
 * candidate falling behind another is dropped (cand_behind; on the six
 * elephant poses the matched points have 434 bad triangles at 3.7 deg
 * against the rows alone's 201 at 6.8 and would go on to 3041 vertices at
 * 18.5 deg).  If none reaches the goal, the largest worst angle is kept
 * (the first in the order of the enum on a tie).  ah: the rows alone
 * built ahead (struct ahead; not started: built here when needed).  On
 * return cp holds the kept mesh and kept (ksize bytes) its name for -v;
 * returns its worst angle (degrees). */
/* the further matching has DENSE_FACTOR times --match-points (measured on
 * the survey of compat-tri(1): 2 raised the mean worst angle of the 37
 * subsets below 20 deg from 8.40 to 9.34 at 64 -> 97 s of CPU, 3 to 9.52
 * at 118 s, the horse worse than with 2) */
#ifndef DENSE_FACTOR
#define DENSE_FACTOR 2
#endif
/* the spread candidate's weight and --match-points factor (measured in
 * compat-tri(1): with 1 times the points the horse gained nothing) */
#ifndef SPREAD_RETRY
#define SPREAD_RETRY 3
#endif
#ifndef SPREAD_POINTS
#define SPREAD_POINTS 2
#endif
/* the stretch the given points force (the certificate) from which the
 * polished matching starts beside the rows alone instead of last:
 * measured on t0587's flamingo (five rows), whose subsets forcing 5.2-8.2x
 * reach the goal only with the polish, see compat-tri(1) */
#ifndef POLISH_FIRST
#define POLISH_FIRST 4
#endif
/* the certificate's cost the race pays for that at most: one mesh of
 * each quadruple of given rows in each pose (7 rows on 7 poses, 6 on 16,
 * 8 on 3).  Measured on t0587's characters with all seven rows: runs at
 * the goal soon after 3 rounds pay 0.03-0.06 s (horse poses 0 1 4 0.06
 * -> 0.10 s, 1 3 4 0.04 -> 0.10), flamingo poses 2 3 reach it with the
 * polish 3.52 -> 0.53 s, 1 2 3 8.08 -> 1.16 s (the same meshes) */
#ifndef CERT_RACE_MESHES
#define CERT_RACE_MESHES 250
#endif
static double race(struct options *o, struct rings *R, struct compat *cp, double q0, struct ahead *ah,
                   char *kept, size_t ksize)
{
    struct candidate k0, k2, k3, k4, *K[NCAND] = {&k0, ah->k, &k2, &k3, &k4};
    memset(&k0, 0, sizeof k0);
    memset(&k2, 0, sizeof k2);
    memset(&k3, 0, sizeof k3);
    memset(&k4, 0, sizeof k4);
    for (int a = 0; a < NCAND; a++) {
        K[a]->opt = *o;
        K[a]->opt.points_out = NULL;
        K[a]->opt.points_mem = NULL;
        K[a]->opt.match_default = 0;
        K[a]->q = -1;
    }
    int dense_points = DENSE_FACTOR * o->match_points < 1000 ? DENSE_FACTOR * o->match_points : 1000;
    K[C_ROWS]->opt.match = -2;
    K[C_DENSE]->opt.match_points = dense_points;
    K[C_SPREAD]->opt.spread = SPREAD_RETRY;
    if (!o->match_points_given)
        K[C_SPREAD]->opt.match_points = SPREAD_POINTS * o->match_points < 1000 ? SPREAD_POINTS * o->match_points : 1000;
    K[C_POLISH]->opt.mpolish = MPOLISH_STEPS;
    K[C_POLISH]->opt.mpolish_soft = 1;
    K[C_MATCHED]->want = 1;
    K[C_ROWS]->want = o->match_default;
    K[C_DENSE]->want = dense_points > o->match_points && !o->match_points_given;
    K[C_SPREAD]->want = !o->spread_given;
    K[C_POLISH]->want = o->match_default && !o->mpolish_given;
    char dname[64], sname[80], pname[64];
    snprintf(dname, sizeof dname, "the matching with %d points", dense_points);
    snprintf(sname, sizeof sname, "the matching with %d points and --spread %g", K[C_SPREAD]->opt.match_points,
             (double)SPREAD_RETRY);
    snprintf(pname, sizeof pname, "the matched points with --match-polish %d", MPOLISH_STEPS);
    K[C_MATCHED]->name = "the matched points";
    K[C_ROWS]->name = "the given rows only (-m off)";
    K[C_DENSE]->name = dname;
    K[C_SPREAD]->name = sname;
    K[C_POLISH]->name = pname;
    struct candidate *m = K[C_MATCHED];
    m->cp = *cp;
    m->built = 1;
    m->q0 = q0;
    m->pa = refine_params(o, cp);
    if (ah->started) m->pa.threads = 1;   /* the other core builds the rows alone */
    if (!(m->r = compat_refine_begin(&m->cp, &m->pa, &m->rs))) die("%s", cm_errmsg());
    cand_state_read(m->r, &m->now);
    struct progress pr;
    long done = 0;
    int stage = 0, win = -1;   /* 0: the matched points alone, 1: and the rows alone, 2: and the further matchings */
    progress_start(&pr, "compat-tri: refinement rounds", 0);
    for (;;) {
        if (m->r && ah->started && atomic_load(&ah->done)) compat_refine_threads(m->r, o->threads);
        if (!m->r && !below_goal(o, &m->cp, m->q)) { win = C_MATCHED; break; }   /* at the goal alone */
        int nbad0 = 0, fewest0 = 0;
        if (m->r) { nbad0 = m->now.nbad; fewest0 = m->now.fewest; }
        /* the rows alone (3 or more rows) once the matched points fall
         * short after RACE_ROUNDS rounds */
        if (stage == 0 && (!m->r || (m->rounds >= RACE_ROUNDS && nbad0 > fewest0))) {
            stage = 1;
            /* the polished matching now too where the given points force
             * a stretch of POLISH_FIRST or more (the certificate, computed
             * here if -v did not: a run at the goal in its first rounds
             * does not pay for it; not where it costs more than
             * CERT_RACE_MESHES meshes, with or without -v) */
            if (K[C_POLISH]->want) {
                if (o->forced < 0) {
                    char line[1024];
                    certify(o, R, o->flipped, line, sizeof line, CERT_RACE_MESHES);
                }
                if (o->cert_meshes <= CERT_RACE_MESHES && o->forced >= POLISH_FIRST) {
                    info(1, "the given points force a stretch of at least %.3gx (certificate): %s too; at %.3f s",
                         o->forced, K[C_POLISH]->name, elapsed());
                    cand_build(K[C_POLISH], R);
                    cand_start(K[C_POLISH], NULL, o->threads);
                }
            }
            if (K[C_ROWS]->want) {
                if (m->r)
                    info(1, "the matched points not at the goal after %d rounds, %d triangles below it (%d after an "
                            "earlier round): %s too; at %.3f s", m->rounds, nbad0, fewest0, K[C_ROWS]->name, elapsed());
                else info(1, "below the goal with the matched points (%.2f deg): %s too; at %.3f s", m->q,
                          K[C_ROWS]->name, elapsed());
                K[C_ROWS]->R = R;
                if (!ah->started) cand_build(K[C_ROWS], R);
                /* the matched points' next rounds meanwhile, where the
                 * other core is still building the rows alone */
                else if (m->used == m->pre) {
                    atomic_store(&ah->wait, 1);   /* the rows alone's rounds are the race's now */
                    cand_prestep(m, &ah->done, 1);
                }
                if (cand_start(K[C_ROWS], ah, o->threads) == 0 && K[C_ROWS]->pa.threads == 1)
                    compat_refine_threads(K[C_ROWS]->r, o->threads);
                if (m->r) compat_refine_threads(m->r, o->threads);
                continue;
            }
        }
        /* the further matchings once no first pass is left (every live
         * candidate's ended below the goal): where one reaches it there,
         * as the matched points alone on the traced elephant walk or the
         * rows alone on the six shared elephant poses, nothing more is
         * built (measured: with them from the start 0.6 -> 1.55 s there) */
        int first = 0;
        for (int a = 0; a < NCAND; a++)
            if (K[a]->built && K[a]->r && !K[a]->now.pass) first = 1;
        if (stage == 1 && !first) {
            stage = 2;
            char names[512] = "";
            for (int a = C_DENSE; a < C_POLISH; a++)
                if (K[a]->want) {
                    size_t l = strlen(names);
                    snprintf(names + l, sizeof names - l, "%s%s", l ? "; " : "", K[a]->name);
                }
            if (!*names) continue;
            info(1, "no first pass at the goal (%.2f deg kept so far): %s too; at %.3f s", best_sofar(K), names, elapsed());
            /* built side by side where there are threads */
            pthread_t th[NCAND];
            int on[NCAND] = {0}, par = parallel_threads(o->threads) > 1;
            for (int a = C_DENSE; a < C_POLISH; a++) {
                if (!K[a]->want) continue;
                K[a]->R = R;
                if (par) on[a] = pthread_create(&th[a], NULL, cand_build_run, K[a]) == 0;
                if (!on[a]) cand_build(K[a], R);
            }
            for (int a = C_DENSE; a < C_POLISH; a++)
                if (on[a]) pthread_join(th[a], NULL);
            for (int a = C_DENSE; a < C_POLISH; a++)
                if (K[a]->want) cand_start(K[a], NULL, o->threads);
            continue;
        }
        int pick = -1;   /* the least work first */
        for (int a = 0; a < NCAND; a++)
            if (K[a]->built && K[a]->r && (pick < 0 || K[a]->work < K[pick]->work)) pick = a;
        if (pick < 0 && K[C_POLISH]->want && !K[C_POLISH]->built) {
            /* every other one below the goal: the polish, last (its
             * matching costs as the rows^4 and took 0.4-10 s on two to
             * six poses of t0587's horse and flamingo) */
            info(1, "below the goal (%.2f deg): %s too; at %.3f s", best_q(K), K[C_POLISH]->name, elapsed());
            cand_build(K[C_POLISH], R);
            cand_start(K[C_POLISH], NULL, o->threads);
            continue;
        }
        if (pick < 0) break;
        if (cand_step(o, K[pick], &pr, &done) < 0) die("%s", cm_errmsg());
        if (!K[pick]->r && !below_goal(o, &K[pick]->cp, K[pick]->q)) { win = pick; break; }
        /* one behind another after no more work is dropped (one a round) */
        for (int a = 0, dropped = 0; a < NCAND && !dropped; a++) {
            if (!K[a]->built || !K[a]->r) continue;
            for (int b = 0; b < NCAND; b++) {
                char why[512];
                if (b != a && K[b]->built && K[b]->r && cand_behind(K[a], K[b], m->pa.goal, why, sizeof why)) {
                    info(1, "%s; at %.3f s", why, elapsed());
                    compat_refine_abandon(K[a]->r);
                    K[a]->r = NULL;
                    K[a]->q = -1;
                    dropped = 1;
                    break;
                }
            }
        }
    }
    progress_end(&pr);
    if (ah->started) {   /* not needed: the matched points reached the goal */
        ahead_join(ah, 1);
        if (ah->k->r) compat_refine_abandon(ah->k->r);
        ah->k->r = NULL;
        compat_free(&ah->k->cp);
        memset(&ah->k->cp, 0, sizeof ah->k->cp);
    }
    /* kept: the first at the goal, else the largest worst angle */
    int use = win;
    if (use < 0) {
        use = 0;
        for (int a = 1; a < NCAND; a++)
            if (K[a]->built && K[a]->q > K[use]->q) use = a;
    }
    for (int a = 0; a < NCAND; a++)
        if (K[a]->r) {
            info(1, "%s stopped after %d rounds: %s reached the goal", K[a]->name, K[a]->rounds, K[use]->name);
            compat_refine_abandon(K[a]->r);
            K[a]->r = NULL;
            K[a]->q = -1;
        }
    int nbuilt = 0;
    for (int a = 1; a < NCAND; a++) nbuilt += K[a]->built;
    if (nbuilt) {
        char rest[512] = "";
        for (int a = 0; a < NCAND; a++)
            if (a != use && K[a]->built && K[a]->q >= 0) {
                size_t l = strlen(rest);
                snprintf(rest + l, sizeof rest - l, "%s%s: %.2f deg", l ? "; " : "", K[a]->name, K[a]->q);
            }
        if (K[use]->q >= 0)
            info(1, "kept %s: worst angle %.2f deg%s%s%s", K[use]->name, K[use]->q, *rest ? " (" : "", rest, *rest ? ")" : "");
    }
    for (int a = 0; a < NCAND; a++)
        if (a != use && K[a]->built) compat_free(&K[a]->cp);
    *cp = K[use]->cp;
    snprintf(kept, ksize, "%s", K[use]->name);
    if (use > 0 && (o->points_out || o->points_mem)) {   /* the rows actually used */
        struct compat tmp;
        char quiet[LOG_SIZE] = "";   /* its -v lines were printed */
        struct options *w = &K[use]->opt;
        w->points_out = o->points_out;
        w->points_mem = o->points_mem;
        w->log = quiet;
        if (build_single(w, R, &tmp) == 0) compat_free(&tmp);
    }
    return K[use]->q;
}

/* --layers: the faces sorted by layer (stable: the ring whose vertices
 * their connected component holds, the first ring first), so that a
 * renderer drawing them in order puts the later layers in front */
static void layer_order(struct compat *cp)
{
    int nv = cp->nv, nf = cp->nf, nr = cp->nrings;
    int *lab = malloc(((size_t)nv + 1) * sizeof *lab), *stack = malloc(((size_t)nv + 1) * sizeof *stack);
    int *F = malloc(3 * ((size_t)nf + 1) * sizeof *F), *cnt = calloc((size_t)nr + 1, sizeof *cnt);
    struct topology t;
    if (!lab || !stack || !F || !cnt || topology_build(cp->F, nf, nv, &t) < 0) die("out of memory");
    for (int v = 0; v < nv; v++) lab[v] = -1;
    for (int r = 0; r < nr; r++) {   /* each layer's component, from its first ring vertex */
        int top = 0;
        lab[cp->ring_start[r]] = r;
        stack[top++] = cp->ring_start[r];
        while (top) {
            int v = stack[--top];
            for (int k = t.VVs[v]; k < t.VVs[v + 1]; k++)
                if (lab[t.VV[k]] < 0) { lab[t.VV[k]] = r; stack[top++] = t.VV[k]; }
        }
    }
    for (int f = 0; f < nf; f++) {
        if (lab[cp->F[3 * f]] < 0) die("internal: a face in no layer");
        cnt[lab[cp->F[3 * f]] + 1]++;
    }
    for (int r = 0; r < nr; r++) cnt[r + 1] += cnt[r];
    for (int f = 0; f < nf; f++) memcpy(F + 3 * (size_t)cnt[lab[cp->F[3 * f]]]++, cp->F + 3 * (size_t)f, 3 * sizeof *F);
    memcpy(cp->F, F, 3 * (size_t)nf * sizeof *F);
    topology_free(&t);
    free(lab); free(stack); free(F); free(cnt);
}

/* the triangulation's progress (struct compat.progress) in TRI_STEPS */
#define TRI_STEPS 1000
static void tri_progress(void *ctx, double done)
{
    progress_step(ctx, lround(done * TRI_STEPS));
}

/* one outer ring per shape (R): made counter-clockwise once, for every
 * build (flipped[s] = 1 where the file ran clockwise), and o->sharp_in */
static void single_prepare(struct options *o, struct rings *R, int *flipped)
{
    for (int s = 0; s < o->nshapes; s++)
        if ((flipped[s] = rings_orient(&R[s])))
            info(1, "%s: clockwise outline reversed (indices refer to the file order)", R[s].name);
    o->sharp_in = 180;
    for (int s = 0; s < o->nshapes; s++) o->sharp_in = fmin(o->sharp_in, rings_sharpest_left(&R[s], 0) * 180 / M_PI);
}

/* The mesh of R (N shapes; multi: several rings or interior points,
 * else one outer ring each, oriented by single_prepare) into cp: built,
 * triangulated, refined (the race of candidates where the matching is
 * the default) and, one outer ring, its outline checked after the
 * refinement's slides.  o is changed (the matching used). */
static void mesh_rings(struct options *o, struct rings *R, int multi, struct compat *cp)
{
    int N = o->nshapes;
    if (multi) build_multi(o, R, cp);
    else if (build_single(o, R, cp) < 0) die("%s", cm_errmsg());
    /* the default's second candidate, built ahead on a second thread */
    struct candidate k1;
    struct ahead ah;
    memset(&k1, 0, sizeof k1);
    memset(&ah, 0, sizeof ah);
    ah.k = &k1;
    if (!multi && o->match_default && o->refine && o->threads != 1 && parallel_threads(o->threads) > 1)
        ahead_start(&ah, o, R, &k1);
    /* a bar on a terminal while the first triangulation runs (the
     * candidates' on other threads show none) */
    struct progress tp;
    progress_start(&tp, "compat-tri: triangulation", TRI_STEPS);
    cp->progress = tri_progress;
    cp->progress_ctx = &tp;
    int tri_rc = multi ? 0 : compat_triangulate(cp);
    cp->progress = NULL;
    progress_end(&tp);
    if (tri_rc < 0) {
        if (ah.started) {   /* the rows alone are built again below */
            ahead_join(&ah, 1);
            if (k1.r) compat_refine_abandon(k1.r);
            compat_free(&k1.cp);
        }
        /* the points placed by the default matching between 3 or more given
         * rows can make a piece too thin to split; the given rows alone are
         * the earlier default (-m off): use them and say so */
        if (!o->match_default) die("%s", cm_errmsg());
        char msg[512];
        snprintf(msg, sizeof msg, "%s", cm_errmsg());
        compat_free(cp);
        o->match = -2;
        o->match_default = 0;   /* the rows alone already: nothing to compare */
        if (build_single(o, R, cp) < 0 || compat_triangulate(cp) < 0) die("%s", cm_errmsg());
        warn("with the matched points: %s; used the given rows only (-m off)", msg);
    }
    double ma0, q0 = compat_min_angle(cp, &ma0);
    info(1, "triangulation: %d triangles, %d Steiner points (splits: %d stage I, %d stage II, %d %s), "
            "min angle %.2f deg; at %.3f s", cp->nf, cp->nsteiner, cp->stage_count[0], cp->stage_count[1],
         cp->stage_count[2], o->split != COMPAT_LINKPATH ? "overlays" : "stage III", q0 * 180 / M_PI, elapsed());
    char kept[96] = "the matched points";   /* -v: the name of the mesh in cp */
    /* the default matching: its candidates raced (race) */
    double q1 = !multi && o->refine && o->match_auto && o->match >= 0 ? race(o, R, cp, q0, &ah, kept, sizeof kept)
                                                                     : improve(o, cp, q0);
    if (q1 < 0) die("%s", cm_errmsg());
    if (!multi && o->refine && o->slide && o->err > 0) {   /* the outline after the slides (--slide), against the input */
        double hmax = 0;
        int hs = 0;
        for (int s = 0; s < N; s++) {
            double h = compat_outline_error(cp, s, R[s].P, rings_count(&R[s], 0));
            if (h > hmax) { hmax = h; hs = s; }
        }
        if (hmax > o->err * (1 + 1e-6)) {
            char in[64] = "";
            if (o->layer) snprintf(in, sizeof in, "ring %d (a layer) of ", o->layer);
            die("the outline of %s%s is %.3g of the diagonal off its input after the refinement's slides (tolerance %g)",
                in, o->shapes[hs], hmax, o->err);
        }
        info(1, "outline after the refinement (--slide): within %.3g of the diagonal of the input (two-sided, largest in %s)",
             hmax, o->shapes[hs]);
    }
}

/* --layers: a ring inside another in every shape is likely a hole (an eye)
 * drawn as a ring; as a layer it is filled and drawn over the other, not
 * cut out of it, which is said */
static void layers_nested(int N, const struct rings *R)
{
    int nr = R[0].nrings;
    for (int b = 0; b < nr; b++)
        for (int a = 0; a < nr; a++) {
            int all = a != b;
            for (int s = 0; s < N && all; s++) all = compat_ring_inside(&R[s], b, a);
            if (all)
                warn("ring %d lies inside ring %d in every shape: with --layers it is a layer drawn over it, not a "
                     "hole (for a hole, mesh without --layers)", b + 1, a + 1);
        }
}

/* --layers (each) with several rings R: every layer meshed on its own as
 * one outer ring (single_prepare, mesh_rings: the race of the matchings,
 * the outline checked after the slides), with
 *   - the rows of -c on its ring (each row on the same ring in every
 *     shape), re-indexed to it;
 *   - a layer without rows, where other layers have some, starting as its
 *     surroundings turn: the first row match_rings gives it;
 *   - -e of the whole pose's diagonal: the layer's tolerance scaled by the
 *     smallest ratio of the pose's to the layer's diagonal over the shapes;
 * then stacked (compat_stack) into cp, the first ring's first.  The rows
 * used go to --points-out, every ring counted.  Sets o->sharp_in. */
static void mesh_layers(struct options *o, struct rings *R, struct compat *cp)
{
    int N = o->nshapes, nr = R[0].nrings;
    struct columns C;
    int *order, *corr = multi_rows(o, R, &C, &order), nc = C.rows;
    int *ring = malloc(((size_t)nc + 1) * sizeof *ring), *nrow = calloc(nr, sizeof *nrow);
    if (!ring || !nrow) die("out of memory");
    for (int r = 0; r < nc; r++)
        for (int s = 0; s < N; s++) {
            int v = corr[(size_t)r * N + s], k = 0;
            if (v >= R[s].start[nr])
                die("cannot read '%s': line %ld: '%d' is not a vertex index of '%s' (0..%d)", o->corr,
                    data_line(o->corr, r + 1), v, o->shapes[s], R[s].start[nr] - 1);
            while (v >= R[s].start[k + 1]) k++;
            if (s == 0) ring[r] = k;
            else if (k != ring[r])
                die("cannot read '%s': line %ld: the point is on ring %d of '%s' but on ring %d of '%s'; with "
                    "--layers a row is one point of one layer in every shape", o->corr, data_line(o->corr, r + 1),
                    ring[r] + 1, o->shapes[0], k + 1, o->shapes[s]);
        }
    for (int r = 0; r < nc; r++) nrow[ring[r]]++;
    for (int k = 0; k < nr && o->match == -2; k++)   /* -m off: every layer meshed from its own rows */
        if (nrow[k] < 3)
            die("cannot read '%s': %d row%s on ring %d; with -m off every layer needs at least 3 (without -m off "
                "the matching finds the rest)", o->corr ? o->corr : "-c", nrow[k], nrow[k] == 1 ? "" : "s", k + 1);
    /* the layers, copied in file order before compat_layers orients R */
    struct rings **L = malloc(nr * sizeof *L);
    double *err = malloc(nr * sizeof *err);
    if (!L || !err) die("out of memory");
    for (int k = 0; k < nr; k++) {
        if (!(L[k] = calloc(N, sizeof **L))) die("out of memory");
        err[k] = INFINITY;
        for (int s = 0; s < N; s++) {
            int n = rings_count(&R[s], k);
            if (rings_from_points(&L[k][s], rings_ring(&R[s], k), n) < 0) die("%s", cm_errmsg());
            memcpy(L[k][s].line, R[s].line + R[s].start[k], n * sizeof *R[s].line);
            snprintf(L[k][s].name, sizeof L[k][s].name, "%s", R[s].name);
            err[k] = fmin(err[k], polygon_diagonal(R[s].P, R[s].start[nr]) / polygon_diagonal(rings_ring(&R[s], k), n));
        }
        err[k] *= o->err;
    }
    int nwith = 0, nadd = 0, *add = NULL;   /* a start row for each layer without rows */
    for (int k = 0; k < nr; k++) nwith += nrow[k] > 0;
    if (nwith > 0 && nwith < nr && o->match != -2) {
        int *parent = malloc(nr * sizeof *parent);
        unsigned char *fl = malloc((size_t)N * nr);
        if (!parent || !fl) die("out of memory");
        if (compat_layers(N, R, parent, fl) < 0) die("rings do not match: %s", cm_errmsg());
        int nm, *m = match_rings(o, N, R, parent, fl, corr, nc, &nm);
        if (!(add = malloc(((size_t)nr + 1) * N * sizeof *add))) die("out of memory");
        for (int k = 0; k < nr; k++) {
            if (nrow[k]) continue;
            for (int r = 0; r < nm; r++)
                if (m[(size_t)r * N] >= R[0].start[k] && m[(size_t)r * N] < R[0].start[k + 1]) {
                    memcpy(add + (size_t)nadd++ * N, m + (size_t)r * N, N * sizeof *add);
                    break;
                }
        }
        free(parent); free(fl); free(m);
    }
    struct compat *part = calloc(nr, sizeof *part);
    struct kept_points *kp = calloc(nr, sizeof *kp);
    double *x = malloc(((size_t)nc + nadd + 1) * N * sizeof *x);
    if (!part || !kp || !x) die("out of memory");
    o->sharp_in = 180;
    for (int k = 0; k < nr; k++) {
        /* its rows, as numbers of its own ring */
        struct columns Ck = {0, N, x};
        for (int r = 0; r < nc + nadd; r++) {
            const int *row = r < nc ? corr + (size_t)r * N : add + (size_t)(r - nc) * N;
            if (row[0] < R[0].start[k] || row[0] >= R[0].start[k + 1]) continue;
            for (int s = 0; s < N; s++) x[(size_t)Ck.rows * N + s] = row[s] - R[s].start[k];
            Ck.rows++;
        }
        char name[320];
        snprintf(name, sizeof name, "%s, its rows on ring %d", o->corr ? o->corr : "-c", k + 1);
        struct options lo = *o;
        lo.layers = 0;
        lo.corr = Ck.rows ? name : NULL;
        lo.corr_rows = Ck.rows ? &Ck : NULL;
        lo.points_out = NULL;
        lo.points_mem = o->points_out ? &kp[k] : NULL;
        lo.err = err[k];
        lo.layer = k + 1;
        int *fl = calloc(N, sizeof *fl);
        if (!fl) die("out of memory");
        lo.flipped = fl;
        info(1, "layer %d of %d (ring %d of every file): %d correspondence row%s%s; tolerance %.3g of its diagonal; "
                "at %.3f s", k + 1, nr, k + 1, Ck.rows, Ck.rows == 1 ? "" : "s",
             nrow[k] ? "" : Ck.rows ? " (its start, as the layers around it turn)" : "", err[k], elapsed());
        single_prepare(&lo, L[k], fl);
        mesh_rings(&lo, L[k], 0, &part[k]);
        o->sharp_in = fmin(o->sharp_in, lo.sharp_in);
        info(1, "layer %d: %d vertices, %d triangles, worst angle %.2f deg", k + 1, part[k].nv, part[k].nf,
             compat_min_angle(&part[k], NULL) * 180 / M_PI);
        free(fl);
        for (int s = 0; s < N; s++) rings_free(&L[k][s]);
        free(L[k]);
    }
    if (compat_stack(part, nr, cp) < 0) die("%s", cm_errmsg());
    if (o->points_out) {   /* every layer's rows, numbered over all rings */
        int np = 0, *rows;
        for (int k = 0; k < nr; k++) np += kp[k].n;
        if (!(rows = malloc(((size_t)np + 1) * N * sizeof *rows))) die("out of memory");
        np = 0;
        for (int k = 0; k < nr; k++)
            for (int r = 0; r < kp[k].n; r++, np++)
                for (int s = 0; s < N; s++) rows[(size_t)np * N + s] = kp[k].rows[(size_t)r * N + s] + R[s].start[k];
        rows_to_files(N, R, order, rows, np);
        points_file(o->points_out, N, rows, np, 1);
        free(rows);
    }
    for (int k = 0; k < nr; k++) { compat_free(&part[k]); free(kp[k].rows); }
    free(part); free(kp); free(x); free(L); free(err); free(add); free(ring); free(nrow); free(corr); free(order);
    columns_free(&C);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    blas_single_thread();   /* the transfer's CHOLMOD supernodes are small: BLAS threads only spin */
    struct options o;
    parse_args(argc, argv, &o);
    int N = o.nshapes;
    t_start = now_seconds();
    corr_stdin(&o);

    /* read and check every outline */
    struct rings *R = calloc(N, sizeof *R);
    int multi = o.interior != NULL;
    for (int s = 0; s < N; s++) {
        if (rings_read(o.shapes[s], &R[s]) < 0) die("%s", cm_errmsg());
        for (int k = 0; k < R[s].nrings; k++)
            if (rings_degenerate(&R[s], k))
                die("cannot read '%s': line %ld: degenerate outline (ring %d encloses no area)", R[s].name,
                    R[s].line[R[s].start[k]] - 1, k + 1);
        if (o.layers ? rings_check_each_simple(&R[s]) < 0 : rings_check_simple(&R[s]) < 0) {
            /* each ring simple, but two cross: overlapping parts of a drawing */
            int e1, e2;
            if (!o.layers && rings_check_each_simple(&R[s]) == 0 && rings_first_crossing(&R[s], &e1, &e2) == 1)
                die("cannot read '%s': line %ld: two rings cross (edges from lines %ld and %ld); rings drawn "
                    "over each other as layers need --layers", R[s].name, R[s].line[e2], R[s].line[e1], R[s].line[e2]);
            die("%s", cm_errmsg());
        }
        if (R[s].nrings != 1) multi = 1;   /* one ring: --layers changes nothing */
    }
    struct compat cp;
    int *flipped = calloc(N, sizeof *flipped);
    o.flipped = flipped;
    o.sharp_in = 0;   /* several rings: the mesh's own corners (mesh_goal) */
    if (!multi) single_prepare(&o, R, flipped);
    double ceiling = -1;   /* of the given points, degrees; -1: not computed */
    if (o.bound || (verbose && o.corr)) {
        char line[1024];
        if (multi) snprintf(line, sizeof line, "certificate: not computed for several rings or interior points "
                                                "(the quadrilateral moduli are those of one outer ring)");
        else ceiling = certify(&o, R, flipped, line, sizeof line, 0);
        /* --bound with nothing to bound is refused, not answered with a note */
        if (o.bound && ceiling < 0) die("--bound: %s", line + strlen("certificate: "));
        if (o.bound) {
            printf("%s\n", line + strlen("certificate: "));
            if (fclose(stdout) != 0) die("cannot write output");
            for (int s = 0; s < N; s++) rings_free(&R[s]);
            free(R);
            free(flipped);
            return 0;
        }
        info(1, "%s", line);
    }
    if (o.layers && multi) layers_nested(N, R);
    if (o.layers == LAYERS_EACH && multi) mesh_layers(&o, R, &cp);
    else mesh_rings(&o, R, multi, &cp);
    for (int s = 0; verbose && s < N; s++) {
        double mn, u10, u20;
        compat_pose_quality(&cp, s, &mn, &u10, &u20);
        info(1, "pose %d (%s): worst angle %.2f deg, %.1f%% of triangles under 10 deg, %.1f%% under 20, "
                "%d vertices, %d triangles", s, o.shapes[s], mn * 180 / M_PI, 100 * u10, 100 * u20, cp.nv, cp.nf);
    }
    if (o.layers == LAYERS_JOINT && multi) layer_order(&cp);
    double minarea, q = compat_min_angle(&cp, &minarea);
    if (!(minarea > 0))
        die("compatible triangulation failed: a triangle is inverted or degenerate in some shape");
    info(1, "result: %d vertices (%d boundary, %d Steiner, %d refinement), %d triangles, "
            "min angle %.2f deg over %d shapes, %.3f s", cp.nv, cp.nb, cp.nsteiner, cp.nrefine, cp.nf,
         q * 180 / M_PI, N, elapsed());
    /* a mesh below the goal (mesh_goal) is kept: it is compatible and on
     * the outline, but not at the quality asked for, which is said */
    double goal = mesh_goal(&o, &cp);
    if (o.refine && below_goal(&o, &cp, q * 180 / M_PI)) {
        char g[96];
        if (goal < o.min_angle) snprintf(g, sizeof g, "%.2f deg (the sharpest corner of the outlines)", goal);
        else snprintf(g, sizeof g, "%g deg (--min-angle)", goal);
        warn("worst angle %.2f deg, below the goal of %s; the mesh is written anyway%s", q * 180 / M_PI, g,
             verbose ? "" : " (-v says why)");
    }
    if (ceiling > 0 && q * 180 / M_PI < o.min_angle) {   /* the shortfall against the certificate */
        if (ceiling < o.min_angle)
            info(1, "certificate: the goal of %g deg is out of reach with the given points (no triangulation keeps more "
                    "than %.1f deg); the mesh reaches %.2f deg", o.min_angle, floor(ceiling * 10 + 1e-6) / 10, q * 180 / M_PI);
        else
            info(1, "certificate: below the goal, but the given points allow up to %.1f deg: the shortfall to %g deg is not "
                    "proven to come from the outlines and the given points", floor(ceiling * 10 + 1e-6) / 10, o.min_angle);
    }

    struct mesh m;
    if (mesh_alloc(&m, cp.nv, cp.nf, N) < 0) die("%s", cm_errmsg());
    memcpy(m.F, cp.F, 3 * (size_t)cp.nf * sizeof *m.F);
    for (int s = 0; s < N; s++) {
        double *X = mesh_frame(&m, s);
        for (int v = 0; v < cp.nv; v++) { X[3 * v] = cp.X[s][2 * v]; X[3 * v + 1] = cp.X[s][2 * v + 1]; X[3 * v + 2] = 0; }
    }
    FILE *out = out_open(o.output);
    if (mesh_write(out, &m, want_raw(o.raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    mesh_free(&m);
    compat_free(&cp);
    for (int s = 0; s < N; s++) rings_free(&R[s]);
    free(R);
    free(flipped);
    return 0;
}
