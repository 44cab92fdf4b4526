// results.json, latency.svg and the summary table (see results_writer.h).
#include "results_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace mptrack::bench {
namespace {

using nlohmann::json;

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  out.push_back(cur);
  return out;
}

double counter(const RunRecord& r, const std::string& k) {
  const auto it = r.counters.find(k);
  return it == r.counters.end() ? 0.0 : it->second;
}

struct GridPoint {
  std::string tracker, scalar;
  double targets = 0, meas_nominal = 0, meas = 0, comps = 0;
  double scan_us = 0, p50 = 0, p99 = 0, max = 0, not_ok = 0;
};

// Growth exponent between two points: 1 = linear, 2 = quadratic.
double exponent(double x0, double y0, double x1, double y1) {
  if (!(x0 > 0 && x1 > x0 && y0 > 0 && y1 > 0)) return 0.0;
  return std::log(y1 / y0) / std::log(x1 / x0);
}

// Least-squares line y = a + b x and its R^2 (linearity of cost vs work).
void linear_fit(const std::vector<std::pair<double, double>>& xy, double& a, double& b, double& r2) {
  a = b = r2 = 0.0;
  const double n = static_cast<double>(xy.size());
  if (xy.size() < 2) return;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& p : xy) {
    sx += p.first;
    sy += p.second;
    sxx += p.first * p.first;
    sxy += p.first * p.second;
  }
  const double den = n * sxx - sx * sx;
  if (den == 0.0) return;
  b = (n * sxy - sx * sy) / den;
  a = (sy - b * sx) / n;
  double ss_res = 0, ss_tot = 0;
  const double my = sy / n;
  for (const auto& p : xy) {
    const double e = p.second - (a + b * p.first);
    ss_res += e * e;
    ss_tot += (p.second - my) * (p.second - my);
  }
  r2 = ss_tot > 0 ? 1.0 - ss_res / ss_tot : 1.0;
}

// Points of one sweep: vary `axis`, the other two at the centre (T 8, M 128, C 2).
std::vector<std::pair<double, double>> sweep(const std::vector<GridPoint>& g, const std::string& tracker,
                                             const std::string& scalar, const std::string& axis) {
  std::vector<std::pair<double, double>> xy;
  for (const GridPoint& p : g) {
    if (p.tracker != tracker || p.scalar != scalar) continue;
    const bool t_c = p.targets == 8, m_c = p.meas_nominal == 128, c_c = p.comps == 2;
    if (axis == "targets" && m_c && c_c) xy.push_back({p.targets, p.scan_us});
    if (axis == "measurements" && t_c && c_c) xy.push_back({p.meas, p.scan_us});
    if (axis == "clutter_components" && t_c && m_c) xy.push_back({p.comps, p.scan_us});
  }
  std::sort(xy.begin(), xy.end());
  return xy;
}

const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"};

std::string svg_plot(const std::vector<GridPoint>& grid, const std::vector<std::string>& trackers) {
  const char* axes[] = {"targets", "measurements", "clutter_components"};
  const char* labels[] = {"targets (M 128, C 2)", "measurements per scan (T 8, C 2), log-log",
                          "clutter components (T 8, M 128)"};
  const double pw = 360, ph = 280, ml = 80, mt = 40, gap = 30;
  std::ostringstream o;
  const double width = 3 * (pw + ml) + 2 * gap + 20;
  const double height = ph + mt + 110;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
    << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n"
    << "<text x='10' y='20' font-size='14'>mptrack per-scan latency (float, steady state, mean) against work. "
       "Middle panel log-log: dashed guides have slope 1 (linear) and 2 (quadratic).</text>\n";
  for (int a = 0; a < 3; ++a) {
    const bool log_axes = (a == 1);
    const double x0 = ml + a * (pw + ml + gap), y0 = mt;
    double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
    for (const auto& t : trackers) {
      for (const auto& p : sweep(grid, t, "float", axes[a])) {
        xmin = std::min(xmin, p.first);
        xmax = std::max(xmax, p.first);
        ymin = std::min(ymin, p.second);
        ymax = std::max(ymax, p.second);
      }
    }
    if (xmax <= 0) xmax = 1;
    if (ymax <= 0) ymax = 1;
    if (!(xmin > 0) || xmin > xmax) xmin = 1;
    if (!(ymin > 0) || ymin > ymax) ymin = 1;
    double fx0 = 0, fx1 = xmax, fy0 = 0, fy1 = ymax * 1.05;
    if (log_axes) {
      fx0 = std::log10(xmin) - 0.05;
      fx1 = std::log10(xmax) + 0.05;
      fy0 = std::log10(ymin) - 0.1;
      fy1 = std::log10(ymax) + 0.1;
    }
    auto px = [&](double x) { return x0 + pw * ((log_axes ? std::log10(x) : x) - fx0) / (fx1 - fx0); };
    auto py = [&](double y) { return y0 + ph - ph * ((log_axes ? std::log10(y) : y) - fy0) / (fy1 - fy0); };
    o << "<rect x='" << x0 << "' y='" << y0 << "' width='" << pw << "' height='" << ph
      << "' fill='none' stroke='black'/>\n";
    for (int i = 0; i <= 4; ++i) {
      const double fy = fy0 + (fy1 - fy0) * i / 4.0;
      const double fx = fx0 + (fx1 - fx0) * i / 4.0;
      const double yy = y0 + ph - ph * i / 4.0;
      const double xx = x0 + pw * i / 4.0;
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.0f", log_axes ? std::pow(10.0, fy) : fy);
      o << "<line x1='" << x0 << "' x2='" << x0 + pw << "' y1='" << yy << "' y2='" << yy
        << "' stroke='#ddd'/><text x='" << x0 - 5 << "' y='" << yy + 4 << "' text-anchor='end'>" << buf
        << "</text>\n";
      std::snprintf(buf, sizeof buf, "%.0f", log_axes ? std::pow(10.0, fx) : fx);
      o << "<text x='" << xx << "' y='" << y0 + ph + 15 << "' text-anchor='middle'>" << buf << "</text>\n";
    }
    o << "<text x='" << x0 + pw / 2 << "' y='" << y0 + ph + 32 << "' text-anchor='middle'>" << labels[a]
      << "</text>\n";
    o << "<text x='" << x0 - 55 << "' y='" << y0 + ph / 2 << "' transform='rotate(-90 " << x0 - 55 << ' '
      << y0 + ph / 2 << ")' text-anchor='middle'>us per scan</text>\n";
    if (log_axes) {
      // Guides through the lowest point: y = ymin (x / xmin)^k, k = 1, 2.
      for (double k : {1.0, 2.0}) {
        const double xe = std::min(xmax, xmin * std::pow(ymax / ymin, 1.0 / k));
        o << "<line x1='" << px(xmin) << "' y1='" << py(ymin) << "' x2='" << px(xe) << "' y2='"
          << py(ymin * std::pow(xe / xmin, k)) << "' stroke='#888' stroke-dasharray='5,4'/>"
          << "<text x='" << px(xe) + 3 << "' y='" << py(ymin * std::pow(xe / xmin, k)) + 12
          << "' fill='#666'>slope " << k << "</text>\n";
      }
    }
    for (std::size_t ti = 0; ti < trackers.size(); ++ti) {
      const auto pts = sweep(grid, trackers[ti], "float", axes[a]);
      std::ostringstream path;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        if (log_axes && !(pts[i].first > 0 && pts[i].second > 0)) continue;
        path << (path.tellp() == 0 ? "M" : " L") << px(pts[i].first) << ' ' << py(pts[i].second);
        o << "<circle cx='" << px(pts[i].first) << "' cy='" << py(pts[i].second) << "' r='2.5' fill='"
          << kColours[ti % 6] << "'/>\n";
      }
      o << "<path d='" << path.str() << "' fill='none' stroke='" << kColours[ti % 6] << "' stroke-width='1.5'/>\n";
    }
  }
  for (std::size_t ti = 0; ti < trackers.size(); ++ti) {
    const double lx = ml + 130.0 * static_cast<double>(ti);
    const double ly = mt + ph + 60;
    o << "<rect x='" << lx << "' y='" << ly - 9 << "' width='14' height='4' fill='" << kColours[ti % 6]
      << "'/><text x='" << lx + 20 << "' y='" << ly - 3 << "'>" << trackers[ti] << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace

bool write_results(const std::string& dir, const std::vector<RunRecord>& runs, const MachineInfo& machine) {
  json out;
  out["schema"] = "mptrack-bench/1";
  out["machine"] = {{"num_cpus", machine.num_cpus},         {"mhz_per_cpu", machine.mhz_per_cpu},
                    {"build_type", machine.build_type},     {"compiler", machine.compiler},
                    {"timestamp_utc", machine.timestamp_utc}};
  // --- FFT ---
  std::map<int, std::pair<std::vector<double>, std::vector<double>>> fft_reps;  // size -> CPU ns per repetition
  json frontend = json::object();
  json frontend_vs_fft = json::object();  // frontend/large_vs_fft: stage / its FFTs, per frame
  json s2 = json::object();
  std::vector<GridPoint> grid;
  std::vector<std::string> errors;
  for (const RunRecord& r : runs) {
    if (r.error) {
      errors.push_back(r.name);
      continue;
    }
    // Drop Google Benchmark's option suffixes ("/min_time:0.050", "/manual_time").
    std::vector<std::string> parts;
    for (const std::string& p : split(r.name, '/')) {
      if (p.find(':') == std::string::npos && p != "manual_time" && p != "real_time") parts.push_back(p);
    }
    if (parts[0] == "fft" && parts.size() == 3) {
      // CPU time (the thread's own, so time slices lost to other processes
      // on a shared machine do not count); the median of the repetitions below.
      auto& e = fft_reps[std::stoi(parts[2])];
      (parts[1] == "ours" ? e.first : e.second).push_back(r.cpu_ns);
    } else if (parts[0] == "frontend" && parts.size() == 2 && parts[1] == "large_vs_fft") {
      for (const char* k : {"range_vs_fft_p50", "range_vs_fft_p90", "doppler_vs_fft_p50", "doppler_vs_fft_p90",
                            "angle_vs_fft_p50", "angle_vs_fft_p90"}) {
        frontend_vs_fft[k] = counter(r, k);
      }
    } else if (parts[0] == "frontend" && parts.size() == 2) {
      frontend[parts[1]] = {{"frame_us", r.time_ns * 1e-3},
                            {"detections", counter(r, "detections")},
                            {"range_us", counter(r, "range_us")},
                            {"doppler_us", counter(r, "doppler_us")},
                            {"angle_us", counter(r, "angle_us")},
                            {"detect_us", counter(r, "detect_us")}};
    } else if (parts[0] == "s2" && parts.size() == 3) {
      s2[parts[1]][parts[2]] = {{"scan_us", counter(r, "scan_us")}, {"p50_us", counter(r, "p50_us")},
                                {"p99_us", counter(r, "p99_us")},   {"max_us", counter(r, "max_us")},
                                {"scans", counter(r, "scans")},     {"meas_per_scan", counter(r, "meas")},
                                {"not_ok_steps", counter(r, "not_ok")}};
    } else if (parts[0] == "grid" && parts.size() == 6) {
      GridPoint p;
      p.tracker = parts[1];
      p.scalar = parts[2];
      p.targets = counter(r, "targets");
      p.meas_nominal = counter(r, "meas_nominal");
      p.meas = counter(r, "meas");
      p.comps = counter(r, "comps");
      p.scan_us = counter(r, "scan_us");
      p.p50 = counter(r, "p50_us");
      p.p99 = counter(r, "p99_us");
      p.max = counter(r, "max_us");
      p.not_ok = counter(r, "not_ok");
      grid.push_back(p);
    }
  }
  // size -> (ours ns, fftw ns): median of the repetitions (>= 5), each side.
  auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  };
  std::map<int, std::pair<double, double>> fft;
  for (const auto& kv : fft_reps) fft[kv.first] = {median(kv.second.first), median(kv.second.second)};
  json fft_rows = json::array();
  json ratios = json::object();
  double worst_ratio = 0.0;
  for (const auto& kv : fft) {
    const double ratio = kv.second.second > 0 ? kv.second.first / kv.second.second : 0.0;
    worst_ratio = std::max(worst_ratio, ratio);
    fft_rows.push_back({{"size", kv.first},
                        {"ours_ns", kv.second.first},
                        {"fftw_ns", kv.second.second},
                        {"fft_vs_fftw_ratio", ratio}});
    ratios[std::to_string(kv.first)] = ratio;
    out["fft_vs_fftw_ratio_" + std::to_string(kv.first)] = ratio;
  }
  out["fft"] = {{"reference", "FFTW 3 float, FFTW_MEASURE, single thread, out-of-place interleaved"},
                {"timing", "thread CPU time per transform, median of 5 interleaved repetitions"},
                {"sizes", fft_rows}};
  out["fft_vs_fftw_ratio"] = ratios;
  out["frontend"] = frontend;
  if (!frontend_vs_fft.empty()) out["frontend_large_vs_fft"] = frontend_vs_fft;
  out["seed000_s2"] = s2;
  json grid_rows = json::array();
  std::vector<std::string> trackers;
  for (const GridPoint& p : grid) {
    if (std::find(trackers.begin(), trackers.end(), p.tracker) == trackers.end()) trackers.push_back(p.tracker);
    grid_rows.push_back({{"tracker", p.tracker},        {"scalar", p.scalar},     {"targets", p.targets},
                         {"measurements_nominal", p.meas_nominal},                {"measurements", p.meas},
                         {"clutter_components", p.comps}, {"scan_us", p.scan_us}, {"p50_us", p.p50},
                         {"p99_us", p.p99},              {"max_us", p.max},        {"not_ok_steps", p.not_ok}});
  }
  out["latency_grid"] = grid_rows;
  // Growth: linear fit per axis, and the exponent over the upper half.
  json growth = json::object();
  for (const auto& t : trackers) {
    for (const char* axis : {"targets", "measurements", "clutter_components"}) {
      const auto xy = sweep(grid, t, "float", axis);
      if (xy.size() < 2) continue;
      double a, b, r2;
      linear_fit(xy, a, b, r2);
      const auto& lo = xy[xy.size() / 2 - (xy.size() > 2 ? 1 : 0)];
      const auto& hi = xy.back();
      growth[t][axis] = {{"fit_intercept_us", a}, {"fit_slope_us", b}, {"fit_r2", r2},
                         {"exponent_upper", exponent(lo.first, lo.second, hi.first, hi.second)}};
    }
  }
  out["growth_float"] = growth;
  // Goals of the issue, as measured.
  auto s2_us = [&](const char* t, const char* sc) {
    return s2.contains(t) && s2[t].contains(sc) ? s2[t][sc]["scan_us"].get<double>() : 0.0;
  };
  json goals;
  const double f = s2_us("mfbp-filter", "float"), ph = s2_us("gmphd", "float"), sm = s2_us("mfbp", "float");
  goals["mfbp_filter_s2_float_scan_us"] = {{"value", f}, {"goal", "< 100"}, {"met", f > 0 && f < 100.0}};
  goals["mfbp_filter_over_gmphd_s2_float"] = {
      {"value", ph > 0 ? f / ph : 0.0}, {"goal", "<= 2"}, {"met", ph > 0 && f / ph <= 2.0}};
  goals["smoother_over_filter_s2_float"] = {
      {"value", f > 0 ? sm / f : 0.0}, {"goal", "<= 5"}, {"met", f > 0 && sm / f <= 5.0}};
  goals["fft_worst_ratio_vs_fftw"] = {{"value", worst_ratio}, {"goal", "<= 1.5"}, {"met", worst_ratio > 0 && worst_ratio <= 1.5}};
  out["goals"] = goals;
  out["errors"] = errors;

  bool ok = true;
  {
    std::error_code ec;  // the build-tree default may not exist yet
    std::filesystem::create_directories(dir, ec);
    std::ofstream f_json(dir + "/results.json");
    f_json << out.dump(2) << "\n";
    ok = ok && static_cast<bool>(f_json);
    std::ofstream f_svg(dir + "/latency.svg");
    f_svg << svg_plot(grid, trackers);
    ok = ok && static_cast<bool>(f_svg);
  }

  // --- table ---
  std::printf("\n== FFT (float, single thread): ours vs FFTW ==\n%6s %12s %12s %8s\n", "N", "ours ns", "fftw ns",
              "ratio");
  for (const auto& kv : fft) {
    std::printf("%6d %12.1f %12.1f %8.2f\n", kv.first, kv.second.first, kv.second.second,
                kv.second.second > 0 ? kv.second.first / kv.second.second : 0.0);
  }
  std::printf("\n== Front end, full frame ==\n");
  for (auto it = frontend.begin(); it != frontend.end(); ++it) {
    std::printf("%-10s %10.1f us  (range %.1f, doppler %.1f, angle %.1f, detect %.1f; %g detections)\n",
                it.key().c_str(), it.value()["frame_us"].get<double>(), it.value()["range_us"].get<double>(),
                it.value()["doppler_us"].get<double>(), it.value()["angle_us"].get<double>(),
                it.value()["detect_us"].get<double>(), it.value()["detections"].get<double>());
  }
  if (!frontend_vs_fft.empty()) {
    std::printf("large, stage / its FFTs per frame, p50 (p90): range %.2f (%.2f), doppler %.2f (%.2f), angle %.2f (%.2f)\n",
                frontend_vs_fft["range_vs_fft_p50"].get<double>(), frontend_vs_fft["range_vs_fft_p90"].get<double>(),
                frontend_vs_fft["doppler_vs_fft_p50"].get<double>(), frontend_vs_fft["doppler_vs_fft_p90"].get<double>(),
                frontend_vs_fft["angle_vs_fft_p50"].get<double>(), frontend_vs_fft["angle_vs_fft_p90"].get<double>());
  }
  std::printf("\n== Seed 000 S2 (340 scans), per scan [us] ==\n%-12s %-7s %9s %9s %9s %9s\n", "tracker", "scalar",
              "mean", "p50", "p99", "max");
  for (auto it = s2.begin(); it != s2.end(); ++it) {
    for (auto jt = it.value().begin(); jt != it.value().end(); ++jt) {
      std::printf("%-12s %-7s %9.1f %9.1f %9.1f %9.1f\n", it.key().c_str(), jt.key().c_str(),
                  jt.value()["scan_us"].get<double>(), jt.value()["p50_us"].get<double>(),
                  jt.value()["p99_us"].get<double>(), jt.value()["max_us"].get<double>());
    }
  }
  std::printf("\n== Growth (float, linear fit us = a + b x; exponent over the upper half, 1 = linear) ==\n");
  for (auto it = growth.begin(); it != growth.end(); ++it) {
    for (auto jt = it.value().begin(); jt != it.value().end(); ++jt) {
      std::printf("%-12s %-20s slope %9.3f us/unit  R2 %.3f  exponent %.2f\n", it.key().c_str(), jt.key().c_str(),
                  jt.value()["fit_slope_us"].get<double>(), jt.value()["fit_r2"].get<double>(),
                  jt.value()["exponent_upper"].get<double>());
    }
  }
  std::printf("\n== Goals ==\n");
  for (auto it = goals.begin(); it != goals.end(); ++it) {
    std::printf("%-36s %10.3f  goal %-6s %s\n", it.key().c_str(), it.value()["value"].get<double>(),
                it.value()["goal"].get<std::string>().c_str(), it.value()["met"].get<bool>() ? "MET" : "not met");
  }
  if (!errors.empty()) std::printf("\n%zu benchmark(s) failed: see results.json errors\n", errors.size());
  std::printf("\nwrote %s/results.json and %s/latency.svg\n", dir.c_str(), dir.c_str());
  return ok;
}

}  // namespace mptrack::bench
