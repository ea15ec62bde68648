/* clay-classify -- the thesis' Chapter 2 heuristic: scores of the four
 * shape mapping classes for a clay character described by its motion
 * segments, and its category C1 / C2 / C3.
 */
#include "clay_classify.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>
#include <errno.h>

static const char help[] =
"Usage: clay-classify [options] [SEGMENTS]\n"
"Score the shape mapping classes (uniform, nonuniform, extrinsic, intrinsic)\n"
"for a character (thesis Eq. 2.1, Table 2.2) and print its category.\n"
"SEGMENTS: one motion segment per line, '#' comments:\n"
"  CLASS VOLUME SMALL INTERMEDIATE LARGE SALIENT\n"
"CLASS: small-bend spring harmonic furl large-bend (by skeleton),\n"
"       rotate translate scale squash-stretch inflate protract (by shape);\n"
"VOLUME: share of the character's volume (the shares sum to 1);\n"
"SMALL INTERMEDIATE LARGE: frame transitions at each deformation scale\n"
"(overlap(1)); SALIENT: number of salient points on the segment.\n"
"\n"
"Options:\n"
"  -h, --help       show this help\n"
"      --version    show the version\n"
"\n"
"Example: printf 'squash-stretch 0.6 3 2 0 1\\nfurl 0.3 0 2 3 0\\ntranslate 0.1 3 1 1 2\\n' | clay-classify\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {{"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    int c;
    while ((c = getopt_long(argc, argv, "h", lo, NULL)) != -1) {
        switch (c) {
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (argc - optind > 1) usage_error("expected at most one input");
    const char *path = optind < argc ? argv[optind] : "-";
    const char *name = strcmp(path, "-") ? path : "<stdin>";
    FILE *f = strcmp(path, "-") ? fopen(path, "r") : stdin;
    if (!f) die("cannot read '%s': %s", name, strerror(errno));
    struct clay_segment *s = NULL;
    int n = 0, cap = 0;
    long line = 0;
    char buf[1024];
    double vsum = 0;
    while (fgets(buf, sizeof buf, f)) {
        line++;
        char *h = strchr(buf, '#');
        if (h) *h = 0;
        char cls[64];
        double vol;
        int a, b, d, sal, used = 0;
        if (sscanf(buf, " %63s", cls) != 1) continue;
        if (sscanf(buf, " %63s %lf %d %d %d %d %n", cls, &vol, &a, &b, &d, &sal, &used) != 6 ||
            buf[used] != 0)
            die("cannot read '%s': line %ld: expected CLASS VOLUME SMALL INTERMEDIATE LARGE SALIENT",
                name, line);
        int k = clay_anim_index(cls);
        if (k < 0) die("cannot read '%s': line %ld: unknown animation class '%s'", name, line, cls);
        if (!(vol > 0 && vol <= 1)) die("cannot read '%s': line %ld: volume share must be in (0, 1]", name, line);
        if (a < 0 || b < 0 || d < 0 || sal < 0)
            die("cannot read '%s': line %ld: counts must be >= 0", name, line);
        if (n == cap) s = realloc(s, (cap = cap ? 2 * cap : 8) * sizeof *s);
        s[n++] = (struct clay_segment){k, vol, a, b, d, sal};
        vsum += vol;
    }
    if (ferror(f)) die("cannot read '%s': read error", name);
    if (f != stdin) fclose(f);
    if (n == 0) die("cannot read '%s': no segments", name);
    if (fabs(vsum - 1) > 1e-6) die("cannot read '%s': volume shares sum to %g, not 1", name, vsum);
    double score[MAP_COUNT];
    int best[2];
    int cat = clay_classify(s, n, score, best);
    static const char *catname[] = {"", "C1 globally nonuniform - intrinsic metric",
                                    "C2 globally uniform - extrinsic metric",
                                    "C3 extrinsic metric - intrinsic metric"};
    for (int m = 0; m < MAP_COUNT; m++) printf("%s %.4g\n", clay_map_names[m], score[m]);
    printf("best %s %s\n", clay_map_names[best[0]], clay_map_names[best[1]]);
    printf("category %s\n", catname[cat]);
    if (fflush(stdout) != 0) die("cannot write output");
    free(s);
    return 0;
}
