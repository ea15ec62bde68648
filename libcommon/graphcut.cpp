// graphcut.cpp -- C wrapper of libmaxflow's BK Graph<double,double,double>.
#include "graphcut.h"
#include <maxflow/graph.h>
#include <new>

typedef maxflow::Graph<double, double, double> G;

struct graphcut {
    G *g;
};

static void on_error(const char *) { throw std::bad_alloc(); }

extern "C" struct graphcut *graphcut_new(int nnodes, int nedges_hint)
{
    try {
        graphcut *gc = new graphcut;
        gc->g = new G(nnodes > 0 ? nnodes : 1, nedges_hint > 0 ? nedges_hint : 1, on_error);
        gc->g->add_node(nnodes);
        return gc;
    } catch (...) {
        return nullptr;
    }
}

extern "C" void graphcut_add_tweights(struct graphcut *g, int i, double cs, double ct)
{
    g->g->add_tweights(i, cs, ct);
}

extern "C" void graphcut_add_edge(struct graphcut *g, int i, int j, double cij, double cji)
{
    g->g->add_edge(i, j, cij, cji);
}

extern "C" double graphcut_maxflow(struct graphcut *g) { return g->g->maxflow(); }

extern "C" int graphcut_side(struct graphcut *g, int i)
{
    return g->g->what_segment(i) == G::SINK ? 1 : 0;
}

extern "C" void graphcut_free(struct graphcut *g)
{
    if (!g) return;
    delete g->g;
    delete g;
}
