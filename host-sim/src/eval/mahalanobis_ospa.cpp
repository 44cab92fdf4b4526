// Mahalanobis-distance OSPA; see mahalanobis_ospa.h.
#include "eval/mahalanobis_ospa.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mptrack::sim {

MahalanobisOspaParams mahalanobis_ospa_params(const scenario::ScenarioSpec& spec) {
  MahalanobisOspaParams p;
  p.sigma_range_m = spec.space == scenario::MeasurementSpace::kCartesian ? spec.sigma_xy_m : spec.sigma_range_m;
  p.sigma_range_rate_mps = spec.othr.sigma_range_rate_mps;
  return p;
}

void range_and_rate(double px, double vx, double py, double vy, double& range_m, double& range_rate_mps) {
  range_m = std::hypot(px, py);
  range_rate_mps = range_m > 0.0 ? (px * vx + py * vy) / range_m : 0.0;
}

MahalanobisOspa::MahalanobisOspa(const MahalanobisOspaParams& params)
    : params_(params), ospa_(std::make_unique<OspaMetric<double, 256>>()) {
  const bool sigmas_ok = std::isfinite(params.sigma_range_m) && params.sigma_range_m > 0.0 &&
                         std::isfinite(params.sigma_range_rate_mps) && params.sigma_range_rate_mps > 0.0;
  if (!sigmas_ok) throw std::runtime_error("Mahalanobis OSPA: the base standard deviations must be positive");
  if (ospa_->init(MetricParams<double>{params.order, params.cutoff}) != Status::kOk) {
    throw std::runtime_error("Mahalanobis OSPA parameters rejected (need p >= 1, c > 0)");
  }
}

double MahalanobisOspa::evaluate(const scenario::SimScan& scan, const EstimateOut& est) {
  using Point = Eigen::Matrix<double, 2, 1>;
  const auto whiten = [this](double px, double vx, double py, double vy) {
    double r = 0.0, rdot = 0.0;
    range_and_rate(px, vx, py, vy, r, rdot);
    return Point(r / params_.sigma_range_m, rdot / params_.sigma_range_rate_mps);
  };
  std::vector<Point> truths, tracks;
  for (const scenario::TruthState& t : scan.truth) truths.push_back(whiten(t.x.px, t.x.vx, t.x.py, t.x.vy));
  for (const TrackOut& t : est.tracks) {
    if (t.confirmed) tracks.push_back(whiten(t.px, t.vx, t.py, t.vy));
  }
  if (truths.size() > 256 || tracks.size() > 256) {
    throw std::runtime_error("scan " + std::to_string(scan.scan) + ": more than 256 truths or tracks (MOSPA)");
  }
  OspaResult<double> o;
  if (ospa_->compute(truths.data(), truths.size(), tracks.data(), tracks.size(), o) != Status::kOk) {
    throw std::runtime_error("scan " + std::to_string(scan.scan) + ": Mahalanobis OSPA failed (non-finite state?)");
  }
  return o.total;
}

}  // namespace mptrack::sim
