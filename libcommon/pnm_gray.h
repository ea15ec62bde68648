/* pnm_gray.h -- read netpbm bitmaps and graymaps (PBM P1/P4, PGM P2/P5;
 * PPM P3/P6 converted to luminance) as 8- or 16-bit gray values.
 */
#ifndef CM_PNM_GRAY_H
#define CM_PNM_GRAY_H
#ifdef __cplusplus
extern "C" {
#endif

struct gray {
    int w, h;          /* size in pixels */
    int maxval;        /* largest value (1 for PBM) */
    int *v;            /* h by w values, row-major, top row first; PBM: 1 = black */
    int bitmap;        /* 1 if read from a PBM (1 means black, ink) */
};

/* path NULL or "-" = stdin.  Errors name the file (and line for plain
 * formats) in cm_errmsg(). */
int gray_read(const char *path, struct gray *g);
void gray_free(struct gray *g);

#ifdef __cplusplus
}
#endif
#endif
