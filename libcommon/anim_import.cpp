// anim_import.cpp -- morph-target animations through assimp; see anim_import.h.
#include "anim_import.h"
#include "cm_error.h"
#include "fbx_weights.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <strings.h>
#include <vector>

extern "C" int anim_format_parse(const char *s)
{
    if (!s) return ANIM_NONE;
    if (!strcasecmp(s, "gltf")) return ANIM_GLTF;
    if (!strcasecmp(s, "glb")) return ANIM_GLB;
    if (!strcasecmp(s, "fbx")) return ANIM_FBX;
    return ANIM_NONE;
}

extern "C" int anim_format_from_name(const char *path)
{
    if (!path) return ANIM_NONE;
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    return dot ? anim_format_parse(dot + 1) : ANIM_NONE;
}

namespace {

/* The format a file's first bytes show: ANIM_GLB (the "glTF" magic),
 * ANIM_GLTF (a JSON object, after an optional UTF-8 byte-order mark and
 * white space), ANIM_FBX (the binary header, or an ASCII FBX file's
 * FBXHeaderExtension in its first 4 KiB); ANIM_NONE otherwise. */
int sniff_format(const char *path)
{
    unsigned char b[4096];
    FILE *f = fopen(path, "rb");
    if (!f) return ANIM_NONE;
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    if (n >= 4 && !memcmp(b, "glTF", 4)) return ANIM_GLB;
    static const char fbx[] = "Kaydara FBX Binary";
    if (n >= sizeof fbx - 1 && !memcmp(b, fbx, sizeof fbx - 1)) return ANIM_FBX;
    size_t i = (n >= 3 && b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF) ? 3 : 0;
    while (i < n && (b[i] == ' ' || b[i] == '\t' || b[i] == '\r' || b[i] == '\n')) i++;
    if (i < n && b[i] == '{') return ANIM_GLTF;
    static const char hdr[] = "FBXHeaderExtension";
    for (size_t j = 0; j + sizeof hdr - 1 <= n; j++)
        if (!memcmp(b + j, hdr, sizeof hdr - 1)) return ANIM_FBX;
    return ANIM_NONE;
}

/* ------------------------------------------------------------------ */
/* A small JSON reader, only to decode glTF weight accessors that     */
/* assimp 5.2 misreads (see the header).                              */

struct JVal {
    enum Type { NUL, BOOL, NUM, STR, ARR, OBJ } t = NUL;
    double num = 0;
    std::string str;
    std::vector<JVal> arr;
    std::vector<std::pair<std::string, JVal>> obj;
    const JVal *get(const char *k) const
    {
        if (t != OBJ) return nullptr;
        for (auto &kv : obj)
            if (kv.first == k) return &kv.second;
        return nullptr;
    }
    const JVal *at(size_t i) const { return t == ARR && i < arr.size() ? &arr[i] : nullptr; }
    /* a JSON number as an index or size: SIZE_MAX unless it is an integer
     * in [0, 2^53] (casting a negative or huge double is undefined) */
    static size_t index(double x) { return x >= 0 && x <= 9007199254740992.0 && x == std::floor(x) ? (size_t)x : SIZE_MAX; }
    size_t size(const char *k, double def) const { return index(number(k, def)); }
    double number(const char *k, double def) const
    {
        const JVal *v = get(k);
        return v && v->t == NUM ? v->num : def;
    }
    /* a glTF enum (componentType and the like): -1 if absent, not a whole
     * number or out of int's range (a cast of 5e50 to int is undefined) */
    int code(const char *k) const
    {
        size_t x = size(k, -1);
        return x <= 1000000000 ? (int)x : -1;
    }
};

struct JParser {
    const char *p, *end;
    int depth = 0;
    bool ws()
    {
        while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) p++;
        return p < end;
    }
    bool lit(const char *s)
    {
        size_t n = strlen(s);
        if ((size_t)(end - p) < n || strncmp(p, s, n)) return false;
        p += n;
        return true;
    }
    bool string(std::string &out)
    {
        if (p >= end || *p != '"') return false;
        p++;
        while (p < end && *p != '"') {
            if (*p == '\\') {
                if (++p >= end) return false;
                char c = *p++;
                switch (c) {
                case 'n': out += '\n'; break;
                case 't': out += '\t'; break;
                case 'r': out += '\r'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'u':             /* names we compare are ASCII: keep a placeholder */
                    if (end - p < 4) return false;
                    p += 4;
                    out += '?';
                    break;
                default: out += c;
                }
            } else {
                out += *p++;
            }
        }
        if (p >= end) return false;
        p++;
        return true;
    }
    bool value(JVal &v)
    {
        if (!ws() || ++depth > 200) return false;
        bool ok = true;
        if (*p == '{') {
            v.t = JVal::OBJ;
            p++;
            if (!ws()) return false;
            if (*p == '}') { p++; depth--; return true; }
            for (;;) {
                std::pair<std::string, JVal> kv;
                if (!ws() || !string(kv.first) || !ws() || *p != ':') return false;
                p++;
                if (!value(kv.second)) return false;
                v.obj.push_back(std::move(kv));
                if (!ws()) return false;
                if (*p == ',') { p++; continue; }
                if (*p == '}') { p++; break; }
                return false;
            }
        } else if (*p == '[') {
            v.t = JVal::ARR;
            p++;
            if (!ws()) return false;
            if (*p == ']') { p++; depth--; return true; }
            for (;;) {
                v.arr.emplace_back();
                if (!value(v.arr.back())) return false;
                if (!ws()) return false;
                if (*p == ',') { p++; continue; }
                if (*p == ']') { p++; break; }
                return false;
            }
        } else if (*p == '"') {
            v.t = JVal::STR;
            ok = string(v.str);
        } else if (lit("true")) {
            v.t = JVal::BOOL; v.num = 1;
        } else if (lit("false")) {
            v.t = JVal::BOOL;
        } else if (lit("null")) {
            v.t = JVal::NUL;
        } else {
            char *e;
            std::string tmp(p, std::min<size_t>(end - p, 64));
            v.t = JVal::NUM;
            v.num = strtod(tmp.c_str(), &e);
            if (e == tmp.c_str()) return false;
            p += e - tmp.c_str();
        }
        depth--;
        return ok;
    }
};

static bool read_file(const std::string &path, std::string &out)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    out = ss.str();
    return true;
}

static uint32_t le32(const unsigned char *b)
{
    return b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static int b64val(int c)
{
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+' || c == '-') return 62;
    if (c == '/' || c == '_') return 63;
    return -1;
}

/* The parts of a glTF file needed to decode weight accessors. */
struct Gltf {
    JVal root;
    std::string bin;                    /* GLB BIN chunk */
    std::string dir;                    /* for external buffers */
    std::map<size_t, std::string> buffers;

    bool load(const std::string &path)
    {
        std::string data;
        if (!read_file(path, data)) return false;
        size_t slash = path.rfind('/');
        dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
        const unsigned char *u = (const unsigned char *)data.data();
        std::string json;
        if (data.size() >= 20 && !memcmp(u, "glTF", 4)) {
            size_t off = 12;
            while (off + 8 <= data.size()) {
                uint32_t len = le32(u + off), type = le32(u + off + 4);
                if (off + 8 + (size_t)len > data.size()) return false;
                if (type == 0x4E4F534A) json = data.substr(off + 8, len);
                else if (type == 0x004E4942) bin = data.substr(off + 8, len);
                off += 8 + ((len + 3) & ~3u);
            }
        } else {
            json = data;
        }
        JParser P{json.data(), json.data() + json.size()};
        return P.value(root) && root.t == JVal::OBJ;
    }

    const std::string *buffer(size_t i)
    {
        auto it = buffers.find(i);
        if (it != buffers.end()) return &it->second;
        const JVal *b = root.get("buffers") ? root.get("buffers")->at(i) : nullptr;
        if (!b) return nullptr;
        const JVal *uri = b->get("uri");
        std::string out;
        if (!uri) {
            if (i != 0 || bin.empty()) return nullptr;
            out = bin;
        } else if (uri->t == JVal::STR && !uri->str.compare(0, 5, "data:")) {
            size_t comma = uri->str.find(',');
            if (comma == std::string::npos) return nullptr;
            unsigned acc = 0;    /* only its low bits matter: unsigned wraps (int overflowed) */
            int nb = 0;
            for (size_t k = comma + 1; k < uri->str.size(); k++) {
                int v = b64val((unsigned char)uri->str[k]);
                if (v < 0) continue;
                acc = acc << 6 | (unsigned)v;
                nb += 6;
                if (nb >= 8) {
                    nb -= 8;
                    out += (char)((acc >> nb) & 0xFF);
                }
            }
        } else if (uri->t == JVal::STR) {
            if (!read_file(dir + uri->str, out)) return nullptr;
        } else {
            return nullptr;
        }
        return &(buffers[i] = out);
    }

    /* Every accessor's elements lie inside its bufferView and every view
     * inside its buffer (sizes checked without overflow; byteStride at least
     * the element size, at most 252).  Checked before assimp sees the file:
     * assimp 5.2 trusts the sizes and reads out of bounds.  false with *bad
     * = the accessor. */
    bool accessors_in_bounds(size_t *bad)
    {
        const JVal *accs = root.get("accessors"), *bvs = root.get("bufferViews");
        for (size_t ai = 0; accs && ai < accs->arr.size(); ai++) {
            const JVal &a = accs->arr[ai];
            *bad = ai;
            const JVal *bvi = a.get("bufferView"), *ty = a.get("type");
            if (!bvi || !ty) continue;
            int ct = a.code("componentType");
            size_t csize = ct == 5126 || ct == 5125 ? 4 : ct == 5122 || ct == 5123 ? 2 : ct == 5120 || ct == 5121 ? 1 : 0;
            const std::string &t = ty->str;
            size_t ncomp = t == "SCALAR" ? 1 : t == "VEC2" ? 2 : t == "VEC3" ? 3 : t == "VEC4" || t == "MAT2" ? 4
                         : t == "MAT3" ? 9 : t == "MAT4" ? 16 : 0;
            if (!csize || !ncomp) continue;             /* assimp refuses these itself */
            size_t elem = csize * ncomp, count = a.size("count", 0);
            const JVal *bv = bvs ? bvs->at(JVal::index(bvi->num)) : nullptr;
            if (!bv || count == SIZE_MAX) return false;
            const std::string *buf = buffer(bv->size("buffer", 0));
            if (!buf) continue;                         /* a missing file: assimp names it */
            size_t bvoff = bv->size("byteOffset", 0), aoff = a.size("byteOffset", 0);
            size_t stride = bv->size("byteStride", 0), len = bv->size("byteLength", 0);
            if (!stride) stride = elem;
            else if (stride < elem || stride > 252) return false;
            if (bvoff > buf->size() || len > buf->size() - bvoff || aoff > len)
                return false;
            if (count && (len - aoff < elem || count - 1 > (len - aoff - elem) / stride))
                return false;
        }
        return true;
    }

    /* Every animation channel has a target with a path and a node, its
     * node and sampler exist, and every sampler names existing input and
     * output accessors (glTF 2.0, 3.11).  Checked before assimp sees the
     * file: assimp 5.2 dereferences a missing target (SIGSEGV, found by
     * fuzz_gltf).  false with *why = "animation A channel C: ...". */
    bool animations_well_formed(std::string *why)
    {
        const JVal *anims = root.get("animations");
        if (!anims) return true;
        size_t nnodes = root.get("nodes") ? root.get("nodes")->arr.size() : 0;
        size_t nacc = root.get("accessors") ? root.get("accessors")->arr.size() : 0;
        char buf[320];
        for (size_t ai = 0; ai < anims->arr.size(); ai++) {
            const JVal &an = anims->arr[ai];
            const JVal *chs = an.get("channels"), *sms = an.get("samplers");
            size_t nsm = sms && sms->t == JVal::ARR ? sms->arr.size() : 0;
            for (size_t si = 0; si < nsm; si++) {
                const JVal &sm = sms->arr[si];
                if (sm.size("input", -1) >= nacc || sm.size("output", -1) >= nacc) {
                    snprintf(buf, sizeof buf, "animation %zu sampler %zu: input or output is not an accessor of the file", ai, si);
                    *why = buf;
                    return false;
                }
                /* glTF 2.0 requires count >= 1; assimp 5.2 divides the
                 * output count by the input count (SIGFPE, found by fuzz_gltf) */
                const JVal &acc = *root.get("accessors");
                if (acc.arr[sm.size("input", -1)].size("count", 0) < 1 || acc.arr[sm.size("output", -1)].size("count", 0) < 1) {
                    snprintf(buf, sizeof buf, "animation %zu sampler %zu: its input or output accessor has no elements "
                                              "(count 0; glTF 2.0 requires at least 1)", ai, si);
                    *why = buf;
                    return false;
                }
            }
            for (size_t ci = 0; chs && chs->t == JVal::ARR && ci < chs->arr.size(); ci++) {
                const JVal &ch = chs->arr[ci];
                const JVal *tg = ch.get("target");
                const char *bad = nullptr;
                if (ch.size("sampler", -1) >= nsm) bad = "its sampler is not one of the animation's (glTF 2.0 requires it)";
                else if (!tg || tg->t != JVal::OBJ) bad = "it has no target (glTF 2.0 requires one)";
                else if (!tg->get("path") || tg->get("path")->t != JVal::STR) bad = "its target has no path (glTF 2.0 requires one)";
                else if (!tg->get("node"))  /* allowed by glTF (for extensions), but assimp 5.2 crashes on it */
                    bad = "its target names no node; stopmo reads the morph weights of a node's mesh (assimp 5.2 crashes on such channels)";
                else if (tg->size("node", -1) >= nnodes) bad = "its target node is not a node of the file";
                if (bad) {
                    snprintf(buf, sizeof buf, "animation %zu channel %zu: %s", ai, ci, bad);
                    *why = buf;
                    return false;
                }
            }
        }
        return true;
    }

    /* Scalar float accessor values (normalized integers decoded);
     * *type gets the componentType.  false if unsupported. */
    bool scalars(size_t ai, std::vector<double> &out, int *type)
    {
        const JVal *accs = root.get("accessors");
        const JVal *a = accs ? accs->at(ai) : nullptr;
        if (!a || a->get("sparse")) return false;
        const JVal *ty = a->get("type");
        if (!ty || ty->str != "SCALAR") return false;
        int ct = a->code("componentType");
        size_t count = a->size("count", 0);
        size_t csize = ct == 5126 ? 4 : ct == 5122 || ct == 5123 ? 2 : ct == 5120 || ct == 5121 ? 1 : 0;
        if (!csize || count > (1u << 30)) return false;
        *type = ct;
        const JVal *bvi = a->get("bufferView");
        if (!bvi) { out.assign(count, 0.0); return true; }
        const JVal *bvs = root.get("bufferViews");
        const JVal *bv = bvs ? bvs->at(JVal::index(bvi->num)) : nullptr;
        if (!bv) return false;
        const std::string *buf = buffer(bv->size("buffer", 0));
        if (!buf) return false;
        /* every size checked without overflow: the view lies in the
         * buffer, the accessor's elements in the view (glTF: stride <= 252) */
        size_t bvoff = bv->size("byteOffset", 0), aoff = a->size("byteOffset", 0);
        size_t stride = bv->size("byteStride", 0), len = bv->size("byteLength", 0);
        if (!stride) stride = csize;
        if (stride < csize || stride > 252 || bvoff > buf->size() || len > buf->size() - bvoff ||
            aoff > len || (count && (len - aoff < csize || count - 1 > (len - aoff - csize) / stride)))
            return false;
        size_t off = bvoff + aoff;
        bool norm = a->get("normalized") && a->get("normalized")->num != 0;
        out.resize(count);
        const unsigned char *u = (const unsigned char *)buf->data() + off;
        for (size_t k = 0; k < count; k++) {
            const unsigned char *e = u + k * stride;
            double v;
            switch (ct) {
            case 5126: { float f; memcpy(&f, e, 4); v = f; break; }
            case 5121: v = e[0]; if (norm) v /= 255.0; break;
            case 5120: v = (int8_t)e[0]; if (norm) v = std::max(v / 127.0, -1.0); break;
            case 5123: v = (uint16_t)(e[0] | e[1] << 8); if (norm) v /= 65535.0; break;
            default: v = (int16_t)(e[0] | e[1] << 8); if (norm) v = std::max(v / 32767.0, -1.0); break;
            }
            out[k] = v;
        }
        return true;
    }
};

/* ------------------------------------------------------------------ */
/* scene helpers                                                       */

static const aiNode *find_node_with_mesh(const aiNode *n, unsigned mesh)
{
    for (unsigned i = 0; i < n->mNumMeshes; i++)
        if (n->mMeshes[i] == mesh) return n;
    for (unsigned c = 0; c < n->mNumChildren; c++)
        if (const aiNode *r = find_node_with_mesh(n->mChildren[c], mesh)) return r;
    return nullptr;
}

static const aiNode *find_node_named(const aiNode *n, const char *name)
{
    if (!strcmp(n->mName.C_Str(), name)) return n;
    for (unsigned c = 0; c < n->mNumChildren; c++)
        if (const aiNode *r = find_node_named(n->mChildren[c], name)) return r;
    return nullptr;
}

static int first_mesh_below(const aiNode *n)
{
    if (n->mNumMeshes) return (int)n->mMeshes[0];
    for (unsigned c = 0; c < n->mNumChildren; c++) {
        int r = first_mesh_below(n->mChildren[c]);
        if (r >= 0) return r;
    }
    return -1;
}

static bool parse_index(const char *s, long *out)
{
    char *e;
    errno = 0;
    long v = strtol(s, &e, 10);
    if (e == s || *e || errno) return false;
    *out = v;
    return true;
}

/* global rest-pose transform of node n (product of the local transforms
 * up to the root) */
static aiMatrix4x4 node_global(const aiNode *n)
{
    aiMatrix4x4 M;
    for (const aiNode *q = n; q; q = q->mParent)
        M = q->mTransformation * M;
    return M;
}

static void copy_name(char *dst, size_t n, const char *src)
{
    size_t l = strlen(src);
    if (l >= n) l = n - 1;
    memcpy(dst, src, l);
    dst[l] = '\0';
}

struct MorphTrack {
    std::vector<double> time;      /* seconds, increasing */
    std::vector<double> w;         /* nkeys by ntargets */
    bool step = false;
};

static void weights_at(const MorphTrack &tr, int nt, double t, std::vector<double> &w)
{
    size_t n = tr.time.size();
    w.assign(nt, 0.0);
    if (n == 0) return;
    if (t <= tr.time[0] || n == 1) {
        std::copy(tr.w.begin(), tr.w.begin() + nt, w.begin());
        return;
    }
    if (t >= tr.time[n - 1]) {
        std::copy(tr.w.begin() + (n - 1) * nt, tr.w.begin() + n * nt, w.begin());
        return;
    }
    size_t i = std::upper_bound(tr.time.begin(), tr.time.end(), t) - tr.time.begin() - 1;
    double u = tr.step ? 0 : (t - tr.time[i]) / (tr.time[i + 1] - tr.time[i]);
    for (int j = 0; j < nt; j++)
        w[j] = (1 - u) * tr.w[i * nt + j] + u * tr.w[(i + 1) * nt + j];
}

} // namespace

extern "C" int anim_import(const char *path, const struct anim_import_opts *opt,
                           struct mesh *m, struct anim_import_info *info)
{
    struct anim_import_opts o0 = {};
    const struct anim_import_opts *o = opt ? opt : &o0;
    struct anim_import_info inf = {};
    inf.anim_index = -1;
    memset(m, 0, sizeof *m);

    FILE *f = fopen(path, "rb");
    if (!f)
        return cm_seterr("cannot read '%s': %s", path, strerror(errno));
    fclose(f);
    int fmt = o->format ? o->format : anim_format_from_name(path);
    /* assimp hands a file whose content its format's importer refuses to
     * any other importer whose signature matches (a ".gltf" starting with
     * "quick3D" went to the Quick3D importer, which asked for 2 TB); so the
     * content must be what the name or --format says before assimp sees it */
    int kind = sniff_format(path);
    if (kind == ANIM_NONE)
        return cm_seterr("cannot read '%s': not a glTF, GLB or FBX file (no glTF magic, "
                         "no JSON object, no FBX header at its start)", path);
    if (fmt != ANIM_NONE && (fmt == ANIM_FBX) != (kind == ANIM_FBX))
        return cm_seterr("cannot read '%s': the file is %s, not %s", path,
                         kind == ANIM_FBX ? "FBX" : "glTF", fmt == ANIM_FBX ? "FBX" : "glTF");
    fmt = kind;

    if (fmt == ANIM_GLTF || fmt == ANIM_GLB) {
        Gltf pre;
        size_t bad;
        /* what our own parse cannot read never reaches assimp: its glTF
         * importers read freed memory on malformed JSON (fuzz_gltf) */
        if (!pre.load(path))
            return cm_seterr("cannot read '%s': not a glTF file (no JSON object%s)", path,
                             fmt == ANIM_GLB ? " in a GLB container" : "");
        const JVal *asset = pre.root.get("asset"), *ver = asset ? asset->get("version") : nullptr;
        if (ver && ver->t == JVal::STR && ver->str.compare(0, 2, "2."))
            return cm_seterr("cannot read '%s': glTF version %s (only glTF 2.x is read)", path, ver->str.c_str());
        if (!pre.accessors_in_bounds(&bad))
            return cm_seterr("cannot read '%s': accessor %zu reaches outside its buffer "
                             "(byteOffset, byteStride, count or byteLength is wrong)", path, bad);
        std::string why;
        if (pre.root.t == JVal::OBJ && !pre.animations_well_formed(&why))
            return cm_seterr("cannot read '%s': %s", path, why.c_str());
    }
    Assimp::Importer imp;
    /* no post-processing that merges or splits vertices: the file's vertex
     * list is kept (glTF is indexed already); triangulate polygons only */
    imp.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene *sc;
    try {
        sc = imp.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType);
    } catch (const std::exception &e) {
        return cm_seterr("cannot read '%s': %s", path, e.what());
    }
    if (!sc) {
        std::string msg = imp.GetErrorString();
        size_t nl = msg.find_first_of("\r\n");
        if (nl != std::string::npos) msg = msg.substr(0, nl);
        return cm_seterr("cannot read '%s': %s", path, msg.empty() ? "assimp could not import it" : msg.c_str());
    }
    if (!sc->mNumMeshes || !sc->mRootNode)
        return cm_seterr("cannot read '%s': no mesh in the file", path);

    /* ---- the mesh ---- */
    int mi = -1;
    if (o->mesh) {
        long idx;
        if (parse_index(o->mesh, &idx)) {
            if (idx < 0 || idx >= (long)sc->mNumMeshes)
                return cm_seterr("cannot read '%s': no mesh %ld (the file has %u)", path, idx, sc->mNumMeshes);
            mi = (int)idx;
        } else {
            for (unsigned i = 0; i < sc->mNumMeshes && mi < 0; i++)
                if (!strcmp(sc->mMeshes[i]->mName.C_Str(), o->mesh)) mi = (int)i;
            if (mi < 0)
                if (const aiNode *n = find_node_named(sc->mRootNode, o->mesh)) mi = first_mesh_below(n);
            if (mi < 0)
                return cm_seterr("cannot read '%s': no mesh or node named '%s'", path, o->mesh);
        }
    } else {
        for (unsigned i = 0; i < sc->mNumMeshes; i++) {
            const aiMesh *a = sc->mMeshes[i];
            if (!(a->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
            inf.morph_meshes += a->mNumAnimMeshes > 0;
            if (mi < 0) { mi = (int)i; continue; }
            const aiMesh *b = sc->mMeshes[mi];
            bool am = a->mNumAnimMeshes > 0, bm = b->mNumAnimMeshes > 0;
            if ((am && !bm) || (am == bm && a->mNumVertices > b->mNumVertices)) mi = (int)i;
        }
        if (mi < 0)
            return cm_seterr("cannot read '%s': no triangle mesh in the file", path);
    }
    const aiMesh *am = sc->mMeshes[mi];
    const aiNode *node = find_node_with_mesh(sc->mRootNode, (unsigned)mi);
    inf.mesh_index = mi;
    {
        const char *nm = am->mName.length ? am->mName.C_Str() : "";
        /* a named parent node says more than "meshes[2]" / "nodes[2]" */
        if (node && node->mParent && node->mParent != sc->mRootNode && node->mParent->mName.length &&
            (!*nm || strchr(nm, '[')))
            nm = node->mParent->mName.C_Str();
        copy_name(inf.mesh_name, sizeof inf.mesh_name, nm);
    }
    int nv = (int)am->mNumVertices, nt = (int)am->mNumAnimMeshes;
    inf.ntargets = nt;
    std::vector<int> F;
    for (unsigned t = 0; t < am->mNumFaces; t++) {
        const aiFace &fc = am->mFaces[t];
        for (unsigned k = 1; k + 1 < fc.mNumIndices; k++) {
            F.push_back((int)fc.mIndices[0]);
            F.push_back((int)fc.mIndices[k]);
            F.push_back((int)fc.mIndices[k + 1]);
        }
    }
    if (nv == 0 || F.empty())
        return cm_seterr("cannot read '%s': mesh %d has no triangles", path, mi);
    for (int v : F)
        if (v < 0 || v >= nv)
            return cm_seterr("cannot read '%s': mesh %d: vertex index %d out of range", path, mi, v);
    for (int i = 0; i < nt; i++)
        if (am->mAnimMeshes[i]->mNumVertices != (unsigned)nv || !am->mAnimMeshes[i]->mVertices)
            return cm_seterr("cannot read '%s': mesh %d: morph target %d has no positions for all vertices",
                             path, mi, i);

    /* ---- merge: the other mesh instances of the scene, placed relative
     * to the chosen mesh's node ---- */
    struct Extra { const aiMesh *mesh; aiMatrix4x4 M; };
    std::vector<Extra> extra;
    int nv_all = nv;
    if (o->merge) {
        aiMatrix4x4 toprim;                       /* identity */
        if (!o->world && node) toprim = node_global(node).Inverse();
        std::vector<const aiNode *> stack{sc->mRootNode};
        while (!stack.empty()) {
            const aiNode *n = stack.back();
            stack.pop_back();
            for (unsigned i = 0; i < n->mNumMeshes; i++) {
                unsigned j = n->mMeshes[i];
                if (j >= sc->mNumMeshes || (n == node && (int)j == mi)) continue;
                const aiMesh *em = sc->mMeshes[j];
                if (!(em->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || !em->mNumVertices) continue;
                extra.push_back({em, toprim * node_global(n)});
                for (unsigned t = 0; t < em->mNumFaces; t++) {
                    const aiFace &fc = em->mFaces[t];
                    for (unsigned k = 0; k < fc.mNumIndices; k++)
                        if (fc.mIndices[k] >= em->mNumVertices)
                            return cm_seterr("cannot read '%s': mesh %u: vertex index %u out of range",
                                             path, j, fc.mIndices[k]);
                    for (unsigned k = 1; k + 1 < fc.mNumIndices; k++) {
                        F.push_back(nv_all + (int)fc.mIndices[0]);
                        F.push_back(nv_all + (int)fc.mIndices[k]);
                        F.push_back(nv_all + (int)fc.mIndices[k + 1]);
                    }
                }
                if ((long)nv_all + em->mNumVertices > 100000000L)
                    return cm_seterr("cannot read '%s': too many vertices to merge", path);
                nv_all += (int)em->mNumVertices;
                inf.merged_morph += em->mNumAnimMeshes > 0;
            }
            for (unsigned c = n->mNumChildren; c-- > 0;) stack.push_back(n->mChildren[c]);
        }
        inf.merged = (int)extra.size();
        inf.merged_nv = nv_all - nv;
    }

    /* ---- the morph animation ---- */
    int want_anim = -1;
    if (o->animation) {
        long idx;
        if (parse_index(o->animation, &idx)) {
            if (idx < 0 || idx >= (long)sc->mNumAnimations)
                return cm_seterr("cannot read '%s': no animation %ld (the file has %u)", path, idx,
                                 sc->mNumAnimations);
            want_anim = (int)idx;
        } else {
            for (unsigned a = 0; a < sc->mNumAnimations; a++)
                if (!strcmp(sc->mAnimations[a]->mName.C_Str(), o->animation)) want_anim = (int)a;
            if (want_anim < 0)
                return cm_seterr("cannot read '%s': no animation named '%s'", path, o->animation);
        }
    }
    /* every animation that drives the mesh's weights (or the one asked
     * for) is a clip */
    struct Clip { const aiAnimation *anim; const aiMeshMorphAnim *ch; int index; };
    std::vector<Clip> clips;
    if (nt > 0) {
        for (unsigned a = 0; a < sc->mNumAnimations; a++) {
            if (want_anim >= 0 && (int)a != want_anim) continue;
            const aiAnimation *an = sc->mAnimations[a];
            for (unsigned c = 0; c < an->mNumMorphMeshChannels; c++) {
                const aiMeshMorphAnim *ch = an->mMorphMeshChannels[c];
                const char *cn = ch->mName.C_Str();
                /* assimp names the channel after the node (glTF) or mesh;
                 * FBX appends "*<n>" */
                bool match = (node && !strncmp(cn, node->mName.C_Str(), node->mName.length) &&
                              (cn[node->mName.length] == '\0' || cn[node->mName.length] == '*')) ||
                             !strcmp(cn, am->mName.C_Str());
                if (match) { clips.push_back({an, ch, (int)a}); break; }
            }
        }
        if (clips.empty()) {     /* a single morph channel in the whole file: take it */
            for (unsigned a = 0; a < sc->mNumAnimations; a++) {
                if (want_anim >= 0 && (int)a != want_anim) continue;
                for (unsigned c = 0; c < sc->mAnimations[a]->mNumMorphMeshChannels; c++)
                    clips.push_back({sc->mAnimations[a], sc->mAnimations[a]->mMorphMeshChannels[c], (int)a});
            }
            if (clips.size() != 1) clips.clear();
        }
    }
    if (want_anim >= 0 && clips.empty())
        return cm_seterr("cannot read '%s': animation %d does not drive the morph weights of mesh %d",
                         path, want_anim, mi);

    std::vector<MorphTrack> tracks(clips.size());
    std::unique_ptr<Gltf> gl;
    for (size_t ci = 0; ci < clips.size(); ci++) {
        const aiAnimation *anim = clips[ci].anim;
        const aiMeshMorphAnim *mc = clips[ci].ch;
        MorphTrack &tr = tracks[ci];
        if (ci == 0) {
            inf.anim_index = clips[0].index;
            copy_name(inf.anim_name, sizeof inf.anim_name, anim->mName.C_Str());
        }
        double tps = anim->mTicksPerSecond > 0 ? anim->mTicksPerSecond : 25;
        int nk = (int)mc->mNumKeys;
        tr.time.resize(nk);
        tr.w.assign((size_t)nk * nt, 0.0);
        for (int k = 0; k < nk; k++) {
            const aiMeshMorphKey &K = mc->mKeys[k];
            tr.time[k] = K.mTime / tps;
            if (k > 0 && !(tr.time[k] > tr.time[k - 1]))
                return cm_seterr("cannot read '%s': morph key times not increasing at key %d", path, k);
            for (unsigned q = 0; q < K.mNumValuesAndWeights; q++)
                if (K.mValues[q] < (unsigned)nt) tr.w[(size_t)k * nt + K.mValues[q]] = K.mWeights[q];
        }
        /* glTF: the interpolation, and non-float weight accessors decoded
         * ourselves */
        if ((fmt == ANIM_GLTF || fmt == ANIM_GLB) && nk > 0) {
            if (!gl) {
                gl.reset(new Gltf);
                if (!gl->load(path)) gl->root = JVal();
            }
            Gltf &g = *gl;
            const JVal *anims = g.root.get("animations");
            const JVal *ga = anims ? anims->at((size_t)clips[ci].index) : nullptr;
            const JVal *chs = ga ? ga->get("channels") : nullptr;
            const JVal *nodes = g.root.get("nodes");
            for (size_t c = 0; chs && c < chs->arr.size(); c++) {
                const JVal &ch = chs->arr[c];
                const JVal *tg = ch.get("target");
                if (!tg || !tg->get("path") || tg->get("path")->str != "weights" || !tg->get("node"))
                    continue;
                size_t ni = JVal::index(tg->get("node")->num);
                const JVal *nd = nodes ? nodes->at(ni) : nullptr;
                std::string nname = nd && nd->get("name") ? nd->get("name")->str
                                                          : "nodes[" + std::to_string(ni) + "]";
                if (nname != mc->mName.C_Str()) continue;
                const JVal *sm = ga->get("samplers") ? ga->get("samplers")->at(ch.size("sampler", -1))
                                                     : nullptr;
                if (!sm) break;
                const JVal *ip = sm->get("interpolation");
                std::string interp = ip ? ip->str : "LINEAR";
                tr.step = interp == "STEP";
                std::vector<double> vals;
                int ct = 0;
                if (!g.scalars(sm->size("output", -1), vals, &ct) || ct == 5126)
                    break;      /* float weights: assimp's are right */
                size_t per = interp == "CUBICSPLINE" ? 3 : 1;
                if (vals.size() != (size_t)nk * nt * per)
                    return cm_seterr("cannot read '%s': weight accessor has %zu values, expected %zu",
                                     path, vals.size(), (size_t)nk * nt * per);
                for (int k = 0; k < nk; k++)
                    for (int j = 0; j < nt; j++)
                        tr.w[(size_t)k * nt + j] = vals[((size_t)k * per + (per == 3 ? 1 : 0)) * nt + j];
                inf.decoded_weights = 1;
                break;
            }
        }
        for (double w : tr.w)
            if (!std::isfinite(w))
                return cm_seterr("cannot read '%s': morph weight is not finite", path);
        inf.nkeys += nk;
        inf.duration += nk ? tr.time[nk - 1] : 0;
    }
    inf.nclips = (int)clips.size();

    /* FBX: the weights from the file itself (fbx_weights.h), so that a
     * channel without a curve keeps its static DeformPercent; used when
     * every morph target is one of the model's channels */
    if (fmt == ANIM_FBX && nt > 0) {
        struct fbx_weights fw;
        int rc = fbx_read_weights(path, node ? node->mName.C_Str() : nullptr, &fw);
        if (rc < 0) return -1;
        std::vector<int> chan(nt, -1);
        bool all = rc == 0 && fw.nclips > 0;
        for (int i = 0; all && i < nt; i++) {
            for (int c = 0; c < fw.nchannels && chan[i] < 0; c++)
                if (!strcmp(fw.names[c], am->mAnimMeshes[i]->mName.C_Str())) chan[i] = c;
            all = chan[i] >= 0;
        }
        int pick = -1;      /* --animation: the stack of that name, else that index */
        if (all && want_anim >= 0) {
            for (int c = 0; c < fw.nclips && pick < 0; c++)
                if (!strcmp(fw.clips[c].name, sc->mAnimations[want_anim]->mName.C_Str())) pick = c;
            if (pick < 0) pick = want_anim < fw.nclips ? want_anim : -1;
            all = pick >= 0;
        }
        if (all) {
            tracks.clear();
            inf.nkeys = 0;
            inf.duration = 0;
            inf.nclips = 0;
            for (int c = 0; c < fw.nclips; c++) {
                if (pick >= 0 && c != pick) continue;
                const struct fbx_clip &cl = fw.clips[c];
                MorphTrack tr;
                tr.time.assign(cl.t, cl.t + cl.nkeys);
                tr.w.resize((size_t)cl.nkeys * nt);
                for (int k = 0; k < cl.nkeys; k++)
                    for (int i = 0; i < nt; i++)
                        tr.w[(size_t)k * nt + i] = cl.w[(size_t)k * fw.nchannels + chan[i]];
                if (inf.nclips == 0) copy_name(inf.anim_name, sizeof inf.anim_name, cl.name);
                inf.nkeys += cl.nkeys;
                inf.duration += cl.t[cl.nkeys - 1];
                inf.nclips++;
                tracks.push_back(std::move(tr));
            }
            inf.fbx_weights = 1;
        }
        fbx_weights_free(&fw);
    }

    /* ---- sample times: (clip, t) pairs ---- */
    std::vector<std::pair<int, double>> times;
    if (tracks.empty()) times.push_back({-1, 0.0});
    for (size_t ci = 0; ci < tracks.size(); ci++) {
        const MorphTrack &tr = tracks[ci];
        if (tr.time.empty()) {
            times.push_back({(int)ci, 0.0});
        } else if (o->fps > 0) {
            double last = tr.time.back();
            long n = (long)std::floor(last * o->fps + 1e-9) + 1;
            if (n + (long)times.size() > 10000000)
                return cm_seterr("cannot read '%s': %ld frames at %g fps is too many", path, n, o->fps);
            for (long k = 0; k < n; k++) times.push_back({(int)ci, k / o->fps});
        } else {
            for (double t : tr.time) times.push_back({(int)ci, t});
        }
    }

    if (mesh_alloc(m, nv_all, (int)(F.size() / 3), (int)times.size()) < 0)
        return -1;
    memcpy(m->F, F.data(), F.size() * sizeof(int));
    std::vector<double> w, D((size_t)nt * nv * 3);
    for (int i = 0; i < nt; i++)
        for (int v = 0; v < nv; v++) {
            const aiVector3D &T = am->mAnimMeshes[i]->mVertices[v], &B = am->mVertices[v];
            D[((size_t)i * nv + v) * 3 + 0] = (double)T.x - B.x;
            D[((size_t)i * nv + v) * 3 + 1] = (double)T.y - B.y;
            D[((size_t)i * nv + v) * 3 + 2] = (double)T.z - B.z;
        }
    for (size_t k = 0; k < times.size(); k++) {
        double *X = mesh_frame(m, (int)k);
        for (int v = 0; v < nv; v++) {
            X[3 * v] = am->mVertices[v].x;
            X[3 * v + 1] = am->mVertices[v].y;
            X[3 * v + 2] = am->mVertices[v].z;
        }
        if (times[k].first >= 0) {
            m->cut[k] = k > 0 && times[k].first != times[k - 1].first;
            weights_at(tracks[times[k].first], nt, times[k].second, w);
            for (int i = 0; i < nt; i++) {
                if (w[i] == 0) continue;
                const double *Di = D.data() + (size_t)i * nv * 3;
                for (int c = 0; c < 3 * nv; c++) X[c] += w[i] * Di[c];
            }
        }
        if (o->world && node) {
            aiMatrix4x4 M = node_global(node);
            for (int v = 0; v < nv; v++) {
                double x = X[3 * v], y = X[3 * v + 1], z = X[3 * v + 2];
                X[3 * v] = M.a1 * x + M.a2 * y + M.a3 * z + M.a4;
                X[3 * v + 1] = M.b1 * x + M.b2 * y + M.b3 * z + M.b4;
                X[3 * v + 2] = M.c1 * x + M.c2 * y + M.c3 * z + M.c4;
            }
        }
        double *Y = X + 3 * (size_t)nv;
        for (const Extra &e : extra)
            for (unsigned v = 0; v < e.mesh->mNumVertices; v++, Y += 3) {
                const aiVector3D &p = e.mesh->mVertices[v];
                const aiMatrix4x4 &M = e.M;
                Y[0] = M.a1 * p.x + M.a2 * p.y + M.a3 * p.z + M.a4;
                Y[1] = M.b1 * p.x + M.b2 * p.y + M.b3 * p.z + M.b4;
                Y[2] = M.c1 * p.x + M.c2 * p.y + M.c3 * p.z + M.c4;
            }
        for (int c = 0; c < 3 * nv_all; c++)
            if (!std::isfinite(X[c])) {
                mesh_free(m);
                return cm_seterr("cannot read '%s': non-finite position in frame %zu", path, k);
            }
    }
    if (info) *info = inf;
    return 0;
}
