#pragma once
// What a channel of a technique's error may reach in a regression guard:
// today's figure plus a fifth and 0.2 points, so that a regression fails and
// llvmpipe's rounding does not.
namespace planet {

inline double allowed_percent(double today) { return 1.2 * today + 0.2; }

}  // namespace planet
