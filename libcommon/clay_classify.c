/* clay_classify.c -- see clay_classify.h */
#include "clay_classify.h"
#include <string.h>

const char *const clay_anim_names[] = {
    "small-bend", "spring", "harmonic", "furl", "large-bend",       /* by skeleton */
    "rotate", "translate", "scale", "squash-stretch", "inflate", "protract", NULL};
const char *const clay_map_names[MAP_COUNT] = {"uniform", "nonuniform", "extrinsic", "intrinsic"};

/* Table 2.2: generic mesh scores, rows as clay_anim_names, columns
 * uniform, nonuniform, extrinsic, intrinsic */
static const double generic[11][MAP_COUNT] = {
    {7, 8, 7, 8}, {6, 8, 7, 8}, {6, 8, 7, 8}, {6, 8, 7, 7}, {6, 8, 7, 7},
    {9, 7, 9, 8}, {9, 7, 9, 8}, {9, 7, 9, 8}, {6, 7, 7, 7}, {7, 7, 7, 8}, {6, 7, 7, 7}};
/* which scales (small, intermediate, large) each mapping class covers */
static const int covers[MAP_COUNT][3] = {{1, 0, 0}, {1, 1, 1}, {1, 1, 0}, {0, 1, 1}};
static const int features[MAP_COUNT] = {0, 1, 0, 1};

int clay_anim_index(const char *name)
{
    for (int i = 0; clay_anim_names[i]; i++)
        if (!strcmp(name, clay_anim_names[i])) return i;
    return -1;
}

int clay_classify(const struct clay_segment *s, int n, double score[MAP_COUNT], int best[2])
{
    for (int m = 0; m < MAP_COUNT; m++) {
        score[m] = 0;
        for (int i = 0; i < n; i++) {
            int tot = s[i].small + s[i].inter + s[i].large;
            int miss = (!covers[m][0]) * s[i].small + (!covers[m][1]) * s[i].inter +
                       (!covers[m][2]) * s[i].large;
            double w = tot > 0 ? (double)miss / tot : 0;
            double k = features[m] ? (s[i].salient >= 3 ? 1 : -1) : 0;
            score[m] += s[i].volume * (generic[s[i].anim][m] - w + k);
        }
    }
    best[0] = 0;
    for (int m = 1; m < MAP_COUNT; m++) if (score[m] > score[best[0]]) best[0] = m;
    best[1] = best[0] == 0 ? 1 : 0;
    for (int m = 0; m < MAP_COUNT; m++)
        if (m != best[0] && score[m] > score[best[1]]) best[1] = m;
    int a = best[0], b = best[1];
    int intr = (a == MAP_NONUNIFORM || a == MAP_INTRINSIC) && (b == MAP_NONUNIFORM || b == MAP_INTRINSIC);
    int extr = (a == MAP_UNIFORM || a == MAP_EXTRINSIC) && (b == MAP_UNIFORM || b == MAP_EXTRINSIC);
    return intr ? 1 : extr ? 2 : 3;
}
