#include "catena/core/hardness.hpp"

#include <cmath>
#include <string>

#include "catena/core/error.hpp"

namespace catena {
namespace {

// ASTM E140-12b Table 1, Vickers column at HRC 20, 21, …, 68 (non-austenitic steels).
constexpr double kVickers[] = {
    238, 243, 248, 254, 260, 266, 272, 279, 286, 294,  // HRC 20–29
    302, 310, 318, 327, 336, 345, 354, 363, 372, 382,  // HRC 30–39
    392, 402, 412, 423, 434, 446, 458, 471, 484, 498,  // HRC 40–49
    513, 528, 544, 560, 577, 595, 613, 633, 653, 674,  // HRC 50–59
    697, 720, 746, 772, 800, 832, 865, 900, 940,       // HRC 60–68
};
static_assert(sizeof kVickers / sizeof kVickers[0] == 49);

constexpr double kStandardGravity = 9.80665;  // [m/s²] g_n: 1 kgf = 9.80665 N

}  // namespace

double vickers_from_rockwell_c(double hrc) {
  if (!std::isfinite(hrc) || hrc < kRockwellCMin || hrc > kRockwellCMax)
    throw InputError({{"hardness", std::to_string(hrc) + " HRC",
                       "20 to 68 HRC (ASTM E140 Table 1, non-austenitic steels)"}});
  const double at = hrc - kRockwellCMin;
  const auto i = static_cast<std::size_t>(std::floor(at));
  if (i + 1 >= std::size(kVickers)) return kVickers[std::size(kVickers) - 1];
  const double t = at - static_cast<double>(i);
  return kVickers[i] + t * (kVickers[i + 1] - kVickers[i]);
}

double vickers_to_pascal(double hv) { return hv * kStandardGravity * 1e6; }

}  // namespace catena
