#pragma once
// Statistics of residual time series that respect their correlation in time (issue 18): the
// integrated autocorrelation time, the white-noise level from successive differences, a moving
// block bootstrap of a mean, and the effective sample size of a correlation between two series.
#include <vector>

namespace wattswath::calibration::detail {

/// Integrated autocorrelation time tau = 1 + 2 sum_k rho_k [samples] of `x` (time order), summed
/// while rho_k stays above 0.05 and k < n / 4 (Sokal's truncated window); 1 for white noise.
double autocorrelationTime(const std::vector<double>& x);

/// Standard deviation of the white (sample-to-sample) part of `x` [unit of x]: 1.4826 median
/// |x_{i+1} - x_i| / sqrt(2), which a smooth structure (a missing effect) hardly changes.
double whiteNoiseSigma(const std::vector<double>& x);

/// Chi-square quantile with `k` (at least 1) degrees of freedom at upper-tail probability `p` in (0, 1) (Boost.Math).
double chiSquareQuantile(int k, double p);

/// Pearson correlation of `a` and `b` (0 when either is constant or fewer than 3 samples).
double correlation(const std::vector<double>& a, const std::vector<double>& b);

/// Effective number of independent pairs for the correlation of two autocorrelated series
/// (Bartlett): n / (1 + 2 sum_k rho_a(k) rho_b(k)), summed over k < n / 4 while both rho > 0.05.
double pairEffectiveSize(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace wattswath::calibration::detail
