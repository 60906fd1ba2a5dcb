/**
 * @file FclPeer.cpp
 * @brief FCL 0.7 peer: see FclPeer.hpp.
 */
#include "FclPeer.hpp"

#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/narrowphase/distance.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace peers {

struct FclPeer::Body::Data {
  explicit Data(const ellipsoids::Ellipsoid& e)
      : shape(e.semiAxes()), tf(fcl::Transform3d::Identity()) {
    tf.linear() = e.rotation();       // columns: body axes in the world frame
    tf.translation() = e.centre();    // x_world = U x_body + r
  }
  fcl::Ellipsoidd shape;              // radii (a, b, c) along local x, y, z
  fcl::Transform3d tf;
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

struct FclPeer::Solvers {
  fcl::detail::GJKSolver_libccdd libccd;
  fcl::detail::GJKSolver_indepd indep;
  fcl::DistanceRequestd request;
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

FclPeer::Parameters FclPeer::parameters(Solver solver, Settings settings) {
  if (settings == Settings::defaults) {
    // fcl::distance(geom, tf, geom, tf, DistanceRequest<double>(), result):
    // a default-constructed solver whose tolerance is set to
    // DistanceRequest::distance_tolerance = 1e-6; iteration limits are the
    // solvers' defaults (GJKSolver_libccd: 1000, GJKSolver_indep: 128).
    return solver == Solver::libccd ? Parameters{1e-6, 1000} : Parameters{1e-6, 128};
  }
  // bestAccurate, chosen by measurement (equal-volume spheroids, D_eq = 1,
  // Ar 1/6..6, gaps 0..0.2 R_eq and 1e-12..1e-3 R_eq; reference: our dual
  // method at epsD = 1e-13). Tolerance 1e-14 for both solvers; iteration
  // limits far above what any pair needed.
  //
  // libccd (_ccdDist): stops when a GJK step improves the distance by less
  //   than distance_tolerance (absolute), or when the new support point's
  //   norm is within it of the current distance. From ~1e-11 down the answers
  //   no longer change (same iterations, same error, ~1e-7 R_eq at worst):
  //   98% of the queries end on a stall, an improvement of exactly 0 (near
  //   convergence the tetrahedron is nearly flat and simplexReduceToTriangle
  //   finds none of the faces through the new support point closer, by
  //   libccd's point-triangle distance, so it keeps the old triangle), not on
  //   the tolerance. Any tolerance > 0 returns (1e-20 too); exactly 0 never
  //   does: the stall (0 < 0 is false) repeats until the iteration limit and
  //   the query returns -1.
  //   Iterations needed: <= 39 (mean 29); limit kept at FCL's 1000.
  //
  // indep (GJK<S>::evaluate): stops on |ray| < tol (reported as contact, -1:
  //   so the tolerance is also the smallest gap it can see), on a new support
  //   point within sqrt(tol) of one of the last four (squaredNorm() < tol), or
  //   on the relative duality gap (|ray| - max w.ray/|ray|) <= tol |ray|.
  //   The error falls with the tolerance down to 1e-14 (max ~1e-13 R_eq, the
  //   reference's own level); tighter tolerances only add iterations (1e-16:
  //   +12%); 0 never stops on 1% of the pairs (iteration limit, -1).
  //   Iterations needed at 1e-14: <= 74 (mean ~50-58); limit raised from
  //   FCL's 128 to 256 for margin.
  return solver == Solver::libccd ? Parameters{1e-14, 1000} : Parameters{1e-14, 256};
}

namespace {

std::string settingName(FclPeer::Solver solver, const FclPeer::Parameters& p) {
  const auto def = FclPeer::parameters(solver, FclPeer::Settings::defaults);
  const auto acc = FclPeer::parameters(solver, FclPeer::Settings::bestAccurate);
  const std::string base = solver == FclPeer::Solver::libccd ? "fcl-libccd" : "fcl-indep";
  if (p.tolerance == def.tolerance && p.maxIterations == def.maxIterations) return base + "-default";
  if (p.tolerance == acc.tolerance && p.maxIterations == acc.maxIterations) return base + "-accurate";
  char buf[64];
  std::snprintf(buf, sizeof buf, "-tol%.0e-it%u", p.tolerance, p.maxIterations);
  return base + buf;
}

}  // namespace

FclPeer::FclPeer(Solver solver, Settings settings)
    : FclPeer(solver, parameters(solver, settings)) {}

FclPeer::FclPeer(Solver solver, const Parameters& p)
    : solver_(solver), parameters_(p), name_(settingName(solver, p)) {
  if (!(p.tolerance >= 0) || p.maxIterations == 0)
    throw std::invalid_argument("FclPeer: tolerance must be >= 0 and maxIterations > 0");
  auto s = std::make_shared<Solvers>();
  s->libccd.distance_tolerance = p.tolerance;
  s->libccd.max_distance_iterations = p.maxIterations;
  s->indep.gjk_tolerance = p.tolerance;
  s->indep.gjk_max_iterations = p.maxIterations;
  s->request.enable_nearest_points = true;      // not read on the shape-shape path, but say it
  s->request.enable_signed_distance = false;    // separated pairs: plain GJK distance
  s->request.distance_tolerance = p.tolerance;  // only read by the request-only fcl::distance
  s->request.gjk_solver_type = solver == Solver::libccd ? fcl::GST_LIBCCD : fcl::GST_INDEP;
  solvers_ = std::move(s);
}

std::string FclPeer::name() const { return name_; }

FclPeer::Body FclPeer::makeBody(const ellipsoids::Ellipsoid& e) const {
  Body b;
  b.data_ = std::make_shared<Body::Data>(e);
  return b;
}

// fcl::distance with a caller-supplied solver is a template with no extern
// instantiation in libfcl: FCL's whole ellipsoid-ellipsoid GJK (both solvers)
// is compiled here, with this file's flags. Build it optimised (Release,
// -O3 -DNDEBUG as the project does) or FCL's times mean nothing.
FclPeer::Result FclPeer::distance(const Body& b1, const Body& b2) const {
  const Body::Data& d1 = *b1.data_;
  const Body::Data& d2 = *b2.data_;
  fcl::DistanceResultd r;
  double d;
  if (solver_ == Solver::libccd)
    d = fcl::distance(&d1.shape, d1.tf, &d2.shape, d2.tf, &solvers_->libccd, solvers_->request, r);
  else
    d = fcl::distance(&d1.shape, d1.tf, &d2.shape, d2.tf, &solvers_->indep, solvers_->request, r);
  Result out;
  out.ok = std::isfinite(d) && d >= 0;
  out.distance = out.ok ? d : -1.0;
  out.point1 = r.nearest_points[0];  // world frame (both solvers, FCL 0.7)
  out.point2 = r.nearest_points[1];
  return out;
}

}  // namespace peers
