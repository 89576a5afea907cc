// Reading the `drive` analyses' records in the property tests (drive_property_test.cpp,
// drive_random_test.cpp): a field as a number, a number as text that reads back as the same
// double, and the tolerance of identities of the same numbers.
#pragma once

#include <cstdio>
#include <string>

#include "catena/catena.hpp"

namespace catena::drive::testing {

constexpr double kRelTol = 1e-12;  // [1] identities of the same numbers

inline double num(const analysis::Value& v, const char* key) { return v.at(key).as_number(); }

// A number as text that reads back as the same double.
inline std::string exact(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

}  // namespace catena::drive::testing
