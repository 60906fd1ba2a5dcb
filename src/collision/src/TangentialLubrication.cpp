#include "collision/TangentialLubrication.hpp"

#include "collision/Range.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace collision {

namespace {
// the ln(1/xi) coefficients of Y^A_11, (2/3)|Y^B_11|, (1/2)|Y^B_11| and Y^C_11
// for the radius ratio beta (infinite: a sphere and a plane)
struct Coefficients {
  Scalar A, B, E, G;
};
Coefficients coefficients(Scalar beta) {
  if (!std::isfinite(beta)) return {Scalar(8) / 15, Scalar(2) / 15, Scalar(1) / 10, Scalar(2) / 5};
  const Scalar b1 = 1 + beta;
  const Scalar B = Scalar(2) / 15 * beta * (4 + beta) / (b1 * b1);
  return {Scalar(4) / 15 * beta * (2 + beta + 2 * beta * beta) / (b1 * b1 * b1), B, Scalar(0.75) * B,
          Scalar(2) / 5 * beta / b1};
}
}  // namespace

TangentialLubrication::TangentialLubrication(Scalar a1, Scalar a2, Scalar viscosity)
    : wall_(!std::isfinite(a2)), a1_(a1), a2_(a2), mu_(viscosity) {
  if (!(std::isfinite(a1) && a1 > 0) || !(a2 > 0) || !(std::isfinite(viscosity) && viscosity > 0)) {
    throw std::invalid_argument("tangential lubrication: radii " + Range::number(a1) + ", " +
                                Range::number(a2) + " and viscosity " + Range::number(viscosity) +
                                " must be > 0");
  }
  beta_ = wall_ ? a2 : a2 / a1;
  const Coefficients c1 = coefficients(beta_);
  A_ = c1.A;
  B_ = c1.B;
  E_ = c1.E;
  G_ = c1.G;
  const Coefficients c2 = wall_ ? Coefficients{0, 0, 0, 0} : coefficients(1 / beta_);
  E2_ = c2.E;
  G2_ = c2.G;
}

TangentialLubricationLoads TangentialLubrication::loads(Scalar logFactor, const Vec3& d,
                                                        const Vec3& u1, const Vec3& omega1,
                                                        const Vec3& u2, const Vec3& omega2) const {
  TangentialLubricationLoads out;
  if (!(logFactor > 0)) return out;
  const Mat3 P = Mat3::Identity() - d * d.transpose();
  const Vec3 u = wall_ ? u1 : Vec3(u1 - u2);
  const Scalar pi = kPi;
  Vec3 f = A_ * (P * u) + B_ * a1_ * omega1.cross(d);
  Vec3 t1 = E_ * d.cross(u) + G_ * a1_ * (P * omega1);
  if (!wall_) {
    f += ((1 + beta_) * A_ - B_) * a1_ * omega2.cross(d);
    t1 += ((1 + beta_) * E_ - G_) * a1_ * (P * omega2);
    // sphere 2: d -> -d and u -> -u leave d x u unchanged
    const Scalar beta2 = 1 / beta_;
    const Vec3 t2 = E2_ * d.cross(u) + G2_ * a2_ * (P * omega2) +
                    ((1 + beta2) * E2_ - G2_) * a2_ * (P * omega1);
    out.torque2 = -8 * pi * mu_ * a2_ * a2_ * logFactor * t2;
  }
  out.force1 = -6 * pi * mu_ * a1_ * logFactor * f;
  out.torque1 = -8 * pi * mu_ * a1_ * a1_ * logFactor * t1;
  return out;
}

Scalar TangentialLubrication::rate(Scalar logFactor, Scalar inverseMass1, const Mat3& inverseInertia1,
                                   Scalar inverseMass2, const Mat3& inverseInertia2) const {
  if (!(logFactor > 0)) return 0;
  const Scalar pi = kPi;
  Scalar r = 6 * pi * mu_ * a1_ * A_ * (inverseMass1 + (wall_ ? 0 : inverseMass2));
  r = std::max(r, 8 * pi * mu_ * a1_ * a1_ * a1_ * G_ * inverseInertia1.norm());
  if (!wall_) r = std::max(r, 8 * pi * mu_ * a2_ * a2_ * a2_ * G2_ * inverseInertia2.norm());
  return logFactor * r;
}

}  // namespace collision
