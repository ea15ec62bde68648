/* image.h -- 8-bit RGB images: PPM (P6) and PNG output, grids of tiles,
 * and a 5x7 bitmap font for frame numbers and labels.
 *
 * Pixels are stored row-major from the top-left corner, 3 bytes per pixel
 * (R, G, B).  Colours are passed as `const unsigned char rgb[3]`.
 */
#ifndef CM_IMAGE_H
#define CM_IMAGE_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

struct image {
    int w, h;              /* width and height in pixels */
    unsigned char *rgb;    /* h by w by 3 bytes, row-major, top row first */
};

/* Parse "WxH" (e.g. 800x800) into positive w, h (at most 16384 each).
 * Returns -1 on junk. */
int image_parse_size(const char *s, int *w, int *h);

/* Pointer to pixel (x, y). */
static inline unsigned char *image_px(const struct image *im, int x, int y)
{
    return im->rgb + ((size_t)y * im->w + x) * 3;
}

/* Allocate a w by h image filled with colour bg (NULL: black).
 * Returns -1 (cm_errmsg) if the size is not positive or too large. */
int image_alloc(struct image *im, int w, int h, const unsigned char bg[3]);
void image_free(struct image *im);
/* Fill the rectangle [x, x+w) by [y, y+h) (clipped) with rgb. */
void image_fill_rect(struct image *im, int x, int y, int w, int h, const unsigned char rgb[3]);

/* Write as binary PPM (netpbm P6, maxval 255).  Returns -1 on a write error. */
int image_write_ppm(FILE *f, const struct image *im);
/* Write as 8-bit RGB PNG through libpng.  Returns -1 on error. */
int image_write_png(FILE *f, const struct image *im);
/* small != 0: later PNGs use zlib level 6 and adaptive filters (smaller
 * files, about 4x slower); default 0: level 1, Up filter. */
void image_png_small(int small);
/* Format by name: "png" or "ppm"; returns -1 for an unknown name. */
int image_write(FILE *f, const struct image *im, const char *format);
/* Read a PNG or a P6 PPM (by magic), converted to 8-bit RGB; for tests and
 * tools that compose images.  Returns -1 (cm_errmsg) on error. */
int image_read(const char *path, struct image *im);

/* Copy src into dst with its top-left corner at (x, y), clipped to dst. */
void image_blit(struct image *dst, const struct image *src, int x, int y);

/* Compose n tiles into a grid of `columns` columns (rows as needed, filled
 * left to right, top to bottom), `gap` pixels between tiles and around
 * the border, background bg.  Every cell has the size of the largest tile;
 * smaller tiles are centred.  tiles[i].rgb may be NULL for an empty cell.
 * Returns -1 (cm_errmsg) on bad arguments. */
int image_grid(const struct image *tiles, int n, int columns, int gap,
               const unsigned char bg[3], struct image *out);

/* ---- 5x7 bitmap font (ASCII 32..126; other bytes draw as '?') ---- */
#define FONT_W 5           /* glyph width in font pixels */
#define FONT_H 7           /* glyph height in font pixels */
#define FONT_ADVANCE 6     /* horizontal advance per character */

/* Size in pixels of text s drawn at integer magnification scale >= 1. */
int text_width(const char *s, int scale);
/* The glyph of character c: FONT_H bytes, one per row (top first), bit
 * (0x10 >> x) set where column x (0 = left) is drawn; '?' for bytes
 * outside ASCII 32..126.  Used to engrave piece ids (piece-plug). */
const unsigned char *font_glyph(int c);
int text_height(int scale);
/* Draw text s with its top-left corner at (x, y), magnification scale,
 * colour fg; if bg is not NULL a box of bg (scale pixels of padding) is
 * drawn behind it first.  Clipped to the image. */
void image_text(struct image *im, int x, int y, const char *s, int scale,
                const unsigned char fg[3], const unsigned char *bg);

#ifdef __cplusplus
}
#endif
#endif
