// GapParaboloid: the local gap of two convex surfaces from their curvature
// tensors, and its squeeze radius against the sphere limits and the
// orientation of the principal directions; the lubrication law's leading term
// with that radius.
#include "collision/GapParaboloid.hpp"
#include "collision/LubricationLaw.hpp"
#include "ellipsoids/Ellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace collision;
using ellipsoids::Ellipsoid;

namespace {

/// curvature tensor with curvatures k1 along t1 and k2 along n x t1 (world frame)
Mat3 tangentTensor(const Vec3& n, const Vec3& t1, Scalar k1, Scalar k2) {
  const Vec3 t2 = n.cross(t1);
  return k1 * t1 * t1.transpose() + k2 * t2 * t2.transpose();
}

const Vec3 kNormal = Vec3(1, 2, 2) / 3;
const Vec3 kTangent = Vec3(2, -2, 1) / 3;  // normal to kNormal

}  // namespace

TEST(GapParaboloid, TwoSpheresGiveTheReducedRadius) {
  for (auto [a1, a2] : {std::pair<Scalar, Scalar>{1e-3, 1e-3}, {1e-3, 2.5e-3}, {0.4, 3.0}}) {
    const Mat3 S1 = tangentTensor(kNormal, kTangent, 1 / a1, 1 / a1);
    const Mat3 S2 = tangentTensor(-kNormal, kTangent, 1 / a2, 1 / a2);
    const GapParaboloid g = GapParaboloid::fromCurvatureTensors(S1, S2, kNormal);
    EXPECT_NEAR(g.k1, 1 / a1 + 1 / a2, 1e-13 * (1 / a1 + 1 / a2));
    EXPECT_NEAR(g.k2, 1 / a1 + 1 / a2, 1e-13 * (1 / a1 + 1 / a2));
    EXPECT_NEAR(g.squeezeRadius(), a1 * a2 / (a1 + a2), 1e-13 * a1);
  }
}

TEST(GapParaboloid, ASphereAndAPlaneGiveItsRadius) {
  const Scalar a = 2e-3;
  const GapParaboloid g =
      GapParaboloid::fromCurvatureTensors(tangentTensor(kNormal, kTangent, 1 / a, 1 / a), Mat3::Zero(), kNormal);
  EXPECT_NEAR(g.squeezeRadius(), a, 1e-15);
}

TEST(GapParaboloid, AnisotropicGapMatchesTheClosedForm) {
  // principal radii Rx, Ry against a plane: R*^2 = 2 (Rx Ry)^(3/2)/(Rx + Ry)
  for (auto [rx, ry] : {std::pair<Scalar, Scalar>{1, 4}, {0.5, 0.5}, {1, 100}}) {
    const GapParaboloid g = GapParaboloid::fromCurvatureTensors(
        tangentTensor(kNormal, kTangent, 1 / rx, 1 / ry), Mat3::Zero(), kNormal);
    EXPECT_NEAR(g.k1, 1 / std::max(rx, ry), 1e-14);
    EXPECT_NEAR(g.k2, 1 / std::min(rx, ry), 1e-13);
    const Scalar expected = std::sqrt(2 * std::pow(rx * ry, 1.5) / (rx + ry));
    EXPECT_NEAR(g.squeezeRadius(), expected, 1e-13 * expected);
  }
}

TEST(GapParaboloid, ThePrincipalDirectionsOrientationMatters) {
  // two equal 'cylinders' (curvatures 1 and 0.01): parallel, the gap is a
  // trough (k 2 and 0.02); crossed, it is nearly round (k about 1.01 both):
  // the same Gaussian radii, squeeze radii 2.2 times apart
  const Scalar kBig = 1, kSmall = 0.01;
  const Vec3 t2 = kNormal.cross(kTangent);
  const Mat3 S1 = tangentTensor(kNormal, kTangent, kBig, kSmall);
  const Mat3 parallel = tangentTensor(kNormal, kTangent, kBig, kSmall);
  const Mat3 crossed = tangentTensor(kNormal, t2, kBig, kSmall);
  const GapParaboloid gp = GapParaboloid::fromCurvatureTensors(S1, parallel, kNormal);
  const GapParaboloid gc = GapParaboloid::fromCurvatureTensors(S1, crossed, kNormal);
  EXPECT_NEAR(gp.k1, 2 * kSmall, 1e-14);
  EXPECT_NEAR(gp.k2, 2 * kBig, 1e-14);
  EXPECT_NEAR(gc.k1, kBig + kSmall, 1e-14);
  EXPECT_NEAR(gc.k2, kBig + kSmall, 1e-14);
  const Scalar parallelRadius = std::sqrt(2 / (std::sqrt(4 * kBig * kSmall) * 2 * (kBig + kSmall)));
  EXPECT_NEAR(gp.squeezeRadius(), parallelRadius, 1e-12 * parallelRadius);
  EXPECT_NEAR(gc.squeezeRadius(), 1 / (kBig + kSmall), 1e-12);
  EXPECT_GT(gp.squeezeRadius() / gc.squeezeRadius(), 2);
}

TEST(GapParaboloid, TwoSpheroidsFromTheirSurfaces) {
  // prolate spheroids (a 2, b 1) side by side along y, touching at their
  // equators: with parallel axes the gap's curvatures are 2 b/a^2 along the
  // axes and 2/b around; with the second turned 90 degrees about y they are
  // 1/b + b/a^2 in both directions
  const Scalar a = 2, b = 1;
  const Ellipsoid e1(Vec3(a, b, b), Vec3::Zero(), ellipsoids::Quat::Identity());
  const Vec3 n(0, 1, 0);
  const Ellipsoid parallel(Vec3(a, b, b), Vec3(0, 2 * b + 0.1, 0), ellipsoids::Quat::Identity());
  const ellipsoids::Quat turn(Eigen::AngleAxisd(ellipsoids::kPi / 2, n));
  const Ellipsoid crossed(Vec3(a, b, b), Vec3(0, 2 * b + 0.1, 0), turn);
  const Vec3 p1(0, b, 0), p2(0, b + 0.1, 0);
  const GapParaboloid gp = GapParaboloid::fromCurvatureTensors(e1.curvatureTensor(p1), parallel.curvatureTensor(p2), n);
  const GapParaboloid gc = GapParaboloid::fromCurvatureTensors(e1.curvatureTensor(p1), crossed.curvatureTensor(p2), n);
  EXPECT_NEAR(gp.k1, 2 * b / (a * a), 1e-14);
  EXPECT_NEAR(gp.k2, 2 / b, 1e-14);
  EXPECT_NEAR(gc.k1, 1 / b + b / (a * a), 1e-14);
  EXPECT_NEAR(gc.k2, 1 / b + b / (a * a), 1e-14);
  // squeeze radii sqrt(0.8) b and 0.8 b; the Gaussian radii (a each) combined
  // as two spheres give a/2 = b for both
  EXPECT_NEAR(gp.squeezeRadius(), std::sqrt(0.8) * b, 1e-14);
  EXPECT_NEAR(gc.squeezeRadius(), 0.8 * b, 1e-14);
  const Scalar gaussian = e1.curvatureRadii(p1).gaussian;
  EXPECT_NEAR(gaussian * gaussian / (2 * gaussian), b, 1e-14);
}

TEST(GapParaboloid, TwoPlanesOrAConcaveSumStopWithAMessage) {
  try {
    GapParaboloid::fromCurvatureTensors(Mat3::Zero(), Mat3::Zero(), kNormal);
    FAIL() << "two planes were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("k1 = 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(GapParaboloid::fromCurvatureTensors(tangentTensor(kNormal, kTangent, 1, -2), Mat3::Zero(), kNormal),
               std::invalid_argument);
}

TEST(GapParaboloid, TheLawsLeadingTermIsTheParaboloidsSqueezeForce) {
  // c(h) -> 6 pi mu R*^2/h at small gaps; the logarithmic terms are the
  // spheres' (the same for any R*), and R* = the spheres' value is the
  // spheres' law exactly
  LubricationParameters p;
  p.saturation = 1e-9;
  const Scalar mu = 0.02, a = 2e-3;
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  for (Scalar a2 : {inf, a, 2.5 * a}) {
    const Scalar sphere = std::isinf(a2) ? a : a * a2 / (a + a2);
    for (Scalar factor : {0.5, 1.0, 3.0}) {
      const Scalar rStar = factor * sphere;
      const LubricationGapLaw law(a, a2, mu, p, rStar);
      const LubricationGapLaw spheres(a, a2, mu, p);
      for (Scalar h : {1e-8 * a, 1e-6 * a, 1e-4 * a}) {
        const Scalar difference = law.coefficient(h) - spheres.coefficient(h);
        const Scalar leadingDifference = 6 * kPi * mu * (rStar * rStar - sphere * sphere) / h;
        // the activation offset differs too: lambda(x_act) scales with the leading term
        const Scalar x = std::isinf(a2) ? p.wallActivation * a : 0.5 * p.pairActivation * (a + a2);
        const Scalar offset = 6 * kPi * mu * (rStar * rStar - sphere * sphere) / x;
        EXPECT_NEAR(difference, leadingDifference - offset, 1e-9 * spheres.coefficient(h)) << a2 << " " << h;
      }
      // the primitive stays the integral of the coefficient
      const Scalar h = 1e-3 * a, dh = 1e-7 * h;
      EXPECT_NEAR((law.primitive(h + dh) - law.primitive(h)) / dh, law.coefficient(h + dh / 2),
                  1e-6 * law.coefficient(h));
      if (factor == 1.0) {
        EXPECT_EQ(law.coefficient(h), spheres.coefficient(h));
        EXPECT_EQ(law.primitive(h), spheres.primitive(h));
      }
    }
  }
}
