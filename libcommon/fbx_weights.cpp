// fbx_weights.cpp -- blend-shape weights from binary FBX; see fbx_weights.h.
#include "fbx_weights.h"
#include "cm_error.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

const double TICKS_PER_SECOND = 46186158000.0;

struct Prop {
    char type = 0;
    int64_t i = 0;
    double d = 0;
    std::string s;
    std::vector<double> darr;     /* f, d arrays */
    std::vector<int64_t> iarr;    /* l, i, b arrays */
};

struct Node {
    std::string name;
    std::vector<Prop> props;
    std::vector<Node> kids;
    const Node *child(const char *n) const
    {
        for (const Node &k : kids)
            if (k.name == n) return &k;
        return nullptr;
    }
};

/* the node names whose arrays we need; other arrays are skipped unread */
static bool wanted_arrays(const std::string &n)
{
    return n == "KeyTime" || n == "KeyValueFloat" || n == "KeyAttrFlags" || n == "KeyAttrRefCount";
}

struct Reader {
    const unsigned char *b;
    size_t n;
    bool wide;            /* version >= 7500: 64-bit record header fields */
    std::string err;

    uint64_t u(size_t at, int bytes) const
    {
        uint64_t v = 0;
        for (int k = bytes - 1; k >= 0; k--) v = v << 8 | b[at + k];
        return v;
    }

    bool fail(const char *what, size_t at)
    {
        if (err.empty()) {
            std::ostringstream s;
            s << what << " at byte " << at;
            err = s.str();
        }
        return false;
    }

    bool prop(size_t &o, size_t end, Prop &p, bool arrays)
    {
        if (o >= end) return fail("truncated property", o);
        p.type = (char)b[o++];
        size_t need;
        switch (p.type) {
        case 'Y': need = 2; break;
        case 'C': need = 1; break;
        case 'I': case 'F': need = 4; break;
        case 'D': case 'L': need = 8; break;
        case 'S': case 'R':
            if (end - o < 4) return fail("truncated string", o);
            need = 4 + u(o, 4);
            break;
        case 'f': case 'd': case 'l': case 'i': case 'b':
            if (end - o < 12) return fail("truncated array", o);
            need = 12 + u(o + 8, 4);
            break;
        default:
            return fail("unknown property type", o - 1);
        }
        if (end - o < need) return fail("truncated property", o);
        switch (p.type) {
        case 'Y': p.i = (int16_t)u(o, 2); break;
        case 'C': p.i = b[o]; break;
        case 'I': p.i = (int32_t)u(o, 4); break;
        case 'L': p.i = (int64_t)u(o, 8); break;
        case 'F': { uint32_t x = (uint32_t)u(o, 4); float f; memcpy(&f, &x, 4); p.d = f; break; }
        case 'D': { uint64_t x = u(o, 8); memcpy(&p.d, &x, 8); break; }
        case 'S': case 'R': p.s.assign((const char *)b + o + 4, need - 4); break;
        default:
            if (arrays && !array(o, p)) return false;
        }
        o += need;
        return true;
    }

    bool array(size_t o, Prop &p)
    {
        uint64_t count = u(o, 4), enc = u(o + 4, 4), clen = u(o + 8, 4);
        size_t es = p.type == 'd' || p.type == 'l' ? 8 : p.type == 'b' ? 1 : 4;
        if (count > (1u << 28)) return fail("array too long", o);
        std::vector<unsigned char> raw(count * es);
        if (enc == 0) {
            if (clen != raw.size()) return fail("array length mismatch", o);
            if (!raw.empty()) memcpy(raw.data(), b + o + 12, raw.size());
        } else if (enc == 1) {
            uLongf len = (uLongf)raw.size();
            if (uncompress(raw.data(), &len, b + o + 12, (uLong)clen) != Z_OK || len != raw.size())
                return fail("damaged compressed array", o);
        } else {
            return fail("unknown array encoding", o);
        }
        for (size_t k = 0; k < count; k++) {
            const unsigned char *e = raw.data() + k * es;
            uint64_t x = 0;
            for (int j = (int)es - 1; j >= 0; j--) x = x << 8 | e[j];
            if (p.type == 'f') { uint32_t y = (uint32_t)x; float f; memcpy(&f, &y, 4); p.darr.push_back(f); }
            else if (p.type == 'd') { double d; memcpy(&d, &x, 8); p.darr.push_back(d); }
            else if (p.type == 'l') p.iarr.push_back((int64_t)x);
            else if (p.type == 'i') p.iarr.push_back((int32_t)x);
            else p.iarr.push_back(e[0]);
        }
        return true;
    }

    /* one node record at o; returns false on error; *null for the null record */
    bool node(size_t &o, size_t limit, Node &nd, bool *null, int depth)
    {
        size_t hs = wide ? 25 : 13;
        if (depth > 64) return fail("nesting too deep", o);
        if (limit - o < hs) return fail("truncated record", o);
        uint64_t end = u(o, wide ? 8 : 4), np = u(o + (wide ? 8 : 4), wide ? 8 : 4),
                 pl = u(o + (wide ? 16 : 8), wide ? 8 : 4);
        size_t nl = b[o + hs - 1];
        if (end == 0 && np == 0 && pl == 0 && nl == 0) {
            *null = true;
            o += hs;
            return true;
        }
        *null = false;
        if (end > limit || end < o + hs + nl + pl) return fail("bad record length", o);
        nd.name.assign((const char *)b + o + hs, nl);
        size_t p = o + hs + nl, pend = p + pl;
        bool arrays = wanted_arrays(nd.name);
        for (uint64_t k = 0; k < np; k++) {
            nd.props.emplace_back();
            if (!prop(p, pend, nd.props.back(), arrays)) return false;
        }
        p = pend;
        while (p < end) {
            Node kid;
            bool nul;
            if (!node(p, end, kid, &nul, depth + 1)) return false;
            if (nul) break;
            nd.kids.push_back(std::move(kid));
        }
        o = end;
        return true;
    }
};

/* "Name\0\1Class" -> "Name" */
static std::string object_name(const Prop &p)
{
    size_t z = p.s.find('\0');
    return z == std::string::npos ? p.s : p.s.substr(0, z);
}

struct Obj {
    const Node *node;
    std::string kind, name, sub;
};

struct Curve {
    std::vector<int64_t> t;
    std::vector<double> v;
    std::vector<char> constant;    /* per key: hold until the next key */
    double at(int64_t T) const
    {
        size_t n = t.size();
        if (T <= t[0]) return v[0];
        if (T >= t[n - 1]) return v[n - 1];
        size_t j = std::upper_bound(t.begin(), t.end(), T) - t.begin() - 1;
        if (constant[j]) return v[j];
        double u = (double)(T - t[j]) / (double)(t[j + 1] - t[j]);
        return (1 - u) * v[j] + u * v[j + 1];
    }
};

static bool read_curve(const Node *n, Curve &c)
{
    const Node *kt = n->child("KeyTime"), *kv = n->child("KeyValueFloat");
    if (!kt || !kv || kt->props.empty() || kv->props.empty()) return false;
    c.t = kt->props[0].iarr;
    c.v = kv->props[0].darr;
    if (c.t.empty() || c.t.size() != c.v.size()) return false;
    for (size_t k = 1; k < c.t.size(); k++)
        if (c.t[k] <= c.t[k - 1]) return false;
    c.constant.assign(c.t.size(), 0);
    const Node *fl = n->child("KeyAttrFlags"), *rc = n->child("KeyAttrRefCount");
    if (fl && rc && !fl->props.empty() && !rc->props.empty()) {
        size_t k = 0;
        const std::vector<int64_t> &F = fl->props[0].iarr, &R = rc->props[0].iarr;
        for (size_t a = 0; a < F.size() && a < R.size(); a++)
            for (int64_t r = 0; r < R[a] && k < c.t.size(); r++) c.constant[k++] = (F[a] & 0x2) != 0;
    }
    return true;
}

static void copy_name(char *dst, size_t n, const std::string &s)
{
    size_t l = std::min(s.size(), n - 1);
    memcpy(dst, s.data(), l);
    dst[l] = '\0';
}

} // namespace

extern "C" void fbx_weights_free(struct fbx_weights *w)
{
    if (!w) return;
    for (int c = 0; c < w->nclips; c++) {
        free(w->clips[c].t);
        free(w->clips[c].w);
    }
    free(w->clips);
    free(w->names);
    free(w->rest);
    memset(w, 0, sizeof *w);
}

extern "C" int fbx_read_weights(const char *path, const char *model, struct fbx_weights *out)
{
    memset(out, 0, sizeof *out);
    std::ifstream in(path, std::ios::binary);
    if (!in) return cm_seterr("cannot read '%s': %s", path, strerror(errno));
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    static const char magic[] = "Kaydara FBX Binary  ";
    if (data.size() < 27 || memcmp(data.data(), magic, 20) != 0) return 1;     /* ASCII FBX */
    Reader R{(const unsigned char *)data.data(), data.size(), false, ""};
    uint32_t version = (uint32_t)R.u(23, 4);
    R.wide = version >= 7500;
    std::vector<Node> top;
    for (size_t o = 27; o < R.n;) {
        Node nd;
        bool nul;
        if (!R.node(o, R.n, nd, &nul, 0))
            return cm_seterr("cannot read '%s': FBX: %s", path, R.err.c_str());
        if (nul) break;
        if (nd.name == "Objects" || nd.name == "Connections") top.push_back(std::move(nd));
    }

    /* objects by id, in file order */
    std::map<int64_t, Obj> objs;
    std::vector<int64_t> order;
    struct Conn { std::string type, prop; int64_t child, parent; };
    std::vector<Conn> conns;
    for (const Node &t : top) {
        for (const Node &k : t.kids) {
            if (t.name == "Objects" && k.props.size() >= 3 && k.props[0].type == 'L') {
                Obj ob{&k, k.name, object_name(k.props[1]), k.props[2].s};
                objs[k.props[0].i] = ob;
                order.push_back(k.props[0].i);
            } else if (t.name == "Connections" && k.name == "C" && k.props.size() >= 3 &&
                       k.props[1].type == 'L' && k.props[2].type == 'L') {
                Conn c{k.props[0].s, k.props.size() > 3 ? k.props[3].s : "", k.props[1].i, k.props[2].i};
                conns.push_back(c);
            }
        }
    }
    auto is = [&](int64_t id, const char *kind, const char *sub) {
        auto it = objs.find(id);
        return it != objs.end() && it->second.kind == kind && (!sub || it->second.sub == sub);
    };
    auto children = [&](int64_t parent, const char *kind, const char *sub) {
        std::vector<int64_t> r;
        for (const Conn &c : conns)
            if (c.type == "OO" && c.parent == parent && is(c.child, kind, sub)) r.push_back(c.child);
        return r;
    };

    /* channels of every model, the one asked for first */
    std::vector<int64_t> models;
    for (int64_t id : order)
        if (is(id, "Model", nullptr) && (!model || objs[id].name == model)) models.push_back(id);
    std::vector<int64_t> chan;
    for (int64_t m : models) {
        std::vector<int64_t> ch;
        for (int64_t g : children(m, "Geometry", "Mesh"))
            for (int64_t bs : children(g, "Deformer", "BlendShape"))
                for (int64_t c : children(bs, "Deformer", "BlendShapeChannel")) ch.push_back(c);
        if (!ch.empty()) {
            if (!chan.empty()) return 1;      /* several models with blend shapes: not ours to guess */
            chan = ch;
        }
    }
    if (chan.empty()) return 1;

    int C = (int)chan.size();
    out->nchannels = C;
    out->names = (char (*)[128])calloc((size_t)C, sizeof *out->names);
    out->rest = (double *)calloc((size_t)C, sizeof *out->rest);
    if (!out->names || !out->rest) { fbx_weights_free(out); return cm_seterr("out of memory"); }
    std::map<int64_t, int> chan_index;
    for (int c = 0; c < C; c++) {
        const Obj &ob = objs[chan[c]];
        std::vector<int64_t> shapes = children(chan[c], "Geometry", "Shape");
        copy_name(out->names[c], sizeof out->names[c], shapes.empty() ? ob.name : objs[shapes[0]].name);
        const Node *dp = ob.node->child("DeformPercent");
        out->rest[c] = dp && !dp->props.empty() ? (dp->props[0].type == 'D' || dp->props[0].type == 'F'
                                                       ? dp->props[0].d : (double)dp->props[0].i) / 100.0
                                                : 0.0;
        chan_index[chan[c]] = c;
    }

    /* curves: curve -OP d|DeformPercent-> curve node -OP DeformPercent-> channel;
     * curve node -OO-> layer -OO-> stack */
    std::map<int64_t, std::vector<std::pair<int, Curve>>> by_stack;
    for (const Conn &cn : conns) {
        if (cn.type != "OP" || cn.prop != "DeformPercent" || !chan_index.count(cn.parent) ||
            !is(cn.child, "AnimationCurveNode", nullptr))
            continue;
        int c = chan_index[cn.parent];
        int64_t node = cn.child;
        const Node *curve = nullptr;
        for (const Conn &k : conns)
            if (k.type == "OP" && k.parent == node && !k.prop.compare(0, 15, "d|DeformPercent") &&
                is(k.child, "AnimationCurve", nullptr))
                curve = objs[k.child].node;
        Curve cv;
        if (!curve || !read_curve(curve, cv)) continue;
        for (const Conn &l : conns) {
            if (l.type != "OO" || l.child != node || !is(l.parent, "AnimationLayer", nullptr)) continue;
            for (const Conn &s : conns)
                if (s.type == "OO" && s.child == l.parent && is(s.parent, "AnimationStack", nullptr))
                    by_stack[s.parent].push_back({c, cv});
        }
    }
    std::vector<int64_t> stacks;
    for (int64_t id : order)
        if (by_stack.count(id)) stacks.push_back(id);
    out->clips = (struct fbx_clip *)calloc(stacks.size() + 1, sizeof *out->clips);
    if (!out->clips) { fbx_weights_free(out); return cm_seterr("out of memory"); }
    for (int64_t st : stacks) {
        const auto &curves = by_stack[st];
        std::vector<int64_t> T;
        for (const auto &pc : curves) T.insert(T.end(), pc.second.t.begin(), pc.second.t.end());
        std::sort(T.begin(), T.end());
        T.erase(std::unique(T.begin(), T.end()), T.end());
        struct fbx_clip &cl = out->clips[out->nclips++];
        copy_name(cl.name, sizeof cl.name, objs[st].name);
        cl.nkeys = (int)T.size();
        cl.t = (double *)malloc(T.size() * sizeof *cl.t);
        cl.w = (double *)malloc(T.size() * C * sizeof *cl.w);
        if (!cl.t || !cl.w) { fbx_weights_free(out); return cm_seterr("out of memory"); }
        for (size_t k = 0; k < T.size(); k++) {
            cl.t[k] = (double)T[k] / TICKS_PER_SECOND;
            for (int c = 0; c < C; c++) cl.w[k * C + c] = out->rest[c];
            for (const auto &pc : curves) cl.w[k * C + pc.first] = pc.second.at(T[k]) / 100.0;
        }
    }
    return 0;
}
