/* part-split -- cut a MESH animation into one stream per part.
 *
 * Per-triangle labels say which part each triangle belongs to; part p gets
 * the triangles labelled p and the vertices they use, renumbered compactly
 * in increasing input order (seam vertices appear in every part they
 * touch).  The map file of a part lists, for each part vertex, its input
 * vertex index, so part-join can put pieces back together.  Streaming: one
 * frame in memory.
 */
#include "cm_error.h"
#include "columns.h"
#include "mesh.h"
#include "progress.h"
#include "tool.h"
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: part-split [options] -l LABELS [file]\n"
"Cut a MESH animation into one MESH stream per part (per-triangle LABELS),\n"
"each with its own compact vertex numbering.\n"
"\n"
"Options:\n"
"  -l, --labels FILE     per-triangle part labels, one integer >= 0 per line\n"
"  -o, --output PATTERN  printf pattern with one %d for the part number\n"
"                        (default part_%d.mesh); with --part, also a plain\n"
"                        file name, or '-' for stdout\n"
"  -m, --map PATTERN     also write, per part, the input vertex index of each\n"
"                        part vertex (one per line), e.g. part_%d.map (with\n"
"                        --part, also a plain file name)\n"
"  -p, --part K          write only part K (to stdout unless -o is given)\n"
"      --raw             write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose         part sizes on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: part-split -l labels.txt -o 'part_%d.mesh' -m 'part_%d.map' homog.mesh\n";

struct options {
    const char *input, *labels, *output, *map;
    int part, raw;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"labels", 1, 0, 'l'}, {"output", 1, 0, 'o'}, {"map", 1, 0, 'm'},
        {"part", 1, 0, 'p'}, {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->part = -1;
    int c;
    while ((c = getopt_long(argc, argv, "l:o:m:p:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': o->labels = optarg; break;
        case 'o': o->output = optarg; break;
        case 'm': o->map = optarg; break;
        case 'p':
            o->part = arg_int(optarg, "--part");
            if (o->part < 0) usage_error("--part must be >= 0");
            break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    o->input = arg_labels_and_input(argc, argv, o->labels);
    if (o->part < 0 && !o->output)
        o->output = "part_%d.mesh";
    if (o->output && strcmp(o->output, "-"))
        pattern_check(o->output, "--output", o->part < 0);
    else if (o->output && o->part < 0)
        usage_error("--output -: only one part (--part K) can go to stdout");
    if (o->map)
        pattern_check(o->map, "--map", o->part < 0);
}

struct part {
    int id, nv, nf;
    int *vmap;       /* nv: input vertex of part vertex */
    int *F;          /* nf by 3, part numbering */
    double *X;       /* nv by 3, one frame */
    FILE *out, *mapf;
    struct mesh_writer w;
};

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    int nv = r.nv, nf = r.nf, *L, nl;
    if (labels_read(o.labels, nf, "faces", 0, -1, &L, &nl) < 0)
        die("%s", cm_errmsg());
    int np = 0;
    for (int f = 0; f < nf; f++)
        if (L[f] + 1 > np) np = L[f] + 1;
    if (o.part >= 0 && o.part >= np)
        die("--part %d: the labels only go up to %d", o.part, np - 1);

    /* the parts that have faces (and the one asked for) */
    int *fcount = calloc((size_t)np + 1, sizeof *fcount);
    for (int f = 0; f < nf; f++) fcount[L[f]]++;
    struct part *parts = calloc((size_t)np + 1, sizeof *parts);
    int nparts = 0;
    int *local = malloc(((size_t)nv + 1) * sizeof *local);
    for (int p = 0; p < np; p++) {
        if (o.part >= 0 && p != o.part) continue;
        if (fcount[p] == 0) {
            if (o.part >= 0) die("--part %d: no triangle has that label", p);
            warn("no triangle has label %d: no part %d written", p, p);
            continue;
        }
        struct part *q = &parts[nparts++];
        q->id = p;
        for (int v = 0; v < nv; v++) local[v] = 0;
        for (int f = 0; f < nf; f++)
            if (L[f] == p)
                for (int c = 0; c < 3; c++) local[r.F[3 * f + c]] = 1;
        for (int v = 0; v < nv; v++) q->nv += local[v];
        q->vmap = malloc(((size_t)q->nv + 1) * sizeof *q->vmap);
        for (int v = 0, k = 0; v < nv; v++)
            if (local[v]) { q->vmap[k] = v; local[v] = k++; }
        q->nf = fcount[p];
        q->F = malloc(((size_t)q->nf * 3 + 1) * sizeof *q->F);
        for (int f = 0, k = 0; f < nf; f++)
            if (L[f] == p) {
                for (int c = 0; c < 3; c++) q->F[3 * k + c] = local[r.F[3 * f + c]];
                k++;
            }
        q->X = malloc(((size_t)q->nv * 3 + 1) * sizeof *q->X);
        info(1, "part %d: %d vertices, %d faces", p, q->nv, q->nf);
    }

    /* open every output (temporary names until the end) and write maps */
    int raw = want_raw(o.raw);
    for (int i = 0; i < nparts; i++) {
        struct part *q = &parts[i];
        char *name = o.output && strcmp(o.output, "-") ? pattern_format(o.output, q->id) : NULL;
        q->out = out_open(name);
        if (mesh_writer_open(&q->w, q->out, q->nv, q->nf, q->F, r.nframes, raw) < 0)
            die("cannot write '%s': %s", name ? name : "<stdout>", cm_errmsg());
        free(name);
        if (o.map) {
            char *mname = pattern_format(o.map, q->id);
            q->mapf = out_open(mname);      /* renamed into place at the end */
            if (labels_write(q->mapf, q->vmap, q->nv) < 0)
                die("cannot write '%s': %s", mname, cm_errmsg());
            free(mname);
        }
    }

    /* stream the frames */
    double *X = malloc(((size_t)nv * 3 + 1) * sizeof *X);
    struct progress pr;
    progress_start(&pr, "part-split", r.nframes);
    int cut, rc, k = 0;
    while ((rc = mesh_reader_next(&r, X, &cut)) > 0) {
        for (int i = 0; i < nparts; i++) {
            struct part *q = &parts[i];
            for (int j = 0; j < q->nv; j++)
                memcpy(q->X + 3 * (size_t)j, X + 3 * (size_t)q->vmap[j], 3 * sizeof *X);
            if (mesh_writer_frame(&q->w, q->X, cut) < 0)
                die("cannot write output: %s", cm_errmsg());
        }
        progress_step(&pr, ++k);
    }
    progress_end(&pr);
    if (rc < 0)
        die("%s", cm_errmsg());
    for (int i = 0; i < nparts; i++) {
        if (mesh_writer_close(&parts[i].w) < 0)
            die("cannot write output: %s", cm_errmsg());
        out_close(parts[i].out);
        if (parts[i].mapf) out_close(parts[i].mapf);
    }
    info(1, "%d frames, %d part%s", k, nparts, nparts == 1 ? "" : "s");
    for (int i = 0; i < nparts; i++) {
        free(parts[i].vmap); free(parts[i].F); free(parts[i].X);
    }
    free(parts); free(fcount); free(local); free(X); free(L);
    mesh_reader_close(&r);
    return 0;
}
