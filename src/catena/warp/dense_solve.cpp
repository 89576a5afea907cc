// Dense linear solve shared by the warp's force and displacement methods.
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "internal.hpp"

namespace catena::warp::detail {

bool solve_dense(std::vector<double>& a, std::vector<double>& x, int n) {
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(a[static_cast<std::size_t>(r * n + c)]) >
          std::abs(a[static_cast<std::size_t>(p * n + c)]))
        p = r;
    if (!(std::abs(a[static_cast<std::size_t>(p * n + c)]) > 0)) return false;
    if (p != c) {
      for (int k = 0; k < n; ++k)
        std::swap(a[static_cast<std::size_t>(p * n + k)], a[static_cast<std::size_t>(c * n + k)]);
      std::swap(x[static_cast<std::size_t>(p)], x[static_cast<std::size_t>(c)]);
    }
    const double piv = a[static_cast<std::size_t>(c * n + c)];
    for (int r = c + 1; r < n; ++r) {
      const double f = a[static_cast<std::size_t>(r * n + c)] / piv;
      if (f == 0.0) continue;
      for (int k = c; k < n; ++k)
        a[static_cast<std::size_t>(r * n + k)] -= f * a[static_cast<std::size_t>(c * n + k)];
      x[static_cast<std::size_t>(r)] -= f * x[static_cast<std::size_t>(c)];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    double s = x[static_cast<std::size_t>(r)];
    for (int k = r + 1; k < n; ++k)
      s -= a[static_cast<std::size_t>(r * n + k)] * x[static_cast<std::size_t>(k)];
    x[static_cast<std::size_t>(r)] = s / a[static_cast<std::size_t>(r * n + r)];
  }
  return true;
}

}  // namespace catena::warp::detail
