// Wording of a refused parameter; see param_error_text.h.
#include "param_error_text.h"

#include <cmath>
#include <cstdio>

namespace mptrack::sim {

std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string describe_bounds(const CheckResult& r) {
  std::string s = "must be ";
  if (r.has_lo && r.has_hi) {
    s += std::string("in ") + (r.lo_open ? "(" : "[") + format_number(r.lo) + ", " + format_number(r.hi) +
         (r.hi_open ? ")" : "]");
  } else if (r.has_hi) {
    s += std::string(r.hi_open ? "< " : "<= ") + format_number(r.hi);
  } else if (r.has_lo) {
    s += std::string(r.lo_open ? "> " : ">= ") + format_number(r.lo);
  } else {
    s += "finite";
  }
  if (r.limit != nullptr && r.limit[0] != '\0') s += std::string(" (") + r.limit + ")";
  if (!std::isfinite(r.value)) s += " and finite";
  return s;
}

std::string describe_param_error(const std::string& prefix, const ParamError& e) {
  const std::string field = prefix.empty() ? std::string(e.field) : prefix + "." + e.field;
  if (!e.result.has_value) return field + ": must satisfy " + e.rule;
  return field + " = " + format_number(e.result.value) + ": " + describe_bounds(e.result);
}

}  // namespace mptrack::sim
