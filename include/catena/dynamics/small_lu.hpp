// A small dense matrix's LU factorisation with partial pivoting (Golub & Van Loan, Matrix
// Computations, §3.4), kept for repeated solves: the stick law's switch update (Integrator, the
// matrix I + Vᵀ W of up to four switched hinges; docs/models/dynamics.md, "Hinges: sticking") and
// the block pentadiagonal solver's closure (its 4×4 A_tl and capacitance).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>

namespace catena::dynamics {

struct SmallLu {
  static constexpr std::size_t kMax = 4;
  std::size_t size = 0;
  /// the matrix, then its factors: U on and above the diagonal, L's multipliers below it (row
  /// swap[c] exchanged with row c before column c's elimination, the multipliers with the rows)
  double lu[kMax][kMax] = {};
  std::size_t swap[kMax] = {};

  /// Factors lu's leading n × n block in place. `terms`: the largest row sum of the sizes of the
  /// terms each entry was summed from (≥ the entries' own: |I| + |V|ᵀ|W| for I + Vᵀ W), the scale
  /// of the entries' rounding. False where a pivot is not above floor × terms (the matrix is
  /// singular to that fraction of its terms, which its entries' rounding may be most of) or
  /// `terms` is not finite; the factors are then not to be used.
  bool factor(std::size_t n, double terms, double floor) {
    if (!std::isfinite(terms)) {
      size = n;
      return false;
    }
    return factor(n, [&](double pivot) { return std::abs(pivot) > floor * terms; });
  }

  /// Factors lu's leading n × n block in place; false (the factors not to be used) at the first
  /// pivot, the largest of its column's candidates, for which usable(pivot) is false.
  template <class Usable>
  bool factor(std::size_t n, Usable usable) {
    size = n;
    for (std::size_t c = 0; c < n; ++c) {
      std::size_t p = c;
      for (std::size_t k = c + 1; k < n; ++k)
        if (std::abs(lu[k][c]) > std::abs(lu[p][c])) p = k;
      if (!usable(lu[p][c])) return false;
      swap[c] = p;
      if (p != c) std::swap(lu[p], lu[c]);
      for (std::size_t k = c + 1; k < n; ++k) {
        const double f = lu[k][c] / lu[c][c];
        for (std::size_t e = c + 1; e < n; ++e) lu[k][e] -= f * lu[c][e];
        lu[k][c] = f;
      }
    }
    return true;
  }

  /// z ← A⁻¹ z with factor()'s factors: the row exchanges, L, then U (the arithmetic of the
  /// elimination of [A | z], z's column carried along)
  void solve(double* z) const {
    for (std::size_t c = 0; c < size; ++c) std::swap(z[c], z[swap[c]]);
    for (std::size_t c = 0; c < size; ++c) {
      for (std::size_t k = c + 1; k < size; ++k) z[k] -= lu[k][c] * z[c];
    }
    for (std::size_t c = size; c-- > 0;) {
      double e = z[c];
      for (std::size_t k = c + 1; k < size; ++k) e -= lu[c][k] * z[k];
      z[c] = e / lu[c][c];
    }
  }
};

}  // namespace catena::dynamics
