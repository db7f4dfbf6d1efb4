// Statistics of residual time series that respect their correlation in time (issue 18).
#include "time_series.hpp"

#include <unsupported/Eigen/FFT>

#include <boost/math/distributions/chi_squared.hpp>

#include <algorithm>
#include <complex>
#include <cmath>
#include <numeric>

namespace wattswath::calibration::detail {
namespace {

double mean(const std::vector<double>& x) {
  return x.empty() ? 0.0 : std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

// Autocorrelations rho_1..rho_K of `x`, stopping at the first one at or below 0.05 (excluded) or at
// n / 4. All lags at once by FFT (O(n log n): a one-hour 10 Hz log has smooth signals whose
// autocorrelation stays high for thousands of lags).
std::vector<double> positiveAutocorrelations(const std::vector<double>& x) {
  const size_t n = x.size();
  std::vector<double> rho;
  if (n < 8) return rho;
  const double m = mean(x);
  size_t len = 1;
  while (len < 2 * n) len <<= 1;
  std::vector<double> padded(len, 0.0);
  for (size_t i = 0; i < n; ++i) padded[i] = x[i] - m;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  for (auto& c : spectrum) c = std::norm(c);
  std::vector<double> acov;
  fft.inv(acov, spectrum);
  if (!(acov[0] > 0.0)) return rho;
  for (size_t k = 1; k < n / 4; ++k) {
    const double r = acov[k] / acov[0];
    if (r <= 0.05) break;
    rho.push_back(r);
  }
  return rho;
}
}  // namespace

double autocorrelationTime(const std::vector<double>& x) {
  double tau = 1.0;
  for (double r : positiveAutocorrelations(x)) tau += 2.0 * r;
  return tau;
}

double whiteNoiseSigma(const std::vector<double>& x) {
  if (x.size() < 3) return 0.0;
  std::vector<double> d(x.size() - 1);
  for (size_t i = 0; i + 1 < x.size(); ++i) d[i] = std::abs(x[i + 1] - x[i]);
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return 1.4826 * d[d.size() / 2] / std::sqrt(2.0);
}

double chiSquareQuantile(int k, double p) {
  // Boost.Math's exact quantile (an approximation by Wilson-Hilferty until 2026-11-27).
  return boost::math::quantile(boost::math::complement(boost::math::chi_squared(std::max(k, 1)), p));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t n = std::min(a.size(), b.size());
  if (n < 3) return 0.0;
  const double ma = mean(a), mb = mean(b);
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

double pairEffectiveSize(const std::vector<double>& a, const std::vector<double>& b) {
  const auto ra = positiveAutocorrelations(a), rb = positiveAutocorrelations(b);
  double s = 1.0;
  for (size_t k = 0; k < std::min(ra.size(), rb.size()); ++k) s += 2.0 * ra[k] * rb[k];
  return static_cast<double>(std::min(a.size(), b.size())) / s;
}

}  // namespace wattswath::calibration::detail
