/**
 * @file CollisionModel.hpp
 * @brief Collision forces between spheroids and plane walls: pair search,
 *        overlap prefilter, certified distance, and the pair and wall models.
 *
 * Per call of forces() (one evaluation in a body sub-step):
 *  1. candidate pairs from bounding spheres and a cell list (PairSearch),
 *     through the minimum image of the second body along periodic axes
 *     (setPeriodicBox; the pair's histories are kept per image);
 *  2. prefilter: axis-aligned boxes of the bodies grown by their reach (the
 *     pair model's lubrication and the film gap), then the Jia et al.
 *     overlap test on the grown bodies;
 *  3. the distance by the method distanceMethod names (default the signed
 *     dual method) to eps_d = distanceAccuracy x the pair's smallest Gaussian
 *     curvature radius, certified stop, warm-started from the pair's previous
 *     direction where the method can; a pair an unsigned method finds
 *     overlapping, or whose bracket reaches down to 0, gets its sign and
 *     penetration depth from the signed dual method;
 *  4. the pair model (PairModel: normal contact, friction) on each pair in
 *     contact; its lubrication law and the film correction (FilmCorrection,
 *     if given) recorded as damped pairs, applied implicitly by dampingForces();
 *  5. walls: the wall model (WallModel) against exact spheroid-plane distances.
 * SubStepper takes each body sub-step through forces() and dampingForces().
 * In a parallel run (setWorkShare) each process finds the pairs whose first
 * body it owns (step 1 from those bodies' cells; evaluated bodies only, when
 * given), computes steps 2-5 for them and keeps their histories; one
 * collective per call gives every process the summed forces, the load sums
 * of the next call and the damped pairs (sorted by key), so that the damping
 * solve and the bodies' motion are the same on every process.
 * The laws and their constants: docs/collisions.md. A distance that does
 * not converge is counted in statistics() (the last iterate is used); a
 * non-finite force throws.
 *
 * Usage (CollisionSettings; defaults and ranges are its members and k...Range constants):
 * | setting            | meaning                                       | default | range |
 * |--------------------|-----------------------------------------------|---------|-------|
 * | maxOverlap         | largest overlap / smallest semi-axis of the pair | 0.1  | (0, 0.5] |
 * | subStepsPerContact | body sub-steps per contact time               | 10      | [4, 10000] |
 * | distanceAccuracy   | eps_d / smallest Gaussian curvature radius    | 1e-5    | [1e-12, 0.1] |
 * | maxSubSteps        | bound on the sub-steps subSteps() may ask for | 100000  | [1, 1e9] |
 * | approachContactTimeScale | shortest stiffened contact time / subStepsPerContact sub-steps | 1 | [0.25, 4] |
 * | distanceMethod     | distance method of step 3 (distanceMethods()) | dual    | dual, paper, auto, gjk, movingBalls |
 *
 * See also: PairModel, WallModel, FilmCorrection, SubStepper.
 */
#ifndef COLLISION_COLLISIONMODEL_HPP
#define COLLISION_COLLISIONMODEL_HPP

#include "collision/FilmCorrection.hpp"
#include "collision/PairModel.hpp"
#include "collision/PairKey.hpp"
#include "collision/PairSearch.hpp"
#include "collision/PeriodicBox.hpp"
#include "collision/PlaneWall.hpp"
#include "collision/WallModel.hpp"
#include "collision/WorkShare.hpp"
#include "ellipsoids/AutoDistance.hpp"
#include "ellipsoids/DualNewton.hpp"
#include "ellipsoids/Ellipsoid.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <cstdint>
#include <stdexcept>
#include <memory>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace collision {

/// The defaults are the member initialisers, the allowed values the k...Range constants.
struct CollisionSettings {
  /// largest overlap allowed, as a fraction of the pair's smallest semi-axis, in kMaxOverlapRange
  Scalar maxOverlap = 0.1;
  static constexpr Range kMaxOverlapRange{0, 0.5, true, false};
  /// body sub-steps per contact time, an integer in kSubStepsPerContactRange
  int subStepsPerContact = 10;
  static constexpr Range kSubStepsPerContactRange{4, 10000};
  /// eps_d / (smallest Gaussian curvature radius of the pair), in kDistanceAccuracyRange
  Scalar distanceAccuracy = 1e-5;
  static constexpr Range kDistanceAccuracyRange{1e-12, 0.1};
  /// largest number of sub-steps subSteps() may ask for, an integer in kMaxSubStepsRange
  int maxSubSteps = 100000;
  static constexpr Range kMaxSubStepsRange{1, 1e9};
  /// the shortest contact time the approach check (SpringDashpotContact) may
  /// stiffen a spring to, in units of subStepsPerContact sub-steps of the
  /// current sub-step, in kApproachContactTimeScaleRange. 1: a stiffened
  /// contact keeps the resolution the settings ask for, so it needs no more
  /// sub-steps in the next step. A setting for sensitivity studies
  /// (validation/dryCollisions): below 1 the stiffened contacts are
  /// under-resolved and raise the next step's sub-steps, which can stiffen
  /// them again; above 1 the check stiffens less and the cap holds less
  Scalar approachContactTimeScale = 1;
  static constexpr Range kApproachContactTimeScaleRange{0.25, 4};
  /// the distance method of each pair, one of distanceMethods(): dual (signed),
  /// paper (the founding paper's: Moving Balls for 1/3 < Ar < 3, GJK otherwise),
  /// auto, or a single method that can serve (certified stop): gjk, movingBalls
  std::string distanceMethod = "dual";

  /// the names distanceMethod accepts, the default first
  static const std::vector<std::string>& distanceMethods();

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
  bool stationary = false;             ///< keeps its place while its velocities are imposed
                                       ///< (a frozen prescribed body): its gaps do not change
  /// the thickness below which the flow solver cannot resolve a film at this
  /// body (its cell size; FilmCorrection); 0: no film correction
  Scalar filmGap = 0;
  /// the flow's cell size at this body, for the resolved-gap lubrication
  /// (LubricationParameters::activationRatio; a pair's is the larger of its
  /// bodies'); 0: unknown (the resolved-gap form is then an error)
  Scalar cellSize = 0;
  /// every force on the body but the collision forces (weight less buoyancy,
  /// the flow): the sustained load it brings to its contacts
  Vec3 externalForce = Vec3::Zero();
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
  long filmPairs = 0;             ///< pairs and wall pairs closer than their film gap
  long dampingSolves = 0;         ///< dampingForces() calls with damped pairs
  long dampingSweeps = 0;         ///< Gauss-Seidel sweeps over the pairs in those calls
  long dampingNotConverged = 0;   ///< solves stopped at the sweep limit (last iterate used)
  long lubricationNotConverged = 0;  ///< a pair's end-speed equation stopped at its iteration limit
  Scalar maxOverlapRatio = 0;     ///< max overlap / smallest semi-axis of the pair
};

/// A pair damped implicitly (lubrication, film correction), recorded by forces() at the start of a sub-step.
struct DampedPair {
  int first = 0;                ///< body index
  int second = 0;               ///< body index, or -1 - wall index
  Vec3 normal = Vec3::Zero();   ///< unit normal from first to second
  Vec3 arm1 = Vec3::Zero();     ///< from the first body's centre to the point between the closest points
  Vec3 arm2 = Vec3::Zero();     ///< the same from the second body's centre (unused for a wall)
  Scalar lubrication = 0;       ///< c >= 0 at the start gap: the force on second -c u_n normal
  Scalar film = 0;              ///< D >= 0 (FilmCorrection): the force on second -D (u_n - u_n,ref) normal
  /// the lubrication correction applies over this sub-step: its impulse is the
  /// integral of c over the gap path from gap to gap + u_n(end) subDt
  bool lubricated = false;
  Scalar gap = 0;               ///< the surface gap at the start of the sub-step (any sign)
  Scalar radius1 = 0;           ///< the curvature radii of the lubrication law
  Scalar radius2 = 0;           ///< (infinite for a wall)
  LubricationGapLaw law;        ///< the correction against the gap (lubricated pairs)
  Scalar startPrimitive = 0;    ///< law.primitive(gap)
  /// set by dampingForces(): the mean c over the sub-step's gap path, the
  /// coefficient the solve applied (-c_mean u_n(end))
  Scalar lubricationMean = 0;
  /// the pair's key (the bodies and the image of the second)
  std::uint64_t key = 0;
};

/// Bodies that may interact within a fluid step, and the sub-steps they need (CollisionModel::islands).
struct Island {
  std::vector<int> bodies;  ///< ascending body indices
  /// subSteps() for these bodies and their contacts alone (1 if they do not interact)
  int subSteps = 1;
  /// two or more bodies, or a body within reach of a wall: the collision
  /// forces are evaluated; otherwise the body moves under its other forces
  bool interacts = false;
};

/// A step that needs more sub-steps than maxSubSteps (CollisionModel::subSteps, islands).
struct TooManySubSteps : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What the model remembers of one pair between calls (the restart state).
struct PairRecord {
  int first = 0;                  ///< body index
  int second = 0;                 ///< body index (> first), or -1 - wall index
  /// the image of second the pair meets through: multiples of the periods
  /// (PeriodicBox; all 0 without periodic axes and for walls)
  std::array<int, 3> image{0, 0, 0};
  bool warm = false;              ///< has a warm-start direction (body pairs)
  Vec3 direction = Vec3::Zero();  ///< the pair's last distance direction
  Scalar contactTime = 0;         ///< > 0: in contact, with this contact time
  /// the contact's spring state (contactTime > 0): elastic force, the stiffness
  /// and the overlap of the last call; stiffness 0 = start from k delta
  Scalar springForce = 0;
  Scalar stiffness = 0;
  Scalar overlap = 0;
  /// the contact force on second in the last call (the load rule's other contacts)
  Vec3 contactForce = Vec3::Zero();
  /// the damping force (lubrication and film correction) on second of the
  /// last dampingForces() call (the load rule's other forces)
  Vec3 dampingForce = Vec3::Zero();
  /// the tangential spring and the slip velocity of the last call
  /// (coulombSpring friction; ContactState)
  Vec3 tangentialSpring = Vec3::Zero();
  Vec3 tangentialSlip = Vec3::Zero();
};

class CollisionModel {
 public:
  /**
   * @param pairModel the interaction of two bodies
   * @param wallModel the interaction of a body and a wall
   * @param film the film correction, or nullptr for none (no film pairs are recorded)
   * @throws std::invalid_argument on invalid settings or walls, or a missing model
   */
  CollisionModel(const CollisionSettings& settings, std::unique_ptr<PairModel> pairModel,
                 std::unique_ptr<WallModel> wallModel, std::vector<PlaneWall> walls,
                 std::unique_ptr<FilmCorrection> film = nullptr);

  const CollisionSettings& settings() const { return settings_; }
  const PairModel& pairModel() const { return *pair_; }
  const WallModel& wallModel() const { return *wall_; }
  /// the film correction, nullptr if none
  const FilmCorrection* filmCorrection() const { return film_.get(); }
  const std::vector<PlaneWall>& walls() const { return walls_; }

  /// The periodic axes of the domain: pairs meet through the second body's
  /// minimum image (none by default; walls are unaffected).
  const PeriodicBox& periodicBox() const { return box_; }
  void setPeriodicBox(const PeriodicBox& box) { box_ = box; }
  /// Share the pairs among the processes of a parallel run (nullptr: this
  /// process does all). The histories of pairs another process owns are
  /// dropped; every process must set the same share before its first call.
  void setWorkShare(std::shared_ptr<const WorkShare> share);
  const WorkShare* workShare() const { return share_.get(); }

  /**
   * Sub-steps a fluid step dt needs (>= 1): dt/subSteps <= T_c,min/subStepsPerContact
   * with T_c,min the shorter of the contact time of the fastest possible impact
   * (twice the largest body speed plus rotation) and the contact times of the
   * contacts under way. 1 without bodies.
   * @throws std::runtime_error if more than maxSubSteps would be needed
   */
  int subSteps(const std::vector<CollisionBody>& bodies, Scalar dt, Scalar contactTime) const;
  /**
   * The islands of a fluid step dt: bodies linked, directly or through others,
   * by pairs whose bounding spheres, grown by their reach (lubrication, film)
   * and by twice the largest distance a body covers in dt (2 (v_max dt +
   * a_max dt^2/2), v_max the largest speed plus rotation at the largest
   * semi-axis, a_max the largest external force over mass), overlap; a
   * body within that distance of a wall's reach interacts with it. Each
   * island's sub-steps are subSteps() of its bodies and contacts alone. In
   * the order of their first bodies; with a work share, the same on every
   * process (one collective).
   * @throws TooManySubSteps if an island would need more than maxSubSteps
   */
  std::vector<Island> islands(const std::vector<CollisionBody>& bodies, Scalar dt, Scalar contactTime);
  /**
   * With a work share: the bodies (flags, one per body) that this process's
   * pairs may use within the step of the last islands() call, its own bodies
   * linked to others or to a wall and their partners; the sub-stepper builds
   * and advances trial states of these only. Empty without a work share.
   */
  const std::vector<char>& evaluatedBodies() const { return evaluated_; }
  /**
   * After the islands of a step were advanced apart: throws std::runtime_error
   * naming two bodies of different islands whose grown bodies (their reach)
   * now meet, or a body of an island without collision forces now within
   * reach of a wall, which the islands' margin should have ruled out (with a
   * work share also bodies, or a body and a wall, that were not linked at the
   * start of the step; on every process alike: one collective).
   */
  void checkIslands(const std::vector<CollisionBody>& bodies, const std::vector<Island>& islands);

  /**
   * Contact forces and torques (about the centres) on every body for one
   * sub-step of length subDt; contactTime is the nominal T_c (N_c fluid steps).
   * The lubrication force and the film correction are not included: with
   * recordDamping the damped pairs of these states replace dampedPairs() (the
   * start of the sub-step), for dampingForces().
   * elapsed: the time since the states of the last call, over which the
   * contacts' tangential springs are advanced (negative: subDt, a caller
   * evaluating once per sub-step; the sub-stepper's predictor, at the time of
   * the last corrector, passes 0, its corrector subDt).
   * The statistics of the call are added to statistics().
   * @throws std::runtime_error on a non-finite force (naming the bodies)
   */
  /// active: the bodies that take this sub-step (nullptr: all; a union of
  /// islands): only their pairs are evaluated, the others' histories are kept.
  /// evaluated (with a work share: evaluatedBodies(), or nullptr): only these
  /// bodies are read (the others' entries of bodies may be stale); the
  /// process's pairs lie among them.
  void forces(const std::vector<CollisionBody>& bodies, Scalar contactTime, Scalar subDt,
              std::vector<Vec3>& force, std::vector<Vec3>& torque, bool recordDamping = true,
              Scalar elapsed = -1, const std::vector<char>* active = nullptr,
              const std::vector<char>* evaluated = nullptr);

  /// The damped pairs recorded by the last forces() call that recorded them.
  const std::vector<DampedPair>& dampedPairs() const { return damped_; }

  /**
   * Forces and torques of the recorded damped pairs for the sub-step subDt,
   * implicit in the velocities (backward Euler). endVelocity and
   * endAngularVelocity are each body's velocities at the end of the sub-step
   * under every other force; referenceVelocity and referenceAngularVelocity
   * those the flow solver's hydrodynamic force responded to (the start of its
   * time step; needed only when a pair has a film coefficient, else they may
   * be empty). The returned forces, held over the sub-step and acting on the
   * bodies' own masses and inertias (those of bodies), change the end
   * velocities so that every pair k gets
   *     F_k subDt = -[I_k(u_n,k) + D_k (u_n,k - u_n,ref,k) subDt] n_k
   * with u_n,k its relative normal velocity at the end and I_k(u) the integral
   * of its lubrication coefficient over the gap path from the start gap to
   * gap + u subDt (for a short path c(gap) u subDt: backward Euler; for a long
   * one the exact Stokes impulse of the path, so the correction does not
   * depend on how finely the sub-steps sample the gap; DampedPair::
   * lubricationMean is the mean coefficient applied). The system is monotone
   * (M + subDt J^T (C + D) J symmetric positive definite in the linear case);
   * it is solved by Gauss-Seidel sweeps over the pairs (one sweep is exact for
   * a single pair, each pair's scalar equation by safeguarded Newton, at most
   * kMaxLubricationIterations), at most kMaxDampingSweeps; a solve stopped
   * there is counted in statistics() and its last iterate is used.
   * @throws std::invalid_argument if the sizes differ from bodies
   * @throws std::runtime_error on a non-finite force
   */
  void dampingForces(const std::vector<CollisionBody>& bodies, const std::vector<Vec3>& endVelocity,
                     const std::vector<Vec3>& endAngularVelocity,
                     const std::vector<Vec3>& referenceVelocity,
                     const std::vector<Vec3>& referenceAngularVelocity, Scalar subDt,
                     std::vector<Vec3>& force, std::vector<Vec3>& torque,
                     const std::vector<char>* active = nullptr);

  static constexpr int kMaxDampingSweeps = 1000;
  static constexpr int kMaxLubricationIterations = 200;
  /// stop when no sweep changes a pair's normal velocity by more than this times the largest one
  static constexpr Scalar kDampingTolerance = 1e-10;

  const CollisionStatistics& statistics() const { return statistics_; }
  void resetStatistics() { statistics_ = CollisionStatistics(); }

  /// Forget the warm starts and contact histories (e.g. after bodies were moved by hand).
  void clearHistory();

  /// The pairs' warm starts and contact times, sorted by (first, second):
  /// with a work share, those of the pairs this process owns (the union over
  /// the processes is the model's history).
  std::vector<PairRecord> history() const;
  /// Restore history() (e.g. on restart); with a work share, every process
  /// is given the whole history and keeps its own pairs'.
  /// @throws std::invalid_argument on a record with bad indices or values
  void setHistory(const std::vector<PairRecord>& records);

  /// Pairs in contact now (body-body and body-wall; walls are -1 - wall index),
  /// of those this process owns.
  std::size_t activeContacts() const { return contact_.size(); }

  /// A pair that overlaps: bodies first and second (-1 - wall index for a
  /// wall), the overlap over the pair's smallest semi-axis.
  struct Overlap {
    int first = 0;
    int second = 0;
    Scalar ratio = 0;
  };

  /**
   * The pairs (bodies and walls) that overlap by more than ratio times the
   * smaller smallest semi-axis of the pair, from the signed distance (a body
   * behind a wall overlaps it by its whole depth). Pairs whose bounding
   * spheres are apart, or proved apart by the overlap test, are skipped.
   * Nothing is recorded (the histories and statistics are unchanged).
   */
  std::vector<Overlap> overlaps(const std::vector<CollisionBody>& bodies, Scalar ratio);

 private:
  /// The static load (N) pressing bodies i and j (j < 0: a wall) together
  /// along n (from i to j), from their external forces and their other
  /// pairs' contact and damping forces, at most the sum over the two bodies
  /// of their external and other contact forces and their other damping
  /// forces, each of these at most the former (CollisionModel.cpp);
  /// ownContact, ownDamping: this pair's last contact and damping forces on j
  Scalar sustainedLoad(const std::vector<CollisionBody>& bodies, int i, int j, const Vec3& n,
                       const Vec3& ownContact, const Vec3& ownDamping) const;
  static std::uint64_t key(int i, int j, int image = PeriodicBox::kNoImage) {
    return PairKey::encode(i, j, image);
  }
  /// each body's reach: half the largest activation gap it can take part in
  /// (centres_, radii_, reach_; of the active bodies only, if given)
  void bodyReach(const std::vector<CollisionBody>& bodies, const std::vector<char>* active = nullptr);
  /// the sub-steps of a step dt for bodies of largest speed (plus rotation)
  /// speed and smallest semi-axis aMin whose contacts last at least tc: a
  /// contact, or their fastest possible impact, lasts subStepsPerContact of them
  /// @throws TooManySubSteps beyond maxSubSteps
  int subStepsFor(Scalar dt, Scalar tc, Scalar speed, Scalar aMin) const;
  /// how close to a wall the body interacts with it: the wall lubrication's
  /// activation gap and the film gap, the larger
  Scalar wallReach(const CollisionBody& b) const;
  /// does this process compute the pair (always without a work share)?
  bool owns(std::uint64_t k) const { return !share_ || share_->owns(k); }
  /// each body's contact force of this process's pairs in contact_ (the
  /// force on second, minus on first), summed in the order of the keys
  void contactSums(int n, std::vector<Vec3>& sums) const;
  /// Every process's partial forces, torques and contact sums added (in
  /// process order, the same bits on every process) and, with withDamped,
  /// the damped pairs of every process concatenated: one collective
  void combine(std::vector<Vec3>& force, std::vector<Vec3>& torque, std::vector<Vec3>& sums,
               bool withDamped);
  /// the lubrication coefficient of a damped pair at the gap h, and its
  /// integral over the gap from h0 to h1
  /// The logarithmic tangential lubrication terms of a pair (j < 0: a wall)
  /// below its activation gap and their coupling to the normal motion,
  /// explicit in the sub-step (TangentialLubrication.hpp, CubicGapCoupling.hpp):
  /// S1, S2 the curvature tensors at the closest points p1, p2 (a wall: 0)
  void addTangentialLubrication(const std::vector<CollisionBody>& bodies,
                                const Lubrication& lubrication, int i, int j, const Vec3& shift,
                                Scalar logFactor, const Mat3& S1, const Mat3& S2, const Vec3& n,
                                const Vec3& p1, const Vec3& p2, const ContactSide& s1,
                                const ContactSide& s2, Scalar subDt, std::vector<Vec3>& force,
                                std::vector<Vec3>& torque) const;
  Scalar lubricationCoefficientAt(const DampedPair& p, Scalar h) const;
  Scalar lubricationIntegral(const DampedPair& p, Scalar h0, Scalar h1) const;
  /// the end relative normal speed of one lubricated pair (the others held)
  Scalar lubricatedEndSpeed(const DampedPair& p, Scalar uFree, Scalar wk, Scalar subDt,
                            Scalar uRef);
  /// The interaction of bodies i, j (j < 0: wall -1 - j) at signed gap d,
  /// through the image of j with this code (shifted by shift; p2 on that image).
  void interact(const std::vector<CollisionBody>& bodies, int i, int j, int image, const Vec3& shift,
                Scalar gap,
                const Vec3& n, const Vec3& p1, const Vec3& p2, Scalar contactTime, Scalar subDt,
                std::vector<Vec3>& force, std::vector<Vec3>& torque);

  CollisionSettings settings_;
  std::unique_ptr<PairModel> pair_;
  std::unique_ptr<WallModel> wall_;
  std::unique_ptr<FilmCorrection> film_;
  std::vector<PlaneWall> walls_;
  PairSearch search_;
  PeriodicBox box_;
  std::shared_ptr<const WorkShare> share_;
  /// the settings' distanceMethod
  std::unique_ptr<ellipsoids::DistanceMethod> distance_;
  /// the penetration depth of overlapping pairs, whatever distance_ is
  ellipsoids::DualNewton dual_;
  ellipsoids::AutoDistance fallback_;
  ellipsoids::JiaOverlapTest overlap_;
  std::vector<Vec3> centres_;
  std::vector<Scalar> radii_;
  std::vector<Scalar> reach_;
  std::vector<ellipsoids::Ellipsoid> grown_;  ///< forces(): valid where grownReady_
  std::vector<Vec3> halfExtent_;  ///< axis-aligned half extents of grown_
  /// warm-start direction of each pair seen last call
  std::unordered_map<std::uint64_t, Vec3> direction_, nextDirection_;
  /// the state of each pair in contact
  std::unordered_map<std::uint64_t, ContactState> contact_, nextContact_;
  /// the damping force on second of each damped pair in the last
  /// dampingForces() call: a film that carries a body's load (a body resting
  /// on another that creeps through its own film to a wall) is part of what
  /// presses a contact of its pair's neighbours (sustainedLoad)
  std::unordered_map<std::uint64_t, Vec3> lastDamping_;
  CollisionStatistics statistics_;
  bool recordDamping_ = true;
  /// the time the tangential springs advance over in this call (forces())
  Scalar elapsed_ = 0;
  std::vector<DampedPair> damped_;
  /// each body's contact and damping forces of the last call (the load of
  /// its other pairs): the contact sums over every process's contact_ (kept
  /// from the last call's collective, recomputed when lastContactValid_ is
  /// false), the damping sums from lastDamping_ at the start of a call
  std::vector<Vec3> lastContactForce_, lastDampingForce_;
  bool lastContactValid_ = false;
  bool lastDampingValid_ = false;  ///< lastDampingForce_ sums lastDamping_
  /// forces() scratch: (pair key, force on second), sorted by key
  std::vector<std::pair<std::uint64_t, Vec3>> lastForces_;
  std::vector<Vec3> contactScratch_;
  std::vector<char> sendScratch_;
  std::vector<int> activeIndex_;  ///< forces(): the active bodies (search order)
  std::vector<Vec3> activeCentres_;
  std::vector<Scalar> activeRadii_;
  std::vector<char> activeFirsts_;  ///< forces(): the active bodies this process owns
  std::vector<char> grownReady_;
  std::vector<char> evaluated_;  ///< evaluatedBodies()
  std::vector<char> searched_;   ///< forces(): the active bodies it evaluates
  std::vector<Scalar> impulse_;  ///< dampingForces(): the pairs' normal impulses
  std::vector<Scalar> pairInverseMass_, pairReferenceSpeed_;  ///< dampingForces() scratch
};

}  // namespace collision

#endif
