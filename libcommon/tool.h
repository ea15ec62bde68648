/* tool.h -- the shared shape of every stopmo program (tools only).
 *
 * This is the one part of libcommon that may print and exit: it is the
 * program harness, used only from tools/NAME.c main() code, never from the
 * numerical library.  Conventions (DESIGN.md section 5):
 *   exit 0 ok, 1 bad input or failed computation, 2 usage error;
 *   messages go to stderr as "tool: message".
 */
#ifndef CM_TOOL_H
#define CM_TOOL_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

#define EXIT_BADINPUT 1
#define EXIT_USAGE 2

extern const char *progname;   /* set by tool_init() */
extern int verbose;            /* -v count */

/* Remember argv[0] (basename) for messages. */
void tool_init(int argc, char **argv);

/* "prog: msg" on stderr, exit 1. */
void die(const char *fmt, ...) __attribute__((noreturn, format(printf, 1, 2)));
/* "prog: msg" + "Try 'prog --help'." on stderr, exit 2. */
void usage_error(const char *fmt, ...) __attribute__((noreturn, format(printf, 1, 2)));
/* "prog: msg" on stderr when verbose >= level. */
void info(int level, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* "prog: warning: msg" on stderr. */
void warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Print the help text (to stdout) and exit 0. */
void print_help_and_exit(const char *text) __attribute__((noreturn));
/* Print "prog (stopmo) VERSION" and exit 0. */
void print_version_and_exit(void) __attribute__((noreturn));

/* Strict number parsing of option arguments; usage_error() on junk.
 * `what` names the option in the message. */
double arg_double(const char *s, const char *what);
long arg_long(const char *s, const char *what);
/* An integer option in [lo, hi]: usage_error() naming the range when it
 * lies outside (no silent wrap of "4294967304" to 8).  arg_int() is the
 * same over the whole range of int. */
int arg_int_range(const char *s, const char *what, long lo, long hi);
int arg_int(const char *s, const char *what);
/* Parse a comma separated list of integers into *out (malloc'd); returns
 * the count. */
int arg_intlist(const char *s, const char *what, int **out);
/* The same for finite numbers ("0,0.5,2"). */
int arg_doublelist(const char *s, const char *what, double **out);
/* A finite number >= 0, and a list of them: usage_error() naming `what`
 * otherwise. */
double arg_nonneg(const char *s, const char *what);
int arg_nonneg_list(const char *s, const char *what, double **out);

/* The input operand of a tool that reads per-triangle part labels from
 * LABELS (-l, required) and one animation (e.g. part-split, seam-homog),
 * after getopt_long: usage_error() when labels is NULL, when more than one
 * operand follows the options, or when labels and the input are both "-"
 * (standard input).  Returns argv[optind], or "-" when there is none. */
const char *arg_labels_and_input(int argc, char **argv, const char *labels);

/* Output file handling with "nothing half-written":
 * out_open(NULL or "-") returns stdout; otherwise a temporary file next to
 * `path` (mkstemp: "PATH.tmpXXXXXX", created exclusively, so a planted
 * symlink is never followed; mode 0666 less the umask) that out_close()
 * renames into place only on success.  If the program dies before
 * out_close(), the temporary is removed: at exit, and on SIGINT, SIGTERM,
 * SIGHUP and SIGPIPE (tool_init installs the handlers). */
FILE *out_open(const char *path);
/* Flush and close; rename the temporary; die on any write error. */
void out_close(FILE *f);

/* Output name patterns ("part_%d.mesh", "frame_%04d.obj"): at most
 * `max` (1: exactly one if `need`) integer conversions %d or %i, with an
 * optional '0' or '-' flag and a width of at most 32, and otherwise only
 * %% escapes; usage_error() naming `what` otherwise.  Returns the number
 * of conversions (0 or 1). */
int pattern_check(const char *pattern, const char *what, int need);
/* The pattern with k in place of its conversion (malloc'd). */
char *pattern_format(const char *pattern, int k);

/* Want raw (binary) MESH output?  --raw flag or STOPMO_RAW=1 in the
 * environment. */
int want_raw(int raw_flag);

#define STOPMO_VERSION "0.1"

#ifdef __cplusplus
}
#endif
#endif
