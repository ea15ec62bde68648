/* dict-learn -- a replacement library of d printable pieces and per-frame
 * labels for one part's animation (StopShop Sec. 3.3, Eq. 10-16).
 *
 * Block coordinate descent with restarts (libcommon/replib.h): library step
 * = a d x d SPD solve, label step = exact chain DP (or alpha-expansion).
 * Output: the library as a MESH stream whose frames are the pieces.
 * Size selection: --max-error (Fig. 16) and --sweep (Fig. 8).
 */
#include "replib.h"
#include "replib_sketch.h"
#include "swapcost.h"
#include "blas_tune.h"
#include "mesh.h"
#include "mesh_prefetch.h"
#include "columns.h"
#include "tool.h"
#include "progress.h"
#include "cm_error.h"
#include <getopt.h>
#include <malloc.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/mman.h>
#include <unistd.h>

#define DEFAULT_SAMPLE 16384    /* --sample */
#define STR_(x) #x
#define STR(x) STR_(x)

static const char help[] =
"Usage: dict-learn [options] [FILE]\n"
"Learn a replacement library of D pieces and per-frame labels for one part's\n"
"animation (a MESH stream); write the library (frames = pieces) on stdout.\n"
"Minimizes |X - R S|_W^2 + lambda/2 |X G - R S G|_W^2 (StopShop Eq. 10).\n"
"\n"
"Options:\n"
"  -d, --pieces D         library size (default 20; D <= frames)\n"
"  -l, --lambda X         velocity weight lambda (default 2)\n"
"  -r, --restarts N       random restarts, best kept (default 5)\n"
"  -i, --iterations N     max iterations per restart (default 50)\n"
"      --seed N           random seed (default 1): same seed, same bytes\n"
"  -w, --weights FILE     per-vertex saliency weights (one number per vertex)\n"
"      --fixed LIB        pieces that must stay (a MESH library from an earlier\n"
"                         film); they become pieces 0..k-1 of the output\n"
"  -m, --method M         label step: dp (exact, default) | expansion | swap\n"
"      --start S          first pieces of a restart: greedy (default: greedy\n"
"                         k-means++, 2 + ln D candidates per piece) | kmeans++\n"
"      --search N         local search per restart: single-frame moves (lambda\n"
"                         0) and N split/merge trials (default: 10 + D/5);\n"
"                         0 = plain block coordinate descent (the paper's)\n"
"      --init-labels FILE start restart 0 from these labels (one per frame)\n"
"      --labels-out FILE  write the per-frame labels (0-based piece ids)\n"
"  -c, --swap-cost C      fewer swaps on set: once the library is learned, the\n"
"                         labels are chosen again by exact chain DP with every\n"
"                         change of piece inside a clip costing C (data-term\n"
"                         units); the report counts the swaps (default 0)\n"
"      --swap-sweep LIST  learn once, relabel for each swap cost of LIST\n"
"                         (\"0,1,10\") and print \"swap_cost swaps energy data\n"
"                         velocity mean_err max_err\" instead of the library\n"
"      --report FILE      write the energy report (key value lines)\n"
"      --max-error E      choose the smallest D whose worst per-vertex error\n"
"                         is <= E model units (Fig. 16); -d is then ignored\n"
"      --sweep D1:D2[:S]  print \"d energy mean_err max_err\" for D = D1..D2\n"
"                         step S (Fig. 8) instead of writing a library\n"
"      --gram auto|on|full|single|off  cost back end: Gram matrix (default\n"
"                         when frames <= 12000; exact low-rank shortcut when the\n"
"                         animation allows), full DSYRK only, single precision\n"
"                         (faster; reports stay exact), or one GEMM per iteration\n"
"      --stream auto|on|off  read the frames once into a low-rank sketch\n"
"                         (auto: when they exceed 512 MB as doubles); the\n"
"                         frames are kept in 32 bits within --memory (exact\n"
"                         integers of the input's decimal step, else floats)\n"
"      --rank K           sketch size (default 128)\n"
"      --memory MB        budget for the 32-bit frames (default 4096);\n"
"                         beyond it pieces come from the sketch (approximate)\n"
"      --resident MB      a raw stream mapped from a file of at most MB\n"
"                         (default 1024) stays mapped whole between its reads;\n"
"                         a larger one is released frame by frame (less\n"
"                         memory, more CPU; the same output)\n"
"      --sample N         past N frames (default " STR(DEFAULT_SAMPLE) "), restarts and search\n"
"                         run on a sample of N frames (blocks of 64), then one\n"
"                         descent on all frames; 0 = search all frames\n"
"      --threads N        restarts run on N threads (default 0: one per core);\n"
"                         the result does not depend on N\n"
"  -o, --output FILE      write the library to FILE instead of stdout\n"
"      --raw              write the raw (binary) MESH variant\n"
"  -v, --verbose          energy, restarts, iterations, time per iteration on\n"
"                         stderr; -vv: every iteration of every restart\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: dict-learn -d 20 --lambda 2 --labels-out lower.lab lower.mesh >lower.lib\n";

struct options {
    const char *input, *weights, *fixed, *init_labels, *labels_out, *report, *output, *sweep;
    double swap_cost, *swap_sweep;
    int nswap;
    int d, restarts, iterations, raw, gram, threads, search, stream, rank, sample;
    double memory, resident;
    enum replib_start start;
    double lambda, max_error;
    long seed;
    enum replib_method method;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"pieces", 1, 0, 'd'}, {"lambda", 1, 0, 'l'}, {"restarts", 1, 0, 'r'},
        {"iterations", 1, 0, 'i'}, {"seed", 1, 0, 'S'}, {"weights", 1, 0, 'w'},
        {"fixed", 1, 0, 'F'}, {"method", 1, 0, 'm'}, {"init-labels", 1, 0, 'I'},
        {"labels-out", 1, 0, 'L'}, {"swap-cost", 1, 0, 'c'}, {"swap-sweep", 1, 0, 'Z'}, {"report", 1, 0, 'P'}, {"max-error", 1, 0, 'E'},
        {"sweep", 1, 0, 'W'}, {"gram", 1, 0, 'G'}, {"threads", 1, 0, 'T'}, {"start", 1, 0, 's'}, {"stream", 1, 0, 'y'}, {"rank", 1, 0, 'k'}, {"memory", 1, 0, 'M'}, {"resident", 1, 0, 'N'}, {"search", 1, 0, 'X'}, {"sample", 1, 0, 'A'}, {"output", 1, 0, 'o'},
        {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->d = 20; o->lambda = 2; o->restarts = 5; o->iterations = 50; o->seed = 1;
    o->gram = -1; o->max_error = -1; o->search = -1; o->stream = -1; o->rank = 128; o->memory = 4096; o->resident = 1024;
    o->sample = DEFAULT_SAMPLE;
    int c;
    while ((c = getopt_long(argc, argv, "d:l:r:i:w:m:c:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'd': o->d = arg_int(optarg, "--pieces"); break;
        case 'l': o->lambda = arg_double(optarg, "--lambda"); break;
        case 'r': o->restarts = arg_int(optarg, "--restarts"); break;
        case 'i': o->iterations = arg_int(optarg, "--iterations"); break;
        case 'S': o->seed = arg_long(optarg, "--seed"); break;
        case 'w': o->weights = optarg; break;
        case 'F': o->fixed = optarg; break;
        case 'm':
            if (!strcmp(optarg, "dp")) o->method = REPLIB_DP;
            else if (!strcmp(optarg, "expansion")) o->method = REPLIB_EXPANSION;
            else if (!strcmp(optarg, "swap")) o->method = REPLIB_SWAP;
            else usage_error("--method: '%s' is not dp, expansion or swap", optarg);
            break;
        case 'I': o->init_labels = optarg; break;
        case 'L': o->labels_out = optarg; break;
        case 'c': o->swap_cost = arg_nonneg(optarg, "--swap-cost"); break;
        case 'Z':
            o->nswap = arg_nonneg_list(optarg, "--swap-sweep", &o->swap_sweep);
            break;
        case 'P': o->report = optarg; break;
        case 'E': o->max_error = arg_double(optarg, "--max-error");
            if (!(o->max_error >= 0)) usage_error("--max-error must be >= 0");
            break;
        case 'W': o->sweep = optarg; break;
        case 'G':
            if (!strcmp(optarg, "auto")) o->gram = -1;
            else if (!strcmp(optarg, "on")) o->gram = 1;
            else if (!strcmp(optarg, "off")) o->gram = 0;
            else if (!strcmp(optarg, "single")) o->gram = 2;
            else if (!strcmp(optarg, "full")) o->gram = 3;
            else usage_error("--gram: '%s' is not auto, on, full, single or off", optarg);
            break;
        case 'T': o->threads = arg_int(optarg, "--threads");
            if (o->threads < 0) usage_error("--threads must be >= 0");
            break;
        case 's':
            if (!strcmp(optarg, "greedy")) o->start = REPLIB_START_GREEDY;
            else if (!strcmp(optarg, "kmeans++")) o->start = REPLIB_START_PLUSPLUS;
            else usage_error("--start: '%s' is not greedy or kmeans++", optarg);
            break;
        case 'X': o->search = arg_int(optarg, "--search");
            if (o->search < 0) usage_error("--search must be >= 0");
            break;
        case 'A': o->sample = arg_int(optarg, "--sample");
            if (o->sample < 0) usage_error("--sample must be >= 0");
            break;
        case 'y':
            if (!strcmp(optarg, "auto")) o->stream = -1;
            else if (!strcmp(optarg, "on")) o->stream = 1;
            else if (!strcmp(optarg, "off")) o->stream = 0;
            else usage_error("--stream: '%s' is not auto, on or off", optarg);
            break;
        case 'k': o->rank = (int)arg_long(optarg, "--rank");
            if (o->rank < 1) usage_error("--rank must be >= 1");
            break;
        case 'M': o->memory = arg_double(optarg, "--memory");
            if (!(o->memory >= 0)) usage_error("--memory must be >= 0");
            break;
        case 'N': o->resident = arg_double(optarg, "--resident");
            if (!(o->resident >= 0)) usage_error("--resident must be >= 0");
            break;
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1) usage_error("expected at most one input FILE");
    o->input = optind < argc ? argv[optind] : NULL;
    if (!(o->lambda >= 0) || !isfinite(o->lambda)) usage_error("--lambda must be >= 0");
    if (o->restarts < 1) usage_error("--restarts must be at least 1");
    if (o->iterations < 1) usage_error("--iterations must be at least 1");
    if ((o->swap_cost > 0 || o->nswap) && (o->sweep || o->max_error >= 0))
        usage_error("--swap-cost and --swap-sweep relabel one library: not with --sweep or --max-error");
    if (o->nswap && o->swap_cost > 0) usage_error("--swap-sweep and --swap-cost exclude each other");
}

static void log_iter(void *ctx, const struct replib_iter *it)
{
    (void)ctx;
    info(2, "restart %d iteration %d: E %.10g (data %.6g, velocity %.6g) changed %d reseeded %d  %.3f s",
         it->restart, it->iteration, it->energy, it->data, it->velocity, it->changed,
         it->reseeded, it->seconds);
}

struct run {
    struct replib_result res;
    struct replib_report rep;
};

static void learn(const struct replib_data *D, const struct options *o, int d,
                  const int *init, const struct mesh *m, const double *w, struct run *run)
{
    struct replib_opts ro = {0};
    ro.d = d; ro.lambda = o->lambda; ro.restarts = o->restarts; ro.iterations = o->iterations;
    ro.seed = (uint64_t)o->seed; ro.method = o->method; ro.init_labels = init; ro.tol = 1e-10;
    ro.threads = o->threads;
    ro.start = o->start; ro.search = o->search >= 0 ? o->search : 10 + d / 5;
    ro.sample = o->sample;
    ro.log = log_iter;
    if (replib_learn(D, &ro, &run->res) < 0) die("%s", cm_errmsg());
    if (D->X)
        replib_evaluate(m->V, m->nframes, m->nv, run->res.R, d, run->res.labels, w, m->cut,
                        o->lambda, &run->rep, NULL);
    else if (D->Xi)
        replib_evaluate_i(D->Xi, D->xstep, D->xbase, D->ref, m->nframes, m->nv, run->res.R, d, run->res.labels, w, m->cut,
                          o->lambda, &run->rep, NULL);
    else if (D->Xm)
        replib_evaluate_m(D->Xm, D->Xm_keep, D->xstep, D->xbase, D->ref, m->nframes, m->nv, run->res.R, d, run->res.labels, w, m->cut,
                          o->lambda, &run->rep, NULL);
    else if (D->Xf)
        replib_evaluate_f(D->Xf, D->xbase, D->ref, m->nframes, m->nv, run->res.R, d, run->res.labels, w, m->cut,
                          o->lambda, &run->rep, NULL);
    else {
        /* sketch only: the model's energy in the sketch's coordinates */
        memset(&run->rep, 0, sizeof run->rep);
        run->rep.energy = run->res.energy; run->rep.data = run->res.data;
        run->rep.velocity = o->lambda > 0 ? run->res.velocity / (o->lambda / 2) : 0;
        run->rep.mean_err = run->rep.max_err = run->rep.mean_verr = run->rep.max_verr = NAN;
        run->rep.worst_frame = -1;
    }
    const struct replib_result *r = &run->res;
    if (r->sampled)
        info(1, "d %d: restarts and search on a sample of %d frames (%d blocks of %d; energy %.10g there), then one restart on all %d frames",
             d, r->sampled, r->sampled / REPLIB_SAMPLE_BLOCK, REPLIB_SAMPLE_BLOCK, r->sample_energy, r->n);
    info(1, "d %d: energy %.10g (data %.6g, velocity %.6g), mean error %.6g, max error %.6g",
         d, run->rep.energy, run->rep.data, run->rep.velocity, run->rep.mean_err, run->rep.max_err);
    info(1, "d %d: %d restarts, %d iterations, %d split/merge moves kept, %.4f s per iteration (labels %.4f s), best restart %d, %.3f s",
         d, r->restarts, r->iterations, r->accepted, r->iterations ? r->seconds / r->iterations : 0,
         r->iterations ? r->label_seconds / r->iterations : 0, r->best_restart, r->seconds);
    if (r->helped) info(1, "d %d: %d chunks of the last restarts' products run by idle threads", d, r->helped);
}

static void parse_sweep(const char *s, int *d1, int *d2, int *step)
{
    char junk;
    if (sscanf(s, "%d:%d:%d%c", d1, d2, step, &junk) != 3) {
        *step = 1;
        if (sscanf(s, "%d:%d%c", d1, d2, &junk) != 2)
            usage_error("--sweep: '%s' is not D1:D2 or D1:D2:STEP", s);
    }
    if (*d1 < 1 || *d2 < *d1 || *step < 1) usage_error("--sweep: need 1 <= D1 <= D2 and STEP >= 1");
}

/* -v: wall and CPU seconds of each stage since the previous call */
static void stage(const char *what)
{
    static double w0 = -1, c0;
    double w = now_seconds(), c = (double)clock() / CLOCKS_PER_SEC;
    if (w0 >= 0 && what) info(1, "time: %s %.3f s wall, %.3f s cpu", what, w - w0, c - c0);
    w0 = w; c0 = c;
}

/* Read the animation once, frame by frame: in memory (m->V, double) while
 * it is small, else (or with --stream on) into the one-pass sketch S, with
 * the frames buffered so far fed to it.  Weights are read once the vertex
 * count is known.  Returns 1 if the frames went to the sketch.  A raw
 * stream in a regular file that goes to the sketch from its first frame
 * is mapped (*map, *maplen: to munmap once the sketch is finished): its
 * frames are sketched and encoded where they lie, not copied
 * (replib_sketch_add_ref; the same results). */
/* one more frame read into m (its vertices stored or sketched elsewhere):
 * its cut flag (a clip starts there; never the first frame) */
static void add_frame_cut(struct mesh *m, int cut)
{
    int f = m->nframes;
    if (f % 1024 == 0) {
        unsigned char *c = realloc(m->cut, (size_t)f + 1024);
        if (!c) die("out of memory");
        m->cut = c;
    }
    m->cut[f] = f > 0 && cut;
    m->nframes++;
}

/* Streamed, the BLAS calls are a few large ones (the sketch's finish, the
 * pieces' solve) between phases whose threads are this program's own: on
 * one BLAS thread, set when the sketch starts, OpenBLAS's workers are
 * stopped before the read and never wake.  Woken, each spun in sched_yield
 * after a call, and the caller yielded while waiting for a descheduled
 * worker: 118k-148k sched_yield calls at the Monkey size on 2 shared cores
 * (the same bytes: the threads split no inner dimension). */
static int sketch_start(struct replib_sketch *S, int nv, const struct options *o, const struct columns *wc,
                        size_t keep)
{
    blas_single_thread();
    return replib_sketch_init(S, nv, o->rank, o->weights ? wc->x : NULL, keep, (uint64_t)o->seed);
}

static int read_anim(const struct options *o, struct mesh *m, struct columns *wc, struct replib_sketch *S,
                     const void **map, size_t *maplen)
{
    *map = NULL; *maplen = 0;
    struct mesh_reader r;
    if (mesh_reader_open(&r, o->input) < 0) die("%s", cm_errmsg());
    memset(m, 0, sizeof *m);
    m->nv = r.nv; m->nf = r.nf;
    m->F = malloc(sizeof(int) * 3 * (size_t)(r.nf ? r.nf : 1));
    if (!m->F) die("out of memory");
    memcpy(m->F, r.F, sizeof(int) * 3 * (size_t)r.nf);
    if (o->weights && columns_read(o->weights, 1, m->nv, "vertices", wc) < 0) die("%s", cm_errmsg());
    size_t fb = sizeof(double) * 3 * (size_t)m->nv;
    size_t lim = o->stream == 0 ? (size_t)-1 : o->stream == 1 ? 0 : (size_t)512 << 20;
    /* frames announced past the limit: to the sketch from the first frame
     * (buffering 512 MB first and feeding them to it gives the same bytes,
     * at the cost of a copy and a page fault per 4 KB) */
    if (r.nframes > 0 && (double)r.nframes * fb > (double)lim) lim = 0;
    int cap = 0, sk = 0, rc, cut;
    if (lim == 0 && mesh_reader_map(&r) == 1) {
        /* no copy: the frames are where they lie */
        size_t keep = (size_t)(o->memory * 1048576.0);
        if (r.nframes > 0 && (double)r.nframes * 12 * m->nv > o->memory * 1048576.0) keep = 0;
        if (sketch_start(S, m->nv, o, wc, keep) < 0)
            die("%s", cm_errmsg());
        S->expect = r.nframes > 0 ? r.nframes : 0;
        /* the file stays mapped until the pieces are built, and its frames
         * are read there again (as the integers of the input's step they
         * would be kept as: the same numbers) instead of copied into
         * 32-bit frames: no memory to zero and fill.  A file larger than
         * half the memory is kept as before (the page cache would not
         * hold it between the passes).  A file of at most --resident MB
         * stays mapped whole: the pieces and the report find its pages
         * in place.  A larger one's pages are released once read, each
         * pass, so the resident set stays a window of the file (releasing
         * and faulting 3 times 155k pages in again cost the Monkey-size
         * run about 0.7 s CPU of 4.5). */
        double phys = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
        const char *km = getenv("STOPMO_DICT_KEEP_MAPPED");
        S->decode = keep > 0 && r.nframes > 0 && (double)r.nframes * fb <= 0.5 * phys && !(km && strcmp(km, "0"));
        S->release = !((double)r.map_len <= o->resident * 1048576.0);
        info(1, "read: '%s' mapped: raw frames sketched where they lie in the file (%s)", r.name,
             S->release ? "pages released once read" : "kept mapped whole");
        /* a second thread finds the frames (headers, checks, page tables)
         * while this one sketches them */
        struct mesh_prefetch pf;
        if (mesh_prefetch_start_ref(&pf, &r, 8) < 0) die("%s", cm_errmsg());
        const mapped_double *x;
        while ((rc = mesh_prefetch_next_ref(&pf, &x, &cut)) == 1) {
            if (replib_sketch_add_ref(S, x, cut) < 0)
                die("cannot read '%s': %s", r.name, cm_errmsg());
            add_frame_cut(m, cut);
        }
        if (rc < 0) die("%s", cm_errmsg());
        mesh_prefetch_stop(&pf);
        if (m->nframes < 1) die("cannot read '%s': no frames", r.name);
        *map = mesh_reader_take_map(&r, maplen);
        mesh_reader_close(&r);
        return 1;
    }
    /* frames parsed on a second thread while this one sketches or stores */
    struct mesh_prefetch pf;
    if (mesh_prefetch_start(&pf, &r, 8) < 0) die("%s", cm_errmsg());
    const double *x;
    while ((rc = mesh_prefetch_next(&pf, &x, &cut)) == 1) {
        int f = m->nframes;
        if (!sk && (size_t)(f + 1) * fb > lim) {
            /* switch to the sketch: feed it what was buffered.  When the
             * header announces more frames than --memory keeps, none are
             * kept (they would be dropped at the budget anyway: the same
             * result, without filling and freeing the budget) */
            size_t keep = (size_t)(o->memory * 1048576.0);
            if (r.nframes > 0 && (double)r.nframes * 12 * m->nv > o->memory * 1048576.0) keep = 0;
            if (sketch_start(S, m->nv, o, wc, keep) < 0)
                die("%s", cm_errmsg());
            S->expect = r.nframes > 0 ? r.nframes : 0;
            for (int g = 0; g < f; g++)
                if (replib_sketch_add(S, m->V + (size_t)g * 3 * m->nv, m->cut[g]) < 0)
                    die("cannot read '%s': %s", r.name, cm_errmsg());
            free(m->V); m->V = NULL;
            sk = 1;
        }
        if (sk) {
            if (replib_sketch_add(S, x, cut) < 0) die("cannot read '%s': %s", r.name, cm_errmsg());
        } else if (f == cap) {
            cap = cap ? 2 * cap : 64;
            double *nvv = realloc(m->V, fb * cap);
            if (!nvv) die("out of memory (%d frames of %d vertices)", f, m->nv);
            m->V = nvv;
        }
        if (!sk) memcpy(m->V + (size_t)f * 3 * m->nv, x, fb);
        add_frame_cut(m, cut);
    }
    if (rc < 0) die("%s", cm_errmsg());
    mesh_prefetch_stop(&pf);
    if (m->nframes < 1) die("cannot read '%s': no frames", r.name);
    mesh_reader_close(&r);
    return sk;
}

int main(int argc, char **argv)
{
    /* OpenBLAS's worker threads, idle between the few threaded calls,
     * spin in sched_yield for 2^28 cycles before they sleep.
     * OPENBLAS_THREAD_TIMEOUT = 4 makes them sleep at once, but OpenBLAS
     * reads it only when it loads: it acts only through blas_tune's
     * re-execution (not when the caller chose OPENBLAS_CORETYPE, as the
     * tests and benchmarks do; a streamed run then keeps BLAS on one
     * thread, below).  A user's value is kept. */
    setenv("OPENBLAS_THREAD_TIMEOUT", "4", 0);
    blas_tune(argv);
    /* arrays below 32 MB freed (a label step's tables, a library step's
     * matrices, the incremental products) stay with malloc for the next
     * ones instead of going back to the kernel and faulting in again: a 4 KB
     * fault costs 10-12 us on this paravirtualized guest (big_alloc.h) */
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    int sd1 = 0, sd2 = 0, sstep = 1;
    if (o.sweep) parse_sweep(o.sweep, &sd1, &sd2, &sstep);
    if (!o.sweep && o.max_error < 0 && o.d < 1)
        die("-d %d: the library needs at least one piece", o.d);

    struct mesh m;
    struct columns wc = {0};
    struct replib_sketch S = {0};
    stage(NULL);
    const void *map;
    size_t maplen;
    int streamed = read_anim(&o, &m, &wc, &S, &map, &maplen);
    stage(streamed ? "read + sketch" : "read");
    struct mesh fx = {0};
    if (o.fixed) {
        if (streamed) die("--fixed needs the animation in memory (--stream off)");
        if (mesh_read(o.fixed, &fx) < 0) die("%s", cm_errmsg());
        if (fx.nv != m.nv) die("cannot read '%s': %d vertices per piece, the animation has %d", o.fixed, fx.nv, m.nv);
    }
    int nfix = o.fixed ? fx.nframes : 0;
    int *init = NULL, ninit = 0;
    if (o.init_labels && labels_read(o.init_labels, m.nframes, "frames", 0, o.d - 1, &init, &ninit) < 0)
        die("%s", cm_errmsg());
    if (!o.sweep && o.max_error < 0) {
        if (o.d < nfix) die("-d %d is less than the %d fixed pieces of '%s'", o.d, nfix, o.fixed);
        if (o.d - nfix > m.nframes)
            die("-d %d: only %d frames to learn %d pieces from", o.d, m.nframes, o.d - nfix);
    }
    if (o.sweep && sd2 - nfix > m.nframes) die("--sweep: D2 = %d but only %d frames", sd2, m.nframes);
    if (o.sweep && sd1 < nfix) die("--sweep: D1 = %d is less than the %d fixed pieces", sd1, nfix);

    struct replib_data D = {0};
    if (streamed) {
        if (replib_sketch_finish(&S, &D) < 0) die("cannot read '%s': %s", o.input ? o.input : "<stdin>", cm_errmsg());
        D.w = o.weights ? wc.x : NULL;
        if (map && !D.Xm) { munmap((void *)map, maplen); map = NULL; }     /* the frames are read */
        /* pieces from the sketch are approximate: said without -v (unless
         * --memory 0 asked for exactly that) */
        if (!D.Xi && !D.Xm && !D.Xf && o.memory > 0) {
            double need = (double)m.nframes * 12 * m.nv / 1048576.0;
            if (S.dropped == 2)
                warn("out of memory keeping the frames in 32 bits (%.0f MB): the pieces and the report come from the rank-%d sketch (approximate)",
                     (double)S.dropped_bytes / 1048576.0, D.zdim);
            else
                warn("the frames need %.0f MB in 32 bits, more than --memory %g: the pieces and the report come from the rank-%d sketch (approximate; raise --memory to keep them)",
                     need, o.memory, D.zdim);
        }
        info(1, "sketch: rank %d captures %.8f of |Z|^2; frames %s", D.zdim, S.captured,
             D.Xi ? "kept in 32-bit integers of the input's step" :
             D.Xm ? "read where they lie in the file, as integers of the input's step" :
             D.Xf ? "kept in single precision" : "not kept (pieces from the sketch)");
        if (D.Xi || D.Xm)
            info(1, "sketch: frames %s exactly as integers of the input's step %g (largest rounding %.3g model units)",
                 D.Xi ? "kept" : "read", D.xstep, S.float_err);
        else if (D.Xf) info(1, "sketch: single-precision frames: largest rounding %.3g model units%s", S.float_err,
                            S.xstep > 0 ? " (a frame left the input's decimal grid or its range)" : " (no decimal step)");
    } else {
        D.n = m.nframes; D.nv = m.nv; D.X = m.V; D.nfix = nfix; D.Rfix = nfix ? fx.V : NULL;
        D.w = o.weights ? wc.x : NULL; D.cut = m.cut;
        D.gram = o.gram == 3 ? 1 : o.gram; D.no_lowrank = o.gram == 3;
        if (replib_prepare(&D) < 0) die("cannot read '%s': %s", o.input ? o.input : "<stdin>", cm_errmsg());
        if (D.lowrank_resid > 0)
            info(1, "low-rank test: input step %g, residual RMS %.3g per coordinate: %s (rank %d)", D.step,
                 D.lowrank_resid, D.lowrank ? "accepted" : "rejected, full Gram matrix", D.lowrank);
    }
    stage(streamed ? "sketch finish" : "prepare");
    info(1, "%d frames, %d vertices, %d clips, %s back end%s (OpenBLAS %s), prepared in %.3f s", m.nframes, m.nv,
         mesh_nclips(&m), D.K ? "Gram" : "direct", streamed ? " (sketch)" : D.lowrank ? " (exact low rank)" : "", blas_corename(),
         D.prep_seconds);

    if (o.sweep) {
        FILE *out = out_open(o.output);
        fprintf(out, "# d energy mean_err max_err\n");
        struct progress pg;
        progress_start(&pg, "dict-learn", (sd2 - sd1) / sstep + 1);
        for (int d = sd1, k = 1; d <= sd2; d += sstep, k++) {
            struct run run;
            learn(&D, &o, d, NULL, &m, D.w, &run);
            fprintf(out, "%d %.10g %.10g %.10g\n", d, run.rep.energy, run.rep.mean_err, run.rep.max_err);
            fflush(out);
            replib_result_free(&run.res);
            progress_step(&pg, k);
        }
        progress_end(&pg);
        out_close(out);
        replib_data_free(&D);
        free(init); free(o.swap_sweep);
        columns_free(&wc); if (o.fixed) mesh_free(&fx); mesh_free(&m);
        return 0;
    }

    struct run best;
    int d = o.d;
    if (o.max_error >= 0 && streamed && !D.Xf && !D.Xi && !D.Xm)
        die("--max-error needs the frames: they exceed --memory %g MB (raise it)", o.memory);
    if (o.max_error >= 0) {
        /* doubling then bisection on d (max error is nearly monotone in d) */
        int lo = nfix > 0 ? nfix : 1, hi = -1;
        int dmax = m.nframes + nfix;
        struct run cur;
        int have = 0;
        for (d = lo;; d = d * 2 > dmax ? dmax : d * 2) {
            learn(&D, &o, d, NULL, &m, D.w, &cur);
            if (cur.rep.max_err <= o.max_error || d == dmax) {
                hi = d; best = cur; have = 1;
                break;
            }
            replib_result_free(&cur.res);
            lo = d + 1;
        }
        while (have && lo < hi) {
            int mid = lo + (hi - lo) / 2;
            learn(&D, &o, mid, NULL, &m, D.w, &cur);
            if (cur.rep.max_err <= o.max_error) {
                replib_result_free(&best.res);
                best = cur; hi = mid;
            } else {
                replib_result_free(&cur.res);
                lo = mid + 1;
            }
        }
        d = hi;
        if (best.rep.max_err > o.max_error)
            warn("max error %g > %g even with one piece per frame", best.rep.max_err, o.max_error);
        info(1, "--max-error %g: d = %d (max error %g)", o.max_error, d, best.rep.max_err);
    } else {
        learn(&D, &o, d, init, &m, D.w, &best);
    }
    stage("learn + evaluate");

    /* fewer swaps: the learned library relabelled with the swap term */
    int swaps = swap_count(best.res.labels, m.nframes, m.cut);
    if (o.swap_cost > 0 || o.nswap) {
        if (!m.V) die("--swap-cost needs the animation in memory (--stream off)");
        struct replib_data L = {0};
        L.n = m.nframes; L.nv = m.nv; L.X = m.V; L.nfix = d; L.Rfix = best.res.R;
        L.w = D.w; L.cut = m.cut; L.gram = 0;
        if (replib_prepare(&L) < 0) die("%s", cm_errmsg());
        struct swap_point *pt = calloc(o.nswap ? o.nswap : 1, sizeof *pt);
        if (!pt) die("out of memory");
        for (int k = 0; k < (o.nswap ? o.nswap : 1); k++) {
            double C = o.nswap ? o.swap_sweep[k] : o.swap_cost;
            if (swap_relabel(&L, o.lambda, o.method, C, best.res.labels, &pt[k]) < 0) die("%s", cm_errmsg());
            info(1, "swap cost %g: %d swaps inside %d clips (%d without), energy %.10g (%.10g without), max error %.6g",
                 C, pt[k].swaps, mesh_nclips(&m), swaps, pt[k].rep.energy, best.rep.energy, pt[k].rep.max_err);
        }
        replib_data_free(&L);
        if (o.nswap) {
            FILE *out = out_open(o.output);
            fprintf(out, "# swap_cost swaps energy data velocity mean_err max_err (%d frames, %d clips, %d pieces, lambda %g)\n",
                    m.nframes, mesh_nclips(&m), d, o.lambda);
            for (int k = 0; k < o.nswap; k++)
                fprintf(out, "%.10g %d %.10g %.10g %.10g %.10g %.10g\n", pt[k].cost, pt[k].swaps, pt[k].rep.energy,
                        pt[k].rep.data, pt[k].rep.velocity, pt[k].rep.mean_err, pt[k].rep.max_err);
            out_close(out);
            free(pt);
            replib_result_free(&best.res); replib_data_free(&D); free(init); free(o.swap_sweep);
            columns_free(&wc); if (o.fixed) mesh_free(&fx); mesh_free(&m);
            return 0;
        }
        best.rep = pt[0].rep;
        swaps = pt[0].swaps;
        free(pt);
    } else
        info(1, "%d swaps on set inside %d clips", swaps, mesh_nclips(&m));

    /* everything computed: write outputs */
    if (o.labels_out) {
        FILE *f = out_open(o.labels_out);
        if (labels_write(f, best.res.labels, m.nframes) < 0) die("cannot write '%s'", o.labels_out);
        out_close(f);
    }
    if (o.report) {
        FILE *f = out_open(o.report);
        const struct replib_report *p = &best.rep;
        const struct replib_result *r = &best.res;
        fprintf(f, "# dict-learn report (energy = data + lambda/2 * velocity, Eq. 10)\n");
        fprintf(f, "frames %d\nvertices %d\nclips %d\npieces %d\nfixed %d\nlambda %.10g\n",
                m.nframes, m.nv, mesh_nclips(&m), d, nfix, o.lambda);
        fprintf(f, "energy %.10g\ndata %.10g\nvelocity %.10g\n", p->energy, p->data, p->velocity);
        fprintf(f, "mean_error %.10g\nmax_error %.10g\nworst_frame %d\n", p->mean_err, p->max_err, p->worst_frame);
        fprintf(f, "mean_velocity_error %.10g\nmax_velocity_error %.10g\n", p->mean_verr, p->max_verr);
        fprintf(f, "swaps %d\nswap_cost %.10g\nenergy_with_swaps %.10g\n", swaps, o.swap_cost,
                p->energy + o.swap_cost * swaps);
        int used = 0;
        int *cnt = calloc(d, sizeof(int));
        for (int k = 0; k < m.nframes; k++) cnt[r->labels[k]]++;
        for (int a = 0; a < d; a++) used += cnt[a] > 0;
        free(cnt);
        fprintf(f, "pieces_used %d\nrestarts %d\niterations %d\nbest_restart %d\nseed %ld\n",
                used, r->restarts, r->iterations, r->best_restart, o.seed);
        out_close(f);
    }
    FILE *out = out_open(o.output);
    struct mesh lib = {m.nv, m.nf, d, m.F, best.res.R, NULL};
    if (streamed && !D.Xf && !D.Xi && !D.Xm) info(1, "pieces reconstructed from the rank-%d sketch", D.zdim);
    unsigned char *cut = calloc(d, 1);
    lib.cut = cut;
    if (mesh_write(out, &lib, want_raw(o.raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    stage("write");
    free(cut);
    replib_result_free(&best.res);
    replib_data_free(&D);
    replib_sketch_free(&S);
    if (map) munmap((void *)map, maplen);
    free(init);
    columns_free(&wc);
    if (o.fixed) mesh_free(&fx);
    mesh_free(&m);
    return 0;
}
