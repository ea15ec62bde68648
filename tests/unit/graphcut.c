/* graphcut: two_node_cut, chain_cut_matches_brute_force */
#include "graphcut.h"
#include "rng.h"
#include "tap.h"
#include <math.h>

int main(void)
{
    /* node 0 prefers source (sink cost 5 vs source cost 1), node 1 prefers
     * sink; edge 0-1 cost 2: the cut separates them with flow 1 + 2 + 1 */
    struct graphcut *g = graphcut_new(2, 1);
    graphcut_add_tweights(g, 0, 5, 1);
    graphcut_add_tweights(g, 1, 1, 5);
    graphcut_add_edge(g, 0, 1, 2, 2);
    double f = graphcut_maxflow(g);
    ok(fabs(f - 4) < 1e-12, "graphcut: two nodes, flow %g == 4", f);
    ok(graphcut_side(g, 0) == 0 && graphcut_side(g, 1) == 1, "graphcut: sides");
    graphcut_free(g);

    /* random 8-node problems vs brute force over 2^8 labelings */
    struct rng r;
    rng_seed(&r, 7);
    int agree = 1;
    for (int t = 0; t < 50; t++) {
        int n = 8;
        double cs[8], ct[8], w[8][8] = {{0}};
        g = graphcut_new(n, 32);
        for (int i = 0; i < n; i++) {
            cs[i] = rng_uniform(&r); ct[i] = rng_uniform(&r);
            graphcut_add_tweights(g, i, cs[i], ct[i]);
        }
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++)
                if (rng_uniform(&r) < 0.4) {
                    w[i][j] = rng_uniform(&r);
                    graphcut_add_edge(g, i, j, w[i][j], w[i][j]);
                }
        double flow = graphcut_maxflow(g), best = 1e300;
        for (int m = 0; m < 1 << n; m++) {
            double e = 0;
            for (int i = 0; i < n; i++) e += (m >> i & 1) ? cs[i] : ct[i];
            for (int i = 0; i < n; i++)
                for (int j = i + 1; j < n; j++)
                    if (((m >> i) ^ (m >> j)) & 1) e += w[i][j];
            if (e < best) best = e;
        }
        double e = 0;
        for (int i = 0; i < n; i++) e += graphcut_side(g, i) ? cs[i] : ct[i];
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++)
                if (graphcut_side(g, i) != graphcut_side(g, j)) e += w[i][j];
        if (fabs(flow - best) > 1e-9 || fabs(e - best) > 1e-9) agree = 0;
        graphcut_free(g);
    }
    ok(agree, "graphcut: min cut equals brute force on 50 random graphs");
    return tap_done();
}
