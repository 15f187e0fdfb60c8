#include "anchorbench/eval/credibility.hpp"

#include <cmath>
#include <stdexcept>

namespace anchorbench::eval {

std::pair<double, double> AneesBounds(int n, int dof) {
  constexpr double kZ975 = 1.959963984540054;
  const double k = static_cast<double>(n) * dof;
  auto quantile = [k](double z) { return k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3); };
  return {quantile(-kZ975) / n, quantile(kZ975) / n};
}

double ChiSquare95(int dof) {
  constexpr double kQuantiles[] = {3.841458820694124, 5.991464547107979, 7.814727903251178, 9.487729036781154};
  if (dof < 1 || dof > 4) throw std::invalid_argument("ChiSquare95: dof must be 1 to 4");
  return kQuantiles[dof - 1];
}

Credibility CredibilityOf(std::span<const double> nees, int dof) {
  Credibility c;
  c.n = static_cast<int>(nees.size());
  if (c.n == 0) return c;
  double sum = 0.0;
  int above = 0;
  for (const double value : nees) {
    sum += value;
    above += value > ChiSquare95(dof);
  }
  c.anees = sum / c.n;
  const auto [lo, hi] = AneesBounds(c.n, dof);
  c.bound_lo = lo;
  c.bound_hi = hi;
  c.above_95_pct = 100.0 * above / c.n;
  return c;
}

}  // namespace anchorbench::eval
