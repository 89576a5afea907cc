// Fuzzes the quantity parser (UDUNITS-2 under Catena's rules) and the plain-number and
// whole-number parsers: the first byte chooses the kind, the rest is the text. What they return
// must be finite, a whole number must lie in its range, and a failure must name the field.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/quantity.hpp"
#include "fuzz_support.hpp"

namespace {

constexpr catena::io::QuantityKind kKinds[] = {
    catena::io::QuantityKind::kLength,       catena::io::QuantityKind::kAngle,
    catena::io::QuantityKind::kAngularSpeed, catena::io::QuantityKind::kForce,
    catena::io::QuantityKind::kStress,       catena::io::QuantityKind::kMass,
    catena::io::QuantityKind::kTime,         catena::io::QuantityKind::kFrequency,
    catena::io::QuantityKind::kSpeed,        catena::io::QuantityKind::kForcePerLength,
    catena::io::QuantityKind::kArea,         catena::io::QuantityKind::kDensity};

// One parser's answer: a value and no issue, or no value and exactly one issue naming `field`.
void check_outcome(const std::optional<double>& value, const std::vector<catena::Issue>& issues,
                   const char* parser) {
  if (value) {
    if (!std::isfinite(*value)) catena::fuzz::fail(std::string(parser) + " returned a non-finite");
    if (!issues.empty()) catena::fuzz::fail(std::string(parser) + " returned a value and an issue");
  } else if (issues.size() != 1 || issues.front().field != "field" ||
             issues.front().expected.empty()) {
    catena::fuzz::fail(std::string(parser) + " failed without exactly one issue naming the field");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const catena::io::QuantityKind kind = kKinds[data[0] % std::size(kKinds)];
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);

  std::vector<catena::Issue> issues;
  const std::optional<double> si = catena::io::parse_quantity(text, kind, "field", issues);
  check_outcome(si, issues, "parse_quantity");
  try {
    const double thrown = catena::io::parse_quantity(text, kind, "field");
    if (!si || thrown != *si) catena::fuzz::fail("the throwing parse_quantity disagrees");
  } catch (const catena::InputError&) {
    if (si) catena::fuzz::fail("the throwing parse_quantity refused what the other accepted");
  }

  issues.clear();
  check_outcome(catena::io::parse_number(text, "field", "a number", issues), issues,
                "parse_number");
  issues.clear();
  const long min = data[0] % 4;
  const std::optional<long> whole = catena::io::parse_integer(text, "field", min, issues);
  if (whole && (*whole < min || *whole > 1000000000L))
    catena::fuzz::fail("parse_integer returned a number outside [min, 10^9]");
  check_outcome(whole ? std::optional<double>(static_cast<double>(*whole)) : std::nullopt, issues,
                "parse_integer");
  // A bare number is read in the kind's default unit, exactly as if that unit were written.
  if (catena::io::is_bare_number(text) && si) {
    std::vector<catena::Issue> spelled_issues;
    const std::string spelled = std::string(text) + " " + catena::io::default_unit(kind);
    const std::optional<double> spelled_si =
        catena::io::parse_quantity(spelled, kind, "field", spelled_issues);
    if (!spelled_si || *spelled_si != *si)
      catena::fuzz::fail("a bare number and the same number with its default unit differ");
  }
  return 0;
}
