/* mesh_concat.c -- see mesh_concat.h */
#include "mesh_concat.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>

int mesh_read_concat(const char *const *paths, int n, struct mesh *m)
{
    memset(m, 0, sizeof *m);
    struct mesh *all = calloc(n > 0 ? n : 1, sizeof *all);
    int total = 0, rc = -1;
    for (int i = 0; i < n; i++) {
        if (mesh_read(paths[i], &all[i]) < 0) goto done;
        const char *name = paths[i] && strcmp(paths[i], "-") ? paths[i] : "<stdin>";
        if (i > 0) {
            if (all[i].nv != all[0].nv || all[i].nf != all[0].nf) {
                cm_seterr("cannot use '%s': different connectivity (%d vertices, %d faces; "
                          "expected %d, %d): register it first (nricp)",
                          name, all[i].nv, all[i].nf, all[0].nv, all[0].nf);
                goto done;
            }
            if (memcmp(all[i].F, all[0].F, (size_t)all[0].nf * 3 * sizeof(int))) {
                cm_seterr("cannot use '%s': different connectivity (same counts, different "
                          "faces): register it first (nricp)", name);
                goto done;
            }
        }
        total += all[i].nframes;
    }
    if (n < 1) { cm_seterr("no input"); goto done; }
    if (mesh_alloc(m, all[0].nv, all[0].nf, total) < 0) goto done;
    memcpy(m->F, all[0].F, (size_t)all[0].nf * 3 * sizeof(int));
    {
        int k = 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < all[i].nframes; j++, k++) {
                memcpy(mesh_frame(m, k), mesh_frame(&all[i], j), (size_t)m->nv * 3 * sizeof(double));
                m->cut[k] = all[i].cut[j];
            }
    }
    rc = 0;
done:
    for (int i = 0; i < n; i++) mesh_free(&all[i]);
    free(all);
    return rc;
}
