// Covariance of fitted coefficients, honest about near-confounded pairs: a pseudo-inverse on the
// raw (unit-laden) normal matrix dropped a direction made mostly of the largest coefficient and
// reported it to a fraction of a watt (induced power 3.38e3 +- 0.036 W while r = -1 with its speed
// scale); scaling the columns first makes the test of "not determined" independent of units.
#include "coefficient_covariance.hpp"

#include <cmath>

namespace wattswath::calibration::detail {

CoefficientCovariance coefficientCovariance(const Eigen::MatrixXd& jacobian, double residual_variance,
                                            double min_reciprocal_condition) {
  const Eigen::Index p = jacobian.cols();
  CoefficientCovariance out;
  out.covariance = Eigen::MatrixXd::Zero(p, p);
  out.determined.assign(static_cast<size_t>(p), true);
  out.tied_to.assign(static_cast<size_t>(p), {});
  Eigen::VectorXd norm = jacobian.colwise().norm().transpose();
  std::vector<Eigen::Index> live;
  for (Eigen::Index j = 0; j < p; ++j) {
    if (norm(j) > 0.0 && std::isfinite(norm(j))) {
      live.push_back(j);
    } else {
      out.determined[static_cast<size_t>(j)] = false;
    }
  }
  if (live.empty()) return out;
  const auto q = static_cast<Eigen::Index>(live.size());
  Eigen::MatrixXd scaled(jacobian.rows(), q);
  for (Eigen::Index k = 0; k < q; ++k) scaled.col(k) = jacobian.col(live[k]) / norm(live[k]);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled.transpose() * scaled);
  const Eigen::VectorXd& lambda = eig.eigenvalues();  // ascending
  const Eigen::MatrixXd& v = eig.eigenvectors();
  const double floor = min_reciprocal_condition * lambda(q - 1);
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(q, q);
  for (Eigen::Index e = 0; e < q; ++e) {
    if (lambda(e) > floor) {
      inverse += v.col(e) * v.col(e).transpose() / lambda(e);
      continue;
    }
    std::vector<Eigen::Index> loaded;
    for (Eigen::Index k = 0; k < q; ++k)
      if (std::abs(v(k, e)) > 0.1) loaded.push_back(k);
    for (Eigen::Index a : loaded) {
      out.determined[static_cast<size_t>(live[a])] = false;
      for (Eigen::Index b : loaded)
        if (b != a) out.tied_to[static_cast<size_t>(live[a])].push_back(static_cast<int>(live[b]));
    }
  }
  for (Eigen::Index a = 0; a < q; ++a) {
    for (Eigen::Index b = 0; b < q; ++b) {
      if (!out.determined[static_cast<size_t>(live[a])] || !out.determined[static_cast<size_t>(live[b])]) continue;
      out.covariance(live[a], live[b]) = residual_variance * inverse(a, b) / (norm(live[a]) * norm(live[b]));
    }
  }
  return out;
}

}  // namespace wattswath::calibration::detail
