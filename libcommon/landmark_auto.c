/* landmark_auto.c -- see landmark_auto.h */
#include "landmark_auto.h"
#include "cm_error.h"
#include "clay_deform.h"
#include "closest_point.h"
#include "geodesic.h"
#include "geometry.h"
#include "procrustes.h"
#include "topology.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void landmark_auto_defaults(struct landmark_auto_params *p)
{
    memset(p, 0, sizeof *p);
    p->radius = 0.1;
    p->penalty = 0.25;
    p->margin = 0.5;
    p->beam = 400;
    p->max_extremities = 12;
    p->limb_t[0] = 0.35;
    p->nlimb = 1;
    p->core = 0;
    p->second_ratio = 1.5;
    p->disc_weight = 1;
    p->verify = 0;
}

/* ---- a binary heap of (key, vertex) for the bounded Dijkstra */
struct heap { double *k; int *v; int n, cap; };
static int heap_push(struct heap *h, double k, int v)
{
    if (h->n == h->cap) {
        int c = 2 * h->cap + 64;
        double *nk = realloc(h->k, (size_t)c * sizeof *nk);
        if (!nk) return -1;
        h->k = nk;
        int *nv = realloc(h->v, (size_t)c * sizeof *nv);
        if (!nv) return -1;
        h->v = nv; h->cap = c;
    }
    int i = h->n++;
    while (i > 0 && h->k[(i - 1) / 2] > k) {
        h->k[i] = h->k[(i - 1) / 2]; h->v[i] = h->v[(i - 1) / 2]; i = (i - 1) / 2;
    }
    h->k[i] = k; h->v[i] = v;
    return 0;
}
static void heap_pop(struct heap *h, double *k, int *v)
{
    *k = h->k[0]; *v = h->v[0];
    double lk = h->k[--h->n]; int lv = h->v[h->n], i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->k[c + 1] < h->k[c]) c++;
        if (h->k[c] >= lk) break;
        h->k[i] = h->k[c]; h->v[i] = h->v[c]; i = c;
    }
    h->k[i] = lk; h->v[i] = lv;
}

/* Is v a maximum of f1 + f2 among the vertices within edge-path
 * distance r?  dist: #V scratch, all INFINITY on entry and on exit. */
static int local_max(const double *V, const struct topology *t, int v, double r, const double *f1,
                     const double *f2, double *dist, struct heap *h, int *touched)
{
    int nt = 0, ok = 1;
    h->n = 0;
    dist[v] = 0;
    touched[nt++] = v;
    heap_push(h, 0, v);
    while (h->n > 0 && ok) {
        double k; int u;
        heap_pop(h, &k, &u);
        if (k > dist[u]) continue;
        if (f1[u] + f2[u] > f1[v] + f2[v]) { ok = 0; break; }
        for (int q = t->VVs[u]; q < t->VVs[u + 1]; q++) {
            int w = t->VV[q];
            double d = k + dist3(V + 3 * u, V + 3 * w);
            if (d <= r && d < dist[w]) {
                if (dist[w] == INFINITY) touched[nt++] = w;
                dist[w] = d;
                if (heap_push(h, d, w) < 0) { ok = -1; break; }
            }
        }
    }
    for (int i = 0; i < nt; i++) dist[touched[i]] = INFINITY;
    return ok;
}

static int argmax_finite(const double *D, int n)
{
    int b = -1;
    for (int i = 0; i < n; i++)
        if (isfinite(D[i]) && (b < 0 || D[i] > D[b])) b = i;
    return b;
}

/* extremities with an existing heat-method solver */
static int extremities(struct geodesic *g, const double *V, const int *F, int nv, int nf,
                       const struct landmark_auto_params *p, int **E)
{
    *E = NULL;
    double s = sqrt(mesh_area(V, F, nf)), r = p->radius * s;
    double *f1 = malloc((size_t)nv * sizeof *f1), *f2 = malloc((size_t)nv * sizeof *f2);
    double *dist = malloc((size_t)nv * sizeof *dist);
    int *touched = malloc((size_t)nv * sizeof *touched), *cand = malloc((size_t)nv * sizeof *cand);
    struct topology t = {0};
    struct heap h = {0};
    int n = -1;
    if (!f1 || !f2 || !dist || !touched || !cand) { cm_seterr("out of memory"); goto done; }
    if (topology_build(F, nf, nv, &t) < 0) goto done;
    /* an approximate diameter: the farthest vertex from the farthest from vertex 0 */
    int s0 = 0, p1, p2;
    while (s0 < nv && t.VFs[s0] == t.VFs[s0 + 1]) s0++;
    if (s0 == nv) { cm_seterr("the mesh has no faces"); goto done; }
    if (geodesic_solve(g, &s0, 1, f1) < 0) goto done;
    p1 = argmax_finite(f1, nv);
    if (geodesic_solve(g, &p1, 1, f1) < 0) goto done;
    p2 = argmax_finite(f1, nv);
    if (geodesic_solve(g, &p2, 1, f2) < 0) goto done;
    for (int i = 0; i < nv; i++) dist[i] = INFINITY;
    int nc = 0;
    for (int v = 0; v < nv; v++) {
        if (!isfinite(f1[v]) || !isfinite(f2[v]) || t.VVs[v] == t.VVs[v + 1]) continue;
        int m = 1;
        for (int q = t.VVs[v]; q < t.VVs[v + 1] && m; q++)
            if (f1[t.VV[q]] + f2[t.VV[q]] > f1[v] + f2[v]) m = 0;
        if (!m) continue;
        int lm = local_max(V, &t, v, r, f1, f2, dist, &h, touched);
        if (lm < 0) { cm_seterr("out of memory"); goto done; }
        if (lm) cand[nc++] = v;
    }
    /* the diameter's ends are extremities too, unless a local maximum lies
     * within r of them (f1, f2 are the distances from them) */
    for (int e = 0; e < 2; e++) {
        const double *fe = e ? f2 : f1;
        int pe = e ? p2 : p1, near = 0;
        for (int i = 0; i < nc && !near; i++) near = fe[cand[i]] < r || cand[i] == pe;
        if (!near) cand[nc++] = pe;
    }
    /* farthest first (by f1 + f2); no two are within r of each other
     * along the surface (each is the maximum of its r-neighbourhood), so
     * two feet that touch in space both stay */
    for (int i = 1; i < nc; i++)
        for (int j = i; j > 0 && f1[cand[j]] + f2[cand[j]] > f1[cand[j - 1]] + f2[cand[j - 1]]; j--) {
            int x = cand[j]; cand[j] = cand[j - 1]; cand[j - 1] = x;
        }
    n = nc < p->max_extremities ? nc : p->max_extremities;
    *E = malloc((size_t)(n > 0 ? n : 1) * sizeof **E);
    if (!*E) { n = -1; cm_seterr("out of memory"); goto done; }
    memcpy(*E, cand, (size_t)n * sizeof **E);
done:
    topology_free(&t);
    free(h.k); free(h.v);
    free(f1); free(f2); free(dist); free(touched); free(cand);
    return n;
}

int mesh_extremities(const double *V, const int *F, int nv, int nf,
                     const struct landmark_auto_params *p, int **E)
{
    struct geodesic *g = geodesic_new(V, F, nv, nf);
    if (!g) return -1;
    int n = extremities(g, V, F, nv, nf, p, E);
    geodesic_free(g);
    return n;
}

/* ---- matching */

struct state { double score; int m[32]; unsigned used; };

static int cmp_state(const void *a, const void *b)
{
    double x = ((const struct state *)a)->score, y = ((const struct state *)b)->score;
    return (x < y) - (x > y);
}

static void area_centroid(const double *V, const int *F, int nf, double c[3])
{
    double w = 0;
    c[0] = c[1] = c[2] = 0;
    for (int f = 0; f < nf; f++) {
        double e1[3], e2[3], n[3];
        const double *a = V + 3 * F[3 * f], *b = V + 3 * F[3 * f + 1], *d = V + 3 * F[3 * f + 2];
        sub3(b, a, e1); sub3(d, a, e2); cross3(e1, e2, n);
        double A = 0.5 * norm3(n);
        for (int k = 0; k < 3; k++) c[k] += A * (a[k] + b[k] + d[k]) / 3;
        w += A;
    }
    if (w > 0) for (int k = 0; k < 3; k++) c[k] /= w;
}

static double triple(const double *c, const double *x, const double *y, const double *z)
{
    double a[3], b[3], d[3], n[3];
    sub3(x, c, a); sub3(y, c, b); sub3(z, c, d);
    cross3(b, d, n);
    return dot3(a, n);
}

/* orientation agreement of a map: weighted mean of sign agreements of the
 * triple products, -1 (mirrored) .. 1 */
static double orientation(const double *VA, const int *EA, const double *cA, const double *VB,
                          const int *EB, const double *cB, const int *m, int na)
{
    double num = 0, den = 0;
    for (int i = 0; i < na; i++) {
        if (m[i] < 0) continue;
        for (int j = i + 1; j < na; j++) {
            if (m[j] < 0) continue;
            for (int k = j + 1; k < na; k++) {
                if (m[k] < 0) continue;
                double a = triple(cA, VA + 3 * EA[i], VA + 3 * EA[j], VA + 3 * EA[k]);
                double b = triple(cB, VB + 3 * EB[m[i]], VB + 3 * EB[m[j]], VB + 3 * EB[m[k]]);
                double w = fmin(fabs(a), fabs(b));
                num += (a * b > 0 ? 1 : -1) * w;
                den += w;
            }
        }
    }
    return den > 0 ? num / den : 0;
}

#define NDISC 3
static const double disc_r[NDISC] = {0.05, 0.1, 0.2};

/* A[i][k]: the area within geodesic distance disc_r[k] s of extremity i
 * (D: n distance fields over nv vertices), over the whole area: each face
 * counts with the fraction of its corners inside */
static void disc_areas(const double *V, const int *F, int nv, int nf, const double *D, int n,
                       double s, double A[][NDISC])
{
    double tot = 0;
    for (int i = 0; i < n; i++) for (int k = 0; k < NDISC; k++) A[i][k] = 0;
    for (int f = 0; f < nf; f++) {
        double e1[3], e2[3], c[3];
        const int *t = F + 3 * f;
        sub3(V + 3 * t[1], V + 3 * t[0], e1); sub3(V + 3 * t[2], V + 3 * t[0], e2); cross3(e1, e2, c);
        double a = 0.5 * norm3(c);
        tot += a;
        for (int i = 0; i < n; i++)
            for (int k = 0; k < NDISC; k++) {
                int in = 0;
                for (int q = 0; q < 3; q++) in += D[(size_t)i * nv + t[q]] < disc_r[k] * s;
                A[i][k] += a * in / 3;
            }
    }
    if (tot > 0) for (int i = 0; i < n; i++) for (int k = 0; k < NDISC; k++) A[i][k] /= tot;
}

/* how unlike two extremities' disc areas are: sum over the radii of |log(a / b)| */
static double disc_cost(const double *a, const double *b)
{
    double c = 0;
    for (int k = 0; k < NDISC; k++) c += fabs(log((a[k] + 1e-9) / (b[k] + 1e-9)));
    return c;
}

/* How well the map m explains B: A's matched extremities aligned rigidly
 * (no reflection) onto B's, then A deformed as rigidly as possible
 * (clay_deform.h, 10 steps of 5 iterations, the volume kept when A is
 * closed) until they sit on B's; the mean of the closest-point distances
 * both ways, over sB, in *fit.  TB: B's closest-point tree.  Returns 0,
 * or -1 (cm_errmsg: the deformation could not be set up). */
static int map_fit(const double *VA, const int *FA, int nva, int nfa, int closed, const double *VB,
                      int nvb, const struct closest_point_tree *TB, const int *EA, const int *EB,
                      const int *m, int na, double sB, double *fit)
{
    int H[32], n = 0;
    double P[96], Q[96], T[96], R[9], t[3];
    for (int i = 0; i < na; i++)
        if (m[i] >= 0) {
            H[n] = EA[i];
            memcpy(P + 3 * n, VA + 3 * EA[i], 3 * sizeof *P);
            memcpy(Q + 3 * n, VB + 3 * EB[m[i]], 3 * sizeof *Q);
            n++;
        }
    double *X0 = malloc(((size_t)nva * 3 + 1) * sizeof *X0), *X = malloc(((size_t)nva * 3 + 1) * sizeof *X);
    double *D = malloc(((size_t)(nva > nvb ? nva : nvb) + 1) * sizeof *D);
    struct clay_deform *cd = NULL;
    struct closest_point_tree *TX = NULL;
    int rc = -1;
    if (!X0 || !X || !D) { cm_seterr("out of memory"); goto done; }
    if (procrustes(P, Q, NULL, n, 0, R, t, NULL) < 0) goto done;
    similarity_apply(R, t, 1, VA, nva, X0);
    memcpy(X, X0, (size_t)nva * 3 * sizeof *X);
    if (!(cd = clay_deform_new(X0, FA, nva, nfa, NULL, H, n, 100))) goto done;
    for (int s = 1; s <= 10; s++) {
        double a = s / 10.0;
        for (int l = 0; l < n; l++)
            for (int d = 0; d < 3; d++) T[3 * l + d] = (1 - a) * X0[3 * H[l] + d] + a * Q[3 * l + d];
        if (clay_deform_solve(cd, T, 5, closed, X) < 0) goto done;
    }
    double sa = 0, sb = 0;
    closest_points(TB, X, nva, NULL, NULL, NULL, D);
    for (int v = 0; v < nva; v++) sa += D[v];
    if (!(TX = closest_point_tree_new(X, nva, FA, nfa))) goto done;
    closest_points(TX, VB, nvb, NULL, NULL, NULL, D);
    for (int v = 0; v < nvb; v++) sb += D[v];
    *fit = 0.5 * (sa / nva + sb / nvb) / sB;
    rc = 0;
done:
    clay_deform_free(cd);
    closest_point_tree_free(TX);
    free(X0); free(X); free(D);
    return rc;
}

void landmark_pairs_free(struct landmark_pairs *L)
{
    free(L->a); free(L->b); free(L->kind);
    memset(L, 0, sizeof *L);
}

int landmark_auto(const double *VA, const int *FA, int nva, int nfa,
                  const double *VB, const int *FB, int nvb, int nfb,
                  const struct landmark_auto_params *p, struct landmark_pairs *out)
{
    memset(out, 0, sizeof *out);
    struct geodesic *gA = geodesic_new(VA, FA, nva, nfa), *gB = NULL;
    int *EA = NULL, *EB = NULL, rc = -1, na = 0, nb = 0;
    double *DA = NULL, *DB = NULL;
    struct state *beam = NULL, *next = NULL;
    if (!gA) return -1;
    if (!(gB = geodesic_new(VB, FB, nvb, nfb))) goto done;
    if ((na = extremities(gA, VA, FA, nva, nfa, p, &EA)) < 0) goto done;
    if ((nb = extremities(gB, VB, FB, nvb, nfb, p, &EB)) < 0) goto done;
    if (na > 32) na = 32;
    if (nb > 32) nb = 32;
    out->na = na; out->nb = nb;
    if (na < 3 || nb < 3) {
        cm_seterr("landmarks: %d and %d extremities found, need 3 on each", na, nb);
        goto done;
    }
    double sA = sqrt(mesh_area(VA, FA, nfa)), sB = sqrt(mesh_area(VB, FB, nfb));
    /* distance fields of every extremity (kept for the limb points) */
    DA = malloc((size_t)na * nva * sizeof *DA);
    DB = malloc((size_t)nb * nvb * sizeof *DB);
    if (!DA || !DB) { cm_seterr("out of memory"); goto done; }
    for (int i = 0; i < na; i++)
        if (geodesic_solve(gA, EA + i, 1, DA + (size_t)i * nva) < 0) goto done;
    for (int i = 0; i < nb; i++)
        if (geodesic_solve(gB, EB + i, 1, DB + (size_t)i * nvb) < 0) goto done;
    /* disc areas: the area within geodesic distance disc_r[k] sqrt(area)
     * of each extremity, over the total area (a thin leg's tip gathers
     * little, a head or a hump much) */
    double aA[32][NDISC], aB[32][NDISC];
    disc_areas(VA, FA, nva, nfa, DA, na, sA, aA);
    disc_areas(VB, FB, nvb, nfb, DB, nb, sB, aB);
    /* symmetric, scale-free extremity distances */
    double dA[32][32], dB[32][32];
    for (int i = 0; i < na; i++)
        for (int j = 0; j < na; j++)
            dA[i][j] = 0.5 * (DA[(size_t)i * nva + EA[j]] + DA[(size_t)j * nva + EA[i]]) / sA;
    for (int i = 0; i < nb; i++)
        for (int j = 0; j < nb; j++)
            dB[i][j] = 0.5 * (DB[(size_t)i * nvb + EB[j]] + DB[(size_t)j * nvb + EB[i]]) / sB;

    /* beam search: every pair of matched extremities whose distances agree
     * to within tau scores tau - |dA - dB| */
    double tau = p->penalty;
    int W = p->beam > 0 ? p->beam : 1, nbeam = 1;
    beam = calloc((size_t)W * (nb + 1), sizeof *beam);
    next = calloc((size_t)W * (nb + 1), sizeof *next);
    if (!beam || !next) { cm_seterr("out of memory"); goto done; }
    for (int i = 0; i < 32; i++) beam[0].m[i] = -1;
    for (int i = 0; i < na; i++) {
        int nn = 0;
        for (int s = 0; s < nbeam; s++)
            for (int c = -1; c < nb; c++) {
                if (c >= 0 && (beam[s].used >> c & 1)) continue;
                struct state x = beam[s];
                x.m[i] = c;
                if (c >= 0) {
                    x.used |= 1u << c;
                    x.score -= p->disc_weight * tau * disc_cost(aA[i], aB[c]);
                    for (int j = 0; j < i; j++)
                        if (x.m[j] >= 0) {
                            double e = fabs(dA[i][j] - dB[c][x.m[j]]);
                            x.score += e < tau ? tau - e : 0;
                        }
                }
                next[nn++] = x;
            }
        qsort(next, nn, sizeof *next, cmp_state);
        nbeam = nn < W ? nn : W;
        struct state *tmp = beam; beam = next; next = tmp;
    }
    /* orientation among the near-best maps */
    double cA[3], cB[3];
    area_centroid(VA, FA, nfa, cA);
    area_centroid(VB, FB, nfb, cB);
    double best = beam[0].score, pick = -1e300;
    int ib = -1;
    out->orient_mirror = -2;
    for (int s = 0; s < nbeam; s++) {
        if (beam[s].score < (1 - p->margin) * best) break;
        int k = 0;
        for (int i = 0; i < na; i++) k += beam[s].m[i] >= 0;
        if (k < 3) continue;
        double o = orientation(VA, EA, cA, VB, EB, cB, beam[s].m, na);
        double v = beam[s].score / (best > 0 ? best : 1) + o;
        if (v > pick) {
            if (ib >= 0 && o < out->orient) out->orient_mirror = out->orient;
            pick = v; ib = s; out->orient = o;
        } else if (out->orient_mirror < -1 || o < out->orient_mirror)
            out->orient_mirror = o;
    }
    if (ib < 0) { cm_seterr("landmarks: fewer than 3 extremities of the two meshes match"); goto done; }
    /* the candidates: the near-best map for each weight of the orientation,
     * each tested by deformation; the best fit wins (see the header, 3.) */
    if (p->verify) {
        static const double wo[4] = {1, 0.5, 0.25, 0};
        int cand[4], nc = 0;
        for (int q = 0; q < 4; q++) {
            double pk = -1e300;
            int is = -1;
            for (int s = 0; s < nbeam; s++) {
                if (beam[s].score < (1 - p->margin) * best) break;
                int k = 0;
                for (int i = 0; i < na; i++) k += beam[s].m[i] >= 0;
                if (k < 3) continue;
                double v = beam[s].score / (best > 0 ? best : 1) +
                           wo[q] * orientation(VA, EA, cA, VB, EB, cB, beam[s].m, na);
                if (v > pk) { pk = v; is = s; }
            }
            int dup = is < 0;
            for (int c = 0; c < nc; c++) dup |= cand[c] == is;
            if (!dup) cand[nc++] = is;
        }
        double f[4];
        int ok = nc > 1;
        if (ok) {
            struct topology tA = {0};
            struct closest_point_tree *TB = NULL;
            if (topology_build(FA, nfa, nva, &tA) < 0 || !(TB = closest_point_tree_new(VB, nvb, FB, nfb))) {
                topology_free(&tA);
                goto done;
            }
            int closed = tA.nboundary == 0 && tA.nnonmanifold == 0;
            topology_free(&tA);
            for (int c = 0; c < nc && ok; c++)
                ok = map_fit(VA, FA, nva, nfa, closed, VB, nvb, TB, EA, EB, beam[cand[c]].m, na, sB, f + c) == 0;
            closest_point_tree_free(TB);
            if (!ok) {      /* kept: the map of score + orientation, said in why */
                snprintf(out->why, sizeof out->why, "%s", cm_errmsg());
                out->verified = -1;
            }
        }
        if (ok) {
            int b = 0, chosen = ib;
            for (int c = 1; c < nc; c++) if (f[c] < f[b]) b = c;
            ib = cand[b];
            out->verified = nc;
            out->fit = f[b];
            out->fit_next = INFINITY;
            for (int c = 0; c < nc; c++) if (c != b && f[c] < out->fit_next) out->fit_next = f[c];
            out->changed = ib != chosen;
            if (out->changed) {     /* the orientations of the chosen map and of the most mirrored other */
                out->orient = orientation(VA, EA, cA, VB, EB, cB, beam[ib].m, na);
                out->orient_mirror = -2;
                for (int s = 0; s < nbeam; s++) {
                    if (beam[s].score < (1 - p->margin) * best) break;
                    int k = 0;
                    for (int i = 0; i < na; i++) k += beam[s].m[i] >= 0;
                    if (k < 3 || s == ib) continue;
                    double o = orientation(VA, EA, cA, VB, EB, cB, beam[s].m, na);
                    if (out->orient_mirror < -1 || o < out->orient_mirror) out->orient_mirror = o;
                }
            }
        }
    }
    int *m = beam[ib].m;
    /* drop matched extremities that disagree with the rest on average (a
     * spurious bump matched to some other bump) */
    for (;;) {
        int worst = -1, cnt = 0;
        double wv = 0;
        for (int i = 0; i < na; i++) cnt += m[i] >= 0;
        if (cnt <= 3) break;
        for (int i = 0; i < na; i++) {
            if (m[i] < 0) continue;
            double e = 0;
            for (int j = 0; j < na; j++)
                if (j != i && m[j] >= 0) e += fabs(dA[i][j] - dB[m[i]][m[j]]);
            e /= cnt - 1;
            if (e > wv) { wv = e; worst = i; }
        }
        if (wv <= 0.5 * tau) break;
        m[worst] = -1;
    }
    /* second chance for the extremities left over: a limb stretched far
     * in one pose is not isometric to the other (its tip's distances off
     * by up to tau), so the search and the pruning above drop it, and the
     * registration never reaches that limb.  Pair a leftover of A with a
     * leftover of B when each is the other's clear best (mean mismatch to
     * the matched extremities below tau, the runner-up at least
     * p->second_ratio times worse in both directions, no single distance
     * off by more than 2 tau, both tips on average at least as far from the
     * matched ones as these are from each other: a limb, not a bump). */
    if (p->second_ratio > 0)
        for (int added = 1; added;) {
            added = 0;
            int cnt = 0;
            unsigned usedb = 0;
            for (int i = 0; i < na; i++)
                if (m[i] >= 0) { cnt++; usedb |= 1u << m[i]; }
            if (cnt < 3) break;
            /* only tips at least as far out as the matched ones on
             * average (a stretched limb; not a bump on the body) */
            double eccA = 0, eccB = 0, ecc[32], eccb[32];
            for (int i = 0; i < na; i++) {
                ecc[i] = 0;
                for (int j = 0; j < na; j++) if (m[j] >= 0) ecc[i] += dA[i][j] / cnt;
                if (m[i] >= 0) eccA += ecc[i] / cnt;
            }
            for (int c = 0; c < nb; c++) {
                eccb[c] = 0;
                for (int j = 0; j < na; j++) if (m[j] >= 0) eccb[c] += dB[c][m[j]] / cnt;
            }
            for (int j = 0; j < na; j++) if (m[j] >= 0) eccB += eccb[m[j]] / cnt;
            double err[32][32];
            for (int i = 0; i < na; i++)
                for (int c = 0; c < nb; c++) {
                    err[i][c] = INFINITY;
                    if (m[i] >= 0 || (usedb >> c & 1)) continue;
                    if (ecc[i] < eccA || eccb[c] < eccB) continue;
                    double e = 0, emax = 0;
                    for (int j = 0; j < na; j++)
                        if (m[j] >= 0) {
                            double x = fabs(dA[i][j] - dB[c][m[j]]);
                            e += x;
                            if (x > emax) emax = x;
                        }
                    if (emax > 2 * tau) continue;   /* one distance far off: another limb */
                    err[i][c] = e / cnt + p->disc_weight * tau * disc_cost(aA[i], aB[c]) / cnt;
                }
            double bestv = INFINITY;
            int bi = -1, bc = -1;
            for (int i = 0; i < na; i++)
                for (int c = 0; c < nb; c++) {
                    double e = err[i][c];
                    if (!(e < tau) || e >= bestv) continue;
                    int clear = 1;
                    for (int x = 0; x < nb && clear; x++)
                        if (x != c && err[i][x] < p->second_ratio * e) clear = 0;
                    for (int x = 0; x < na && clear; x++)
                        if (x != i && err[x][c] < p->second_ratio * e) clear = 0;
                    if (clear) { bestv = e; bi = i; bc = c; }
                }
            if (bi >= 0) { m[bi] = bc; added = 1; out->second++; }
        }
    int k = 0;
    double cost = 0; int npairs = 0;
    for (int i = 0; i < na; i++) {
        if (m[i] < 0) continue;
        k++;
        for (int j = i + 1; j < na; j++)
            if (m[j] >= 0) { cost += fabs(dA[i][j] - dB[m[i]][m[j]]); npairs++; }
    }
    out->matched = k;
    out->cost = npairs ? cost / npairs : 0;
    int cap = k * (1 + p->nlimb) + 1;
    out->a = malloc((size_t)cap * sizeof *out->a);
    out->b = malloc((size_t)cap * sizeof *out->b);
    out->kind = malloc((size_t)cap * sizeof *out->kind);
    if (!out->a || !out->b || !out->kind) { cm_seterr("out of memory"); goto done; }
    for (int i = 0; i < na; i++)
        if (m[i] >= 0) {
            out->a[out->n] = EA[i]; out->b[out->n] = EB[m[i]]; out->kind[out->n++] = 0;
        }
    /* cores: the smallest sum of distances to the matched extremities */
    int coreA = 0, coreB = 0;
    double bestA = INFINITY, bestB = INFINITY;
    for (int v = 0; v < nva; v++) {
        double sum = 0;
        for (int i = 0; i < na; i++) if (m[i] >= 0) sum += DA[(size_t)i * nva + v];
        if (sum < bestA) { bestA = sum; coreA = v; }
    }
    for (int v = 0; v < nvb; v++) {
        double sum = 0;
        for (int i = 0; i < na; i++) if (m[i] >= 0) sum += DB[(size_t)m[i] * nvb + v];
        if (sum < bestB) { bestB = sum; coreB = v; }
    }
    /* limb points: on the ring at distance t x (distance to the nearest
     * other matched extremity, in A) from each tip, the vertex with the
     * smallest sum of distances to the other matched extremities (the
     * inner side of the limb, on the way to the body) */
    for (int l = 0; l < p->nlimb; l++)
        for (int i = 0; i < na; i++) {
            if (m[i] < 0) continue;
            double near = INFINITY;
            for (int j = 0; j < na; j++)
                if (j != i && m[j] >= 0 && dA[i][j] < near) near = dA[i][j];
            int pv[2] = {-1, -1};
            for (int side = 0; side < 2; side++) {
                int n = side ? nvb : nva;
                double sc = side ? sB : sA, r = p->limb_t[l] * near * sc, band = 0.02 * sc, bb = INFINITY;
                const double *De = side ? DB + (size_t)m[i] * nvb : DA + (size_t)i * nva;
                for (int v = 0; v < n; v++) {
                    if (fabs(De[v] - r) > band) continue;
                    double sum = 0;
                    for (int j = 0; j < na; j++)
                        if (j != i && m[j] >= 0)
                            sum += side ? DB[(size_t)m[j] * nvb + v] : DA[(size_t)j * nva + v];
                    if (sum < bb) { bb = sum; pv[side] = v; }
                }
            }
            if (pv[0] < 0 || pv[1] < 0) continue;
            out->a[out->n] = pv[0]; out->b[out->n] = pv[1]; out->kind[out->n++] = 1;
        }
    if (p->core) { out->a[out->n] = coreA; out->b[out->n] = coreB; out->kind[out->n++] = 2; }
    rc = 0;
done:
    if (rc < 0 && out->a) { int na2 = out->na, nb2 = out->nb; landmark_pairs_free(out); out->na = na2; out->nb = nb2; }
    geodesic_free(gA);
    geodesic_free(gB);
    free(EA); free(EB); free(DA); free(DB); free(beam); free(next);
    return rc;
}
