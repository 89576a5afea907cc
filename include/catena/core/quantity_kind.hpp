// What a dimensional value measures. The kind decides which units a value may be written in and
// the unit a bare number takes; the parser itself lives in io/quantity (UDUNITS-2).
#pragma once

namespace catena {

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
  kArea,            ///< SI m^2; bare number: mm^2
  kDensity,         ///< SI kg/m^3 (mass per volume); bare number: kg/m^3
  kPower,           ///< SI W; bare number: kW; hp accepted (the mechanical horsepower)
  kMassPerLength,   ///< SI kg/m (a chain's mass per metre); bare number: kg/m
};

/// A short name of the kind for help texts ("length", "angular speed").
constexpr const char* kind_name(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kLength:
      return "length";
    case QuantityKind::kAngle:
      return "angle";
    case QuantityKind::kAngularSpeed:
      return "angular speed";
    case QuantityKind::kForce:
      return "force";
    case QuantityKind::kStress:
      return "stress";
    case QuantityKind::kMass:
      return "mass";
    case QuantityKind::kTime:
      return "time";
    case QuantityKind::kFrequency:
      return "frequency";
    case QuantityKind::kSpeed:
      return "speed";
    case QuantityKind::kForcePerLength:
      return "force per length";
    case QuantityKind::kArea:
      return "area";
    case QuantityKind::kDensity:
      return "density";
    case QuantityKind::kPower:
      return "power";
    case QuantityKind::kMassPerLength:
      return "mass per length";
  }
  return "quantity";
}

}  // namespace catena
