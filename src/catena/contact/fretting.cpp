#include "catena/contact/fretting.hpp"

#include <cmath>

namespace catena::contact {

std::vector<Issue> validate(const Fretting& f) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "roughness", f.roughness, "m");
  check::finite_positive(issues, "amplitude", f.amplitude, "m");
  check::finite_positive(issues, "load", f.load, "N");
  check::finite_positive(issues, "frequency", f.frequency, "1/s");
  check::finite_positive(issues, "k1", f.k1, "s/m");
  if (!std::isfinite(f.k2) || f.k2 >= 0.0) {
    issues.push_back({"k2", check::format_si(f.k2, "s/N"),
                      "K2 < 0: with K2 ≥ 0 the latent period would not fall with amplitude, load "
                      "and frequency, against the model's premise (001, Vikulov eq. 1)"});
  }
  return issues;
}

double latent_period(const Fretting& f) {
  throw_if_any(validate(f));
  return f.k1 * f.roughness * std::exp(f.k2 * f.amplitude * f.load * f.frequency / f.roughness);
}

}  // namespace catena::contact
