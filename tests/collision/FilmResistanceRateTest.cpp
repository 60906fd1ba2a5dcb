// filmResistanceRate: the Frobenius norm of D R D from the film's 6 x 6
// resistance and the mobility of the relative motion, against D R D assembled
// column by column from the 12 x 12 load matrix, for both film laws, generic
// spheroid pairs, anisotropic inertia, a wall and a fixed body.
#include "collision/CubicGapCoupling.hpp"
#include "collision/FilmResistanceRate.hpp"
#include "collision/TangentialLubrication.hpp"

#include "FilmLawSupport.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace collision;

namespace {

constexpr Scalar mu = 0.01;

/// A body's inverse mass and world-frame inverse inertia: a spheroid of
/// density 7800 with semi-axes a, b, b along e (a solid body's inertia).
struct Mobility {
  Scalar inverseMass;
  Mat3 inverseInertia;
};
Mobility spheroidMobility(Scalar a, Scalar b, const Vec3& e) {
  const Scalar m = 7800 * 4 / 3.0 * kPi * a * b * b;
  const Vec3 axis = e.normalized();
  const Mat3 along = axis * axis.transpose();
  const Mat3 I = m / 5 * (2 * b * b * along + (a * a + b * b) * (Mat3::Identity() - along));
  return {1 / m, I.inverse()};
}

/// |D R D|_F with R from the 12 x 12 load matrix and D the symmetric square
/// roots of the mobilities: the definition, column by column
Scalar frobeniusByColumns(const FilmLaw& law, const Vec3& arm1, const Mobility& b1,
                          const Vec3& arm2, const Mobility& b2) {
  const auto root = [](const Mat3& A) -> Mat3 {
    if (A.isZero(0)) return Mat3::Zero();
    return Eigen::SelfAdjointEigenSolver<Mat3>(A).operatorSqrt();
  };
  Eigen::Matrix<Scalar, 12, 12> D = Eigen::Matrix<Scalar, 12, 12>::Zero();
  D.block<3, 3>(0, 0) = Mat3::Identity() * std::sqrt(b1.inverseMass);
  D.block<3, 3>(3, 3) = root(b1.inverseInertia);
  D.block<3, 3>(6, 6) = Mat3::Identity() * std::sqrt(b2.inverseMass);
  D.block<3, 3>(9, 9) = root(b2.inverseInertia);
  const Mat12 table = loadMatrix(law, arm1, arm2);
  Eigen::Matrix<Scalar, 12, 12> R;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) R(i, j) = table[i][j];
  return (D * R * D).norm();
}

struct Case {
  const char* name;
  Touching first, second;
  Vec3 n;
  Mobility b1, b2;
};

std::vector<Case> cases() {
  const Vec3 n1 = Vec3(0.3, -0.5, 0.8).normalized(), n2 = Vec3(1, 1, 0.2).normalized();
  const Vec3 z = Vec3::UnitZ();
  const Mobility wall{0, Mat3::Zero()};
  return {
      {"prolate / oblate", spheroidAt(2.5e-3, 1e-3, Vec3(1, 0.2, 0), n1),
       spheroidAt(0.6e-3, 1.2e-3, Vec3(0, 1, 0.4), -n1), n1,
       spheroidMobility(2.5e-3, 1e-3, Vec3(1, 0.2, 0)),
       spheroidMobility(0.6e-3, 1.2e-3, Vec3(0, 1, 0.4))},
      {"prolate / prolate", spheroidAt(2.5e-3, 1e-3, Vec3(0.2, 1, 1), n2),
       spheroidAt(1.2e-3, 0.8e-3, Vec3(1, -0.7, 0.3), -n2), n2,
       spheroidMobility(2.5e-3, 1e-3, Vec3(0.2, 1, 1)),
       spheroidMobility(1.2e-3, 0.8e-3, Vec3(1, -0.7, 0.3))},
      {"tilted prolate / wall", spheroidAt(2e-3, 1e-3, Vec3(1, 0, 1), -z),
       {Mat3::Zero(), {Mat3::Zero(), Mat3::Zero(), Mat3::Zero()}, Vec3::Zero()}, -z,
       spheroidMobility(2e-3, 1e-3, Vec3(1, 0, 1)), wall},
      {"fixed prolate / sphere", spheroidAt(2e-3, 1e-3, Vec3(1, 1, 0), n1),
       spheroidAt(1e-3, 1e-3, Vec3::UnitX(), -n1), n1, wall,
       spheroidMobility(1e-3, 1e-3, Vec3::UnitX())},
  };
}

}  // namespace

TEST(FilmResistanceRate, EqualsTheFrobeniusNormOfDRDForBothFilmLaws) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const TangentialLubrication law(c.first.curvature, c.second.curvature, c.n, mu);
    const CubicGapCoupling coupling(c.first.curvature, c.second.curvature, c.first.third,
                                    c.second.third, c.n, mu);
    const FilmLaw laws[2] = {
        [&law](const FilmSide& one, const FilmSide& two) { return law.loads(1, one, two); },
        [&coupling](const FilmSide& one, const FilmSide& two) {
          return coupling.loads(1, one, two);
        }};
    const FilmMobility mobility(c.first.arm, c.b1.inverseMass, c.b1.inverseInertia,
                                c.second.arm, c.b2.inverseMass, c.b2.inverseInertia);
    for (const FilmLaw& l : laws) {
      const Scalar expected = frobeniusByColumns(l, c.first.arm, c.b1, c.second.arm, c.b2);
      ASSERT_GT(expected, 0);
      EXPECT_NEAR(filmResistanceRate(l, mobility), expected, 1e-12 * expected);
      EXPECT_NEAR(filmResistanceRate(l, c.first.arm, c.b1.inverseMass, c.b1.inverseInertia,
                                     c.second.arm, c.b2.inverseMass, c.b2.inverseInertia),
                  expected, 1e-12 * expected);
    }
    EXPECT_NEAR(law.rate(2.5, mobility),
                2.5 * frobeniusByColumns(laws[0], c.first.arm, c.b1, c.second.arm, c.b2),
                1e-12 * law.rate(2.5, mobility));
  }
}

TEST(FilmResistanceRate, ALawActingAwayFromTheClosestPointsIsNotOfTheFilmForm) {
  // a force at body 1's centre proportional to body 1's own velocity (a drag,
  // not a film law): R is not B^T N B, and the identity must not hold, so the
  // assertion above can tell the film form from any other
  const FilmLaw drag = [](const FilmSide& one, const FilmSide&) {
    FilmLoads l;
    l.force1 = -one.velocity;
    l.torque1 = -one.arm.cross(one.velocity);
    l.torque2 = Vec3::Zero();
    return l;
  };
  const Mobility body = spheroidMobility(2e-3, 1e-3, Vec3(1, 1, 0));
  const Vec3 arm1(1e-3, -0.5e-3, 0.2e-3), arm2(-0.8e-3, 0.1e-3, 0.4e-3);
  const Scalar expected = frobeniusByColumns(drag, arm1, body, arm2, body);
  const Scalar filmForm = filmResistanceRate(
      drag, FilmMobility(arm1, body.inverseMass, body.inverseInertia, arm2, body.inverseMass,
                         body.inverseInertia));
  EXPECT_GT(std::abs(filmForm - expected), 1e-3 * expected);
}
