/* mesh-io -- benchmark driver for the MESH reader and writer.
 *
 *   mesh-io read FILE        read every frame with mesh_reader; prints
 *                            "bytes B seconds S frames K"
 *   mesh-io write FILE OUT   read FILE into memory (all frames), then time
 *                            writing it with mesh_write to OUT in the same
 *                            variant as FILE; prints "bytes B seconds S
 *                            frames K cpu C" (wall and CPU seconds of the
 *                            writing alone; B = size of FILE)
 */
#include "mesh.h"
#include "cm_error.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 3 || (strcmp(argv[1], "read") && strcmp(argv[1], "write")) ||
        (!strcmp(argv[1], "write") && argc < 4)) {
        fprintf(stderr, "usage: mesh-io read FILE | mesh-io write FILE OUT\n");
        return 2;
    }
    struct stat st;
    if (stat(argv[2], &st) != 0) { perror(argv[2]); return 1; }
    if (!strcmp(argv[1], "read")) {
        double t0 = now();
        struct mesh_reader r;
        if (mesh_reader_open(&r, argv[2]) < 0) { fprintf(stderr, "%s\n", cm_errmsg()); return 1; }
        double *X = malloc(((size_t)r.nv * 3 + 1) * sizeof *X), sum = 0;
        int rc, k = 0;
        while ((rc = mesh_reader_next(&r, X, NULL)) > 0) { sum += X[0]; k++; }
        if (rc < 0) { fprintf(stderr, "%s\n", cm_errmsg()); return 1; }
        mesh_reader_close(&r);
        double t = now() - t0;
        printf("bytes %lld seconds %.6f frames %d check %g\n", (long long)st.st_size, t, k, sum);
        free(X);
        return 0;
    }
    struct mesh m;
    if (mesh_read(argv[2], &m) < 0) { fprintf(stderr, "%s\n", cm_errmsg()); return 1; }
    int raw;
    { FILE *f = fopen(argv[2], "rb"); char b[16] = ""; fgets(b, sizeof b, f); fclose(f); raw = !strncmp(b, "MESH 1 raw", 10); }
    FILE *out = fopen(argv[3], "wb");
    if (!out) { perror(argv[3]); return 1; }
    double t0 = now(), c0 = cpu();
    if (mesh_write(out, &m, raw) < 0 || fclose(out) != 0) {
        fprintf(stderr, "%s\n", cm_errmsg());
        return 1;
    }
    double t = now() - t0, c = cpu() - c0;
    printf("bytes %lld seconds %.6f frames %d cpu %.6f\n", (long long)st.st_size, t, m.nframes, c);
    mesh_free(&m);
    return 0;
}
