/* predicates2: the inline orient2_sign and segments_meet (a floating-point
 * filter, CGAL where it cannot decide) give CGAL's answers: random points,
 * points on a grid (many exactly collinear), points on a segment to the
 * last bit (rounded: just off it), shared endpoints, degenerate segments */
#include "predicates2.h"
#include "rng.h"
#include "tap.h"

int main(void)
{
    struct rng r;
    rng_seed(&r, 7);
    long n = 0, collinear = 0, meet = 0, bad_o = 0, bad_s = 0;
    for (long it = 0; it < 400000; it++) {
        double P[8];
        int mode = it % 6;
        for (int k = 0; k < 8; k++) {
            double u = rng_uniform(&r);
            P[k] = mode == 0 ? u : mode == 1 ? (double)(int)(u * 6) : 600 * u;
        }
        if (mode >= 2) {   /* c on ab (rounded); d on ab too, or at b */
            double t = rng_uniform(&r);
            P[4] = P[0] + t * (P[2] - P[0]);
            P[5] = P[1] + t * (P[3] - P[1]);
            if (mode == 3) { P[6] = P[0] + 2 * t * (P[2] - P[0]); P[7] = P[1] + 2 * t * (P[3] - P[1]); }
            if (mode == 4) { P[6] = P[2]; P[7] = P[3]; }
            if (mode == 5) { P[2] = P[0]; P[3] = P[1]; }   /* ab a point */
        }
        int oe = orient2_sign_exact(P, P + 2, P + 4), se = segments_meet_exact(P, P + 2, P + 4, P + 6);
        bad_o += orient2_sign(P, P + 2, P + 4) != oe;
        bad_s += segments_meet(P, P + 2, P + 4, P + 6) != se;
        n++;
        collinear += oe == 0;
        meet += se;
    }
    diag("%ld cases, %ld collinear, %ld meeting", n, collinear, meet);
    ok(collinear > 1000 && meet > 1000, "predicates2: the cases include collinear points and meeting segments");
    ok(bad_o == 0, "predicates2: orient2_sign is CGAL's exact sign (%ld differ)", bad_o);
    ok(bad_s == 0, "predicates2: segments_meet is CGAL's do_intersect (%ld differ)", bad_s);
    return tap_done();
}
