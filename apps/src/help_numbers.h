#pragma once
// Numbers in help and report text written from the constants they describe
// (a default fraction, a multiple of tol), so the text cannot drift from
// the code.

#include <cstdio>
#include <string>

namespace hullcover::app {

/// `value` in the fewest digits that give it back (17 significant always do),
/// exponents without padding: 1e-05 is written 1e-5, 0.02 as 0.02.
inline std::string number_text(double value) {
  char text[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::stod(text) == value) break;
  }
  std::string out = text;
  for (const char* padded : {"e-0", "e+0"}) {
    const size_t at = out.find(padded);
    if (at != std::string::npos) out.erase(at + 2, 1);
  }
  const size_t plus = out.find("e+");
  if (plus != std::string::npos) out.erase(plus + 1, 1);
  return out;
}

} // namespace hullcover::app
