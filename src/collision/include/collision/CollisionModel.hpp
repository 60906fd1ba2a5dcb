/**
 * @file CollisionModel.hpp
 * @brief Collision forces between spheroids and plane walls: pair search,
 *        overlap prefilter, certified distance, lubrication, soft contact.
 *
 * Per call (one body sub-step):
 *  1. candidate pairs from bounding spheres (largest semi-axis plus half the
 *     lubrication reach) and a cell list (PairSearch);
 *  2. prefilter: the axis-aligned boxes of the grown bodies below, then the
 *     exact algebraic test of Jia et al. on the bodies scaled
 *     about their centres by 1 + delta_i/a_min,i, which contain the bodies
 *     grown by delta_i (the support function grows by at least delta_i), so a
 *     separated answer proves the gap exceeds the reach delta_1 + delta_2 and
 *     no distance is computed (contact only: delta = 0, the bodies themselves);
 *  3. the signed distance by the dual method (the measured fastest at every
 *     aspect ratio and accuracy, what `auto` picks; it also gives the
 *     penetration depth and direction; if it does not converge, auto's other
 *     methods give the separated distance) to eps_d = distanceAccuracy x the
 *     smaller of the two bodies' smallest Gaussian curvature radii (founding
 *     paper eq. 1.6), warm-started from the pair's previous direction;
 *  4. contact (ContactLaw) at the midpoint of the two deepest points, with the
 *     pair's contact time set at the first touch,
 *         T_c = min(contactTime, pi maxOverlap a_min / |u_n|),
 *     a_min the smaller smallest semi-axis, u_n the impact speed: the overlap
 *     of the linear law stays below v T_c/pi <= maxOverlap a_min, so that fast
 *     bodies cannot pass through each other or a wall. k_n and eta_n are
 *     those of the effective mass at the first touch and stay fixed for the
 *     contact (a linear oscillator: its spring is conservative even while a
 *     turning spheroid moves the contact point; with k_n following the moving
 *     point's effective mass such impacts gained up to 6 % kinetic energy).
 *     While the bodies approach, the first touch's rule is applied again at
 *     every call: a body swinging into the contact after the touch (normal
 *     speed above the one T_c was made for) shortens T_c to pi D / |u_n|, D
 *     the overlap still allowed (at least half the cap), stiffening the
 *     spring from then on; the elastic force is integrated as dF = k_n
 *     d(delta) so that the stiffer spring never returns more work than it
 *     took (with the dashpot's pull off once F is spent);
 *  5. lubrication (LubricationLaw) with the Gaussian curvature radii at the
 *     closest points, between the activation and saturation gaps, held at its
 *     saturated value down to touching and off in contact (overlap);
 *  6. walls: exact spheroid-plane distances (PlaneWall), the same laws with a
 *     fixed, infinitely heavy wall.
 * subSteps() gives the number of body sub-steps a fluid step needs so that a
 * contact lasts at least subStepsPerContact sub-steps. Callers advance each
 * sub-step with Heun's predictor-corrector: forces at the start, a predicted
 * end state, forces there, and the step taken with the mean of the two
 * (validation/dryCollisions: the restitution error, worst over where the touch
 * falls in a sub-step, is about 0.35/subStepsPerContact in absolute terms:
 * e 0.97 -0.75 % at 10, -0.17 % at 20; e 0.5 -3.4 % at 20, -1.4 % at 50; the
 * medians are below 0.1 % from 20 for e >= 0.5; with the start forces only the
 * error is ~ 1.6/subStepsPerContact).
 * Non-convergence of a distance is never silent: it is counted in
 * statistics() (the last iterate is used, its certified bracket known) and a
 * non-finite force throws.
 */
#ifndef COLLISION_COLLISIONMODEL_HPP
#define COLLISION_COLLISIONMODEL_HPP

#include "collision/ContactLaw.hpp"
#include "collision/LubricationLaw.hpp"
#include "collision/PairSearch.hpp"
#include "collision/PlaneWall.hpp"
#include "ellipsoids/AutoDistance.hpp"
#include "ellipsoids/DualNewton.hpp"
#include "ellipsoids/Ellipsoid.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace collision {

enum class CollisionMode { none, contact, lubricationContact };

/// "none", "contact", "lubricationContact"
const char* toString(CollisionMode mode);
/// @throws std::invalid_argument naming the allowed values
CollisionMode collisionModeFromString(const std::string& name);

struct CollisionSettings {
  CollisionMode mode = CollisionMode::contact;
  ContactParameters contact;
  LubricationParameters lubrication;
  /// dynamic viscosity mu of the fluid (lubrication; >= 0)
  Scalar viscosity = 0;
  /// largest overlap allowed, as a fraction of the pair's smallest semi-axis, in (0, 0.5]
  Scalar maxOverlap = 0.1;
  /// body sub-steps per contact time, >= 4
  int subStepsPerContact = 10;
  /// eps_d / (smallest Gaussian curvature radius of the pair), in [1e-12, 1e-1]
  Scalar distanceAccuracy = 1e-5;
  /// largest number of sub-steps subSteps() may ask for
  int maxSubSteps = 100000;

  /// @throws std::invalid_argument naming the parameter and its allowed range
  void validate() const;
};

/// What the model needs to know of one body at the start of a sub-step.
struct CollisionBody {
  ellipsoids::Ellipsoid shape;
  Vec3 velocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();
  Scalar mass = 1;
  Mat3 inverseInertia = Mat3::Zero();  ///< world frame
  bool movable = true;                 ///< false: fixed (infinitely heavy)
};

struct CollisionStatistics {
  long candidatePairs = 0;     ///< from the bounding spheres
  long prefilterRejected = 0;  ///< proved out of reach (boxes or the overlap test)
  long boxRejected = 0;        ///< of which by the axis-aligned boxes of the grown bodies
  long distanceQueries = 0;
  long distanceIterations = 0;
  long distanceNotConverged = 0;  ///< answers taken from a non-converged iterate
  long contacts = 0;              ///< body-body contacts
  long wallContacts = 0;
  long lubricated = 0;            ///< pairs and wall pairs with a lubrication force
  long stiffened = 0;             ///< contact evaluations that raised k_n to keep the overlap cap
  Scalar maxOverlapRatio = 0;     ///< max overlap / smallest semi-axis of the pair
};

/// What the model remembers of one pair between calls (the restart state).
struct PairRecord {
  int first = 0;                  ///< body index
  int second = 0;                 ///< body index (> first), or -1 - wall index
  bool warm = false;              ///< has a warm-start direction (body pairs)
  Vec3 direction = Vec3::Zero();  ///< the pair's last distance direction
  Scalar contactTime = 0;         ///< > 0: in contact, with this contact time
  /// the contact's spring state (contactTime > 0): elastic force, the stiffness
  /// and the overlap of the last call; stiffness 0 = start from k delta
  Scalar springForce = 0;
  Scalar stiffness = 0;
  Scalar overlap = 0;
};

class CollisionModel {
 public:
  /// @throws std::invalid_argument on invalid settings or walls
  CollisionModel(const CollisionSettings& settings, std::vector<PlaneWall> walls);

  const CollisionSettings& settings() const { return settings_; }
  const std::vector<PlaneWall>& walls() const { return walls_; }

  /**
   * Sub-steps a fluid step dt needs (>= 1): dt/subSteps <= T_c,min/subStepsPerContact
   * with T_c,min the shorter of the contact time of the fastest possible impact
   * (twice the largest body speed plus rotation) and the contact times of the
   * contacts under way. 1 when the mode is none.
   * @throws std::runtime_error if more than maxSubSteps would be needed
   */
  int subSteps(const std::vector<CollisionBody>& bodies, Scalar dt, Scalar contactTime) const;

  /**
   * Collision forces and torques (about the centres) on every body for one
   * sub-step of length subDt; contactTime is the nominal T_c (N_c fluid steps).
   * The statistics of the call are added to statistics().
   * @throws std::runtime_error on a non-finite force (naming the bodies)
   */
  void forces(const std::vector<CollisionBody>& bodies, Scalar contactTime, Scalar subDt,
              std::vector<Vec3>& force, std::vector<Vec3>& torque);

  const CollisionStatistics& statistics() const { return statistics_; }
  void resetStatistics() { statistics_ = CollisionStatistics(); }

  /// Forget the warm starts and contact histories (e.g. after bodies were moved by hand).
  void clearHistory();

  /// The pairs' warm starts and contact times, sorted by (first, second).
  std::vector<PairRecord> history() const;
  /// Restore history() (e.g. on restart).
  /// @throws std::invalid_argument on a record with bad indices or values
  void setHistory(const std::vector<PairRecord>& records);

  /// Pairs in contact now (body-body and body-wall; walls are -1 - wall index).
  std::size_t activeContacts() const { return contact_.size(); }

 private:
  static std::uint64_t key(int i, int j) {
    return (std::uint64_t(std::uint32_t(i)) << 32) | std::uint32_t(j);
  }
  /// The interaction of bodies i, j (j < 0: wall -1 - j) at signed gap d.
  void interact(const std::vector<CollisionBody>& bodies, int i, int j, Scalar gap,
                const Vec3& n, const Vec3& p1, const Vec3& p2, Scalar contactTime, Scalar subDt,
                std::vector<Vec3>& force, std::vector<Vec3>& torque);

  CollisionSettings settings_;
  std::vector<PlaneWall> walls_;
  PairSearch search_;
  ellipsoids::DualNewton dual_;
  ellipsoids::AutoDistance fallback_;
  ellipsoids::JiaOverlapTest overlap_;
  std::vector<Vec3> centres_;
  std::vector<Scalar> radii_;
  std::vector<Scalar> reach_;
  std::vector<ellipsoids::Ellipsoid> grown_;
  std::vector<Vec3> halfExtent_;  ///< axis-aligned half extents of grown_
  /// warm-start direction of each pair seen last call
  std::unordered_map<std::uint64_t, Vec3> direction_, nextDirection_;
  /// What a contact under way carries from call to call.
  struct ContactState {
    Scalar contactTime = 0;  ///< T_c of the contact (shortened if the overlap needs it)
    Scalar springForce = 0;  ///< elastic normal force, updated incrementally
    Scalar stiffness = 0;    ///< k_n of the contact (0: set at the next call)
    Scalar overlap = 0;      ///< overlap of the last call
  };
  /// the state of each pair in contact
  std::unordered_map<std::uint64_t, ContactState> contact_, nextContact_;
  CollisionStatistics statistics_;
};

}  // namespace collision

#endif
