/**
 * @file FclPeer.hpp
 * @brief FCL 0.7 (Debian's libfcl-dev) as a peer of our distance methods:
 *        fcl::Ellipsoid<double> pairs through fcl::distance with one of its two
 *        GJK solvers (libccd's GJK, or FCL's own "indep" GJK).
 *
 * This header does not include FCL (the FCL objects live behind a pointer), so
 * only FclPeer.cpp needs FCL's headers; the executable links the CMake target
 * `fcl` (find_package(fcl REQUIRED), which brings libccd and octomap).
 *
 * What FCL 0.7 does for an ellipsoid-ellipsoid distance (read from its headers):
 * - fcl::Ellipsoid(a, b, c) has the radii along its local x, y, z axes and the
 *   body pose is a Transform3 (x_world = R x_local + t): with R = our U
 *   (Ellipsoid::rotation()) and t = our centre, the two descriptions agree.
 * - Both solvers return the nearest points in the world frame (libccd works in
 *   world coordinates; indep works in body 1's frame and maps back with tf1).
 *   They are convex combinations of support points (the GJK simplex), so they
 *   lie slightly inside the surfaces, by about the solver's own error.
 * - A negative answer (-1) means "in contact / overlapping" or "solver did not
 *   converge within its iteration limit": FCL does not tell which. Result::ok is
 *   false then. Separated pairs come back -1 when the gap is tiny: indep below
 *   its tolerance (default 1e-6: gaps up to ~1e-6 R_eq), libccd when its
 *   intersection test (__ccdGJK) says overlap (seen up to gap 2e-10 R_eq).
 * - DistanceRequest::rel_err / abs_err only matter for BVH models and
 *   enable_nearest_points is not read on the shape-shape path (nearest points
 *   are always computed); what controls accuracy is the solver's tolerance
 *   (libccd: GJKSolver_libccd::distance_tolerance; indep:
 *   GJKSolver_indep::gjk_tolerance; both set from DistanceRequest::distance_tolerance
 *   by the request-only fcl::distance) and its iteration limit
 *   (max_distance_iterations / gjk_max_iterations), which the request-only
 *   fcl::distance cannot change; so this adapter keeps its own solver objects
 *   and calls fcl::distance(geom1, tf1, geom2, tf2, &solver, request, result).
 * See FclPeer.cpp (parameters()) for the two settings and why.
 */
#ifndef PEERS_FCLPEER_HPP
#define PEERS_FCLPEER_HPP

#include "ellipsoids/Ellipsoid.hpp"

#include <memory>
#include <string>

namespace peers {

/// FCL 0.7 distance between ellipsoids (fcl::Ellipsoid<double>), one of its two GJK solvers.
class FclPeer {
 public:
  enum class Solver { libccd, indep };  // fcl::GST_LIBCCD, fcl::GST_INDEP
  /**
   * defaults: what fcl::distance(geom1, tf1, geom2, tf2, DistanceRequest<double>(true), result)
   * does: tolerance 1e-6 for either solver; iteration limits libccd 1000, indep 128.
   * bestAccurate: tolerance 1e-14 for both solvers (where their accuracy stops
   * improving; tighter only costs iterations, and 0 never converges), iteration
   * limits libccd 1000, indep 256 (pairs need <= ~40 and <= ~80). See parameters().
   */
  enum class Settings { defaults, bestAccurate };

  /// The solver parameters that control accuracy and run time.
  struct Parameters {
    double tolerance;            ///< libccd distance_tolerance / indep gjk_tolerance
    unsigned maxIterations;      ///< libccd max_distance_iterations / indep gjk_max_iterations
  };
  /// The parameters of a named setting.
  static Parameters parameters(Solver solver, Settings settings);

  FclPeer(Solver solver, Settings settings);
  /// Any parameters (for parameter sweeps); name() then says them.
  FclPeer(Solver solver, const Parameters& parameters);

  /// e.g. "fcl-libccd-accurate", "fcl-indep-default", "fcl-libccd-tol1e-10-it2000"
  std::string name() const;
  Solver solver() const { return solver_; }
  const Parameters& parameters() const { return parameters_; }

  /// Per-body precomputation, outside any timed region: the FCL geometry and its transform.
  class Body {
   public:
    Body() = default;
   private:
    friend class FclPeer;
    struct Data;
    std::shared_ptr<const Data> data_;
  };
  Body makeBody(const ellipsoids::Ellipsoid& e) const;

  struct Result {
    double distance = -1;            ///< FCL's distance; -1 when !ok
    ellipsoids::Vec3 point1 = ellipsoids::Vec3::Zero();  ///< nearest point on body 1 (world frame)
    ellipsoids::Vec3 point2 = ellipsoids::Vec3::Zero();  ///< nearest point on body 2 (world frame)
    bool ok = false;                 ///< false: FCL returned a negative distance (contact or no convergence)
  };
  /// One distance query (this is what gets timed): no allocation beyond what FCL
  /// itself does (libccd: one small heap object per body per query).
  Result distance(const Body& b1, const Body& b2) const;

 private:
  struct Solvers;
  Solver solver_;
  Parameters parameters_;
  std::string name_;
  std::shared_ptr<const Solvers> solvers_;
};

}  // namespace peers

#endif
