/* mesh_stream: plain_round_trip_is_bit_exact (random coordinates of every
 * magnitude, -0, values that are ties for the fast parser, lines across
 * buffer refills), raw_round_trip, frames_unknown, cut_marks, reader
 * return codes, whole-mesh read/write, read-ahead on a second thread
 * (mesh_prefetch: same frames, cuts and errors as mesh_reader_next),
 * big text output formatted on threads (same bytes as frame by frame) */
#include "mesh.h"
#include "mesh_prefetch.h"
#include "cm_error.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static double random_coord(struct rng *r)
{
    switch (rng_int(r, 8)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return (double)rng_int(r, 1000) / 1000;              /* short decimals */
    case 3: return rng_normal(r) * 1e-19;                         /* roundoff noise */
    case 4: return rng_normal(r) * pow(10, rng_int(r, 60) - 30);  /* any magnitude */
    case 5: { uint64_t u = rng_u64(r); double x; memcpy(&x, &u, 8); return isfinite(x) ? x : 1.5; }
    case 6: return 0.02164619265807541;                           /* a parser tie */
    default: return rng_uniform(r) * 2 - 1;
    }
}

int main(void)
{
    struct rng r;
    rng_seed(&r, 3);
    int nv = 40000, nf = 2, nframes = 4;   /* > 1 MB per plain frame: buffer refills */
    int F[6] = {0, 1, 2, 2, 1, 3};
    double *V = malloc(sizeof *V * 3 * nv * nframes);
    for (long i = 0; i < 3L * nv * nframes; i++) V[i] = random_coord(&r);
    char path[] = "/tmp/stopmo-mesh-XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0) { printf("Bail out! mkstemp\n"); return 1; }
    close(fd);

    for (int raw = 0; raw <= 1; raw++) {
        for (int known = 0; known <= 1; known++) {
            FILE *f = fopen(path, "wb");
            struct mesh_writer w;
            int ok_w = mesh_writer_open(&w, f, nv, nf, F, known ? nframes : -1, raw) == 0;
            for (int k = 0; k < nframes; k++)
                ok_w &= mesh_writer_frame(&w, V + 3L * nv * k, k == 2) == 0;
            ok_w &= mesh_writer_close(&w) == 0;
            ok_w &= fclose(f) == 0;
            ok(ok_w, "mesh_writer: %s, frames %s", raw ? "raw" : "plain", known ? "known" : "?");

            struct mesh_reader rd;
            int rc = mesh_reader_open(&rd, path);
            ok(rc == 0 && rd.nv == nv && rd.nf == nf && rd.raw == raw &&
               rd.nframes == (known ? nframes : -1) && !memcmp(rd.F, F, sizeof F),
               "mesh_reader_open: header and faces (%s)", rc ? cm_errmsg() : "");
            double *X = malloc(sizeof *X * 3 * nv);
            int frames = 0, exact = 1, cuts_ok = 1, cut;
            while ((rc = mesh_reader_next(&rd, X, &cut)) == 1) {
                exact &= !memcmp(X, V + 3L * nv * frames, sizeof *X * 3 * nv);
                cuts_ok &= cut == (frames == 2);
                frames++;
            }
            ok(rc == 0 && frames == nframes, "mesh_reader_next: %d frames, then 0 (%s)", frames,
               rc ? cm_errmsg() : "");
            ok(exact, "%s round trip is bit-exact (every magnitude, -0, ties)",
               raw ? "raw" : "plain");
            ok(cuts_ok, "cut marks survive (%s)", raw ? "raw" : "plain");
            mesh_reader_close(&rd);
            free(X);
        }
    }

    /* read-ahead (the file holds the last stream: raw, frames known), with
     * the smallest ring: the reader waits for the caller at every frame */
    {
        struct mesh_reader rd;
        struct mesh_prefetch pf;
        int rc = mesh_reader_open(&rd, path), frames = 0, exact = 1, cut;
        ok(rc == 0 && mesh_prefetch_start(&pf, &rd, 2) == 0, "mesh_prefetch_start");
        const double *X;
        while ((rc = mesh_prefetch_next(&pf, &X, &cut)) == 1 && frames < nframes) {
            exact &= !memcmp(X, V + 3L * nv * frames, sizeof *X * 3 * nv) && cut == (frames == 2);
            frames++;
        }
        ok(rc == 0 && frames == nframes && exact, "mesh_prefetch_next: %d frames in order, cuts, then 0", frames);
        ok(mesh_prefetch_next(&pf, &X, &cut) == 0, "mesh_prefetch_next: 0 again after the end");
        mesh_prefetch_stop(&pf);
        mesh_reader_close(&rd);
    }

    /* whole-mesh interface */
    struct mesh m;
    ok(mesh_read(path, &m) == 0 && m.nframes == nframes && mesh_nclips(&m) == 2 &&
       !memcmp(mesh_frame(&m, 3), V + 3L * nv * 3, sizeof(double) * 3 * nv),
       "mesh_read: frames, clips, positions");
    FILE *f = fopen(path, "wb");
    ok(mesh_write(f, &m, 0) == 0, "mesh_write");
    fclose(f);
    mesh_free(&m);
    ok(mesh_read(path, &m) == 0 && !memcmp(m.V, V, sizeof(double) * 3 * nv * nframes),
       "mesh_write/mesh_read: bit-exact");
    mesh_free(&m);

    /* a truncated plain stream: the reader reports it, names the file */
    f = fopen(path, "wb");
    fputs("MESH 1\nvertices 2\nfaces 0\nframes 2\nframe 0\n1 2 3\n4 5 6\nframe 1\n1 2 3\n", f);
    fclose(f);
    ok(mesh_read(path, &m) < 0 && strstr(cm_errmsg(), path) && strstr(cm_errmsg(), "truncated"),
       "mesh_read: truncated frame reported (%s)", cm_errmsg());
    {
        /* the same through the read-ahead: one frame, then the reader's message */
        struct mesh_reader rd;
        struct mesh_prefetch pf;
        char direct[1024];
        double X2[6];
        mesh_reader_open(&rd, path);
        int r1 = mesh_reader_next(&rd, X2, NULL), r2 = mesh_reader_next(&rd, X2, NULL);
        snprintf(direct, sizeof direct, "%s", cm_errmsg());
        mesh_reader_close(&rd);
        mesh_reader_open(&rd, path);
        mesh_prefetch_start(&pf, &rd, 4);
        const double *X;
        int p1 = mesh_prefetch_next(&pf, &X, NULL);
        int first_ok = p1 == 1 && X[0] == 1 && X[5] == 6;
        cm_seterr("-");
        int p2 = mesh_prefetch_next(&pf, &X, NULL);
        ok(r1 == 1 && r2 < 0 && first_ok && p2 < 0 && !strcmp(cm_errmsg(), direct),
           "mesh_prefetch_next: the good frame, then the reader's error (%s)", cm_errmsg());
        mesh_prefetch_stop(&pf);
        mesh_prefetch_stop(&pf);
        mesh_reader_close(&rd);
    }
    {
        /* a text mesh big enough for mesh_write's threads (several jobs
         * per frame, more jobs than ring slots, cut marks, a frame whose
         * last job is short): the same bytes as frame by frame */
        struct mesh b;
        struct rng rb;
        rng_seed(&rb, 7);
        mesh_alloc(&b, 9000, 1, 11);
        b.F[0] = 0; b.F[1] = 1; b.F[2] = 2;
        for (size_t i = 0; i < (size_t)9000 * 3 * 11; i++) b.V[i] = random_coord(&rb);
        b.cut[0] = 1; b.cut[4] = 1; b.cut[9] = 1;
        char *p1 = NULL, *p2 = NULL;
        size_t n1 = 0, n2 = 0;
        FILE *f1 = open_memstream(&p1, &n1), *f2 = open_memstream(&p2, &n2);
        int r1 = mesh_write(f1, &b, 0);
        struct mesh_writer w2;
        int r2 = mesh_writer_open(&w2, f2, b.nv, b.nf, b.F, b.nframes, 0);
        for (int k = 0; k < b.nframes && r2 == 0; k++) r2 = mesh_writer_frame(&w2, mesh_frame(&b, k), b.cut[k]);
        if (r2 == 0) r2 = mesh_writer_close(&w2);
        fclose(f1); fclose(f2);
        ok(r1 == 0 && r2 == 0 && n1 == n2 && n1 > 0 && !memcmp(p1, p2, n1),
           "mesh_write: a big text mesh (threads) has the bytes of mesh_writer_frame (%zu, %zu)", n1, n2);
        free(p1); free(p2);
        FILE *full = fopen("/dev/full", "wb");
        if (full) {
            ok(mesh_write(full, &b, 0) < 0 && strstr(cm_errmsg(), "write error"),
               "mesh_write: a full disk is reported (%s)", cm_errmsg());
            fclose(full);
        } else
            ok(1, "# SKIP no /dev/full");
        mesh_free(&b);
    }
    /* a writer that is given too many frames refuses */
    f = fopen(path, "wb");
    struct mesh_writer w;
    double x3[3] = {0, 0, 0};
    mesh_writer_open(&w, f, 1, 0, NULL, 1, 0);
    mesh_writer_frame(&w, x3, 0);
    ok(mesh_writer_frame(&w, x3, 0) < 0, "mesh_writer_frame: more than announced refused");
    fclose(f);
    f = fopen(path, "wb");
    mesh_writer_open(&w, f, 1, 0, NULL, 2, 0);
    mesh_writer_frame(&w, x3, 0);
    ok(mesh_writer_close(&w) < 0, "mesh_writer_close: fewer than announced reported");
    fclose(f);
    unlink(path);
    free(V);
    return tap_done();
}
