#include "catena/dynamics/report_charts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "catena/drive/sprocket.hpp"
#include "catena/dynamics/spectrum.hpp"

namespace catena::dynamics {

std::vector<std::pair<double, double>> sprocket_outline(double pitch, double roller_diameter,
                                                        double inner_width, int teeth) {
  const drive::Sprocket s = drive::sprocket({.pitch = pitch,
                                             .roller_diameter = roller_diameter,
                                             .inner_width = inner_width,
                                             .teeth = teeth});
  return drive::tooth_outline(s, s.min_gap, 3);
}

std::vector<std::pair<double, double>> guide_polyline(const Guide& g) {
  if (g.kind == Guide::Kind::kStraight) return {{g.x0, g.y0}, {g.x1, g.y1}};
  const double sweep = g.end_angle - g.start_angle;
  const int segments =
      std::max(2, static_cast<int>(std::ceil(std::abs(sweep) / (5.0 * std::numbers::pi / 180.0))));
  std::vector<std::pair<double, double>> line;
  for (int k = 0; k <= segments; ++k) {
    const double a = g.start_angle + sweep * k / segments;
    line.emplace_back(g.centre_x + g.radius * std::cos(a), g.centre_y + g.radius * std::sin(a));
  }
  return line;
}

std::size_t frame_count(std::size_t nodes, std::size_t outline_points) {
  const std::size_t per_frame = nodes + 1 + outline_points;
  return std::clamp<std::size_t>(kMaxFramePoints / std::max<std::size_t>(per_frame, 1), 2,
                                 kMaxFrames);
}

analysis::Trace decimated(const std::string& name, const std::vector<double>& t,
                          const std::vector<double>& y, std::size_t max_points) {
  analysis::Trace out{name, {}, {}};
  const std::size_t n = std::min(t.size(), y.size());
  if (n <= max_points || max_points < 2) {
    out.x.assign(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n));
    out.y.assign(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n));
    return out;
  }
  const std::size_t buckets = max_points / 2;
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t from = b * n / buckets, to = (b + 1) * n / buckets;  // [from, to)
    std::size_t lo = from, hi = from;
    for (std::size_t k = from; k < to; ++k) {
      if (y[k] < y[lo]) lo = k;
      if (y[k] > y[hi]) hi = k;
    }
    for (const std::size_t k : {std::min(lo, hi), std::max(lo, hi)}) {
      out.x.push_back(t[k]);
      out.y.push_back(y[k]);
    }
  }
  return out;
}

std::vector<analysis::Marker> mesh_markers(int teeth, double omega, double f_max) {
  std::vector<analysis::Marker> out;
  const double f = teeth * omega / (2.0 * std::numbers::pi);
  if (!(f > 0.0) || !std::isfinite(f)) return out;
  char text[96];
  for (int k = 1; k <= kSpectrumHarmonics && k * f <= f_max; ++k) {
    if (k == 1)
      std::snprintf(text, sizeof text, "tooth mesh z\xCF\x89/2\xCF\x80 = %.4g Hz", f);
    else
      std::snprintf(text, sizeof text, "%d\xC3\x97 mesh %.4g Hz", k, k * f);
    out.push_back({k * f, text});
  }
  return out;
}

namespace {

analysis::Chart series(const std::string& title, const std::string& y_label,
                       const std::vector<double>& t, const std::vector<ChartSeries>& list) {
  analysis::Chart c;
  c.title = title;
  c.x_label = "time t [s]";
  c.y_label = y_label;
  for (const ChartSeries& s : list) c.traces.push_back(decimated(s.name, t, s.values));
  return c;
}

// Coordinates in mm, rounded to 1 µm: the report's JSON stays short.
double mm(double metres) { return std::round(metres * 1e6) / 1e3; }

}  // namespace

std::vector<analysis::Chart> report_charts(const ReportInput& in) {
  std::vector<analysis::Chart> charts;
  charts.push_back(series("Sprocket speeds", "speed \xCF\x89 [rad/s]", in.time, in.speed));
  charts.push_back(series("Chain torque on the sprockets", "torque [N m]", in.time, in.torque));
  charts.push_back(series("Span tensions (the link nearest each span's middle)", "tension [N]",
                          in.time, in.span));

  // the spectrum of the second half of the run, or from spectrum_start (at least 16 samples)
  const std::size_t n = in.time.size();
  std::size_t from = n / 2;
  if (!std::isnan(in.spectrum_start)) {
    from = 0;
    // (a sample's time is a sum of steps: within rounding of the start counts as at it)
    const double tol = 1e-9 * std::abs(in.spectrum_start) + 1e-12;
    while (from < n && in.time[from] < in.spectrum_start - tol) ++from;
  }
  if (n >= 16 && (std::isnan(in.spectrum_start) || from + 16 <= n)) {
    const double dt = (in.time[n - 1] - in.time[from]) / static_cast<double>(n - 1 - from);
    const double f_mesh = in.teeth * in.driver_speed / (2.0 * std::numbers::pi);
    const double nyquist = 0.5 / dt;
    // up to just past the last marked harmonic, or the whole band when the mesh is above it
    const double f_max = f_mesh > 0.0 && (kSpectrumHarmonics + 0.5) * f_mesh < nyquist
                             ? (kSpectrumHarmonics + 0.5) * f_mesh
                             : nyquist;
    analysis::Chart c;
    c.title = "Span-tension spectrum (Hann window, t \xE2\x89\xA5 " +
              analysis::format_g(in.time[from], 4) + " s)";
    c.x_label = "frequency f [Hz]";
    c.y_label = "tension amplitude [N]";
    for (const ChartSeries& s : in.span) {
      const std::vector<double> tail(s.values.begin() + static_cast<std::ptrdiff_t>(from),
                                     s.values.end());
      const Spectrum sp = amplitude_spectrum(tail, dt);
      analysis::Trace t{s.name, {}, {}};
      for (std::size_t m = 0; m < sp.frequency.size() && sp.frequency[m] <= f_max; ++m) {
        t.x.push_back(sp.frequency[m]);
        t.y.push_back(sp.amplitude[m]);
      }
      // the band is bounded by the harmonics, but a coarse grid could still be long
      c.traces.push_back(decimated(t.name, t.x, t.y));
    }
    c.markers = mesh_markers(in.teeth, in.driver_speed, f_max);
    for (const analysis::Marker& m : in.span_markers)
      if (m.x > 0.0 && m.x <= f_max) c.markers.push_back(m);
    charts.push_back(std::move(c));
  }

  // the animation: the chain's nodes and the wheels' outlines, turned to their angles
  if (!in.frames.empty()) {
    auto frame_traces = [&](const LoopFrame& f) {
      std::vector<analysis::Trace> traces;
      for (std::size_t w = 0; w < in.wheels.size(); ++w) {
        const WheelOutline& o = in.wheels[w];
        const double a = w < f.angle.size() ? f.angle[w] : 0.0;
        const double c = std::cos(a), s = std::sin(a);
        const double ox = w < f.centre_x.size() ? f.centre_x[w] : o.centre_x;
        const double oy = w < f.centre_y.size() ? f.centre_y[w] : o.centre_y;
        analysis::Trace t{o.name, {}, {}};
        for (const auto& [x, y] : o.outline) {
          t.x.push_back(mm(ox + c * x - s * y));
          t.y.push_back(mm(oy + s * x + c * y));
        }
        if (!o.outline.empty()) {  // closed
          t.x.push_back(t.x.front());
          t.y.push_back(t.y.front());
        }
        traces.push_back(std::move(t));
      }
      for (std::size_t g = 0; g < in.guides.size(); ++g) {
        analysis::Trace t{"guide " + std::to_string(g + 1), {}, {}};
        for (const auto& [x, y] : in.guides[g]) {
          t.x.push_back(mm(x));
          t.y.push_back(mm(y));
        }
        traces.push_back(std::move(t));
      }
      analysis::Trace chain{"chain (roller centres)", {}, {}};
      for (std::size_t i = 0; i < f.x.size(); ++i) {
        chain.x.push_back(mm(f.x[i]));
        chain.y.push_back(mm(f.y[i]));
      }
      if (!f.x.empty()) {  // the loop closes
        chain.x.push_back(chain.x.front());
        chain.y.push_back(chain.y.front());
      }
      traces.push_back(std::move(chain));
      return traces;
    };
    analysis::Chart c;
    c.title = "The loop in motion (" + std::to_string(in.frames.size()) + " frames)";
    c.x_label = "x [mm]";
    c.y_label = "y [mm]";
    c.equal_axes = true;
    c.traces = frame_traces(in.frames.front());
    for (const LoopFrame& f : in.frames)
      c.frames.push_back({"t = " + analysis::format_g(f.time, 4) + " s", frame_traces(f)});
    charts.push_back(std::move(c));
  }
  return charts;
}

}  // namespace catena::dynamics
