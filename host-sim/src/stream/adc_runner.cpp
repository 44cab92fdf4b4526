// Raw-ADC Monte Carlo runner; see adc_runner.h.
#include "stream/adc_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "mptrack/math/detmath.h"
#include "run/run_loop.h"
#include "run/run_outputs.h"
#include "run/truncate.h"
#include "stream/adc_source.h"
#include "stream/adc_trackers.h"
#include "svg_plot.h"
#include "writers.h"

namespace mptrack::sim {

namespace {

constexpr double kRadToDeg = 180.0 / dmath::kPi<double>;

LatencyStats stats_of(const std::vector<FrameRecord>& recs, double FrameRecord::*field) {
  std::vector<double> v;
  for (const FrameRecord& r : recs) {
    if (r.processed) v.push_back(r.*field);
  }
  return latency_stats(std::move(v));
}

nlohmann::ordered_json lat_json(const LatencyStats& s) {
  return {{"p50", s.p50_us}, {"p99", s.p99_us}, {"max", s.max_us}, {"mean", s.mean_us}, {"samples", s.count}};
}

}  // namespace

namespace {

void finish_frontend(const FrontEndTotals& t, AdcSummary& out) {
  out.ring = t.ring;
  out.mean_detections = out.base.mean_measurements;
  out.drone_detection_rate =
      t.drone_frames > 0 ? static_cast<double>(t.matched) / static_cast<double>(t.drone_frames) : 0.0;
  out.range_error_rms_m = t.matched > 0 ? std::sqrt(t.sum_range_err2 / static_cast<double>(t.matched)) : 0.0;
  out.bearing_error_rms_deg =
      t.matched > 0 ? std::sqrt(t.sum_bearing_err2 / static_cast<double>(t.matched)) * kRadToDeg : 0.0;
  out.clipped_samples = t.clipped_samples;
  out.frames_saturated = t.frames_saturated;
  out.saturated_detections = t.saturated_detections;
  out.saturated_frames_dropped = t.saturated_frames_dropped;
}

/// Raw-ADC statistics on top of the aggregator's, per tracker: OSPA by
/// phase, track start delay, stage latencies; frontend.csv (first tracker).
class AdcRunObserver final : public RunObserver {
 public:
  AdcRunObserver(const AdcScanSource& source, std::size_t trackers, const std::string& out_dir,
                 std::int64_t csv_runs)
      : source_(source), csv_runs_(csv_runs), per_tracker_(trackers) {
    if (out_dir.empty()) return;
    fe_csv_.open(out_dir + "/frontend.csv");
    if (!fe_csv_) throw std::runtime_error(out_dir + "/frontend.csv: cannot write");
    fe_csv_ << "run,frame,processed,detections,drone_detections,over_cap,range_us,doppler_us,angle_us,cfar_us,"
               "tracker_us,frame_us,queue_us,saturated\n";
  }

  void on_run(std::size_t tracker, const std::vector<scenario::SimScan>& scans, const RunRecord& rec,
              const std::vector<ScanMetrics>& metrics) override {
    const adc::AdcScenario& sc = source_.scenario();
    PerTracker& p = per_tracker_[tracker];
    std::map<std::uint32_t, bool> started;
    for (std::uint32_t k = 1; k <= sc.num_frames; ++k) {
      const ScanMetrics& m = metrics[k - 1];
      for (const adc::EvalPhase& ph : sc.phases) {
        if (k < ph.first_frame || k > ph.last_frame) continue;
        p.phase_sum[ph.name] += m.ospa;
        ++p.phase_n[ph.name];
      }
      note_track_starts(p, k, scans[k - 1], rec.by_scan[k - 1], started);
    }
    // A drone never picked up counts its whole life as delay.
    for (const adc::DroneSpec& d : sc.drones) {
      if (!started[d.id]) {
        p.delay_sum[d.id] += static_cast<double>(d.death_frame - d.birth_frame + 1);
        ++p.delay_n[d.id];
      }
    }
    const std::vector<FrameRecord>& recs = source_.frame_records();
    if (tracker == 0 && fe_csv_.is_open() && (csv_runs_ < 0 || static_cast<std::int64_t>(rec.run) < csv_runs_)) {
      write_frontend_rows(rec.run, recs);
    }
    p.records.insert(p.records.end(), recs.begin(), recs.end());
    add_totals(p.totals, source_.totals());
  }

  void finish(std::size_t tracker, AdcSummary& out) const {
    const PerTracker& p = per_tracker_[tracker];
    for (const auto& [name, v] : p.phase_sum) out.ospa_by_phase[name] = v / static_cast<double>(p.phase_n.at(name));
    for (const auto& [id, v] : p.delay_sum) out.start_delay[id] = v / static_cast<double>(p.delay_n.at(id));
    out.stages.range = stats_of(p.records, &FrameRecord::range_us);
    out.stages.doppler = stats_of(p.records, &FrameRecord::doppler_us);
    out.stages.angle = stats_of(p.records, &FrameRecord::angle_us);
    out.stages.cfar = stats_of(p.records, &FrameRecord::cfar_us);
    out.stages.tracker = stats_of(p.records, &FrameRecord::tracker_us);
    out.stages.frame = stats_of(p.records, &FrameRecord::frame_us);
    out.stages.queue = stats_of(p.records, &FrameRecord::queue_us);
    std::vector<double> v;
    for (const FrameRecord& r : p.records) {
      if (r.processed) v.push_back(r.range_us + r.doppler_us + r.angle_us + r.cfar_us);
    }
    out.stages.frontend = latency_stats(std::move(v));
    finish_frontend(p.totals, out);
  }

 private:
  static void add_totals(FrontEndTotals& sum, const FrontEndTotals& t) {
    sum.ring.frames_offered += t.ring.frames_offered;
    sum.ring.frames_pushed += t.ring.frames_pushed;
    sum.ring.frames_processed += t.ring.frames_processed;
    sum.ring.dropped_frames += t.ring.dropped_frames;
    sum.ring.producer_late += t.ring.producer_late;
    sum.drone_frames += t.drone_frames;
    sum.matched += t.matched;
    sum.sum_range_err2 += t.sum_range_err2;
    sum.sum_bearing_err2 += t.sum_bearing_err2;
    sum.clipped_samples += t.clipped_samples;
    sum.frames_saturated += t.frames_saturated;
    sum.saturated_detections += t.saturated_detections;
    sum.saturated_frames_dropped += t.saturated_frames_dropped;
  }

  struct PerTracker {
    FrontEndTotals totals;  ///< summed over this tracker's deliveries
    std::map<std::string, double> phase_sum;
    std::map<std::string, std::uint64_t> phase_n;
    std::map<std::uint32_t, double> delay_sum;
    std::map<std::uint32_t, std::uint32_t> delay_n;
    std::vector<FrameRecord> records;
  };

  /// Track start delay: the first frame with a confirmed track within c.
  void note_track_starts(PerTracker& p, std::uint32_t k, const scenario::SimScan& scan, const EstimateOut& est,
                         std::map<std::uint32_t, bool>& started) const {
    const adc::AdcScenario& sc = source_.scenario();
    for (const auto& t : scan.truth) {
      if (started[t.target_id]) continue;
      for (const TrackOut& e : est.tracks) {
        if (e.confirmed && std::hypot(e.px - t.x.px, e.py - t.x.py) < sc.ospa_cutoff_m) {
          started[t.target_id] = true;
          for (const adc::DroneSpec& d : sc.drones) {
            if (d.id == t.target_id) {
              p.delay_sum[d.id] += static_cast<double>(k - d.birth_frame);
              ++p.delay_n[d.id];
            }
          }
          break;
        }
      }
    }
  }

  void write_frontend_rows(std::uint32_t run, const std::vector<FrameRecord>& recs) {
    for (std::size_t k = 0; k < recs.size(); ++k) {
      const FrameRecord& r = recs[k];
      char line[320];
      // saturated: 0, 1 (int16 frame saturated, detections kept) or 2 (saturated, dropped)
      std::snprintf(line, sizeof line, "%u,%zu,%d,%u,%u,%u,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d\n", run, k + 1,
                    r.processed ? 1 : 0, r.detections, r.drone_detections, r.over_cap, r.range_us, r.doppler_us,
                    r.angle_us, r.cfar_us, r.tracker_us, r.frame_us, r.queue_us,
                    r.dropped_saturated ? 2 : r.saturated ? 1 : 0);
      fe_csv_ << line;
    }
  }

  const AdcScanSource& source_;
  std::int64_t csv_runs_ = -1;
  std::ofstream fe_csv_;
  std::vector<PerTracker> per_tracker_;
};


}  // namespace

std::vector<AdcSummary> run_adc_loop(const AdcRunConfig& cfg, const std::vector<std::string>& trackers,
                                     bool run_outputs) {
  adc::AdcScenario sc = cfg.scenario;
  truncate_frames(sc, cfg.frames);
  if (!cfg.adc_format.empty()) sc.adc.sample_format = cfg.adc_format;
  if (!cfg.saturation_policy.empty()) sc.adc.saturation_policy = cfg.saturation_policy;
  const std::string err = adc::validate(sc);
  if (!err.empty()) throw std::runtime_error("scenario " + sc.name + ": " + err);
  if (!(cfg.rate_hz >= 0.0)) throw std::runtime_error("--rate must be >= 0");
  LoopConfig loop = one_tracker_loop(cfg, sc.name);
  loop.trackers = trackers;
  if (trackers.size() > 1) loop.progress_label = "compare " + sc.name;
  loop.factory = &make_adc_tracker;
  loop.raw_scenario = std::make_shared<const adc::AdcScenario>(sc);
  loop.ospa_cutoff_m = sc.ospa_cutoff_m;
  loop.ospa_order = sc.ospa_order;
  check_loop_config(loop);  // before the output directory is created

  AdcScanSource source(sc, cfg.seed, cfg.rate_hz, cfg.consumer_delay_us);
  std::unique_ptr<RunOutputs> outputs;
  std::vector<RunObserver*> observers;
  if (run_outputs) {
    outputs = std::make_unique<RunOutputs>(cfg, source.spec());
    observers = outputs->observers();
  } else if (!cfg.out_dir.empty()) {
    std::filesystem::create_directories(cfg.out_dir);
  }
  AdcRunObserver adc_stats(source, trackers.size(), cfg.out_dir, cfg.csv_runs);
  observers.push_back(&adc_stats);

  const std::vector<Summary> base = run_loop(source, loop, observers);
  std::vector<AdcSummary> out(base.size());
  for (std::size_t t = 0; t < base.size(); ++t) {
    out[t].base = base[t];
    out[t].rate_hz = cfg.rate_hz;
    out[t].ospa_cutoff_m = sc.ospa_cutoff_m;
    out[t].ospa_order = sc.ospa_order;
    out[t].phases = sc.phases;
    out[t].adc = sc.adc;
    adc_stats.finish(t, out[t]);
  }
  if (outputs) {
    char title[200];
    std::snprintf(title, sizeof title, "%s / %s, raw ADC (run 0; OSPA c = %g m, mean of %u runs)", sc.name.c_str(),
                  trackers.front().c_str(), sc.ospa_cutoff_m, cfg.runs);
    outputs->write_plot(out.front().base.ospa_per_scan, title, sc.ospa_order, sc.ospa_cutoff_m);
  }
  source.print_stage_profile();
  return out;
}

AdcSummary run_adc_monte_carlo(const AdcRunConfig& cfg) {
  AdcSummary out = run_adc_loop(cfg, {cfg.tracker}, true).front();
  if (!cfg.out_dir.empty()) {
    std::ofstream f(cfg.out_dir + "/summary.json");
    if (!f) throw std::runtime_error(cfg.out_dir + "/summary.json: cannot write");
    f << adc_summary_to_json(out).dump(2) << "\n";
  }
  return out;
}

nlohmann::ordered_json adc_summary_to_json(const AdcSummary& s) {
  nlohmann::ordered_json j = summary_to_json(s.base);
  j["input"] = "raw_adc";
  j["rate_hz"] = s.rate_hz;
  j["stage_latency_us"] = {{"range", lat_json(s.stages.range)},       {"doppler", lat_json(s.stages.doppler)},
                           {"angle", lat_json(s.stages.angle)},       {"cfar", lat_json(s.stages.cfar)},
                           {"tracker", lat_json(s.stages.tracker)},   {"frontend_total", lat_json(s.stages.frontend)},
                           {"frame_total", lat_json(s.stages.frame)}, {"queue_wait", lat_json(s.stages.queue)}};
  j["ring"] = {{"frames_offered", s.ring.frames_offered},
               {"frames_pushed", s.ring.frames_pushed},
               {"frames_processed", s.ring.frames_processed},
               {"dropped_frames", s.ring.dropped_frames},
               {"producer_late", s.ring.producer_late}};
  j["frontend"] = {{"mean_detections_per_frame", s.mean_detections},
                   {"drone_detection_rate", s.drone_detection_rate},
                   {"range_error_rms_m", s.range_error_rms_m},
                   {"bearing_error_rms_deg", s.bearing_error_rms_deg}};
  if (s.adc.sample_format == "int16") {  // the float path's summary is unchanged
    j["adc"] = {{"sample_format", s.adc.sample_format},
                {"bits", s.adc.bits},
                {"full_scale_v", s.adc.full_scale_v},
                {"saturation_fraction", s.adc.saturation_fraction},
                {"saturation_policy", s.adc.saturation_policy},
                {"clipped_samples", s.clipped_samples},
                {"frames_saturated", s.frames_saturated},
                {"saturated_frame_detections", s.saturated_detections},
                {"saturated_frames_dropped", s.saturated_frames_dropped}};
  }
  j["ospa"] = {{"cutoff_m", s.ospa_cutoff_m}, {"order_p", s.ospa_order}};
  nlohmann::ordered_json spans = nlohmann::ordered_json::array();
  for (const adc::EvalPhase& p : s.phases) spans.push_back({{"name", p.name}, {"frames", {p.first_frame, p.last_frame}}});
  j["phases"] = spans;
  j["ospa_by_phase"] = s.ospa_by_phase;
  nlohmann::ordered_json d = nlohmann::ordered_json::object();
  for (const auto& [id, v] : s.start_delay) d[std::to_string(id)] = v;
  j["track_start_delay_frames"] = d;
  j["mean_confirmed_per_frame"] = s.base.confirmed_mean_per_scan;  // kept for scripts; = cardinality_per_scan.mean_confirmed
  return j;
}

void print_adc_summary(const AdcSummary& a, const std::string& out_dir) {
  const Summary& s = a.base;
  char rate[64];
  if (a.rate_hz > 0.0) {
    std::snprintf(rate, sizeof rate, "%g Hz", a.rate_hz);
  } else {
    std::snprintf(rate, sizeof rate, "lossless (as fast as consumed)");
  }
  std::printf("scenario %s (raw ADC: %s): %u run(s) x %u frames, seed %llu, rate %s\n",
              s.scenario.c_str(), pipeline_description(s.tracker).c_str(), s.runs, s.scans, static_cast<unsigned long long>(s.seed), rate);
  std::printf("  mean OSPA %.2f m (c = %g m, p = %g)   confirmed tracks per frame %.2f (truths %.2f)   "
              "distinct confirmed tracks per run %.1f\n",
              s.mean_ospa, a.ospa_cutoff_m, a.ospa_order, s.mean_confirmed_tracks, s.mean_truths,
              s.tracks_found_per_run);
  std::printf("  OSPA by phase:");
  for (const auto& [name, v] : a.ospa_by_phase) std::printf(" %s %.2f", name.c_str(), v);
  std::printf("\n  track start delay [frames]:");
  for (const auto& [id, v] : a.start_delay) std::printf(" drone %u: %.1f", id, v);
  std::printf("\n");
  if (a.stages.frontend.max_us > 0.0 || a.mean_detections > 0.0) {
    std::printf("  detections: %.2f per frame, drone detection rate %.3f, rms error %.2f m / %.2f deg\n",
                a.mean_detections, a.drone_detection_rate, a.range_error_rms_m, a.bearing_error_rms_deg);
  }
  const auto row = [](const char* name, const LatencyStats& l) {
    std::printf("    %-15s p50 %8.1f  p99 %8.1f  max %8.1f us\n", name, l.p50_us, l.p99_us, l.max_us);
  };
  std::printf("  per-frame latency (host):\n");
  if (a.stages.frontend.max_us > 0.0 && s.tracker == "sbl-gnn") {  // the SBL detector's stages
    row("spectrum", a.stages.range);
    row("map searches", a.stages.angle);
    row("sbl refinement", a.stages.cfar);
  } else if (a.stages.frontend.max_us > 0.0) {  // else the tracker consumed the raw frame
    row("range", a.stages.range);
    row("doppler", a.stages.doppler);
    row("angle", a.stages.angle);
    row("cfar+peaks", a.stages.cfar);
  }
  row("tracker", a.stages.tracker);
  row("frame total", a.stages.frame);
  if (a.adc.sample_format == "int16") {
    std::printf("  adc: int16, %u bits, full scale %g V; %llu values clipped, %llu saturated frames "
                "(%llu detections; policy %s, %llu dropped)\n",
                a.adc.bits, a.adc.full_scale_v, static_cast<unsigned long long>(a.clipped_samples),
                static_cast<unsigned long long>(a.frames_saturated),
                static_cast<unsigned long long>(a.saturated_detections), a.adc.saturation_policy.c_str(),
                static_cast<unsigned long long>(a.saturated_frames_dropped));
  }
  std::printf("  ring: offered %llu, pushed %llu, processed %llu, dropped %llu\n",
              static_cast<unsigned long long>(a.ring.frames_offered),
              static_cast<unsigned long long>(a.ring.frames_pushed),
              static_cast<unsigned long long>(a.ring.frames_processed),
              static_cast<unsigned long long>(a.ring.dropped_frames));
  if (!out_dir.empty()) {
    std::printf("  wrote %s/{summary.json,truth.csv,measurements.csv,tracks.csv,metrics.csv,frontend.csv,plot.svg}\n",
                out_dir.c_str());
  }
}

}  // namespace mptrack::sim
