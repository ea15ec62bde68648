/* fuzz_replay.c -- make check replays every fuzz input kept in the tree
 * (tests/fuzz/corpus/NAME/: seeds and what the fuzzers found worth
 * keeping; tests/fuzz/regress/NAME/: inputs that once crashed or failed an
 * oracle) through the harnesses of tests/fuzz/, built here with the normal
 * compiler and flags, no libFuzzer.  A crash or a failed oracle (abort)
 * fails the test; each target prints how many inputs it ran. */
#define _GNU_SOURCE
#include "tap.h"
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>

#define FUZZ_TARGET(name) static int fuzz_##name
#include "../fuzz/fuzz_mesh.c"
#include "../fuzz/fuzz_meshio.c"
#include "../fuzz/fuzz_gltf.c"
#include "../fuzz/fuzz_columns.c"
#include "../fuzz/fuzz_rings.c"
#include "../fuzz/fuzz_compat.c"
#include "../fuzz/fuzz_holes.c"

static const struct { const char *name; int (*run)(const uint8_t *, size_t); } targets[] = {
    {"mesh", fuzz_mesh}, {"meshio", fuzz_meshio}, {"gltf", fuzz_gltf},
    {"columns", fuzz_columns}, {"rings", fuzz_rings}, {"compat", fuzz_compat}, {"holes", fuzz_holes}};

/* run every file of dir through fn in a child (a crash is a failure of that
 * input, named, not of the whole test); returns the count, *bad the failures */
static int replay_dir(const char *dir, int (*fn)(const uint8_t *, size_t), int *bad)
{
    DIR *d = opendir(dir);
    if (!d) return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        FILE *f = fopen(path, "rb");
        if (!f) continue;
        struct stat st;
        fstat(fileno(f), &st);
        uint8_t *buf = malloc((size_t)st.st_size + 1);
        size_t len = fread(buf, 1, (size_t)st.st_size, f);
        fclose(f);
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0) {
            fn(buf, len);
            _exit(0);
        }
        int status = 0;
        waitpid(pid, &status, 0);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            diag("%s: %s", path, WIFSIGNALED(status) ? strsignal(WTERMSIG(status)) : "exit status not 0");
            (*bad)++;
        }
        free(buf);
        n++;
    }
    closedir(d);
    return n;
}

int main(void)
{
    /* the source tree, from this file's name (make builds from the top) */
    char root[4096];
    snprintf(root, sizeof root, "%s", __FILE__);
    char *s = strstr(root, "tests/unit/fuzz_replay.c");
    if (s) *s = 0;
    if (!*root) strcpy(root, "./");
    for (size_t t = 0; t < sizeof targets / sizeof *targets; t++) {
        char dir[4200];
        int bad = 0, n = 0;
        snprintf(dir, sizeof dir, "%stests/fuzz/corpus/%s", root, targets[t].name);
        n += replay_dir(dir, targets[t].run, &bad);
        snprintf(dir, sizeof dir, "%stests/fuzz/regress/%s", root, targets[t].name);
        n += replay_dir(dir, targets[t].run, &bad);
        ok(n > 0 && bad == 0, "fuzz target %s: %d inputs replayed, %d failed", targets[t].name, n, bad);
    }
    return tap_done();
}
