/* blas_tune.c -- see blas_tune.h */
#include "blas_tune.h"
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

extern char *openblas_get_corename(void);
extern void openblas_set_num_threads(int);

const char *blas_corename(void)
{
    return openblas_get_corename();
}

void blas_tune(char **argv)
{
    const char *e = getenv("STOPMO_BLAS_TUNE");
    if (e && !strcmp(e, "0")) return;
    if (getenv("OPENBLAS_CORETYPE")) return;
    const char *core = openblas_get_corename();
    if (!core || strcasecmp(core, "prescott") != 0) return;
    __builtin_cpu_init();
    const char *want = __builtin_cpu_supports("avx512f") ? "SkylakeX" :
                       __builtin_cpu_supports("avx2") ? "Haswell" : NULL;
    if (!want) return;
    setenv("OPENBLAS_CORETYPE", want, 1);
    execv("/proc/self/exe", argv);
    unsetenv("OPENBLAS_CORETYPE");      /* exec failed: carry on as we are */
}

/* OpenBLAS's pthread server (exported; absent from other builds: weak) */
extern int blas_thread_shutdown_(void) __attribute__((weak));

void blas_single_thread(void)
{
    if (getenv("OPENBLAS_NUM_THREADS") || getenv("OMP_NUM_THREADS")) return;
    openblas_set_num_threads(1);
    /* the workers OpenBLAS started when it loaded: stopped (no call starts
     * them again on one thread) */
    if (blas_thread_shutdown_) blas_thread_shutdown_();
}
