/* fuzz_common.h -- shared by the libFuzzer harnesses in tests/fuzz/.
 *
 * Each harness file defines one target with FUZZ_TARGET(name)(data, size).
 * Built by tests/fuzz/fuzz.mk with clang -fsanitize=fuzzer it is
 * LLVMFuzzerTestOneInput; tests/unit/fuzz_replay.c includes every harness
 * with FUZZ_TARGET defined to a plain function and replays the corpora and
 * the crash inputs (tests/fuzz/corpus/NAME/, tests/fuzz/regress/NAME/)
 * through the normal build in make check.
 *
 * An oracle that fails calls fuzz_fail(), which aborts (a crash the fuzzer
 * keeps, a failed replay).
 */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#ifndef FUZZ_TARGET
#define FUZZ_TARGET(name) int LLVMFuzzerTestOneInput
#endif

static inline void fuzz_fail(const char *what)
{
    fprintf(stderr, "fuzz oracle failed: %s\n", what);
    abort();
}

/* The input as a file the readers can open by name: a temporary with the
 * given suffix (".gltf"), unlinked by fuzz_file_done().  path: >= 64 bytes. */
static inline int fuzz_file(const uint8_t *data, size_t size, const char *suffix, char *path)
{
    const char *dir = getenv("TMPDIR");
    snprintf(path, 64, "%.30s/stopmo-fuzz-XXXXXX%s", dir && *dir ? dir : "/tmp", suffix);
    int fd = mkstemps(path, (int)strlen(suffix));
    if (fd < 0) fuzz_fail("mkstemps");
    size_t at = 0;
    while (at < size) {
        ssize_t k = write(fd, data + at, size - at);
        if (k <= 0) fuzz_fail("write");
        at += (size_t)k;
    }
    close(fd);
    return 0;
}

static inline void fuzz_file_done(const char *path) { unlink(path); }

#endif
