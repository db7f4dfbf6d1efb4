#pragma once
// Formal covariance of least-squares coefficients from the Jacobian of the residuals, with the
// directions the data do not determine found on the column-scaled (unit-free) normal matrix.
#include <Eigen/Dense>
#include <vector>

namespace wattswath::calibration::detail {

/// What the Jacobian says about a fit's coefficients.
struct CoefficientCovariance {
  Eigen::MatrixXd covariance;            ///< [unit_i unit_j] covariance, 0 in rows/columns not determined
  std::vector<bool> determined;          ///< false: the column is zero or lies in a direction the data do not fix
  std::vector<std::vector<int>> tied_to; ///< for an undetermined column, the other columns it is confounded with
};

/// Covariance residual_variance (J^T J)^-1 of the coefficients whose residuals have Jacobian `jacobian`
/// (rows: residuals, columns: coefficients), by eigen-decomposition of J^T J scaled to unit columns:
/// a direction whose eigenvalue is below `min_reciprocal_condition` times the largest is not
/// determined, and the columns that load on it by more than 0.1 are marked so (tied to one another).
/// A column of zeros is not determined either. `residual_variance` [residual unit^2] scales the result.
CoefficientCovariance coefficientCovariance(const Eigen::MatrixXd& jacobian, double residual_variance,
                                            double min_reciprocal_condition = 1e-10);

}  // namespace wattswath::calibration::detail
