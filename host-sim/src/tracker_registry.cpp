// Tracker registry; see tracker_registry.h.
#include "tracker_registry.h"

#include "mptrack/caps.h"
#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "trackers/vmp_adapter.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "mptrack/mptf/mptf_tracker.h"
#include "mptrack/phd/phd_filter.h"

namespace mptrack::sim {

namespace {

struct Entry {
  const char* name;
  const char* description;
};

constexpr Entry kEntries[] = {
    {"mfbp", "MF-BP (MP-RMTT) window-7 smoother, slide 3, clutter estimated (seed 000); polar and OTHR scenarios (mfbp-* too: seed 001's Cartesian ones are refused)"},
    {"mfbp-s1", "MF-BP window-7 smoother processing a window every scan (slide 1), for hard clutter: births inside weaker clutter confirmed ~3 scans sooner, none under clutter of CNR above 6, 2-2.5x the mean compute"},
    {"mfbp-filter", "MF-BP online filter (window 1, one scan per step)"},
    {"mfbp-ki", "MF-BP ablation MP-RMTT-KI: kinematics only, no amplitude"},
    {"mfbp-nce", "MF-BP ablation MP-RMTT-NCE: uniform clutter of known rate, no estimation"},
    {"mfbp-kce", "MF-BP ablation MP-RMTT-KCE: clutter map known exactly (from the scenario)"},
    {"mfbp-st", "MF-BP ablation MP-RMTTst: first MP iteration only"},
    {"gnn", "GNN + Kalman baseline; polar and OTHR scenarios (seed 001's Cartesian ones are refused)"},
    {"mfbp-multipath", "multipath MF-BP (seed 002): BP over (target, path), OTHR scenarios only"},
    {"mptf", "multipath track fusion baseline (seed 002): slant PDA path tracks fused in ground, OTHR only"},
    {"gmphd", "IGGM GM-PHD with amplitude, clutter map estimated (seed 001)"},
    {"gmphd-uniform", "IGGM GM-PHD, uniform clutter rate and power estimated"},
    {"gmphd-known", "IGGM GM-PHD, uniform clutter of known rate (fixed model)"},
    {"gmphd-ki", "GM-PHD kinematics only (no amplitude), clutter map estimated"},
    {"gmcphd", "IGGM GM-CPHD with amplitude, clutter map estimated (seed 001)"},
    {"gmcphd-uniform", "IGGM GM-CPHD, uniform clutter rate and power estimated"},
    {"gmcphd-known", "IGGM GM-CPHD, uniform clutter of known rate (fixed model)"},
    {"gmcphd-ki", "GM-CPHD kinematics only (no amplitude), clutter map estimated"},
    {"cbmember", "IGGM CBMeMBer with amplitude, clutter map estimated (seed 001)"},
    {"cbmember-uniform", "IGGM CBMeMBer, uniform clutter rate and power estimated"},
    {"cbmember-known", "IGGM CBMeMBer, uniform clutter of known rate (fixed model)"},
    {"cbmember-ki", "CBMeMBer kinematics only (no amplitude), clutter map estimated"},
    {"vmp", "raw-ADC scenarios only: seed 004 VMP tracker on the raw MIMO frames (no detector)"},
    {"sbl-gnn", "raw-ADC scenarios only: SBL detector + GNN + CV Kalman (seed 004 detect-then-track baseline)"},
    {"oracle", "test oracle: reports each target-originated measurement as a track (uses truth); raw-ADC scenarios: the true states (the ceiling, OSPA 0)"},
    {"mfbp-nn", "seed 003 sea scenes only: MF-BP after removing detections the patch classifier calls clutter"},
    {"nemp", "seed 003 sea scenes only: MF-BP with the patch classifier fused into BP (NEMP)"},
};

}  // namespace

std::vector<TrackerInfo> tracker_list() {
  std::vector<TrackerInfo> out;
  for (const Entry& e : kEntries) out.push_back(TrackerInfo{e.name, e.description});
  return out;
}

std::vector<TrackerFootprint> tracker_footprints() {
  std::vector<TrackerFootprint> out;
  out.push_back({"MfbpTracker<T, DefaultCaps>", sizeof(MfbpTracker<float, DefaultCaps>),
                 sizeof(MfbpTracker<double, DefaultCaps>)});
  out.push_back({"GnnTracker<T, DefaultCaps>", sizeof(GnnTracker<float, DefaultCaps>),
                 sizeof(GnnTracker<double, DefaultCaps>)});
  out.push_back({"GmPhdFilter<T, DefaultCaps>", sizeof(GmPhdFilter<float, DefaultCaps>),
                 sizeof(GmPhdFilter<double, DefaultCaps>)});
  out.push_back({"GmCphdFilter<T, DefaultCaps>", sizeof(GmCphdFilter<float, DefaultCaps>),
                 sizeof(GmCphdFilter<double, DefaultCaps>)});
  out.push_back({"MultipathMfbpTracker<T, DefaultCaps>", sizeof(MultipathMfbpTracker<float, DefaultCaps>),
                 sizeof(MultipathMfbpTracker<double, DefaultCaps>)});
  out.push_back({"CbMemberFilter<T, DefaultCaps>", sizeof(CbMemberFilter<float, DefaultCaps>),
                 sizeof(CbMemberFilter<double, DefaultCaps>)});
  out.push_back({"MptfTracker<T, DefaultCaps>", sizeof(MptfTracker<float, DefaultCaps>),
                 sizeof(MptfTracker<double, DefaultCaps>)});
  return out;
}

std::unique_ptr<TrackerAdapter> make_tracker(const std::string& name, std::string& error) {
  for (const Entry& e : kEntries) {
    if (name != e.name) continue;
    if (name == "oracle") return make_oracle_tracker();
    if (name == "mfbp-multipath") return make_multipath_tracker();
    if (name == "mptf") return make_mptf_tracker();
    if (name == "mfbp-nn" || name == "nemp") return make_nemp_tracker(name);
    if (name.rfind("mfbp", 0) == 0) return make_mfbp_tracker(name);
    if (name == "gnn") return make_gnn_tracker();
    if (name == "vmp") return make_vmp_adapter();
    if (name == "sbl-gnn") {
      error = "sbl-gnn detects in raw ADC frames: use it on a raw-ADC scenario (seed004-drones, mimo-interference)";
      return nullptr;
    }
    if (auto t = make_iggm_tracker(name)) return t;
  }
  error = "unknown tracker '" + name + "'";
  return nullptr;
}

}  // namespace mptrack::sim
