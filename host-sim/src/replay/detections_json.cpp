// Detections JSON reader and writer; see detections_json.h.
#include "replay/detections_json.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "replay/detections_csv.h"

namespace mptrack::sim {

namespace {

using json = nlohmann::ordered_json;

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw std::runtime_error(path_ + ": " + where + ": " + what);
  }

  void check_keys(const json& v, const std::string& where, std::initializer_list<const char*> allowed) const {
    if (!v.is_object()) fail(where, "expected an object");
    for (auto it = v.begin(); it != v.end(); ++it) {
      bool known = false;
      for (const char* k : allowed) known = known || it.key() == k;
      if (!known) fail(where + "." + it.key(), "unknown field");
    }
  }

  double number(const json& obj, const std::string& where, const char* key) const {
    const auto it = obj.find(key);
    const std::string w = where + "." + key;
    if (it == obj.end()) fail(w, "missing");
    if (!it->is_number()) fail(w, "expected a number");
    const double v = it->get<double>();
    if (!std::isfinite(v)) fail(w, "expected a finite number");
    return v;
  }

  scenario::SimMeasurement detection(const json& d, const std::string& w, bool& doppler, bool first) const {
    check_keys(d, w, {"range_m", "azimuth_rad", "azimuth_deg", "amplitude", "doppler_mps"});
    scenario::SimMeasurement m;
    m.range_m = number(d, w, "range_m");
    if (!(m.range_m >= 0.0)) fail(w + ".range_m", "must be >= 0");
    const bool deg = d.contains("azimuth_deg");
    if (deg == d.contains("azimuth_rad")) fail(w, "expected exactly one of azimuth_rad and azimuth_deg");
    const double az = number(d, w, deg ? "azimuth_deg" : "azimuth_rad");
    if (deg ? std::fabs(az) > 180.0 : std::fabs(az) > 3.14159265358979323846) {
      fail(w + (deg ? ".azimuth_deg" : ".azimuth_rad"), "must be in [-180, 180] deg ([-pi, pi] rad)");
    }
    m.azimuth_rad = deg ? scenario::deg_to_rad(az) : az;
    m.amplitude = number(d, w, "amplitude");
    if (!(m.amplitude > 0.0)) fail(w + ".amplitude", "must be > 0");
    const bool has_doppler = d.contains("doppler_mps");
    if (first) doppler = has_doppler;
    if (has_doppler != doppler) fail(w, "doppler_mps must be given for every detection or for none");
    if (has_doppler) m.doppler_mps = number(d, w, "doppler_mps");
    m.origin.kind = scenario::OriginKind::kClutter;
    return m;
  }

  std::vector<scenario::SimScan> scans(const json& doc) const {
    check_keys(doc, "(document)", {"schema", "scans"});
    const auto schema = doc.find("schema");
    if (schema == doc.end() || !schema->is_string() || schema->get<std::string>() != kDetectionsJsonSchema) {
      fail("schema", std::string("expected \"") + kDetectionsJsonSchema + "\"");
    }
    const auto list = doc.find("scans");
    if (list == doc.end() || !list->is_array()) fail("scans", "expected an array of scans");
    std::vector<scenario::SimScan> out;
    bool doppler = false, first = true;
    for (std::size_t k = 0; k < list->size(); ++k) {
      const json& s = (*list)[k];
      const std::string w = "scans[" + std::to_string(k) + "]";
      check_keys(s, w, {"time_s", "detections"});
      const double t = number(s, w, "time_s");
      if (t < 0.0 || t > 1e9) fail(w + ".time_s", "must be in [0, 1e9] s");
      const auto time_us = static_cast<std::uint64_t>(std::llround(t * 1e6));
      if (!out.empty() && time_us < out.back().time_us) fail(w + ".time_s", "times must not decrease");
      if (out.empty() || time_us != out.back().time_us) {
        out.emplace_back();
        out.back().scan = static_cast<std::uint32_t>(out.size());
        out.back().time_us = time_us;
      }
      const auto dets = s.find("detections");
      if (dets == s.end() || !dets->is_array()) fail(w + ".detections", "expected an array (empty: no detections)");
      for (std::size_t i = 0; i < dets->size(); ++i) {
        out.back().measurements.push_back(
            detection((*dets)[i], w + ".detections[" + std::to_string(i) + "]", doppler, first));
        first = false;
      }
    }
    if (out.empty()) fail("scans", "no scans");
    for (auto& s : out) s.has_doppler = doppler;
    return out;
  }

 private:
  std::string path_;
};

}  // namespace

std::vector<scenario::SimScan> read_detections_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return Reader(path).scans(doc);
}

void write_detections_json(const std::string& path, const std::vector<scenario::SimScan>& scans) {
  bool doppler = false;
  for (const auto& s : scans) doppler = doppler || s.has_doppler;
  json list = json::array();
  for (const auto& s : scans) {
    json dets = json::array();
    for (const auto& m : s.measurements) {
      json d = {{"range_m", m.range_m}, {"azimuth_rad", m.azimuth_rad}, {"amplitude", m.amplitude}};
      if (doppler) d["doppler_mps"] = m.doppler_mps;
      dets.push_back(std::move(d));
    }
    // Microseconds as seconds: llround(t * 1e6) gives time_us back exactly.
    list.push_back({{"time_s", static_cast<double>(s.time_us) * 1e-6}, {"detections", std::move(dets)}});
  }
  const json doc = {{"schema", kDetectionsJsonSchema}, {"scans", std::move(list)}};
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot write");
  f << doc.dump(1) << "\n";  // nlohmann writes doubles as the shortest exact round trip
  if (!f) throw std::runtime_error(path + ": write failed");
}

std::vector<scenario::SimScan> read_detections_file(const std::string& path) {
  const bool is_json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  return is_json ? read_detections_json(path) : read_detections_csv(path);
}

}  // namespace mptrack::sim
