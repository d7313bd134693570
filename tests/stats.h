// Statistics for the tests: Pearson's chi-square goodness of fit (Mitsuba's and pbrt's
// method for validating samplers) and the chi-square survival function.
#pragma once
#include <cmath>
#include <vector>

namespace pt {

// Regularized upper incomplete gamma Q(a, x) (series below a + 1, Lentz continued fraction above).
double gamma_q(double a, double x);
inline double chi2_survival(double stat, int dof) { return gamma_q(0.5 * dof, 0.5 * stat); }

struct Chi2Result {
  double stat = 0;
  int dof = 0;
  double p_value = 1;
  int pooled = 0;  // cells merged because their expected count was below the minimum
};

// Cells whose expected count is below `min_expected` are pooled into one cell (after
// sorting by expectation), as in Mitsuba's ChiSquareTest. Observed counts in cells with
// zero expectation make the test fail outright (p = 0).
Chi2Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected, double min_expected = 5.0);

// Per-test significance for `tests` tests at overall level alpha (Sidak correction).
double sidak_alpha(double alpha, int tests);

// Closed forms the tests compare against, written once for every test file.
inline constexpr double kPi = 3.14159265358979323846;
// Schlick's Fresnel approximation: reflectance f0 at normal incidence, c = cos(theta).
inline double schlick(double f0, double c) { return f0 + (1 - f0) * std::pow(1 - c, 5); }

}  // namespace pt
