/* raster.c -- see raster.h */
#include "raster.h"
#include "cm_error.h"
#include "geometry.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int camera_named_view(const char *name, double *azimuth, double *elevation)
{
    static const struct { const char *name; double az, el; } views[] = {
        {"front", 0, 0}, {"back", 180, 0}, {"right", 90, 0}, {"left", -90, 0},
        {"top", 0, 90}, {"bottom", 0, -90},
        {"iso", 45, 35.26438968275466},   /* asin(1/sqrt(3)): the cube diagonal */
    };
    for (size_t i = 0; i < sizeof views / sizeof views[0]; i++)
        if (!strcmp(name, views[i].name)) {
            *azimuth = views[i].az;
            *elevation = views[i].el;
            return 0;
        }
    return -1;
}

void camera_init(struct camera *c, double azimuth, double elevation, int up)
{
    memset(c, 0, sizeof *c);
    c->azimuth = azimuth;
    c->elevation = elevation;
    c->up = up;
    c->fov = 30;
    c->margin = 0.04;
    double a = azimuth * M_PI / 180, e = elevation * M_PI / 180;
    /* camera frame in the y-up frame */
    double d[3] = {cos(e) * sin(a), sin(e), cos(e) * cos(a)};
    double r[3] = {cos(a), 0, -sin(a)};
    double u[3];
    cross3(d, r, u);
    /* y-up frame from world: P (rows) maps world coordinates to it */
    double P[9];
    memset(P, 0, sizeof P);
    switch (up) {
    case 0: P[1] = -1; P[3] = 1; P[8] = 1; break;    /* +x: x' = -y, y' = x, z' = z */
    case 2: P[0] = 1; P[5] = 1; P[7] = -1; break;    /* +z: x' = x, y' = z, z' = -y */
    case 3: P[1] = 1; P[3] = -1; P[8] = 1; break;    /* -x: x' = y, y' = -x, z' = z */
    case 4: P[0] = 1; P[4] = -1; P[8] = -1; break;   /* -y: x' = x, y' = -y, z' = -z */
    case 5: P[0] = 1; P[5] = -1; P[7] = 1; break;    /* -z: x' = x, y' = -z, z' = y */
    default: P[0] = P[4] = P[8] = 1; break;          /* +y */
    }
    const double *M[3] = {r, u, d};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c->R[3 * i + j] = M[i][0] * P[j] + M[i][1] * P[3 + j] + M[i][2] * P[6 + j];
    camera_reset(c);
}

void camera_fit(struct camera *c, const double *V, int nv)
{
    const double *R = c->R;
    for (int i = 0; i < nv; i++) {
        const double *p = V + 3 * i;
        for (int k = 0; k < 3; k++) {
            double q = R[3 * k] * p[0] + R[3 * k + 1] * p[1] + R[3 * k + 2] * p[2];
            if (q < c->lo[k]) c->lo[k] = q;
            if (q > c->hi[k]) c->hi[k] = q;
        }
    }
    c->fitted += nv;
}

void camera_reset(struct camera *c)
{
    for (int k = 0; k < 3; k++) {
        c->lo[k] = DBL_MAX;
        c->hi[k] = -DBL_MAX;
    }
    c->fitted = 0;
}

void camera_fit_box(struct camera *c, const double lo[3], const double hi[3])
{
    for (int k = 0; k < 3; k++) {
        if (lo[k] < c->lo[k]) c->lo[k] = lo[k];
        if (hi[k] > c->hi[k]) c->hi[k] = hi[k];
    }
    c->fitted += 2;
}

void render_style_default(struct render_style *s)
{
    memset(s, 0, sizeof *s);
    s->color[0] = 214; s->color[1] = 186; s->color[2] = 150;    /* clay */
    s->background[0] = s->background[1] = s->background[2] = 255;
    s->ambient = 0.25;
    s->back_dim = 0.55;
    s->wire_rgb[0] = s->wire_rgb[1] = s->wire_rgb[2] = 40;
    s->wire_width = 1;
    s->ss = 2;
}

/* the screen-space projection of one render */
struct proj {
    int persp;
    double R[9], cx, cy, scale, eye, W2, H2;
};

static void project(const struct proj *p, const double *v, float *out)
{
    const double *R = p->R;
    double x = R[0] * v[0] + R[1] * v[1] + R[2] * v[2];
    double y = R[3] * v[0] + R[4] * v[1] + R[5] * v[2];
    double z = R[6] * v[0] + R[7] * v[1] + R[8] * v[2];
    if (p->persp) {
        double dz = p->eye - z, f = p->scale / dz;
        out[0] = (float)(p->W2 + f * (x - p->cx));
        out[1] = (float)(p->H2 - f * (y - p->cy));
        out[2] = (float)(1 / dz);   /* affine in screen space; larger is nearer */
    } else {
        out[0] = (float)(p->W2 + p->scale * (x - p->cx));
        out[1] = (float)(p->H2 - p->scale * (y - p->cy));
        out[2] = (float)z;
    }
}

/* Everything the resolve pass needs to shade one face at a point. */
struct face_setup {
    int f, front;
    int t[3];                 /* vertex indices */
    double ax, ay, bx, by, cx, cy, invA;
    double hgt[3];            /* screen heights over each side, for the wireframe */
    double base[3], sf, fac, sgn;
};

struct shader {
    const struct render_style *s;
    const double *V;
    const int *F;
    const float *P;           /* #V by 3 projected positions (samples) */
    const float *sv;          /* #V signed n.l (smooth shading) or NULL */
    double Lw[3];             /* light direction in world coordinates */
    double amb, dim, half_wire;
};

static inline double sq(double x) { return x * x; }

static void face_setup(const struct shader *sh, int f, struct face_setup *fs)
{
    const struct render_style *s = sh->s;
    const int *t = sh->F + 3 * f;
    const float *a = sh->P + 3 * t[0], *b = sh->P + 3 * t[1], *c = sh->P + 3 * t[2];
    fs->f = f;
    memcpy(fs->t, t, sizeof fs->t);
    fs->ax = a[0]; fs->ay = a[1]; fs->bx = b[0]; fs->by = b[1]; fs->cx = c[0]; fs->cy = c[1];
    double A = (fs->bx - fs->ax) * (fs->cy - fs->ay) - (fs->cx - fs->ax) * (fs->by - fs->ay);
    if (A == 0) A = 1e-300;
    fs->invA = 1 / A;
    fs->front = A < 0;   /* screen y points down: counter-clockwise in view is A < 0 */
    if (s->wireframe) {
        double aa = fabs(A);
        fs->hgt[0] = aa / fmax(1e-300, sqrt(sq(fs->cx - fs->bx) + sq(fs->cy - fs->by)));
        fs->hgt[1] = aa / fmax(1e-300, sqrt(sq(fs->ax - fs->cx) + sq(fs->ay - fs->cy)));
        fs->hgt[2] = aa / fmax(1e-300, sqrt(sq(fs->bx - fs->ax) + sq(fs->by - fs->ay)));
    }
    for (int k = 0; k < 3; k++)
        fs->base[k] = s->face_rgb ? s->face_rgb[3 * f + k] : s->color[k];
    fs->sf = 0;
    if (s->flat) {
        double e1[3], e2[3], n[3];
        sub3(sh->V + 3 * t[1], sh->V + 3 * t[0], e1);
        sub3(sh->V + 3 * t[2], sh->V + 3 * t[0], e2);
        cross3(e1, e2, n);
        double nn = norm3(n);
        fs->sf = nn > 0 ? dot3(n, sh->Lw) / nn : 0;
    }
    fs->sgn = fs->front ? 1 : -1;
    fs->fac = fs->front ? 1 : sh->dim;
}

static void barycentric(const struct face_setup *fs, double px, double py, double w[3])
{
    w[0] = ((fs->cx - fs->bx) * (py - fs->by) - (fs->cy - fs->by) * (px - fs->bx)) * fs->invA;
    w[1] = ((fs->ax - fs->cx) * (py - fs->cy) - (fs->ay - fs->cy) * (px - fs->cx)) * fs->invA;
    w[2] = 1 - w[0] - w[1];
}

/* is the sample at (px, py) on the wireframe of the face? */
static int on_wire(const struct shader *sh, const struct face_setup *fs, double px, double py)
{
    double w[3];
    barycentric(fs, px, py, w);
    return w[0] * fs->hgt[0] < sh->half_wire || w[1] * fs->hgt[1] < sh->half_wire ||
           w[2] * fs->hgt[2] < sh->half_wire;
}

/* shaded colour of the face at sample position (px, py) */
static void shade_at(const struct shader *sh, const struct face_setup *fs, double px, double py,
                     double rgb[3])
{
    const struct render_style *s = sh->s;
    double w[3];
    barycentric(fs, px, py, w);
    const int *t = fs->t;
    double sd = s->flat ? fs->sf : w[0] * sh->sv[t[0]] + w[1] * sh->sv[t[1]] + w[2] * sh->sv[t[2]];
    double I = fs->fac * (sh->amb + (1 - sh->amb) * fmax(0, fs->sgn * sd));
    double col[3] = {fs->base[0], fs->base[1], fs->base[2]};
    if (s->vertex_t) {
        double tv = w[0] * s->vertex_t[t[0]] + w[1] * s->vertex_t[t[1]] + w[2] * s->vertex_t[t[2]];
        int li = (int)(tv * 255 + 0.5);
        li = li < 0 ? 0 : li > 255 ? 255 : li;
        for (int k = 0; k < 3; k++) col[k] = s->lut[3 * li + k];
    } else if (s->vertex_rgb) {
        const unsigned char *c0 = s->vertex_rgb + 3 * t[0], *c1 = s->vertex_rgb + 3 * t[1],
                            *c2 = s->vertex_rgb + 3 * t[2];
        if (s->vertex_nearest) {
            const unsigned char *m = w[0] >= w[1] && w[0] >= w[2] ? c0 : w[1] >= w[2] ? c1 : c2;
            for (int k = 0; k < 3; k++) col[k] = m[k];
        } else
            for (int k = 0; k < 3; k++) col[k] = w[0] * c0[k] + w[1] * c1[k] + w[2] * c2[k];
    }
    for (int k = 0; k < 3; k++) rgb[k] = col[k] * I;
}

/* Meshes imported with vertices split along UV seams have two normals at
 * one point, and smooth shading shows the seam.  Average the normals of
 * vertices at exactly the same position when they are within 60 degrees
 * of each other (so modelled hard edges, split for the same reason, stay
 * sharp).  N: #V by 3 unit normals, updated. */
static int join_split_normals(const double *V, int nv, double *N)
{
    int cap = 16;
    while (cap < 2 * nv) cap *= 2;
    int *head = malloc((size_t)cap * sizeof *head), *next = malloc((size_t)nv * sizeof *next);
    double *S = malloc((size_t)nv * 3 * sizeof *S);
    if (!head || !next || !S) {
        free(head); free(next); free(S);
        return -1;
    }
    for (int i = 0; i < cap; i++) head[i] = -1;
    int shared = 0;
    for (int i = 0; i < nv; i++) {
        uint64_t hsh = 1469598103934665603ull;
        const unsigned char *b = (const unsigned char *)(V + 3 * i);
        for (size_t k = 0; k < 3 * sizeof(double); k++) hsh = (hsh ^ b[k]) * 1099511628211ull;
        int slot = (int)(hsh & (uint64_t)(cap - 1));
        /* chain of vertices in this slot; a position match links i in */
        next[i] = head[slot];
        head[slot] = i;
        for (int j = next[i]; j >= 0 && !shared; j = next[j])
            shared = !memcmp(V + 3 * i, V + 3 * j, 3 * sizeof(double));
    }
    if (shared) {
        memcpy(S, N, (size_t)nv * 3 * sizeof *S);
        for (int slot = 0; slot < cap; slot++)
            for (int i = head[slot]; i >= 0; i = next[i])
                for (int j = next[i]; j >= 0; j = next[j]) {
                    if (memcmp(V + 3 * i, V + 3 * j, 3 * sizeof(double)) ||
                        dot3(N + 3 * i, N + 3 * j) < 0.5)
                        continue;
                    for (int k = 0; k < 3; k++) {
                        S[3 * i + k] += N[3 * j + k];
                        S[3 * j + k] += N[3 * i + k];
                    }
                }
        for (int i = 0; i < nv; i++) {
            double l = norm3(S + 3 * i);
            if (l > 0)
                for (int k = 0; k < 3; k++) N[3 * i + k] = S[3 * i + k] / l;
        }
    }
    free(head); free(next); free(S);
    return 0;
}

/* Fixed-point screen coordinates: 8 fractional bits per sample, so edge
 * functions are exact 64-bit integers and shared edges are watertight
 * (a sample on an edge belongs to exactly one of its two triangles). */
#define SUB 256
#define GUARD (1 << 20)   /* clamp far-off vertices to +-2^20 samples */

static int32_t fixp(float v)
{
    double d = (double)v * SUB;
    if (!(d < (double)GUARD * SUB)) d = (double)GUARD * SUB;
    if (d < -(double)GUARD * SUB) d = -(double)GUARD * SUB;
    return (int32_t)lrint(d);
}

/* tie rule for samples exactly on an edge a->b: antisymmetric, so the
 * reversed edge of the neighbouring triangle gets the opposite decision */
static int64_t edge_bias(int64_t dx, int64_t dy)
{
    return (dy > 0 || (dy == 0 && dx < 0)) ? 0 : -1;
}

/* Narrow [lo, hi] to the steps k with w + e k >= 0 (exact integers);
 * returns 0 if none is left. */
static inline int span(int64_t w, int64_t e, int64_t *lo, int64_t *hi)
{
    if (e > 0) {
        if (w < 0) {
            int64_t k = (-w + e - 1) / e;   /* ceil(-w / e) */
            if (k > *lo) *lo = k;
        }
    } else if (e < 0) {
        if (w < 0)
            return 0;
        int64_t k = w / -e;                 /* floor(w / -e) */
        if (k < *hi) *hi = k;
    } else if (w < 0)
        return 0;
    return *lo <= *hi;
}

/* sample bounding box of face f, clipped to [0, W) x [0, H); 0 if empty */
static int face_bbox(const int32_t *XY, const int *t, int W, int H, int *x0, int *x1, int *y0,
                     int *y1)
{
    int32_t mnx = XY[2 * t[0]], mxx = mnx, mny = XY[2 * t[0] + 1], mxy = mny;
    for (int k = 1; k < 3; k++) {
        int32_t x = XY[2 * t[k]], y = XY[2 * t[k] + 1];
        if (x < mnx) mnx = x;
        if (x > mxx) mxx = x;
        if (y < mny) mny = y;
        if (y > mxy) mxy = y;
    }
    /* samples sit at (i + 1/2) * SUB */
    int64_t xa = ((int64_t)mnx - SUB / 2 + SUB - 1) >> 8, xb = ((int64_t)mxx - SUB / 2) >> 8;
    int64_t ya = ((int64_t)mny - SUB / 2 + SUB - 1) >> 8, yb = ((int64_t)mxy - SUB / 2) >> 8;
    if (xa < 0) xa = 0;
    if (ya < 0) ya = 0;
    if (xb > W - 1) xb = W - 1;
    if (yb > H - 1) yb = H - 1;
    if (xa > xb || ya > yb)
        return 0;
    *x0 = (int)xa; *x1 = (int)xb; *y0 = (int)ya; *y1 = (int)yb;
    return 1;
}

/* Rasterize face f into a tile's visibility buffer (depth and face index
 * per sample).  The tile covers samples [tx, tx+TW) x [ty, ty+TH). */
static void rasterize_face(int f, const int *t, const int32_t *XY, const float *P, int W, int H,
                           int tx, int ty, int TW, int TH, float *zb, int32_t *id)
{
    int xa, xb, ya, yb;
    if (!face_bbox(XY, t, W, H, &xa, &xb, &ya, &yb))
        return;
    if (xa < tx) xa = tx;
    if (ya < ty) ya = ty;
    if (xb > tx + TW - 1) xb = tx + TW - 1;
    if (yb > ty + TH - 1) yb = ty + TH - 1;
    if (xa > xb || ya > yb)
        return;
    int64_t X0 = XY[2 * t[0]], Y0 = XY[2 * t[0] + 1];
    int64_t X1 = XY[2 * t[1]], Y1 = XY[2 * t[1] + 1];
    int64_t X2 = XY[2 * t[2]], Y2 = XY[2 * t[2] + 1];
    double z0 = P[3 * t[0] + 2], z1 = P[3 * t[1] + 2], z2 = P[3 * t[2] + 2];
    int64_t A = (X1 - X0) * (Y2 - Y0) - (X2 - X0) * (Y1 - Y0);
    if (A == 0)
        return;
    if (A < 0) {   /* make the winding positive */
        int64_t tx_ = X1, ty_ = Y1;
        X1 = X2; Y1 = Y2; X2 = tx_; Y2 = ty_;
        double tz = z1; z1 = z2; z2 = tz;
        A = -A;
    }
    /* edge functions w_i(p) = (b - a) x (p - a) over the side opposite vertex i */
    int64_t e0x = -(Y2 - Y1) * SUB, e0y = (X2 - X1) * SUB;
    int64_t e1x = -(Y0 - Y2) * SUB, e1y = (X0 - X2) * SUB;
    int64_t e2x = -(Y1 - Y0) * SUB, e2y = (X1 - X0) * SUB;
    int64_t px = (int64_t)xa * SUB + SUB / 2, py = (int64_t)ya * SUB + SUB / 2;
    int64_t r0 = (X2 - X1) * (py - Y1) - (Y2 - Y1) * (px - X1) + edge_bias(X2 - X1, Y2 - Y1);
    int64_t r1 = (X0 - X2) * (py - Y2) - (Y0 - Y2) * (px - X2) + edge_bias(X0 - X2, Y0 - Y2);
    int64_t r2 = (X1 - X0) * (py - Y0) - (Y1 - Y0) * (px - X0) + edge_bias(X1 - X0, Y1 - Y0);
    /* depth plane z = z0 + dzdx (x - x0) + dzdy (y - y0), x and y in samples */
    double k = (double)SUB / (double)A;
    double dzdx = ((z1 - z0) * (double)(Y2 - Y0) - (z2 - z0) * (double)(Y1 - Y0)) * k;
    double dzdy = ((z2 - z0) * (double)(X1 - X0) - (z1 - z0) * (double)(X2 - X0)) * k;
    double zrow = z0 + (dzdx * (double)(px - X0) + dzdy * (double)(py - Y0)) / SUB;
    for (int y = ya; y <= yb; y++, r0 += e0y, r1 += e1y, r2 += e2y, zrow += dzdy) {
        int64_t w0 = r0, w1 = r1, w2 = r2;
        double z = zrow;
        /* the covered span of this row, exactly: w_i + e_ix * k >= 0 */
        int64_t lo = 0, hi = xb - xa;
        if (!span(w0, e0x, &lo, &hi) || !span(w1, e1x, &lo, &hi) || !span(w2, e2x, &lo, &hi))
            continue;
        z += dzdx * (double)lo;
        size_t i = (size_t)(y - ty) * TW + (xa + lo - tx);
        for (int64_t k = lo; k <= hi; k++, i++, z += dzdx) {
            float zf = (float)z;
            if (zf > zb[i]) {
                zb[i] = zf;
                id[i] = f;
            }
        }
    }
}

/* the projection of a W by H (samples) render, fitted to the camera's
 * view-space bounds */
static void setup_proj(const struct camera *cam, int W, int H, struct proj *pj)
{
    memcpy(pj->R, cam->R, sizeof pj->R);
    pj->persp = cam->perspective;
    pj->W2 = 0.5 * W;
    pj->H2 = 0.5 * H;
    pj->cx = 0.5 * (cam->lo[0] + cam->hi[0]);
    pj->cy = 0.5 * (cam->lo[1] + cam->hi[1]);
    double ex = cam->hi[0] - cam->lo[0], ey = cam->hi[1] - cam->lo[1];
    double ez = cam->hi[2] - cam->lo[2];
    double avail = 1 - 2 * (cam->margin < 0 ? 0 : cam->margin > 0.45 ? 0.45 : cam->margin);
    double sx = ex > 0 ? W * avail / ex : DBL_MAX, sy = ey > 0 ? H * avail / ey : DBL_MAX;
    if (!pj->persp) {
        pj->scale = sx < sy ? sx : sy;
        if (pj->scale == DBL_MAX) pj->scale = 1;
    } else {
        double fov = cam->fov > 1 && cam->fov < 170 ? cam->fov : 30;
        pj->scale = pj->H2 / tan(0.5 * fov * M_PI / 180);     /* focal length in samples */
        /* the camera sees the bounding sphere of the view-space box; then
         * the zoom below makes the projected box fill the view */
        double r = 0.5 * sqrt(ex * ex + ey * ey + ez * ez);
        if (!(r > 0)) r = 1;
        pj->eye = 0.5 * (cam->lo[2] + cam->hi[2]) + r / sin(0.5 * fov * M_PI / 180);
        /* the 8 corners of the view-space box, projected, bound the
         * projection of every fitted point: zoom and shift so they fill the
         * view */
        double mnx = DBL_MAX, mxx = -DBL_MAX, mny = DBL_MAX, mxy = -DBL_MAX;
        for (int c = 0; c < 8; c++) {
            double x = c & 1 ? cam->hi[0] : cam->lo[0], y = c & 2 ? cam->hi[1] : cam->lo[1];
            double z = c & 4 ? cam->hi[2] : cam->lo[2], f = pj->scale / (pj->eye - z);
            mnx = fmin(mnx, f * (x - pj->cx)); mxx = fmax(mxx, f * (x - pj->cx));
            mny = fmin(mny, f * (y - pj->cy)); mxy = fmax(mxy, f * (y - pj->cy));
        }
        double zx = mxx > mnx ? W * avail / (mxx - mnx) : DBL_MAX;
        double zy = mxy > mny ? H * avail / (mxy - mny) : DBL_MAX;
        double zoom = fmin(zx, zy);
        if (zoom < DBL_MAX && zoom > 0) {
            pj->scale *= zoom;
            pj->W2 -= zoom * 0.5 * (mnx + mxx);
            pj->H2 += zoom * 0.5 * (mny + mxy);
        }
    }
}

int raster_render(const double *V, const int *F, int nv, int nf, const struct camera *cam,
                  const struct render_style *s, int w, int h, struct image *out)
{
    int ss = s->ss < 1 ? 1 : s->ss > 8 ? 8 : s->ss;
    if (w < 1 || h < 1 || (double)w * h * ss * ss > 4e8)
        return cm_seterr("render size %dx%d (supersampling %d) out of range", w, h, ss);
    if (image_alloc(out, w, h, s->background) < 0)
        return -1;
    if (cam->fitted < 1 || nf < 1)
        return 0;   /* nothing to draw (an empty mesh): the background */
    int W = w * ss, H = h * ss;
    /* tiles of TP x TP pixels keep the visibility buffer in cache */
    enum { TP = 64, NCACHE = 4096 };
    int TS = TP * ss, ntx = (w + TP - 1) / TP, nty = (h + TP - 1) / TP, ntiles = ntx * nty;
    size_t nvv = (size_t)(nv > 0 ? nv : 1);
    float *zb = malloc((size_t)TS * TS * sizeof *zb);
    int32_t *id = malloc((size_t)TS * TS * sizeof *id);
    float *P = malloc(nvv * 3 * sizeof *P);
    int32_t *XY = malloc(nvv * 2 * sizeof *XY);
    int *tstart = calloc((size_t)ntiles + 1, sizeof *tstart);
    struct face_setup *fc = malloc(NCACHE * sizeof *fc);
    float *sv = NULL;
    double *N = NULL;
    int *tfaces = NULL;
    int ok = zb && id && P && XY && tstart && fc;
    if (ok && !s->flat && nv > 0) {
        N = malloc((size_t)nv * 3 * sizeof *N);
        sv = malloc((size_t)nv * sizeof *sv);
        ok = N && sv;
    }

    /* projection fitted to the camera's view-space bounds */
    struct proj pj;
    setup_proj(cam, W, H, &pj);
    if (ok)
        for (int i = 0; i < nv; i++) {
            project(&pj, V + 3 * i, P + 3 * i);
            XY[2 * i] = fixp(P[3 * i]);
            XY[2 * i + 1] = fixp(P[3 * i + 1]);
        }

    /* bin faces into tiles (counting sort) */
    if (ok) {
        for (int pass = 0; pass < 2 && ok; pass++) {
            for (int f = 0; f < nf; f++) {
                int x0, x1, y0, y1;
                if (!face_bbox(XY, F + 3 * f, W, H, &x0, &x1, &y0, &y1))
                    continue;
                for (int ty = y0 / TS; ty <= y1 / TS; ty++)
                    for (int tx = x0 / TS; tx <= x1 / TS; tx++) {
                        int t = ty * ntx + tx;
                        if (pass == 0) tstart[t + 1]++;
                        else tfaces[tstart[t]++] = f;
                    }
            }
            if (pass == 0) {
                for (int t = 0; t < ntiles; t++) tstart[t + 1] += tstart[t];
                tfaces = malloc((size_t)(tstart[ntiles] > 0 ? tstart[ntiles] : 1) * sizeof *tfaces);
                ok = tfaces != NULL;
            } else {   /* tstart[t] now holds the end of tile t: shift back */
                for (int t = ntiles; t > 0; t--) tstart[t] = tstart[t - 1];
                tstart[0] = 0;
            }
        }
    }
    if (!ok) {
        free(zb); free(id); free(P); free(XY); free(tstart); free(tfaces); free(fc);
        free(N); free(sv);
        image_free(out);
        return cm_seterr("out of memory for a %dx%d render", W, H);
    }

    struct shader sh;
    sh.s = s;
    sh.V = V;
    sh.F = F;
    sh.P = P;
    /* headlight, slightly above and to the left, in view space */
    double L[3] = {-0.25, 0.35, 1};
    double ln = norm3(L);
    for (int k = 0; k < 3; k++) L[k] /= ln;
    for (int k = 0; k < 3; k++)   /* in world coordinates: R^T L */
        sh.Lw[k] = cam->R[k] * L[0] + cam->R[3 + k] * L[1] + cam->R[6 + k] * L[2];
    if (sv) {
        vertex_normals(V, F, nv, nf, N);
        if (join_split_normals(V, nv, N) < 0) {
            free(zb); free(id); free(P); free(XY); free(tstart); free(tfaces); free(fc);
            free(N); free(sv);
            image_free(out);
            return cm_seterr("out of memory for vertex normals");
        }
        for (int i = 0; i < nv; i++) sv[i] = (float)dot3(N + 3 * i, sh.Lw);
    }
    sh.sv = sv;
    sh.amb = s->ambient < 0 ? 0 : s->ambient > 1 ? 1 : s->ambient;
    sh.dim = s->back_dim < 0 ? 0 : s->back_dim > 1 ? 1 : s->back_dim;
    sh.half_wire = 0.5 * s->wire_width * ss;
    for (int i = 0; i < NCACHE; i++) fc[i].f = -1;

    int n2 = ss * ss;
    for (int ty = 0; ty < nty; ty++)
        for (int tx = 0; tx < ntx; tx++) {
            int t = ty * ntx + tx;
            if (tstart[t] == tstart[t + 1])
                continue;   /* empty tile: background */
            int px0 = tx * TP, py0 = ty * TP;
            int pw = w - px0 < TP ? w - px0 : TP, ph = h - py0 < TP ? h - py0 : TP;
            int sx0 = px0 * ss, sy0 = py0 * ss;
            for (int i = 0; i < TS * TS; i++) zb[i] = -FLT_MAX;
            memset(id, 0xff, (size_t)TS * TS * sizeof *id);   /* -1: background */
            for (int k = tstart[t]; k < tstart[t + 1]; k++) {
                int f = tfaces[k];
                rasterize_face(f, F + 3 * f, XY, P, W, H, sx0, sy0, TS, TS, zb, id);
            }
            /* Resolve: each pixel shades each distinct face among its ss x ss
             * samples once (at that face's first sample) and averages; the
             * wireframe is decided per sample so lines stay antialiased. */
            for (int y = 0; y < ph; y++)
                for (int x = 0; x < pw; x++) {
                    const int32_t *row0 = id + (size_t)y * ss * TS + (size_t)x * ss;
                    int32_t f0 = row0[0];
                    int uniform = 1;
                    for (int j = 0; j < ss && uniform; j++)
                        for (int i = 0; i < ss; i++)
                            if (row0[(size_t)j * TS + i] != f0) { uniform = 0; break; }
                    if (uniform && f0 < 0)
                        continue;   /* background, already filled */
                    unsigned char *o = image_px(out, px0 + x, py0 + y);
                    double acc[3] = {0, 0, 0};
                    int gx = (px0 + x) * ss, gy = (py0 + y) * ss;   /* global sample coords */
                    if (uniform && !s->wireframe) {
                        struct face_setup *fs = &fc[f0 & (NCACHE - 1)];
                        if (fs->f != f0) face_setup(&sh, f0, fs);
                        shade_at(&sh, fs, gx + 0.5 * ss, gy + 0.5 * ss, acc);
                        for (int k = 0; k < 3; k++) o[k] = (unsigned char)(acc[k] > 254.5 ? 255 : acc[k] + 0.5);
                        continue;
                    }
                    int nc = 0, seen[64];
                    double col[64][3];
                    for (int j = 0; j < ss; j++)
                        for (int i = 0; i < ss; i++) {
                            int32_t f = row0[(size_t)j * TS + i];
                            if (f < 0) {
                                for (int k = 0; k < 3; k++) acc[k] += s->background[k];
                                continue;
                            }
                            double px = gx + i + 0.5, py = gy + j + 0.5;
                            int c = 0;
                            while (c < nc && seen[c] != f) c++;
                            struct face_setup *fs = &fc[f & (NCACHE - 1)];
                            if (fs->f != f) face_setup(&sh, f, fs);
                            if (c == nc) {
                                seen[nc++] = f;
                                shade_at(&sh, fs, px, py, col[c]);
                            }
                            if (s->wireframe && on_wire(&sh, fs, px, py))
                                for (int k = 0; k < 3; k++) acc[k] += s->wire_rgb[k];
                            else
                                for (int k = 0; k < 3; k++) acc[k] += col[c][k];
                        }
                    for (int k = 0; k < 3; k++) {
                        double v = acc[k] / n2;
                        o[k] = (unsigned char)(v > 254.5 ? 255 : v + 0.5);
                    }
                }
        }
    free(zb); free(id); free(P); free(XY); free(tstart); free(tfaces); free(fc);
    free(N); free(sv);
    return 0;
}

void raster_project_points(const struct camera *cam, int w, int h, const double *P, int n,
                           double *XY)
{
    struct proj pj;
    setup_proj(cam, w, h, &pj);
    for (int i = 0; i < n; i++) {
        float o[3];
        project(&pj, P + 3 * i, o);
        XY[2 * i] = o[0];
        XY[2 * i + 1] = o[1];
    }
}
