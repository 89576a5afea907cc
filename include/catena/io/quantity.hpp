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
#include "catena/core/quantity_kind.hpp"

namespace catena::io {

/// The kind of a value (core/quantity_kind.hpp), here for the parser's callers.
using QuantityKind = catena::QuantityKind;

/// The SI unit the library uses for `kind` ("m", "rad", "rad/s", "N", "Pa", "kg", "s", "m/s",
/// "N/m", "m^2", "kg/m^3").
const char* si_unit(QuantityKind kind);
/// The unit a bare number is taken in ("mm", "degree", "1/s", "N", "MPa", "kg", "s", "m/s",
/// "N/m", "mm^2", "kg/m^3").
const char* default_unit(QuantityKind kind);
/// A short human description used in messages, e.g. "a length".
const char* describe(QuantityKind kind);

/// Parses `text` as a quantity of `kind` and returns its value in SI units. On failure appends an
/// Issue naming `field`, the text and what was expected, and returns nothing. Non-finite values
/// are rejected here; ranges are checked by the caller.
std::optional<double> parse_quantity(std::string_view text, QuantityKind kind,
                                     std::string_view field, std::vector<Issue>& issues);

/// A plain real number ("0.3", "-1.5e3"): nothing else in the text, finite. On failure appends
/// Issue{field, "'text'", expected}. The only number parser besides parse_quantity.
std::optional<double> parse_number(std::string_view text, std::string_view field,
                                   std::string_view expected, std::vector<Issue>& issues);

/// True when `text` is a number with nothing after it but blanks ("20", " 1.5e3 "): a bare number.
bool is_bare_number(std::string_view text);

/// A whole number in [min, 10⁹]. On failure appends Issue{field, "'text'", "a whole number ≥ min"}.
std::optional<long> parse_integer(std::string_view text, std::string_view field, long min,
                                  std::vector<Issue>& issues);

/// As above, but throws InputError.
double parse_quantity(std::string_view text, QuantityKind kind, std::string_view field);

}  // namespace catena::io
