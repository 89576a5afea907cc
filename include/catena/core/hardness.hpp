// Hardness conversion for the wear model's Archard law, which takes the hardness as a pressure.
//
// Source: ASTM E140-12b, Standard Hardness Conversion Tables for Metals, Table 1 "Approximate
// hardness conversion numbers for non-austenitic steels (Rockwell C hardness range)": Vickers
// HV against Rockwell C at whole HRC numbers 20–68 (the values read from that table's
// reproduction cited in docs/bibliography.md). Between the table's whole numbers the conversion is
// interpolated linearly, as ASTM E140 itself says every converted value is approximate.
// A Vickers number is kgf per mm² of indentation surface: HV·g_n MPa, g_n = 9.80665 m/s².
#pragma once

namespace catena {

/// [-] lowest and highest Rockwell C number of ASTM E140 Table 1.
inline constexpr double kRockwellCMin = 20.0;
inline constexpr double kRockwellCMax = 68.0;

/// [HV] Vickers number of a non-austenitic steel of Rockwell C hardness `hrc` (ASTM E140
/// Table 1; linear between its whole numbers). Throws InputError naming "hardness" outside 20–68.
double vickers_from_rockwell_c(double hrc);

/// [Pa] a Vickers number as a pressure: HV kgf/mm² = HV·9.80665 MPa.
double vickers_to_pascal(double hv);

}  // namespace catena
