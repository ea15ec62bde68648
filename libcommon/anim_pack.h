/* anim_pack.h -- compact, lossy-but-bounded encoding of an animation's
 * vertex positions for embedding in a web page (anim-view).
 *
 * Positions are quantised to 16 bits per coordinate over the animation's
 * bounding box (all frames): q = round((x - lo) / (hi - lo) * 65535) per
 * axis.  The error added is at most (hi - lo) / 131070 per axis, so at most
 * |hi - lo| / 131070 = 7.6e-6 of the box diagonal per vertex (anim_pack_bound).
 * For compression the frames are then differenced (frame k minus frame k-1,
 * modulo 2^16; frame 0 as is), each frame's low bytes stored before its
 * high bytes, and the whole deflated (zlib format, RFC 1950) at level 6 (level 9 is 6x
 * slower for 1% less on a 26,940-vertex x 335-frame facecap merge).
 *
 * Decoding (what the page does): inflate; per frame, u = lo_bytes | hi_bytes
 * << 8, q_k = (q_{k-1} + u) mod 2^16; x = lo + q / 65535 * (hi - lo).
 */
#ifndef CM_ANIM_PACK_H
#define CM_ANIM_PACK_H
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Bounding box of nframes * nv points.
 *   X       nframes by nv by 3 positions
 *   lo, hi  3 each (out); an axis with hi == lo is widened to lo + 1 so
 *           that it quantises to 0 exactly */
void anim_pack_bbox(const double *X, size_t npoints, double lo[3], double hi[3]);

/* Largest distance between a point in the box and its decoded position:
 * half a quantisation step on every axis, |hi - lo| / 131070. */
double anim_pack_bound(const double lo[3], const double hi[3]);

/* Quantise, difference and shuffle (no compression).
 *   X        nframes by nv by 3 positions, inside [lo, hi]
 *   out      nframes * nv * 6 bytes (out)
 * The largest actual error of the decoded positions is returned in *err
 * (may be NULL); it never exceeds anim_pack_bound(). */
void anim_pack_positions(const double *X, int nframes, int nv, const double lo[3],
                         const double hi[3], unsigned char *out, double *err);

/* Deflate n bytes (zlib format, level 6).
 *   out  malloc'd buffer (out), *outn its length
 * Returns -1 (cm_errmsg) when out of memory or zlib fails. */
int anim_pack_deflate(const void *in, size_t n, unsigned char **out, size_t *outn);

/* Inflate what anim_pack_deflate() wrote, into exactly n bytes (for tests).
 * Returns -1 (cm_errmsg) on corrupt data or a length other than n. */
int anim_pack_inflate(const unsigned char *in, size_t inn, void *out, size_t n);

#ifdef __cplusplus
}
#endif
#endif
