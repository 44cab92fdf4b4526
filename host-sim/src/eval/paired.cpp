#include "eval/paired.h"

#include <cmath>
#include <cstdio>

namespace mptrack::sim {

PairedDifference paired_difference(const std::vector<double>& a, const std::vector<double>& b) {
  PairedDifference d;
  if (a.empty() || a.size() != b.size()) return d;
  d.runs = a.size();
  double sum = 0.0;
  for (std::size_t r = 0; r < a.size(); ++r) {
    sum += a[r] - b[r];
    if (a[r] < b[r]) ++d.a_lower;
  }
  const double n = static_cast<double>(d.runs);
  d.mean = sum / n;
  if (d.runs < 2) return d;
  double ss = 0.0;  // two passes: the differences' mean first, then the spread around it
  for (std::size_t r = 0; r < a.size(); ++r) {
    const double e = (a[r] - b[r]) - d.mean;
    ss += e * e;
  }
  d.standard_error = std::sqrt(ss / (n - 1.0)) / std::sqrt(n);
  return d;
}

std::string paired_difference_text(const PairedDifference& d, int digits) {
  if (d.runs == 0) return "n/a";
  char b[96];
  std::snprintf(b, sizeof b, "%+.*f +- %.*f (lower in %zu of %zu)", digits, d.mean, digits, d.standard_error,
                d.a_lower, d.runs);
  return b;
}

}  // namespace mptrack::sim
