/* clay_classify.h -- the character classification heuristic of the
 * E-StopMotion thesis (Chapter 2.2): which shape mapping (registration)
 * class suits a clay character, from its motion segments.
 *
 * Each segment has an animation class (Table 2.2 rows), its share of the
 * character's volume, how many frame transitions it shows at each
 * deformation scale (small / intermediate / large, see overlap(1)) and its
 * number of salient points.  The score of a shape mapping class is Eq. 2.1:
 *     S = sum_segments w_vol (S_generic - w_SODef + K_features),
 * S_generic from Table 2.2; w_SODef the fraction of transitions at a scale
 * the mapping class does not cover; K_features = +1 (>= 3 salient points) or
 * -1 (fewer) for the classes that benefit from salient features, else 0.
 * The thesis does not print which class covers which scale nor which
 * benefits from features; this implementation uses (and documents):
 *     uniform: small;            nonuniform: small, intermediate, large;
 *     extrinsic: small, intermediate;   intrinsic: intermediate, large;
 *     features help nonuniform and intrinsic mappings.
 * Category: the two best classes; both of {nonuniform, intrinsic} -> C1
 * (globally nonuniform - intrinsic metric), both of {uniform, extrinsic} ->
 * C2 (globally uniform - extrinsic metric), otherwise C3 (extrinsic -
 * intrinsic metric).
 */
#ifndef CM_CLAY_CLASSIFY_H
#define CM_CLAY_CLASSIFY_H
#ifdef __cplusplus
extern "C" {
#endif

enum { MAP_UNIFORM, MAP_NONUNIFORM, MAP_EXTRINSIC, MAP_INTRINSIC, MAP_COUNT };

struct clay_segment {
    int anim;             /* index into clay_anim_names */
    double volume;        /* share of the volume, in (0, 1] */
    int small, inter, large;   /* transitions at each scale */
    int salient;          /* salient points */
};

extern const char *const clay_anim_names[];     /* NULL-terminated */
extern const char *const clay_map_names[MAP_COUNT];

/* Index of an animation class name, -1 if unknown. */
int clay_anim_index(const char *name);

/* score: MAP_COUNT (out).  Returns the category 1, 2 or 3. */
int clay_classify(const struct clay_segment *s, int n, double score[MAP_COUNT], int best[2]);

#ifdef __cplusplus
}
#endif
#endif
