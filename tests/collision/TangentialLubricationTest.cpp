// The logarithmic tangential lubrication terms (TangentialLubrication.hpp),
// from the gap's paraboloid: the ln(a/h) coefficients of Goldman, Cox and
// Brenner (1967) for a sphere and a plane and of Jeffrey and Onishi (1984)
// for two spheres; for spheroids in any orientation no load under a rigid
// motion of the pair, the same loads with the bodies' labels exchanged, one
// symmetric dissipative resistance matrix; and the terms as CollisionModel
// applies them to a sphere sliding over a wall and to two spheroids.
#include "collision/LubricationLaw.hpp"
#include "ellipsoids/Ellipsoid.hpp"
#include "collision/RigidBody.hpp"
#include "collision/TangentialLubrication.hpp"
#include "FilmLawSupport.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace collision;

namespace {

constexpr Scalar kInf = std::numeric_limits<Scalar>::infinity();
constexpr Scalar mu = 0.01, L = 2.5;

Mat12 resistance(const TangentialLubrication& law, const Vec3& arm1, const Vec3& arm2) {
  return loadMatrix([&](const FilmSide& one, const FilmSide& two) { return law.loads(L, one, two); },
                    arm1, arm2);
}

/// The loads on spheres of radii a1, a2 (a2 infinite: a plane at rest) with
/// the unit normal d from 1 to 2, for the motions of their centres.
FilmLoads sphereLoads(Scalar a1, Scalar a2, const Vec3& d, Scalar logFactor,
                                       const Vec3& u1, const Vec3& omega1, const Vec3& u2,
                                       const Vec3& omega2) {
  const TangentialLubrication law = TangentialLubrication::spheres(a1, a2, d, mu);
  const FilmSide second = std::isfinite(a2) ? FilmSide{-a2 * d, u2, omega2} : FilmSide{};
  return law.loads(logFactor, {a1 * d, u1, omega1}, second);
}

/// Two prolate spheroids (Ar 2.5 and 1.5) touching at the origin with the
/// normal d from the first to the second, their axes along e1, e2 (the
/// configurations of the invariance tests).
struct SpheroidPair {
  Touching first, second;
  Vec3 d;
};
SpheroidPair spheroidPair(const Vec3& d, const Vec3& e1, const Vec3& e2) {
  return {spheroidAt(2.5e-3, 1e-3, e1.normalized(), d), spheroidAt(1.2e-3, 0.8e-3, e2.normalized(), -d),
          d};
}
const SpheroidPair kPairs[] = {
    spheroidPair(Vec3(0.3, -0.5, 0.8).normalized(), Vec3(1, 0.2, 0), Vec3(0, 1, 0.4)),
    spheroidPair(Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0)),   // crossed, side by side
    spheroidPair(Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(1, 0, 0)),   // parallel
    spheroidPair(Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 1)),   // tip on side
};

TangentialLubrication lawOf(const SpheroidPair& p) {
  return TangentialLubrication(p.first.curvature, p.second.curvature, p.d, mu);
}

}  // namespace

TEST(TangentialLubrication, SphereAndPlaneGiveGoldmanCoxBrenner) {
  // sphere of radius a above a floor (d = -z, from the sphere to the plane)
  const Scalar a = 2e-3;
  const Vec3 d(0, 0, -1);
  auto load = [&](Scalar logFactor, const Vec3& u, const Vec3& omega) {
    return sphereLoads(a, kInf, d, logFactor, u, omega, Vec3::Zero(), Vec3::Zero());
  };
  const Scalar f0 = 6 * kPi * mu * a * L, t0 = 8 * kPi * mu * a * a * L;
  // translation U along x: drag (8/15) ln(a/h), torque (1/10) ln(a/h) in the rolling sense (+y)
  FilmLoads l = load(L, Vec3(1, 0, 0), Vec3::Zero());
  EXPECT_NEAR(l.force1.x(), -f0 * 8 / 15, 1e-15);
  EXPECT_NEAR(l.torque1.y(), t0 / 10, 1e-15);
  EXPECT_NEAR(l.force1.y() + l.force1.z() + l.torque1.x() + l.torque1.z(), 0, 1e-18);
  // rotation Omega about y (bottom surface moving along -x): force (2/15) a ln(a/h)
  // along +x, torque -(2/5) a ln(a/h) against the rotation
  l = load(L, Vec3::Zero(), Vec3(0, 1, 0));
  EXPECT_NEAR(l.force1.x(), f0 * a * 2 / 15, 1e-18);
  EXPECT_NEAR(l.torque1.y(), -t0 * a * 2 / 5, 1e-18);
  // rotation about the normal, motion along the normal: no logarithmic term
  l = load(L, Vec3(0, 0, 1), Vec3(0, 0, 1));
  EXPECT_LT(l.force1.norm() + l.torque1.norm(), 1e-15 * f0);
  EXPECT_EQ(load(0, Vec3(1, 0, 0), Vec3(0, 1, 0)).force1.norm(), 0);
}

TEST(TangentialLubrication, TwoSpheresGiveJeffreyOnishi) {
  // the ln(1/xi) coefficients of Y^A_11 (force), Y^C_11 and Y^C_12 (torques)
  // and -Y^B_11/2 (torque of a translation); the forces of the rotations
  // against the closed forms of Simeonov & Calantoni (2012)
  const Vec3 d(1, 0, 0);
  for (const Scalar beta : {0.3, 1.0, 2.0, 5.0}) {
    const Scalar a1 = 1e-3, a2 = beta * a1, b1 = 1 + beta;
    auto load = [&](const Vec3& u1, const Vec3& omega1, const Vec3& omega2) {
      return sphereLoads(a1, a2, d, L, u1, omega1, Vec3::Zero(), omega2);
    };
    const Scalar YA = 4.0 / 15 * beta * (2 + beta + 2 * beta * beta) / (b1 * b1 * b1);
    const Scalar YB = -1.0 / 5 * beta * (4 + beta) / (b1 * b1);
    const Scalar YC11 = 2.0 / 5 * beta / b1, YC12 = beta * beta / (10 * b1);
    const Scalar f0 = 6 * kPi * mu * a1 * L, t0 = 8 * kPi * mu * a1 * a1 * L;
    FilmLoads l = load(Vec3(0, 1, 0), Vec3::Zero(), Vec3::Zero());
    EXPECT_NEAR(l.force1.y(), -f0 * YA, 1e-15 * f0) << beta;
    EXPECT_NEAR(l.torque1.z(), t0 * YB / 2, 1e-15 * t0) << "d x u = +z: T1 = -t0 E z" << beta;
    l = load(Vec3::Zero(), Vec3(0, 0, 1), Vec3::Zero());
    EXPECT_NEAR(l.torque1.z(), -t0 * a1 * YC11, 1e-15 * t0 * a1) << beta;
    EXPECT_NEAR(l.force1.y(), f0 * a1 * YB * 2 / 3, 1e-15 * f0 * a1) << "Omega1 x d = +y" << beta;
    l = load(Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, 1));
    EXPECT_NEAR(l.torque1.z(), -t0 * a1 * YC12, 1e-15 * t0 * a1) << beta;
    EXPECT_NEAR(l.force1.y(), -f0 * a1 * 2 * beta * beta * (1 + 4 * beta) / (15 * b1 * b1),
                1e-15 * f0 * a1)
        << beta;
  }
  // equal spheres: Y^A_11 = (1/6) ln(1/xi)
  const TangentialLubrication equal = TangentialLubrication::spheres(1, 1, d, 1);
  EXPECT_NEAR(equal.loads(1, {d, Vec3(0, 0, 1), Vec3::Zero()}, {-d, Vec3::Zero(), Vec3::Zero()})
                  .force1.z(),
              -kPi, 1e-14);
}


TEST(TangentialLubrication, NoLoadUnderARigidMotionOfThePair) {
  // the pair translating and rotating as one rigid body about any point
  for (const SpheroidPair& p : kPairs) {
    const TangentialLubrication law = lawOf(p);
    expectNoLoadUnderRigidMotion(
        [&](const FilmSide& one, const FilmSide& two) { return law.loads(L, one, two); },
        p.first.arm, p.second.arm, 6 * kPi * mu * 1e-3 * L, 3);
  }
}

TEST(TangentialLubrication, ExchangingTheBodiesGivesTheSameLoads) {
  for (const SpheroidPair& p : kPairs) {
    const TangentialLubrication law = lawOf(p);
    const TangentialLubrication exchanged(p.second.curvature, p.first.curvature, -p.d, mu);
    expectSameLoadsExchanged(
        [&](const FilmSide& one, const FilmSide& two) { return law.loads(L, one, two); },
        [&](const FilmSide& one, const FilmSide& two) { return exchanged.loads(L, one, two); },
        p.first.arm, p.second.arm, 1e-3, 5);
  }
}

TEST(TangentialLubrication, OneSymmetricDissipativeResistance) {
  // spheres of three radius ratios and the spheroid pairs: the force-rotation
  // and torque-translation terms of one symmetric matrix (reciprocity), and
  // the loads never feed the motion
  const Vec3 d = Vec3(1, 2, -2).normalized();
  std::vector<std::pair<TangentialLubrication, std::array<Vec3, 2>>> cases;
  for (const Scalar a2 : {0.5e-3, 1e-3, 3e-3}) {
    cases.push_back({TangentialLubrication::spheres(1e-3, a2, d, mu), {1e-3 * d, -a2 * d}});
  }
  for (const SpheroidPair& p : kPairs) cases.push_back({lawOf(p), {p.first.arm, p.second.arm}});
  int which = 0;
  for (const auto& [law, arms] : cases) {
    const Mat12 R = resistance(law, arms[0], arms[1]);
    const Scalar scale = largestEntry(R);
    ASSERT_GT(scale, 0) << which;
    for (int row = 0; row < 12; ++row)
      for (int col = 0; col < row; ++col)
        EXPECT_NEAR(R[row][col], R[col][row], 1e-12 * scale) << which << " " << row << " " << col;
    // loads oppose the motion: the power q.R q is never positive, and some motions dissipate
    std::mt19937 rng(7);
    std::normal_distribution<Scalar> normal;
    Scalar largestDissipation = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      std::array<Scalar, 12> q;
      Scalar qq = 0;
      for (Scalar& v : q) {
        v = normal(rng);
        qq += v * v;
      }
      const Scalar p = power(R, q);
      EXPECT_LE(p, 1e-12 * scale * qq) << which;
      largestDissipation = std::max(largestDissipation, -p);
    }
    EXPECT_GT(largestDissipation, 0) << which;
    ++which;
  }
}

TEST(TangentialLubrication, TheSurfacesOrientationsSetTheSlidingResistance) {
  // two spheroids side by side (normal z), sliding along x: with their axes
  // parallel the shapes carried along cancel (S1 = S2 on the film) and only
  // the Couette film resists, 2 pi mu R L U with R = 1/sqrt(k1 k2) of the
  // gap; otherwise the resistance depends on the direction of sliding (most
  // for crossed axes), which the spheres of the Gaussian radii cannot give
  const Vec3 z = Vec3::UnitZ();
  const SpheroidPair parallel = spheroidPair(z, Vec3::UnitX(), Vec3::UnitX());
  const SpheroidPair crossed = spheroidPair(z, Vec3::UnitX(), Vec3::UnitY());
  auto slidingForce = [&](const SpheroidPair& p, const Vec3& u) {
    const TangentialLubrication law = lawOf(p);
    return law.loads(L, {p.first.arm, u, Vec3::Zero()}, {p.second.arm, Vec3::Zero(), Vec3::Zero()})
        .force1;
  };
  const TangentialLubrication same(spheroidAt(2e-3, 1e-3, Vec3::UnitX(), z).curvature,
                                   spheroidAt(2e-3, 1e-3, Vec3::UnitX(), -z).curvature, z, mu);
  const Vec3 fx = same.loads(L, {Vec3(0, 0, 1e-3), Vec3::UnitX(), Vec3::Zero()}, {}).force1;
  EXPECT_NEAR(fx.x(), -2 * kPi * mu * same.areaRadius() * L, 1e-14) << "S1 = S2";
  // the equal bodies' R: curvatures 2 (b/a^2) and 2/b along x and y
  EXPECT_NEAR(same.areaRadius(), 1 / std::sqrt(4 * (1e-3 / 4e-6) / 1e-3), 1e-15);
  const Vec3 px = slidingForce(parallel, Vec3::UnitX()), py = slidingForce(parallel, Vec3::UnitY());
  const Vec3 cx = slidingForce(crossed, Vec3::UnitX()), cy = slidingForce(crossed, Vec3::UnitY());
  // the two spheres of the Gaussian radii (2.5 and 1.2 mm on the spheroids' sides)
  const Vec3 g = sphereLoads(2.5e-3, 1.2e-3, z, L, Vec3::UnitX(), Vec3::Zero(), Vec3::Zero(),
                             Vec3::Zero())
                     .force1;
  auto inMm = [&](Scalar f) { return -f / (2 * kPi * mu * L) * 1e3; };
  std::printf("sliding resistance / (2 pi mu L) [mm]: parallel %.4g (x) %.4g (y), crossed %.4g "
              "(x) %.4g (y), spheres of the Gaussian radii %.4g\n",
              inMm(px.x()), inMm(py.y()), inMm(cx.x()), inMm(cy.y()), inMm(g.x()));
  EXPECT_LT(px.x(), 0);
  EXPECT_LT(cy.y(), 0);
  EXPECT_GT(std::abs(cx.x() / cy.y() - 1), 0.2) << "crossed: x and y differ";
  EXPECT_GT(std::abs(px.x() / py.y() - 1), 0.05) << "parallel: x and y differ";
  EXPECT_GT(std::abs(cy.y() / g.x() - 1), 0.15) << "not the Gaussian radii's spheres";
}

TEST(TangentialLubrication, RateAndBadArguments) {
  // a sphere of radius 1 mm over a plane: the translation's and the
  // rotation's blocks of D R D, two equal tangential eigenvalues each
  const Vec3 d(0, 0, -1), arm = 1e-3 * d;
  const TangentialLubrication law = TangentialLubrication::spheres(1e-3, kInf, d, mu);
  const Mat3 I = Mat3::Identity() * 1e6;
  EXPECT_EQ(law.rate(0, FilmMobility(arm, 1, I, Vec3::Zero(), 0, Mat3::Zero())), 0);
  EXPECT_NEAR(law.rate(L, FilmMobility(arm, 1, Mat3::Zero(), Vec3::Zero(), 0, Mat3::Zero())),
              std::sqrt(2.0) * 6 * kPi * mu * 1e-3 * L * 8 / 15, 1e-15);
  EXPECT_NEAR(law.rate(L, FilmMobility(arm, 0, I, Vec3::Zero(), 0, Mat3::Zero())),
              std::sqrt(2.0) * 8 * kPi * mu * 1e-9 * L * 2 / 5 * 1e6, 1e-12);
  EXPECT_THROW(TangentialLubrication::spheres(0, 1, d, mu), std::invalid_argument);
  EXPECT_THROW(TangentialLubrication::spheres(1, -1, d, mu), std::invalid_argument);
  EXPECT_THROW(TangentialLubrication::spheres(1, 1, d, 0), std::invalid_argument);
  EXPECT_THROW(TangentialLubrication(Mat3::Zero(), Mat3::Zero(), d, mu), std::invalid_argument)
      << "two planes have no film";
}

TEST(TangentialLubrication, LogFactorOfTheGapLaw) {
  LubricationParameters p;  // walls: activation 0.075 a, saturation 1e-3
  const Scalar a = 2e-3;
  const LubricationGapLaw law(a, kInf, mu, p);
  EXPECT_NEAR(law.logFactor(0.01 * a), std::log(7.5), 1e-14);
  EXPECT_NEAR(law.logFactor(1e-5 * a), std::log(75.0), 1e-14) << "frozen below saturation";
  EXPECT_NEAR(law.logFactor(0), std::log(75.0), 1e-14);
  EXPECT_EQ(law.logFactor(0.075 * a), 0);
  EXPECT_EQ(law.logFactor(-1e-6), 0) << "off in contact";
  EXPECT_EQ(LubricationGapLaw().logFactor(1e-6), 0);
}

TEST(TangentialLubrication, ASphereSlidingOverAWallIsHeldBackAndSpunUp) {
  // a sphere 0.01 a above the floor sliding along x: the collision model adds
  // the sphere-plane terms scaled by 1/(1 + dt rate), drag along -x and torque
  // along +y (rolling), with the wall's log factor ln(0.075/0.01)
  const Scalar a = 2e-3, dt = 1e-4, gap = 0.01 * a;
  RigidBody b;
  b.semiAxes = Vec3::Constant(a);
  b.centre = Vec3(0, 0, a + gap);
  b.velocity = Vec3(0.05, 0, 0);
  b.density = 2500;
  ModelSetup s;
  s.model = "lubricatedSpringDashpot";
  s.laws.viscosity = mu;
  for (const bool tangential : {true, false}) {
    s.laws.lubrication.tangential = tangential;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    std::vector<Vec3> F, T;
    model.forces({b.collisionBody()}, 10 * dt, dt, F, T);
    if (!tangential) {
      EXPECT_EQ(F[0].norm() + T[0].norm(), 0);
      continue;
    }
    const TangentialLubrication law = TangentialLubrication::spheres(a, kInf, -Vec3::UnitZ(), mu);
    const Scalar Lw = std::log(7.5);
    const CollisionBody cb = b.collisionBody();
    const Scalar relax = 1 / (1 + dt * law.rate(Lw, FilmMobility(-a * Vec3::UnitZ(), 1 / cb.mass,
                                                             cb.inverseInertia, Vec3::Zero(), 0,
                                                             Mat3::Zero())));
    EXPECT_GT(relax, 0.5) << "a case where the terms are resolved by the sub-step";
    EXPECT_LT(relax, 1);
    EXPECT_NEAR(F[0].x(), -relax * 6 * kPi * mu * a * Lw * 8 / 15 * 0.05, 1e-12 * std::abs(F[0].x()));
    EXPECT_NEAR(T[0].y(), relax * 8 * kPi * mu * a * a * Lw / 10 * 0.05, 1e-12 * std::abs(T[0].y()));
    EXPECT_NEAR(F[0].z(), 0, 1e-18) << "the normal term is dampingForces()'s";
  }
}
