/* tool.c -- see tool.h */
#include "tool.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char *progname = "stopmo";
int verbose = 0;

#define MAX_OUTS 256
static struct { FILE *f; char *tmp; char *path; } outs[MAX_OUTS];

static void remove_temporaries(void)
{
    for (int i = 0; i < MAX_OUTS; i++)
        if (outs[i].tmp) {
            unlink(outs[i].tmp);
            outs[i].tmp = NULL;
        }
}

void tool_init(int argc, char **argv)
{
    (void)argc;
    const char *s = strrchr(argv[0], '/');
    progname = s ? s + 1 : argv[0];
    atexit(remove_temporaries);
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
    exit(EXIT_BADINPUT);
}

void usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg("", fmt, ap);
    va_end(ap);
    fprintf(stderr, "Try '%s --help' for more information.\n", progname);
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
            size_t n = strlen(path) + 32;
            outs[i].tmp = malloc(n);
            snprintf(outs[i].tmp, n, "%s.tmp%ld", path, (long)getpid());
            outs[i].path = strdup(path);
            outs[i].f = fopen(outs[i].tmp, "wb");
            if (!outs[i].f) {
                int e = errno;
                free(outs[i].tmp);
                outs[i].tmp = NULL;
                die("cannot write '%s': %s", path, strerror(e));
            }
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
            if (outs[i].tmp && rename(outs[i].tmp, outs[i].path) != 0)
                die("cannot rename to '%s': %s", outs[i].path, strerror(errno));
            free(outs[i].tmp);
            free(outs[i].path);
            outs[i].tmp = outs[i].path = NULL;
            outs[i].f = NULL;
            return;
        }
    die("internal: out_close on unknown file");
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
