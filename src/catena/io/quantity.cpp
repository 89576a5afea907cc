#include "catena/io/quantity.hpp"

#include <udunits2.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <regex>
#include <shared_mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace catena::io {
namespace {

struct UnitDeleter {
  void operator()(ut_unit* unit) const { ut_free(unit); }
};
using UnitPtr = std::unique_ptr<ut_unit, UnitDeleter>;

// The unit system is loaded once and never freed; UDUNITS-2 is not thread-safe, so every use
// of it goes through this mutex.
struct UnitSystem {
  ut_system* system = nullptr;
  std::mutex mutex;

  UnitSystem() {
    ut_set_error_message_handler(ut_ignore);  // the database's duplicate-name notes are noise
    system = ut_read_xml(nullptr);
    if (system == nullptr) {
      throw std::runtime_error(
          "UDUNITS-2 could not load its unit database (is the udunits2 data package installed? "
          "UDUNITS2_XML_PATH may point to udunits2.xml)");
    }
    // Spellings UDUNITS-2 lacks: "deg" for degree and "rev" for revolution.
    UnitPtr degree(ut_parse(system, "degree", UT_UTF8));
    UnitPtr revolution(ut_parse(system, "revolution", UT_UTF8));
    ut_map_symbol_to_unit("deg", UT_UTF8, degree.get());
    ut_map_symbol_to_unit("rev", UT_UTF8, revolution.get());
  }
};

UnitSystem& units() {
  static UnitSystem instance;
  return instance;
}

std::string trim(std::string_view text) {
  std::size_t begin = 0;
  std::size_t end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return std::string(text.substr(begin, end - begin));
}

// A bare number ("64", "-1.5e3") with nothing after it.
std::optional<double> bare_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return std::nullopt;
  return value;
}

// Degrees-minutes-seconds such as 0°42', 3°26′, 1°30'15" (the form papers print skews in).
std::optional<double> dms_degrees(const std::string& text) {
  static const std::regex pattern(
      R"(^([+-]?)(\d+(?:\.\d+)?)\s*°\s*(?:(\d+(?:\.\d+)?)\s*(?:'|′))?\s*(?:(\d+(?:\.\d+)?)\s*(?:"|″))?$)");
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) return std::nullopt;
  if (!match[3].matched && !match[4].matched) return std::nullopt;  // plain "20°": UDUNITS does it
  // strtod, not std::stod: a part of 400 digits overflows to inf (refused by the caller as not
  // finite) or underflows to 0, where std::stod would throw out_of_range (found by fuzzing).
  auto part = [&match](int i) { return std::strtod(match[i].str().c_str(), nullptr); };
  double degrees = part(2);
  if (match[3].matched) degrees += part(3) / 60.0;
  if (match[4].matched) degrees += part(4) / 3600.0;
  return match[1].str() == "-" ? -degrees : degrees;
}

bool mentions_hertz(const std::string& text) {
  return text.find("Hz") != std::string::npos || text.find("hertz") != std::string::npos;
}

const char* accepted_spellings(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kLength:
      return "a length, e.g. 64mm, 64 mm, 0.064m, 2.5in (bare number: mm)";
    case QuantityKind::kAngle:
      return "an angle, e.g. 20deg, 20 degree, 20°, 0°42', 42 arcmin, 0.35 rad (bare number: "
             "degree)";
    case QuantityKind::kAngularSpeed:
      return "an angular speed, e.g. 5 1/s, 5 rad/s, 47.75 rpm (bare number: 1/s = rad/s; Hz is "
             "ambiguous and rejected)";
    case QuantityKind::kForce:
      return "a force, e.g. 29.4kN, 1200 N (bare number: N)";
    case QuantityKind::kStress:
      return "a stress, e.g. 350MPa, 210 GPa (bare number: MPa)";
    case QuantityKind::kMass:
      return "a mass, e.g. 40kg, 500 g (bare number: kg)";
    case QuantityKind::kTime:
      return "a time, e.g. 2 s, 5 min (bare number: s)";
    case QuantityKind::kFrequency:
      return "a frequency in cycles per second, e.g. 20 Hz, 1200 1/min (bare number: Hz)";
    case QuantityKind::kSpeed:
      return "a speed, e.g. 0.5 m/s, 30 m/min (bare number: m/s)";
    case QuantityKind::kForcePerLength:
      return "a weight (force) per length, e.g. 150 N/m, 0.15 kN/m, 15 kgf/m (bare number: N/m)";
    case QuantityKind::kArea:
      return "an area, e.g. 22.7mm^2, 22.7 mm2, 0.227 cm^2 (bare number: mm^2)";
    case QuantityKind::kDensity:
      return "a density, e.g. 2.56g/cm^3, 1200 kg/m^3 (bare number: kg/m^3)";
    case QuantityKind::kPower:
      return "a power, e.g. 7.5kW, 750 W, 10 hp (bare number: kW)";
    case QuantityKind::kMassPerLength:
      return "a mass per length, e.g. 1.25 kg/m, 1250 g/m (bare number: kg/m)";
  }
  return "a quantity";
}

// SI target unit as UDUNITS-2 spells it.
const char* target_spelling(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kLength:
      return "m";
    case QuantityKind::kAngle:
      return "radian";
    case QuantityKind::kAngularSpeed:
      return "radian/s";
    case QuantityKind::kForce:
      return "N";
    case QuantityKind::kStress:
      return "Pa";
    case QuantityKind::kMass:
      return "kg";
    case QuantityKind::kTime:
      return "s";
    case QuantityKind::kFrequency:
      return "1/s";
    case QuantityKind::kSpeed:
      return "m/s";
    case QuantityKind::kForcePerLength:
      return "N/m";
    case QuantityKind::kArea:
      return "m^2";
    case QuantityKind::kDensity:
      return "kg/m^3";
    case QuantityKind::kPower:
      return "W";
    case QuantityKind::kMassPerLength:
      return "kg/m";
  }
  return "1";
}

// UDUNITS-2 treats radian as dimensionless, so "3" or "50 %" would convert to an angle and
// "1/min" to an angular speed. Angles must name an angle unit; angular speeds must name rad or
// revolution, or be exactly 1/s.
bool names_angle(const std::string& definition) {
  return definition.find("rad") != std::string::npos;
}

// True when the unit part of "<number> <unit>" is written as exactly one per second.
bool is_per_second(const std::string& expression) {
  char* end = nullptr;
  std::strtod(expression.c_str(), &end);
  const std::string unit = trim(end == nullptr ? expression : std::string_view(end));
  return unit == "1/s" || unit == "/s" || unit == "s-1" || unit == "s^-1" ||
         unit == "s\u207b\u00b9";
}

// UDUNITS-2 builds a conversion factor by multiplying its database's factors, so an exact
// decimal factor can come out a few ulps off (g/cm^3 → kg/m^3 gives 999.99999999999989, and
// 2.56 g/cm^3 would read 2559.9999999999995 kg/m^3). A factor within 1e-14 of a number with 12
// significant digits is that number; factors that are not short decimals (rpm's 2π/60) are kept.
double tidy_factor(double factor) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", factor);
  const double short_form = std::strtod(text, nullptr);
  return std::abs(short_form - factor) <= 1e-14 * std::abs(factor) ? short_form : factor;
}

}  // namespace

const char* si_unit(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kLength:
      return "m";
    case QuantityKind::kAngle:
      return "rad";
    case QuantityKind::kAngularSpeed:
      return "rad/s";
    case QuantityKind::kForce:
      return "N";
    case QuantityKind::kStress:
      return "Pa";
    case QuantityKind::kMass:
      return "kg";
    case QuantityKind::kTime:
      return "s";
    case QuantityKind::kFrequency:
      return "1/s";
    case QuantityKind::kSpeed:
      return "m/s";
    case QuantityKind::kForcePerLength:
      return "N/m";
    case QuantityKind::kArea:
      return "m^2";
    case QuantityKind::kDensity:
      return "kg/m^3";
    case QuantityKind::kPower:
      return "W";
    case QuantityKind::kMassPerLength:
      return "kg/m";
  }
  return "1";
}

const char* default_unit(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kLength:
      return "mm";
    case QuantityKind::kAngle:
      return "degree";
    case QuantityKind::kAngularSpeed:
      return "1/s";
    case QuantityKind::kForce:
      return "N";
    case QuantityKind::kStress:
      return "MPa";
    case QuantityKind::kMass:
      return "kg";
    case QuantityKind::kTime:
      return "s";
    case QuantityKind::kFrequency:
      return "Hz";
    case QuantityKind::kSpeed:
      return "m/s";
    case QuantityKind::kForcePerLength:
      return "N/m";
    case QuantityKind::kArea:
      return "mm^2";
    case QuantityKind::kDensity:
      return "kg/m^3";
    case QuantityKind::kPower:
      return "kW";
    case QuantityKind::kMassPerLength:
      return "kg/m";
  }
  return "1";
}

const char* describe(QuantityKind kind) { return accepted_spellings(kind); }

namespace {

// What reading one text gives: the value in SI, or why it is not one.
struct Outcome {
  std::optional<double> value;
  std::string why;
};

Outcome parse_uncached(std::string_view raw, QuantityKind kind) {
  const std::string text = trim(raw);
  auto fail = [](const std::string& why) { return Outcome{std::nullopt, why}; };
  if (text.empty()) return fail("the value is empty");

  std::string expression;
  if (const auto number = bare_number(text)) {
    if (!std::isfinite(*number)) return fail("the value is not finite");
    expression = text + " " + default_unit(kind);
  } else if (const auto degrees = dms_degrees(text); degrees && kind == QuantityKind::kAngle) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g degree", *degrees);
    expression = buffer;
  } else {
    expression = text;
  }
  if (kind == QuantityKind::kAngularSpeed && mentions_hertz(text)) {
    return fail(
        "Hz does not say whether it counts revolutions or radians per second: use rpm "
        "or 1/s");
  }

  // The number and the unit are parsed apart: UDUNITS-2 cannot scale a unit by 0, so "0 mm"
  // as one expression would fail.
  char* number_end = nullptr;
  const double number = std::strtod(expression.c_str(), &number_end);
  if (number_end == expression.c_str()) return fail("not a number with a unit UDUNITS-2 knows");
  if (!std::isfinite(number)) return fail("the value is not finite");
  const std::string unit_text = trim(std::string_view(number_end));
  if (unit_text.empty()) return fail("not a number with a unit UDUNITS-2 knows");

  UnitSystem& system = units();
  std::lock_guard<std::mutex> lock(system.mutex);
  UnitPtr parsed(ut_parse(system.system, unit_text.c_str(), UT_UTF8));
  if (!parsed) return fail("not a number with a unit UDUNITS-2 knows");
  UnitPtr target(ut_parse(system.system, target_spelling(kind), UT_UTF8));
  if (!ut_are_convertible(parsed.get(), target.get())) {
    if (kind == QuantityKind::kForcePerLength) {
      UnitPtr mass_per_length(ut_parse(system.system, "kg/m", UT_UTF8));
      if (ut_are_convertible(parsed.get(), mass_per_length.get()))
        return fail("wrong dimension: a mass per length is not a weight; write kgf/m");
    }
    return fail("wrong dimension");
  }

  char definition[256] = {0};
  ut_format(parsed.get(), definition, sizeof definition - 1, UT_ASCII | UT_DEFINITION);
  const std::string def(definition);
  if (kind == QuantityKind::kAngle && !names_angle(def)) return fail("no angle unit given");
  if (kind == QuantityKind::kFrequency && names_angle(def)) {
    return fail("an angular unit (rad/s, rpm) does not count cycles: use Hz or 1/min");
  }

  cv_converter* converter = ut_get_converter(parsed.get(), target.get());
  const double value = number * tidy_factor(cv_convert_double(converter, 1.0));
  cv_free(converter);
  if (kind == QuantityKind::kAngularSpeed && !names_angle(def) && !is_per_second(expression)) {
    return fail("a frequency other than 1/s is ambiguous: use rpm or 1/s");
  }
  if (!std::isfinite(value)) return fail("the value is not finite");
  return Outcome{value, ""};
}

// Reading a text is a function of the text and the kind alone, and UDUNITS-2 runs under one
// mutex: threads that read the same texts over and over (a sweep's shared values, at every
// point) would queue on it. Outcomes are remembered, up to kRemembered texts (then forgotten
// all at once); a remembered outcome is the one the parser gave, so nothing read changes.
class Remembered {
 public:
  Outcome get(std::string_view raw, QuantityKind kind) {
    std::string key(1, static_cast<char>(kind));
    key += raw;
    {
      const std::shared_lock<std::shared_mutex> lock(mutex_);
      const auto found = outcomes_.find(key);
      if (found != outcomes_.end()) return found->second;
    }
    Outcome outcome = parse_uncached(raw, kind);
    const std::unique_lock<std::shared_mutex> lock(mutex_);
    if (outcomes_.size() >= kRemembered) outcomes_.clear();
    outcomes_.emplace(std::move(key), outcome);
    return outcome;
  }

 private:
  static constexpr std::size_t kRemembered = 4096;
  std::shared_mutex mutex_;
  std::unordered_map<std::string, Outcome> outcomes_;
};

}  // namespace

std::optional<double> parse_quantity(std::string_view raw, QuantityKind kind,
                                     std::string_view field, std::vector<Issue>& issues) {
  static Remembered remembered;
  Outcome outcome = remembered.get(raw, kind);
  if (!outcome.value) {
    issues.push_back({std::string(field), "'" + std::string(raw) + "'",
                      std::string(accepted_spellings(kind)) +
                          (outcome.why.empty() ? "" : " (" + outcome.why + ")")});
  }
  return outcome.value;
}

std::optional<double> parse_number(std::string_view text, std::string_view field,
                                   std::string_view expected, std::vector<Issue>& issues) {
  const std::string copy(text);
  char* end = nullptr;
  const double v = std::strtod(copy.c_str(), &end);
  if (copy.empty() || *end != '\0' || !std::isfinite(v)) {
    issues.push_back({std::string(field), "'" + copy + "'", std::string(expected)});
    return std::nullopt;
  }
  return v;
}

bool is_bare_number(std::string_view text) {
  const std::string t = trim(text);
  return bare_number(t).has_value();
}

std::optional<long> parse_integer(std::string_view text, std::string_view field, long min,
                                  std::vector<Issue>& issues) {
  const std::string copy(text);
  char* end = nullptr;
  const long value = std::strtol(copy.c_str(), &end, 10);
  if (copy.empty() || *end != '\0' || value < min || value > 1000000000L) {
    issues.push_back(
        {std::string(field), "'" + copy + "'", "a whole number ≥ " + std::to_string(min)});
    return std::nullopt;
  }
  return value;
}

double parse_quantity(std::string_view text, QuantityKind kind, std::string_view field) {
  std::vector<Issue> issues;
  const auto value = parse_quantity(text, kind, field, issues);
  throw_if_any(issues);
  return *value;
}

}  // namespace catena::io
