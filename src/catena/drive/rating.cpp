// ANSI roller-chain power rating (A series): H1, H2, strand factors.
#include "catena/drive/rating.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace catena::drive {

std::optional<AnsiConstants> ansi_constants(int number) {
  if (number == 25 || number == 35) return AnsiConstants{number, 0.004, 29.0};
  if (number == 41) return AnsiConstants{number, 0.0022, 3.4};
  if (number >= 40 && number <= 240 && number % 10 == 0) return AnsiConstants{number, 0.004, 17.0};
  return std::nullopt;
}

std::optional<int> ansi_number(const std::string& iso_name) {
  // "08A": two digits of the pitch in sixteenths of an inch, then the series letter
  if (iso_name.size() != 3 || !std::isdigit(static_cast<unsigned char>(iso_name[0])) ||
      !std::isdigit(static_cast<unsigned char>(iso_name[1])) ||
      std::toupper(static_cast<unsigned char>(iso_name[2])) != 'A')
    return std::nullopt;
  const int sixteenths = (iso_name[0] - '0') * 10 + (iso_name[1] - '0');
  if (sixteenths % 2 != 0) return std::nullopt;
  return sixteenths / 2 * 10;
}

double plate_fatigue_hp(const AnsiConstants& c, int n1_teeth, double rpm, double p) {
  return c.k * std::pow(n1_teeth, 1.08) * std::pow(rpm, 0.9) * std::pow(p, 3 - 0.07 * p);
}

double roller_impact_hp(const AnsiConstants& c, int n1_teeth, double rpm, double p) {
  return 1000 * c.kr * std::pow(n1_teeth, 1.5) * std::pow(p, 0.8) / std::pow(rpm, 1.5);
}

std::optional<double> strand_factor(int strands) {
  switch (strands) {
    case 1:
      return 1.0;
    case 2:
      return 1.7;
    case 3:
      return 2.5;
    case 4:
      return 3.3;
    default:
      return std::nullopt;
  }
}

Rating rate(const AnsiConstants& c, double pitch, int z1, double rpm, int strands, double power,
            double service_factor) {
  constexpr double kInch = 0.0254;
  Rating r;
  r.ansi = c.number;
  const double p = pitch / kInch;
  r.plate_fatigue = plate_fatigue_hp(c, z1, rpm, p) * kHorsepower;
  r.roller_impact = roller_impact_hp(c, z1, rpm, p) * kHorsepower;
  r.strand_factor = strand_factor(strands).value_or(NAN);
  r.governed_by_impact = r.roller_impact < r.plate_fatigue;
  r.rated_power = std::min(r.plate_fatigue, r.roller_impact) * r.strand_factor;
  r.design_power = power * service_factor;
  r.margin = r.rated_power / r.design_power;
  return r;
}

}  // namespace catena::drive
