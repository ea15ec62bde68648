/* mesh-import -- OBJ, OFF, PLY, STL meshes, OBJ frame sequences and
 * glTF/GLB/FBX morph-target animations to a MESH stream.
 *
 * One static file gives a one-frame stream; several OBJ files (or a quoted
 * glob, or --list FILE) give one frame each and must share one
 * connectivity; one animated file (glTF, GLB, FBX) gives its morph-target
 * animation sampled at its keyframes or at --fps.  Everything is read and
 * checked before the first byte is written.
 */
#include "anim_import.h"
#include "cm_error.h"
#include "coincident.h"
#include "mesh.h"
#include "mesh_spool.h"
#include "meshio.h"
#include "progress.h"
#include "tool.h"
#include "weld.h"
#include <errno.h>
#include <getopt.h>
#include <glob.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static const char help[] =
"Usage: mesh-import [options] FILE...\n"
"Convert meshes and animations to a MESH stream on stdout.\n"
"\n"
"  one FILE.obj|.off|.ply|.stl       a static mesh (one frame)\n"
"  one FILE.glb|.gltf|.fbx           its morph-target animation\n"
"  several OBJ files, a quoted glob ('frames/*.obj') or --list FILE:\n"
"                                    one frame per file, same connectivity\n"
"\n"
"Options:\n"
"  -l, --list FILE      read frame file names from FILE, one per line ('-': stdin)\n"
"  -F, --format FMT     input format: obj, off, ply, stl, gltf, glb, fbx\n"
"                       (default: from each file's extension)\n"
"      --fps F          animations: sample at F frames per second\n"
"                       (default: at the keyframes of the animation)\n"
"      --mesh NAME|I    animations: which mesh to take (default: the one with\n"
"                       morph targets, the largest if several)\n"
"      --animation NAME|I  animations: which animation (default: every one\n"
"                       that drives the mesh's morph weights, one clip each)\n"
"      --rest           animations: take the rest pose of a mesh whose morph\n"
"                       targets no animation drives (default: an error)\n"
"      --merge          animations: append every other mesh of the scene (eyes,\n"
"                       teeth, ...) after the chosen one, placed as in the\n"
"                       scene, static (repeated in every frame)\n"
"      --world          animations: apply the mesh's node transform\n"
"                       (default: mesh coordinates, like a baked OBJ export)\n"
"      --weld [EPS]     merge vertices within EPS in every frame (default 0:\n"
"                       identical positions), e.g. copies split at UV seams\n"
"                       or at every corner (flat-shaded glTF/FBX exports)\n"
"      --raw            write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose        print what was read, counts and timings to stderr\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"Examples:\n"
"  mesh-import spot.obj > spot.mesh\n"
"  mesh-import 'frames/frame_*.obj' > anim.mesh\n"
"  mesh-import --fps 24 facecap.glb > face.mesh\n";

struct options {
    const char *list, *format, *mesh, *animation;
    double fps, weld_eps;
    int weld, world, raw, merge, rest;
    char **files;
    int nfiles;
};

static int is_number(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno) return 0;
    *out = v;
    return 1;
}

static int file_exists(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0;
}

static void add_file(struct options *o, int *cap, const char *p)
{
    if (o->nfiles == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        o->files = realloc(o->files, *cap * sizeof *o->files);
        if (!o->files) die("out of memory");
    }
    o->files[o->nfiles++] = strdup(p);
}

/* A name with glob characters that is not itself a file is expanded
 * (sorted, as glob(3) does); a pattern that matches nothing is bad input. */
static void add_arg(struct options *o, int *cap, const char *p)
{
    if (strpbrk(p, "*?[") && !file_exists(p)) {
        glob_t g;
        int r = glob(p, 0, NULL, &g);
        if (r == GLOB_NOMATCH)
            die("cannot read '%s': no file matches this pattern", p);
        if (r != 0)
            die("cannot read '%s': pattern expansion failed", p);
        for (size_t i = 0; i < g.gl_pathc; i++) add_file(o, cap, g.gl_pathv[i]);
        globfree(&g);
    } else {
        add_file(o, cap, p);
    }
}

static void read_list(struct options *o, int *cap, const char *path)
{
    FILE *f = strcmp(path, "-") ? fopen(path, "r") : stdin;
    if (!f) die("cannot read '%s': %s", path, strerror(errno));
    char *line = NULL;
    size_t n = 0;
    ssize_t len;
    while ((len = getline(&line, &n, f)) >= 0) {
        while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = '\0';
        char *s = line;
        while (*s == ' ' || *s == '\t') s++;
        if (!*s || *s == '#') continue;
        add_arg(o, cap, s);
    }
    if (ferror(f)) die("cannot read '%s': %s", path, strerror(errno));
    free(line);
    if (f != stdin) fclose(f);
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"list", 1, 0, 'l'}, {"format", 1, 0, 'F'}, {"fps", 1, 0, 'P'}, {"mesh", 1, 0, 'M'},
        {"animation", 1, 0, 'A'}, {"world", 0, 0, 'W'}, {"merge", 0, 0, 'G'}, {"weld", 2, 0, 'w'}, {"raw", 0, 0, 'R'},
        {"rest", 0, 0, 'r'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c, cap = 0;
    while ((c = getopt_long(argc, argv, "l:F:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'l': o->list = optarg; break;
        case 'F': o->format = optarg; break;
        case 'P':
            o->fps = arg_double(optarg, "--fps");
            if (o->fps <= 0 || o->fps > 10000) usage_error("--fps must be in (0, 10000]");
            break;
        case 'M': o->mesh = optarg; break;
        case 'A': o->animation = optarg; break;
        case 'W': o->world = 1; break;
        case 'G': o->merge = 1; break;
        case 'w': {
            double e;
            o->weld = 1;
            if (optarg) {
                o->weld_eps = arg_double(optarg, "--weld");
            } else if (optind < argc && is_number(argv[optind], &e) && !file_exists(argv[optind])) {
                o->weld_eps = e;       /* "--weld 1e-6" */
                optind++;
            }
            if (o->weld_eps < 0) usage_error("--weld: EPS must not be negative");
            break;
        }
        case 'R': o->raw = 1; break;
        case 'r': o->rest = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (o->format && !meshio_format_parse(o->format) && !anim_format_parse(o->format))
        usage_error("unknown format '%s' (obj, off, ply, stl, gltf, glb, fbx)", o->format);
    if (o->list && optind < argc)
        usage_error("give either --list FILE or FILE arguments, not both");
    if (!o->list && optind >= argc)
        usage_error("expected at least one FILE");
    if (o->list) read_list(o, &cap, o->list);
    for (int i = optind; i < argc; i++) add_arg(o, &cap, argv[i]);
    if (o->nfiles == 0)
        die("cannot read '%s': no file names in it", o->list);
    for (int i = 0; i < o->nfiles; i++)
        if (strcmp(o->files[i], "-") && !file_exists(o->files[i]))
            die("cannot read '%s': %s", o->files[i], strerror(errno));   /* before any format guess */
    for (int i = 0; i < o->nfiles; i++)
        if (!strcmp(o->files[i], "-")) {
            if (!o->format || !meshio_format_parse(o->format))
                usage_error("reading stdin ('-') needs --format obj, off, ply or stl");
            if (o->list && !strcmp(o->list, "-"))
                usage_error("stdin cannot be both the list and a frame");
        }
}

/* which reader a file goes to */
enum kind { K_STATIC, K_ANIM, K_UNKNOWN };

static enum kind file_kind(const struct options *o, const char *path, int *fmt)
{
    const char *name = o->format ? o->format : NULL;
    if (name) {
        if ((*fmt = meshio_format_parse(name))) return K_STATIC;
        if ((*fmt = anim_format_parse(name))) return K_ANIM;
        return K_UNKNOWN;
    }
    if ((*fmt = meshio_format_from_name(path))) return K_STATIC;
    if ((*fmt = anim_format_from_name(path))) return K_ANIM;
    return K_UNKNOWN;
}

/* file k of a sequence, read and checked against the first file's
 * connectivity (first == NULL: k is the first) */
static void read_frame_file(const struct options *o, int k, const struct mesh *first, struct mesh *m)
{
    const char *path = o->files[k];
    int fmt;
    enum kind kd = file_kind(o, path, &fmt);
    if (kd == K_ANIM)
        die("cannot read '%s': an animation file cannot be a frame of a sequence", path);
    if (kd == K_UNKNOWN)
        die("cannot read '%s': unknown mesh format (expected .obj, .off, .ply or .stl)", path);
    if (meshio_read(path, fmt, m) < 0)
        die("%s", cm_errmsg());
    if (!first) return;
    if (m->nv != first->nv || m->nf != first->nf)
        die("cannot read '%s': connectivity differs from '%s' (%d vertices, %d triangles instead of %d, %d)",
            path, o->files[0], m->nv, m->nf, first->nv, first->nf);
    if (memcmp(m->F, first->F, (size_t)m->nf * 3 * sizeof *m->F)) {
        int t = 0;
        while (!memcmp(m->F + 3 * t, first->F + 3 * t, 3 * sizeof *m->F)) t++;
        die("cannot read '%s': connectivity differs from '%s' (triangle %d differs)", path, o->files[0], t);
    }
}

static void split_hint_rep(const int *rep, int nv, const char *path);

static int has_stdin(const struct options *o)
{
    for (int i = 0; i < o->nfiles; i++)
        if (!strcmp(o->files[i], "-")) return 1;
    return 0;
}

/* An OBJ (OFF, PLY, STL) sequence streamed: each file is read and checked
 * (connectivity, the vertices that coincide in every frame for the --weld
 * hint) and its positions go to a temporary raw MESH file (mesh_spool.h);
 * only when every file passed is the stream written, from that copy.  So
 * nothing is written before everything was checked, each file is parsed
 * once, and memory is O(one frame): holding 335 x 26,719 vertices took
 * 224 MB. */
static void stream_frames(const struct options *o)
{
    struct mesh first, m;
    struct progress p;
    double t0 = now_seconds();
    read_frame_file(o, 0, NULL, &first);
    int *rep = malloc((size_t)first.nv * sizeof *rep + 1);
    double *X = malloc((size_t)first.nv * 3 * sizeof *X + 1);
    if (!rep || !X || coincident_find(first.V, first.nv, rep) < 0) die("out of memory");
    struct mesh_reader r0, r;
    memset(&r0, 0, sizeof r0);
    r0.nv = first.nv;
    r0.nf = first.nf;
    r0.F = first.F;
    r0.nframes = o->nfiles;
    struct mesh_spool sp;
    if (mesh_spool_begin(&sp, NULL, &r0) < 0 || mesh_spool_frame(&sp, first.V, 0) < 0)
        die("%s", cm_errmsg());
    progress_start(&p, "mesh-import", o->nfiles);
    for (int k = 1; k < o->nfiles; k++) {
        read_frame_file(o, k, &first, &m);
        if (coincident_refine(m.V, m.nv, rep) < 0) die("out of memory");
        if (mesh_spool_frame(&sp, m.V, 0) < 0) die("%s", cm_errmsg());
        mesh_free(&m);
        progress_step(&p, k + 1);
    }
    progress_end(&p);
    split_hint_rep(rep, first.nv, o->files[0]);
    free(rep);
    if (mesh_spool_rewind(&sp, &r) < 0) die("%s", cm_errmsg());
    struct mesh_writer w;
    if (mesh_writer_open(&w, stdout, first.nv, first.nf, first.F, o->nfiles, want_raw(o->raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    int rc, cut;
    while ((rc = mesh_reader_next(&r, X, &cut)) == 1)
        if (mesh_writer_frame(&w, X, cut) < 0) die("cannot write output: %s", cm_errmsg());
    if (rc < 0) die("%s", cm_errmsg());
    if (mesh_writer_close(&w) < 0 || fflush(stdout) != 0 || ferror(stdout))
        die("cannot write output: %s", cm_errmsg());
    if (fclose(stdout) != 0)
        die("cannot write output: %s", strerror(errno));
    info(1, "read %d files: %d vertices, %d triangles, %.2f s (streamed through a temporary file)",
         o->nfiles, first.nv, first.nf, now_seconds() - t0);
    mesh_reader_close(&r);
    mesh_spool_free(&sp);
    mesh_free(&first);
    free(X);
}

/* several static files -> one animation with one frame each */
static void read_frames(const struct options *o, struct mesh *out)
{
    struct mesh first;
    struct progress p;
    double t0 = now_seconds();
    progress_start(&p, "mesh-import", o->nfiles);
    for (int k = 0; k < o->nfiles; k++) {
        struct mesh m;
        read_frame_file(o, k, k ? &first : NULL, &m);
        if (k == 0) {
            first = m;
            if (mesh_alloc(out, m.nv, m.nf, o->nfiles) < 0)
                die("%s", cm_errmsg());
            memcpy(out->F, m.F, (size_t)m.nf * 3 * sizeof *m.F);
        }
        memcpy(mesh_frame(out, k), m.V, (size_t)m.nv * 3 * sizeof *m.V);
        if (k > 0) mesh_free(&m);
        progress_step(&p, k + 1);
    }
    progress_end(&p);
    info(1, "read %d file%s: %d vertices, %d triangles, %.2f s", o->nfiles, o->nfiles > 1 ? "s" : "",
         out->nv, out->nf, now_seconds() - t0);
    mesh_free(&first);
}

static void read_animation(const struct options *o, const char *path, int fmt, struct mesh *out)
{
    struct anim_import_opts ao = {0};
    struct anim_import_info ai;
    ao.format = fmt;
    ao.mesh = o->mesh;
    ao.animation = o->animation;
    ao.fps = o->fps;
    ao.world = o->world;
    ao.merge = o->merge;
    double t0 = now_seconds();
    if (anim_import(path, &ao, out, &ai) < 0)
        die("%s", cm_errmsg());
    if (ai.nkeys > 0 && ai.nclips > 1)
        info(1, "%s: mesh %d '%s' (%d morph targets), %d animations from %d '%s' (%d keys, %.3f s%s): "
             "%d clips, %d frames, %d vertices, %d triangles, %.2f s",
             path, ai.mesh_index, ai.mesh_name, ai.ntargets, ai.nclips, ai.anim_index, ai.anim_name, ai.nkeys,
             ai.duration, ai.decoded_weights ? ", weights decoded from the glTF accessor"
                         : ai.fbx_weights ? ", weights read from the FBX blend-shape channels" : "",
             ai.nclips, out->nframes, out->nv, out->nf, now_seconds() - t0);
    else if (ai.nkeys > 0)
        info(1, "%s: mesh %d '%s' (%d morph targets), animation %d '%s' (%d keys, %.3f s%s): "
             "%d frames, %d vertices, %d triangles, %.2f s",
             path, ai.mesh_index, ai.mesh_name, ai.ntargets, ai.anim_index, ai.anim_name, ai.nkeys,
             ai.duration, ai.decoded_weights ? ", weights decoded from the glTF accessor"
                         : ai.fbx_weights ? ", weights read from the FBX blend-shape channels" : "",
             out->nframes, out->nv, out->nf, now_seconds() - t0);
    else if (ai.ntargets > 0 && !o->rest)
        die("cannot read '%s': mesh %d '%s' has %d morph targets but the file has no animation of "
            "their weights that assimp reads%s; give --rest to take the rest pose", path, ai.mesh_index, ai.mesh_name,
            ai.ntargets, fmt == ANIM_FBX
                ? " (Blender 3.4 writes none with its default FBX export: untick Bake Animation > "
                  "All Actions and NLA Strips, or export glTF)"
                : " (export it with its animation)");
    else
        info(1, "%s: mesh %d '%s' (%d morph targets, no morph animation): %d vertices, %d triangles, %.2f s",
             path, ai.mesh_index, ai.mesh_name, ai.ntargets, out->nv, out->nf, now_seconds() - t0);
    if (ai.morph_meshes > 1 && !o->merge)
        warn("'%s': %d meshes have morph targets; took mesh %d '%s' (choose with --mesh)", path,
             ai.morph_meshes, ai.mesh_index, ai.mesh_name);
    if (o->merge)
        info(1, "merged %d other mesh%s (%d vertices) after mesh %d", ai.merged, ai.merged == 1 ? "" : "es",
             ai.merged_nv, ai.mesh_index);
    if (ai.merged_morph)
        warn("%s: %d merged mesh%s morph targets of its own, taken at the base shape (import it alone with --mesh)",
             path, ai.merged_morph, ai.merged_morph == 1 ? " has" : "es have");
}

/* Vertices at the same position as another one in every frame: copies an
 * exporter split off (UV seams, hard edges; every corner of a flat-shaded
 * glTF/FBX).  Half or more of them: one warning line suggesting --weld;
 * fewer: counted with -v. */
static void split_hint(const struct mesh *m, const char *path)
{
    int *rep = malloc((size_t)m->nv * sizeof *rep + 1);
    if (!rep) die("out of memory");
    if (coincident_find(mesh_frame(m, 0), m->nv, rep) < 0) die("out of memory");
    for (int k = 1; k < m->nframes; k++) coincident_refine(mesh_frame(m, k), m->nv, rep);
    split_hint_rep(rep, m->nv, path);
    free(rep);
}

static void split_hint_rep(const int *rep, int nv, const char *path)
{
    int copies = 0;
    for (int v = 0; v < nv; v++) copies += rep[v] != v;
    if (2 * copies >= nv)
        warn("'%s': %d of %d vertices are copies at the position of another vertex in every frame "
             "(split at every corner, as flat-shaded exports do): --weld joins them", path, copies, nv);
    else if (copies > 0)
        info(1, "'%s': %d of %d vertices are copies at the position of another vertex in every frame "
             "(split at seams): --weld joins them", path, copies, nv);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    struct mesh m;
    int fmt;
    enum kind kd = file_kind(&o, o.files[0], &fmt);
    if (o.merge && !(o.nfiles == 1 && kd == K_ANIM))
        usage_error("--merge is for one glTF, GLB or FBX scene (an OBJ file is read whole already)");
    if (o.nfiles == 1 && kd == K_ANIM)
        read_animation(&o, o.files[0], fmt, &m);
    else if (o.nfiles == 1 && kd == K_UNKNOWN)
        die("cannot read '%s': unknown file format (expected .obj, .off, .ply, .stl, .gltf, .glb or .fbx)",
            o.files[0]);
    else if (o.nfiles > 1 && !o.weld && !has_stdin(&o)) {
        stream_frames(&o);
        for (int i = 0; i < o.nfiles; i++) free(o.files[i]);
        free(o.files);
        return 0;
    } else
        read_frames(&o, &m);

    if (!o.weld) split_hint(&m, o.files[0]);
    if (o.weld) {
        int merged, dropped;
        if (mesh_weld(&m, o.weld_eps, &merged, &dropped) < 0)
            die("%s", cm_errmsg());
        info(1, "weld: merged %d vertices, dropped %d degenerate triangles: %d vertices, %d triangles",
             merged, dropped, m.nv, m.nf);
        if (m.nf == 0)
            die("cannot read '%s': no triangle left after welding", o.files[0]);
    }
    if (mesh_write(stdout, &m, want_raw(o.raw)) < 0 || fflush(stdout) != 0 || ferror(stdout))
        die("cannot write output: %s", cm_errmsg());
    if (fclose(stdout) != 0)
        die("cannot write output: %s", strerror(errno));
    mesh_free(&m);
    for (int i = 0; i < o.nfiles; i++) free(o.files[i]);
    free(o.files);
    return 0;
}
