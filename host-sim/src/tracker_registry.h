// --tracker names -> adapters.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "tracker_adapter.h"

namespace mptrack::sim {

struct TrackerInfo {
  std::string name;
  std::string description;
};

/// Every registered name, in --help order.
std::vector<TrackerInfo> tracker_list();

/// sizeof of a core tracker object for DefaultCaps (what a board must place).
struct TrackerFootprint {
  std::string name;           ///< core type, e.g. "MfbpTracker<T, DefaultCaps>"
  std::size_t bytes_float = 0;
  std::size_t bytes_double = 0;
};
/// The core trackers of the harness.
std::vector<TrackerFootprint> tracker_footprints();

/// A fresh adapter, or nullptr with `error` set (unknown name).
std::unique_ptr<TrackerAdapter> make_tracker(const std::string& name, std::string& error);

// Factories, one per adapter source file.
std::unique_ptr<TrackerAdapter> make_oracle_tracker();
std::unique_ptr<TrackerAdapter> make_mfbp_tracker(const std::string& variant);
std::unique_ptr<TrackerAdapter> make_nemp_tracker(const std::string& variant);
std::unique_ptr<TrackerAdapter> make_gnn_tracker();
std::unique_ptr<TrackerAdapter> make_multipath_tracker();
std::unique_ptr<TrackerAdapter> make_mptf_tracker();
/// gmphd, gmcphd, cbmember and their -uniform/-known/-ki variants (nullptr if unknown).
std::unique_ptr<TrackerAdapter> make_iggm_tracker(const std::string& name);

}  // namespace mptrack::sim
