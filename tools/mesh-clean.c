/* mesh-clean -- clean a scanned mesh: degenerate and duplicate faces
 * (including zero-volume fins), non-manifold vertices, holes; optionally
 * isotropic remeshing (CGAL Polygon Mesh Processing; thesis Sec. 3.2).
 */
#include "geometry.h"
#include "mesh.h"
#include "mesh_clean.h"
#include "tool.h"
#include "unfold.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: mesh-clean [options] [FILE]\n"
"Clean a static mesh (a scan): remove degenerate faces, duplicate faces and\n"
"fins (two copies of a face with opposite orientation), split non-manifold\n"
"vertices, orient, close holes, turn fold-overs back (faces pointing against\n"
"all three neighbours); optionally remesh isotropically.\n"
"Vertex indices change (unreferenced vertices go).\n"
"\n"
"Options:\n"
"      --no-fill          keep the holes\n"
"      --max-hole N       close only holes with at most N boundary edges (default: all)\n"
"      --min-component F  remove pieces with fewer than F times all faces (default 0.01)\n"
"  -r, --remesh L         isotropic remeshing to edge length L (model units)\n"
"  -R, --remesh-rel R     ... to R times the bounding-box diagonal\n"
"      --iterations N     remeshing iterations (default 3)\n"
"      --no-unfold        keep fold-overs\n"
"  -o, --output FILE      write to FILE (atomically) instead of stdout\n"
"      --raw              write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose          report what was removed and filled\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: mesh-import scan.off | mesh-clean -v -R 0.005 > scan-clean.mesh\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    enum { O_NOFILL = 256, O_MAXHOLE, O_ITER, O_RAW, O_VERSION, O_MINC, O_NOUNF };
    static const struct option lo[] = {
        {"no-fill", 0, 0, O_NOFILL}, {"no-unfold", 0, 0, O_NOUNF}, {"max-hole", 1, 0, O_MAXHOLE}, {"min-component", 1, 0, O_MINC}, {"remesh", 1, 0, 'r'},
        {"remesh-rel", 1, 0, 'R'}, {"iterations", 1, 0, O_ITER}, {"output", 1, 0, 'o'},
        {"raw", 0, 0, O_RAW}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, O_VERSION}, {0, 0, 0, 0}};
    struct mesh_clean_opts o = {1, 0, 0, 3, 0.01};
    double rel = 0;
    const char *output = NULL;
    int raw = 0, unfold = 1, c;
    while ((c = getopt_long(argc, argv, "r:R:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case O_NOFILL: o.fill_holes = 0; break;
        case O_NOUNF: unfold = 0; break;
        case O_MINC: o.min_component = arg_double(optarg, "--min-component"); break;
        case O_MAXHOLE: o.max_hole = arg_int(optarg, "--max-hole"); break;
        case 'r': o.edge_length = arg_double(optarg, "--remesh"); break;
        case 'R': rel = arg_double(optarg, "--remesh-rel"); break;
        case O_ITER: o.iterations = arg_int(optarg, "--iterations"); break;
        case 'o': output = optarg; break;
        case O_RAW: raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (o.edge_length < 0 || rel < 0) usage_error("remeshing edge length must be positive");
    if (o.iterations < 1) usage_error("--iterations must be >= 1");
    if (o.min_component < 0 || o.min_component >= 1) usage_error("--min-component must be in [0, 1)");
    if (argc - optind > 1) usage_error("expected at most one input");
    const char *in = optind < argc ? argv[optind] : "-";
    struct mesh m;
    if (mesh_read(in, &m) < 0) die("%s", cm_errmsg());
    if (m.nframes != 1)
        die("cannot clean '%s': %d frames; mesh-clean works on a static mesh (anim-slice -f K)",
            in, m.nframes);
    if (rel > 0) o.edge_length = rel * bbox_diagonal(m.V, m.nv);
    double *V;
    int *F, nv, nf;
    struct mesh_clean_report r;
    if (mesh_clean(m.V, m.nv, m.F, m.nf, &o, &V, &nv, &F, &nf, &r) < 0)
        die("cannot clean '%s': %s", in, cm_errmsg());
    info(1, "removed %d degenerate, %d duplicate, %d fin faces, %d small pieces; filled %d holes, "
         "%d left; %d vertices, %d faces", r.degenerate, r.duplicate, r.fins, r.components_removed,
         r.holes_filled, r.holes_left, nv, nf);
    if (unfold) {
        /* after remeshing too: fold-overs are faces turned over in place */
        int found, left = unfold_faces(V, F, nv, nf, -0.5, 20, &found);
        if (left < 0) die("cannot clean '%s': %s", in, cm_errmsg());
        info(1, "fold-overs: %d found, %d left", found, left);
    }
    struct mesh out = {0};
    out.nv = nv; out.nf = nf; out.nframes = 1; out.V = V; out.F = F;
    unsigned char cut = 0;
    out.cut = &cut;
    FILE *f = out_open(output);
    if (mesh_write(f, &out, want_raw(raw)) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(f);
    free(V); free(F);
    mesh_free(&m);
    return 0;
}
