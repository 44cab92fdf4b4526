// The capacities of the Gaussian-mixture RFS filters read from a caps type
// (caps.h), with the presets' values as defaults for caps types that do
// not declare them.
#pragma once

#include <cstddef>
#include <type_traits>

#include "mptrack/caps.h"

namespace mptrack::rfs {

namespace detail {
MPTRACK_OPTIONAL_CAP(MixtureComponentsOf, kMaxMixtureComponents, 2 * Caps::kMaxTargets);
MPTRACK_OPTIONAL_CAP(ComponentsPerBernoulliOf, kMaxComponentsPerBernoulli, 4);
MPTRACK_OPTIONAL_CAP(RawComponentsPerBernoulliOf, kMaxRawComponentsPerBernoulli, 16);
}  // namespace detail

/// GM-PHD/CPHD: Gaussian components kept after reduction (default 2 per target).
template <class Caps>
inline constexpr std::size_t kMaxMixtureComponents = detail::MixtureComponentsOf<Caps>::value;
/// CBMeMBer: Gaussian components per Bernoulli after reduction (default 4).
template <class Caps>
inline constexpr std::size_t kMaxComponentsPerBernoulli = detail::ComponentsPerBernoulliOf<Caps>::value;
/// CBMeMBer: components per Bernoulli collected before reduction (default 16).
template <class Caps>
inline constexpr std::size_t kMaxRawComponentsPerBernoulli =
    detail::RawComponentsPerBernoulliOf<Caps>::value;

/// Compile-time checks of these capacities.
template <class Caps>
constexpr bool rfs_caps_are_valid() {
  static_assert(kMaxMixtureComponents<Caps> >= 1, "Caps::kMaxMixtureComponents must be >= 1");
  static_assert(kMaxComponentsPerBernoulli<Caps> >= 1,
                "Caps::kMaxComponentsPerBernoulli must be >= 1");
  static_assert(kMaxRawComponentsPerBernoulli<Caps> >= kMaxComponentsPerBernoulli<Caps>,
                "Caps::kMaxRawComponentsPerBernoulli must be >= kMaxComponentsPerBernoulli");
  return true;
}

}  // namespace mptrack::rfs
