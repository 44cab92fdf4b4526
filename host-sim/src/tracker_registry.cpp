// Tracker registry; see tracker_registry.h.
#include "tracker_registry.h"

#include "mptrack/caps.h"
#if MPTRACK_SIM_HAVE_MFBP
#include "mptrack/mfbp/mfbp_tracker.h"
#endif
#if MPTRACK_SIM_HAVE_GNN
#include "mptrack/gnn/gnn_tracker.h"
#endif
#if MPTRACK_SIM_HAVE_IGGM
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/phd/phd_filter.h"
#endif

namespace mptrack::sim {

namespace {

struct Entry {
  const char* name;
  const char* description;
  bool available;
};

constexpr Entry kEntries[] = {
    {"mfbp", "MF-BP (MP-RMTT) window-7 smoother, slide 3, clutter estimated (seed 000)", MPTRACK_SIM_HAVE_MFBP != 0},
    {"mfbp-filter", "MF-BP online filter (window 1, one scan per step)", MPTRACK_SIM_HAVE_MFBP != 0},
    {"mfbp-ki", "MF-BP ablation MP-RMTT-KI: kinematics only, no amplitude", MPTRACK_SIM_HAVE_MFBP != 0},
    {"mfbp-nce", "MF-BP ablation MP-RMTT-NCE: uniform clutter of known rate, no estimation",
     MPTRACK_SIM_HAVE_MFBP != 0},
    {"mfbp-kce", "MF-BP ablation MP-RMTT-KCE: clutter map known exactly (from the scenario)",
     MPTRACK_SIM_HAVE_MFBP != 0},
    {"mfbp-st", "MF-BP ablation MP-RMTTst: first MP iteration only", MPTRACK_SIM_HAVE_MFBP != 0},
    {"gnn", "GNN + Kalman baseline", MPTRACK_SIM_HAVE_GNN != 0},
    {"gmphd", "IGGM GM-PHD with amplitude, clutter map estimated (seed 001)", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmphd-uniform", "IGGM GM-PHD, uniform clutter rate and power estimated", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmphd-known", "IGGM GM-PHD, uniform clutter of known rate (fixed model)", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmphd-ki", "GM-PHD kinematics only (no amplitude), clutter map estimated", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmcphd", "IGGM GM-CPHD with amplitude, clutter map estimated (seed 001)", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmcphd-uniform", "IGGM GM-CPHD, uniform clutter rate and power estimated", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmcphd-known", "IGGM GM-CPHD, uniform clutter of known rate (fixed model)", MPTRACK_SIM_HAVE_IGGM != 0},
    {"gmcphd-ki", "GM-CPHD kinematics only (no amplitude), clutter map estimated", MPTRACK_SIM_HAVE_IGGM != 0},
    {"cbmember", "IGGM CBMeMBer with amplitude, clutter map estimated (seed 001)", MPTRACK_SIM_HAVE_IGGM != 0},
    {"cbmember-uniform", "IGGM CBMeMBer, uniform clutter rate and power estimated", MPTRACK_SIM_HAVE_IGGM != 0},
    {"cbmember-known", "IGGM CBMeMBer, uniform clutter of known rate (fixed model)", MPTRACK_SIM_HAVE_IGGM != 0},
    {"cbmember-ki", "CBMeMBer kinematics only (no amplitude), clutter map estimated", MPTRACK_SIM_HAVE_IGGM != 0},
    {"oracle", "test oracle: reports each target-originated measurement as a track (uses truth)", true},
};

}  // namespace

std::vector<TrackerInfo> tracker_list() {
  std::vector<TrackerInfo> out;
  for (const Entry& e : kEntries) out.push_back(TrackerInfo{e.name, e.description, e.available});
  return out;
}

std::vector<TrackerFootprint> tracker_footprints() {
  std::vector<TrackerFootprint> out;
#if MPTRACK_SIM_HAVE_MFBP
  out.push_back({"MfbpTracker<T, DefaultCaps>", sizeof(MfbpTracker<float, DefaultCaps>),
                 sizeof(MfbpTracker<double, DefaultCaps>)});
#endif
#if MPTRACK_SIM_HAVE_GNN
  out.push_back({"GnnTracker<T, DefaultCaps>", sizeof(GnnTracker<float, DefaultCaps>),
                 sizeof(GnnTracker<double, DefaultCaps>)});
#endif
#if MPTRACK_SIM_HAVE_IGGM
  out.push_back({"phd::GmPhdFilter<T, DefaultCaps>", sizeof(phd::GmPhdFilter<float, DefaultCaps>),
                 sizeof(phd::GmPhdFilter<double, DefaultCaps>)});
  out.push_back({"phd::GmCphdFilter<T, DefaultCaps>", sizeof(phd::GmCphdFilter<float, DefaultCaps>),
                 sizeof(phd::GmCphdFilter<double, DefaultCaps>)});
  out.push_back({"cbmember::CbMemberFilter<T, DefaultCaps>", sizeof(cbmember::CbMemberFilter<float, DefaultCaps>),
                 sizeof(cbmember::CbMemberFilter<double, DefaultCaps>)});
#endif
  return out;
}

std::unique_ptr<TrackerAdapter> make_tracker(const std::string& name, std::string& error) {
  for (const Entry& e : kEntries) {
    if (name != e.name) continue;
    if (!e.available) {
      error = "tracker '" + name + "' is not built in this tree (its core header is missing)";
      return nullptr;
    }
    if (name == "oracle") return make_oracle_tracker();
#if MPTRACK_SIM_HAVE_MFBP
    if (name.rfind("mfbp", 0) == 0) return make_mfbp_tracker(name);
#endif
#if MPTRACK_SIM_HAVE_GNN
    if (name == "gnn") return make_gnn_tracker();
#endif
#if MPTRACK_SIM_HAVE_IGGM
    if (auto t = make_iggm_tracker(name)) return t;
#endif
  }
  error = "unknown tracker '" + name + "'";
  return nullptr;
}

}  // namespace mptrack::sim
