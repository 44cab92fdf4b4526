// --rfs-param NAME=VALUE overrides; see rfs_param_override.h. NAME is the
// field as written in RfsFilterParams ("amplitude.use_amplitude" for the
// shared amplitude block).
#include "trackers/rfs_param_override.h"

#include <iterator>

#include "trackers/param_override.h"

namespace mptrack::sim {

namespace {

using P = RfsFilterParams<double>;

// One line per field a user tunes most; units and defaults in rfs_params.h.
const RealField<P> kReals[] = {
    {"extract_threshold", [](P& p) -> double& { return p.extract_threshold; }},
    {"existence_extract", [](P& p) -> double& { return p.existence_extract; }},
    {"existence_prune", [](P& p) -> double& { return p.existence_prune; }},
    {"prune_threshold", [](P& p) -> double& { return p.prune_threshold; }},
    {"merge_threshold", [](P& p) -> double& { return p.merge_threshold; }},
    {"birth_rate", [](P& p) -> double& { return p.birth_rate; }},
    {"birth_velocity_std_mps", [](P& p) -> double& { return p.birth_velocity_std_mps; }},
    {"survival_prob", [](P& p) -> double& { return p.survival_prob; }},
    {"detection_prob", [](P& p) -> double& { return p.detection_prob; }},
    {"accel_var_m2ps4", [](P& p) -> double& { return p.accel_var_m2ps4; }},
    {"gate_probability", [](P& p) -> double& { return p.gate_probability; }},
    {"clutter_rate", [](P& p) -> double& { return p.clutter_rate; }},
};
const FlagField<P> kFlags[] = {
    {"amplitude.use_amplitude", [](P& p) -> bool& { return p.amplitude.use_amplitude; }},
};

}  // namespace

std::string apply_rfs_params(RfsFilterParams<double>& p, const std::vector<std::string>& overrides) {
  static const ParamTable<P> kTable{"--rfs-param", kReals, std::size(kReals), nullptr, 0, kFlags, std::size(kFlags)};
  return apply_params(p, overrides, kTable);
}

}  // namespace mptrack::sim
