#include "collision/FilmResistanceRate.hpp"

#include <algorithm>
#include <cmath>

namespace collision {

namespace {
/// [a]x: the matrix of the cross product a x
Mat3 cross(const Vec3& a) {
  Mat3 c;
  c << 0, -a(2), a(1), a(2), 0, -a(0), -a(1), a(0), 0;
  return c;
}
}  // namespace

FilmMobility::FilmMobility(const Vec3& r1, Scalar inverseMass1, const Mat3& inverseInertia1,
                           const Vec3& r2, Scalar inverseMass2, const Mat3& inverseInertia2)
    : arm1(r1), arm2(r2) {
  // B = [[I, -[r1]x, -I, [r2]x], [0, I, 0, -I]] on (v1, Omega1, v2, Omega2)
  const Mat3 c1 = cross(r1), c2 = cross(r2);
  const Mat3 J1c1 = inverseInertia1 * c1, J2c2 = inverseInertia2 * c2;
  relative.topLeftCorner<3, 3>() =
      (inverseMass1 + inverseMass2) * Mat3::Identity() - c1 * J1c1 - c2 * J2c2;
  relative.topRightCorner<3, 3>() = -c1 * inverseInertia1 - c2 * inverseInertia2;
  relative.bottomLeftCorner<3, 3>() = relative.topRightCorner<3, 3>().transpose();
  relative.bottomRightCorner<3, 3>() = inverseInertia1 + inverseInertia2;
}

Scalar filmResistanceRate(const FilmLaw& loads, const Vec3& arm1, Scalar inverseMass1,
                          const Mat3& inverseInertia1, const Vec3& arm2, Scalar inverseMass2,
                          const Mat3& inverseInertia2) {
  return filmResistanceRate(
      loads, FilmMobility(arm1, inverseMass1, inverseInertia1, arm2, inverseMass2, inverseInertia2));
}

Scalar filmResistanceRate(const FilmLaw& loads, const FilmMobility& mobility) {
  // N column by column: the force and moment at body 1's closest point for a
  // unit relative velocity (body 1 translating) and a unit relative rotation
  // (body 1 rotating about its closest point), body 2 at rest
  Eigen::Matrix<Scalar, 6, 6> N;
  FilmSide one, two;
  one.arm = mobility.arm1;
  two.arm = mobility.arm2;
  for (int k = 0; k < 6; ++k) {
    const Vec3 e = Vec3::Unit(k % 3);
    one.velocity = k < 3 ? e : Vec3(-e.cross(mobility.arm1));
    one.angularVelocity = k < 3 ? Vec3::Zero() : e;
    const FilmLoads l = loads(one, two);
    N.col(k) << l.force1, l.torque1 - mobility.arm1.cross(l.force1);
  }
  // tr(N^T H N H) = sum over (i, j) of (N^T H)_ij (N H)_ji, and with H
  // symmetric (N^T H)_ij = (H N)_ji: the elementwise product of H N and N H
  const Eigen::Matrix<Scalar, 6, 6>& H = mobility.relative;
  const Scalar sum = (H * N).cwiseProduct(N * H).sum();
  return std::sqrt(std::max(sum, Scalar(0)));
}

}  // namespace collision
