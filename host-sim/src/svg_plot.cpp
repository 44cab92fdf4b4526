#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "mptrack/math/detmath.h"

namespace mptrack::sim {

namespace {

constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b",
                                    "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#ff7f0e"};

std::string f1(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", x);
  return b;
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

struct Frame {  // maps data to a pixel box
  double x0, x1, y0, y1;        // data range
  double px, py, pw, ph;        // pixel box
  double sx(double x) const { return px + (x - x0) / (x1 - x0) * pw; }
  double sy(double y) const { return py + ph - (y - y0) / (y1 - y0) * ph; }
  double unit_m = 1.0;          // metres per data unit (x/y panel: 1 or 1000)
  double mx(double x_m) const { return sx(x_m / unit_m); }
  double my(double y_m) const { return sy(y_m / unit_m); }
};

/// Round tick values (1, 2 or 5 x 10^k apart, about `target` of them) in [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> out;
  if (!(hi > lo) || target < 1) return out;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / mag;
  const double step = (r < 1.5 ? 1.0 : r < 3.5 ? 2.0 : r < 7.5 ? 5.0 : 10.0) * mag;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) {
    out.push_back(std::fabs(v) < 1e-12 * step ? 0.0 : v);
  }
  return out;
}

/// A tick label with as few digits as the step needs.
std::string tick_text(double v, double step) {
  char b[32];
  const int digits = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

/// Tick marks and labels on the bottom and left edges of f's pixel box.
void draw_ticks(std::ostream& out, const Frame& f, bool x_axis, bool y_axis) {
  if (x_axis) {
    const std::vector<double> t = nice_ticks(f.x0, f.x1, 6);
    const double step = t.size() > 1 ? t[1] - t[0] : 1.0;
    for (double v : t) {
      const std::string x = f1(f.sx(v));
      out << "<line x1=\"" << x << "\" x2=\"" << x << "\" y1=\"" << f1(f.py + f.ph) << "\" y2=\""
          << f1(f.py + f.ph + 5) << "\" stroke=\"#888\"/>\n<text x=\"" << x << "\" y=\"" << f1(f.py + f.ph + 17)
          << "\" text-anchor=\"middle\">" << tick_text(v, step) << "</text>\n";
    }
  }
  if (y_axis) {
    const std::vector<double> t = nice_ticks(f.y0, f.y1, 6);
    const double step = t.size() > 1 ? t[1] - t[0] : 1.0;
    for (double v : t) {
      const std::string y = f1(f.sy(v));
      out << "<line x1=\"" << f1(f.px - 5) << "\" x2=\"" << f1(f.px) << "\" y1=\"" << y << "\" y2=\"" << y
          << "\" stroke=\"#888\"/>\n<text x=\"" << f1(f.px - 7) << "\" y=\"" << f1(f.sy(v) + 4)
          << "\" text-anchor=\"end\">" << tick_text(v, step) << "</text>\n";
    }
  }
}

void polar_to_xy(double r, double az, double& x, double& y) {
  double s = 0.0, c = 0.0;
  dmath::dsincos(az, s, c);
  x = r * c;
  y = r * s;
}

// 2-sigma contour of a polar Gaussian, mapped point by point to x/y.
std::string ellipse_path(const Frame& f, double mr, double ma, double crr, double cra, double caa) {
  const double l11 = std::sqrt(std::max(crr, 0.0));
  const double l21 = l11 > 0.0 ? cra / l11 : 0.0;
  const double l22 = std::sqrt(std::max(caa - l21 * l21, 0.0));
  std::ostringstream d;
  constexpr int kPoints = 48;
  for (int i = 0; i <= kPoints; ++i) {
    double s = 0.0, c = 0.0;
    dmath::dsincos(2.0 * scenario::kPi * i / kPoints, s, c);
    const double r = mr + 2.0 * l11 * c;
    const double a = ma + 2.0 * (l21 * c + l22 * s);
    double x = 0.0, y = 0.0;
    polar_to_xy(r, a, x, y);
    d << (i == 0 ? "M" : "L") << f1(f.mx(x)) << ',' << f1(f.my(y));
  }
  return d.str();
}

// 2-sigma contour of a Cartesian Gaussian [m], drawn in the panel's unit.
std::string xy_ellipse_path(const Frame& f, double mx, double my, double cxx, double cxy, double cyy) {
  const double l11 = std::sqrt(std::max(cxx, 0.0));
  const double l21 = l11 > 0.0 ? cxy / l11 : 0.0;
  const double l22 = std::sqrt(std::max(cyy - l21 * l21, 0.0));
  std::ostringstream d;
  constexpr int kPoints = 48;
  for (int i = 0; i <= kPoints; ++i) {
    double s = 0.0, c = 0.0;
    dmath::dsincos(2.0 * scenario::kPi * i / kPoints, s, c);
    const double x = mx + 2.0 * l11 * c;
    const double y = my + 2.0 * (l21 * c + l22 * s);
    d << (i == 0 ? "M" : "L") << f1(f.mx(x)) << ',' << f1(f.my(y));
  }
  return d.str();
}

}  // namespace

void write_plot_svg(const std::string& path, const scenario::ScenarioSpec& spec,
                    const std::vector<scenario::SimScan>& scans, const std::vector<EstimateOut>& estimates,
                    const std::vector<double>& ospa_per_scan, const std::string& title, double order_p,
                    double cutoff_m) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  constexpr double kW = 1200, kH = 560;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kW << "\" height=\"" << kH
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"20\" y=\"24\" font-size=\"15\">" << escape(title) << "</text>\n";

  // ---- left panel: x/y in km (m below a 2 km region), square aspect over the region's bounding box ----
  const scenario::Region& reg = spec.region;
  const double a0 = scenario::deg_to_rad(reg.azimuth_min_deg);
  const double a1 = scenario::deg_to_rad(reg.azimuth_max_deg);
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  std::vector<std::pair<double, double>> outline;
  const bool cartesian = spec.space == scenario::MeasurementSpace::kCartesian;
  if (cartesian) {  // seed 001: the x/y box
    const scenario::CartesianRegion& q = spec.xy_region;
    outline = {{q.x_min_m, q.y_min_m},
               {q.x_max_m, q.y_min_m},
               {q.x_max_m, q.y_max_m},
               {q.x_min_m, q.y_max_m}};
  }
  for (int i = 0; i <= 40 && !cartesian; ++i) {
    double x = 0.0, y = 0.0;
    polar_to_xy(reg.range_max_m, a0 + (a1 - a0) * i / 40.0, x, y);
    outline.emplace_back(x, y);
  }
  for (int i = 40; i >= 0 && !cartesian; --i) {
    double x = 0.0, y = 0.0;
    polar_to_xy(reg.range_min_m, a0 + (a1 - a0) * i / 40.0, x, y);
    outline.emplace_back(x, y);
  }
  // Outline in metres so far; the panel's unit follows the region's size.
  double ext = 0.0;
  for (const auto& p : outline) ext = std::max({ext, std::fabs(p.first), std::fabs(p.second)});
  const double unit_m = ext >= 2000.0 ? 1000.0 : 1.0;
  const char* unit = unit_m > 1.0 ? "km" : "m";
  for (auto& p : outline) {
    p.first /= unit_m;
    p.second /= unit_m;
  }
  for (const auto& p : outline) {
    xmin = std::min(xmin, p.first);
    xmax = std::max(xmax, p.first);
    ymin = std::min(ymin, p.second);
    ymax = std::max(ymax, p.second);
  }
  const double span = std::max(xmax - xmin, ymax - ymin) * 1.04;
  const double cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
  const Frame xy{cx - span / 2, cx + span / 2, cy - span / 2, cy + span / 2, 60, 50, 470, 470, unit_m};
  out << "<rect x=\"60\" y=\"50\" width=\"470\" height=\"470\" fill=\"none\" stroke=\"#888\"/>\n";
  out << "<path fill=\"#f4f4f4\" stroke=\"#aaa\" d=\"";
  for (std::size_t i = 0; i < outline.size(); ++i) {
    out << (i == 0 ? "M" : "L") << f1(xy.sx(outline[i].first)) << ',' << f1(xy.sy(outline[i].second));
  }
  out << "Z\"/>\n";
  draw_ticks(out, xy, true, true);
  out << "<text x=\"295\" y=\"552\" text-anchor=\"middle\">x [" << unit << "]</text>\n"
      << "<text x=\"14\" y=\"285\" transform=\"rotate(-90 14 285)\" text-anchor=\"middle\">y [" << unit
      << "]</text>\n";

  // True clutter components at mid-life (dashed grey).
  for (const scenario::ClutterSpec& c : spec.clutter) {
    if (c.uniform) continue;
    const std::uint32_t mid = (c.birth_scan + c.death_scan) / 2;
    const scenario::ClutterAtScan p = scenario::clutter_at_scan(spec, c, mid);
    out << "<path fill=\"none\" stroke=\"#555\" stroke-dasharray=\"5,3\" d=\""
        << (cartesian ? xy_ellipse_path(xy, p.mean_x_m, p.mean_y_m, p.cov_xx, p.cov_xy, p.cov_yy)
                      : ellipse_path(xy, p.mean_range_m, p.mean_azimuth_rad, p.cov_rr, p.cov_ra, p.cov_aa))
        << "\"/>\n";
  }
  // Estimated non-uniform clutter, every 10th scan (orange).
  for (const EstimateOut& e : estimates) {
    if (e.scan % 10 != 0) continue;
    for (const ClutterOut& c : e.clutter) {
      if (c.uniform) continue;
      // Cartesian filters report (x, y) [m] in the (range, azimuth) slots.
      out << "<path fill=\"none\" stroke=\"#ff7f0e\" stroke-opacity=\"0.6\" d=\""
          << (cartesian ? xy_ellipse_path(xy, c.mean_range_m, c.mean_azimuth_rad, c.cov_rr, c.cov_ra, c.cov_aa)
                        : ellipse_path(xy, c.mean_range_m, c.mean_azimuth_rad, c.cov_rr, c.cov_ra, c.cov_aa))
          << "\"/>\n";
    }
  }
  // Truth trajectories.
  std::map<std::uint32_t, std::string> truth_paths;
  for (const scenario::SimScan& s : scans) {
    for (const auto& t : s.truth) {
      std::string& d = truth_paths[t.target_id];
      d += (d.empty() ? "M" : "L") + f1(xy.mx(t.x.px)) + "," + f1(xy.my(t.x.py));
    }
  }
  for (const auto& [id, d] : truth_paths) {
    out << "<path fill=\"none\" stroke=\"black\" stroke-width=\"2\" d=\"" << d << "\"/>\n";
  }
  // Confirmed tracks: dots coloured by id.
  for (const EstimateOut& e : estimates) {
    for (const TrackOut& t : e.tracks) {
      if (!t.confirmed) continue;
      out << "<circle r=\"1.4\" fill=\"" << kPalette[t.id % 10] << "\" cx=\"" << f1(xy.mx(t.px))
          << "\" cy=\"" << f1(xy.my(t.py)) << "\"/>\n";
    }
  }
  // Two short lines: one line of 90 characters ran past the panel.
  out << "<text x=\"70\" y=\"56\">black: truth, dots: confirmed tracks (colour = id)</text>\n"
         "<text x=\"70\" y=\"70\">dashed: true clutter (2&#963;), orange: estimated clutter</text>\n";

  // ---- right panel: OSPA over time ----
  const double n = static_cast<double>(std::max<std::size_t>(ospa_per_scan.size(), 1));
  double omax = 1e-3;  // scale to the data (at most c), not to a fixed 100 m
  for (double v : ospa_per_scan) omax = std::max(omax, v);
  const Frame os{1.0, std::max(n, 2.0), 0.0, omax * 1.05, 640, 50, 520, 470};
  out << "<rect x=\"640\" y=\"50\" width=\"520\" height=\"470\" fill=\"none\" stroke=\"#888\"/>\n";
  out << "<rect x=\"" << f1(os.sx(spec.eval_first_scan)) << "\" y=\"50\" width=\""
      << f1(os.sx(spec.eval_last_scan) - os.sx(spec.eval_first_scan)) << "\" height=\"470\" fill=\"#e8f0ff\"/>\n";
  out << "<path fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\" d=\"";
  for (std::size_t i = 0; i < ospa_per_scan.size(); ++i) {
    out << (i == 0 ? "M" : "L") << f1(os.sx(static_cast<double>(i + 1))) << ',' << f1(os.sy(ospa_per_scan[i]));
  }
  out << "\"/>\n";
  draw_ticks(out, os, true, true);
  out << "<text x=\"900\" y=\"552\" text-anchor=\"middle\">scan; shaded: evaluation interval</text>\n"
      << "<text x=\"650\" y=\"68\">OSPA [m] (p = " << order_p << ", c = " << cutoff_m
      << " m, the run's metric), mean over runs</text>\n</svg>\n";
  if (!out) throw std::runtime_error(path + ": write failed");
}

void write_ospa_comparison_svg(const std::string& path, const std::string& title,
                               const std::vector<OspaSeries>& series, std::uint32_t eval_first_scan,
                               std::uint32_t eval_last_scan, double order_p, double cutoff_m) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  constexpr double kW = 1000, kH = 560;
  std::size_t scans = 1;
  double omax = 1.0;
  for (const OspaSeries& s : series) {
    scans = std::max(scans, s.ospa_per_scan.size());
    for (double v : s.ospa_per_scan) omax = std::max(omax, v);
  }
  const double top = std::min(omax * 1.05, cutoff_m * 1.05);  // OSPA never exceeds c
  const Frame os{1.0, std::max(static_cast<double>(scans), 2.0), 0.0, top, 70, 50, 680, 450};
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kW << "\" height=\"" << kH
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"20\" y=\"24\" font-size=\"15\">" << escape(title) << "</text>\n";
  out << "<rect x=\"" << f1(os.sx(eval_first_scan)) << "\" y=\"50\" width=\""
      << f1(os.sx(eval_last_scan) - os.sx(eval_first_scan)) << "\" height=\"450\" fill=\"#e8f0ff\"/>\n";
  out << "<rect x=\"70\" y=\"50\" width=\"680\" height=\"450\" fill=\"none\" stroke=\"#888\"/>\n";
  for (int i = 0; i <= 5; ++i) {
    const double v = top * i / 5.0;
    out << "<line x1=\"70\" x2=\"750\" y1=\"" << f1(os.sy(v)) << "\" y2=\"" << f1(os.sy(v))
        << "\" stroke=\"#ddd\"/>\n<text x=\"64\" y=\"" << f1(os.sy(v) + 4) << "\" text-anchor=\"end\">" << f1(v)
        << "</text>\n";
  }
  draw_ticks(out, os, true, false);
  for (std::size_t t = 0; t < series.size(); ++t) {
    const char* colour = kPalette[t % 10];
    const char* dash = t >= 10 ? " stroke-dasharray=\"6,3\"" : "";
    out << "<path fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.6\"" << dash << " d=\"";
    const std::vector<double>& v = series[t].ospa_per_scan;
    for (std::size_t i = 0; i < v.size(); ++i) {
      out << (i == 0 ? "M" : "L") << f1(os.sx(static_cast<double>(i + 1))) << ',' << f1(os.sy(v[i]));
    }
    out << "\"/>\n";
    const double ly = 66.0 + 18.0 * static_cast<double>(t);
    out << "<line x1=\"770\" x2=\"800\" y1=\"" << f1(ly) << "\" y2=\"" << f1(ly) << "\" stroke=\"" << colour
        << "\" stroke-width=\"2\"" << dash << "/>\n<text x=\"806\" y=\"" << f1(ly + 4) << "\">"
        << escape(series[t].name) << "</text>\n";
  }
  char axis[128];
  std::snprintf(axis, sizeof axis, "OSPA [m] (p = %g, c = %g m)", order_p, cutoff_m);
  out << "<text x=\"410\" y=\"540\" text-anchor=\"middle\">scan; shaded: evaluation interval</text>\n"
      << "<text x=\"18\" y=\"275\" transform=\"rotate(-90 18 275)\" text-anchor=\"middle\">" << axis
      << "</text>\n</svg>\n";
  if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace mptrack::sim
