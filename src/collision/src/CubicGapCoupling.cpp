#include "collision/CubicGapCoupling.hpp"

#include "collision/Range.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace collision {

namespace {
/// T(a, b, c) for the tensor stored as T[k](i, j) = T_ijk
Scalar contract(const Tensor3& T, const Vec3& a, const Vec3& b, const Vec3& c) {
  Scalar sum = 0;
  for (int k = 0; k < 3; ++k) sum += c(k) * a.dot(T[k] * b);
  return sum;
}
}  // namespace

CubicGapCoupling::CubicGapCoupling(const Mat3& S1, const Mat3& S2, const Tensor3& C1,
                                   const Tensor3& C2, const Vec3& n, Scalar viscosity)
    : n_(n) {
  if (!(std::isfinite(viscosity) && viscosity > 0)) {
    throw std::invalid_argument("cubic gap coupling: viscosity " + Range::number(viscosity) +
                                " must be > 0");
  }
  const Mat3 P = Mat3::Identity() - n * n.transpose();
  const Mat3 s1 = P * S1 * P, s2 = P * S2 * P;
  // K's principal axes on the plane: the two largest eigenvalues (n's is 0)
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(0.5 * (s1 + s2 + (s1 + s2).transpose()));
  const Vec3 e[2] = {eigen.eigenvectors().col(2), eigen.eigenvectors().col(1)};
  const Scalar k[2] = {eigen.eigenvalues()(2), eigen.eigenvalues()(1)};
  if (!(k[1] > 0) || !std::isfinite(k[0])) {
    std::ostringstream msg;
    msg << "cubic gap coupling: the gap's curvatures must be positive and finite, got "
        << k[1] << ", " << k[0] << " (two convex surfaces, at most one of them a plane)";
    throw std::invalid_argument(msg.str());
  }
  Tensor3 Gamma, D;
  for (int c = 0; c < 3; ++c) {
    Gamma[c] = C1[c] + C2[c];
    D[c] = C2[c] - C1[c];
  }
  const Scalar trace = k[0] + k[1];
  Scalar j[2];
  Scalar d[2];
  for (int m = 0; m < 2; ++m) {
    const int o = 1 - m;
    const Scalar gmmm = contract(Gamma, e[m], e[m], e[m]);
    const Scalar gmoo = contract(Gamma, e[m], e[o], e[o]);
    j[m] = 36 / (trace * (3 * k[m] + 2 * k[o])) *
           (-(7 * k[m] + 2 * k[o]) * gmmm / (6 * k[m] * k[m]) -
            (k[m] + 2 * k[o]) * gmoo / (2 * k[m] * k[o]));
    // sum_a D_aam/k_a
    d[m] = contract(D, e[0], e[0], e[m]) / k[0] + contract(D, e[1], e[1], e[m]) / k[1];
  }
  const Vec3 jVector = j[0] * e[0] + j[1] * e[1];
  const Scalar scale = kPi * viscosity / std::sqrt(k[0] * k[1]);
  force_ = scale * (3 / trace * (d[0] * e[0] + d[1] * e[1]) + 0.5 * (s2 - s1) * jVector);
  // the twist: (S1 K^-1)_21 - (S1 K^-1)_12 in K's axes
  const Scalar twist = e[1].dot(s1 * e[0]) / k[0] - e[0].dot(s1 * e[1]) / k[1];
  moment_ = -scale * jVector.cross(n) - 12 * scale / trace * twist * e[0].cross(e[1]);
}

FilmLoads CubicGapCoupling::loads(Scalar logFactor, const FilmSide& body1,
                                  const FilmSide& body2) const {
  FilmLoads out;
  if (!(logFactor > 0)) return out;
  const Vec3 relative = body1.velocity + body1.angularVelocity.cross(body1.arm) -
                        body2.velocity - body2.angularVelocity.cross(body2.arm);
  const Scalar approach = relative.dot(n_);
  const Scalar normal =
      force_.dot(relative) + moment_.dot(body1.angularVelocity - body2.angularVelocity);
  out.force1 = logFactor * (approach * force_ + normal * n_);
  const Vec3 moment = logFactor * approach * moment_;
  out.torque1 = moment + body1.arm.cross(out.force1);
  out.torque2 = -moment - body2.arm.cross(out.force1);
  return out;
}

}  // namespace collision
