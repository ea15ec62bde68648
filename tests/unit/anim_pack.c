/* unit tests: base64 round trips and RFC 4648 vectors; anim_pack positions
 * decode (as the page does) to within the stated bound, which is below 1e-4
 * of the bounding box diagonal. */
#include "anim_pack.h"
#include "base64.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static void vector(const char *in, const char *want)
{
    char out[64] = {0};
    base64_encode(in, strlen(in), out);
    ok(!strcmp(out, want) && base64_len(strlen(in)) == strlen(want), "base64: '%s' -> '%s' (got '%s')",
       in, want, out);
}

int main(void)
{
    vector("", "");
    vector("f", "Zg==");
    vector("fo", "Zm8=");
    vector("foo", "Zm9v");
    vector("foob", "Zm9vYg==");
    vector("fooba", "Zm9vYmE=");
    vector("foobar", "Zm9vYmFy");

    /* round trip of every length 0..300 of arbitrary bytes */
    unsigned char bytes[300], back[300];
    char text[400];
    int good = 1;
    for (int i = 0; i < 300; i++) bytes[i] = (unsigned char)(i * 37 + 11);
    for (size_t n = 0; n <= 300; n++) {
        base64_encode(bytes, n, text);
        long m = base64_decode(text, base64_len(n), back);
        if (m != (long)n || memcmp(bytes, back, n)) good = 0;
    }
    ok(good, "base64: decode(encode(x)) == x for lengths 0..300");
    ok(base64_decode("Zm9v!A==", 8, back) < 0, "base64: a bad character is an error");
    ok(base64_decode("Zm9", 3, back) < 0, "base64: a length not a multiple of 4 is an error");

    /* an animation: 500 vertices, 40 frames of random motion in a 3 x 0.5 x 0.01 box
     * (one flat axis: its step is small, the others large) */
    int nv = 500, nf = 40;
    size_t m = (size_t)nv * 3;
    double *X = malloc((size_t)nf * m * sizeof *X);
    struct rng r;
    rng_seed(&r, 7);
    for (size_t i = 0; i < (size_t)nf * m; i++) {
        int a = i % 3;
        X[i] = (a == 0 ? 3 : a == 1 ? 0.5 : 0.01) * rng_uniform(&r) - 1;
    }
    double lo[3], hi[3], err;
    anim_pack_bbox(X, (size_t)nf * nv, lo, hi);
    unsigned char *P = malloc((size_t)nf * m * 2), *Z, *U = malloc((size_t)nf * m * 2);
    size_t zn;
    anim_pack_positions(X, nf, nv, lo, hi, P, &err);
    int rc = anim_pack_deflate(P, (size_t)nf * m * 2, &Z, &zn);
    ok(rc == 0, "deflate: %zu -> %zu bytes", (size_t)nf * m * 2, zn);
    ok(anim_pack_inflate(Z, zn, U, (size_t)nf * m * 2) == 0 && !memcmp(P, U, (size_t)nf * m * 2),
       "inflate gives the packed bytes back");
    ok(anim_pack_inflate(Z, zn, U, (size_t)nf * m * 2 - 1) < 0, "inflate: a wrong length is an error");
    /* decode like web/anim-view.js */
    uint16_t *prev = calloc(m, sizeof *prev);
    double worst = 0, diag = sqrt(pow(hi[0] - lo[0], 2) + pow(hi[1] - lo[1], 2) + pow(hi[2] - lo[2], 2));
    for (int k = 0; k < nf; k++)
        for (size_t v = 0; v < (size_t)nv; v++) {
            double e2 = 0;
            for (int a = 0; a < 3; a++) {
                size_t i = 3 * v + a;
                const unsigned char *b = U + (size_t)k * m * 2;
                prev[i] = (uint16_t)(prev[i] + (b[i] | b[m + i] << 8));
                double x = lo[a] + prev[i] * (hi[a] - lo[a]) / 65535;
                e2 += pow(x - X[(size_t)k * m + i], 2);
            }
            if (sqrt(e2) > worst) worst = sqrt(e2);
        }
    double bound = anim_pack_bound(lo, hi);
    diag("decoded error %.3g, reported %.3g, bound %.3g, diagonal %.4g", worst, err, bound, diag);
    ok(fabs(worst - err) <= 1e-12 * diag, "the reported error is the decoded error");
    ok(worst <= bound * (1 + 1e-9), "decoded error <= |hi - lo| / 131070");
    ok(worst / diag < 1e-4 && bound / diag < 1e-5, "decoded error %.2g of the diagonal, below 1e-4", worst / diag);
    ok(lo[0] >= -1 && lo[0] < -0.99 && hi[0] > 1.99 && hi[0] <= 2, "bbox spans the data");

    /* a flat axis (all z equal) quantises to exactly 0 error on it */
    for (size_t i = 2; i < (size_t)nf * m; i += 3) X[i] = 0.25;
    anim_pack_bbox(X, (size_t)nf * nv, lo, hi);
    ok(lo[2] == 0.25 && hi[2] == 1.25, "flat axis: box widened to [z, z + 1]");
    free(X); free(P); free(Z); free(U); free(prev);
    return tap_done();
}
