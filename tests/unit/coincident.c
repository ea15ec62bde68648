/* coincident: duplicates_found, representative_is_smallest, refine_unwelds, faces_rewritten */
#include "coincident.h"
#include "tap.h"

int main(void)
{
    double V[15] = {0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0};
    int rep[5], F[6] = {0, 1, 4, 2, 3, 4}, Fw[6];
    int n = coincident_find(V, 5, rep);
    ok(n == 2, "coincident: two duplicates found (%d)", n);
    ok(rep[0] == 0 && rep[2] == 0 && rep[1] == 1 && rep[3] == 1 && rep[4] == 4,
       "coincident: representative is the smallest index");
    coincident_faces(F, 2, rep, Fw);
    ok(Fw[3] == 0 && Fw[4] == 1 && Fw[5] == 4, "coincident: faces rewritten");
    V[3 * 3 + 1] = 1e-300;   /* vertex 3 leaves vertex 1 in this frame */
    int u = coincident_refine(V, 5, rep);
    ok(u == 1 && rep[3] == 3 && rep[2] == 0, "coincident: refine un-welds a vertex that moved");
    return tap_done();
}
