/* shell-extrude -- turn open replacement pieces into closed printable
 * solids (StopShop Sec. 3.4, 4): offset every piece inward along its vertex
 * normals and stitch each boundary loop to its offset copy with a strip of
 * quads (two triangles each).  Boundary vertices are offset along normals
 * shared by all pieces of the stream, so the seam side of every piece is
 * the same solid cross-section and pieces of neighbouring parts still mate.
 */
#include "mesh.h"
#include "topology.h"
#include "geometry.h"
#include "tool.h"
#include "cm_error.h"
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: shell-extrude [options] [FILE]\n"
"Make closed solids from open pieces (a MESH stream, frames = pieces, e.g. a\n"
"dict-learn library): each piece is offset inward along its vertex normals\n"
"and every boundary loop is stitched to its offset with a strip of\n"
"triangulated quads.  Boundary vertices use normals averaged over all pieces\n"
"so the seam side is identical in every piece and pieces still mate.\n"
"Output: a MESH stream of the solids (2#V vertices, 2#F + 2#boundary-edges\n"
"faces), one frame per piece; export to STL with mesh-export.\n"
"\n"
"Options:\n"
"  -t, --thickness T      wall thickness in model units\n"
"  -m, --model FILE       the whole model (a MESH stream, its first frame, e.g.\n"
"                         the seam-homog output): what the options below are\n"
"                         relative to, so every part gets the same wall\n"
"  -r, --thickness-rel R  wall thickness as a fraction of the bounding-box\n"
"                         diagonal of --model (default 0.02; without --model:\n"
"                         of this library's first piece, with a warning)\n"
"      --thickness-mm T   wall thickness T mm on a print of --model that is\n"
"                         --height H mm tall along --axis (x, y or z; default y)\n"
"      --outward          offset along +normal instead (normals point inward)\n"
"  -o, --output FILE      write to FILE instead of stdout\n"
"      --raw              raw (binary) MESH output\n"
"  -v, --verbose          report thickness, loops, volumes\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: shell-extrude -m homog.mesh --thickness-mm 1 --height 40 lower.lib > lower.solid\n"
"         shell-extrude -t 1.5 lower.lib | mesh-export -k 0 -F stl -o piece0.stl\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"thickness", 1, 0, 't'}, {"thickness-rel", 1, 0, 'r'}, {"outward", 0, 0, 'O'},
        {"model", 1, 0, 'm'}, {"thickness-mm", 1, 0, 'T'}, {"height", 1, 0, 'H'}, {"axis", 1, 0, 'A'},
        {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    double thick = -1, rel = 0.02, mm = -1, height = -1;
    int outward = 0, raw = 0, c, axis = 1, nthick = 0;
    const char *output = NULL, *model = NULL;
    while ((c = getopt_long(argc, argv, "t:r:m:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 't': thick = arg_double(optarg, "--thickness"); nthick++;
            if (!(thick > 0) || !isfinite(thick)) usage_error("--thickness must be > 0");
            break;
        case 'r': rel = arg_double(optarg, "--thickness-rel"); nthick++;
            if (!(rel > 0) || !isfinite(rel)) usage_error("--thickness-rel must be > 0");
            break;
        case 'T': mm = arg_double(optarg, "--thickness-mm"); nthick++;
            if (!(mm > 0) || !isfinite(mm)) usage_error("--thickness-mm must be > 0");
            break;
        case 'H': height = arg_double(optarg, "--height");
            if (!(height > 0) || !isfinite(height)) usage_error("--height must be > 0");
            break;
        case 'A':
            if (strlen(optarg) != 1 || optarg[0] < 'x' || optarg[0] > 'z')
                usage_error("--axis must be x, y or z");
            axis = optarg[0] - 'x';
            break;
        case 'm': model = optarg; break;
        case 'O': outward = 1; break;
        case 'o': output = optarg; break;
        case 'R': raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1) usage_error("expected at most one input FILE");
    if (nthick > 1) usage_error("give one of --thickness, --thickness-rel, --thickness-mm");
    if (mm > 0 && (height < 0 || !model))
        usage_error("--thickness-mm needs --height H (mm) and --model FILE (the whole model)");
    if (height > 0 && mm < 0) usage_error("--height goes with --thickness-mm");
    if (model && thick > 0) usage_error("--thickness is in model units: --model is not used with it");
    /* the whole model's first frame: its bbox diagonal and extent */
    double mdiag = 0, mext = 0;
    if (model) {
        struct mesh_reader mr;
        if (mesh_reader_open(&mr, model) < 0) die("%s", cm_errmsg());
        double *X = malloc(sizeof(double) * 3 * ((size_t)mr.nv + 1));
        if (!X) die("out of memory");
        int rc = mesh_reader_next(&mr, X, NULL);
        if (rc < 0) die("%s", cm_errmsg());
        if (rc == 0) die("cannot read '%s': the stream has no frames", model);
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < mr.nv; i++) {
            if (X[3 * i + axis] < lo) lo = X[3 * i + axis];
            if (X[3 * i + axis] > hi) hi = X[3 * i + axis];
        }
        mdiag = bbox_diagonal(X, mr.nv);
        mext = hi - lo;
        free(X);
        mesh_reader_close(&mr);
        if (!(mdiag > 0) || (mm > 0 && !(mext > 0)))
            die("cannot read '%s': the model has no extent%s", model, mm > 0 ? " along --axis" : "");
    }
    const char *input = optind < argc ? argv[optind] : NULL, *iname = input ? input : "<stdin>";
    struct mesh m;
    if (mesh_read(input, &m) < 0) die("%s", cm_errmsg());
    int nv = m.nv, nf = m.nf, np = m.nframes;
    struct topology t;
    if (topology_build(m.F, nf, nv, &t) < 0) die("cannot read '%s': %s", iname, cm_errmsg());
    if (t.nnonmanifold > 0) die("cannot read '%s': %d non-manifold edges", iname, t.nnonmanifold);
    int *Ls, *L;
    int nl = boundary_loops(&t, m.F, &Ls, &L);
    if (nl < 0) die("cannot read '%s': %s", iname, cm_errmsg());
    int nb = Ls[nl];
    if (thick < 0 && mm > 0) {
        thick = mm * mext / height;
        info(1, "%g mm at %g mm tall: %g model units", mm, height, thick);
    } else if (thick < 0 && model) {
        thick = rel * mdiag;
    } else if (thick < 0) {
        thick = rel * bbox_diagonal(mesh_frame(&m, 0), nv);
        warn("thickness %g relative to this library's own box: other parts get other walls "
             "(give --model WHOLE.mesh)", thick);
    }
    if (!(thick > 0)) die("cannot read '%s': zero-size piece, no thickness", iname);
    double sgn = outward ? 1 : -1;

    /* seam normals: vertex normals of the mean piece, for boundary vertices */
    double *mean = calloc((size_t)nv * 3, sizeof(double)), *Nm = malloc(sizeof(double) * nv * 3);
    double *N = malloc(sizeof(double) * nv * 3);
    unsigned char *onb = calloc(nv, 1);
    for (int k = 0; k < np; k++)
        for (int i = 0; i < 3 * nv; i++) mean[i] += mesh_frame(&m, k)[i] / np;
    vertex_normals(mean, m.F, nv, nf, Nm);
    for (int k = 0; k < nb; k++) onb[L[k]] = 1;

    struct mesh out;
    if (mesh_alloc(&out, 2 * nv, 2 * nf + 2 * nb, np) < 0) die("%s", cm_errmsg());
    int *F = out.F;
    for (int f = 0; f < nf; f++) {
        F[3 * f] = m.F[3 * f]; F[3 * f + 1] = m.F[3 * f + 1]; F[3 * f + 2] = m.F[3 * f + 2];
        int *g = F + 3 * (nf + f);
        g[0] = m.F[3 * f] + nv; g[1] = m.F[3 * f + 2] + nv; g[2] = m.F[3 * f + 1] + nv;
    }
    int *s = F + 6 * nf;
    for (int l = 0; l < nl; l++)
        for (int k = Ls[l]; k < Ls[l + 1]; k++) {
            int a = L[k], b = L[k + 1 < Ls[l + 1] ? k + 1 : Ls[l]];
            /* boundary half-edge a->b of the outer face: strip has b->a and a'->b' */
            s[0] = b; s[1] = a; s[2] = a + nv;
            s[3] = b; s[4] = a + nv; s[5] = b + nv;
            s += 6;
        }
    double vmin = INFINITY, vmax = -INFINITY;
    for (int k = 0; k < np; k++) {
        const double *V = mesh_frame(&m, k);
        double *O = mesh_frame(&out, k);
        vertex_normals(V, m.F, nv, nf, N);
        for (int i = 0; i < nv; i++) {
            const double *n = onb[i] ? Nm + 3 * i : N + 3 * i;
            double len = norm3(n);
            if (!(len > 0)) die("cannot read '%s': piece %d: vertex %d has no normal (isolated or degenerate)", iname, k, i);
            for (int c3 = 0; c3 < 3; c3++) {
                O[3 * i + c3] = V[3 * i + c3];
                O[3 * (nv + i) + c3] = V[3 * i + c3] + sgn * thick * n[c3] / len;
            }
        }
        double vol = mesh_volume(O, out.F, out.nf);
        if (vol < vmin) vmin = vol;
        if (vol > vmax) vmax = vol;
    }
    info(1, "%d pieces, thickness %g, %d boundary loops (%d edges), volumes %g .. %g", np, thick, nl, nb, vmin, vmax);
    if (vmax < 0) warn("negative volumes: the normals point inward; try --outward");
    FILE *fo = out_open(output);
    if (mesh_write(fo, &out, want_raw(raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(fo);
    free(mean); free(Nm); free(N); free(onb); free(Ls); free(L);
    topology_free(&t);
    mesh_free(&out);
    mesh_free(&m);
    return 0;
}
