// meshio.cpp -- OBJ/OFF (exact text parsers) and PLY/STL (OpenMesh) reading
// and writing of static triangle meshes; see meshio.h.
#include "meshio.h"
#include "cm_error.h"
#include "numparse.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/IO/exporter/BaseExporter.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Core/Mesh/BaseKernel.hh>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <strings.h>
#include <vector>

using OpenMesh::Vec2f;
using OpenMesh::Vec3d;
using OpenMesh::Vec3f;
using OpenMesh::Vec3uc;
using OpenMesh::Vec3ui;
using OpenMesh::Vec4f;
using OpenMesh::Vec4uc;
using OpenMesh::Vec4ui;
using OpenMesh::VertexHandle;
using OpenMesh::FaceHandle;
using OpenMesh::EdgeHandle;
using OpenMesh::HalfedgeHandle;
namespace Attr = OpenMesh::Attributes;

static const int MAX_ELEMENTS = 200000000;

extern "C" int meshio_format_parse(const char *s)
{
    if (!s) return MESHIO_NONE;
    if (!strcasecmp(s, "obj")) return MESHIO_OBJ;
    if (!strcasecmp(s, "off")) return MESHIO_OFF;
    if (!strcasecmp(s, "ply")) return MESHIO_PLY;
    if (!strcasecmp(s, "stl")) return MESHIO_STL;
    return MESHIO_NONE;
}

extern "C" int meshio_format_from_name(const char *path)
{
    if (!path) return MESHIO_NONE;
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    return dot ? meshio_format_parse(dot + 1) : MESHIO_NONE;
}

extern "C" const char *meshio_format_name(int fmt)
{
    switch (fmt) {
    case MESHIO_OBJ: return "obj";
    case MESHIO_OFF: return "off";
    case MESHIO_PLY: return "ply";
    case MESHIO_STL: return "stl";
    default: return "none";
    }
}

/* ------------------------------------------------------------------ */
/* common: the collected polygons, validated and copied into a mesh    */

struct soup {
    std::vector<double> V;       // #V by 3
    std::vector<int> F;          // #F by 3 (fan triangles)
    std::vector<long> Fline;     // source line of each triangle (0: unknown)
};

// Fan-triangulate polygon idx[0..n-1] (orientation kept).
static void add_polygon(soup &s, const int *idx, int n, long line)
{
    for (int i = 1; i + 1 < n; i++) {
        s.F.push_back(idx[0]);
        s.F.push_back(idx[i]);
        s.F.push_back(idx[i + 1]);
        s.Fline.push_back(line);
    }
}

static int soup_to_mesh(soup &s, const char *path, struct mesh *m)
{
    size_t nv = s.V.size() / 3, nf = s.F.size() / 3;
    if (nv == 0)
        return cm_seterr("cannot read '%s': no vertices", path);
    if (nf == 0)
        return cm_seterr("cannot read '%s': no faces", path);
    if (nv > (size_t)MAX_ELEMENTS || nf > (size_t)MAX_ELEMENTS)
        return cm_seterr("cannot read '%s': too many elements", path);
    for (size_t i = 0; i < s.V.size(); i++)
        if (!std::isfinite(s.V[i]))
            return cm_seterr("cannot read '%s': vertex %zu: coordinate is not finite", path, i / 3);
    for (size_t t = 0; t < nf; t++)
        for (int c = 0; c < 3; c++) {
            int v = s.F[3 * t + c];
            if (v < 0 || (size_t)v >= nv) {
                long line = t < s.Fline.size() ? s.Fline[t] : 0;
                if (line > 0)
                    return cm_seterr("cannot read '%s': line %ld: vertex index %ld out of range (%zu vertices)",
                                     path, line, (long)v + 1, nv);
                return cm_seterr("cannot read '%s': face %zu: vertex index %d out of range (%zu vertices)",
                                 path, t, v, nv);
            }
        }
    if (mesh_alloc(m, (int)nv, (int)nf, 1) < 0)
        return -1;
    memcpy(m->V, s.V.data(), s.V.size() * sizeof(double));
    memcpy(m->F, s.F.data(), s.F.size() * sizeof(int));
    return 0;
}

/* Whole file (path "-": stdin) into memory; text != 0 rejects NUL bytes. */
static int slurp(const char *path, std::string &buf, int text)
{
    int is_stdin = !strcmp(path, "-");
    FILE *f = is_stdin ? stdin : fopen(path, "rb");
    if (!f)
        return cm_seterr("cannot read '%s': %s", path, strerror(errno));
    char tmp[1 << 16];
    size_t n;
    while ((n = fread(tmp, 1, sizeof tmp, f)) > 0)
        buf.append(tmp, n);
    int bad = ferror(f);
    int e = errno;
    if (!is_stdin) fclose(f);
    if (bad)
        return cm_seterr("cannot read '%s': %s", path, strerror(e));
    if (text && memchr(buf.data(), '\0', buf.size()))
        return cm_seterr("cannot read '%s': binary data in a text format", path);
    return 0;
}

/* Line iterator over a buffer: returns the next line (NUL terminated in
 * place, '\r' and '#' comments stripped), NULL at the end. */
struct lines {
    char *p, *end;
    long no;
    bool toolong;    /* set when a line over MESHIO_LINE_MAX stopped the reading */
};

/* the longest text line accepted ('\n' not counted), as in the MESH reader */
static const long MESHIO_LINE_MAX = 1L << 20;

static char *next_line(lines &L)
{
    while (L.p < L.end) {
        char *s = L.p;
        char *nl = (char *)memchr(s, '\n', L.end - s);
        char *e = nl ? nl : L.end;
        if (e - s > MESHIO_LINE_MAX) {
            L.no++;
            L.toolong = true;
            L.p = L.end;
            return NULL;
        }
        L.p = nl ? nl + 1 : L.end;
        L.no++;
        *e = '\0';
        char *hash = strchr(s, '#');
        if (hash) *hash = '\0';
        for (char *q = s; *q; q++)
            if (*q == '\r') *q = ' ';
        while (*s == ' ' || *s == '\t') s++;
        if (*s)
            return s;
    }
    return NULL;
}

static int too_long(const char *path, const lines &L)
{
    return cm_seterr("cannot read '%s': line %ld: line longer than %ld bytes", path, L.no, MESHIO_LINE_MAX);
}

static int only_blanks(const char *p)
{
    while (*p == ' ' || *p == '\t') p++;
    return *p == '\0';
}

/* ------------------------------------------------------------------ */
/* OBJ                                                                 */

static int is_ignored_obj_keyword(const char *k, size_t n)
{
    static const char *const ok[] = {
        "vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p", "cstype", "deg",
        "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end",
        "con", "mg", "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj",
        "ctech", "stech", "call", "csh", "maplib", "usemap", NULL};
    for (int i = 0; ok[i]; i++)
        if (strlen(ok[i]) == n && !strncmp(ok[i], k, n))
            return 1;
    return 0;
}

static int read_obj(const char *path, struct mesh *m)
{
    std::string buf;
    if (slurp(path, buf, 1) < 0)
        return -1;
    soup s;
    lines L = {&buf[0], &buf[0] + buf.size(), 0, false};
    std::vector<int> poly;
    char *ln;
    while ((ln = next_line(L))) {
        size_t kl = strcspn(ln, " \t");
        char *p = ln + kl;
        if (kl == 1 && ln[0] == 'v') {
            double x[3];
            for (int d = 0; d < 3; d++) {
                const char *q = parse_double(p, &x[d]);
                if (!q)
                    return cm_seterr("cannot read '%s': line %ld: expected 3 numbers after 'v'", path, L.no);
                p = (char *)q;
            }
            if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
                return cm_seterr("cannot read '%s': line %ld: coordinate is not finite", path, L.no);
            if ((long)s.V.size() / 3 >= MAX_ELEMENTS)
                return cm_seterr("cannot read '%s': line %ld: too many vertices", path, L.no);
            s.V.insert(s.V.end(), x, x + 3);
        } else if (kl == 1 && ln[0] == 'f') {
            poly.clear();
            long nv = (long)s.V.size() / 3;
            for (;;) {
                while (*p == ' ' || *p == '\t') p++;
                if (!*p) break;
                long i;
                const char *q = parse_long(p, &i);
                if (!q || (*q && *q != '/' && *q != ' ' && *q != '\t'))
                    return cm_seterr("cannot read '%s': line %ld: bad face vertex '%.*s'", path, L.no,
                                     (int)strcspn(p, " \t"), p);
                if (i == 0)
                    return cm_seterr("cannot read '%s': line %ld: vertex index 0 (OBJ counts from 1)", path, L.no);
                if (i < 0) {                 /* relative to the vertices so far */
                    if (-i > nv)
                        return cm_seterr("cannot read '%s': line %ld: vertex index %ld out of range", path, L.no, i);
                    i = nv + i;
                } else {
                    if (i > MAX_ELEMENTS)
                        return cm_seterr("cannot read '%s': line %ld: vertex index %ld out of range", path, L.no, i);
                    i = i - 1;
                }
                poly.push_back((int)i);
                p = (char *)q + strcspn(q, " \t");   /* skip /vt/vn */
            }
            if (poly.size() < 3)
                return cm_seterr("cannot read '%s': line %ld: a face needs at least 3 vertices", path, L.no);
            add_polygon(s, poly.data(), (int)poly.size(), L.no);
        } else if (!is_ignored_obj_keyword(ln, kl)) {
            return cm_seterr("cannot read '%s': line %ld: unknown OBJ statement '%.*s'", path, L.no,
                             (int)(kl > 20 ? 20 : kl), ln);
        }
    }
    if (L.toolong)
        return too_long(path, L);
    return soup_to_mesh(s, path, m);
}

/* ------------------------------------------------------------------ */
/* OFF                                                                 */

/* header keyword: [ST][C][N]OFF (texture/colour/normal variants, 3D only) */
static int off_keyword(const char *k, size_t n)
{
    if (n < 3 || strncmp(k + n - 3, "OFF", 3)) return 0;
    for (size_t i = 0; i + 3 < n; i++)
        if (!strchr("STCN", k[i])) return 0;
    return 1;
}

static int read_off(const char *path, struct mesh *m)
{
    std::string buf;
    if (slurp(path, buf, 1) < 0)
        return -1;
    soup s;
    lines L = {&buf[0], &buf[0] + buf.size(), 0, false};
    char *ln = next_line(L);
    if (L.toolong)
        return too_long(path, L);
    size_t kl = ln ? strcspn(ln, " \t") : 0;
    if (!ln || !off_keyword(ln, kl))
        return cm_seterr("cannot read '%s': line %ld: not an OFF file (expected 'OFF')", path, L.no ? L.no : 1);
    char *p = ln + kl;
    while (*p == ' ' || *p == '\t') p++;
    if (!strncmp(p, "BINARY", 6))
        return cm_seterr("cannot read '%s': binary OFF is not supported", path);
    if (!*p) {
        p = next_line(L);
        if (L.toolong)
            return too_long(path, L);
        if (!p)
            return cm_seterr("cannot read '%s': line %ld: missing vertex and face counts", path, L.no);
    }
    long nv, nf, ne = 0;
    const char *q = parse_long(p, &nv);
    if (q) q = parse_long(q, &nf);
    if (q && !only_blanks(q)) q = parse_long(q, &ne);
    if (!q || !only_blanks(q) || nv < 0 || nf < 0 || nv > MAX_ELEMENTS || nf > MAX_ELEMENTS)
        return cm_seterr("cannot read '%s': line %ld: expected 'vertices faces edges' counts", path, L.no);
    /* reserve what the file can hold (a vertex line has at least 6
     * bytes), not what the header claims */
    s.V.reserve(3 * (size_t)std::min(nv, (long)(buf.size() / 6)));
    for (long i = 0; i < nv; i++) {
        p = next_line(L);
        if (L.toolong)
            return too_long(path, L);
        if (!p)
            return cm_seterr("cannot read '%s': line %ld: expected %ld vertices, found %ld", path, L.no, nv, i);
        double x[3];
        for (int d = 0; d < 3; d++) {
            q = parse_double(p, &x[d]);
            if (!q)
                return cm_seterr("cannot read '%s': line %ld: expected 3 numbers", path, L.no);
            p = (char *)q;
        }
        if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
            return cm_seterr("cannot read '%s': line %ld: coordinate is not finite", path, L.no);
        s.V.insert(s.V.end(), x, x + 3);
    }
    std::vector<int> poly;
    for (long f = 0; f < nf; f++) {
        p = next_line(L);
        if (L.toolong)
            return too_long(path, L);
        if (!p)
            return cm_seterr("cannot read '%s': line %ld: expected %ld faces, found %ld", path, L.no, nf, f);
        long n;
        q = parse_long(p, &n);
        if (!q || n < 3 || n > 1000000)
            return cm_seterr("cannot read '%s': line %ld: expected a face 'n i1 ... in' with n >= 3", path, L.no);
        poly.clear();
        for (long k = 0; k < n; k++) {
            long i;
            q = parse_long(q, &i);
            if (!q)
                return cm_seterr("cannot read '%s': line %ld: expected %ld vertex indices", path, L.no, n);
            if (i < 0 || i >= nv)
                return cm_seterr("cannot read '%s': line %ld: vertex index %ld out of range (%ld vertices)",
                                 path, L.no, i, nv);
            poly.push_back((int)i);
        }
        /* the rest of the line may hold a colour */
        add_polygon(s, poly.data(), (int)n, L.no);
    }
    return soup_to_mesh(s, path, m);
}

/* ------------------------------------------------------------------ */
/* PLY and STL through OpenMesh                                        */

/* Collects what an OpenMesh reader sends: positions and polygons. */
class SoupImporter : public OpenMesh::IO::BaseImporter {
public:
    soup s;
    int nface = 0;
    VertexHandle add_vertex(const Vec3f &p) override { return push(p[0], p[1], p[2]); }
    VertexHandle add_vertex(const Vec3d &p) override { return push(p[0], p[1], p[2]); }
    VertexHandle add_vertex() override { return push(0, 0, 0); }
    void set_point(VertexHandle vh, const Vec3f &p) override
    {
        if (vh.is_valid() && (size_t)vh.idx() < s.V.size() / 3)
            for (int d = 0; d < 3; d++) s.V[3 * vh.idx() + d] = p[d];
    }
    FaceHandle add_face(const VHandles &h) override
    {
        std::vector<int> idx(h.size());
        for (size_t i = 0; i < h.size(); i++) idx[i] = h[i].idx();
        if (idx.size() >= 3)
            add_polygon(s, idx.data(), (int)idx.size(), 0);
        return FaceHandle(nface++);
    }
    HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
    FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f> &) override {}
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f> &) override {}
    void set_face_texindex(FaceHandle, int) override {}
    void set_halfedge(VertexHandle, HalfedgeHandle) override {}
    void set_normal(VertexHandle, const Vec3f &) override {}
    void set_normal(VertexHandle, const Vec3d &) override {}
    void set_color(VertexHandle, const Vec3uc &) override {}
    void set_color(VertexHandle, const Vec4uc &) override {}
    void set_color(VertexHandle, const Vec3f &) override {}
    void set_color(VertexHandle, const Vec4f &) override {}
    void set_texcoord(VertexHandle, const Vec2f &) override {}
    void set_status(VertexHandle, const Attr::StatusInfo &) override {}
    void set_next(HalfedgeHandle, HalfedgeHandle) override {}
    void set_face(HalfedgeHandle, FaceHandle) override {}
    void request_face_texcoords2D() override {}
    void set_texcoord(HalfedgeHandle, const Vec2f &) override {}
    void set_texcoord(VertexHandle, const Vec3f &) override {}
    void set_texcoord(HalfedgeHandle, const Vec3f &) override {}
    void set_status(HalfedgeHandle, const Attr::StatusInfo &) override {}
    void set_color(EdgeHandle, const Vec3uc &) override {}
    void set_color(EdgeHandle, const Vec4uc &) override {}
    void set_color(EdgeHandle, const Vec3f &) override {}
    void set_color(EdgeHandle, const Vec4f &) override {}
    void set_status(EdgeHandle, const Attr::StatusInfo &) override {}
    void set_normal(FaceHandle, const Vec3f &) override {}
    void set_normal(FaceHandle, const Vec3d &) override {}
    void set_color(FaceHandle, const Vec3uc &) override {}
    void set_color(FaceHandle, const Vec4uc &) override {}
    void set_color(FaceHandle, const Vec3f &) override {}
    void set_color(FaceHandle, const Vec4f &) override {}
    void set_status(FaceHandle, const Attr::StatusInfo &) override {}
    void add_texture_information(int, std::string) override {}
    size_t n_vertices() const override { return s.V.size() / 3; }
    size_t n_faces() const override { return nface; }
    size_t n_edges() const override { return 0; }

private:
    VertexHandle push(double x, double y, double z)
    {
        s.V.push_back(x);
        s.V.push_back(y);
        s.V.push_back(z);
        return VertexHandle((int)(s.V.size() / 3 - 1));
    }
};

/* OpenMesh reports problems on omerr/omlog (stderr by default); libcommon
 * must not print, so they are captured for the error message instead. */
class OmCapture {
public:
    std::ostringstream msg;
    OmCapture()
    {
        omerr().disconnect(std::cerr);
        omlog().disable();
        omout().disable();
        omerr().connect(msg);
    }
    ~OmCapture()
    {
        omerr().disconnect(msg);
        omerr().connect(std::cerr);
        omlog().enable();
        omout().enable();
    }
    /* first line of what OpenMesh said, trimmed */
    std::string first()
    {
        omerr().flush();
        std::string t = msg.str();
        size_t a = t.find_first_not_of(" \t\r\n");
        if (a == std::string::npos) return "";
        t = t.substr(a);
        size_t e = t.find_first_of("\r\n");
        if (e != std::string::npos) t = t.substr(0, e);
        return t;
    }
};

/* Check a PLY file before OpenMesh sees it: OpenMesh 9 crashes on a
 * property before any element, loops forever on a header without
 * end_header, and reads past the end (growing without bound) when a list
 * count is not what its type allows or fewer values follow than announced.
 * So the header is parsed here, the counts must fit the bytes after it
 * (binary: each element at least its fixed-size properties and list counts;
 * ascii: at least 2 bytes a property), and then the body is walked element
 * by element against the header: ascii, every value a number (integer types:
 * an integer in the type's range), every list count a non-negative integer
 * that fits its declared type and followed by that many values, nothing
 * after the last element; binary, every list count non-negative and its
 * values inside the file, the file ending with the last element. */
namespace {
struct PlyType { const char *name; int size; bool integer, sign; };
const PlyType ply_types[] = {
    {"char", 1, true, true},    {"uchar", 1, true, false},   {"short", 2, true, true},
    {"ushort", 2, true, false}, {"int", 4, true, true},      {"uint", 4, true, false},
    {"float", 4, false, true},  {"double", 8, false, true},  {"int8", 1, true, true},
    {"uint8", 1, true, false},  {"int16", 2, true, true},    {"uint16", 2, true, false},
    {"int32", 4, true, true},   {"uint32", 4, true, false},  {"float32", 4, false, true},
    {"float64", 8, false, true},
};
const PlyType *ply_type(const std::string &t)
{
    for (const PlyType &p : ply_types)
        if (t == p.name) return &p;
    return NULL;
}
struct PlyProp { const PlyType *type, *count; };  /* count: NULL unless a list */
struct PlyElem { std::string name; long count; long minsize; bool x, y, z, list; std::vector<PlyProp> P; };

/* the ascii body as tokens, with line numbers */
struct PlyTokens {
    const std::string &b;
    size_t i;
    long line;
    /* next token in [*s, *e); false at the end of the file */
    bool next(size_t *s, size_t *e)
    {
        while (i < b.size()) {
            unsigned char c = (unsigned char)b[i];
            if (!(c == ' ' || (c >= '\t' && c <= '\r'))) break;
            if (c == '\n') line++;
            i++;
        }
        if (i >= b.size()) return false;
        *s = i;
        while (i < b.size() && b[i] != ' ' && !(b[i] >= '\t' && b[i] <= '\r')) i++;
        *e = i;
        return true;
    }
};

/* an ascii value of type t in b[s, e): 0, or a reason */
const char *ply_ascii_value(const std::string &b, size_t s, size_t e, const PlyType *t, long long *v)
{
    const char *p = b.c_str() + s, *end;
    if (!t->integer) {
        char *q;
        strtod(p, &q);
        return q == b.c_str() + e ? NULL : "a value that is not a number";
    }
    end = b.c_str() + e;
    const char *d = p + (*p == '-' || *p == '+');
    if (d == end) return "a value that is not a number";
    for (const char *c = d; c < end; c++)
        if (*c < '0' || *c > '9') {
            char *q;
            strtod(p, &q);
            return q == end ? "a value of an integer type that is not an integer" : "a value that is not a number";
        }
    errno = 0;
    char *q;
    long long x = strtoll(p, &q, 10);
    int bits = 8 * t->size;
    long long lo = t->sign ? -(1LL << (bits - 1)) : 0, hi = t->sign ? (1LL << (bits - 1)) - 1 : (1LL << bits) - 1;
    if (errno == ERANGE || x < lo || x > hi) return "an integer out of the range of its type";
    *v = x;
    return NULL;
}

/* a binary count of type t at u (file order: big endian or not) */
long long ply_binary_count(const unsigned char *u, const PlyType *t, bool big)
{
    unsigned long long x = 0;
    for (int k = 0; k < t->size; k++) x |= (unsigned long long)u[big ? t->size - 1 - k : k] << (8 * k);
    if (t->sign && (x >> (8 * t->size - 1)) & 1) return (long long)x - (1LL << (8 * t->size));
    return (long long)x;
}
} // namespace

static int ply_check(const std::string &b, const char *path)
{
    std::vector<PlyElem> E;
    size_t at = 0;
    long no = 0;
    bool ascii = false, big = false, ended = false;
    std::string why;
    while (!ended && at < b.size()) {
        size_t nl = b.find('\n', at);
        if (nl == std::string::npos) break;
        if (nl - at > 4096 || at > 1 << 20) { why = "header line too long or header too big"; break; }
        std::string line = b.substr(at, nl - at);
        at = nl + 1;
        no++;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        if (no == 1) {
            if (key != "ply" || !(ls >> std::ws).eof()) { why = "no 'ply' magic"; break; }
            continue;
        }
        if (no == 2) {
            std::string fmt, ver;
            if (key != "format" || !(ls >> fmt >> ver) || ver != "1.0" ||
                (fmt != "ascii" && fmt != "binary_little_endian" && fmt != "binary_big_endian")) {
                why = "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'";
                break;
            }
            ascii = fmt == "ascii";
            big = fmt == "binary_big_endian";
            continue;
        }
        if (key == "comment" || key == "obj_info") continue;
        if (key == "end_header") { ended = true; break; }
        if (key == "element") {
            std::string name, extra;
            long n;
            if (!(ls >> name >> n) || n < 0 || n > MAX_ELEMENTS || (ls >> extra)) {
                why = "bad element line";
                break;
            }
            E.push_back({name, n, 0, false, false, false, false, {}});
            continue;
        }
        if (key == "property") {
            if (E.empty()) { why = "a property before any element"; break; }
            std::string t, name, it, extra;
            if (!(ls >> t)) { why = "bad property line"; break; }
            PlyElem &e = E.back();
            if (t == "list") {
                if (!(ls >> t >> it >> name) || !ply_type(t) || !ply_type(it) || !ply_type(t)->integer ||
                    (ls >> extra)) {
                    why = "bad list property";
                    break;
                }
                e.minsize += ply_type(t)->size;
                e.list = true;
                e.P.push_back({ply_type(it), ply_type(t)});
            } else {
                if (!(ls >> name) || !ply_type(t) || (ls >> extra)) { why = "bad property line"; break; }
                e.minsize += ply_type(t)->size;
                e.P.push_back({ply_type(t), NULL});
            }
            if (name == "x") e.x = true;
            if (name == "y") e.y = true;
            if (name == "z") e.z = true;
            continue;
        }
        why = "unknown header line '" + line.substr(0, 20) + "'";
        break;
    }
    if (why.empty() && !ended) why = "no end_header";
    if (!why.empty())
        return cm_seterr("cannot read '%s': not a valid PLY file (header line %ld: %s)", path, no, why.c_str());
    double need = 0;
    bool vertex = false;
    for (const PlyElem &e : E) {
        if (e.P.empty())
            return cm_seterr("cannot read '%s': not a valid PLY file (element '%s' has no property)", path,
                             e.name.c_str());
        if (e.name == "vertex") {
            vertex = true;
            if (!e.x || !e.y || !e.z)
                return cm_seterr("cannot read '%s': not a valid PLY file (vertex element without x, y, z)", path);
        }
        if (e.name == "face" && e.count > 0 && !e.list)
            return cm_seterr("cannot read '%s': not a valid PLY file (face element without a list)", path);
        need += (double)e.count * (ascii ? 2.0 * (double)e.P.size() : (double)e.minsize);
    }
    if (!vertex)
        return cm_seterr("cannot read '%s': not a valid PLY file (no vertex element)", path);
    if (need > (double)(b.size() - at))
        return cm_seterr("cannot read '%s': truncated: the PLY header announces at least %.0f bytes of data, "
                         "the file has %zu", path, need, b.size() - at);
    if (ascii) {
        PlyTokens tk{b, at, no + 1};
        size_t s, e;
        for (const PlyElem &el : E)
            for (long k = 0; k < el.count; k++)
                for (const PlyProp &p : el.P) {
                    long long n = 1, v;
                    const char *bad;
                    if (p.count) {
                        if (!tk.next(&s, &e)) goto short_ascii;
                        if ((bad = ply_ascii_value(b, s, e, p.count, &v)))
                            return cm_seterr("cannot read '%s': not a valid PLY file (line %ld: %s %ld: "
                                             "list count of type %s: %s)", path, tk.line, el.name.c_str(), k,
                                             p.count->name, bad);
                        if (v < 0)
                            return cm_seterr("cannot read '%s': not a valid PLY file (line %ld: %s %ld: "
                                             "negative list count %lld)", path, tk.line, el.name.c_str(), k, v);
                        n = v;
                    }
                    for (long long j = 0; j < n; j++) {
                        if (!tk.next(&s, &e)) goto short_ascii;
                        if ((bad = ply_ascii_value(b, s, e, p.type, &v)))
                            return cm_seterr("cannot read '%s': not a valid PLY file (line %ld: %s)", path,
                                             tk.line, bad);
                    }
                    continue;
                short_ascii:
                    return cm_seterr("cannot read '%s': truncated: the PLY file ends at line %ld inside %s %ld "
                                     "of %ld", path, tk.line, el.name.c_str(), k, el.count);
                }
        if (tk.next(&s, &e))
            return cm_seterr("cannot read '%s': not a valid PLY file (line %ld: data after the last element)",
                             path, tk.line);
        return 0;
    }
    const unsigned char *u = (const unsigned char *)b.data();
    size_t o = at, len = b.size();
    for (const PlyElem &el : E) {
        if (!el.list) {  /* fixed size: the whole element at once */
            if ((double)el.count * (double)el.minsize > (double)(len - o)) goto short_binary;
            o += (size_t)el.count * (size_t)el.minsize;
            continue;
        }
        for (long k = 0; k < el.count; k++)
            for (const PlyProp &p : el.P) {
                if (!p.count) {
                    if ((size_t)p.type->size > len - o) goto short_binary;
                    o += p.type->size;
                    continue;
                }
                if ((size_t)p.count->size > len - o) goto short_binary;
                long long n = ply_binary_count(u + o, p.count, big);
                if (n < 0)
                    return cm_seterr("cannot read '%s': not a valid PLY file (byte %zu: %s %ld: negative list "
                                     "count %lld)", path, o, el.name.c_str(), k, n);
                o += p.count->size;
                if ((double)n * p.type->size > (double)(len - o))
                    return cm_seterr("cannot read '%s': truncated: the PLY list at byte %zu (%s %ld) announces "
                                     "%lld values, the file has %zu bytes left", path, o - p.count->size,
                                     el.name.c_str(), k, n, len - o);
                o += (size_t)n * p.type->size;
            }
        continue;
    short_binary:
        return cm_seterr("cannot read '%s': truncated: the PLY file ends inside element '%s' (byte %zu)", path,
                         el.name.c_str(), len);
    }
    if (o != len)
        return cm_seterr("cannot read '%s': not a valid PLY file (%zu bytes after the last element, at byte %zu)",
                         path, len - o, o);
    return 0;
}

static int read_openmesh(const char *path, int fmt, struct mesh *m)
{
    std::string buf;
    if (slurp(path, buf, 0) < 0)
        return -1;
    if (fmt == MESHIO_PLY && ply_check(buf, path) < 0)
        return -1;
    if (fmt == MESHIO_STL && buf.size() < 15)
        return cm_seterr("cannot read '%s': not an STL file (too short)", path);
    SoupImporter imp;
    OpenMesh::IO::Options opt;
    bool ok;
    std::string said;
    try {
        OmCapture cap;
        /* read from memory (works for stdin and any extension); OpenMesh
         * is told the format, and for STL whether it is binary: 80-byte
         * header, uint32 count n, then exactly 50 n bytes */
        if (fmt == MESHIO_STL && buf.size() >= 84) {
            const unsigned char *u = (const unsigned char *)buf.data();
            uint32_t n = u[80] | (uint32_t)u[81] << 8 | (uint32_t)u[82] << 16 | (uint32_t)u[83] << 24;
            if (buf.size() == 84 + 50 * (size_t)n)
                opt += OpenMesh::IO::Options::Binary;
        }
        std::istringstream in(buf);
        ok = OpenMesh::IO::IOManager().read(in, fmt == MESHIO_PLY ? "ply" : "stl", imp, opt);
        said = cap.first();
    } catch (const std::bad_alloc &) {
        return cm_seterr("cannot read '%s': out of memory", path);
    } catch (const std::exception &e) {
        return cm_seterr("cannot read '%s': %s", path, e.what());
    }
    if (!ok) {
        if (!said.empty())
            return cm_seterr("cannot read '%s': not a valid %s file (%s)", path,
                             fmt == MESHIO_PLY ? "PLY" : "STL", said.c_str());
        return cm_seterr("cannot read '%s': not a valid %s file", path, fmt == MESHIO_PLY ? "PLY" : "STL");
    }
    if (imp.s.F.empty())
        return cm_seterr("cannot read '%s': not a valid %s file (no faces)", path,
                         fmt == MESHIO_PLY ? "PLY" : "STL");
    return soup_to_mesh(imp.s, path, m);
}

extern "C" int meshio_read(const char *path, int fmt, struct mesh *m)
{
    memset(m, 0, sizeof *m);
    if (fmt == MESHIO_NONE)
        fmt = meshio_format_from_name(path);
    /* a C caller gets no exception: out of memory is an error message */
    try {
        switch (fmt) {
        case MESHIO_OBJ: return read_obj(path, m);
        case MESHIO_OFF: return read_off(path, m);
        case MESHIO_PLY:
        case MESHIO_STL: return read_openmesh(path, fmt, m);
        default:
            return cm_seterr("cannot read '%s': unknown mesh format (expected .obj, .off, .ply or .stl)", path);
        }
    } catch (const std::bad_alloc &) {
        mesh_free(m);
        return cm_seterr("cannot read '%s': out of memory", path);
    }
}

/* ------------------------------------------------------------------ */
/* writing                                                             */

/* Presents a triangle soup to an OpenMesh writer. */
class SoupExporter : public OpenMesh::IO::BaseExporter {
public:
    int nv, nf;
    const int *F;
    const double *X;
    SoupExporter(int nv_, int nf_, const int *F_, const double *X_) : nv(nv_), nf(nf_), F(F_), X(X_) {}
    Vec3d pointd(VertexHandle vh) const override
    {
        const double *p = X + 3 * vh.idx();
        return Vec3d(p[0], p[1], p[2]);
    }
    Vec3f point(VertexHandle vh) const override { return Vec3f(pointd(vh)); }
    bool is_point_double() const override { return true; }
    Vec3f normal(VertexHandle) const override { return Vec3f(0, 0, 0); }
    Vec3d normald(VertexHandle) const override { return Vec3d(0, 0, 0); }
    bool is_normal_double() const override { return true; }
    Vec3uc color(VertexHandle) const override { return Vec3uc(0, 0, 0); }
    Vec4uc colorA(VertexHandle) const override { return Vec4uc(0, 0, 0, 0); }
    Vec3ui colori(VertexHandle) const override { return Vec3ui(0, 0, 0); }
    Vec4ui colorAi(VertexHandle) const override { return Vec4ui(0, 0, 0, 0); }
    Vec3f colorf(VertexHandle) const override { return Vec3f(0, 0, 0); }
    Vec4f colorAf(VertexHandle) const override { return Vec4f(0, 0, 0, 0); }
    Vec2f texcoord(VertexHandle) const override { return Vec2f(0, 0); }
    Vec2f texcoord(HalfedgeHandle) const override { return Vec2f(0, 0); }
    Attr::StatusInfo status(VertexHandle) const override { return Attr::StatusInfo(); }
    unsigned int get_vhandles(FaceHandle fh, std::vector<VertexHandle> &vh) const override
    {
        vh.clear();
        for (int c = 0; c < 3; c++) vh.push_back(VertexHandle(F[3 * fh.idx() + c]));
        return 3;
    }
    HalfedgeHandle getHeh(FaceHandle, VertexHandle) const override { return HalfedgeHandle(); }
    unsigned int get_face_texcoords(std::vector<Vec2f> &) const override { return 0; }
    Vec3d normald(FaceHandle fh) const override
    {
        Vec3d a = pointd(VertexHandle(F[3 * fh.idx()])), b = pointd(VertexHandle(F[3 * fh.idx() + 1])),
              c = pointd(VertexHandle(F[3 * fh.idx() + 2]));
        Vec3d n = OpenMesh::cross(b - a, c - a);
        double l = n.norm();
        return l > 0 ? n / l : Vec3d(0, 0, 0);
    }
    Vec3f normal(FaceHandle fh) const override { return Vec3f(normald(fh)); }
    Vec3uc color(FaceHandle) const override { return Vec3uc(0, 0, 0); }
    Vec4uc colorA(FaceHandle) const override { return Vec4uc(0, 0, 0, 0); }
    Vec3ui colori(FaceHandle) const override { return Vec3ui(0, 0, 0); }
    Vec4ui colorAi(FaceHandle) const override { return Vec4ui(0, 0, 0, 0); }
    Vec3f colorf(FaceHandle) const override { return Vec3f(0, 0, 0); }
    Vec4f colorAf(FaceHandle) const override { return Vec4f(0, 0, 0, 0); }
    Attr::StatusInfo status(FaceHandle) const override { return Attr::StatusInfo(); }
    Vec3uc color(EdgeHandle) const override { return Vec3uc(0, 0, 0); }
    Vec4uc colorA(EdgeHandle) const override { return Vec4uc(0, 0, 0, 0); }
    Vec3ui colori(EdgeHandle) const override { return Vec3ui(0, 0, 0); }
    Vec4ui colorAi(EdgeHandle) const override { return Vec4ui(0, 0, 0, 0); }
    Vec3f colorf(EdgeHandle) const override { return Vec3f(0, 0, 0); }
    Vec4f colorAf(EdgeHandle) const override { return Vec4f(0, 0, 0, 0); }
    Attr::StatusInfo status(EdgeHandle) const override { return Attr::StatusInfo(); }
    int get_halfedge_id(VertexHandle) override { return -1; }
    int get_halfedge_id(FaceHandle) override { return -1; }
    int get_next_halfedge_id(HalfedgeHandle) override { return -1; }
    int get_to_vertex_id(HalfedgeHandle) override { return -1; }
    int get_face_id(HalfedgeHandle) override { return -1; }
    Attr::StatusInfo status(HalfedgeHandle) const override { return Attr::StatusInfo(); }
    size_t n_vertices() const override { return nv; }
    size_t n_faces() const override { return nf; }
    size_t n_edges() const override { return 0; }
    bool is_triangle_mesh() const override { return true; }
    bool has_face_normals() const override { return true; }
    /* OpenMesh's PLY writer looks for custom properties in the kernel and
     * crashes on nullptr: give it an empty mesh, which has none */
    const OpenMesh::BaseKernel *kernel() override { return &empty; }

private:
    OpenMesh::BaseKernel empty;
};

static int put(FILE *f, const char *name, const char *s, size_t n)
{
    if (fwrite(s, 1, n, f) != n)
        return cm_seterr("cannot write '%s': %s", name, strerror(errno));
    return 0;
}

static int write_text(FILE *f, const char *name, int fmt, int nv, int nf, const int *F, const double *X)
{
    std::string out;
    char b[128];
    if (fmt == MESHIO_OFF) {
        snprintf(b, sizeof b, "OFF\n%d %d 0\n", nv, nf);
        out += b;
    }
    for (int i = 0; i < nv; i++) {
        char *q = b;
        if (fmt == MESHIO_OBJ) { *q++ = 'v'; *q++ = ' '; }
        for (int d = 0; d < 3; d++) {
            q += format_double(q, X[3 * i + d]);
            *q++ = d < 2 ? ' ' : '\n';
        }
        out.append(b, q - b);
        if (out.size() > (1 << 20)) {
            if (put(f, name, out.data(), out.size()) < 0) return -1;
            out.clear();
        }
    }
    for (int t = 0; t < nf; t++) {
        const int *v = F + 3 * t;
        if (fmt == MESHIO_OBJ)
            snprintf(b, sizeof b, "f %d %d %d\n", v[0] + 1, v[1] + 1, v[2] + 1);
        else
            snprintf(b, sizeof b, "3 %d %d %d\n", v[0], v[1], v[2]);
        out += b;
        if (out.size() > (1 << 20)) {
            if (put(f, name, out.data(), out.size()) < 0) return -1;
            out.clear();
        }
    }
    return put(f, name, out.data(), out.size());
}

extern "C" int meshio_write(FILE *f, const char *name, int fmt, int flags,
                            int nv, int nf, const int *F, const double *X)
{
    for (long i = 0; i < 3L * nf; i++)
        if (F[i] < 0 || F[i] >= nv)
            return cm_seterr("cannot write '%s': face %ld: vertex index %d out of range", name, i / 3, F[i]);
    if (fmt == MESHIO_OBJ || fmt == MESHIO_OFF)
        return write_text(f, name, fmt, nv, nf, F, X);
    if (fmt != MESHIO_PLY && fmt != MESHIO_STL)
        return cm_seterr("cannot write '%s': unknown mesh format", name);
    SoupExporter ex(nv, nf, F, X);
    OpenMesh::IO::Options opt;
    if (!(flags & MESHIO_ASCII))
        opt += OpenMesh::IO::Options::Binary;
    if (fmt == MESHIO_PLY && !(flags & MESHIO_ASCII))
        opt += OpenMesh::IO::Options::LSB;
    std::ostringstream os;
    bool ok;
    std::string said;
    try {
        OmCapture cap;
        ok = OpenMesh::IO::IOManager().write(os, fmt == MESHIO_PLY ? ".ply" : ".stl", ex, opt, 17);
        said = cap.first();
    } catch (const std::exception &e) {
        return cm_seterr("cannot write '%s': %s", name, e.what());
    }
    if (!ok)
        return cm_seterr("cannot write '%s': OpenMesh %s writer failed%s%s", name,
                         fmt == MESHIO_PLY ? "PLY" : "STL", said.empty() ? "" : ": ", said.c_str());
    std::string s = os.str();
    return put(f, name, s.data(), s.size());
}
