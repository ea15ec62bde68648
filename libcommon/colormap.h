/* colormap.h -- colours for per-element data: a categorical palette for
 * integer labels and a continuous (viridis-like) map for scalars.
 */
#ifndef CM_COLORMAP_H
#define CM_COLORMAP_H
#ifdef __cplusplus
extern "C" {
#endif

/* Colour of an integer label.  Labels 0..16 come from a fixed table of
 * well separated colours (matplotlib's tab10 and tab20 light variants,
 * without their greys and light cyan); labels 17..255 are chosen once, greedily, each as
 * far as possible from all earlier colours (and from grey and white) among
 * 4096 candidates spread over hue, saturation and value; larger labels take
 * the candidates in sequence.  Negative labels (-1 = "unlabelled") are grey.
 *   rgb  3 bytes (out) */
void colormap_label(int label, unsigned char rgb[3]);

/* Viridis-like colour of t in [0, 1] (clamped; NaN gives grey).
 * A degree-6 polynomial fit of matplotlib's viridis, within 4/255 of it.
 *   rgb  3 bytes (out) */
void colormap_viridis(double t, unsigned char rgb[3]);

/* 256 by 3 table of colormap_viridis(i / 255). */
void colormap_viridis_table(unsigned char lut[256 * 3]);

/* Position of x in [lo, hi] as t in [0, 1], clamped; lo == hi gives 0.5. */
double colormap_t(double x, double lo, double hi);

/* Parse a colour: "R,G,B" (0..255 each), "#rrggbb", or one of the names
 * white, black, grey (gray), red, green, blue.  Returns -1 on junk.
 *   rgb  3 bytes (out) */
int color_parse(const char *s, unsigned char rgb[3]);

/* Minimum and maximum of n values (n >= 1).
 *   x       n values
 *   lo, hi  (out) */
void scalar_range(const double *x, int n, double *lo, double *hi);

#ifdef __cplusplus
}
#endif
#endif
