// ISO 606 roller chains: the dimensions the contact models use, from data/catalog/iso606/
// (embedded at build time; each value's source is in that folder's README). A value no source
// stated is absent (nullopt), never guessed.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace catena::contact {

struct ChainDimensions {
  std::string name;                        ///< e.g. "12B"
  double pitch = 0.0;                      ///< [m] p
  std::optional<double> roller_diameter;   ///< [m] d1 max
  std::optional<double> inner_width;       ///< [m] b1 min (bounds the roller length)
  std::optional<double> pin_diameter;      ///< [m] d2 max
  std::optional<double> plate_depth;       ///< [m] h2 max
  std::optional<double> tensile_strength;  ///< [N] simplex, minimum
  std::optional<double> transverse_pitch;  ///< [m] pt (multi-strand chains)
  std::optional<double> mass_per_metre;    ///< [kg/m] q, simplex
  /// [N/m] axial stiffness of one link (one pitch), simplex: EA/p with EA = 12 k lbf from the
  /// source's stretch factor k (README, `CALCULATORS_K`; a secondary source, an order of
  /// magnitude); the A rows 08A … 32A only
  std::optional<double> axial_stiffness;
  std::string source;  ///< source ids (README)
};

/// The chain of that name (case-insensitive), or nothing.
std::optional<ChainDimensions> iso606_chain(const std::string& name);
/// All names in the catalogue.
std::vector<std::string> iso606_names();

}  // namespace catena::contact
