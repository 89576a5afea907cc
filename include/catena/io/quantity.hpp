// Unit-tagged quantities at the I/O boundary, parsed with UDUNITS-2.
//
// "64mm", "64 mm", "0.064m", "5 1/s", "47.75 rpm", "20deg", "0°42'", "29.4kN", "210GPa" all parse;
// a bare number takes the kind's default unit (mm, 1/s, N, MPa, degree, kg, s, m/s, N/m). The
// result is SI.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::io {

/// What a value measures; decides the accepted units and the default unit of a bare number.
enum class QuantityKind {
  kLength,          ///< SI m; bare number: mm
  kAngle,           ///< SI rad; bare number: degree
  kAngularSpeed,    ///< SI rad/s; bare number: 1/s (= rad/s); rpm accepted, Hz rejected
  kForce,           ///< SI N; bare number: N
  kStress,          ///< SI Pa; bare number: MPa
  kMass,            ///< SI kg; bare number: kg
  kTime,            ///< SI s; bare number: s
  kFrequency,       ///< SI 1/s (cycles per second); bare number: Hz
  kSpeed,           ///< SI m/s; bare number: m/s
  kForcePerLength,  ///< SI N/m (a weight per metre of a conveyor run); bare number: N/m;
                    ///< a mass per metre (kg/m) is rejected with a hint to write kgf/m
};

/// The SI unit the library uses for `kind` ("m", "rad", "rad/s", "N", "Pa", "kg", "s", "m/s",
/// "N/m").
const char* si_unit(QuantityKind kind);
/// The unit a bare number is taken in ("mm", "degree", "1/s", "N", "MPa", "kg", "s", "m/s",
/// "N/m").
const char* default_unit(QuantityKind kind);
/// A short human description used in messages, e.g. "a length".
const char* describe(QuantityKind kind);

/// Parses `text` as a quantity of `kind` and returns its value in SI units. On failure appends an
/// Issue naming `field`, the text and what was expected, and returns nothing. Non-finite values
/// are rejected here; ranges are checked by the caller.
std::optional<double> parse_quantity(std::string_view text, QuantityKind kind,
                                     std::string_view field, std::vector<Issue>& issues);

/// As above, but throws InputError.
double parse_quantity(std::string_view text, QuantityKind kind, std::string_view field);

}  // namespace catena::io
