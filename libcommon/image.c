/* image.c -- see image.h */
#include "image.h"
#include "cm_error.h"
#include <errno.h>
#include <png.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int image_alloc(struct image *im, int w, int h, const unsigned char bg[3])
{
    im->w = im->h = 0;
    im->rgb = NULL;
    if (w <= 0 || h <= 0 || (int64_t)w * h > (int64_t)1 << 28)
        return cm_seterr("image size %dx%d out of range", w, h);
    size_t n = (size_t)w * h;
    im->rgb = malloc(n * 3);
    if (!im->rgb)
        return cm_seterr("out of memory for a %dx%d image", w, h);
    im->w = w;
    im->h = h;
    if (!bg || (bg[0] == bg[1] && bg[1] == bg[2]))
        memset(im->rgb, bg ? bg[0] : 0, n * 3);
    else
        for (size_t i = 0; i < n; i++) memcpy(im->rgb + 3 * i, bg, 3);
    return 0;
}

int image_parse_size(const char *s, int *w, int *h)
{
    char *end;
    if (*s < '0' || *s > '9')
        return -1;
    long a = strtol(s, &end, 10);
    if (*end != 'x' && *end != 'X')
        return -1;
    const char *q = end + 1;
    if (*q < '0' || *q > '9')
        return -1;
    long b = strtol(q, &end, 10);
    if (*end || a < 1 || b < 1 || a > 16384 || b > 16384)
        return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

void image_free(struct image *im)
{
    free(im->rgb);
    im->rgb = NULL;
    im->w = im->h = 0;
}

void image_fill_rect(struct image *im, int x, int y, int w, int h, const unsigned char rgb[3])
{
    int x0 = x < 0 ? 0 : x, y0 = y < 0 ? 0 : y;
    int x1 = x + w > im->w ? im->w : x + w, y1 = y + h > im->h ? im->h : y + h;
    for (int j = y0; j < y1; j++)
        for (int i = x0; i < x1; i++) memcpy(image_px(im, i, j), rgb, 3);
}

int image_write_ppm(FILE *f, const struct image *im)
{
    fprintf(f, "P6\n%d %d\n255\n", im->w, im->h);
    fwrite(im->rgb, 3, (size_t)im->w * im->h, f);
    if (ferror(f))
        return cm_seterr("write error: %s", strerror(errno));
    return 0;
}

static void png_err(png_structp p, png_const_charp msg)
{
    cm_seterr("PNG: %s", msg);
    png_longjmp(p, 1);
}

static void png_warn(png_structp p, png_const_charp msg)
{
    (void)p;
    (void)msg;
}

static int level_fast = 1;

void image_png_small(int small)
{
    level_fast = !small;
}

int image_write_png(FILE *f, const struct image *im)
{
    png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_err, png_warn);
    if (!p)
        return cm_seterr("PNG: out of memory");
    png_infop info = png_create_info_struct(p);
    png_bytep *volatile rows = NULL;
    if (!info) {
        png_destroy_write_struct(&p, NULL);
        return cm_seterr("PNG: out of memory");
    }
    if (setjmp(png_jmpbuf(p))) {
        free(rows);
        png_destroy_write_struct(&p, &info);
        return -1;
    }
    png_init_io(p, f);
    /* Renders are mostly flat background with smooth shading: zlib level 1
     * with the Up filter only writes files about 1.5x the size of libpng's
     * defaults (level 6, adaptive filters) in a quarter of the time (800x800
     * renders: 8 ms against 30 ms; bench/b-render.sh prints both). */
    png_set_compression_level(p, level_fast ? 1 : 6);
    png_set_filter(p, 0, level_fast ? PNG_FILTER_UP : PNG_ALL_FILTERS);
    png_set_IHDR(p, info, im->w, im->h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(p, info);
    rows = malloc((size_t)im->h * sizeof *rows);
    if (!rows)
        png_error(p, "out of memory");
    for (int y = 0; y < im->h; y++) rows[y] = im->rgb + (size_t)y * im->w * 3;
    png_write_image(p, rows);
    png_write_end(p, NULL);
    free(rows);
    png_destroy_write_struct(&p, &info);
    if (fflush(f) != 0 || ferror(f))
        return cm_seterr("write error: %s", strerror(errno));
    return 0;
}

int image_write(FILE *f, const struct image *im, const char *format)
{
    if (!strcmp(format, "png"))
        return image_write_png(f, im);
    if (!strcmp(format, "ppm"))
        return image_write_ppm(f, im);
    return cm_seterr("unknown image format '%s' (png, ppm)", format);
}

/* one whitespace/comment separated PPM header number */
static int ppm_num(FILE *f, int *out)
{
    int c;
    for (;;) {
        c = getc(f);
        if (c == '#')
            while ((c = getc(f)) != EOF && c != '\n') {}
        else if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
            break;
    }
    long v = 0;
    if (c < '0' || c > '9')
        return -1;
    while (c >= '0' && c <= '9') {
        v = 10 * v + (c - '0');
        if (v > 1 << 20)
            return -1;
        c = getc(f);
    }
    *out = (int)v;
    return 0;   /* the single whitespace after the number is consumed */
}

static int read_png(FILE *f, const char *path, struct image *im)
{
    png_structp p = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, png_err, png_warn);
    if (!p)
        return cm_seterr("PNG: out of memory");
    png_infop info = png_create_info_struct(p);
    png_bytep *volatile rows = NULL;
    if (!info) {
        png_destroy_read_struct(&p, NULL, NULL);
        return cm_seterr("PNG: out of memory");
    }
    if (setjmp(png_jmpbuf(p))) {
        char msg[256];
        snprintf(msg, sizeof msg, "%s", cm_errmsg());
        cm_seterr("cannot read '%s': %s", path, msg);
        free(rows);
        image_free(im);
        png_destroy_read_struct(&p, &info, NULL);
        return -1;
    }
    png_init_io(p, f);
    png_read_info(p, info);
    png_set_expand(p);
    png_set_strip_16(p);
    png_set_strip_alpha(p);
    png_set_gray_to_rgb(p);
    png_read_update_info(p, info);
    int w = (int)png_get_image_width(p, info), h = (int)png_get_image_height(p, info);
    if (png_get_rowbytes(p, info) != (size_t)w * 3 || image_alloc(im, w, h, NULL) < 0)
        png_error(p, "unsupported PNG layout");
    rows = malloc((size_t)h * sizeof *rows);
    for (int y = 0; y < h; y++) rows[y] = im->rgb + (size_t)y * w * 3;
    png_read_image(p, rows);
    png_read_end(p, NULL);
    free(rows);
    png_destroy_read_struct(&p, &info, NULL);
    return 0;
}

int image_read(const char *path, struct image *im)
{
    im->w = im->h = 0;
    im->rgb = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return cm_seterr("cannot read '%s': %s", path, strerror(errno));
    unsigned char sig[8];
    int r = -1;
    if (fread(sig, 1, 8, f) == 8 && !png_sig_cmp(sig, 0, 8)) {
        rewind(f);
        r = read_png(f, path, im);
    } else if (sig[0] == 'P' && sig[1] == '6') {
        int w, h, maxval;
        rewind(f);
        getc(f);
        getc(f);
        if (ppm_num(f, &w) < 0 || ppm_num(f, &h) < 0 || ppm_num(f, &maxval) < 0 || maxval != 255)
            cm_seterr("cannot read '%s': bad or unsupported PPM header", path);
        else if (image_alloc(im, w, h, NULL) == 0) {
            if (fread(im->rgb, 3, (size_t)w * h, f) == (size_t)w * h)
                r = 0;
            else {
                cm_seterr("cannot read '%s': truncated PPM", path);
                image_free(im);
            }
        }
    } else
        cm_seterr("cannot read '%s': not a PNG or P6 PPM image", path);
    fclose(f);
    return r;
}

void image_blit(struct image *dst, const struct image *src, int x, int y)
{
    int x0 = x < 0 ? -x : 0, x1 = src->w;
    if (x + x1 > dst->w) x1 = dst->w - x;
    if (x1 <= x0)
        return;
    for (int j = 0; j < src->h; j++) {
        int yy = y + j;
        if (yy < 0 || yy >= dst->h)
            continue;
        memcpy(image_px(dst, x + x0, yy), image_px(src, x0, j), (size_t)(x1 - x0) * 3);
    }
}

int image_grid(const struct image *tiles, int n, int columns, int gap,
               const unsigned char bg[3], struct image *out)
{
    if (n < 1 || columns < 1 || gap < 0)
        return cm_seterr("image grid: bad layout (%d tiles, %d columns)", n, columns);
    int cw = 0, ch = 0;
    for (int i = 0; i < n; i++) {
        if (!tiles[i].rgb) continue;
        if (tiles[i].w > cw) cw = tiles[i].w;
        if (tiles[i].h > ch) ch = tiles[i].h;
    }
    if (cw == 0)
        return cm_seterr("image grid: no tiles");
    int cols = columns < n ? columns : n, rows = (n + columns - 1) / columns;
    if (image_alloc(out, cols * cw + (cols + 1) * gap, rows * ch + (rows + 1) * gap, bg) < 0)
        return -1;
    for (int i = 0; i < n; i++) {
        if (!tiles[i].rgb) continue;
        int c = i % columns, r = i / columns;
        image_blit(out, &tiles[i], gap + c * (cw + gap) + (cw - tiles[i].w) / 2,
                   gap + r * (ch + gap) + (ch - tiles[i].h) / 2);
    }
    return 0;
}

/* 5x7 glyphs for ASCII 32..126, one byte per row (top first), bit 4 is the
 * leftmost pixel.  Drawn for stopmo after the usual LCD character sets. */
static const unsigned char font5x7[95][7] = {
    {0x00,0x00,0x00,0x00,0x00,0x00,0x00}, /* ' ' */
    {0x04,0x04,0x04,0x04,0x04,0x00,0x04}, /* '!' */
    {0x0a,0x0a,0x0a,0x00,0x00,0x00,0x00}, /* '"' */
    {0x0a,0x0a,0x1f,0x0a,0x1f,0x0a,0x0a}, /* '#' */
    {0x04,0x0f,0x14,0x0e,0x05,0x1e,0x04}, /* '$' */
    {0x18,0x19,0x02,0x04,0x08,0x13,0x03}, /* '%' */
    {0x0c,0x12,0x14,0x08,0x15,0x12,0x0d}, /* '&' */
    {0x04,0x04,0x08,0x00,0x00,0x00,0x00}, /* "'" */
    {0x02,0x04,0x08,0x08,0x08,0x04,0x02}, /* '(' */
    {0x08,0x04,0x02,0x02,0x02,0x04,0x08}, /* ')' */
    {0x00,0x04,0x15,0x0e,0x15,0x04,0x00}, /* '*' */
    {0x00,0x04,0x04,0x1f,0x04,0x04,0x00}, /* '+' */
    {0x00,0x00,0x00,0x00,0x0c,0x04,0x08}, /* ',' */
    {0x00,0x00,0x00,0x1f,0x00,0x00,0x00}, /* '-' */
    {0x00,0x00,0x00,0x00,0x00,0x0c,0x0c}, /* '.' */
    {0x00,0x01,0x02,0x04,0x08,0x10,0x00}, /* '/' */
    {0x0e,0x11,0x13,0x15,0x19,0x11,0x0e}, /* '0' */
    {0x04,0x0c,0x04,0x04,0x04,0x04,0x0e}, /* '1' */
    {0x0e,0x11,0x01,0x02,0x04,0x08,0x1f}, /* '2' */
    {0x1f,0x02,0x04,0x02,0x01,0x11,0x0e}, /* '3' */
    {0x02,0x06,0x0a,0x12,0x1f,0x02,0x02}, /* '4' */
    {0x1f,0x10,0x1e,0x01,0x01,0x11,0x0e}, /* '5' */
    {0x06,0x08,0x10,0x1e,0x11,0x11,0x0e}, /* '6' */
    {0x1f,0x01,0x02,0x04,0x08,0x08,0x08}, /* '7' */
    {0x0e,0x11,0x11,0x0e,0x11,0x11,0x0e}, /* '8' */
    {0x0e,0x11,0x11,0x0f,0x01,0x02,0x0c}, /* '9' */
    {0x00,0x0c,0x0c,0x00,0x0c,0x0c,0x00}, /* ':' */
    {0x00,0x0c,0x0c,0x00,0x0c,0x04,0x08}, /* ';' */
    {0x02,0x04,0x08,0x10,0x08,0x04,0x02}, /* '<' */
    {0x00,0x00,0x1f,0x00,0x1f,0x00,0x00}, /* '=' */
    {0x08,0x04,0x02,0x01,0x02,0x04,0x08}, /* '>' */
    {0x0e,0x11,0x01,0x02,0x04,0x00,0x04}, /* '?' */
    {0x0e,0x11,0x01,0x0d,0x15,0x15,0x0e}, /* '@' */
    {0x0e,0x11,0x11,0x1f,0x11,0x11,0x11}, /* 'A' */
    {0x1e,0x11,0x11,0x1e,0x11,0x11,0x1e}, /* 'B' */
    {0x0e,0x11,0x10,0x10,0x10,0x11,0x0e}, /* 'C' */
    {0x1c,0x12,0x11,0x11,0x11,0x12,0x1c}, /* 'D' */
    {0x1f,0x10,0x10,0x1e,0x10,0x10,0x1f}, /* 'E' */
    {0x1f,0x10,0x10,0x1e,0x10,0x10,0x10}, /* 'F' */
    {0x0e,0x11,0x10,0x17,0x11,0x11,0x0f}, /* 'G' */
    {0x11,0x11,0x11,0x1f,0x11,0x11,0x11}, /* 'H' */
    {0x0e,0x04,0x04,0x04,0x04,0x04,0x0e}, /* 'I' */
    {0x07,0x02,0x02,0x02,0x02,0x12,0x0c}, /* 'J' */
    {0x11,0x12,0x14,0x18,0x14,0x12,0x11}, /* 'K' */
    {0x10,0x10,0x10,0x10,0x10,0x10,0x1f}, /* 'L' */
    {0x11,0x1b,0x15,0x15,0x11,0x11,0x11}, /* 'M' */
    {0x11,0x11,0x19,0x15,0x13,0x11,0x11}, /* 'N' */
    {0x0e,0x11,0x11,0x11,0x11,0x11,0x0e}, /* 'O' */
    {0x1e,0x11,0x11,0x1e,0x10,0x10,0x10}, /* 'P' */
    {0x0e,0x11,0x11,0x11,0x15,0x12,0x0d}, /* 'Q' */
    {0x1e,0x11,0x11,0x1e,0x14,0x12,0x11}, /* 'R' */
    {0x0f,0x10,0x10,0x0e,0x01,0x01,0x1e}, /* 'S' */
    {0x1f,0x04,0x04,0x04,0x04,0x04,0x04}, /* 'T' */
    {0x11,0x11,0x11,0x11,0x11,0x11,0x0e}, /* 'U' */
    {0x11,0x11,0x11,0x11,0x11,0x0a,0x04}, /* 'V' */
    {0x11,0x11,0x11,0x15,0x15,0x15,0x0a}, /* 'W' */
    {0x11,0x11,0x0a,0x04,0x0a,0x11,0x11}, /* 'X' */
    {0x11,0x11,0x11,0x0a,0x04,0x04,0x04}, /* 'Y' */
    {0x1f,0x01,0x02,0x04,0x08,0x10,0x1f}, /* 'Z' */
    {0x0e,0x08,0x08,0x08,0x08,0x08,0x0e}, /* '[' */
    {0x00,0x10,0x08,0x04,0x02,0x01,0x00}, /* 'backslash' */
    {0x0e,0x02,0x02,0x02,0x02,0x02,0x0e}, /* ']' */
    {0x04,0x0a,0x11,0x00,0x00,0x00,0x00}, /* '^' */
    {0x00,0x00,0x00,0x00,0x00,0x00,0x1f}, /* '_' */
    {0x08,0x04,0x02,0x00,0x00,0x00,0x00}, /* '`' */
    {0x00,0x00,0x0e,0x01,0x0f,0x11,0x0f}, /* 'a' */
    {0x10,0x10,0x16,0x19,0x11,0x11,0x1e}, /* 'b' */
    {0x00,0x00,0x0e,0x10,0x10,0x11,0x0e}, /* 'c' */
    {0x01,0x01,0x0d,0x13,0x11,0x11,0x0f}, /* 'd' */
    {0x00,0x00,0x0e,0x11,0x1f,0x10,0x0e}, /* 'e' */
    {0x06,0x09,0x08,0x1c,0x08,0x08,0x08}, /* 'f' */
    {0x00,0x0f,0x11,0x11,0x0f,0x01,0x0e}, /* 'g' */
    {0x10,0x10,0x16,0x19,0x11,0x11,0x11}, /* 'h' */
    {0x04,0x00,0x0c,0x04,0x04,0x04,0x0e}, /* 'i' */
    {0x02,0x00,0x06,0x02,0x02,0x12,0x0c}, /* 'j' */
    {0x10,0x10,0x12,0x14,0x18,0x14,0x12}, /* 'k' */
    {0x0c,0x04,0x04,0x04,0x04,0x04,0x0e}, /* 'l' */
    {0x00,0x00,0x1a,0x15,0x15,0x11,0x11}, /* 'm' */
    {0x00,0x00,0x16,0x19,0x11,0x11,0x11}, /* 'n' */
    {0x00,0x00,0x0e,0x11,0x11,0x11,0x0e}, /* 'o' */
    {0x00,0x00,0x1e,0x11,0x1e,0x10,0x10}, /* 'p' */
    {0x00,0x00,0x0d,0x13,0x0f,0x01,0x01}, /* 'q' */
    {0x00,0x00,0x16,0x19,0x10,0x10,0x10}, /* 'r' */
    {0x00,0x00,0x0e,0x10,0x0e,0x01,0x1e}, /* 's' */
    {0x08,0x08,0x1c,0x08,0x08,0x09,0x06}, /* 't' */
    {0x00,0x00,0x11,0x11,0x11,0x13,0x0d}, /* 'u' */
    {0x00,0x00,0x11,0x11,0x11,0x0a,0x04}, /* 'v' */
    {0x00,0x00,0x11,0x11,0x15,0x15,0x0a}, /* 'w' */
    {0x00,0x00,0x11,0x0a,0x04,0x0a,0x11}, /* 'x' */
    {0x00,0x00,0x11,0x11,0x0f,0x01,0x0e}, /* 'y' */
    {0x00,0x00,0x1f,0x02,0x04,0x08,0x1f}, /* 'z' */
    {0x02,0x04,0x04,0x08,0x04,0x04,0x02}, /* '{' */
    {0x04,0x04,0x04,0x04,0x04,0x04,0x04}, /* '|' */
    {0x08,0x04,0x04,0x02,0x04,0x04,0x08}, /* '}' */
    {0x00,0x00,0x08,0x15,0x02,0x00,0x00}, /* '~' */
};

int text_width(const char *s, int scale)
{
    int n = (int)strlen(s);
    return n ? scale * (n * FONT_ADVANCE - 1) : 0;
}

int text_height(int scale)
{
    return scale * FONT_H;
}

const unsigned char *font_glyph(int c)
{
    c &= 0xff;
    return font5x7[(c >= 32 && c < 127 ? c : '?') - 32];
}

void image_text(struct image *im, int x, int y, const char *s, int scale,
                const unsigned char fg[3], const unsigned char *bg)
{
    if (scale < 1) scale = 1;
    if (bg && *s)
        image_fill_rect(im, x - scale, y - scale, text_width(s, scale) + 2 * scale,
                        text_height(scale) + 2 * scale, bg);
    for (; *s; s++, x += FONT_ADVANCE * scale) {
        const unsigned char *g = font_glyph((unsigned char)*s);
        for (int r = 0; r < FONT_H; r++)
            for (int b = 0; b < FONT_W; b++)
                if (g[r] & (0x10 >> b))
                    image_fill_rect(im, x + b * scale, y + r * scale, scale, scale, fg);
    }
}
