#pragma once

#include <optional>
#include <span>
#include <utility>

namespace anchorbench::eval {

// Whether reported covariances can be trusted, over many attempts (Bar-Shalom, Li, Kirubarajan,
// "Estimation with Applications to Tracking and Navigation", ch. 5.4): for a credible covariance
// each NEES is chi-square with `dof` degrees of freedom, so their average (ANEES) lies within
// AneesBounds with probability 0.95, and 5% of them exceed the 95% quantile.
struct Credibility {
  int n = 0;                           // attempts with a NEES
  std::optional<double> anees;         // mean NEES
  std::optional<double> bound_lo, bound_hi;  // 95% two-sided bounds of the ANEES of a credible estimator
  std::optional<double> above_95_pct;  // percent of NEES above the chi-square 95% quantile (credible: 5)
};

// The 95% two-sided bounds of the average of n chi-square variables with `dof` degrees of freedom
// (Wilson-Hilferty: chi2 of k dof ~ k (1 - 2/(9k) + z sqrt(2/(9k)))^3, accurate to <1% for k >= 3).
std::pair<double, double> AneesBounds(int n, int dof);
// The chi-square 95% quantile for 1 to 4 degrees of freedom.
double ChiSquare95(int dof);

Credibility CredibilityOf(std::span<const double> nees, int dof);

}  // namespace anchorbench::eval
