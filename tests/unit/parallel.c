/* parallel.c -- parallel_run runs every job exactly once, whatever the
 * number of threads (0: one per processor; more threads than jobs; none). */
#include "parallel.h"
#include "tap.h"
#include <string.h>

struct ctx { int count[100]; unsigned long value[100]; };

static void job(void *p, int i)
{
    struct ctx *c = p;
    c->count[i]++;
    unsigned long x = (unsigned long)i;
    for (int k = 0; k < 1000; k++) x = (x * 6364136223846793005UL + 1442695040888963407UL) >> 1;
    c->value[i] = x;
}

int main(void)
{
    static const int threads[] = {0, 1, 2, 3, 64, 200};
    struct ctx ref;
    memset(&ref, 0, sizeof ref);
    for (int i = 0; i < 100; i++) job(&ref, i);
    for (int t = 0; t < 6; t++) {
        struct ctx c;
        memset(&c, 0, sizeof c);
        parallel_run(100, threads[t], job, &c);
        int once = 1;
        for (int i = 0; i < 100; i++) once &= c.count[i] == 1;
        ok(once, "%d threads: every one of 100 jobs ran once", threads[t]);
        ok(!memcmp(c.value, ref.value, sizeof c.value), "%d threads: the same results as in order", threads[t]);
    }
    struct ctx z;
    memset(&z, 0, sizeof z);
    parallel_run(0, 2, job, &z);
    ok(z.count[0] == 0, "no jobs: nothing runs");
    parallel_run(1, 4, job, &z);
    ok(z.count[0] == 1, "one job on four threads runs once");
    return tap_done();
}
