/* rotation.c -- see rotation.h */
#include "rotation.h"
#include <math.h>

void rot_log(const double R[9], double r[3])
{
    double w[3] = {R[7] - R[5], R[2] - R[6], R[3] - R[1]};   /* 2 sin(th) a */
    double c = 0.5 * (R[0] + R[4] + R[8] - 1);
    if (c > 1) c = 1;
    if (c < -1) c = -1;
    double th = acos(c);
    double s = sin(th);
    if (th < 1e-6) {                       /* R ~ I + [r]x */
        for (int k = 0; k < 3; k++) r[k] = 0.5 * w[k];
        return;
    }
    if (s > 1e-3) {
        double f = th / (2 * s);
        for (int k = 0; k < 3; k++) r[k] = f * w[k];
        return;
    }
    /* near pi: symmetric part = c I + (1 - c) a a^T */
    double B[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            B[3 * i + j] = (0.5 * (R[3 * i + j] + R[3 * j + i]) - (i == j ? c : 0)) / (1 - c);
    int m = 0;
    if (B[4] > B[0]) m = 1;
    if (B[8] > B[3 * m + m]) m = 2;
    double a[3] = {B[3 * m], B[3 * m + 1], B[3 * m + 2]};
    double n = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (n == 0) n = 1;
    double sg = (a[0] * w[0] + a[1] * w[1] + a[2] * w[2]) < 0 ? -1 : 1;
    for (int k = 0; k < 3; k++) r[k] = sg * th * a[k] / n;
}

void rot_exp(const double r[3], double R[9])
{
    double th = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    double A, B;                      /* sin(th)/th, (1-cos th)/th^2 */
    if (th < 1e-8) { A = 1 - th * th / 6; B = 0.5 - th * th / 24; }
    else { A = sin(th) / th; B = (1 - cos(th)) / (th * th); }
    double x = r[0], y = r[1], z = r[2];
    R[0] = 1 - B * (y * y + z * z); R[1] = -A * z + B * x * y;      R[2] = A * y + B * x * z;
    R[3] = A * z + B * x * y;       R[4] = 1 - B * (x * x + z * z); R[5] = -A * x + B * y * z;
    R[6] = -A * y + B * x * z;      R[7] = A * x + B * y * z;       R[8] = 1 - B * (x * x + y * y);
}

void rot_branch_closest(const double r[3], const double ref[3], double out[3])
{
    double th = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    out[0] = r[0]; out[1] = r[1]; out[2] = r[2];
    if (th < 1e-12) return;
    double best = 1e300;
    for (int k = -2; k <= 2; k++) {
        double f = (th + 2 * M_PI * k) / th, d = 0, c[3];
        for (int i = 0; i < 3; i++) { c[i] = f * r[i]; d += (c[i] - ref[i]) * (c[i] - ref[i]); }
        if (d < best) { best = d; out[0] = c[0]; out[1] = c[1]; out[2] = c[2]; }
    }
}
