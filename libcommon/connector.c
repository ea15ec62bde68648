/* connector.c -- see connector.h */
#include "connector.h"
#include "image.h"
#include "geometry.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void trimesh_free(struct trimesh *m)
{
    free(m->V); free(m->F);
    memset(m, 0, sizeof *m);
}

static int addv(struct trimesh *m, const double p[3])
{
    if (m->nv == m->capv) {
        m->capv = m->capv ? 2 * m->capv : 64;
        m->V = realloc(m->V, sizeof(double) * 3 * m->capv);
    }
    memcpy(m->V + 3 * m->nv, p, sizeof(double) * 3);
    return m->nv++;
}

static void addf(struct trimesh *m, int a, int b, int c)
{
    if (m->nf == m->capf) {
        m->capf = m->capf ? 2 * m->capf : 64;
        m->F = realloc(m->F, sizeof(int) * 3 * m->capf);
    }
    int *f = m->F + 3 * m->nf++;
    f[0] = a; f[1] = b; f[2] = c;
}

/* the prism over the general frame (e1, e2, e3) with e1 x e2 = +-e3 */
static void prism(struct trimesh *m, const double o[3], const double e1[3], const double e2[3],
                  const double e3[3], const double *P, int n, double z0, double z1)
{
    double c1[3];
    cross3(e1, e2, c1);
    int flip = dot3(c1, e3) < 0;   /* keep the solid outward oriented */
    int base = m->nv;
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < n; i++) {
            double p[3], z = k ? z1 : z0;
            for (int c = 0; c < 3; c++) p[c] = o[c] + P[2 * i] * e1[c] + P[2 * i + 1] * e2[c] + z * e3[c];
            addv(m, p);
        }
    /* with e1 x e2 = e3, the CCW polygon faces +e3: the top (z1) keeps its order */
    for (int i = 1; i + 1 < n; i++) {
        if (!flip) {
            addf(m, base + n, base + n + i, base + n + i + 1);
            addf(m, base, base + i + 1, base + i);
        } else {
            addf(m, base + n, base + n + i + 1, base + n + i);
            addf(m, base, base + i, base + i + 1);
        }
    }
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n, a = base + i, b = base + j, c = base + n + j, d = base + n + i;
        if (!flip) { addf(m, a, b, c); addf(m, a, c, d); }
        else { addf(m, a, c, b); addf(m, a, d, c); }
    }
}

void connector_prism(struct trimesh *m, const struct connector_frame *fr, const double *P, int n,
                     double z0, double z1)
{
    prism(m, fr->o, fr->u, fr->w, fr->a, P, n, z0, z1);
}

void connector_circle(double R, int n, double *P)
{
    double Rc = R / cos(M_PI / n);
    for (int i = 0; i < n; i++) {
        P[2 * i] = Rc * cos(2 * M_PI * (i + 0.5) / n);
        P[2 * i + 1] = Rc * sin(2 * M_PI * (i + 0.5) / n);
    }
}

void connector_keyed(double W, double L, double *P)
{
    double q[8] = {-L / 4, -W / 2, L / 4, -W / 2, L / 2, W / 2, -L / 2, W / 2};
    memcpy(P, q, sizeof q);
}

void convex_offset(const double *P, int n, double d, double *Q)
{
    for (int i = 0; i < n; i++) {
        /* vertex i: intersection of edges (i-1, i) and (i, i+1) moved by d */
        const double *a = P + 2 * ((i + n - 1) % n), *b = P + 2 * i, *c = P + 2 * ((i + 1) % n);
        double e1x = b[0] - a[0], e1y = b[1] - a[1], e2x = c[0] - b[0], e2y = c[1] - b[1];
        double l1 = hypot(e1x, e1y), l2 = hypot(e2x, e2y);
        double n1x = e1y / l1, n1y = -e1x / l1, n2x = e2y / l2, n2y = -e2x / l2;   /* outer normals (CCW) */
        double bx = n1x + n2x, by = n1y + n2y, s = 1 + n1x * n2x + n1y * n2y;      /* bisector, 1 + cos */
        Q[2 * i] = b[0] + d * bx / s;
        Q[2 * i + 1] = b[1] + d * by / s;
    }
}

int connector_text(struct trimesh *m, const char *s, const double c[3], const double x[3],
                   const double y[3], const double n[3], double pitch, double depth, double above,
                   void (*place)(void *ctx, const double p[3], double q[3]), void *ctx)
{
    int len = (int)strlen(s), boxes = 0;
    double wx = (len * FONT_ADVANCE - 1) * pitch, hy = (FONT_H - 1) * pitch, h = 0.4 * pitch;
    double sq[8] = {-h, -h, h, -h, h, h, -h, h};
    for (int k = 0; k < len; k++) {
        const unsigned char *g = font_glyph((unsigned char)s[k]);
        for (int r = 0; r < FONT_H; r++)
            for (int b = 0; b < FONT_W; b++) {
                if (!(g[r] & (0x10 >> b))) continue;
                double px = (k * FONT_ADVANCE + b) * pitch - wx / 2, py = hy / 2 - r * pitch, p[3], q[3];
                for (int i = 0; i < 3; i++) p[i] = c[i] + px * x[i] + py * y[i];
                if (place) place(ctx, p, q); else memcpy(q, p, sizeof q);
                prism(m, q, x, y, n, sq, 4, -depth, above);
                boxes++;
            }
    }
    return boxes;
}
