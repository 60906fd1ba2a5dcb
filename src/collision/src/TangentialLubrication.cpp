#include "collision/TangentialLubrication.hpp"

#include "collision/GapParaboloid.hpp"
#include "collision/Range.hpp"

#include <cmath>
#include <stdexcept>

namespace collision {

namespace {
/// the inverse on the plane normal to n of a symmetric tensor T that maps
/// that plane onto itself and n to 0
Mat3 inverseOnPlane(const Mat3& T, const Vec3& n) {
  const Mat3 nn = n * n.transpose();
  return (T + nn).inverse() - nn;
}
}  // namespace

TangentialLubrication::TangentialLubrication(const Mat3& S1, const Mat3& S2, const Vec3& n,
                                             Scalar viscosity)
    : n_(n), P_(Mat3::Identity() - n * n.transpose()), mu_(viscosity) {
  if (!(std::isfinite(viscosity) && viscosity > 0)) {
    throw std::invalid_argument("tangential lubrication: viscosity " + Range::number(viscosity) +
                                " must be > 0");
  }
  // the gap's principal curvatures; throws unless K is positive definite on the plane
  const GapParaboloid gap = GapParaboloid::fromCurvatureTensors(S1, S2, n);
  radius_ = 1 / std::sqrt(gap.k1 * gap.k2);
  S1_ = P_ * S1 * P_;
  S2_ = P_ * S2 * P_;
  const Mat3 K = S1_ + S2_;
  const Mat3 Kinv = inverseOnPlane(K, n);
  const Mat3 M = inverseOnPlane(2 * K.trace() * P_ + K, n);
  forceMap_ = (P_ - 2 * S1_ * Kinv) * M;
  torqueMap_ = Kinv * M;
}

TangentialLubrication TangentialLubrication::spheres(Scalar a1, Scalar a2, const Vec3& n,
                                                     Scalar viscosity) {
  if (!(std::isfinite(a1) && a1 > 0) || !(a2 > 0)) {
    throw std::invalid_argument("tangential lubrication: radii " + Range::number(a1) + ", " +
                                Range::number(a2) + " must be > 0");
  }
  const Mat3 P = Mat3::Identity() - n * n.transpose();
  return TangentialLubrication(P / a1, std::isfinite(a2) ? Mat3(P / a2) : Mat3::Zero(), n,
                               viscosity);
}

FilmLoads TangentialLubrication::loads(Scalar logFactor, const FilmSide& body1,
                                                        const FilmSide& body2) const {
  FilmLoads out;
  if (!(logFactor > 0)) return out;
  // the surfaces' velocities along the film at the closest points
  const Vec3 U1 = P_ * (body1.velocity + body1.angularVelocity.cross(body1.arm));
  const Vec3 U2 = P_ * (body2.velocity + body2.angularVelocity.cross(body2.arm));
  const Vec3 w = (S2_ - S1_) * (U1 - U2) +
                 2 * n_.cross(body2.angularVelocity - body1.angularVelocity);
  const Scalar scale = kPi * mu_ * radius_ * logFactor;
  out.force1 = scale * (2 * (U2 - U1) - 6 * (forceMap_ * w));
  // the pressure's moment about the closest point
  const Vec3 moment = 12 * scale * (torqueMap_ * w).cross(n_);
  out.torque1 = moment + body1.arm.cross(out.force1);
  out.torque2 = -moment - body2.arm.cross(out.force1);
  return out;
}

Scalar TangentialLubrication::rate(Scalar logFactor, const FilmMobility& mobility) const {
  if (!(logFactor > 0)) return 0;
  const FilmLaw law = [this](const FilmSide& one, const FilmSide& two) { return loads(1, one, two); };
  return logFactor * filmResistanceRate(law, mobility);
}

}  // namespace collision
