/* lib-budget -- one printing budget for every part (past StopShop, which
 * sets the library size part by part): from each part's error-vs-size
 * curve (dict-learn --sweep), the library sizes with the least total error
 * whose pieces (or grams of resin) fit the budget.
 */
#include "budget.h"
#include "columns.h"
#include "tool.h"
#include "cm_error.h"
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: lib-budget [options] (-n PIECES | -g GRAMS) SWEEP...\n"
"Split one printing budget across parts.  SWEEP: one file per part, the\n"
"part's error-vs-size curve as written by dict-learn --sweep (rows\n"
"\"d energy mean_err max_err\").  Prints, per part, the library size to learn\n"
"so the summed error (default: the energy, which adds up over parts) is\n"
"least and the pieces (or grams) stay within the budget:\n"
"  # comments: method, convexity of every curve, greedy vs exact\n"
"  part pieces error cost\n"
"  ...\n"
"  total PIECES ERROR COST\n"
"\n"
"The exact method is dynamic programming over parts on (cost, error) Pareto\n"
"fronts: optimal for any curves.  Greedy on marginal gain (the step with the\n"
"largest error drop per unit of cost, while it fits) is optimal only for\n"
"convex curves; the comments say which curves are not convex and what the\n"
"greedy choice would cost in error.\n"
"\n"
"Options:\n"
"  -n, --pieces N        total pieces to print\n"
"  -g, --grams G         total grams of resin instead (needs --piece-grams)\n"
"      --piece-grams L   comma separated grams per piece, one per part (e.g.\n"
"                        the mean of piece-plug --report's or assembly-sheet's\n"
"                        catalogue grams for that part)\n"
"      --column K        error column of the sweep files (default 2, energy;\n"
"                        3 mean and 4 max error do not add up over parts)\n"
"      --method M        exact (default) or greedy\n"
"      --names LIST      comma separated part names for the output\n"
"  -o, --output FILE     write to FILE instead of stdout\n"
"  -v, --verbose         the curves' convexity on stderr too\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: lib-budget -n 40 sweep_0.txt sweep_1.txt >budget.txt\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"pieces", 1, 0, 'n'}, {"grams", 1, 0, 'g'}, {"piece-grams", 1, 0, 'G'}, {"column", 1, 0, 'k'},
        {"method", 1, 0, 'm'}, {"names", 1, 0, 'N'}, {"output", 1, 0, 'o'}, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    long pieces = -1;
    double grams = -1;
    const char *pg = NULL, *output = NULL;
    char *names = NULL;
    int col = 2, c;
    enum budget_method method = BUDGET_EXACT;
    while ((c = getopt_long(argc, argv, "n:g:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'n': pieces = arg_long(optarg, "--pieces"); break;
        case 'g': grams = arg_double(optarg, "--grams");
            if (!(grams > 0) || !isfinite(grams)) usage_error("--grams must be > 0");
            break;
        case 'G': pg = optarg; break;
        case 'k': col = (int)arg_long(optarg, "--column");
            if (col < 2) usage_error("--column must be >= 2 (column 1 is the size d)");
            break;
        case 'm':
            if (!strcmp(optarg, "exact")) method = BUDGET_EXACT;
            else if (!strcmp(optarg, "greedy")) method = BUDGET_GREEDY;
            else usage_error("--method: '%s' is not exact or greedy", optarg);
            break;
        case 'N': names = optarg; break;
        case 'o': output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    int np = argc - optind;
    if (np < 1) usage_error("expected one SWEEP file per part");
    if ((pieces >= 0) == (grams > 0)) usage_error("give one budget: -n PIECES or -g GRAMS");
    if (grams > 0 && !pg) usage_error("-g needs --piece-grams (grams per piece of every part)");
    if (pg && grams <= 0) usage_error("--piece-grams goes with -g GRAMS");
    double *cost = malloc(sizeof(double) * np);
    for (int p = 0; p < np; p++) cost[p] = 1;
    if (pg) {
        const char *s = pg;
        for (int p = 0; p < np; p++) {
            char *end;
            cost[p] = strtod(s, &end);
            if (end == s || !(cost[p] > 0) || !isfinite(cost[p]) || (p + 1 < np ? *end != ',' : *end != 0))
                usage_error("--piece-grams: '%s' is not %d positive numbers separated by commas", pg, np);
            s = end + 1;
        }
    }
    char **name = calloc(np, sizeof(char *));
    if (names) {
        int k = 0;
        for (char *t = strtok(names, ","); t; t = strtok(NULL, ",")) { if (k < np) name[k] = t; k++; }
        if (k != np) usage_error("--names: %d names for %d parts", k, np);
    }
    /* every part needs one piece at least */
    if (pieces >= 0 && pieces < np)
        die("a budget of %ld pieces is below the number of parts (%d): every part needs at least one piece",
            pieces, np);

    int *n = malloc(sizeof(int) * np), **d = malloc(sizeof(int *) * np);
    double **e = malloc(sizeof(double *) * np);
    for (int p = 0; p < np; p++) {
        const char *path = argv[optind + p];
        struct columns t = {0};
        if (columns_read(path, 0, -1, "sizes", &t) < 0) die("%s", cm_errmsg());
        if (t.rows < 1) die("cannot read '%s': no rows (dict-learn --sweep writes \"d energy mean_err max_err\")", path);
        if (t.cols < col) die("cannot read '%s': %d columns, --column %d asked", path, t.cols, col);
        n[p] = t.rows;
        d[p] = malloc(sizeof(int) * t.rows);
        e[p] = malloc(sizeof(double) * t.rows);
        for (int i = 0; i < t.rows; i++) {
            double x = t.x[i * t.cols];
            if (x != floor(x) || x < 1 || x > 1e9)
                die("cannot read '%s': row %d: size %g is not a positive integer", path, i + 1, x);
            d[p][i] = (int)x;
            e[p][i] = t.x[i * t.cols + col - 1];
            if (i && d[p][i] <= d[p][i - 1])
                die("cannot read '%s': row %d: sizes must increase (%d after %d)", path, i + 1, d[p][i], d[p][i - 1]);
        }
        columns_free(&t);
    }
    double budget = pieces >= 0 ? (double)pieces : grams;
    int *pick = malloc(sizeof(int) * np), *gpick = malloc(sizeof(int) * np);
    double tc, te, gc, ge;
    if (budget_allocate(np, n, (const int *const *)d, (const double *const *)e, cost, budget, method, pick, &tc, &te) < 0)
        die("%s%s", cm_errmsg(), pieces >= 0 ? " pieces" : " g");
    int gok = budget_allocate(np, n, (const int *const *)d, (const double *const *)e, cost, budget,
                              method == BUDGET_EXACT ? BUDGET_GREEDY : BUDGET_EXACT, gpick, &gc, &ge) == 0;

    FILE *out = out_open(output);
    fprintf(out, "# lib-budget: %g %s, %s\n", budget, pieces >= 0 ? "pieces" : "g of resin",
            method == BUDGET_EXACT ? "exact (dynamic programming over parts, Pareto fronts)"
                                   : "greedy on marginal gain");
    int allconvex = 1;
    for (int p = 0; p < np; p++) {
        int at;
        int cv = budget_curve_convex(n[p], d[p], e[p], &at);
        allconvex &= cv;
        if (cv) fprintf(out, "# part %d: curve convex over d = %d..%d (%d sizes)\n", p, d[p][0], d[p][n[p] - 1], n[p]);
        else fprintf(out, "# part %d: curve NOT convex (the drop per piece grows after d = %d): greedy may miss\n", p, at);
        if (!cv) info(1, "part %d: error curve not convex at d = %d", p, at);
    }
    if (gok)
        fprintf(out, "# %s would give total error %.10g at cost %g (%s)\n",
                method == BUDGET_EXACT ? "greedy" : "exact", ge, gc,
                fabs(ge - te) <= 1e-12 * fabs(te) ? "the same" : ge > te ? "worse" : "better");
    fprintf(out, "# part pieces error cost\n");
    for (int p = 0; p < np; p++) {
        if (name[p]) fprintf(out, "%s", name[p]); else fprintf(out, "%d", p);
        fprintf(out, " %d %.10g %.10g\n", d[p][pick[p]], e[p][pick[p]], cost[p] * d[p][pick[p]]);
    }
    int total = 0;
    for (int p = 0; p < np; p++) total += d[p][pick[p]];
    fprintf(out, "total %d %.10g %.10g\n", total, te, tc);
    out_close(out);
    info(1, "%d pieces over %d parts, total error %g%s", total, np, te, allconvex ? "" : " (a curve is not convex)");
    for (int p = 0; p < np; p++) { free(d[p]); free(e[p]); }
    free(d); free(e); free(n); free(pick); free(gpick); free(cost); free(name);
    return 0;
}
