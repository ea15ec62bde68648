/* lib-assemble -- play a replacement animation: for every frame, mount the
 * chosen piece of every part and write the assembled mesh.
 *
 * Each part is given as LIB:LABELS:MAP -- its library of pieces (a MESH
 * stream whose frames are the pieces, from dict-learn or lib-uniform), its
 * per-frame piece labels (label-expand, dict-learn --labels-out) and its map
 * from part vertices to the vertices of BASE (part-split --map).  BASE
 * supplies the full connectivity; vertices that no part covers keep BASE's
 * frame 0 position.  Seam vertices shared by several parts are averaged and
 * the largest disagreement (the seam gap) is reported with -v.
 */
#include "cm_error.h"
#include "columns.h"
#include "mesh.h"
#include "tool.h"
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: lib-assemble [options] BASE.mesh LIB:LABELS:MAP...\n"
"Assemble the stop-motion animation from per-part piece libraries and labels.\n"
"\n"
"  BASE.mesh          the segmented (seam-homog) animation: gives faces and #V\n"
"  LIB:LABELS:MAP     one per part: library MESH (frames = pieces), per-frame\n"
"                     piece labels (one integer per line), part->BASE vertex map\n"
"  Seam vertices get the average of their copies; vertices no part covers keep\n"
"  BASE's frame 0.  One input file at most may be '-' (standard input).\n"
"\n"
"Options:\n"
"      --raw          raw (binary) MESH output (or STOPMO_RAW=1)\n"
"  -o, --output FILE  write to FILE (temporary + rename) instead of stdout\n"
"  -v, --verbose      report the largest seam gap\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Example:\n"
"  lib-assemble homog.mesh lib_0.mesh:labels_0.txt:part_0.map \\\n"
"               lib_1.mesh:labels_1.txt:part_1.map > stopmo.mesh\n";

struct part {
    struct mesh lib;
    int *labels, nlabels;
    int *map, nmap;
};

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"raw", 0, 0, 'R'}, {"output", 1, 0, 'o'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    int raw = 0, c;
    const char *out = NULL;
    while ((c = getopt_long(argc, argv, "o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'R': raw = 1; break;
        case 'o': out = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind < 2)
        usage_error("expected BASE.mesh and at least one LIB:LABELS:MAP");
    const char *base_path = argv[optind];
    int np = argc - optind - 1;

    /* parse every LIB:LABELS:MAP before reading anything (usage errors first) */
    struct part *P = calloc(np, sizeof *P);
    char **lib_path = calloc(np, sizeof *lib_path), **lab_path = calloc(np, sizeof *lab_path),
         **map_path = calloc(np, sizeof *map_path);
    int nstdin = !strcmp(base_path, "-");
    for (int p = 0; p < np; p++) {
        char *spec = strdup(argv[optind + 1 + p]);
        char *lab = strchr(spec, ':'), *map = lab ? strchr(lab + 1, ':') : NULL;
        if (!lab || !map || lab == spec || map == lab + 1 || !map[1])
            usage_error("part %d: expected LIB:LABELS:MAP, got '%s'", p, argv[optind + 1 + p]);
        *lab++ = 0;
        *map++ = 0;
        lib_path[p] = spec;
        lab_path[p] = lab;
        map_path[p] = map;
        nstdin += !strcmp(spec, "-") + !strcmp(lab, "-") + !strcmp(map, "-");
    }
    if (nstdin > 1)
        usage_error("only one input can be standard input ('-')");

    struct mesh_reader base;
    if (mesh_reader_open(&base, base_path) < 0)
        die("%s", cm_errmsg());
    int nv = base.nv;
    double *X0 = malloc((size_t)nv * 3 * sizeof *X0);
    int rc = mesh_reader_next(&base, X0, NULL);
    if (rc < 0)
        die("%s", cm_errmsg());
    if (rc == 0)
        die("cannot read '%s': the stream has no frames", base.name);

    int nframes = -1, *owner = malloc((size_t)nv * sizeof *owner);
    for (int p = 0; p < np; p++) {
        if (mesh_read(lib_path[p], &P[p].lib) < 0)
            die("%s", cm_errmsg());
        const char *mname = strcmp(map_path[p], "-") ? map_path[p] : "<stdin>";
        if (labels_read(map_path[p], P[p].lib.nv, "vertices in the library", 0, -1, &P[p].map,
                        &P[p].nmap) < 0)
            die("%s", cm_errmsg());
        /* every map entry names a BASE vertex, each at most once per part */
        for (int v = 0; v < nv; v++) owner[v] = -1;
        for (int j = 0; j < P[p].nmap; j++) {
            int v = P[p].map[j];
            if (v >= nv)
                die("cannot read '%s': row %d: vertex %d, but '%s' has %d vertices", mname, j + 1,
                    v, base.name, nv);
            if (owner[v] >= 0)
                die("cannot read '%s': rows %d and %d both name vertex %d", mname, owner[v] + 1,
                    j + 1, v);
            owner[v] = j;
        }
        const char *lname = strcmp(lab_path[p], "-") ? lab_path[p] : "<stdin>";
        if (labels_read(lab_path[p], -1, "frames", 0, P[p].lib.nframes - 1, &P[p].labels,
                        &P[p].nlabels) < 0)
            die("%s", cm_errmsg());
        if (P[p].nlabels < 1)
            die("cannot read '%s': no labels (one piece number per frame expected)", lname);
        /* one label per frame, the same count in every part; when they
         * differ and BASE's frame count matches one, the other is named */
        if (nframes >= 0 && P[p].nlabels != nframes) {
            const char *l0 = strcmp(lab_path[0], "-") ? lab_path[0] : "<stdin>";
            if (base.nframes == P[p].nlabels)
                die("cannot read '%s': %d labels, but '%s' has %d frames (one piece label per frame)",
                    l0, nframes, base.name, base.nframes);
            if (base.nframes == nframes)
                die("cannot read '%s': %d labels, but '%s' has %d frames (one piece label per frame)",
                    lname, P[p].nlabels, base.name, base.nframes);
            die("cannot read '%s': %d labels, but '%s' (part 0) has %d: every part needs one label "
                "per frame", lname, P[p].nlabels, l0, nframes);
        }
        if (nframes < 0) nframes = P[p].nlabels;
    }
    free(owner);

    FILE *f = out_open(out);
    struct mesh_writer w;
    double *X = malloc((size_t)nv * 3 * sizeof *X);
    int *cnt = malloc((size_t)nv * sizeof *cnt);
    double *first = malloc((size_t)nv * 3 * sizeof *first);
    double gap = 0;
    if (mesh_writer_open(&w, f, nv, base.nf, base.F, nframes, want_raw(raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    for (int k = 0; k < nframes; k++) {
        memcpy(X, X0, (size_t)nv * 3 * sizeof *X);
        memset(cnt, 0, (size_t)nv * sizeof *cnt);
        for (int p = 0; p < np; p++) {
            const double *piece = mesh_frame(&P[p].lib, P[p].labels[k]);
            for (int j = 0; j < P[p].nmap; j++) {
                int v = P[p].map[j];
                const double *y = piece + 3 * j;
                if (cnt[v] == 0) {
                    memcpy(X + 3 * v, y, 3 * sizeof *y);
                    memcpy(first + 3 * v, y, 3 * sizeof *y);
                } else {
                    double d = sqrt(pow(y[0] - first[3 * v], 2) + pow(y[1] - first[3 * v + 1], 2) +
                                    pow(y[2] - first[3 * v + 2], 2));
                    if (d > gap) gap = d;
                    /* X = first copy + sum of the differences to it, so
                     * copies that agree average to exactly their value */
                    for (int e = 0; e < 3; e++) X[3 * v + e] += y[e] - first[3 * v + e];
                }
                cnt[v]++;
            }
        }
        for (int v = 0; v < nv; v++)
            if (cnt[v] > 1)
                for (int e = 0; e < 3; e++)
                    X[3 * v + e] = first[3 * v + e] + (X[3 * v + e] - first[3 * v + e]) / cnt[v];
        /* cut marks: a new clip wherever the base stream had one is unknown
         * here (labels carry no cuts); the assembled film is one clip */
        if (mesh_writer_frame(&w, X, 0) < 0)
            die("cannot write output: %s", cm_errmsg());
    }
    if (mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(f);
    info(1, "%d frames, %d parts, largest seam gap %.3g", nframes, np, gap);
    mesh_reader_close(&base);
    for (int p = 0; p < np; p++) {
        mesh_free(&P[p].lib);
        free(P[p].map);
        free(P[p].labels);
        free(lib_path[p]);   /* the strdup'ed spec; lab_path and map_path point into it */
    }
    free(P);
    free(lib_path);
    free(lab_path);
    free(map_path);
    free(X0);
    free(X);
    free(cnt);
    free(first);
    return 0;
}
