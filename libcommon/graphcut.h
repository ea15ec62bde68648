/* graphcut.h -- s-t minimum cut with the Boykov-Kolmogorov max-flow
 * algorithm (libmaxflow, BK 2004), behind a C interface.
 *
 *   struct graphcut *g = graphcut_new(nnodes, nedges_hint);
 *   graphcut_add_tweights(g, i, cost_if_sink, cost_if_source);
 *   graphcut_add_edge(g, i, j, cap_ij, cap_ji);
 *   double flow = graphcut_maxflow(g);
 *   int side = graphcut_side(g, i);     0 = source side, 1 = sink side
 *
 * Convention as in BK's code: add_tweights(i, cap_source, cap_sink); a node
 * on the SINK side pays cap_source (its source edge is cut) and a node on
 * the SOURCE side pays cap_sink.  Capacities must be >= 0 (tweights may be
 * any sign; BK normalizes them).
 */
#ifndef CM_GRAPHCUT_H
#define CM_GRAPHCUT_H
#ifdef __cplusplus
extern "C" {
#endif

struct graphcut;

struct graphcut *graphcut_new(int nnodes, int nedges_hint);
void graphcut_add_tweights(struct graphcut *g, int i, double cap_source, double cap_sink);
void graphcut_add_edge(struct graphcut *g, int i, int j, double cap_ij, double cap_ji);
double graphcut_maxflow(struct graphcut *g);
/* 0 if node i ends on the source side, 1 if on the sink side. */
int graphcut_side(struct graphcut *g, int i);
void graphcut_free(struct graphcut *g);

#ifdef __cplusplus
}
#endif
#endif
