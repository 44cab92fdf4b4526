// "NAME=VALUE" overrides of a tracker's params struct by field name, shared by
// `--mfbp-param` (mfbp_param_override.h) and `--rfs-param`
// (rfs_param_override.h): each keeps a table of the fields users tune and
// this parses, checks the kind (real, count, 0/1 flag) and sets the field.
// The tracker's init() still validates the values.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <string>
#include <vector>

namespace mptrack::sim {

template <class P>
struct RealField {
  const char* name;
  double& (*field)(P&);
};
template <class P>
struct CountField {
  const char* name;
  std::size_t& (*field)(P&);
};
template <class P>
struct FlagField {
  const char* name;
  bool& (*field)(P&);
};

/// The fields one option can set (arrays of n_* entries; nullptr when none).
template <class P>
struct ParamTable {
  const char* option;  ///< "--mfbp-param": names the option in every error
  const RealField<P>* reals;
  std::size_t n_reals;
  const CountField<P>* counts;
  std::size_t n_counts;
  const FlagField<P>* flags;
  std::size_t n_flags;
};

namespace detail {

/// "did you mean 'amplitude.use_amplitude'?" for a flag given without its block.
template <class P>
std::string unknown_param(const ParamTable<P>& t, const std::string& name) {
  const std::string opt = t.option;
  for (std::size_t i = 0; i < t.n_flags; ++i) {
    const std::string full = t.flags[i].name;
    if (full.size() > name.size() && full.compare(full.size() - name.size() - 1, std::string::npos, "." + name) == 0) {
      return opt + ": unknown parameter '" + name + "'; did you mean '" + full + "' (0 or 1)?";
    }
  }
  return opt + ": unknown parameter '" + name + "' (see host-sim/README.md)";
}

}  // namespace detail

/// Applies one "name=value" to p through table t; returns "" or an error
/// naming the option and the field.
template <class P>
std::string apply_param(P& p, const std::string& kv, const ParamTable<P>& t) {
  const std::string opt = t.option;
  const std::size_t eq = kv.find('=');
  if (eq == std::string::npos) return opt + " " + kv + ": expected NAME=VALUE";
  const std::string name = kv.substr(0, eq);
  const std::string text = kv.substr(eq + 1);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == nullptr || *end != '\0') return opt + " " + name + ": '" + text + "' is not a number";
  for (std::size_t i = 0; i < t.n_reals; ++i) {
    if (name != t.reals[i].name) continue;
    t.reals[i].field(p) = v;
    return "";
  }
  for (std::size_t i = 0; i < t.n_counts; ++i) {
    if (name != t.counts[i].name) continue;
    if (!(v >= 0.0 && v <= 1e9 && v == static_cast<double>(static_cast<std::size_t>(v)))) {
      return opt + " " + name + " = " + text + ": must be an integer in [0, 1e9]";
    }
    t.counts[i].field(p) = static_cast<std::size_t>(v);
    return "";
  }
  for (std::size_t i = 0; i < t.n_flags; ++i) {
    if (name != t.flags[i].name) continue;
    if (v != 0.0 && v != 1.0) return opt + " " + name + ": expected 0 or 1, got '" + text + "'";
    t.flags[i].field(p) = v != 0.0;
    return "";
  }
  return detail::unknown_param(t, name);
}

/// Applies every "name=value" in order through t; returns the first error or "".
template <class P>
std::string apply_params(P& p, const std::vector<std::string>& overrides, const ParamTable<P>& t) {
  for (const std::string& kv : overrides) {
    std::string error = apply_param(p, kv, t);
    if (!error.empty()) return error;
  }
  return "";
}

}  // namespace mptrack::sim
