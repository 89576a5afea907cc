// Mean of a sampled series over the whole tooth periods after t0: the steady mean the dynamics
// validations and the command's tests compare with closed forms (a partial period would bias it
// by the polygonal action's ripple).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

// Mean of `series` (sampled at `time`) over the samples in (t0, t1].
inline double mean_between(const std::vector<double>& time, const std::vector<double>& series,
                           double t0, double t1) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] > t0 && time[k] <= t1) {
      sum += series[k];
      ++count;
    }
  }
  EXPECT_GT(count, 0);
  return sum / count;
}

// Mean of `series` (sampled at `time`) over the whole periods in (t0, t_end].
inline double mean_over_periods(const std::vector<double>& time, const std::vector<double>& series,
                                double t0, double period) {
  const double whole = std::floor((time.back() - t0) / period) * period;
  return mean_between(time, series, t0, t0 + whole);
}
