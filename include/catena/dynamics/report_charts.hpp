// The report's charts for the `dynamics` command (issue 21): the time series, the span-tension
// spectrum with the tooth-mesh frequency and its harmonics marked, and an animation of the loop
// (Plotly frames with a slider). Charts only: none of this is in the command's JSON or CSV.
//
// Size bounds (a report must stay small): every curve of a time series at most kMaxChartPoints
// points (min/max per bucket, so that peaks survive); the spectrum up to kSpectrumHarmonics + ½
// tooth-mesh harmonics; the animation at most kMaxFrames frames and kMaxFramePoints points over
// all of them (chain nodes and both sprocket outlines).
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "catena/analysis/record.hpp"
#include "catena/dynamics/chain.hpp"

namespace catena::dynamics {

inline constexpr std::size_t kMaxChartPoints = 2000;
inline constexpr std::size_t kMaxFrames = 60;
inline constexpr std::size_t kMaxFramePoints = 24000;
inline constexpr int kSpectrumHarmonics = 6;

/// A named series sampled at the report input's `time`.
struct ChartSeries {
  std::string name;
  std::vector<double> values;
};

/// The loop at one instant: node positions [m], each wheel's angle [rad] and, when given, each
/// wheel's centre [m] (a take-up's moves with its slide; empty: the outline's own centre).
struct LoopFrame {
  double time = 0.0;
  std::vector<double> x, y, angle;
  std::vector<double> centre_x, centre_y;
};

/// A sprocket's outline about its centre at angle 0 [m] (drive::tooth_outline), and its centre.
struct WheelOutline {
  std::string name;  ///< the legend's ("sprocket 0 (driver)")
  double centre_x = 0.0, centre_y = 0.0;
  std::vector<std::pair<double, double>> outline;
};

struct ReportInput {
  std::vector<double> time;                      ///< [s], uniform after the first sample
  std::vector<ChartSeries> speed, torque, span;  ///< [rad/s], [N m], [N]
  int teeth = 0;                                 ///< z of the driver
  double driver_speed = 0.0;                     ///< ω [rad/s]: tooth mesh at z ω / 2π
  /// [s] the spectrum's window starts at the first sample at or after this time (NaN: the
  /// second half of the run, from sample n/2)
  double spectrum_start = std::numeric_limits<double>::quiet_NaN();
  /// more labelled frequencies for the spectrum (the spans' natural frequencies), drawn after
  /// the mesh harmonics when below the spectrum's top frequency
  std::vector<analysis::Marker> span_markers;
  std::vector<WheelOutline> wheels;
  /// [m] each guide's rail surface as a polyline (guide_polyline): drawn, fixed, in every frame
  std::vector<std::vector<std::pair<double, double>>> guides;
  std::vector<LoopFrame> frames;
};

/// A guide's rail surface as a polyline [m]: a straight rail's two ends, an arc at most 5° a
/// segment (at least 2 segments).
std::vector<std::pair<double, double>> guide_polyline(const Guide& g);

/// The outline of an ISO 606 sprocket (minimum tooth-gap form, 3 points an arc), about its
/// centre, seat 0 on +x: what the animation draws.
std::vector<std::pair<double, double>> sprocket_outline(double pitch, double roller_diameter,
                                                        double inner_width, int teeth);

/// How many frames the animation of a loop of `nodes` nodes over wheels with `outline_points`
/// points in all may have: kMaxFramePoints / (nodes + 1 + outline_points + wheels), within
/// [2, kMaxFrames].
std::size_t frame_count(std::size_t nodes, std::size_t outline_points);

/// y(t) with at most `max_points` points: all of them when they fit, else the minimum and the
/// maximum of each of max_points/2 equal buckets, in time order.
analysis::Trace decimated(const std::string& name, const std::vector<double>& t,
                          const std::vector<double>& y, std::size_t max_points = kMaxChartPoints);

/// The tooth-mesh frequency z ω / 2π [Hz] and its harmonics below f_max, as labelled markers.
std::vector<analysis::Marker> mesh_markers(int teeth, double omega, double f_max);

/// The charts: speeds, torques and span tensions versus time; the span-tension spectrum over
/// the second half of the run (the first half is taken as the start-up transient) or from
/// `spectrum_start`; the animation, when there are frames.
std::vector<analysis::Chart> report_charts(const ReportInput& in);

}  // namespace catena::dynamics
