/* closest_point.c -- unit tests of the nearest-triangle walk (against brute
 * force over every triangle, with and without hints, degenerate triangles)
 * and of frame_compare (against one_sided_distance and flipped_face_flags);
 * closest_points_batch against closest_points, bit for bit. */
#include "tap.h"
#include "testmesh.h"
#include "closest_point.h"
#include "mesh_distance.h"
#include "rng.h"
#include <math.h>
#include <string.h>

/* brute force: the smallest distance to any triangle, by dense sampling of
 * each triangle's closest point with the plain formula on its plane */
static double seg_d2(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3], t = 0, l = 0, s = 0;
    for (int d = 0; d < 3; d++) { ab[d] = b[d] - a[d]; ap[d] = p[d] - a[d]; t += ab[d] * ap[d]; l += ab[d] * ab[d]; }
    t = l > 0 ? t / l : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (int d = 0; d < 3; d++) { double e = ap[d] - t * ab[d]; s += e * e; }
    return s;
}
static double tri_d2(const double *p, const double *a, const double *b, const double *c)
{
    double u[3], v[3], n[3], w[3];
    for (int d = 0; d < 3; d++) { u[d] = b[d] - a[d]; v[d] = c[d] - a[d]; w[d] = p[d] - a[d]; }
    n[0] = u[1] * v[2] - u[2] * v[1]; n[1] = u[2] * v[0] - u[0] * v[2]; n[2] = u[0] * v[1] - u[1] * v[0];
    double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2], best = seg_d2(p, a, b);
    double e = seg_d2(p, b, c); if (e < best) best = e;
    e = seg_d2(p, c, a); if (e < best) best = e;
    if (nn > 0) {
        double h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn, q[3], s1[3], s2[3], s3[3];
        for (int d = 0; d < 3; d++) q[d] = p[d] - h * n[d];
        /* inside test by signed areas */
        double in = 1;
        const double *T[3] = {a, b, c};
        for (int k = 0; k < 3; k++) {
            const double *x = T[k], *y = T[(k + 1) % 3];
            for (int d = 0; d < 3; d++) { s1[d] = y[d] - x[d]; s2[d] = q[d] - x[d]; }
            s3[0] = s1[1] * s2[2] - s1[2] * s2[1]; s3[1] = s1[2] * s2[0] - s1[0] * s2[2]; s3[2] = s1[0] * s2[1] - s1[1] * s2[0];
            if (s3[0] * n[0] + s3[1] * n[1] + s3[2] * n[2] < 0) in = 0;
        }
        if (in) { double hh = h * h * nn; if (hh < best) best = hh; }
    }
    return best;
}

/* for closest_point_faces_within_visit: collect, never stop */
static int visit_collect(int f, void *ctx)
{
    struct { int *seen, n; } *c = ctx;
    if (c->n < 512) c->seen[c->n] = f;
    c->n++;
    return 0;
}

int main(void)
{
    double *V; int *F, nv, nf;
    cylinder_mesh(24, 10, &V, &F, &nv, &nf);
    /* bend it and squash two triangles to slivers / points */
    for (int i = 0; i < nv; i++) { double z = V[3 * i + 2]; V[3 * i] += 0.3 * z * z; }
    memcpy(V + 3 * F[3 * 5 + 1], V + 3 * F[3 * 5], 3 * sizeof *V);
    struct closest_point_tree *T = closest_point_tree_new(V, nv, F, nf);
    ok(T != NULL, "tree of %d faces", nf);
    struct rng r;
    rng_seed(&r, 7);
    int n = 3000, bad = 0, badh = 0, badf = 0;
    double *P = malloc(sizeof(double) * 3 * n), *D = malloc(sizeof(double) * n), *Dh = malloc(sizeof(double) * n);
    double *B = malloc(sizeof(double) * 3 * n), *C = malloc(sizeof(double) * 3 * n);
    int *I = malloc(sizeof(int) * n), *H = malloc(sizeof(int) * n);
    for (int i = 0; i < 3 * n; i++) P[i] = 3 * rng_uniform(&r) - 1.5;
    closest_points(T, P, n, C, I, B, D);
    for (int i = 0; i < n; i++) {
        double best = 1e300;
        for (int f = 0; f < nf; f++) {
            double e = tri_d2(P + 3 * i, V + 3 * F[3 * f], V + 3 * F[3 * f + 1], V + 3 * F[3 * f + 2]);
            if (e < best) best = e;
        }
        if (fabs(sqrt(best) - D[i]) > 1e-12) bad++;
        /* the closest point is on face I[i] at barycentrics B */
        double q[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++) q[d] += B[3 * i + k] * V[3 * F[3 * I[i] + k] + d];
        double e = 0;
        for (int d = 0; d < 3; d++) e += (q[d] - C[3 * i + d]) * (q[d] - C[3 * i + d]);
        if (e > 1e-20) badf++;
        H[i] = (i * 7919) % nf;   /* poor hints: the answer must not change */
    }
    ok(bad == 0, "closest distances equal brute force (%d of %d differ)", bad, n);
    ok(badf == 0, "face and barycentrics give the closest point (%d differ)", badf);
    closest_points_hinted(T, P, n, H, NULL, H, NULL, Dh);
    for (int i = 0; i < n; i++) if (Dh[i] != D[i]) badh++;
    ok(badh == 0, "random hints, same distances (%d differ)", badh);
    closest_points_hinted(T, P, n, H, NULL, H, NULL, Dh);
    badh = 0;
    for (int i = 0; i < n; i++) if (Dh[i] != D[i]) badh++;
    ok(badh == 0, "the answers as hints (I aliasing H), same distances (%d differ)", badh);
    /* the wide-tree batch walk: the same distances bit for bit, with poor
     * hints, without hints, with a given order and with its own; the face
     * and barycentrics it names give the closest point */
    {
        double *Db = malloc(sizeof(double) * n), *Bb = malloc(sizeof(double) * 3 * n);
        double *Cb = malloc(sizeof(double) * 3 * n);
        int *Ib = malloc(sizeof(int) * n), *O = malloc(sizeof(int) * n), bd = 0, bf = 0, bi = 0;
        closest_points_order(P, n, O);
        for (int pass = 0; pass < 3; pass++) {
            for (int i = 0; i < n; i++) H[i] = pass == 0 ? (i * 7919) % nf : -1;
            closest_points_batch(T, P, n, pass == 1 ? NULL : H, pass == 2 ? NULL : O, Cb, Ib, Bb, Db);
            for (int i = 0; i < n; i++) {
                if (Db[i] != D[i]) bd++;
                if (Ib[i] != I[i]) bi++;
                double q[3] = {0, 0, 0}, e = 0;
                for (int k = 0; k < 3; k++)
                    for (int d = 0; d < 3; d++) q[d] += Bb[3 * i + k] * V[3 * F[3 * Ib[i] + k] + d];
                for (int d = 0; d < 3; d++) e += (q[d] - Cb[3 * i + d]) * (q[d] - Cb[3 * i + d]);
                if (e > 1e-20) bf++;
            }
        }
        ok(bd == 0, "closest_points_batch: the same distances (%d of %d differ)", bd, 3 * n);
        ok(bf == 0, "closest_points_batch: face and barycentrics give the closest point (%d differ)", bf);
        ok(bi == 0, "closest_points_batch names the faces closest_points names (%d differ)", bi);
        /* ties: at a vertex every face around it is at distance 0; all the
         * query functions name the smallest such id, hints or not */
        {
            int bt = 0, *It = malloc(sizeof(int) * nv), *Ht = malloc(sizeof(int) * nv);
            for (int i = 0; i < nv; i++) Ht[i] = (i * 7919) % nf;
            for (int pass = 0; pass < 4; pass++) {
                if (pass == 0) closest_points(T, V, nv, NULL, It, NULL, NULL);
                if (pass == 1) closest_points_hinted(T, V, nv, Ht, NULL, It, NULL, NULL);
                if (pass == 2) closest_points_batch(T, V, nv, Ht, NULL, NULL, It, NULL, NULL);
                if (pass == 3) closest_points_batch(T, V, nv, NULL, NULL, NULL, It, NULL, NULL);
                for (int i = 0; i < nv; i++) {
                    int want = -1;
                    for (int f = 0; f < nf && want < 0; f++)
                        if (closest_point_on_face(T, f, V + 3 * i, NULL, NULL) == 0) want = f;
                    if (It[i] != want) bt++;
                }
            }
            ok(bt == 0, "ties at the vertices: the smallest face id, with and without hints (%d differ)", bt);
            free(It); free(Ht);
        }
        /* closest_point_faces_within_visit: the faces closest_point_faces_within lists */
        {
            int bw = 0, list[512], seen[512];
            struct { int *seen, n; } vc;
            for (int i = 0; i < 200; i++) {
                double rr = 0.3 * (i % 7) / 6.0;
                int m = closest_point_faces_within(T, P + 3 * i, rr, list, 512);
                vc.seen = seen; vc.n = 0;
                int stop = closest_point_faces_within_visit(T, P + 3 * i, rr, visit_collect, &vc);
                if (stop != 0 || vc.n != m) { bw++; continue; }
                for (int a = 0; a < m; a++) {
                    int found = 0;
                    for (int b = 0; b < m; b++) found |= seen[b] == list[a];
                    if (!found) bw++;
                }
            }
            ok(bw == 0, "closest_point_faces_within_visit visits the faces within r (%d differ)", bw);
        }
        /* one face, and points on the surface itself (distance 0 ties) */
        struct closest_point_tree *T1 = closest_point_tree_new(V, nv, F, 1);
        closest_points_batch(T1, P, 10, NULL, NULL, NULL, NULL, NULL, Db);
        bd = 0;
        for (int i = 0; i < 10; i++) if (Db[i] != closest_point_query(T1, P + 3 * i, Cb, NULL, NULL)) bd++;
        ok(bd == 0, "closest_points_batch on a one-face tree (%d differ)", bd);
        closest_point_tree_free(T1);
        closest_points_batch(T, V, nv, NULL, NULL, NULL, NULL, NULL, Db);
        bd = 0;
        for (int i = 0; i < nv; i++) if (Db[i] > 1e-15) bd++;
        ok(bd == 0, "closest_points_batch: the mesh's own vertices are on it (%d are not)", bd);
        /* beyond the single-precision range: no box may be pruned on an
         * overflowed bound (a mesh at 1e20, queries 1e20 further out) */
        double *Vf = malloc(sizeof(double) * 3 * nv), Pf[6];
        for (int i = 0; i < 3 * nv; i++) Vf[i] = 1e20 * V[i];
        for (int d = 0; d < 3; d++) { Pf[d] = 1e20 * P[d]; Pf[3 + d] = 1e20 * (P[3 + d] + 3); }
        struct closest_point_tree *Tf = closest_point_tree_new(Vf, nv, F, nf);
        int hf[2] = {nf - 1, nf / 2};
        closest_points_batch(Tf, Pf, 2, hf, NULL, NULL, NULL, NULL, Db);
        bd = 0;
        for (int i = 0; i < 2; i++) if (Db[i] != closest_point_query(Tf, Pf + 3 * i, Cb, NULL, NULL)) bd++;
        ok(bd == 0, "closest_points_batch at 1e20 (%d differ)", bd);
        closest_point_tree_free(Tf);
        free(Vf);
        free(Db); free(Bb); free(Cb); free(Ib); free(O);
    }

    /* frame_compare against the one-shot functions, over two frames */
    double *X = malloc(sizeof(double) * 3 * nv);
    struct frame_compare *FC = frame_compare_new(V, nv, F, nf);
    ok(FC != NULL, "frame_compare_new");
    int okall = 1;
    unsigned char *fl = malloc(nf), *fl2 = malloc(nf);
    double *ff = malloc(sizeof(double) * nf);
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < nv; i++)
            for (int d = 0; d < 3; d++) X[3 * i + d] = V[3 * i + d] + 0.05 * k * sin(3 * V[3 * i + (d + 1) % 3] + d);
        if (k == 2) for (int i = 0; i < nv; i++) X[3 * i] = -X[3 * i];   /* mirrored: flipped */
        struct frame_distance fd;
        struct one_sided a, b;
        struct closest_point_tree *TX = closest_point_tree_new(X, nv, F, nf);
        frame_compare_run(FC, X, nv, F, nf, 1e-3, &fd, fl, ff);
        one_sided_distance(X, nv, F, nf, T, &a);
        one_sided_distance(V, nv, F, nf, TX, &b);
        int nfl = flipped_face_flags(X, F, nf, V, nv, F, nf, T, 1e-3, fl2);
        int same = fabs(fd.fit.max - a.max) < 1e-14 && fabs(fd.cover.max - b.max) < 1e-14 &&
                   fabs(fd.fit.sumsq - a.sumsq) < 1e-12 && fabs(fd.cover.sumsq - b.sumsq) < 1e-12 &&
                   fd.flipped == nfl && !memcmp(fl, fl2, nf);
        double mx = 0;
        for (int f = 0; f < nf; f++) if (ff[f] > mx) mx = ff[f];
        same = same && fabs(mx - a.max) < 1e-14;
        if (!same) okall = 0;
        diag("frame %d: fit %g cover %g flipped %d", k, fd.fit.max, fd.cover.max, fd.flipped);
        if (k == 2) ok(fd.flipped > nf / 4, "mirrored frame: %d of %d faces flipped", fd.flipped, nf);
        closest_point_tree_free(TX);
    }
    ok(okall, "frame_compare equals one_sided_distance both ways and flipped_face_flags; face maxima reach the max");
    frame_compare_free(FC);
    closest_point_tree_free(T);
    free(V); free(F); free(P); free(D); free(Dh); free(B); free(C); free(I); free(H); free(X);
    free(fl); free(fl2); free(ff);
    return tap_done();
}
