#include "collision/FilmResistanceRate.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace collision {

namespace {
/// the symmetric square root of a symmetric positive semi-definite tensor
Mat3 squareRoot(const Mat3& A) {
  if (A.isZero(0)) return Mat3::Zero();
  return Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (A + A.transpose())).operatorSqrt();
}
}  // namespace

Scalar filmResistanceRate(const FilmLaw& loads, const Vec3& arm1, Scalar inverseMass1,
                          const Mat3& inverseInertia1, const Vec3& arm2, Scalar inverseMass2,
                          const Mat3& inverseInertia2) {
  // D: the square roots of the mobilities of (v1, Omega1, v2, Omega2)
  const Mat3 D[4] = {Mat3::Identity() * std::sqrt(inverseMass1), squareRoot(inverseInertia1),
                     Mat3::Identity() * std::sqrt(inverseMass2), squareRoot(inverseInertia2)};
  // the Frobenius norm of D R D, column by column
  Scalar sum = 0;
  for (int k = 0; k < 12; ++k) {
    FilmSide side[2];
    side[0].arm = arm1;
    side[1].arm = arm2;
    Vec3* motion[4] = {&side[0].velocity, &side[0].angularVelocity, &side[1].velocity,
                       &side[1].angularVelocity};
    *motion[k / 3] = D[k / 3].col(k % 3);
    const FilmLoads l = loads(side[0], side[1]);
    sum += (D[0] * l.force1).squaredNorm() + (D[1] * l.torque1).squaredNorm() +
           (D[2] * l.force1).squaredNorm() + (D[3] * l.torque2).squaredNorm();
  }
  return std::sqrt(sum);
}

}  // namespace collision
