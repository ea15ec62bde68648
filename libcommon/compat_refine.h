/* compat_refine.h -- quality refinement of an N-way compatible
 * triangulation (Surazhsky and Gotsman, "High quality compatible
 * triangulations", Engineering with Computers 20, 2004): Steiner points
 * inserted at corresponding positions in all N shapes, compatible edge
 * flips and per-shape smoothing, until every angle of every triangle in
 * every shape reaches a goal (or nothing helps any more).
 *
 * First (with MIPS smoothing, pa->mips > 0: a remeshing loop) compatible
 * edge collapses: an interior vertex of a triangle below the goal is
 * merged into the neighbour that makes its star better in every shape
 * (link condition, every changed triangle positive in every shape, exact);
 * this undoes the tiny pieces overlays leave (and again after every
 * round's smoothing, for the input's vertices).  With pa->mips > 0 the
 * splitting also stops when it stalls (COMPAT_REFINE_STALLED: where the
 * maps between the shapes are stretched, splits only make more bad
 * triangles) and the mesh goes back to the round with the best worst
 * angle; the final polish then coarsens: a vertex (interior, or an outline
 * vertex made by a split) is collapsed wherever no triangle gets worse
 * than the smaller of its old smallest angle and the goal.
 * One round:
 *   flips      an interior edge is flipped if the flipped pair is
 *              positively oriented in all N shapes (exact orientation
 *              predicate) and its smallest angle over the shapes is larger.
 *   MIPS       (pa->mips > 0) shape by shape, every interior vertex takes
 *              gradient steps on the sum over its star of (S / (4 sqrt3 A))^2
 *              (S: sum of squared edge lengths, A: area; 1 for an
 *              equilateral triangle, unbounded as one degenerates, so it is
 *              a barrier: no step inverts a triangle, checked exactly).
 *              Spreads the distortion between shapes over the whole mesh,
 *              which the local smoothing below cannot.  Outline vertices
 *              made by splits slide along their input segment (shape by
 *              shape), so the outline is unchanged.
 *   smoothing  each interior vertex is moved, shape by shape, to the best
 *              of a few candidate positions (mean of the points that make
 *              each incident triangle equilateral on its opposite edge,
 *              the centroid of the neighbours, halfway steps): kept only if
 *              every incident triangle stays positive (exact) and the
 *              smallest angle of the vertex's star grows.  A shape's
 *              positions never depend on another shape's, so each shape is
 *              smoothed on its own.
 *   polish     (pa->mips > 0) shape by shape, every movable vertex of a
 *              triangle below the goal (and its neighbours) does a pattern
 *              search (eight directions, halving steps; along its segment
 *              for an outline split vertex) on the smallest angle of its
 *              star, each step kept only if the star stays positive
 *              (exact).  MIPS and the candidates above optimise proxies;
 *              without this, triangles a little under the goal were split
 *              again and again instead of moved.
 *   splits     each triangle below the goal, worst first, has its longest
 *              edge (in the shape where the triangle is worst) bisected in
 *              all N shapes (Rivara); the split is kept only if the new
 *              triangles are positive in every shape.  Boundary edges are
 *              split too: the new vertex lies on the outline segment in
 *              every shape, so the outline is unchanged.
 * Input boundary vertices and interior points never move, except (with
 * pa->slide) outline vertices that are not given points, which slide along
 * their own shape's input outline in the polish, within the tolerance.  Angles at a boundary corner whose
 * opening is below twice the goal count as good when they are all the
 * corner can give (its opening divided by its triangle count).
 * Deterministic: no randomness, fixed visiting order.
 */
#ifndef CM_COMPAT_REFINE_H
#define CM_COMPAT_REFINE_H
#include "compat_tri.h"
#ifdef __cplusplus
extern "C" {
#endif

struct compat_refine_stats {
    int rounds;        /* rounds run */
    int splits;        /* interior edges bisected */
    int bsplits;       /* boundary edges bisected */
    int flips;         /* compatible flips */
    int moves;         /* accepted smoothing moves (vertex x shape) */
    int collapses;     /* interior vertices removed by edge collapses */
    int coarsened;     /* of collapses: those of the final coarsening */
    int kept_input;    /* 1 if the refined mesh was worse than the input and
                          the input was kept */
    int stop;          /* why the splitting stopped: COMPAT_REFINE_* */
    int stalled;       /* rounds in a row at the end without progress (see
                          COMPAT_REFINE_STALLED) */
    int rerun;         /* split_share < 1: 0 if the first pass reached the
                          goal, 1 if the second pass (only the worst share
                          split) was run and kept, 2 if it was run and the
                          first pass kept (stop, stalled, cycles and
                          restored are then of the kept pass), 3 if the
                          third pass (pa->lookahead) was run and kept */
    int restored;      /* 1 if the mesh went back to the best round (later
                          rounds only added vertices) */
    int cycles;        /* stalls answered by going back to the best round,
                          the final polish and more rounds
                          (COMPAT_REFINE_CYCLES); stop and stalled are then
                          of the rounds after the last one */
    int worst_shape;   /* where the result's worst triangle is (measured
                          against what its corner allows): the shape, */
    double worst_at[2];/* its centroid in that shape, and */
    double gpolish[2]; /* below the goal: the worst angle (radians) before
                          and after the global max-min polish of the result
                          (maxmin_polish.h) and its flips; 0 0 at the goal */
    double gslide[2];  /* (pa->slide_global) the worst angle (radians) before
                          and after the global polish with outline slides;
                          0 0 if not run */
    int grown;         /* the first pass was cut short after this many
                          rounds (COMPAT_REFINE_GROWING; 0: it was not) */
    double stretch;    /* the largest ratio of singular values of the
                          affine maps between the shapes on it (1: similar
                          copies; a triangle whose map is stretched k times
                          cannot have all angles good in both shapes once
                          k is large) */
};

/* compat_refine_stats.stop */
enum {
    COMPAT_REFINE_GOAL,     /* every angle reached the goal */
    COMPAT_REFINE_STALLED,  /* COMPAT_REFINE_STALL rounds in a row neither
                               raised the worst angle by COMPAT_REFINE_GAIN
                               nor cut the triangles below the goal by 5%,
                               and the mesh has twice the vertices of the
                               best round (or 4 times as many rounds) */
    COMPAT_REFINE_MAXNV,    /* max_nv reached */
    COMPAT_REFINE_NOSPLIT,  /* no split kept every shape positive */
    COMPAT_REFINE_ROUNDS,   /* rounds used up */
    COMPAT_REFINE_GROWING   /* (the first pass of a refinement with a
                               second, split_share < 1) from its
                               COMPAT_REFINE_GROW_ROUND-th round on, its
                               triangles below the goal grew in a round
                               and are at least half its vertices: where
                               the maps are stretched, splitting every bad
                               triangle only multiplies them (measured on
                               the 57 stick-horse subsets of compat-tri(1):
                               the 26 first passes that went on to the
                               goal had at most 0.95 times the bad
                               triangles of their third round in their
                               fourth, and at most 17% of their vertices
                               bad where the count rose later; of the 64
                               that went on to a second pass, 63 had more
                               in their fourth, at least half their
                               vertices), so the second pass starts at
                               once */
};
#define COMPAT_REFINE_GROW_ROUND 4
#define COMPAT_REFINE_STALL 3
/* a stall (pa->mips > 0) first goes back to the best round and gets the
 * final polish; that mesh is kept unless the rounds that then follow from it
 * (up to the next stall) end better.  This many times, then it stops. */
#define COMPAT_REFINE_CYCLES 1
#define COMPAT_REFINE_GAIN (0.05 * M_PI / 180)   /* radians */
#define COMPAT_REFINE_POLISH_MAX 64   /* final polish sweeps at most */
#define COMPAT_REFINE_GPOLISH 4   /* global max-min polishes (each then flips) at most */

struct compat_refine_params {
    double goal;       /* target smallest angle, radians (e.g. 20 degrees) */
    double size;       /* also split triangles with an edge longer than size
                          times the shape's bounding-box diagonal (<= 0: no
                          size bound) */
    int max_nv;        /* stop splitting once the mesh has this many vertices */
    int rounds;        /* at most this many rounds (flips + smoothing + splits) */
    int mips;          /* at most this many sweeps of MIPS smoothing per
                          round before the smallest-angle smoothing (they
                          stop when no vertex moves; 0: none, the paper's
                          smoothing only, and no max-min polish; e.g. 200:
                          with 20 a heavily distorted start was split
                          before the smoothing had settled, and the splits
                          ran into max_nv) */
    int threads;       /* the smoothing and polish run pose by pose on this
                          many threads (0: one per processor); the result
                          does not depend on it */
    double split_share;/* (pa->mips > 0) 0 or 1: one pass, every triangle
                          below the goal split every round.  Below 1: a
                          refinement whose first pass (as with 1) ends
                          below the goal is run again from its start, and
                          after COMPAT_REFINE_FULL_SPLITS rounds each round
                          of that second pass splits only this share of
                          the triangles below the goal, the worst first
                          (at least one); the better of the two passes is
                          the result (a tie: the first).  Where the maps
                          between the poses are stretched, splitting every
                          bad triangle doubles the vertices there each
                          round and reaches max_nv (or a stall) before the
                          smoothing has spread the stretch; splitting the
                          worst only leaves the smoothing, polish and
                          flips more rounds per vertex */
    int lookahead;     /* (split_share < 1) 1: a second pass that ends
                          below the goal is followed by a third, from the
                          start again and with the same share, in which
                          each triangle below the goal is bisected at the
                          edge whose split gives the new triangles the
                          largest smallest angle over every shape (not the
                          longest edge in its worst shape); the best of the
                          three passes is the result (a tie: the earlier) */
    double slide;      /* (pa->mips > 0; one outer ring whose c->bidx is
                          set) > 0: in the max-min polish an outline vertex
                          that is neither a given point (c->bpin) nor made by
                          a split may slide along its own shape's input
                          outline (c->B), shape by shape, as long as each
                          of its two outline edges stays within slide times
                          the shape's bounding-box diagonal of the input
                          points it spans (compat_simplify's measure) and
                          crosses no other outline edge; 0: they stay.
                          Only in the passes run again (split_share) unless
                          slide_first */
    int slide_first;   /* 1: also in the first pass */
    int slide_global;  /* (slide > 0) 1: a result below the goal after the
                          global max-min polish gets it again with those
                          outline vertices sliding along their input
                          outline as well (maxmin_polish_curve: all at
                          once, each by its arc length, within the same
                          tolerance, no crossing), then flips, while the
                          worst angle rises by COMPAT_REFINE_GAIN */
    int grow;          /* (split_share < 1) 1: the first pass ends as soon
                          as its bad triangles grow with its vertices
                          (COMPAT_REFINE_GROWING) and the second starts;
                          0: it goes on to its own end (a stall, max_nv).
                          A first pass cut short is kept aside without its
                          final polish, which runs only where a later pass
                          ends below the goal and is compared with it */
};
/* rounds of the second pass that split every triangle below the goal
 * before split_share applies */
#define COMPAT_REFINE_FULL_SPLITS 3

/* Refine c in place.
 * c          compatible triangulation (every triangle positive in every
 *            shape); boundary vertices 0..c->nb-1 in order; on return the
 *            boundary vertices added by splits are inserted into that order
 *            (vertex indices are renumbered: boundary first, then interior)
 * pa         goal, size bound and limits
 * st         out (may be NULL): counts
 * The result's smallest angle over all shapes is never below the input's
 * (if refinement made it worse, the input is kept: st->kept_input).
 * Returns 0, -1 on out of memory (cm_errmsg). */
int compat_refine(struct compat *c, const struct compat_refine_params *pa,
                  struct compat_refine_stats *st);

/* The same refinement a round at a time, so that a caller can run several
 * candidate triangulations side by side and drop the ones falling behind
 * (compat-tri: the matched points against the given rows alone).
 * compat_refine(c, pa, st) is begin, step until it returns 0, finish.
 *
 * compat_refine_begin  starts on c (as compat_refine; c belongs to the
 *                      refiner until finish or abandon); NULL on out of
 *                      memory (cm_errmsg).  st (may be NULL) is filled as
 *                      the rounds go.
 * compat_refine_step   one round (flips, smoothing, collapses, splits);
 *                      1: more rounds may help, 0: the splitting has
 *                      stopped (st->stop says why), -1: out of memory.
 * compat_refine_progress  after a step: worst = the smallest angle
 *                      (radians) measured against what each corner allows
 *                      (>= pa->goal: done), nbad = triangles below it
 *                      (INT_MAX before the first step), fewest = the
 *                      fewest such triangles after any step so far (any
 *                      output may be NULL).  Once a stall was answered by
 *                      the final polish and more rounds (COMPAT_REFINE_CYCLES)
 *                      it reports like a finished refinement: worst = the
 *                      polished mesh's (the result is at least as good),
 *                      nbad = INT_MAX.
 * compat_refine_finish back to the best round, final polish and
 *                      coarsening, renumbering; frees the refiner.  0 or -1.
 * compat_refine_threads sets the threads of the later steps (pa->threads;
 *                      the result does not depend on it).
 * compat_refine_abandon frees the refiner; c stays a valid compatible
 *                      triangulation of the last round (unpolished, its
 *                      vertices not renumbered) to be freed by the caller. */
struct compat_refiner;
struct compat_refiner *compat_refine_begin(struct compat *c, const struct compat_refine_params *pa,
                                           struct compat_refine_stats *st);
int compat_refine_step(struct compat_refiner *r);
void compat_refine_progress(const struct compat_refiner *r, double *worst, int *nbad, int *fewest);
int compat_refine_finish(struct compat_refiner *r);
void compat_refine_threads(struct compat_refiner *r, int threads);
void compat_refine_abandon(struct compat_refiner *r);
/* compat_refine_pass: the current pass (0: every bad triangle split, 1:
 * the share, 2: the lookahead; see split_share), its rounds so far, and
 * its last round's worst angle (radians, against what each corner allows)
 * and triangles below the goal -- that round's own, where
 * compat_refine_progress reports a later pass like a finished refinement
 * (compat-tri: candidates compared pass against pass).  Any output may be
 * NULL. */
void compat_refine_pass(const struct compat_refiner *r, int *pass, int *rounds, double *worst, int *nbad);


/* Quality of shape s: smallest angle (radians) of any triangle, and the
 * share of triangles (0..1) whose smallest angle is below 10 and below 20
 * degrees.  Any output pointer may be NULL. */
void compat_pose_quality(const struct compat *c, int s, double *min_angle,
                         double *under10, double *under20);

/* Sharpest outline corner over all shapes: the smallest interior angle
 * (radians) of the boundary polygon at a boundary vertex, measured as the
 * sum of the incident triangles' angles there.  No triangle can have a
 * larger smallest angle than this where that corner is. */
double compat_sharpest_corner(const struct compat *c);

#ifdef __cplusplus
}
#endif
#endif
