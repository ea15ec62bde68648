/* shortest.h -- the shortest decimal that reads back to a double.
 *
 * shortest_decimal(x) finds the decimal s 10^E with the fewest significant
 * digits that rounds back to x (among those, the nearest to x), by
 * Dragonbox (Jeon 2020) as {fmt} implements it: correctly, without
 * extended precision or a read-back check.  format_double (numparse.h)
 * lays it out as printf's %g would.
 */
#ifndef CM_SHORTEST_H
#define CM_SHORTEST_H
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

/* x: finite and nonzero (the sign is ignored).  Out: *sig, the significant
 * digits as an integer (1 to 17 digits, no trailing zero), and *exp10, so
 * that |x| reads back from sig 10^exp10. */
void shortest_decimal(double x, uint64_t *sig, int *exp10);

#ifdef __cplusplus
}
#endif
#endif
