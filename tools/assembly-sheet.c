/* assembly-sheet -- the animator's sheet for a replacement animation
 * (StopShop Sec. 4): for every frame, which printed piece to mount on each
 * part, and a catalogue of the pieces to print (use count, frames, volume,
 * material).
 */
#include "mesh.h"
#include "columns.h"
#include "geometry.h"
#include "tool.h"
#include "cm_error.h"
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: assembly-sheet [options] LABELS...\n"
"Write the assembly sheet of a replacement animation as CSV on stdout:\n"
"\"frame,part0,part1,...\" with the piece id (0-based) to mount per part and\n"
"frame.  LABELS: one per part, per-frame piece labels (dict-learn\n"
"--labels-out, label-expand).  With --catalogue, also a piece catalogue.\n"
"\n"
"Options:\n"
"  -c, --catalogue FILE  write \"part,piece,count,frames,volume,grams\" CSV: how\n"
"                        many frames use each piece and which (ranges a-b\n"
"                        separated by ';')\n"
"  -s, --solids LIST     comma separated solid libraries (shell-extrude output,\n"
"                        one per part, same order): gives the piece count,\n"
"                        volumes and grams\n"
"      --volumes FILE    piece volumes instead: rows \"part piece volume ...\"\n"
"                        (piece-plug --report; model units^3)\n"
"  -n, --names LIST      comma separated part names for the header\n"
"      --density D       material density in g/cm^3 (default 1.2, PLA/resin)\n"
"      --unit-mm U       length of one model unit in mm (default 1)\n"
"      --changes         list only the frames where a piece changes, and in\n"
"                        them only the parts that change (others left empty);\n"
"                        frame 0 lists every part\n"
"  -o, --output FILE     write the sheet to FILE instead of stdout\n"
"  -v, --verbose         pieces used and total material on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: assembly-sheet -n upper,lower -s up.solid,low.solid -c pieces.csv \\\n"
"             up.lab low.lab >sheet.csv\n";

static int split(char *s, char ***out)
{
    int n = 1;
    for (char *p = s; *p; p++) n += *p == ',';
    char **v = malloc(sizeof(char *) * n);
    int k = 0;
    for (char *tok = strtok(s, ","); tok; tok = strtok(NULL, ",")) v[k++] = tok;
    *out = v;
    return k;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"catalogue", 1, 0, 'c'}, {"solids", 1, 0, 's'}, {"volumes", 1, 0, 'W'}, {"changes", 0, 0, 'X'}, {"names", 1, 0, 'n'},
        {"density", 1, 0, 'D'}, {"unit-mm", 1, 0, 'U'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    const char *catalogue = NULL, *output = NULL, *volumes = NULL;
    char *solids = NULL, *names = NULL;
    double density = 1.2, unit = 1;
    int c, changes = 0;
    while ((c = getopt_long(argc, argv, "c:s:n:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'c': catalogue = optarg; break;
        case 's': solids = optarg; break;
        case 'W': volumes = optarg; break;
        case 'X': changes = 1; break;
        case 'n': names = optarg; break;
        case 'D': density = arg_double(optarg, "--density");
            if (!(density > 0)) usage_error("--density must be > 0");
            break;
        case 'U': unit = arg_double(optarg, "--unit-mm");
            if (!(unit > 0)) usage_error("--unit-mm must be > 0");
            break;
        case 'o': output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    int np = argc - optind;
    if (np < 1) usage_error("expected at least one LABELS file");
    char **name = NULL, **solid = NULL;
    int nlist;
    if (names && (nlist = split(names, &name)) != np) usage_error("--names: %d names for %d parts", nlist, np);
    if (solids && (nlist = split(solids, &solid)) != np) usage_error("--solids: %d files for %d parts", nlist, np);

    if (solids && volumes) usage_error("--solids and --volumes exclude each other");
    int **L = malloc(sizeof(int *) * np), *npieces = calloc(np, sizeof(int)), n = -1;
    double **vol = calloc(np, sizeof(double *));
    if (volumes) {
        struct columns vc = {0};
        if (columns_read(volumes, 0, -1, "pieces", &vc) < 0) die("%s", cm_errmsg());
        if (vc.cols < 3) die("cannot read '%s': %d columns, expected \"part piece volume\"", volumes, vc.cols);
        for (int i = 0; i < vc.rows; i++) {
            double pp = vc.x[i * vc.cols], kk = vc.x[i * vc.cols + 1];
            if (pp != floor(pp) || pp < 0 || pp >= np || kk != floor(kk) || kk < 0 || kk > 1e7)
                die("cannot read '%s': row %d: part %g piece %g (%d parts)", volumes, i + 1, pp, kk, np);
            if (kk + 1 > npieces[(int)pp]) npieces[(int)pp] = (int)kk + 1;
        }
        for (int p = 0; p < np; p++) {
            vol[p] = malloc(sizeof(double) * (npieces[p] + 1));
            for (int k = 0; k < npieces[p]; k++) vol[p][k] = NAN;
        }
        for (int i = 0; i < vc.rows; i++)
            vol[(int)vc.x[i * vc.cols]][(int)vc.x[i * vc.cols + 1]] = fabs(vc.x[i * vc.cols + 2]);
        for (int p = 0; p < np; p++)
            for (int k = 0; k < npieces[p]; k++)
                if (isnan(vol[p][k])) die("cannot read '%s': no volume for part %d piece %d", volumes, p, k);
        columns_free(&vc);
    }
    for (int p = 0; p < np; p++) {
        int hi = -1;
        struct mesh s;
        if (solids) {
            if (mesh_read(solid[p], &s) < 0) die("%s", cm_errmsg());
            npieces[p] = s.nframes;
            hi = s.nframes - 1;
            vol[p] = malloc(sizeof(double) * s.nframes);
            for (int k = 0; k < s.nframes; k++) vol[p][k] = fabs(mesh_volume(mesh_frame(&s, k), s.F, s.nf));
            mesh_free(&s);
        }
        int rows;
        if (volumes) hi = npieces[p] - 1;
        if (labels_read(argv[optind + p], n, "frames", 0, hi, &L[p], &rows) < 0) die("%s", cm_errmsg());
        n = rows;
        if (n == 0)
            die("cannot read '%s': no labels (one piece id per frame expected)", argv[optind + p]);
        if (!solids && !volumes)
            for (int f = 0; f < n; f++) if (L[p][f] + 1 > npieces[p]) npieces[p] = L[p][f] + 1;
    }

    FILE *out = out_open(output);
    fprintf(out, "frame");
    for (int p = 0; p < np; p++)
        if (name) fprintf(out, ",%s", name[p]); else fprintf(out, ",part%d", p);
    fprintf(out, "\n");
    int swaps = 0;
    for (int f = 0; f < n; f++) {
        int changed = f == 0;
        for (int p = 0; p < np && f; p++) changed |= L[p][f] != L[p][f - 1];
        if (changes && !changed) continue;
        fprintf(out, "%d", f);
        for (int p = 0; p < np; p++) {
            int ch = f > 0 && L[p][f] != L[p][f - 1];
            swaps += ch;
            if (!changes || f == 0 || ch) fprintf(out, ",%d", L[p][f]); else fprintf(out, ",");
        }
        fprintf(out, "\n");
    }
    info(1, "%d swaps on set (a part changes piece between consecutive frames)", swaps);
    if (catalogue) {
        FILE *cf = out_open(catalogue);
        fprintf(cf, "part,piece,count,frames,volume,grams\n");
        double total = 0;
        int used_total = 0;
        for (int p = 0; p < np; p++)
            for (int k = 0; k < npieces[p]; k++) {
                int cnt = 0;
                for (int f = 0; f < n; f++) cnt += L[p][f] == k;
                used_total += cnt > 0;
                if (name) fprintf(cf, "%s,%d,%d,", name[p], k, cnt); else fprintf(cf, "part%d,%d,%d,", p, k, cnt);
                int first = 1;
                for (int f = 0; f < n; f++) {
                    if (L[p][f] != k || (f > 0 && L[p][f - 1] == k)) continue;
                    int e = f;
                    while (e + 1 < n && L[p][e + 1] == k) e++;
                    if (e > f) fprintf(cf, "%s%d-%d", first ? "" : ";", f, e);
                    else fprintf(cf, "%s%d", first ? "" : ";", f);
                    first = 0;
                }
                if (vol[p]) {
                    double mm3 = vol[p][k] * unit * unit * unit, g = mm3 / 1000 * density;
                    total += g;
                    fprintf(cf, ",%.6g,%.4g\n", vol[p][k], g);
                } else {
                    fprintf(cf, ",,\n");
                }
            }
        out_close(cf);
        info(1, "%d frames, %d parts, %d pieces used", n, np, used_total);
        if (solids || volumes) info(1, "material %.4g g", total);
    }
    out_close(out);
    for (int p = 0; p < np; p++) { free(L[p]); free(vol[p]); }
    free(L); free(vol); free(npieces); free(name); free(solid);
    return 0;
}
