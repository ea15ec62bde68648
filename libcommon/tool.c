/* tool.c -- see tool.h */
#include "tool.h"
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define TOOL_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TOOL_LSAN 1
#endif
#endif
#ifdef TOOL_LSAN
/* Sanitizer builds (make check-sanitize): a tool that dies (die,
 * usage_error) exits with everything it was working on still allocated,
 * and LeakSanitizer's at-exit check would call that a leak.  So the tools'
 * leak check runs from their own atexit handler instead, skipped only when
 * they exit through die() or usage_error(): every other exit (return from
 * main, exit from --help, a write error) is still checked.  Units and other
 * programs that do not link tool.o keep LSan's own check. */
#include <sanitizer/lsan_interface.h>
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "leak_check_at_exit=0"; }
static volatile int dying;
static void leak_check(void)
{
    if (!dying) __lsan_do_leak_check();
}
#define TOOL_DYING() (dying = 1)
#else
#define TOOL_DYING() ((void)0)
#endif

const char *progname = "stopmo";
int verbose = 0;

#define MAX_OUTS 256
/* tmp is read by the signal handler: it is set only once the name is
 * complete, and cleared before it is freed */
static struct { FILE *f; char *volatile tmp; char *path; } outs[MAX_OUTS];
static mode_t file_mode = 0644;   /* 0666 less the umask */

static void remove_temporaries(void)
{
    for (int i = 0; i < MAX_OUTS; i++) {
        char *t = outs[i].tmp;
        if (t) {
            outs[i].tmp = NULL;
            unlink(t);
        }
    }
}

/* SIGINT, SIGTERM, SIGHUP, SIGPIPE: remove the temporaries (unlink is
 * async-signal-safe), then die of the signal as if there were no handler */
static void on_signal(int sig)
{
    for (int i = 0; i < MAX_OUTS; i++)
        if (outs[i].tmp)
            unlink(outs[i].tmp);
    signal(sig, SIG_DFL);
    raise(sig);
}

void tool_init(int argc, char **argv)
{
    (void)argc;
    const char *s = strrchr(argv[0], '/');
    progname = s ? s + 1 : argv[0];
#ifdef TOOL_LSAN
    atexit(leak_check);   /* runs after remove_temporaries */
#endif
    atexit(remove_temporaries);
    mode_t um = umask(0);
    umask(um);
    file_mode = 0666 & ~um;
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
    for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++) {
        struct sigaction sa, old;
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;           /* ignored by the parent (nohup, SIGPIPE): keep it so */
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

static void vmsg(const char *prefix, const char *fmt, va_list ap)
{
    fflush(stdout);
    fprintf(stderr, "%s: %s", progname, prefix);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void die(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg("", fmt, ap);
    va_end(ap);
    TOOL_DYING();
    exit(EXIT_BADINPUT);
}

void usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg("", fmt, ap);
    va_end(ap);
    fprintf(stderr, "Try '%s --help' for more information.\n", progname);
    TOOL_DYING();
    exit(EXIT_USAGE);
}

void info(int level, const char *fmt, ...)
{
    if (verbose < level)
        return;
    va_list ap;
    va_start(ap, fmt);
    vmsg("", fmt, ap);
    va_end(ap);
}

void warn(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg("warning: ", fmt, ap);
    va_end(ap);
}

void print_help_and_exit(const char *text)
{
    fputs(text, stdout);
    exit(fclose(stdout) == 0 ? 0 : 1);
}

void print_version_and_exit(void)
{
    printf("%s (stopmo) %s\n", progname, STOPMO_VERSION);
    exit(0);
}

double arg_double(const char *s, const char *what)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(v))
        usage_error("%s: '%s' is not a number", what, s);
    return v;
}

long arg_long(const char *s, const char *what)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || errno)
        usage_error("%s: '%s' is not an integer", what, s);
    return v;
}

int arg_int_range(const char *s, const char *what, long lo, long hi)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || (errno && errno != ERANGE))
        usage_error("%s: '%s' is not an integer", what, s);
    if (errno == ERANGE || v < lo || v > hi)
        usage_error("%s: %s is out of range (%ld..%ld)", what, s, lo, hi);
    return (int)v;
}

int arg_int(const char *s, const char *what)
{
    return arg_int_range(s, what, INT_MIN, INT_MAX);
}

int arg_intlist(const char *s, const char *what, int **out)
{
    int n = 0, cap = 8;
    int *v = malloc(cap * sizeof *v);
    const char *p = s;
    while (*p) {
        char *end;
        errno = 0;
        long x = strtol(p, &end, 10);
        if (end == p || errno || (*end && *end != ','))
            usage_error("%s: '%s' is not a comma separated list of integers", what, s);
        if (x < INT_MIN || x > INT_MAX)
            usage_error("%s: %ld is out of range (%d..%d)", what, x, INT_MIN, INT_MAX);
        if (n == cap)
            v = realloc(v, (cap *= 2) * sizeof *v);
        v[n++] = (int)x;
        p = *end ? end + 1 : end;
    }
    if (n == 0)
        usage_error("%s: empty list", what);
    *out = v;
    return n;
}

int arg_doublelist(const char *s, const char *what, double **out)
{
    int n = 0, cap = 8;
    double *v = malloc(cap * sizeof *v);
    const char *p = s;
    while (*p) {
        char *end;
        errno = 0;
        double x = strtod(p, &end);
        if (end == p || errno || !isfinite(x) || (*end && *end != ','))
            usage_error("%s: '%s' is not a comma separated list of numbers", what, s);
        if (n == cap)
            v = realloc(v, (cap *= 2) * sizeof *v);
        v[n++] = x;
        p = *end ? end + 1 : end;
    }
    if (n == 0)
        usage_error("%s: empty list", what);
    *out = v;
    return n;
}

double arg_nonneg(const char *s, const char *what)
{
    double v = arg_double(s, what);
    if (!(v >= 0)) usage_error("%s must be >= 0, got '%s'", what, s);
    return v;
}

int arg_nonneg_list(const char *s, const char *what, double **out)
{
    int n = arg_doublelist(s, what, out);
    for (int k = 0; k < n; k++)
        if (!((*out)[k] >= 0)) usage_error("%s: %g is negative", what, (*out)[k]);
    return n;
}

FILE *out_open(const char *path)
{
    if (!path || !strcmp(path, "-"))
        return stdout;
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        /* a device or FIFO (/dev/null, a named pipe): there is nothing to
         * replace atomically, and renaming over it would destroy it */
        FILE *f = fopen(path, "wb");
        if (!f)
            die("cannot write '%s': %s", path, strerror(errno));
        for (int i = 0; i < MAX_OUTS; i++)
            if (!outs[i].f) {
                outs[i].f = f;
                outs[i].path = strdup(path);
                outs[i].tmp = NULL;
                return f;
            }
        die("too many output files open");
    }
    for (int i = 0; i < MAX_OUTS; i++)
        if (!outs[i].f) {
            /* mkstemp: a new file of our own (O_EXCL), never a planted link */
            size_t n = strlen(path) + 16;
            char *tmp = malloc(n);
            if (!tmp)
                die("out of memory");
            snprintf(tmp, n, "%s.tmpXXXXXX", path);
            int fd = mkstemp(tmp);
            if (fd < 0) {
                int e = errno;
                free(tmp);
                die("cannot write '%s': %s", path, strerror(e));
            }
            outs[i].tmp = tmp;
            if (fchmod(fd, file_mode) != 0 || !(outs[i].f = fdopen(fd, "wb"))) {
                int e = errno;
                close(fd);
                die("cannot write '%s': %s", path, strerror(e));
            }
            outs[i].path = strdup(path);
            return outs[i].f;
        }
    die("too many output files open");
}

void out_close(FILE *f)
{
    if (f == stdout) {
        if (fflush(stdout) != 0 || ferror(stdout))
            die("cannot write output: %s", strerror(errno));
        return;
    }
    for (int i = 0; i < MAX_OUTS; i++)
        if (outs[i].f == f) {
            int bad = ferror(f) | fflush(f);
            if (fclose(f) != 0 || bad)
                die("cannot write '%s': %s", outs[i].path, strerror(errno));
            char *tmp = outs[i].tmp;
            if (tmp && rename(tmp, outs[i].path) != 0)
                die("cannot rename to '%s': %s", outs[i].path, strerror(errno));
            outs[i].tmp = NULL;
            free(tmp);
            free(outs[i].path);
            outs[i].path = NULL;
            outs[i].f = NULL;
            return;
        }
    die("internal: out_close on unknown file");
}

int pattern_check(const char *s, const char *what, int need)
{
    int n = 0;
    for (const char *p = s; *p; p++) {
        if (*p != '%') continue;
        if (p[1] == '%') { p++; continue; }
        p++;
        while (*p == '0' || *p == '-') p++;
        int width = 0;
        while (*p >= '0' && *p <= '9') {
            width = width * 10 + (*p++ - '0');
            if (width > 32)
                usage_error("%s: '%s': a field width of at most 32", what, s);
        }
        if (*p != 'd' && *p != 'i')
            usage_error("%s: '%s': only %%d (with a width) and %%%% are allowed in a pattern", what, s);
        n++;
    }
    if (n > 1)
        usage_error("%s: '%s': more than one %%d", what, s);
    if (need && n != 1)
        usage_error("%s: '%s' needs exactly one %%d", what, s);
    return n;
}

char *pattern_format(const char *pattern, int k)
{
    int n = snprintf(NULL, 0, pattern, k);
    char *s = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (!s)
        die("cannot format the file name pattern '%s'", pattern);
    snprintf(s, (size_t)n + 1, pattern, k);
    return s;
}

int want_raw(int raw_flag)
{
    if (raw_flag)
        return 1;
    const char *e = getenv("STOPMO_RAW");
    return e && *e && strcmp(e, "0") != 0;
}

const char *arg_labels_and_input(int argc, char **argv, const char *labels)
{
    if (!labels)
        usage_error("missing -l LABELS (per-triangle part labels)");
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    const char *input = optind < argc ? argv[optind] : "-";
    if (!strcmp(labels, "-") && !strcmp(input, "-"))
        usage_error("the labels and the animation cannot both come from standard input");
    return input;
}
