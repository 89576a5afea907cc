// Power rating of roller chains where a public formula exists: the ANSI envelopes for A-series
// (ANSI B29.1) chains, link-plate fatigue H1 and roller–bushing impact H2, as quoted in
// Shigley's Mechanical Engineering Design (eqs. 17-40 and 17-41 in the 9th edition), with the
// multiple-strand factors. Units are the formulas' own: pitch in inches, speed in rpm, power in hp.
#pragma once

#include <optional>
#include <string>

namespace catena::drive {

/// The mechanical horsepower, 550 ft·lbf/s [W].
inline constexpr double kHorsepower = 745.69987158227022;

/// The constants of one ANSI chain number.
struct AnsiConstants {
  int number = 0;   ///< ANSI chain number (#40 …)
  double k = 0.0;   ///< link-plate constant K: 0.004, 0.0022 for #41
  double kr = 0.0;  ///< roller constant Kr: 29 (#25, #35), 3.4 (#41), 17 (#40–#240)
};

/// The constants of ANSI chain `number`, or nothing for a number the formulas do not cover.
std::optional<AnsiConstants> ansi_constants(int number);

/// The ANSI number of an ISO 606 A-series chain ("08A" → 40: eighths of an inch × 10), or
/// nothing (B series and anything else: no public rating formula).
std::optional<int> ansi_number(const std::string& iso_name);

/// Link-plate fatigue H1 = K N1^1.08 n1^0.9 p^(3 − 0.07p) [hp]; p [in], n1 [rpm].
double plate_fatigue_hp(const AnsiConstants& c, int n1_teeth, double rpm, double pitch_in);

/// Roller–bushing impact H2 = 1000 Kr N1^1.5 p^0.8 / n1^1.5 [hp].
double roller_impact_hp(const AnsiConstants& c, int n1_teeth, double rpm, double pitch_in);

/// Multiple-strand factor: 1, 1.7, 2.5, 3.3 for 1…4 strands; nothing beyond.
std::optional<double> strand_factor(int strands);

/// One rating in SI.
struct Rating {
  int ansi = 0;
  double plate_fatigue = 0.0;  ///< [W] H1 of one strand
  double roller_impact = 0.0;  ///< [W] H2 of one strand
  double strand_factor = 1.0;
  double rated_power = 0.0;   ///< [W] min(H1, H2) × strand factor
  double design_power = 0.0;  ///< [W] transmitted power × service factor
  double margin = 0.0;        ///< rated / design power (≥ 1: the chain carries it)
  bool governed_by_impact = false;
};

/// The rating of `strands` strands of ANSI chain `c` of pitch `pitch` [m] on a driver of `z1`
/// teeth at `rpm`, for `power` [W] × `service_factor`.
Rating rate(const AnsiConstants& c, double pitch, int z1, double rpm, int strands, double power,
            double service_factor);

}  // namespace catena::drive
