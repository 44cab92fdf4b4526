// summary.json and the SCR tables of the sea scenes; see sea_runner.h.
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "eval/paired.h"
#include "sea_runner.h"
#include "writers.h"

namespace mptrack::sim {

namespace {

/// Seed 003's method names for our trackers (Sec. IV: MP, MP-NN, NEMP).
std::string paper_name(const std::string& tracker) {
  if (tracker == "mfbp") return "MP (mfbp)";
  if (tracker == "mfbp-nn") return "MP-NN (mfbp-nn)";
  if (tracker == "nemp") return "NEMP (nemp)";
  return tracker;
}

struct Column {
  const char* key;    ///< top-level summary.json field
  const char* title;
  double scale;       ///< printed value = field * scale
  const char* format;
};

// The paper's columns (seed 003 Tables I-II) in its units, then ours.
// Fields another part of the harness may not write yet print as "n/a".
constexpr Column kColumns[] = {
    {"amota", "AMOTA", 1.0, "%.2f"},
    {"ids", "IDS per target", 1.0, "%.2f"},
    {"frag", "Frag per target", 1.0, "%.2f"},
    {"rmse_range_m", "RMSE range [m]", 1.0, "%.2f"},
    {"rmse_velocity_mps", "RMSE velocity [cm/s]", 100.0, "%.2f"},
    {"mospa_mahalanobis", "MOSPA (Mahalanobis in range, range rate; c 9.4, p 2)", 1.0, "%.2f"},
    {"mean_ospa", "OSPA range [m] (c 141 m, p 2)", 1.0, "%.1f"},
    {"tpd", "TPD", 1.0, "%.3f"},
    {"nft", "false tracks per scan", 1.0, "%.2f"},
};

std::string fmt1(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", x);
  return b;
}

std::string cell(const nlohmann::ordered_json& j, const Column& c) {
  if (!j.contains(c.key) || !j[c.key].is_number()) return "n/a";
  char b[48];
  std::snprintf(b, sizeof b, c.format, j[c.key].get<double>() * c.scale);
  return b;
}

/// A table's two header lines: the leading cells, then one "N dB" column
/// per SCR of r.
std::string scr_header(const std::vector<std::vector<SeaSummary>>& r, const char* lead, const char* lead_rule) {
  std::string s = lead;
  for (const auto& col : r) s += " " + std::to_string(static_cast<int>(col.front().scr_db)) + " dB |";
  s += std::string("\n") + lead_rule;
  for (std::size_t i = 0; i < r.size(); ++i) s += "---:|";
  return s + "\n";
}

// NEMP against MP-NN run by run (eval/paired.h; docs/algorithms/metrics.md
// §Paired differences): both ran on the same scenes, so the scene-to-scene
// spread cancels and the standard error says whether a gap is noise.
struct PairedMetric {
  const char* key;    ///< compare.json field under nemp_minus_mfbp_nn
  const char* title;
  const std::vector<double>& (*per_run)(const SeaSummary&);
};
const std::vector<double>& amota_runs(const SeaSummary& s) { return s.base.track_scores.amota_per_run; }
const std::vector<double>& mospa_runs(const SeaSummary& s) { return s.base.ospa_mahalanobis_per_run; }
constexpr PairedMetric kPaired[] = {
    {"amota", "AMOTA", &amota_runs},
    {"mospa_mahalanobis", "MOSPA", &mospa_runs},
};

/// Index of `tracker` among a column's summaries; col.size() if absent.
std::size_t tracker_index(const std::vector<SeaSummary>& col, const char* tracker) {
  std::size_t i = 0;
  while (i < col.size() && col[i].base.tracker != tracker) ++i;
  return i;
}

/// NEMP - MP-NN of one metric in one column; runs 0 if either is absent.
PairedDifference nemp_minus_mpnn(const std::vector<SeaSummary>& col, const PairedMetric& m) {
  const std::size_t a = tracker_index(col, "nemp"), b = tracker_index(col, "mfbp-nn");
  if (a == col.size() || b == col.size()) return PairedDifference{};
  return paired_difference(m.per_run(col[a]), m.per_run(col[b]));
}

/// One value per run of `tracker`'s metric averaged over the SCR columns
/// (in column order); empty if a column lacks the tracker or the run counts
/// differ.
std::vector<double> mean_over_scr(const std::vector<std::vector<SeaSummary>>& r, const char* tracker,
                                  const PairedMetric& m) {
  std::vector<double> sum;
  for (const auto& col : r) {
    const std::size_t i = tracker_index(col, tracker);
    if (i == col.size()) return {};
    const std::vector<double>& runs = m.per_run(col[i]);
    if (sum.empty()) sum.assign(runs.size(), 0.0);
    if (runs.size() != sum.size()) return {};
    for (std::size_t k = 0; k < runs.size(); ++k) sum[k] += runs[k];
  }
  for (double& v : sum) v /= static_cast<double>(r.size());
  return sum;
}

/// NEMP - MP-NN over every SCR at once: each run's values are averaged over
/// the SCRs first, then paired. Run k is the same scene at every SCR, so the
/// SCR columns are not independent and their standard errors do not combine
/// as if they were (docs/algorithms/metrics.md §Paired differences).
PairedDifference nemp_minus_mpnn_over_scr(const std::vector<std::vector<SeaSummary>>& r, const PairedMetric& m) {
  return paired_difference(mean_over_scr(r, "nemp", m), mean_over_scr(r, "mfbp-nn", m));
}

std::string short_name(const std::string& tracker) {
  const std::string n = paper_name(tracker);
  const std::size_t space = n.find(' ');
  return space == std::string::npos ? n : n.substr(0, space);
}

/// The trackers of one SCR column within 0.005 of its best value of `key`
/// as printed in the table (sign +1: higher is better), "/"-separated.
std::string best_in_column(const std::vector<SeaSummary>& col, const char* key, double sign) {
  constexpr double kLevel = 0.005;
  std::vector<double> v(col.size(), 0.0);
  std::vector<bool> has(col.size(), false);
  double best = 0.0;
  bool any = false;
  for (std::size_t t = 0; t < col.size(); ++t) {
    const nlohmann::ordered_json j = sea_summary_to_json(col[t]);
    if (!j.contains(key) || !j[key].is_number()) continue;
    v[t] = sign * j[key].get<double>();
    has[t] = true;
    if (!any || v[t] > best) best = v[t];
    any = true;
  }
  std::string names;
  for (std::size_t t = 0; t < col.size(); ++t) {
    if (has[t] && !(v[t] < best - kLevel)) names += (names.empty() ? "" : "/") + short_name(col[t].base.tracker);
  }
  return names.empty() ? "n/a" : names;
}

/// "best AMOTA" / "best MOSPA" rows under the metric table.
std::string best_rows(const std::vector<std::vector<SeaSummary>>& r) {
  std::string s = "| best AMOTA (within 0.005) | |";
  for (const auto& col : r) s += " " + best_in_column(col, "amota", 1.0) + " |";
  s += "\n| best MOSPA (within 0.005) | |";
  for (const auto& col : r) s += " " + best_in_column(col, "mospa_mahalanobis", -1.0) + " |";
  return s + "\n";
}

/// The paired rows under the table, or "" without both trackers.
std::string paired_markdown(const std::vector<std::vector<SeaSummary>>& r) {
  if (nemp_minus_mpnn(r.front(), kPaired[0]).runs == 0) return "";
  std::string s =
      "\nNEMP - MP-NN, paired over runs on the same scenes: mean of the per-run differences +- its "
      "standard error (AMOTA higher, MOSPA lower is NEMP ahead; 2 standard errors is about 95 %). The last "
      "column averages each run over the SCRs first, then pairs the runs.\n\n";
  std::string header = scr_header(r, "| metric |", "|---|");
  header.insert(header.find('\n'), " mean over SCRs |");
  header.insert(header.size() - 1, "---:|");  // the rule line, before its newline
  s += header;
  const auto text = [](const PairedDifference& d) {
    char b[64];
    std::snprintf(b, sizeof b, " %+.3f +- %.3f |", d.mean, d.standard_error);
    return std::string(b);
  };
  for (const PairedMetric& m : kPaired) {
    s += std::string("| ") + m.title + " |";
    for (const auto& col : r) s += text(nemp_minus_mpnn(col, m));
    const PairedDifference all = nemp_minus_mpnn_over_scr(r, m);
    s += (all.runs > 0 ? text(all) : std::string(" n/a |")) + "\n";
  }
  return s;
}

}  // namespace

nlohmann::ordered_json sea_summary_to_json(const SeaSummary& s) {
  nlohmann::ordered_json j = summary_to_json(s.base);
  j["input"] = "sea_scene";
  j["scr_db"] = s.scr_db;
  j["ospa"] = {{"cutoff_m", kSeaOspaCutoff_m}, {"order_p", kSeaOspaOrder}};
  // Top-level names of seed 003's table. The generic track scores pair a
  // target with a track inside the OSPA cut-off in metres; on the sea scenes
  // the paper's pairing (Mahalanobis on range and range rate, as its MOSPA)
  // replaces them, so the table's RMSE and MOSPA judge the same pairs.
  // null when no confirmed track was ever paired with a target.
  const nlohmann::ordered_json rmse_r = s.errors.matched > 0 ? nlohmann::ordered_json(s.errors.rmse_range_m()) : nullptr;
  const nlohmann::ordered_json rmse_v =
      s.errors.matched > 0 ? nlohmann::ordered_json(s.errors.rmse_velocity_mps()) : nullptr;
  j["rmse_range_m"] = rmse_r;
  j["rmse_velocity_mps"] = rmse_v;
  j["sea"] = {{"rmse_range_m", rmse_r},
              {"rmse_velocity_mps", rmse_v},
              {"matched_target_scans", s.errors.matched},
              {"target_scans", s.errors.truths},
              {"matching", "per scan, greedy by Mahalanobis distance on (range, range rate) with deviations (range bin, Doppler bin) within 9.4, each confirmed track once"},
              {"plots_per_scan", s.plots_per_scan},
              {"target_plots_per_scan", s.target_plots_per_scan},
              {"cnn_us_per_detection", s.feature_us_per_detection}};
  return j;
}

std::string sea_compare_to_markdown(const SeaCompareConfig& cfg, const std::vector<std::vector<SeaSummary>>& r) {
  if (r.empty() || r.front().empty()) return "";
  std::string s = "# " + cfg.scenario.name + ": MP / MP-NN / NEMP over SCR\n\n";
  s += std::to_string(cfg.runs) + " run(s) per SCR x " + std::to_string(cfg.scenario.num_scans) + " scans, seed " +
       std::to_string(cfg.seed) + "; every tracker and every SCR on the same scenes. Plots per scan " +
       fmt1(r.front().front().plots_per_scan) + ".\n\n" + scr_header(r, "| metric | tracker |", "|---|---|");
  for (const Column& c : kColumns) {
    for (std::size_t t = 0; t < r.front().size(); ++t) {
      s += std::string("| ") + c.title + " | " + paper_name(r.front()[t].base.tracker) + " |";
      for (const auto& col : r) s += " " + cell(sea_summary_to_json(col[t]), c) + " |";
      s += "\n";
    }
  }
  s += best_rows(r);
  s += "\nn/a: the field is not in summary.json (yet), or no track was paired with a target. IDS and Frag per target (track scores); RMSE of the confirmed "
       "track paired with each target (Mahalanobis on range and range rate, within 9.4); OSPA on range with p = 2, c = 9.4 x 15 m.\n";
  return s + paired_markdown(r);
}

nlohmann::ordered_json sea_compare_to_json(const SeaCompareConfig& cfg, const std::vector<std::vector<SeaSummary>>& r) {
  nlohmann::ordered_json levels = nlohmann::ordered_json::array();
  for (const auto& col : r) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const SeaSummary& x : col) rows.push_back(sea_summary_to_json(x));
    nlohmann::ordered_json level = {{"scr_db", col.empty() ? 0.0 : col.front().scr_db}, {"rows", rows}};
    if (!col.empty() && nemp_minus_mpnn(col, kPaired[0]).runs > 0) {
      nlohmann::ordered_json paired;
      for (const PairedMetric& m : kPaired) {
        const PairedDifference d = nemp_minus_mpnn(col, m);
        paired[m.key] = {{"mean", d.mean}, {"standard_error", d.standard_error}, {"runs", d.runs},
                         {"nemp_lower", d.a_lower}};
      }
      level["nemp_minus_mfbp_nn"] = paired;
    }
    levels.push_back(level);
  }
  nlohmann::ordered_json out = {{"scenario", cfg.scenario.name}, {"runs", cfg.runs}, {"seed", cfg.seed}, {"levels", levels}};
  if (!r.empty() && nemp_minus_mpnn_over_scr(r, kPaired[0]).runs > 0) {
    nlohmann::ordered_json paired;
    for (const PairedMetric& m : kPaired) {
      const PairedDifference d = nemp_minus_mpnn_over_scr(r, m);
      paired[m.key] = {{"mean", d.mean}, {"standard_error", d.standard_error}, {"runs", d.runs}};
    }
    out["nemp_minus_mfbp_nn_over_scr"] = paired;
  }
  return out;
}

}  // namespace mptrack::sim
