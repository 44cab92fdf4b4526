// Raw-ADC Monte Carlo runner; see adc_runner.h.
#include "stream/adc_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <set>
#include <thread>

#include "metrics.h"
#include "mptrack/adc/frontend_config.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/math/detmath.h"
#include "mptrack/platform/stage_report.h"
#include "progress.h"
#include "stream/adc_trackers.h"
#include "svg_plot.h"
#include "writers.h"

namespace mptrack::sim {

namespace {

using FrontEnd = frontend::FrontEnd<adc::AdcCaps>;
using FeScan = Scan<float, adc::AdcCaps::kMaxDetections>;

constexpr double kMatchGate_m = 3.0;  ///< detection <-> drone association gate for origin labels and accuracy
constexpr double kRadToDeg = 180.0 / dmath::kPi<double>;

// FrontEndStageTimes wants a 32-bit tick source: steady-clock nanoseconds
// (wraps every 4.3 s; stage deltas are far shorter).
std::uint32_t ns_clock() { return static_cast<std::uint32_t>(stream_now_ns()); }

struct FrameRecord {
  std::uint32_t detections = 0, drone_detections = 0, over_cap = 0;
  double range_us = 0, doppler_us = 0, angle_us = 0, cfar_us = 0, tracker_us = 0, frame_us = 0, queue_us = 0;
  bool processed = false;
};

/// Labels each detection with the nearest drone within the gate (each
/// detection and each drone used once, closest pairs first); fills
/// truth.measurement_index. Returns the squared errors of the matches.
void label_origins(scenario::SimScan& s, double& sum_dr2, double& sum_db2, std::uint64_t& matched) {
  struct Pair {
    double d;
    std::size_t t, m;
  };
  std::vector<Pair> pairs;
  for (std::size_t t = 0; t < s.truth.size(); ++t) {
    for (std::size_t m = 0; m < s.measurements.size(); ++m) {
      const scenario::SimMeasurement& y = s.measurements[m];
      double sn = 0.0, cs = 1.0;
      dmath::dsincos(y.azimuth_rad, sn, cs);
      const double d = std::hypot(y.range_m * cs - s.truth[t].x.px, y.range_m * sn - s.truth[t].x.py);
      if (d < kMatchGate_m) pairs.push_back(Pair{d, t, m});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.d < b.d || (a.d == b.d && (a.t < b.t || (a.t == b.t && a.m < b.m)));
  });
  for (const Pair& p : pairs) {
    scenario::TruthState& t = s.truth[p.t];
    scenario::SimMeasurement& y = s.measurements[p.m];
    if (t.measurement_index >= 0 || y.origin.kind == scenario::OriginKind::kTarget) continue;
    t.measurement_index = static_cast<std::int32_t>(p.m);
    t.detected = true;
    y.origin = scenario::Origin{scenario::OriginKind::kTarget, t.target_id};
    const double r = std::hypot(t.x.px, t.x.py);
    const double dr = y.range_m - r;
    double db = y.azimuth_rad - dmath::datan2(t.x.py, t.x.px);
    sum_dr2 += dr * dr;
    sum_db2 += db * db;
    ++matched;
  }
}


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

void truncate_frames(adc::AdcScenario& s, std::uint32_t frames) {
  if (frames == 0 || frames >= s.num_frames) return;
  s.num_frames = frames;
  const auto clip = [&](auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    std::vector<T> keep;
    for (T x : v) {
      if (x.birth_frame > frames) continue;
      x.death_frame = std::min(x.death_frame, frames);
      keep.push_back(x);
    }
    v = keep;
  };
  clip(s.drones);
  clip(s.clutter_patches);
  clip(s.chaff_clouds);
  clip(s.jammers);
  std::vector<adc::EvalPhase> phases;
  for (adc::EvalPhase p : s.phases) {
    if (p.first_frame > frames) continue;
    p.last_frame = std::min(p.last_frame, frames);
    phases.push_back(p);
  }
  s.phases = phases;
}

AdcSummary run_adc_monte_carlo(const AdcRunConfig& cfg) {
  adc::AdcScenario sc = cfg.scenario;
  truncate_frames(sc, cfg.frames);
  const std::string err = adc::validate(sc);
  if (!err.empty()) throw std::runtime_error("scenario " + sc.name + ": " + err);
  if (cfg.runs < 1) throw std::runtime_error("--runs must be >= 1");
  if (!(cfg.rate_hz >= 0.0)) throw std::runtime_error("--rate must be >= 0");
  {
    std::string error;
    if (!make_adc_tracker(cfg.tracker, error)) throw std::runtime_error(error);
  }
  const scenario::ScenarioSpec view = tracker_view(sc);
  const std::uint32_t n_frames = sc.num_frames;

  AdcSummary out;
  Summary& sum = out.base;
  sum.scenario = sc.name;
  sum.tracker = cfg.tracker;
  sum.runs = cfg.runs;
  sum.scans = n_frames;
  sum.seed = cfg.seed;
  sum.eval_first_scan = 1;
  sum.eval_last_scan = n_frames;
  sum.ospa_per_scan.assign(n_frames, 0.0);
  out.rate_hz = cfg.rate_hz;
  out.cardinality_per_frame.assign(n_frames, 0.0);

  std::unique_ptr<CsvWriters> csv;
  std::ofstream fe_csv;
  if (!cfg.out_dir.empty()) {
    csv = std::make_unique<CsvWriters>(cfg.out_dir);
    fe_csv.open(cfg.out_dir + "/frontend.csv");
    if (!fe_csv) throw std::runtime_error(cfg.out_dir + "/frontend.csv: cannot write");
    fe_csv << "run,frame,processed,detections,drone_detections,over_cap,range_us,doppler_us,angle_us,cfar_us,"
              "tracker_us,frame_us,queue_us\n";
  }

  ScanEvaluator evaluator(sc.ospa_cutoff_m);
  std::vector<FrameRecord> all_records;
  double ospa_sum = 0.0, gospa_sum = 0.0, nft_sum = 0.0, confirmed_sum = 0.0, truths_sum = 0.0;
  double tracks_found_sum = 0.0, det_sum = 0.0, dr2 = 0.0, db2 = 0.0;
  std::uint64_t matched = 0, drone_frames = 0, processed_total = 0;
  std::map<std::string, double> phase_sum;
  std::map<std::string, std::uint64_t> phase_n;
  std::map<std::uint32_t, double> delay_sum;
  std::map<std::uint32_t, std::uint32_t> delay_n;
  std::vector<scenario::SimScan> plot_scans;
  std::vector<EstimateOut> plot_estimates;

  auto fe = std::make_unique<FrontEnd>();
  Progress progress(sc.name + " " + cfg.tracker, static_cast<std::uint64_t>(cfg.runs) * n_frames, cfg.progress);
  platform::CoreProfileRecorders stage_profile;  // per-stage table with -DMPTRACK_PROFILE=ON
  for (std::uint32_t run = 0; run < cfg.runs; ++run) {
    evaluator.begin_run();
    adc::FrameSynthesizer syn;
    if (syn.init(sc, cfg.seed, run) != Status::kOk) throw std::runtime_error(syn.error());
    if (fe->init(adc::frontend_params_for(sc)) != Status::kOk) throw std::runtime_error("front end init failed");
    std::string error;
    std::unique_ptr<TrackerAdapter> tracker = make_adc_tracker(cfg.tracker, error);
    TrackerSetup setup;
    setup.spec = view;
    setup.mfbp_params = cfg.mfbp_params;
    error = tracker->init(setup);
    if (!error.empty()) throw std::runtime_error("tracker " + cfg.tracker + ": " + error);

    // 1. Synthesise (not timed, not streamed yet).
    std::vector<adc::AdcCube> cubes(n_frames);
    std::vector<scenario::SimScan> scans(n_frames);
    std::vector<adc::DroneTruth> truth;
    for (std::uint32_t k = 1; k <= n_frames; ++k) {
      if (syn.synthesize(k, cubes[k - 1], truth) != Status::kOk) throw std::runtime_error("synthesis failed");
      scenario::SimScan& s = scans[k - 1];
      s.scan = k;
      s.time_us = cubes[k - 1].time_us;
      for (const adc::DroneTruth& t : truth) {
        scenario::TruthState ts;
        ts.target_id = t.id;
        ts.x.px = t.state.x;
        ts.x.py = t.state.y;
        ts.x.vx = t.state.vx;
        ts.x.vy = t.state.vy;
        ts.snr = t.snr_mean;
        ts.in_region = true;
        s.truth.push_back(ts);
      }
    }

    // 2.-3. Stream through the ring; the consumer runs front end + tracker.
    auto ring = std::make_unique<StreamRing>();  // fresh counters per run
    std::vector<FrameRecord> recs(n_frames);
    std::vector<EstimateOut> finals;
    std::vector<std::uint32_t> step_frame;  // tracker step index -> frame
    FeScan fe_scan;
    StreamOptions sopt;
    sopt.rate_hz = cfg.rate_hz;
    const StreamCounters rc = run_stream(
        *ring, n_frames, sopt,
        [&](std::uint32_t k, StreamFrame& slot) { slot.cube = cubes[k - 1]; },
        [&](const StreamFrame& f, std::uint64_t queue_ns) {
          const std::uint64_t t0 = stream_now_ns();
          FrameRecord& r = recs[f.frame - 1];
          r.processed = true;
          r.queue_us = static_cast<double>(queue_ns) * 1e-3;
          frontend::FrontEndStageTimes times;
          times.clock = &ns_clock;
          const Status fst = fe->process(f.cube, fe_scan, &times);
          stage_profile.poll();
          const std::uint64_t t1 = stream_now_ns();
          r.range_us = times.ticks[0] * 1e-3;
          r.doppler_us = times.ticks[1] * 1e-3;
          r.angle_us = times.ticks[2] * 1e-3;
          r.cfar_us = times.ticks[3] * 1e-3;
          r.over_cap = static_cast<std::uint32_t>(fe->last_frame_dropped());
          scenario::SimScan& s = scans[f.frame - 1];
          // kCapacityExceeded: the strongest detections were kept (the rest
          // are counted in over_cap); the frame is still usable.
          if (fst == Status::kOk || fst == Status::kCapacityExceeded) {
            for (const Measurement<float>& m : fe_scan.measurements) {
              scenario::SimMeasurement y;
              y.range_m = static_cast<double>(m.range_m);
              y.azimuth_rad = static_cast<double>(m.azimuth_rad);
              y.amplitude = static_cast<double>(m.amplitude);
              y.origin = scenario::Origin{scenario::OriginKind::kClutter, 0};
              s.measurements.push_back(y);
            }
          }
          r.detections = static_cast<std::uint32_t>(s.measurements.size());
          step_frame.push_back(f.frame);
          const std::uint64_t t2 = stream_now_ns();
          const Status st = tracker->step(s, finals);
          const std::uint64_t t3 = stream_now_ns();
          stage_profile.poll();
          sum.count_status(st);
          r.tracker_us = static_cast<double>(t3 - t2) * 1e-3;
          r.frame_us = static_cast<double>((t1 - t0) + (t3 - t2)) * 1e-3;
          if (cfg.consumer_delay_us > 0) std::this_thread::sleep_for(std::chrono::microseconds(cfg.consumer_delay_us));
          progress.tick();
        });
    sum.count_status(tracker->flush(finals));
    sum.add_counters(tracker->counters());
    out.ring.frames_offered += rc.frames_offered;
    out.ring.frames_pushed += rc.frames_pushed;
    out.ring.frames_processed += rc.frames_processed;
    out.ring.dropped_frames += rc.dropped_frames;
    out.ring.producer_late += rc.producer_late;

    // Origin labels (truth only; after the tracker saw the frame).
    for (std::uint32_t k = 1; k <= n_frames; ++k) {
      scenario::SimScan& s = scans[k - 1];
      label_origins(s, dr2, db2, matched);
      FrameRecord& r = recs[k - 1];
      for (const auto& t : s.truth) r.drone_detections += t.measurement_index >= 0 ? 1u : 0u;
      if (r.processed) {
        ++processed_total;
        det_sum += r.detections;
        drone_frames += s.truth.size();
      }
    }

    std::vector<EstimateOut> by_scan(n_frames);
    for (std::uint32_t k = 1; k <= n_frames; ++k) by_scan[k - 1].scan = k;
    for (EstimateOut& e : finals) {
      if (e.scan < 1 || e.scan > step_frame.size()) continue;
      const std::uint32_t frame = step_frame[e.scan - 1];
      e.scan = frame;
      by_scan[frame - 1] = std::move(e);
    }

    std::vector<ScanMetrics> metrics(n_frames);
    std::set<std::uint32_t> found;
    std::map<std::uint32_t, bool> started;
    for (std::uint32_t k = 1; k <= n_frames; ++k) {
      const ScanMetrics m = evaluator.evaluate(scans[k - 1], by_scan[k - 1]);
      metrics[k - 1] = m;
      sum.ospa_per_scan[k - 1] += m.ospa / static_cast<double>(cfg.runs);
      out.cardinality_per_frame[k - 1] += static_cast<double>(m.confirmed) / static_cast<double>(cfg.runs);
      for (const TrackOut& t : by_scan[k - 1].tracks) {
        if (t.confirmed) found.insert(t.id);
      }
      ospa_sum += m.ospa;
      gospa_sum += m.gospa;
      nft_sum += m.false_tracks;
      confirmed_sum += m.confirmed;
      truths_sum += m.truths;
      sum.car_correct += m.car_correct;
      sum.car_total += m.car_total;
      sum.car_id_correct += m.car_id_correct;
      for (const adc::EvalPhase& p : sc.phases) {
        if (k < p.first_frame || k > p.last_frame) continue;
        phase_sum[p.name] += m.ospa;
        ++phase_n[p.name];
      }
      // Track start delay: first frame with a confirmed track within c.
      for (const auto& t : scans[k - 1].truth) {
        if (started[t.target_id]) continue;
        for (const TrackOut& e : by_scan[k - 1].tracks) {
          if (e.confirmed && std::hypot(e.px - t.x.px, e.py - t.x.py) < sc.ospa_cutoff_m) {
            started[t.target_id] = true;
            for (const adc::DroneSpec& d : sc.drones) {
              if (d.id == t.target_id) {
                delay_sum[d.id] += static_cast<double>(k - d.birth_frame);
                ++delay_n[d.id];
              }
            }
            break;
          }
        }
      }
    }
    // A drone never picked up counts its whole life as delay.
    for (const adc::DroneSpec& d : sc.drones) {
      if (!started[d.id]) {
        delay_sum[d.id] += static_cast<double>(d.death_frame - d.birth_frame + 1);
        ++delay_n[d.id];
      }
    }
    tracks_found_sum += static_cast<double>(found.size());

    std::vector<double> lat(n_frames, 0.0);
    for (std::uint32_t k = 0; k < n_frames; ++k) lat[k] = recs[k].tracker_us;
    if (csv && (cfg.csv_runs < 0 || static_cast<std::int64_t>(run) < cfg.csv_runs)) {
      csv->write_run(run, view, scans, by_scan, metrics, lat);
      for (std::uint32_t k = 0; k < n_frames; ++k) {
        const FrameRecord& r = recs[k];
        char line[320];
        std::snprintf(line, sizeof line, "%u,%u,%d,%u,%u,%u,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n", run, k + 1,
                      r.processed ? 1 : 0, r.detections, r.drone_detections, r.over_cap, r.range_us, r.doppler_us,
                      r.angle_us, r.cfar_us, r.tracker_us, r.frame_us, r.queue_us);
        fe_csv << line;
      }
    }
    all_records.insert(all_records.end(), recs.begin(), recs.end());
    if (run == 0) {
      plot_scans = std::move(scans);
      plot_estimates = std::move(by_scan);
    }
  }
  progress.finish();

  const double n_eval = static_cast<double>(cfg.runs) * n_frames;
  sum.mean_ospa = ospa_sum / n_eval;
  sum.mean_gospa = gospa_sum / n_eval;
  sum.nft = nft_sum / n_eval;
  sum.mean_confirmed_tracks = confirmed_sum / n_eval;
  sum.mean_truths = truths_sum / n_eval;
  sum.car = sum.car_total > 0 ? static_cast<double>(sum.car_correct) / static_cast<double>(sum.car_total) : 0.0;
  sum.car_identity =
      sum.car_total > 0 ? static_cast<double>(sum.car_id_correct) / static_cast<double>(sum.car_total) : 0.0;
  sum.tracks_found_per_run = tracks_found_sum / static_cast<double>(cfg.runs);
  sum.mean_measurements = processed_total > 0 ? det_sum / static_cast<double>(processed_total) : 0.0;
  out.mean_detections = sum.mean_measurements;
  out.drone_detection_rate = drone_frames > 0 ? static_cast<double>(matched) / static_cast<double>(drone_frames) : 0.0;
  out.range_error_rms_m = matched > 0 ? std::sqrt(dr2 / static_cast<double>(matched)) : 0.0;
  out.bearing_error_rms_deg = matched > 0 ? std::sqrt(db2 / static_cast<double>(matched)) * kRadToDeg : 0.0;
  for (const auto& [name, v] : phase_sum) out.ospa_by_phase[name] = v / static_cast<double>(phase_n[name]);
  for (const auto& [id, v] : delay_sum) out.start_delay[id] = v / static_cast<double>(delay_n[id]);
  out.stages.range = stats_of(all_records, &FrameRecord::range_us);
  out.stages.doppler = stats_of(all_records, &FrameRecord::doppler_us);
  out.stages.angle = stats_of(all_records, &FrameRecord::angle_us);
  out.stages.cfar = stats_of(all_records, &FrameRecord::cfar_us);
  out.stages.tracker = stats_of(all_records, &FrameRecord::tracker_us);
  out.stages.frame = stats_of(all_records, &FrameRecord::frame_us);
  out.stages.queue = stats_of(all_records, &FrameRecord::queue_us);
  {
    std::vector<double> v;
    for (const FrameRecord& r : all_records) {
      if (r.processed) v.push_back(r.range_us + r.doppler_us + r.angle_us + r.cfar_us);
    }
    out.stages.frontend = latency_stats(std::move(v));
  }
  sum.latency = out.stages.tracker;

  if (!cfg.out_dir.empty()) {
    std::ofstream f(cfg.out_dir + "/summary.json");
    if (!f) throw std::runtime_error(cfg.out_dir + "/summary.json: cannot write");
    f << adc_summary_to_json(out).dump(2) << "\n";
    if (cfg.plot) {
      char title[200];
      std::snprintf(title, sizeof title, "%s / %s, raw ADC (run 0; OSPA c = %g m, mean of %u runs)", sc.name.c_str(),
                    cfg.tracker.c_str(), sc.ospa_cutoff_m, cfg.runs);
      write_plot_svg(cfg.out_dir + "/plot.svg", view, plot_scans, plot_estimates, sum.ospa_per_scan, title);
    }
  }
  stage_profile.print();
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
  j["ospa_by_phase"] = s.ospa_by_phase;
  nlohmann::ordered_json d = nlohmann::ordered_json::object();
  for (const auto& [id, v] : s.start_delay) d[std::to_string(id)] = v;
  j["track_start_delay_frames"] = d;
  j["mean_confirmed_per_frame"] = s.cardinality_per_frame;
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
  std::printf("scenario %s (raw ADC -> front end -> %s): %u run(s) x %u frames, seed %llu, rate %s\n",
              s.scenario.c_str(), s.tracker.c_str(), s.runs, s.scans, static_cast<unsigned long long>(s.seed), rate);
  std::printf("  mean OSPA %.2f m (c = 10 m, p = 2)   confirmed tracks per frame %.2f (truths %.2f)   "
              "distinct confirmed tracks per run %.1f\n",
              s.mean_ospa, s.mean_confirmed_tracks, s.mean_truths, s.tracks_found_per_run);
  std::printf("  OSPA by phase:");
  for (const auto& [name, v] : a.ospa_by_phase) std::printf(" %s %.2f", name.c_str(), v);
  std::printf("\n  track start delay [frames]:");
  for (const auto& [id, v] : a.start_delay) std::printf(" drone %u: %.1f", id, v);
  std::printf("\n  front end: %.2f detections/frame, drone detection rate %.3f, rms error %.2f m / %.2f deg\n",
              a.mean_detections, a.drone_detection_rate, a.range_error_rms_m, a.bearing_error_rms_deg);
  const auto row = [](const char* name, const LatencyStats& l) {
    std::printf("    %-15s p50 %8.1f  p99 %8.1f  max %8.1f us\n", name, l.p50_us, l.p99_us, l.max_us);
  };
  std::printf("  per-frame latency (host):\n");
  row("range", a.stages.range);
  row("doppler", a.stages.doppler);
  row("angle", a.stages.angle);
  row("cfar+peaks", a.stages.cfar);
  row("tracker", a.stages.tracker);
  row("frame total", a.stages.frame);
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
