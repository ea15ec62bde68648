// shortest.cpp -- see shortest.h.  {fmt}'s Dragonbox (the engine behind
// fmt::format("{}", x)); its decimal_fp is in fmt's detail namespace but
// exported by libfmt (FMT_API), stable from fmt 7 to 11.
#include "shortest.h"

#include <fmt/format.h>
#include <cmath>

extern "C" void shortest_decimal(double x, uint64_t *sig, int *exp10)
{
    auto d = fmt::detail::dragonbox::to_decimal(std::fabs(x));
    uint64_t s = d.significand;
    int e = d.exponent;
    while (s % 10 == 0) { s /= 10; e++; }   // (Dragonbox already strips them)
    *sig = s;
    *exp10 = e;
}
