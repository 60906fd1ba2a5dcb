#include "LongDoubleReference.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace testgeometry {

namespace {

using LD = long double;
using V = Eigen::Matrix<LD, 3, 1>;
using M = Eigen::Matrix<LD, 3, 3>;
using M2 = Eigen::Matrix<LD, 2, 2>;
using V2 = Eigen::Matrix<LD, 2, 1>;

constexpr LD kEpsLd = std::numeric_limits<LD>::epsilon();

struct Body {
  M R;   // columns: the body axes
  V a;   // semi-axes
  V c;   // centre
};

Body makeBody(const BodyInput& in) {
  Eigen::Quaternion<LD> q(LD(in.orientation.w()), LD(in.orientation.x()), LD(in.orientation.y()),
                          LD(in.orientation.z()));
  q.normalize();
  return Body{q.toRotationMatrix(), in.semiAxes.cast<LD>(), in.centre.cast<LD>()};
}

/// P n = R D^2 R^T n and the support radius |D R^T n|.
struct Support {
  V y;
  LD h;
};
Support support(const Body& b, const V& n) {
  const V d = (b.R.transpose() * n).cwiseProduct(b.a);
  return Support{b.R * d.cwiseProduct(b.a), d.norm()};
}

/// Q t = (P t - y (y.t)/h^2)/h: the curvature-radius tensor at the support point applied to t.
V curvature(const Body& b, const Support& s, const V& t) {
  const V Pt = b.R * (b.R.transpose() * t).cwiseProduct(b.a).cwiseProduct(b.a);
  return (Pt - s.y * (s.y.dot(t) / (s.h * s.h))) / s.h;
}

struct Point {
  V n;
  Support s1, s2;
  V x1, x2;
  LD L;
  LD U;
};

Point evaluate(const Body& b1, const Body& b2, const V& dr, const V& unitN) {
  Point p;
  p.n = unitN;
  p.s1 = support(b1, unitN);
  p.s2 = support(b2, unitN);
  p.x1 = b1.c + p.s1.y / p.s1.h;
  p.x2 = b2.c - p.s2.y / p.s2.h;
  p.L = unitN.dot(dr) - p.s1.h - p.s2.h;
  p.U = (p.x2 - p.x1).norm();
  return p;
}

void tangentBasis(const V& n, V& t1, V& t2) {
  int k = 0;
  if (std::abs(n[1]) < std::abs(n[k])) k = 1;
  if (std::abs(n[2]) < std::abs(n[k])) k = 2;
  V e = V::Zero();
  e[k] = 1;
  t1 = (e - n[k] * n).normalized();
  t2 = n.cross(t1);
}

}  // namespace

ReferenceBracket LongDoubleReference::distance(const BodyInput& in1, const BodyInput& in2,
                                               const ellipsoids::Vec3& start,
                                               long double targetWidth) const {
  const Body b1 = makeBody(in1), b2 = makeBody(in2);
  const V dr = b2.c - b1.c;
  Point p = evaluate(b1, b2, dr, start.cast<LD>().normalized());
  ReferenceBracket out;
  for (int it = 0; it < 200 && p.U - p.L > targetWidth / 4; ++it) {
    out.iterations = it + 1;
    V t1, t2;
    tangentBasis(p.n, t1, t2);
    const V v = p.x2 - p.x1;
    const V2 g(t1.dot(v), t2.dot(v));
    // minus the Hessian of L on the tangent plane: Q1 + Q2 + L I
    M2 H;
    const V q1 = curvature(b1, p.s1, t1) + curvature(b2, p.s2, t1);
    const V q2 = curvature(b1, p.s1, t2) + curvature(b2, p.s2, t2);
    H << t1.dot(q1) + p.L, t1.dot(q2), t2.dot(q1), t2.dot(q2) + p.L;
    H = LD(0.5) * (H + H.transpose()).eval();
    const LD lambdaMin = Eigen::SelfAdjointEigenSolver<M2>(H).eigenvalues()[0];
    const LD scale = H.cwiseAbs().maxCoeff();
    if (lambdaMin <= LD(1e-3) * scale) H += (LD(1e-3) * scale - lambdaMin) * M2::Identity();
    V2 step = H.ldlt().solve(g);
    if (step.norm() > LD(0.5)) step *= LD(0.5) / step.norm();
    bool moved = false;
    for (LD t = 1; t > LD(1e-18); t *= LD(0.5)) {
      const Point q = evaluate(b1, b2, dr, (p.n + t * (step[0] * t1 + step[1] * t2)).normalized());
      if (q.L > p.L || (q.L >= p.L && q.U < p.U)) {
        p = q;
        moved = true;
        break;
      }
    }
    if (!moved) break;  // no increase representable in long double
  }
  const LD rounding = 64 * kEpsLd *
                      (dr.norm() + b1.a.maxCoeff() + b2.a.maxCoeff() + p.x1.cwiseAbs().sum() +
                       p.x2.cwiseAbs().sum());
  out.direction = p.n.cast<double>();
  out.point1 = p.x1.cast<double>();
  out.point2 = p.x2.cast<double>();
  out.lower = p.L - rounding;
  out.upper = p.U + rounding;
  out.tight = out.upper - out.lower <= targetWidth;
  return out;
}

long double referenceTarget(const ellipsoids::Ellipsoid& e1, const ellipsoids::Ellipsoid& e2) {
  // written out, not roundingAllowance(): the reference must not move with the code under test
  const long double scale = (e2.centre() - e1.centre()).norm() + e1.maxOfMaxCurvatureRadius() +
                            e2.maxOfMaxCurvatureRadius() + e1.centre().cwiseAbs().sum() +
                            e2.centre().cwiseAbs().sum();
  return ellipsoids::kEps * scale / 8;
}

}  // namespace testgeometry
