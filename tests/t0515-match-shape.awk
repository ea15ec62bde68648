# t0515-match-shape.awk -- a three-lobed outline with a known correspondence:
# vertex i of pose 0 (n = 120) is at polar angle 2 pi i / 120; vertex j of
# pose 1 (n = 90, starting at angle index 17) at 2 pi (j + 17) / 90.  Pose 1
# has its upper left lobe stretched twice, is turned by 25 degrees and scaled
# by 1.5, so arc length from a common start does not give the correspondence.
# Points at angle 2 pi k / 30 are vertex 4k of pose 0 and (3k - 17) mod 90
# of pose 1.
# usage: awk -v pose=0|1 [-v reverse=1] -f t0515-match-shape.awk
BEGIN {
    pi = atan2(0, -1)
    n = pose ? 90 : 120
    off = pose ? 17 : 0
    printf "ring %d\n", n
    for (k = 0; k < n; k++) {
        j = reverse ? n - 1 - k : k
        t = 2 * pi * (j + off) / n
        r = 1 + 0.35 * cos(3 * t) + 0.12 * sin(5 * t)
        if (pose) {
            d = (t - 2 * pi / 3) / 0.45
            while (d > pi / 0.45) d -= 2 * pi / 0.45
            r *= 1 + 1.0 * exp(-d * d)
        }
        x = r * cos(t); y = r * sin(t)
        if (pose) {
            a = 25 * pi / 180
            u = 1.5 * (cos(a) * x - sin(a) * y) + 3; v = 1.5 * (sin(a) * x + cos(a) * y) - 1
            x = u; y = v
        }
        printf "%.9f %.9f\n", x, y
    }
}
