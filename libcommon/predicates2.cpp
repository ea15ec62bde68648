// predicates2.cpp -- see predicates2.h.
#include <algorithm>
#include "predicates2.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef K::Segment_2 Segment;

static inline Point pt(const double *p) { return Point(p[0], p[1]); }

extern "C" int orient2_sign_exact(const double *a, const double *b, const double *c)
{
    switch (CGAL::orientation(pt(a), pt(b), pt(c))) {
    case CGAL::LEFT_TURN: return 1;
    case CGAL::RIGHT_TURN: return -1;
    default: return 0;
    }
}

extern "C" int segments_meet_exact(const double *a, const double *b, const double *c, const double *d)
{
    /* closed segments that meet have overlapping bounding boxes: most
     * pairs asked (an outline's chord against its other edges) are told
     * apart by comparisons alone, exactly, without the kernel's call */
    for (int k = 0; k < 2; k++)
        if (std::max(a[k], b[k]) < std::min(c[k], d[k]) || std::max(c[k], d[k]) < std::min(a[k], b[k])) return 0;
    return CGAL::do_intersect(Segment(pt(a), pt(b)), Segment(pt(c), pt(d)));
}

/* collinear p on the closed segment ab (exact: comparisons of coordinates) */
static bool between(const double *a, const double *b, const double *p)
{
    return CGAL::collinear_are_ordered_along_line(pt(a), pt(p), pt(b));
}

extern "C" int open_segment_meets(const double *a, const double *b, const double *c, const double *d)
{
    int o1 = orient2_sign_exact(a, b, c), o2 = orient2_sign_exact(a, b, d);
    int o3 = orient2_sign_exact(c, d, a), o4 = orient2_sign_exact(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;        // proper crossing
    auto eq = [](const double *p, const double *q) { return p[0] == q[0] && p[1] == q[1]; };
    // c or d on the open segment ab
    if (o1 == 0 && between(a, b, c) && !eq(c, a) && !eq(c, b)) return 1;
    if (o2 == 0 && between(a, b, d) && !eq(d, a) && !eq(d, b)) return 1;
    // an interior point of ab on cd: either a proper crossing (above), or
    // ab and cd collinear and overlapping beyond an endpoint
    if (o1 == 0 && o2 == 0) {
        // collinear: overlap of the open ab with the closed cd
        if ((between(c, d, a) && between(c, d, b))) return !eq(a, b);
        if (between(a, b, c) && !eq(c, a) && !eq(c, b)) return 1;
        if (between(a, b, d) && !eq(d, a) && !eq(d, b)) return 1;
        return 0;
    }
    // a or b touching the line cd with the other not collinear: only an endpoint touch
    return 0;
}
