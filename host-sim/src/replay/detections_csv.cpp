// Detections CSV reader and writer; see detections_csv.h.
#include "replay/detections_csv.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace mptrack::sim {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') {
      out.emplace_back();
    } else if (c != '\r') {
      out.back() += c;
    }
  }
  return out;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

/// Column layout from the header.
struct Layout {
  bool degrees = false;
  bool doppler = false;
  std::vector<std::string> names;
};

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& what) {
  throw std::runtime_error(path + ":" + std::to_string(line) + ": " + what);
}

Layout parse_header(const std::string& path, const std::string& line) {
  Layout l;
  l.names = split(line);
  for (auto& n : l.names) n = trim(n);
  const std::size_t n = l.names.size();
  if (n < 4 || n > 5 || l.names[0] != "time_s" || l.names[1] != "range_m" ||
      (l.names[2] != "azimuth_rad" && l.names[2] != "azimuth_deg") || l.names[3] != "amplitude" ||
      (n == 5 && l.names[4] != "doppler_mps")) {
    fail(path, 1,
         "expected the header time_s,range_m,azimuth_rad|azimuth_deg,amplitude[,doppler_mps], got '" + line + "'");
  }
  l.degrees = l.names[2] == "azimuth_deg";
  l.doppler = n == 5;
  return l;
}

double field(const std::string& path, std::size_t line, const Layout& l, const std::vector<std::string>& f,
             std::size_t col) {
  const std::string t = trim(f[col]);
  const std::string where = "column " + std::to_string(col + 1) + " (" + l.names[col] + ")";
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || end == nullptr || *end != '\0') fail(path, line, where + ": '" + t + "' is not a number");
  if (!std::isfinite(v)) fail(path, line, where + ": '" + t + "' is not finite");
  return v;
}

}  // namespace

std::vector<scenario::SimScan> read_detections_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::string text;
  if (!std::getline(in, text)) throw std::runtime_error(path + ":1: empty file, expected a header row");
  const Layout l = parse_header(path, text);
  std::vector<scenario::SimScan> scans;
  std::size_t line = 1;
  while (std::getline(in, text)) {
    ++line;
    if (trim(text).empty()) continue;
    const std::vector<std::string> f = split(text);
    if (f.size() != l.names.size()) {
      fail(path, line, "expected " + std::to_string(l.names.size()) + " columns, got " + std::to_string(f.size()));
    }
    const double t = field(path, line, l, f, 0);
    if (t < 0.0 || t > 1e9) fail(path, line, "column 1 (time_s): " + text.substr(0, 40) + " must be in [0, 1e9] s");
    const auto time_us = static_cast<std::uint64_t>(std::llround(t * 1e6));
    if (!scans.empty() && time_us < scans.back().time_us) {
      fail(path, line, "column 1 (time_s): times must not decrease (previous scan at " +
                           std::to_string(static_cast<double>(scans.back().time_us) * 1e-6) + " s)");
    }
    if (scans.empty() || time_us != scans.back().time_us) {
      scans.emplace_back();
      scans.back().scan = static_cast<std::uint32_t>(scans.size());
      scans.back().time_us = time_us;
      scans.back().has_doppler = l.doppler;
    }
    bool all_empty = true;
    for (std::size_t c = 1; c < f.size(); ++c) all_empty = all_empty && trim(f[c]).empty();
    if (all_empty) continue;  // a scan without detections
    scenario::SimMeasurement m;
    m.range_m = field(path, line, l, f, 1);
    const double az = field(path, line, l, f, 2);
    m.amplitude = field(path, line, l, f, 3);
    if (l.doppler) m.doppler_mps = field(path, line, l, f, 4);
    if (!(m.range_m >= 0.0)) fail(path, line, "column 2 (range_m): must be >= 0");
    if (l.degrees ? std::fabs(az) > 180.0 : std::fabs(az) > 3.14159265358979323846) {
      fail(path, line, "column 3 (" + l.names[2] + "): must be in [-180, 180] deg ([-pi, pi] rad)");
    }
    m.azimuth_rad = l.degrees ? scenario::deg_to_rad(az) : az;
    if (!(m.amplitude > 0.0)) fail(path, line, "column 4 (amplitude): must be > 0");
    m.origin.kind = scenario::OriginKind::kClutter;
    scans.back().measurements.push_back(m);
  }
  if (scans.empty()) throw std::runtime_error(path + ": no detections (only a header)");
  return scans;
}

std::string detections_csv_header(bool doppler) {
  return doppler ? "time_s,range_m,azimuth_rad,amplitude,doppler_mps" : "time_s,range_m,azimuth_rad,amplitude";
}

void write_detections_csv(const std::string& path, const std::vector<scenario::SimScan>& scans) {
  bool doppler = false;
  for (const auto& s : scans) doppler = doppler || s.has_doppler;
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw std::runtime_error(path + ": cannot write");
  std::fprintf(f, "%s\n", detections_csv_header(doppler).c_str());
  for (const auto& s : scans) {
    // Microseconds as seconds: llround(t * 1e6) gives time_us back exactly.
    const double t = static_cast<double>(s.time_us) * 1e-6;
    if (s.measurements.empty()) std::fprintf(f, doppler ? "%.17g,,,,\n" : "%.17g,,,\n", t);
    for (const auto& m : s.measurements) {
      std::fprintf(f, "%.17g,%.17g,%.17g,%.17g", t, m.range_m, m.azimuth_rad, m.amplitude);
      if (doppler) std::fprintf(f, ",%.17g", m.doppler_mps);
      std::fputc('\n', f);
    }
  }
  if (std::fclose(f) != 0) throw std::runtime_error(path + ": write failed");
}

}  // namespace mptrack::sim
