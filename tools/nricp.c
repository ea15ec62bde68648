/* nricp -- register a source mesh to a target scan of different
 * connectivity: optimal-step non-rigid ICP (Amberg et al. 2007) as in the
 * E-StopMotion thesis Sec. 5.2.1, Algorithm 2, after a Procrustes
 * alignment on the landmarks.
 */
#include "blas_tune.h"
#include "clay_deform.h"
#include "thin_shell.h"
#include "closest_point.h"
#include "correspond.h"
#include "geometry.h"
#include "landmarks.h"
#include "landmark_auto.h"
#include "mesh.h"
#include "mesh_distance.h"
#include "nricp.h"
#include "patch_unflip.h"
#include "sample_fit.h"
#include "procrustes.h"
#include "columns.h"
#include "topology.h"
#include "progress.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: nricp [options] [-l LANDMARKS] SOURCE TARGET\n"
"       nricp --chain [options] SOURCE TARGET1 TARGET2 ...\n"
"Deform SOURCE onto the surface of TARGET (any connectivity); writes the\n"
"registered source (SOURCE's connectivity) to stdout.  --chain registers\n"
"SOURCE to every TARGET in turn, each from the previous result, and writes\n"
"the key poses as one animation: SOURCE, then one frame per TARGET.\n"
"\n"
"Options:\n"
"      --chain           a chain of keys: each key starts from the previous key's\n"
"                        result, its ARAP fit relative to SOURCE's shape and to the\n"
"                        previous key's, the better kept (--chain-rest)\n"
"      --chain-rest R    first, previous or both (default): the rest shape of each\n"
"                        key's fit is SOURCE, or the previous key (the one-key-at-a-time\n"
"                        recipe), or every start is tried with both, the best kept\n"
"      --rest FILE       rest shape of the ARAP fit (SOURCE's connectivity), when\n"
"                        SOURCE is a warm start: the first key of a chain\n"
"  -l, --landmarks FILE  rows 'src_vertex dst_vertex' or 'src_vertex x y z'\n"
"                        (optional: without it landmark-auto(1) proposes them)\n"
"      --landmark-mesh M the mesh whose vertices dst_vertex names, if not TARGET\n"
"                        (e.g. the scan before mesh-clean renumbered it)\n"
"      --start S         without -l, how each key starts: landmarks (automatic ones,\n"
"                        ARAP clay start), shell (the same with the thesis' thin\n"
"                        shell), none (no landmarks), or auto (default): landmarks,\n"
"                        and unless that ends within 1% of the diagonal with at most\n"
"                        10 flipped faces also none and shell, the best kept\n"
"      --paper           the thesis' method: thin-shell clay start, Amberg's NRICP\n"
"                        (closest points, 10 iterations per stiffness), no backward\n"
"                        term, no search, no ARAP term or fit, no untangling\n"
"      --no-auto         without -l: no landmarks at all (small motions only)\n"
"      --landmarks-out F write the landmarks used (automatic ones too) to F\n"
"      --align KIND      rigid | similarity | none: Procrustes on the landmarks\n"
"                        first (default rigid; none without >= 3 landmarks)\n"
"  -k, --steps K         stiffness steps (default 6)\n"
"      --alpha-max A     first stiffness (default 50)\n"
"      --alpha-min A     last stiffness, geometric schedule (default 0.5)\n"
"      --beta B          initial landmark weight, fading to 0 (default 10)\n"
"      --gamma G         translation weight in the smoothness term (default 1)\n"
"      --max-angle DEG   reject correspondences whose normals differ more (default 60)\n"
"      --max-dist D      reject correspondences farther than D diagonals (default 0.1, 0 off)\n"
"      --search D        where the closest point's normal disagrees, take the nearest\n"
"                        agreeing point up to D diagonals farther (default 0.01, 0 off)\n"
"      --backward W      weight of target->source correspondences (default 1, 0 off)\n"
"      --max-inner N     iterations per stiffness (default 1)\n"
"      --rigid W         as-rigid-as-possible term inside the stiffness steps, weight\n"
"                        W x alpha / alpha-max per edge: keeps the steps' local\n"
"                        maps near rotations (default 0: off; try 10)\n"
"      --rigid-iters N   its rotation updates per step (default 4)\n"
"      --coarse E        coarse to fine: the stiff steps on SOURCE remeshed to edge\n"
"                        length E (target diagonals), the last --fine-steps on SOURCE,\n"
"                        from the coarse maps (default 0: off)\n"
"      --rigid-const     --rigid keeps its weight W at every step (default: fades)\n"
"      --fine-steps N    steps on SOURCE itself with --coarse (default 2; 0: the\n"
"                        ARAP fit refines the coarse result directly)\n"
"      --untangle R      after the fit, smooth out the pleats where the target's\n"
"                        skin folds (faces on the target but turned over) on the\n"
"                        target, with R rings around them (default 1; 0: off)\n"
"      --unflip R        last, lay the patches still flipped against the target\n"
"                        (R rings around them) flat on it by a foldover-free solve,\n"
"                        each kept where it flips fewer faces; after --refine once\n"
"                        more, until none is flipped or none gets fewer, and at the\n"
"                        largest distance, kept where closer (default 2; 0: off)\n"
"      --refine N        last, N iterations pulling every sample of the kept key\n"
"                        (vertices, centroids, edge midpoints) onto TARGET and TARGET's\n"
"                        onto it, the largest distances first, no face newly flipped,\n"
"                        kept where the Hausdorff distance drops (default 12; 0: off)\n"
"      --fit-release R   the ARAP fit's vertices released at folds keep their place\n"
"                        (stay), take their neighbours' mean (mean: irons flaps of\n"
"                        surplus skin flat), or both (default): the mean too where\n"
"                        stay leaves more than 10 flipped faces, the better kept\n"
"      --fit-smooth-retry N  where the key kept ends farther than 1% of the diagonal\n"
"                        or with more than 10 flipped faces, fit it once more with\n"
"                        the rest shape smoothed N times, the better kept (default\n"
"                        3; 0: off)\n"
"      --settle N        last, register the result again from itself (no landmarks,\n"
"                        the fit's rest shape that result, refined), and again from\n"
"                        that, up to N times, each kept where the Hausdorff distance\n"
"                        + 1e-4 per flipped face drops (at most 10 flipped faces, or\n"
"                        no more than before; a key with more than 10 is not\n"
"                        settled); default 2 with --chain, after the whole chain,\n"
"                        on every key; 0 for one pair: off\n"
"      --passes N        1: one registration per key; 2: register it once more\n"
"                        from its result, as if that were SOURCE (its own\n"
"                        automatic landmarks and starts; the\n"
"                        fit's rest shape is the first result), and keep the one\n"
"                        with the lower Hausdorff distance + 1e-4 per flipped\n"
"                        face; 3: also a third time from the first result with\n"
"                        SOURCE as the rest shape; auto (default): the second only\n"
"                        where the first ends farther than 1% of the diagonal or\n"
"                        with more than 10 flipped faces, the third where both do\n"
"      --parts P         auto (default), yes or no: SOURCE has parts (open boundaries\n"
"                        or several components: a face, eyes, teeth), so target\n"
"                        surface lying over source that already fits (a cap\n"
"                        mesh-clean closed a hole with) pulls nothing and is not\n"
"                        measured, the fit's rest smoothing keeps rims and sizes,\n"
"                        and small parts move rigidly\n"
"      --overlay R       with parts: that test's ratio (default 0.5, 0 off)\n"
"      --small-parts F   with parts: components within F of SOURCE's diagonal or\n"
"                        vertex count, grouped when near, end rigid (default 0.1;\n"
"                        0 off)\n"
"      --nearest-vertex  baseline: correspond to target vertices, not closest points\n"
"      --fit N           ARAP fit iterations after the schedule: unfolds what the\n"
"                        affine maps folded (default 30, 0: pure Amberg)\n"
"      --fit-weight W    final data weight of the ARAP fit (default 30)\n"
"      --fit-smooth N    smoothing sweeps of the fit's rest shape (default 1)\n"
"      --eps E           inner loop tolerance, in diagonals (default 1e-4)\n"
"      --init-deform     first deform the source toward the landmarks with\n"
"                        clay-deform (volume kept if closed): Algorithm 3 (the\n"
"                        default with automatic landmarks)\n"
"      --no-init-deform  do not (with automatic landmarks)\n"
"      --init-model M    its model: arap (default, fast) or shell (the thin shell\n"
"                        of clay-deform(1); implies --init-deform)\n"
"      --init-stiffness FILE  per-vertex stiffness for --init-deform (stiffness(1));\n"
"                        default uniform\n"
"      --steps-out FILE  also write the pose after every stiffness step (animation)\n"
"  -o, --output FILE     write to FILE (atomically) instead of stdout\n"
"      --raw             write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose         per-step report; time, Hausdorff and flipped faces at the end\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: nricp -v -l marks-01-02.txt camel-01.mesh camel-02.mesh > camel-02-reg.mesh\n";

/* how a key starts without -l: the automatic landmarks with the ARAP clay
 * start, the same with the thesis' thin shell, no landmarks at all, or
 * auto: the first, and where it ends worse than START_ACCEPT the other two,
 * the best kept */
enum { START_AUTO, START_LANDMARKS, START_SHELL, START_NONE };
/* auto keeps the landmark start if it ends at most this far (fraction of
 * the target's diagonal, symmetric Hausdorff) with at most START_FLIPS
 * flipped faces */
#define START_ACCEPT 0.01
#define START_FLIPS 10
/* the score of a start: symmetric Hausdorff distance (fraction of the
 * diagonal) + START_FLIP_COST per flipped face + START_STRETCH_COST times
 * the mean edge stretch from SOURCE (nricp_stretch: 10% stretch counts as
 * 1% of the diagonal; a start that slid along the target ends near the
 * surface but stretched) */
#define START_FLIP_COST 1e-4
#define START_STRETCH_COST 0.1

struct options {
    const char *src, *dst, *landmarks, *align, *steps_out, *output, *init_stiffness, *lm_mesh;
    const char *lm_out, *rest;
    const char **targets;
    int ntargets, chain, chain_prev;   /* chain_prev: 0 first, 1 previous, 2 both */
    int chain_rest_given;
    int raw, init_deform, init_shell, no_auto, no_init;
    int start;             /* START_* */
    int start_given;       /* --start on the command line */
    int paper;             /* --paper: the thesis' method */
    int fit_release;       /* 0 stay, 1 mean, 2 both (nricp_params.fit_release per run) */
    int fit_smooth_retry;  /* > fit_smooth: the kept key's second fit with this rest smoothing */
    int refine;            /* iterations of the kept key's last refinement (sample_fit.h) */
    int settle;            /* the result (with --chain every key, after the chain) registered
                              up to this many times more from itself, kept where closer
                              (key_settle) */
    int settle_given;
    int passes_given;      /* --passes on the command line */
    int passes;            /* 2: each key registered again from its result, the better kept;
                              3: and a third time from the first result with the rest
                              shape SOURCE; 0 (auto): the second only where the first
                              ends farther than START_ACCEPT or with more than
                              START_FLIPS flipped faces, the third where both do */
    struct nricp_params p;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    enum { O_ALIGN = 256, O_AMAX, O_AMIN, O_BETA, O_GAMMA, O_ANGLE, O_DIST, O_BACK, O_INNER,
           O_EPS, O_SOUT, O_RAW, O_VERSION, O_INIT, O_INITK, O_NV, O_FIT, O_FITW, O_INITM, O_SEARCH, O_FITS, O_LMESH,
           O_NOAUTO, O_LMOUT, O_NOINIT, O_CHAIN, O_REST, O_CREST, O_START, O_PAPER, O_RIGID,
           O_RIGIDN, O_UNTANGLE, O_FITREL, O_FITSR, O_COARSE, O_FINESTEPS, O_RIGIDC, O_PASSES, O_UNFLIP, O_REFINE, O_SETTLE, O_OVERLAY, O_PARTS, O_SMALL };
    static const struct option lo[] = {
        {"landmarks", 1, 0, 'l'}, {"align", 1, 0, O_ALIGN}, {"steps", 1, 0, 'k'},
        {"alpha-max", 1, 0, O_AMAX}, {"alpha-min", 1, 0, O_AMIN}, {"beta", 1, 0, O_BETA},
        {"gamma", 1, 0, O_GAMMA}, {"max-angle", 1, 0, O_ANGLE}, {"max-dist", 1, 0, O_DIST},
        {"backward", 1, 0, O_BACK}, {"max-inner", 1, 0, O_INNER}, {"eps", 1, 0, O_EPS}, {"fit", 1, 0, O_FIT}, {"fit-weight", 1, 0, O_FITW}, {"init-deform", 0, 0, O_INIT}, {"init-model", 1, 0, O_INITM}, {"search", 1, 0, O_SEARCH}, {"fit-smooth", 1, 0, O_FITS}, {"landmark-mesh", 1, 0, O_LMESH}, {"nearest-vertex", 0, 0, O_NV}, {"init-stiffness", 1, 0, O_INITK},
        {"start", 1, 0, O_START}, {"paper", 0, 0, O_PAPER}, {"rigid", 1, 0, O_RIGID},
        {"rigid-iters", 1, 0, O_RIGIDN}, {"untangle", 1, 0, O_UNTANGLE}, {"unflip", 1, 0, O_UNFLIP}, {"refine", 1, 0, O_REFINE}, {"settle", 1, 0, O_SETTLE}, {"fit-release", 1, 0, O_FITREL},
        {"fit-smooth-retry", 1, 0, O_FITSR}, {"coarse", 1, 0, O_COARSE}, {"fine-steps", 1, 0, O_FINESTEPS}, {"rigid-const", 0, 0, O_RIGIDC}, {"passes", 1, 0, O_PASSES}, {"overlay", 1, 0, O_OVERLAY}, {"parts", 1, 0, O_PARTS}, {"small-parts", 1, 0, O_SMALL},
        {"chain", 0, 0, O_CHAIN}, {"rest", 1, 0, O_REST}, {"chain-rest", 1, 0, O_CREST},
        {"no-auto", 0, 0, O_NOAUTO}, {"landmarks-out", 1, 0, O_LMOUT}, {"no-init-deform", 0, 0, O_NOINIT},
        {"steps-out", 1, 0, O_SOUT}, {"output", 1, 0, 'o'}, {"raw", 0, 0, O_RAW},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, O_VERSION},
        {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    nricp_defaults(&o->p);
    o->align = "rigid";
    o->fit_release = 2;
    o->fit_smooth_retry = 3;
    o->passes = 0;          /* auto */
    o->refine = 12;
    int c;
    while ((c = getopt_long(argc, argv, "l:k:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': o->landmarks = optarg; break;
        case O_ALIGN: o->align = optarg; break;
        case 'k': o->p.steps = arg_int(optarg, "--steps"); break;
        case O_AMAX: o->p.alpha_max = arg_double(optarg, "--alpha-max"); break;
        case O_AMIN: o->p.alpha_min = arg_double(optarg, "--alpha-min"); break;
        case O_BETA: o->p.beta = arg_double(optarg, "--beta"); break;
        case O_GAMMA: o->p.gamma = arg_double(optarg, "--gamma"); break;
        case O_ANGLE: o->p.max_angle = arg_double(optarg, "--max-angle"); break;
        case O_DIST: o->p.max_dist = arg_double(optarg, "--max-dist"); break;
        case O_BACK: o->p.backward = arg_double(optarg, "--backward"); break;
        case O_INNER: o->p.max_inner = arg_int(optarg, "--max-inner"); break;
        case O_INIT: o->init_deform = 1; break;
        case O_NOAUTO: o->no_auto = 1; break;
        case O_CHAIN: o->chain = 1; break;
        case O_START:
            o->start_given = 1;
            if (!strcmp(optarg, "auto")) o->start = START_AUTO;
            else if (!strcmp(optarg, "landmarks")) o->start = START_LANDMARKS;
            else if (!strcmp(optarg, "shell")) o->start = START_SHELL;
            else if (!strcmp(optarg, "none")) o->start = START_NONE;
            else usage_error("--start must be auto, landmarks, shell or none");
            break;
        case O_PAPER: o->paper = 1; break;
        case O_RIGID: o->p.rigid = arg_double(optarg, "--rigid"); break;
        case O_UNTANGLE: o->p.untangle = arg_int(optarg, "--untangle"); break;
        case O_UNFLIP: o->p.unflip = arg_int(optarg, "--unflip"); break;
        case O_REFINE: o->refine = arg_int(optarg, "--refine"); break;
        case O_SETTLE: o->settle = arg_int(optarg, "--settle"); o->settle_given = 1; break;
        case O_FITREL:
            if (!strcmp(optarg, "stay")) o->fit_release = 0;
            else if (!strcmp(optarg, "mean")) o->fit_release = 1;
            else if (!strcmp(optarg, "both")) o->fit_release = 2;
            else usage_error("--fit-release must be stay, mean or both");
            break;
        case O_RIGIDN: o->p.rigid_iters = arg_int(optarg, "--rigid-iters"); break;
        case O_COARSE: o->p.coarse = arg_double(optarg, "--coarse"); break;
        case O_RIGIDC: o->p.rigid_const = 1; break;
        case O_PASSES:
            o->passes_given = 1;
            o->passes = strcmp(optarg, "auto") ? arg_int(optarg, "--passes") : 0;
            if (strcmp(optarg, "auto") && (o->passes < 1 || o->passes > 3))
                usage_error("--passes must be 1, 2, 3 or auto");
            break;
        case O_FINESTEPS: o->p.fine_steps = arg_int(optarg, "--fine-steps"); break;
        case O_OVERLAY: o->p.overlay = arg_double(optarg, "--overlay"); break;
        case O_SMALL: o->p.small_parts = arg_double(optarg, "--small-parts"); break;
        case O_PARTS:
            if (!strcmp(optarg, "auto")) o->p.parts = -1;
            else if (!strcmp(optarg, "yes")) o->p.parts = 1;
            else if (!strcmp(optarg, "no")) o->p.parts = 0;
            else usage_error("--parts must be auto, yes or no");
            break;
        case O_REST: o->rest = optarg; break;
        case O_CREST:
            o->chain_rest_given = 1;
            if (!strcmp(optarg, "previous")) o->chain_prev = 1;
            else if (!strcmp(optarg, "both")) o->chain_prev = 2;
            else if (!strcmp(optarg, "first")) o->chain_prev = 0;
            else usage_error("--chain-rest must be first, previous or both");
            break;
        case O_LMOUT: o->lm_out = optarg; break;
        case O_NOINIT: o->no_init = 1; break;
        case O_LMESH: o->lm_mesh = optarg; break;
        case O_FITS: o->p.fit_smooth = arg_int(optarg, "--fit-smooth"); break;
        case O_FITSR: o->fit_smooth_retry = arg_int(optarg, "--fit-smooth-retry"); break;
        case O_SEARCH: o->p.search = arg_double(optarg, "--search"); break;
        case O_INITM:
            if (!strcmp(optarg, "shell")) o->init_shell = 1;
            else if (strcmp(optarg, "arap")) usage_error("--init-model must be arap or shell");
            o->init_deform = 1;
            break;
        case O_NV: o->p.nearest_vertex = 1; break;
        case O_INITK: o->init_stiffness = optarg; o->init_deform = 1; break;
        case O_FIT: o->p.fit = arg_int(optarg, "--fit"); break;
        case O_FITW: o->p.fit_weight = arg_double(optarg, "--fit-weight"); break;
        case O_EPS: o->p.eps = arg_double(optarg, "--eps"); break;
        case O_SOUT: o->steps_out = optarg; break;
        case 'o': o->output = optarg; break;
        case O_RAW: o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (o->chain ? argc - optind < 2 : argc - optind != 2)
        usage_error(o->chain ? "expected SOURCE and at least one TARGET" : "expected SOURCE and TARGET");
    o->src = argv[optind];
    o->dst = argv[optind + 1];
    o->targets = (const char **)argv + optind + 1;
    o->ntargets = argc - optind - 1;
    if (o->chain_rest_given && !o->chain) usage_error("--chain-rest needs --chain");
    if (!o->chain_rest_given) o->chain_prev = 2;   /* both: the score decides per key */
    if (o->chain && o->rest) usage_error("--chain keeps SOURCE as the rest shape: no --rest");
    if (o->chain && (o->landmarks || o->lm_out || o->steps_out))
        usage_error("--chain takes no -l, --landmarks-out or --steps-out (one key per run does)");
    if (strcmp(o->align, "rigid") && strcmp(o->align, "similarity") && strcmp(o->align, "none"))
        usage_error("--align must be rigid, similarity or none");
    if (o->p.steps < 1 || o->p.steps > 1000) usage_error("--steps must be in 1..1000");
    if (!(o->p.alpha_max > 0) || !(o->p.alpha_min > 0)) usage_error("stiffness must be positive");
    if (o->p.beta < 0 || o->p.backward < 0 || o->p.gamma < 0) usage_error("weights must be >= 0");
    if (!(o->p.max_angle > 0) || o->p.max_angle > 180) usage_error("--max-angle must be in (0, 180]");
    if (o->p.max_inner < 1) usage_error("--max-inner must be >= 1");
    if (o->lm_mesh && !o->landmarks) usage_error("--landmark-mesh needs --landmarks");
    if (o->no_auto && o->landmarks) usage_error("--no-auto and --landmarks exclude each other");
    if (o->no_init && o->init_deform) usage_error("--no-init-deform and --init-deform/--init-model exclude each other");
    if (o->lm_out && o->no_auto) usage_error("--landmarks-out with --no-auto: there are none");
    if (o->start_given && (o->landmarks || o->no_auto || o->no_init || o->init_deform))
        usage_error("--start chooses the start without -l: not with -l, --no-auto, --init-deform, "
                    "--no-init-deform, --init-model or --init-stiffness");
    if (o->paper) {
        /* the thesis' method (Algorithm 3 with Amberg's NRICP): the thin
         * shell toward the landmarks, closest points without the backward
         * term or the search, iterated per stiffness, no ARAP fit */
        if (o->start_given && o->start != START_SHELL && o->start != START_NONE)
            usage_error("--paper starts with the thin shell (--start shell or none)");
        o->p.fit = 0;
        o->p.rigid = 0;
        o->p.untangle = 0;
        o->p.unflip = 0;
        o->refine = 0;
        o->p.backward = 0;
        o->p.search = 0;
        o->p.max_inner = 10;
        if (!o->landmarks && !o->no_auto && !o->no_init && !o->start_given) o->start = START_SHELL;
        if (o->landmarks && !o->no_init) o->init_deform = o->init_shell = 1;
    }
    if (o->no_auto) o->start = START_NONE;
    /* one fixed start: given landmarks, or a start option given */
    if (o->landmarks || o->no_init || o->init_deform) o->start = START_LANDMARKS;
    if (!o->landmarks && !o->no_auto && !o->no_init && o->start != START_NONE) o->init_deform = 1;
    if (o->p.fit < 0 || o->p.fit > 1000) usage_error("--fit must be in 0..1000");
    if (!(o->p.rigid >= 0 && o->p.rigid <= 1e6)) usage_error("--rigid must be in [0, 1e6]");
    if (o->p.untangle < 0 || o->p.untangle > 20) usage_error("--untangle must be in 0..20");
    if (o->p.unflip < 0 || o->p.unflip > 20) usage_error("--unflip must be in 0..20");
    if (o->refine < 0 || o->refine > 1000) usage_error("--refine must be in 0..1000");
    if (o->settle < 0 || o->settle > 100) usage_error("--settle must be in 0..100");
    if (o->p.rigid_iters < 1 || o->p.rigid_iters > 100) usage_error("--rigid-iters must be in 1..100");
    if (!(o->p.coarse >= 0 && o->p.coarse <= 0.5)) usage_error("--coarse must be in [0, 0.5]");
    if (o->p.fine_steps < 0 || o->p.fine_steps > 1000) usage_error("--fine-steps must be in 0..1000");
    if (o->p.fit_smooth < 0 || o->p.fit_smooth > 100) usage_error("--fit-smooth must be in 0..100");
    if (o->passes < 0 || o->passes > 3) usage_error("--passes must be 1, 2, 3 or auto");
    /* --paper is the thesis' method: one pass, unless asked otherwise */
    if (!o->passes_given && o->paper) o->passes = 1;
    /* --settle: 2 with --chain (build-up, nricp(1)); one pair and --paper: off */
    if (!o->settle_given) o->settle = o->chain && !o->paper ? 2 : 0;
    if (o->fit_smooth_retry < 0 || o->fit_smooth_retry > 100)
        usage_error("--fit-smooth-retry must be in 0..100");
    if (!(o->p.search >= 0 && o->p.search <= 1)) usage_error("--search must be in [0, 1]");
    if (!(o->p.overlay >= 0 && o->p.overlay <= 1)) usage_error("--overlay must be in [0, 1]");
    if (!(o->p.small_parts >= 0 && o->p.small_parts <= 1)) usage_error("--small-parts must be in [0, 1]");
    if (!(o->p.fit_weight > 0) || o->p.fit_weight > 1e6)
        usage_error("--fit-weight must be in (0, 1e6]");
    if (!(o->p.eps >= 0)) usage_error("--eps must be >= 0");
}

struct steps { double *frames; int n, cap, nv, nsteps, nfit; struct progress pr; double t0;
               double coarse; int fine_steps; };

static int on_step(void *ctx, int step, double alpha, double beta, int inner, int rejected,
                   int folded, const double *X)
{
    struct steps *s = ctx;
    if (folded == -3) {
        info(1, "coarse level: %d vertices, %d faces (--coarse %g); the last %d steps on the "
             "source's %d vertices", inner, rejected, s->coarse, s->fine_steps, s->nv);
        return 0;
    }
    if (folded == -5) {
        info(1, "small parts: %d groups of them moved rigidly (--small-parts), %.2f s", inner,
             now_seconds() - s->t0);
        return 0;
    }
    if (folded == -4) {
        info(1, "unflipped: %d -> %d faces flipped against the target, %.2f s", inner, rejected,
             now_seconds() - s->t0);
        return 0;
    }
    if (folded == -2) {
        info(1, "untangled: %d -> %d faces flipped against the target, %.2f s", inner, rejected,
             now_seconds() - s->t0);
        return 0;
    }
    if (folded >= 0) {
        if (verbose > 1 || step - s->nsteps + 1 == s->nfit)
            info(1, "ARAP fit iteration %d: data weight %.3g, %d rejected, %d folded faces, %.2f s",
                 step - s->nsteps + 1, alpha, rejected, folded, now_seconds() - s->t0);
        return 0;
    }
    if (s->frames) {
        memcpy(s->frames + (size_t)s->n * s->nv * 3, X, (size_t)s->nv * 3 * sizeof *X);
        s->n++;
    }
    info(1, "step %d: alpha %.4g beta %.4g, %d iterations, %d rejected, %.2f s", step + 1, alpha,
         beta, inner, rejected, now_seconds() - s->t0);
    progress_step(&s->pr, step + 1);
    return 0;
}

/* one pose, and a surface the closest points and geodesics make sense on */
static void check_surface(const struct mesh *M, const char *name, int is_target)
{
    if (M->nf < 1) die("cannot register: %s has no faces", name);
    {
        int k = is_target;
        if (M->nframes != 1)
            die("cannot register %s'%s': it has %d frames, nricp takes one pose; pick one with "
                "anim-slice -f K", k ? "to " : "", name, M->nframes);
        struct topology tp;
        if (topology_build(M->F, M->nf, M->nv, &tp) < 0) die("%s", cm_errmsg());
        /* a few non-manifold edges (a raw scan's triangle stored twice) do
         * no harm to closest points: say so; a mesh made of them is no
         * surface to register to: refuse */
        int bad = -1, nbf = 0;
        for (int e = 0; e < tp.ne; e++)
            if (tp.EFn[e] > 2) {
                if (bad < 0) bad = e;
                nbf += tp.EFn[e];
            }
        if (bad >= 0) {
            int a = tp.E[2 * bad], b = tp.E[2 * bad + 1], n = tp.EFn[bad];
            if (10 * nbf >= M->nf) {
                topology_free(&tp);
                die("cannot register %s'%s': %d of its %d faces meet at non-manifold edges "
                    "(edge %d-%d has %d faces); mesh-clean it first", k ? "to " : "", name, nbf,
                    M->nf, a, b, n);
            }
            warn("'%s': %d non-manifold edges (edge %d-%d has %d faces); mesh-clean would remove them",
                 name, tp.nnonmanifold, a, b, n);
        }
        topology_free(&tp);
    }
}

/* landmark-auto: matched geodesic extremities and limb points, between the
 * pose V of the source and the target T */
static int auto_landmarks(const double *V, const struct mesh *S, const struct mesh *T,
                          struct landmarks *L, int may_fail)
{
    {
        /* landmark-auto: matched geodesic extremities and limb points */
        struct landmark_auto_params lp;
        struct landmark_pairs lpairs;
        landmark_auto_defaults(&lp);
        double ta = now_seconds();
        if (landmark_auto(V, S->F, S->nv, S->nf, T->V, T->F, T->nv, T->nf, &lp, &lpairs) < 0) {
            if (may_fail) {
                warn("no automatic landmarks: %s; registering without", cm_errmsg());
                return -1;
            }
            die("no landmarks given and none found: %s (give -l, or --no-auto)", cm_errmsg());
        }
        L->n = lpairs.n;
        L->src = malloc((size_t)L->n * sizeof *L->src);
        L->dst = malloc((size_t)L->n * sizeof *L->dst);
        L->P = malloc((size_t)L->n * 3 * sizeof *L->P);
        if (!L->src || !L->dst || !L->P) die("out of memory");
        for (int l = 0; l < L->n; l++) {
            L->src[l] = lpairs.a[l];
            L->dst[l] = lpairs.b[l];
            memcpy(L->P + 3 * l, T->V + 3 * (size_t)lpairs.b[l], 3 * sizeof *L->P);
        }
        if (lpairs.verified < 0)
            warn("automatic landmarks: the near-best maps were not tested by deformation (%s): the "
                 "map of score and orientation alone is kept", lpairs.why);
        info(1, "automatic landmarks: %d extremities matched (of %d and %d), %d pairs, "
             "orientation %.2f, %d maps verified by deformation%s, %.2f s", lpairs.matched, lpairs.na,
             lpairs.nb, L->n, lpairs.orient, lpairs.verified > 0 ? lpairs.verified : 0,
             lpairs.changed ? " (another than score and orientation alone)" : "", now_seconds() - ta);
        landmark_pairs_free(&lpairs);
    }
    return 0;
}

/* with a SOURCE of parts (open boundaries or several components,
 * correspond_parts): the overlay ratio of the scores' distance and of the
 * refinement (0: a closed single surface, symmetric_distance as always) */
static double parts_overlay;
static int parts_on;      /* SOURCE has parts (--parts, or decided from it) */

/* how well X (SOURCE's connectivity) lies on T: the symmetric Hausdorff
 * distance over T's diagonal (with parts, the target's samples lying over
 * source that already fits left out: overlay_distance) and the flipped
 * faces (mesh-metrics' test) */
static void measure(const double *X, const struct mesh *S, const struct mesh *T, double *hrel,
                    int *flips)
{
    struct closest_point_tree *TS = closest_point_tree_new(X, S->nv, S->F, S->nf);
    struct closest_point_tree *TT = closest_point_tree_new(T->V, T->nv, T->F, T->nf);
    double h, rms, diag = bbox_diagonal(T->V, T->nv);
    if (!TS || !TT ||
        (parts_overlay > 0 ? overlay_distance(X, S->nv, S->F, S->nf, TS, T->V, T->nv, T->F, T->nf, TT,
                                              parts_overlay, OVERLAY_TAU, &h, NULL)
                           : symmetric_distance(X, S->nv, S->F, S->nf, TS, T->V, T->nv, T->F, T->nf, TT,
                                                &h, &rms)) < 0)
        die("cannot measure the registration: %s", cm_errmsg());
    *hrel = h / diag;
    *flips = flipped_faces(X, S->F, S->nf, T->V, T->nv, T->F, T->nf, TT, FLIP_THIN_TOL * diag);
    closest_point_tree_free(TS);
    closest_point_tree_free(TT);
}

/* the start of one key: SOURCE's pose START (#V by 3) aligned on the
 * landmarks L, then the clay start toward them (o.init_deform); returns it
 * (#V by 3, malloc'd) */
static double *key_start(const struct options *op, const struct mesh *S, const double *start,
                         const struct landmarks *Lp)
{
    const struct options o = *op;
    const struct landmarks L = *Lp;
    double t0 = now_seconds();
    /* Procrustes on the landmarks (Algorithm 2, first line) */
    double *VS = malloc((size_t)S->nv * 3 * sizeof *VS + 1);
    memcpy(VS, start, (size_t)S->nv * 3 * sizeof *VS);
    if (strcmp(o.align, "none") && L.n >= 3) {
        double *A = malloc((size_t)L.n * 3 * sizeof *A), R[9], t[3], s;
        for (int l = 0; l < L.n; l++) memcpy(A + 3 * l, start + 3 * (size_t)L.src[l], 3 * sizeof *A);
        double res = procrustes(A, L.P, NULL, L.n, !strcmp(o.align, "similarity"), R, t, &s);
        if (res < 0) die("%s", cm_errmsg());
        similarity_apply(R, t, s, VS, S->nv, VS);
        info(1, "%s alignment on %d landmarks: scale %.6g, RMS residual %.6g", o.align, L.n, s, res);
        free(A);
    }
    if (o.init_deform) {
        /* Algorithm 3, first loop: clay deformation toward the landmarks */
        if (L.n < 1) die("--init-deform and --init-model need landmarks (-l)");
        double *k = NULL;
        if (o.init_stiffness) {
            struct columns col;
            if (columns_read(o.init_stiffness, 1, S->nv, "vertices", &col) < 0) die("%s", cm_errmsg());
            for (int v = 0; v < S->nv; v++)
                if (!(col.x[v] > 0))
                    die("cannot read '%s': row %d: stiffness must be positive", o.init_stiffness, v + 1);
            k = col.x;
        }
        struct topology t;
        if (topology_build(S->F, S->nf, S->nv, &t) < 0) die("%s", cm_errmsg());
        int closed = t.nboundary == 0 && t.nnonmanifold == 0;
        topology_free(&t);
        /* arap: clay_deform.h, one factorization; shell: thin_shell.h (the
         * thesis' Froehlich-Botsch shell, clay-deform's default; slower) */
        struct clay_deform *cd = NULL;
        struct thin_shell *sh = NULL;
        if (o.init_shell) {
            struct thin_shell_params sp;
            thin_shell_defaults(&sp);
            if (!closed) sp.kv = sp.kvg = 0;
            sh = thin_shell_new(VS, S->F, S->nv, S->nf, k, L.src, L.n, &sp);
        } else
            cd = clay_deform_new(VS, S->F, S->nv, S->nf, k, L.src, L.n, 100);
        if (!cd && !sh) die("--init-deform: %s", cm_errmsg());
        double *X0 = malloc((size_t)S->nv * 3 * sizeof *X0), *TL = malloc((size_t)L.n * 3 * sizeof *TL);
        memcpy(X0, VS, (size_t)S->nv * 3 * sizeof *X0);
        const int nsteps = 10;
        for (int s = 1; s <= nsteps; s++) {
            double a = (double)s / nsteps;
            for (int l = 0; l < L.n; l++)
                for (int d = 0; d < 3; d++)
                    TL[3 * l + d] = (1 - a) * VS[3 * (size_t)L.src[l] + d] + a * L.P[3 * l + d];
            if ((sh ? thin_shell_solve(sh, TL, 5, X0, NULL) : clay_deform_solve(cd, TL, 5, closed, X0)) < 0)
                die("--init-deform: %s", cm_errmsg());
        }
        memcpy(VS, X0, (size_t)S->nv * 3 * sizeof *VS);
        info(1, "clay deformation (%s) toward %d landmarks%s: %.2f s", sh ? "thin shell" : "arap",
             L.n, closed ? " (volume kept)" : "", now_seconds() - t0);
        clay_deform_free(cd);
        thin_shell_free(sh);
        free(X0); free(TL); free(k);
    }
    return VS;
}

/* one key from its start VS (key_start): NRICP with the ARAP fit relative
 * to REST (NULL: VS) toward T and the landmarks L; X (out, #V by 3) */
static void key_register(const struct options *o, const struct mesh *S, const double *VS,
                         const double *rest, const struct mesh *T, const struct landmarks *L,
                         struct steps *st, double *X)
{
    st->t0 = now_seconds();
    if (st->frames) {
        memcpy(st->frames, VS, (size_t)S->nv * 3 * sizeof *VS);
        st->n = 1;
    }
    progress_start(&st->pr, progname, o->p.steps);
    if (nricp_register(VS, rest, S->F, S->nv, S->nf, T->V, T->F, T->nv, T->nf, L->src, L->P, L->n,
                       &o->p, X, on_step, st) < 0)
        die("%s", cm_errmsg());
    progress_end(&st->pr);
}

/* the kept key X (#V by 3, in and out) refined last (sample_fit.h): every
 * sample mesh-metrics measures pulled onto T and T's pulling X, the largest
 * distances first; kept only where the Hausdorff distance drops and no face
 * newly flips */
static void key_refine(const struct options *o, const struct mesh *S, const struct mesh *T,
                       const char *name, double *X)
{
    double t0 = now_seconds(), diag = bbox_diagonal(T->V, T->nv), st[4];
    struct sample_fit_params sp;
    sample_fit_defaults(&sp);
    sp.iters = o->refine;
    sp.tol = FLIP_THIN_TOL * diag;
    sp.overlay = parts_overlay;
    struct closest_point_tree *TT = closest_point_tree_new(T->V, T->nv, T->F, T->nf);
    if (!TT || sample_fit(X, S->F, S->nv, S->nf, T->V, T->F, T->nv, T->nf, TT, &sp, st) < 0)
        die("cannot refine the registration: %s", cm_errmsg());
    closest_point_tree_free(TT);
    /* the small parts rigid again (nricp_small_parts) */
    if (parts_on && o->p.small_parts > 0 &&
        nricp_small_parts(S->V, S->F, S->nv, S->nf, o->p.small_parts, X) < 0)
        die("cannot refine the registration: %s", cm_errmsg());
    info(1, "%s%srefined: Hausdorff %.3f%% -> %.3f%% of the diagonal, %d -> %d flipped faces, "
         "edge stretch %.3f, %.2f s", name ? name : "", name ? ": " : "", 100 * st[0] / diag,
         100 * st[1] / diag, (int)st[2], (int)st[3], nricp_stretch(S->V, X, S->F, S->nf),
         now_seconds() - t0);
}

/* the faces of X (#V by 3) where its Hausdorff distance to T lies: the
 * faces whose samples are farthest from T, or where T's samples are
 * farther from X, the face of X closest to T's farthest vertex; seed (#F,
 * out).  FC: T's frame_compare, TT its tree, ff: #F scratch. */
static void farthest_faces(const double *X, const struct mesh *S, const struct mesh *T,
                           struct frame_compare *FC, double tol, double *ff, unsigned char *seed)
{
    struct frame_distance fd;
    if (frame_compare_run(FC, X, S->nv, S->F, S->nf, tol, &fd, NULL, ff) < 0)
        die("cannot measure the registration: %s", cm_errmsg());
    memset(seed, 0, (size_t)S->nf);
    if (fd.fit.max >= fd.cover.max) {
        double mx = 0;
        for (int f = 0; f < S->nf; f++) if (ff[f] > mx) mx = ff[f];
        for (int f = 0; f < S->nf; f++) seed[f] = ff[f] >= mx;
        return;
    }
    struct closest_point_tree *TS = closest_point_tree_new(X, S->nv, S->F, S->nf);
    double *C = malloc((size_t)T->nv * 3 * sizeof *C), *D = malloc((size_t)T->nv * sizeof *D);
    int *I = malloc((size_t)T->nv * sizeof *I);
    if (!TS || !C || !D || !I) die("out of memory");
    closest_points(TS, T->V, T->nv, C, I, NULL, D);
    int jm = 0;
    for (int j = 1; j < T->nv; j++) if (D[j] > D[jm]) jm = j;
    seed[I[jm]] = 1;
    closest_point_tree_free(TS);
    free(C); free(D); free(I);
}

/* The kept key X (#V by 3, in and out) repaired last, after the
 * refinement, by patch_unflip.h's foldover-free solve (rest shape SOURCE):
 *   - unflip: the patches of the faces still flipped, round after round
 *     with one ring more each, until no face is flipped or a round keeps no
 *     patch; a patch's samples may end up to START_ACCEPT diagonals from
 *     the target (the distance a key ends well within) where the key was
 *     closer, since laying a pleat flat can bridge the crease it folded
 *     into;
 *   - refit: the patch around the faces where the Hausdorff distance lies,
 *     kept where it is closer there with no face newly flipped, again from
 *     the new farthest place until a round keeps nothing (at most
 *     REPAIR_ROUNDS);
 * then refined again where a patch was unflipped (after a refit alone the
 * refinement, already run, changed nothing on the camel).  The unflip inside the registration runs before the
 * refinement, whose moves can leave a pleat another solve lays flat; the
 * refinement's foldover guard holds an edge standing across a crease,
 * which the solve lays down (camel 01 -> 03 with SkylakeX's kernel: 1.002%
 * -> 0.764% of the diagonal, no face flipped).  Kept only with fewer
 * flipped faces and a Hausdorff distance no larger than before or within
 * START_ACCEPT, or as many flipped faces and a lower distance (-v says). */
#define REPAIR_ROUNDS 20
static void key_repair(const struct options *o, const struct mesh *S, const struct mesh *T,
                       const char *name, double *X)
{
    double h0, h1, t0 = now_seconds(), diag = bbox_diagonal(T->V, T->nv);
    int f0, f1, nunflip = 0, nrefit = 0;
    measure(X, S, T, &h0, &f0);
    size_t n3 = (size_t)S->nv * 3;
    double *Xu = malloc(n3 * sizeof *Xu), *ff = malloc((size_t)S->nf * sizeof *ff);
    unsigned char *seed = malloc((size_t)S->nf);
    if (!Xu || !ff || !seed) die("out of memory");
    memcpy(Xu, X, n3 * sizeof *Xu);
    struct closest_point_tree *TT = closest_point_tree_new(T->V, T->nv, T->F, T->nf);
    struct frame_compare *FC = frame_compare_new(T->V, T->nv, T->F, T->nf);
    if (!TT || !FC) die("cannot repair the registration: %s", cm_errmsg());
    struct patch_unflip_params up;
    patch_unflip_defaults(&up);
    up.tol = FLIP_THIN_TOL * diag;
    int st[4];
    for (int rings = o->p.unflip; f0 > 0 && rings <= 20; rings++) {
        up.rings = rings;
        up.allow = START_ACCEPT * diag;
        if (patch_unflip(Xu, S->V, S->F, S->nv, S->nf, T->V, T->F, T->nv, T->nf, TT, &up, st) < 0)
            die("cannot unflip the registration: %s", cm_errmsg());
        nunflip += st[3];
        if (st[1] == 0 || st[3] == 0) break;     /* none left, or stuck */
    }
    up.rings = o->p.unflip;
    up.allow = 0;
    for (int r = 0; r < REPAIR_ROUNDS; r++) {
        farthest_faces(Xu, S, T, FC, up.tol, ff, seed);
        if (patch_refit(Xu, S->V, S->F, S->nv, S->nf, T->V, T->F, T->nv, T->nf, TT, &up, seed, st) < 0)
            die("cannot refit the registration: %s", cm_errmsg());
        nrefit += st[3];
        if (st[3] == 0) break;
    }
    frame_compare_free(FC);
    closest_point_tree_free(TT);
    if (nunflip + nrefit == 0) {
        info(1, "%s%srepaired last: no patch kept, %.2f s", name ? name : "", name ? ": " : "",
             now_seconds() - t0);
        free(Xu); free(ff); free(seed);
        return;
    }
    if (o->refine > 0 && nunflip > 0) key_refine(o, S, T, name, Xu);
    measure(Xu, S, T, &h1, &f1);
    int keep = (f1 < f0 && (h1 <= h0 || h1 <= START_ACCEPT)) || (f1 <= f0 && h1 < h0);
    info(1, "%s%srepaired last (%d patches unflipped, %d refitted): %d -> %d flipped faces, "
         "Hausdorff %.3f%% -> %.3f%% of the diagonal, %.2f s: %s", name ? name : "",
         name ? ": " : "", nunflip, nrefit, f0, f1, 100 * h0, 100 * h1, now_seconds() - t0,
         keep ? "kept" : "not kept");
    if (keep) memcpy(X, Xu, n3 * sizeof *X);
    free(Xu); free(ff); free(seed);
}

/* A near-identical pose: the key X (#V by 3, in and out) against its
 * start X0 (SOURCE, or with --chain the previous key) on T, by the score
 * of the starts (distance + START_FLIP_COST per flipped face +
 * START_STRETCH_COST times the edge stretch from SOURCE): where the start
 * already lies on the target at least as well, the registration made
 * nothing better and the start is kept (-v says so). */
static void key_or_start(const struct mesh *S, const struct mesh *T, const char *name,
                         const double *X0, double *X)
{
    double h0, h;
    int f0, fl;
    measure(X0, S, T, &h0, &f0);
    measure(X, S, T, &h, &fl);
    double s0 = h0 + START_FLIP_COST * f0 + START_STRETCH_COST * nricp_stretch(S->V, X0, S->F, S->nf);
    double s1 = h + START_FLIP_COST * fl + START_STRETCH_COST * nricp_stretch(S->V, X, S->F, S->nf);
    int keep = s0 <= s1;
    info(1, "%s%sthe start scores %.4g (Hausdorff %.3f%%, %d flipped faces), the registration "
         "%.4g (%.3f%%, %d): %s", name ? name : "", name ? ": " : "", s0, 100 * h0, f0, s1, 100 * h,
         fl, keep ? "the start kept (already as close)" : "registration kept");
    if (keep) {
        /* not silent: the output is the start, not a registration */
        warn("%s%sthe registration scored no better than its start (%.3f%% of the diagonal, %d "
             "flipped faces, against %.3f%%, %d): the start is written unchanged",
             name ? name : "", name ? ": " : "", 100 * h, fl, 100 * h0, f0);
        memcpy(X, X0, (size_t)S->nv * 3 * sizeof *X);
    }
}

/* --settle: the kept key X (#V by 3, in and out; with --chain every key,
 * after the whole chain) registered once more from itself, and again from
 * that result, up to o->settle times: no landmarks, the fit's rest shape
 * the pass's start (so what the chain handed on is not pulled back toward
 * SOURCE), released vertices kept in
 * place (and pulled to their neighbours' mean too where that leaves more
 * than START_FLIPS flipped faces, the lower score kept), then refined as
 * every key.  A pass's result replaces X only where its score is lower
 * (Hausdorff distance + START_FLIP_COST per flipped face, as --passes)
 * with no more flipped faces than X or at most START_FLIPS; the passes
 * stop early when one does not lower the score of its start.  A
 * chain key starts one step away and ends where that start's
 * correspondences let it; started on the target, the schedule and the
 * refinement reach about what they reach for a neighbouring pair
 * (nricp(1), --settle).  st: its counters (its frames are not touched). */
static void key_settle(const struct options *o, const struct mesh *S, const struct mesh *T,
                       const char *name, const struct steps *st, double *X)
{
    double h0, h, hc, hs;
    int f0, fl, fc, fs;
    measure(X, S, T, &h0, &f0);
    /* a key with more than START_FLIPS flipped faces did not register (a
     * sheet folded on the target): a pass from it lowers the distance by
     * sliding that sheet along the target, not by fitting it (facecap
     * chain: closer, but farther from the true places; nricp(1)) */
    if (f0 > START_FLIPS) {
        info(1, "%s%snot settled: %d flipped faces", name ? name : "", name ? ": " : "", f0);
        return;
    }
    hs = h0;
    fs = f0;
    size_t n3 = (size_t)S->nv * 3;
    double *Xs = malloc(n3 * sizeof *Xs), *Xc = malloc(n3 * sizeof *Xc), *Xb = malloc(n3 * sizeof *Xb);
    if (!Xs || !Xc || !Xb) die("out of memory");
    memcpy(Xs, X, n3 * sizeof *Xs);
    struct landmarks none = {0};
    struct steps sst = *st;
    sst.frames = NULL;         /* --steps-out keeps the kept registration's steps */
    int nrel = o->fit_release == 2 && o->p.fit > 0 ? 2 : 1;
    for (int it = 0; it < o->settle; it++) {
        double t0 = now_seconds(), best = INFINITY;
        struct options oc = *o;
        for (int v = 0; v < nrel; v++) {
            oc.p.fit_release = nrel == 2 ? v : o->fit_release;
            key_register(&oc, S, Xs, NULL, T, &none, &sst, Xc);
            measure(Xc, S, T, &hc, &fc);
            double sc = hc + START_FLIP_COST * fc;
            if (sc < best) {
                best = sc;
                memcpy(Xb, Xc, n3 * sizeof *Xb);
            }
            if (fc <= START_FLIPS) break;
        }
        if (o->refine > 0) key_refine(o, S, T, name, Xb);
        if (o->p.unflip > 0) key_repair(o, S, T, name, Xb);
        measure(Xb, S, T, &h, &fl);
        /* the score of --passes; more flipped faces than X only up to
         * START_FLIPS (a chain key's goal) */
        int keep = h + START_FLIP_COST * fl < h0 + START_FLIP_COST * f0 &&
                   (fl <= f0 || fl <= START_FLIPS);
        info(1, "%s%ssettled (pass %d): Hausdorff %.3f%% -> %.3f%% of the diagonal, %d -> %d "
             "flipped faces, %.2f s%s", name ? name : "", name ? ": " : "", it + 1, 100 * hs, 100 * h, fs, fl, now_seconds() - t0,
             keep ? ": kept" : "");
        if (keep) {
            memcpy(X, Xb, n3 * sizeof *X);
            h0 = h;
            f0 = fl;
        }
        if (!(h + START_FLIP_COST * fl < hs + START_FLIP_COST * fs)) break;
        memcpy(Xs, Xb, n3 * sizeof *Xs);
        hs = h;
        fs = fl;
    }
    free(Xs);
    free(Xc);
    free(Xb);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    blas_single_thread();          /* small supernodes: threads only spin */
    struct options o;
    parse_args(argc, argv, &o);
    struct mesh S, R = {0};
    if (mesh_read(o.src, &S) < 0) die("%s", cm_errmsg());
    check_surface(&S, o.src, 0);
    {
        int parts = o.p.parts;
        if (parts < 0) {
            struct topology tp;
            if (topology_build(S.F, S.nf, S.nv, &tp) < 0) die("%s", cm_errmsg());
            parts = correspond_parts(&tp, S.F);
            topology_free(&tp);
            if (parts < 0) die("%s: %s", o.src, cm_errmsg());
        }
        parts_overlay = parts ? o.p.overlay : 0;
        parts_on = parts;
        o.p.parts = parts;    /* every registration the same */
        if (parts && o.p.overlay > 0)
            info(1, "%s has parts (open boundaries or several components): target surface lying "
                 "over source that already fits is not pulled on nor measured (--overlay %g)",
                 o.src, o.p.overlay);
    }
    if (o.rest) {
        if (mesh_read(o.rest, &R) < 0) die("%s", cm_errmsg());
        if (R.nv != S.nv || R.nf != S.nf || memcmp(R.F, S.F, (size_t)S.nf * 3 * sizeof *S.F))
            die("cannot use '%s' as the rest shape: its connectivity is not that of '%s'", o.rest, o.src);
        if (R.nframes != 1)
            die("cannot use '%s' as the rest shape: it has %d frames; pick one with anim-slice -f K",
                o.rest, R.nframes);
    }
    /* every target is read and checked before any work */
    struct mesh *T = calloc((size_t)o.ntargets, sizeof *T);
    for (int k = 0; k < o.ntargets; k++) {
        if (mesh_read(o.targets[k], &T[k]) < 0) die("%s", cm_errmsg());
        check_surface(&T[k], o.targets[k], 1);
    }
    struct landmarks L = {0};
    struct mesh LM = {0};
    if (o.lm_mesh && mesh_read(o.lm_mesh, &LM) < 0) die("%s", cm_errmsg());
    if (o.landmarks && landmarks_read(o.landmarks, S.nv, o.lm_mesh ? LM.V : T[0].V,
                                      o.lm_mesh ? LM.nv : T[0].nv, &L) < 0)
        die("%s", cm_errmsg());
    if (o.lm_mesh) mesh_free(&LM);
    struct steps st = {0};
    st.nv = S.nv;
    st.nsteps = o.p.steps;
    st.nfit = o.p.fit;
    st.coarse = o.p.coarse;
    st.fine_steps = o.p.fine_steps >= o.p.steps ? o.p.steps - 1 : o.p.fine_steps;
    if (o.steps_out) st.frames = malloc((size_t)(o.p.steps + 1) * S.nv * 3 * sizeof *st.frames);
    /* the keys: frame 0 the source, frame k the registration to target k;
     * key k starts from key k - 1, the fit keeps the source's shape */
    double *K = malloc((size_t)(o.ntargets + 1) * S.nv * 3 * sizeof *K);
    memcpy(K, S.V, (size_t)S.nv * 3 * sizeof *K);
    /* --start auto: up to three starts per key, the best kept (with its
     * landmarks and steps) */
    double *Xc = malloc((size_t)S.nv * 3 * sizeof *Xc);
    double *Fc = o.steps_out ? malloc((size_t)(o.p.steps + 1) * S.nv * 3 * sizeof *Fc) : NULL;
    struct landmarks Lbest = {0};
    static const char *const start_name[] = {"auto", "landmarks", "shell", "none"};
    /* --passes 2: the key registered once more from the first pass's result
     * (Xp), as if it were SOURCE; X2 that pass's result, L0 the first
     * pass's automatic landmarks while the second runs */
    const int npass = o.passes ? o.passes : 3;     /* 0: auto; the third only as below */
    double *Xp = npass > 1 ? malloc((size_t)S.nv * 3 * sizeof *Xp) : NULL;
    /* the second pass's starts by kind (START_*), for the third: the same
     * start from the same result and landmarks, so not made twice */
    double *VS2 = npass > 2 ? malloc((size_t)4 * S.nv * 3 * sizeof *VS2) : NULL;
    int vs2_ok[4];
    double *X2 = npass > 1 ? malloc((size_t)S.nv * 3 * sizeof *X2) : NULL;
    /* --steps-out: the first pass's steps while the second runs */
    double *Fp = npass > 1 && o.steps_out ? malloc((size_t)(o.p.steps + 1) * S.nv * 3 * sizeof *Fp) : NULL;
    if (npass > 1 && (!Xp || !X2 || (o.steps_out && !Fp))) die("out of memory");
    int np = 0;
    for (int k = 0; k < o.ntargets; k++) {
      double score0 = 0;
      int bestc0 = START_NONE;
      memset(vs2_ok, 0, sizeof vs2_ok);
      int passk = 0, bfl0 = 0;      /* the pass kept, its flipped faces and distance */
      double bh0 = 0;
      struct landmarks L0 = {0};
      for (int pass = 0; pass < npass; pass++) {
        const double *start = pass ? Xp : K + (size_t)k * S.nv * 3;
        /* the shape the edge stretch of the score is measured from: the
         * key's start (as a run with it as SOURCE): SOURCE, a chain key's
         * previous key, or in the second pass the first pass's result.
         * Measured from SOURCE, a chain key's stretch grows with the chain
         * and the score took a farther candidate whose fit's rest was
         * SOURCE (camel chain's key 04: 1.556% with edge stretch 0.175
         * over 1.125% with 0.233 once every start ended with no flipped
         * face; the last key 0.941% against 0.297% measured so) */
        const double *SV = start;
        /* the rest shape of the fit: SOURCE (first) or the start, i.e. the
         * previous key (previous), or each start with both, the better kept;
         * in the second pass the start */
        const double *rest_first = pass == 2 ? (o.rest && !(o.chain && k > 0) ? R.V : S.V)
                                   : pass ? NULL : o.chain && k > 0 ? S.V : o.rest ? R.V : NULL;
        int nrest = !pass && o.chain && k > 0 && o.chain_prev == 2 ? 2 : 1;
        if (!pass && o.chain && k > 0 && o.chain_prev == 1) rest_first = NULL;
        double *X = pass ? X2 : K + (size_t)(k + 1) * S.nv * 3;
        int have_lm = o.landmarks != NULL;
        if (!o.landmarks && o.start != START_NONE) {
            landmarks_free(&L);
            have_lm = auto_landmarks(start, &S, &T[k], &L, o.start == START_AUTO) == 0;
        }
        int cand[3], nc = 0;
        if (o.start == START_AUTO) {
            if (have_lm) cand[nc++] = START_LANDMARKS;
            cand[nc++] = START_NONE;
            if (have_lm) cand[nc++] = START_SHELL;     /* only if neither ends well */
        } else
            cand[nc++] = o.start;
        /* the ARAP fit's released vertices: kept in place, pulled to their
         * neighbours' mean, or both tried (--fit-release both: the mean
         * only where keeping the place ends with more than START_FLIPS
         * flipped faces, within twice the best Hausdorff distance so far) */
        int nrel = o.fit_release == 2 && o.p.fit > 0 ? 2 : 1;
        double best = INFINITY;
        int bestc = -1, bestn = 0, bfl = 0, bestr = 0, bestv = 0, bests = 0;
        double *VSbest = malloc((size_t)S.nv * 3 * sizeof *VSbest);
        double bh = 0;
        for (int c = 0; c < nc; c++) {
            struct options oc = o;
            struct landmarks none = {0};
            const struct landmarks *Lc = cand[c] == START_NONE ? &none : &L;
            if (cand[c] == START_SHELL) oc.init_deform = oc.init_shell = 1;
            if (cand[c] == START_NONE) oc.init_deform = 0;
            double t0 = now_seconds();
            double *VS;
            if (pass == 2 && vs2_ok[cand[c]]) {
                VS = malloc((size_t)S.nv * 3 * sizeof *VS);
                if (!VS) die("out of memory");
                memcpy(VS, VS2 + (size_t)cand[c] * S.nv * 3, (size_t)S.nv * 3 * sizeof *VS);
            } else {
                VS = key_start(&oc, &S, start, Lc);
                if (pass == 1 && VS2) {
                    memcpy(VS2 + (size_t)cand[c] * S.nv * 3, VS, (size_t)S.nv * 3 * sizeof *VS);
                    vs2_ok[cand[c]] = 1;
                }
            }
            for (int rv = 0; rv < nrest * nrel; rv++) {
                int r = rv / nrel, v = rv % nrel;
                const double *rest = r ? NULL : rest_first;
                oc.p.fit_release = nrel == 2 ? v : o.fit_release;
                if (rv > 0) t0 = now_seconds();
                key_register(&oc, &S, VS, rest, &T[k], Lc, &st, Xc);
                double dt = now_seconds() - t0;
                double h = 0, str = 0;
                int fl = 0;
                if (verbose || nc * nrest * nrel > 1) {
                    measure(Xc, &S, &T[k], &h, &fl);
                    str = nricp_stretch(SV, Xc, S.F, S.nf);
                    info(1, "%s%sregistered in %.2f s: Hausdorff %.4g (%.3f%% of the diagonal), "
                         "%d flipped faces, edge stretch %.3f (start %s%s%s)",
                         o.chain ? o.targets[k] : "", o.chain ? ": " : "", dt,
                         h * bbox_diagonal(T[k].V, T[k].nv), 100 * h, fl, str, start_name[cand[c]],
                         nrest == 2 ? rest ? ", rest first" : ", rest previous" : "",
                         nrel == 2 ? v ? ", fit release mean" : ", fit release stay" : "");
                }
                double score = h + START_FLIP_COST * fl + START_STRETCH_COST * str;
                if (score < best) {
                    best = score;
                    bestc = cand[c];
                    bestr = r;
                    bestv = v;
                    memcpy(VSbest, VS, (size_t)S.nv * 3 * sizeof *VS);
                    memcpy(X, Xc, (size_t)S.nv * 3 * sizeof *X);
                    if (Fc) memcpy(Fc, st.frames, (size_t)st.n * S.nv * 3 * sizeof *Fc);
                    bestn = st.n;
                    bh = h;
                    bfl = fl;
                }
                /* the neighbours' mean only where keeping the place left folds,
                 * and not at a start already twice as far as the best one */
                if (nrel == 2 && v == 0 && (fl <= START_FLIPS || h > 2 * bh)) rv++;
            }
            free(VS);
            if (cand[c] == START_NONE && bh <= START_ACCEPT && bfl <= START_FLIPS) break;
        }
        /* the kept key fitted once more with a smoother rest shape, where it
         * ended far or folded: the fit's rest keeps SOURCE's remeshing
         * detail (knife-edge rims of an ear) that the target may not share */
        if (o.fit_smooth_retry > o.p.fit_smooth && o.p.fit > 0 && nc * nrest * nrel > 1 &&
            (bh > START_ACCEPT || bfl > START_FLIPS)) {
            struct options oc = o;
            struct landmarks none = {0};
            oc.p.fit_smooth = o.fit_smooth_retry;
            oc.p.fit_release = nrel == 2 ? bestv : o.fit_release;
            const double *rest = bestr ? NULL : rest_first;
            double t0 = now_seconds(), h, str;
            int fl;
            key_register(&oc, &S, VSbest, rest, &T[k], bestc == START_NONE ? &none : &L, &st, Xc);
            measure(Xc, &S, &T[k], &h, &fl);
            str = nricp_stretch(SV, Xc, S.F, S.nf);
            info(1, "%s%sregistered in %.2f s: Hausdorff %.4g (%.3f%% of the diagonal), %d flipped "
                 "faces, edge stretch %.3f (start %s, the rest smoothed %d times)",
                 o.chain ? o.targets[k] : "", o.chain ? ": " : "", now_seconds() - t0,
                 h * bbox_diagonal(T[k].V, T[k].nv), 100 * h, fl, str, start_name[bestc],
                 o.fit_smooth_retry);
            double score = h + START_FLIP_COST * fl + START_STRETCH_COST * str;
            if (score < best) {
                best = score;
                bests = 1;
                memcpy(X, Xc, (size_t)S.nv * 3 * sizeof *X);
                if (Fc) memcpy(Fc, st.frames, (size_t)st.n * S.nv * 3 * sizeof *Fc);
                bestn = st.n;
                bh = h;
                bfl = fl;
            }
        }
        free(VSbest);
        if (nc * nrest * nrel > 1)
            info(1, "%s%skept start %s%s%s%s", o.chain ? o.targets[k] : "", o.chain ? ": " : "",
                 start_name[bestc], nrest == 2 ? bestr ? ", rest previous" : ", rest first" : "",
                 nrel == 2 ? bestv ? ", fit release mean" : ", fit release stay" : "",
                 bests ? ", the rest smoothed more" : "");
        if (Fc) {
            memcpy(st.frames, Fc, (size_t)bestn * S.nv * 3 * sizeof *Fc);
            st.n = bestn;
        }
        if (npass > 1) {
            /* the passes compared by distance and flipped faces alone: the
             * second pass's result is farther from SOURCE's shape by design
             * (its rest is the first result); each pass's own choice of
             * start weighs the stretch from its start */
            if (!(verbose || nc * nrest * nrel > 1)) measure(X, &S, &T[k], &bh, &bfl);
            double sc = bh + START_FLIP_COST * bfl;
            if (pass == 0) {
                /* auto: again only where the key ended far or folded */
                if (o.passes >= 2 || bh > START_ACCEPT || bfl > START_FLIPS) {
                    score0 = sc;
                    bh0 = bh;
                    bfl0 = bfl;
                    bestc0 = bestc;
                    memcpy(Xp, X, (size_t)S.nv * 3 * sizeof *Xp);
                    if (Fp) {
                        memcpy(Fp, st.frames, (size_t)st.n * S.nv * 3 * sizeof *Fp);
                        np = st.n;
                    }
                    if (!o.landmarks) {
                        L0 = L;
                        L = (struct landmarks){0};
                    }
                    continue;
                }
                pass = npass - 1;     /* the last pass: this one */
            } else {
                static const char *const pass_name[] = {"first", "second", "third"};
                int second = sc < score0;
                /* a third pass, from the first pass's result again but with
                 * SOURCE (or --rest) as the fit's rest shape, only where
                 * neither pass ended within START_ACCEPT with at most
                 * START_FLIPS flipped faces: a first result that stretched
                 * the skin somewhere is, as the second pass's rest shape,
                 * kept stretched there (camel 03 -> 01 by OpenBLAS kernel,
                 * nricp(1)) */
                int third = pass == 1 && npass == 3 &&
                            (o.passes == 3 || !((second ? bh : bh0) <= START_ACCEPT &&
                                                (second ? bfl : bfl0) <= START_FLIPS));
                info(1, "%s%s%s the %s pass (score %.4g against %.4g)%s", o.chain ? o.targets[k] : "",
                     o.chain ? ": " : "", third ? "so far" : "kept", pass_name[second ? pass : passk],
                     second ? sc : score0, second ? score0 : sc,
                     third ? ": once more from the first's result, the rest shape SOURCE" : "");
                if (second) {
                    passk = pass;
                    memcpy(K + (size_t)(k + 1) * S.nv * 3, X, (size_t)S.nv * 3 * sizeof *X);
                    if (third) {
                        score0 = sc;
                        bh0 = bh;
                        bfl0 = bfl;
                        bestc0 = bestc;
                        if (Fp) {
                            memcpy(Fp, st.frames, (size_t)st.n * S.nv * 3 * sizeof *Fp);
                            np = st.n;
                        }
                        if (!o.landmarks) {
                            landmarks_free(&L0);
                            L0 = L;
                            L = (struct landmarks){0};
                        }
                    }
                }
                if (third) continue;
                if (!second) {
                    bestc = bestc0;
                    if (Fp) {
                        memcpy(st.frames, Fp, (size_t)np * S.nv * 3 * sizeof *Fp);
                        st.n = np;
                    }
                    if (!o.landmarks) {
                        landmarks_free(&L);
                        L = L0;
                        L0 = (struct landmarks){0};
                    }
                }
                landmarks_free(&L0);
                pass = npass - 1;     /* no third pass */
            }
        }
        if (k == o.ntargets - 1 && pass == npass - 1 && bestc != START_NONE) {
            Lbest = L;
            L = (struct landmarks){0};
        }
      }
      if (o.refine > 0)
          key_refine(&o, &S, &T[k], o.chain ? o.targets[k] : NULL, K + (size_t)(k + 1) * S.nv * 3);
      if (o.p.unflip > 0)
          key_repair(&o, &S, &T[k], o.chain ? o.targets[k] : NULL, K + (size_t)(k + 1) * S.nv * 3);
      key_or_start(&S, &T[k], o.chain ? o.targets[k] : NULL, K + (size_t)k * S.nv * 3,
                   K + (size_t)(k + 1) * S.nv * 3);
    }
    /* --settle: after the whole chain (every key started as before), each
     * key registered again from its own result, kept where closer */
    for (int k = 0; k < o.ntargets && o.settle > 0; k++)
        key_settle(&o, &S, &T[k], o.chain ? o.targets[k] : NULL, &st, K + (size_t)(k + 1) * S.nv * 3);
    free(Xp);
    free(VS2);
    free(X2);
    free(Fp);
    free(Xc);
    free(Fc);
    landmarks_free(&L);
    L = Lbest;
    double *X = K + (size_t)o.ntargets * S.nv * 3;
    if (o.steps_out) {
        FILE *f = out_open(o.steps_out);
        struct mesh_writer w;
        if (mesh_writer_open(&w, f, S.nv, S.nf, S.F, st.n, want_raw(o.raw)) < 0)
            die("cannot write '%s': %s", o.steps_out, cm_errmsg());
        for (int k = 0; k < st.n; k++)
            if (mesh_writer_frame(&w, st.frames + (size_t)k * S.nv * 3, 0) < 0)
                die("cannot write '%s': %s", o.steps_out, cm_errmsg());
        if (mesh_writer_close(&w) < 0) die("cannot write '%s': %s", o.steps_out, cm_errmsg());
        out_close(f);
    }
    FILE *lf = NULL;
    if (o.lm_out) {
        lf = out_open(o.lm_out);
        fprintf(lf, "# nricp %s -> %s: landmarks used (%s)\n", o.src, o.dst,
                o.landmarks ? o.landmarks : "automatic");
        for (int l = 0; l < L.n; l++)
            if (L.dst[l] >= 0) fprintf(lf, "%d %d\n", L.src[l], L.dst[l]);
            else fprintf(lf, "%d %.17g %.17g %.17g\n", L.src[l], L.P[3 * l], L.P[3 * l + 1], L.P[3 * l + 2]);
    }
    FILE *out = out_open(o.output);
    struct mesh W = S;
    W.V = o.chain ? K : X;
    W.nframes = o.chain ? o.ntargets + 1 : 1;
    W.cut = NULL;   /* one clip; S.cut has S's one frame only (ASan: read past it with --chain) */
    if (mesh_write(out, &W, want_raw(o.raw)) < 0) die("cannot write output: %s", cm_errmsg());
    if (lf) out_close(lf);
    out_close(out);
    free(st.frames);
    free(K);
    landmarks_free(&L);
    mesh_free(&S);
    mesh_free(&R);
    for (int k = 0; k < o.ntargets; k++) mesh_free(&T[k]);
    free(T);
    return 0;
}
