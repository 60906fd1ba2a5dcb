#include "collision/CollisionModel.hpp"
#include "collision/CubicGapCoupling.hpp"
#include "collision/GapParaboloid.hpp"
#include "collision/RollingResistance.hpp"
#include "collision/TangentialLubrication.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace collision {

namespace {
constexpr Scalar kInf = std::numeric_limits<Scalar>::infinity();

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("collision: " + what);
}

ContactSide sideOf(const CollisionBody& b, const Vec3& point) {
  ContactSide s;
  s.movable = b.movable;
  if (b.movable) {
    s.inverseMass = 1 / b.mass;
    s.inverseInertia = b.inverseInertia;
  }
  s.arm = point - b.shape.centre();
  return s;
}

Vec3 pointVelocity(const CollisionBody& b, const Vec3& point) {
  return b.velocity + b.angularVelocity.cross(point - b.shape.centre());
}

/// The body scaled about its centre so that it contains the body grown by delta.
ellipsoids::Ellipsoid grown(const ellipsoids::Ellipsoid& e, Scalar delta) {
  if (delta <= 0) return e;
  return ellipsoids::Ellipsoid(e.semiAxes() * (1 + delta / e.minSemiAxis()), e.centre(),
                               e.orientation());
}
}  // namespace

void CollisionSettings::validate() const {
  require(kMaxOverlapRange.contains(maxOverlap),
          outOfRangeMessage("maxOverlap", maxOverlap, kMaxOverlapRange));
  require(kSubStepsPerContactRange.contains(subStepsPerContact),
          outOfRangeMessage("subStepsPerContact", subStepsPerContact, kSubStepsPerContactRange));
  require(kDistanceAccuracyRange.contains(distanceAccuracy),
          outOfRangeMessage("distanceAccuracy", distanceAccuracy, kDistanceAccuracyRange));
  require(kMaxSubStepsRange.contains(maxSubSteps),
          outOfRangeMessage("maxSubSteps", maxSubSteps, kMaxSubStepsRange));
  require(kApproachContactTimeScaleRange.contains(approachContactTimeScale),
          outOfRangeMessage("approachContactTimeScale", approachContactTimeScale,
                            kApproachContactTimeScaleRange));
  const std::vector<std::string>& names = distanceMethods();
  if (std::find(names.begin(), names.end(), distanceMethod) == names.end()) {
    std::string allowed;
    for (const std::string& m : names) allowed += (allowed.empty() ? "" : ", ") + m;
    require(false, "distanceMethod = " + distanceMethod + " must be one of " + allowed);
  }
}

const std::vector<std::string>& CollisionSettings::distanceMethods() {
  // the methods that certify their answer within eps_d on every pair they
  // accept (Newton-Coulomb, exterior penalty and Jain et al. do not)
  static const std::vector<std::string> names = {"dual", "paper", "auto", "gjk", "movingBalls"};
  return names;
}

CollisionModel::CollisionModel(const CollisionSettings& settings,
                               std::unique_ptr<PairModel> pairModel,
                               std::unique_ptr<WallModel> wallModel, std::vector<PlaneWall> walls,
                               std::unique_ptr<FilmCorrection> film)
    : settings_(settings),
      pair_(std::move(pairModel)),
      wall_(std::move(wallModel)),
      film_(std::move(film)),
      walls_(std::move(walls)) {
  require(pair_ && wall_, "a collision model needs a pair model and a wall model");
  settings_.validate();
  distance_ = ellipsoids::makeDistanceMethod(settings_.distanceMethod);
  for (const PlaneWall& w : walls_) w.validate();
}

void CollisionModel::clearHistory() {
  direction_.clear();
  contact_.clear();
  lastDamping_.clear();
  lastContactValid_ = false;
  lastDampingValid_ = false;
}

void CollisionModel::setWorkShare(std::shared_ptr<const WorkShare> share) {
  require(!share || share->size() >= 1, "collision: a work share needs at least one process");
  share_ = std::move(share);
  for (auto it = direction_.begin(); it != direction_.end();) it = owns(it->first) ? std::next(it) : direction_.erase(it);
  for (auto it = contact_.begin(); it != contact_.end();) it = owns(it->first) ? std::next(it) : contact_.erase(it);
  lastContactValid_ = false;
}

std::vector<PairRecord> CollisionModel::history() const {
  std::unordered_map<std::uint64_t, PairRecord> merged;
  auto record = [&merged](std::uint64_t k) -> PairRecord& {
    PairRecord& r = merged[k];
    r.first = PairKey::first(k);
    r.second = PairKey::second(k);
    r.image = PeriodicBox::multiples(PairKey::image(k));
    return r;
  };
  for (const auto& [k, d] : direction_) {
    PairRecord& r = record(k);
    r.warm = true;
    r.direction = d;
  }
  for (const auto& [k, c] : contact_) {
    PairRecord& r = record(k);
    r.contactTime = c.contactTime;
    r.springForce = c.springForce;
    r.stiffness = c.stiffness;
    r.overlap = c.overlap;
    r.contactForce = c.force;
    r.tangentialSpring = c.tangentialSpring;
    r.tangentialSlip = c.tangentialSlip;
  }
  // every process holds every damping force (the solve is replicated); each
  // reports its own pairs'
  for (const auto& [k, f] : lastDamping_) {
    if (owns(k)) record(k).dampingForce = f;
  }
  std::vector<PairRecord> out;
  out.reserve(merged.size());
  for (const auto& kv : merged) out.push_back(kv.second);
  std::sort(out.begin(), out.end(), [](const PairRecord& a, const PairRecord& b) {
    return a.first != b.first ? a.first < b.first
                              : (a.second != b.second ? a.second < b.second : a.image < b.image);
  });
  return out;
}

void CollisionModel::setHistory(const std::vector<PairRecord>& records) {
  clearHistory();
  for (const PairRecord& r : records) {
    const std::string pair = "(" + std::to_string(r.first) + " " + std::to_string(r.second) + ")";
    require(r.first >= 0 && (r.second > r.first ||
                             (r.second < 0 && -1 - r.second < static_cast<int>(walls_.size()))),
            "pair history " + pair + ": second must be a body index > first or -1 - wall index");
    require(std::isfinite(r.contactTime) && r.contactTime >= 0,
            "pair history " + pair + ": contact time must be >= 0");
    require(!r.warm || (r.direction.allFinite() && r.direction.norm() > 0),
            "pair history " + pair + ": the warm-start direction must be finite and non-zero");
    require(std::isfinite(r.springForce) && r.springForce >= 0 && std::isfinite(r.stiffness) &&
                r.stiffness >= 0 && std::isfinite(r.overlap) && r.overlap >= 0 &&
                r.contactForce.allFinite() && r.tangentialSpring.allFinite() &&
                r.tangentialSlip.allFinite() && r.dampingForce.allFinite(),
            "pair history " + pair +
                ": spring force, stiffness and overlap must be finite and >= 0, the contact and"
                " damping forces and the tangential spring and slip finite");
    int image = PeriodicBox::kNoImage;
    try {
      image = PeriodicBox::imageCode(r.image);
    } catch (const std::out_of_range&) {
      require(false, "pair history " + pair + ": image multiples must be in [-" +
                         std::to_string(PeriodicBox::kMaxMultiple) + ", " +
                         std::to_string(PeriodicBox::kMaxMultiple) + "]");
    }
    require(r.second >= 0 || image == PeriodicBox::kNoImage,
            "pair history " + pair + ": a wall pair has no periodic image");
    const std::uint64_t k = key(r.first, r.second, image);
    if (r.warm && owns(k)) direction_[k] = r.direction;
    if (r.contactTime > 0 && owns(k)) {
      contact_[k] =
          ContactState{r.contactTime, r.springForce, r.stiffness, r.overlap, r.contactForce,
                       r.tangentialSpring, r.tangentialSlip};
    }
    if (r.dampingForce.squaredNorm() > 0) lastDamping_[k] = r.dampingForce;
    lastDampingValid_ = false;
  }
}

int CollisionModel::subSteps(const std::vector<CollisionBody>& bodies, Scalar dt,
                             Scalar contactTime) const {
  if (bodies.empty()) return 1;
  require(std::isfinite(dt) && dt > 0, "time step " + std::to_string(dt) + " must be > 0");
  require(std::isfinite(contactTime) && contactTime > 0,
          "contact time " + std::to_string(contactTime) + " must be > 0");
  Scalar speed = 0, aMin = kInf;
  for (const CollisionBody& b : bodies) {
    if (!b.velocity.allFinite() || !b.angularVelocity.allFinite()) {
      throw std::runtime_error("collision: a body has a non-finite velocity");
    }
    aMin = std::min(aMin, b.shape.minSemiAxis());
    if (b.movable) {
      speed = std::max(speed,
                       b.velocity.norm() + b.angularVelocity.norm() * b.shape.maxSemiAxis());
    }
  }
  // the contacts under way keep the contact time they started with
  Scalar tc = contactTime;
  for (const auto& kv : contact_) tc = std::min(tc, kv.second.contactTime);
  if (share_) {
    std::vector<Scalar> all{tc};
    share_->minimum(all);  // the other processes' contacts
    tc = all[0];
  }
  return subStepsFor(dt, tc, speed, aMin);
}

int CollisionModel::subStepsFor(Scalar dt, Scalar tc, Scalar speed, Scalar aMin) const {
  // the fastest possible impact: twice the largest speed, the overlap cap
  if (speed > 0) tc = std::min(tc, kPi * settings_.maxOverlap * aMin / (2 * speed));
  const Scalar n = std::ceil(dt * settings_.subStepsPerContact / tc - 1e-9);
  if (!(n <= settings_.maxSubSteps)) {
    throw TooManySubSteps("collision: " + std::to_string(n) +
                          " body sub-steps would be needed in a step of " + std::to_string(dt) +
                          " s (largest body speed " + std::to_string(speed) + "; maxSubSteps " +
                          std::to_string(settings_.maxSubSteps) + ")");
  }
  return std::max(1, int(n));
}

namespace {

/// union-find with path halving
int rootOf(std::vector<int>& parent, int b) {
  while (parent[b] != b) b = parent[b] = parent[parent[b]];
  return b;
}

/// each body's sum of the pairs' forces on it (on second, minus on first),
/// added in the order of the keys so that the sums do not depend on the
/// maps' order (a model restored from its history sums to the same bits)
void sumInKeyOrder(std::vector<std::pair<std::uint64_t, Vec3>>& forces, int n,
                   std::vector<Vec3>& sums) {
  std::sort(forces.begin(), forces.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  sums.assign(n, Vec3::Zero());
  for (const auto& [k, f] : forces) {
    const int i = PairKey::first(k);
    const int j = PairKey::second(k);
    if (i < n) sums[i] -= f;
    if (j >= 0 && j < n) sums[j] += f;
  }
}

}  // namespace

std::vector<Island> CollisionModel::islands(const std::vector<CollisionBody>& bodies, Scalar dt,
                                            Scalar contactTime) {
  require(std::isfinite(dt) && dt > 0, "time step " + std::to_string(dt) + " must be > 0");
  require(std::isfinite(contactTime) && contactTime > 0,
          "contact time " + std::to_string(contactTime) + " must be > 0");
  const int n = static_cast<int>(bodies.size());
  Scalar speed = 0, acceleration = 0;
  for (const CollisionBody& b : bodies) {
    if (!b.velocity.allFinite() || !b.angularVelocity.allFinite()) {
      throw std::runtime_error("collision: a body has a non-finite velocity");
    }
    if (b.movable) {
      speed = std::max(speed, b.velocity.norm() + b.angularVelocity.norm() * b.shape.maxSemiAxis());
      if (std::isfinite(b.mass) && b.mass > 0 && b.externalForce.allFinite()) {
        acceleration = std::max(acceleration, b.externalForce.norm() / b.mass);
      }
    }
  }
  // how far two bodies can close in on each other within the step: each by
  // twice what the largest speed and the largest acceleration under the
  // bodies' other forces carry it (room for the speed a contact gives; a
  // body starting from rest moves too)
  const Scalar margin = 2 * (speed * dt + 0.5 * acceleration * dt * dt);
  bodyReach(bodies);
  std::vector<Scalar> grownRadii(radii_);
  for (Scalar& r : grownRadii) r += margin;
  std::vector<int> parent(n);
  for (int i = 0; i < n; ++i) parent[i] = i;
  std::vector<char> interacts(n, 0);
  // the links: pairs that may meet (second >= 0) and bodies that may meet a
  // wall (second -1); with a work share each process finds those of its own
  // bodies (as first bodies) and every process joins them all
  std::vector<std::pair<int, int>> links;
  std::vector<char> own;
  if (share_) {
    own.resize(n);
    for (int i = 0; i < n; ++i) own[i] = share_->ownsBody(i);
  }
  bool oneIsland = false;
  try {
    for (const CandidatePair& c : search_.find(centres_, grownRadii, box_, share_ ? &own : nullptr)) {
      if (!bodies[c.first].movable && !bodies[c.second].movable) continue;
      links.emplace_back(c.first, c.second);
    }
  } catch (const std::invalid_argument&) {
    // the margin makes the reach too long for the periodic box's single
    // image (the bodies' own reach fits: forces() checks it): every body
    // in one island, as without islands
    oneIsland = true;
  }
  for (int i = 0; i < n; ++i) {
    if (!bodies[i].movable || (share_ && !own[i])) continue;
    const Scalar reach = wallReach(bodies[i]);
    for (const PlaneWall& w : walls_) {
      if (wallDistance(bodies[i].shape, w).distance <= reach + margin) {
        links.emplace_back(i, -1);
        break;
      }
    }
  }
  // the bodies this process's pairs may use within the step
  evaluated_.assign(share_ ? n : 0, 0);
  for (const auto& [i, j] : links) {
    if (!share_) break;
    evaluated_[i] = 1;
    if (j >= 0) evaluated_[j] = 1;
  }
  if (share_) {
    std::vector<int> flat;
    flat.reserve(2 * links.size());
    for (const auto& [i, j] : links) flat.insert(flat.end(), {i, j});
    flat = share_->allGatherValues(flat);
    if (flat.size() % 2 != 0) throw std::runtime_error("collision: a process sent half a link");
    links.clear();
    for (std::size_t k = 0; k < flat.size(); k += 2) {
      if (flat[k] < 0 || flat[k] >= n || flat[k + 1] < -1 || flat[k + 1] >= n) {
        throw std::runtime_error("collision: a process sent a link of bodies " +
                                 std::to_string(flat[k]) + " and " + std::to_string(flat[k + 1]));
      }
      links.emplace_back(flat[k], flat[k + 1]);
    }
  }
  for (const auto& [i, j] : links) {
    interacts[i] = 1;
    if (j < 0) continue;
    interacts[j] = 1;
    parent[rootOf(parent, i)] = rootOf(parent, j);
  }
  if (oneIsland) {
    // (every process met the same periodic box and radii: all fall back)
    for (int i = 0; i < n; ++i) {
      parent[i] = 0;
      interacts[i] = n > 1;
    }
    if (share_) evaluated_.assign(n, 1);
  }

  // the islands in the order of their first bodies, each body ascending
  std::vector<int> islandOf(n, -1);
  std::vector<Island> out;
  for (int i = 0; i < n; ++i) {
    const int r = rootOf(parent, i);
    if (islandOf[r] < 0) {
      islandOf[r] = static_cast<int>(out.size());
      out.emplace_back();
    }
    Island& island = out[islandOf[r]];
    island.bodies.push_back(i);
    island.interacts = island.interacts || interacts[i];
  }
  // each island's shortest contact time: its fastest possible impact and the
  // contacts under way (on every process: one collective)
  std::vector<Scalar> tc(out.size(), contactTime);
  std::vector<Scalar> islandSpeed(out.size(), 0), islandMinAxis(out.size(), kInf);
  for (int i = 0; i < n; ++i) {
    const int k = islandOf[rootOf(parent, i)];
    islandMinAxis[k] = std::min(islandMinAxis[k], bodies[i].shape.minSemiAxis());
    if (bodies[i].movable) {
      islandSpeed[k] = std::max(islandSpeed[k], bodies[i].velocity.norm() +
                                                    bodies[i].angularVelocity.norm() *
                                                        bodies[i].shape.maxSemiAxis());
    }
  }
  for (const auto& [k, c] : contact_) {
    const int i = PairKey::first(k);
    if (i < n) {
      Scalar& t = tc[islandOf[rootOf(parent, i)]];
      t = std::min(t, c.contactTime);
    }
  }
  if (share_) share_->minimum(tc);
  for (std::size_t k = 0; k < out.size(); ++k) {
    Island& island = out[k];
    if (island.interacts) island.subSteps = subStepsFor(dt, tc[k], islandSpeed[k], islandMinAxis[k]);
  }
  return out;
}

void CollisionModel::checkIslands(const std::vector<CollisionBody>& bodies,
                                  const std::vector<Island>& islands) {
  const int n = static_cast<int>(bodies.size());
  std::vector<int> islandOf(n, -1);
  for (std::size_t k = 0; k < islands.size(); ++k) {
    for (const int b : islands[k].bodies) islandOf[b] = static_cast<int>(k);
  }
  bodyReach(bodies);
  std::vector<char> own;
  if (share_) {
    own.resize(n);
    for (int i = 0; i < n; ++i) own[i] = share_->ownsBody(i);
  }
  // the first pair (of this process's) whose grown bodies meet across islands,
  // or, with a work share, with a body this process did not evaluate
  std::vector<Scalar> found{kInf, kInf};
  for (const CandidatePair& c : search_.find(centres_, radii_, box_, share_ ? &own : nullptr)) {
    const int i = c.first, j = c.second;
    if (!bodies[i].movable && !bodies[j].movable) continue;
    const bool unseen = share_ && !(evaluated_[i] && evaluated_[j]);
    if (islandOf[i] == islandOf[j] && !unseen) continue;
    const Vec3 shift = c.image != PeriodicBox::kNoImage ? box_.shift(c.image) : Vec3::Zero();
    if (overlap_.test(grown(bodies[i].shape, reach_[i]),
                      grown(bodies[j].shape, reach_[j]).translatedBy(shift)) ==
        ellipsoids::OverlapStatus::separated) {
      continue;
    }
    if (std::make_pair(Scalar(i), Scalar(j)) < std::make_pair(found[0], found[1])) found = {Scalar(i), Scalar(j)};
  }
  // a body of an island without collision forces (or, with a work share,
  // one this process did not evaluate) now within reach of a wall
  std::vector<char> interacting(n, 0);
  for (std::size_t k = 0; k < islands.size(); ++k) {
    for (const int b : islands[k].bodies) interacting[b] = islands[k].interacts;
  }
  for (int i = 0; i < n && !walls_.empty(); ++i) {
    if (!bodies[i].movable || (share_ && !own[i])) continue;
    if (interacting[i] && !(share_ && !evaluated_[i])) continue;
    const Scalar reach = wallReach(bodies[i]);
    for (int w = 0; w < static_cast<int>(walls_.size()); ++w) {
      if (wallDistance(bodies[i].shape, walls_[w]).distance <= reach &&
          std::make_pair(Scalar(i), Scalar(-1 - w)) < std::make_pair(found[0], found[1])) {
        found = {Scalar(i), Scalar(-1 - w)};
      }
    }
  }
  // (every process stops alike: the smallest pair of any)
  if (share_) share_->minimum(found);
  if (std::isfinite(found[0])) {
    const int i = int(found[0]), j = int(found[1]);
    throw std::runtime_error(
        "collision: body " + std::to_string(i) +
        (j >= 0 ? " and body " + std::to_string(j) : " and wall '" + walls_[-1 - j].name + "'") +
        " came within reach of each other within a step from different islands, or (with a work share)"
        " without being linked at its start (bodies"
        " that can meet within a step are sub-stepped together; their speeds grew beyond the"
        " islands' margin of twice the distance the largest speed and acceleration carry a body):"
        " reduce the time step");
  }
}

Scalar CollisionModel::wallReach(const CollisionBody& b) const {
  const Lubrication& wallLubrication = wall_->lubrication();
  return std::max(wallLubrication.acts() ? wallLubrication.activationGap(
                                               b.shape.maxOfMaxCurvatureRadius(), kInf, b.cellSize)
                                         : Scalar(0),
                  film_ ? b.filmGap : Scalar(0));
}

void CollisionModel::bodyReach(const std::vector<CollisionBody>& bodies,
                               const std::vector<char>* active) {
  const int n = static_cast<int>(bodies.size());
  const Lubrication& pairLubrication = pair_->lubrication();
  Scalar largestCellSize = 0;
  for (int i = 0; i < n; ++i) largestCellSize = std::max(largestCellSize, bodies[i].cellSize);
  centres_.resize(n);
  radii_.resize(n);
  reach_.resize(n);
  for (int i = 0; i < n; ++i) {
    if (active && !(*active)[i]) continue;
    const ellipsoids::Ellipsoid& e = bodies[i].shape;
    reach_[i] = pairLubrication.acts()
                    ? pairLubrication.reach(e.maxOfMaxCurvatureRadius(), largestCellSize)
                    : 0;
    if (film_) reach_[i] = std::max(reach_[i], 0.5 * bodies[i].filmGap);
    centres_[i] = e.centre();
    radii_[i] = e.maxSemiAxis() + reach_[i];
  }
}

void CollisionModel::forces(const std::vector<CollisionBody>& bodies, Scalar contactTime,
                            Scalar subDt, std::vector<Vec3>& force, std::vector<Vec3>& torque,
                            bool recordDamping, Scalar elapsed, const std::vector<char>* active,
                            const std::vector<char>* evaluated) {
  elapsed_ = elapsed < 0 ? subDt : elapsed;
  const int n = static_cast<int>(bodies.size());
  if (n > PairKey::kMaxBodies) {
    require(false, "collision: at most " + std::to_string(PairKey::kMaxBodies) + " bodies");
  }
  force.assign(n, Vec3::Zero());
  torque.assign(n, Vec3::Zero());
  recordDamping_ = recordDamping;
  if (recordDamping) damped_.clear();
  // each body's damping forces of the last solve (every process holds them),
  // summed in the order of the pairs' keys so that a model restored from its
  // history sums them to the same bits; its contact forces of the last call,
  // kept from that call's collective (or summed afresh after a restore)
  if (!lastDampingValid_ || static_cast<int>(lastDampingForce_.size()) != n) {
    lastForces_.assign(lastDamping_.begin(), lastDamping_.end());
    sumInKeyOrder(lastForces_, n, lastDampingForce_);
    lastDampingValid_ = true;
  }
  if (!lastContactValid_ || static_cast<int>(lastContactForce_.size()) != n) {
    contactSums(n, lastContactForce_);
    if (share_) {
      contactScratch_.assign(n, Vec3::Zero());
      std::vector<Vec3> none(n, Vec3::Zero());
      combine(contactScratch_, none, lastContactForce_, false);
    }
    lastContactValid_ = true;
  }
  const Lubrication& wallLubrication = wall_->lubrication();
  const bool films = film_ != nullptr;
  auto on = [active](int b) { return !active || (*active)[b]; };
  if ((active && static_cast<int>(active->size()) != n) ||
      (evaluated && static_cast<int>(evaluated->size()) != n)) {
    require(false, "collision: the active or evaluated bodies' flags are not one per body");
  }
  // the bodies searched: the active ones (of those this process evaluates)
  const std::vector<char>* searched = active;
  if (evaluated) {
    searched_.resize(n);
    for (int i = 0; i < n; ++i) searched_[i] = on(i) && (*evaluated)[i];
    searched = &searched_;
  }
  auto inSearch = [searched](int b) { return !searched || (*searched)[b]; };

  // the active bodies, their reach and bounding spheres for the search (with
  // a work share, the flags of the first bodies of this process's pairs)
  bodyReach(bodies, searched);
  activeIndex_.clear();
  activeCentres_.clear();
  activeRadii_.clear();
  activeFirsts_.clear();
  for (int i = 0; i < n; ++i) {
    if (!inSearch(i)) continue;
    activeIndex_.push_back(i);
    activeCentres_.push_back(centres_[i]);
    activeRadii_.push_back(radii_[i]);
    if (share_) activeFirsts_.push_back(share_->ownsBody(i));
  }
  // the prefilter's grown bodies and their axis-aligned boxes (half extents
  // sqrt(P_kk)), once per body of the pairs found (not per pair)
  if (n > 0 && static_cast<int>(grown_.size()) != n) grown_.assign(n, bodies[0].shape);
  halfExtent_.resize(n);
  grownReady_.assign(n, 0);
  auto prepareGrown = [&](int i) {
    if (grownReady_[i]) return;
    grown_[i] = grown(bodies[i].shape, reach_[i]);
    halfExtent_[i] = grown_[i].shapeMatrix().diagonal().cwiseSqrt();
    grownReady_[i] = 1;
  };
  nextDirection_.clear();
  nextContact_.clear();
  if (active) {
    // the pairs of the bodies that do not take this sub-step keep their
    // histories (islands: a pair's bodies are both active or both not)
    for (const auto& [k, d] : direction_) {
      if (!on(PairKey::first(k))) nextDirection_.emplace(k, d);
    }
    for (const auto& [k, c] : contact_) {
      if (!on(PairKey::first(k))) nextContact_.emplace(k, c);
    }
  }

  const auto& pairs = search_.find(activeCentres_, activeRadii_, box_, share_ ? &activeFirsts_ : nullptr);
  statistics_.candidatePairs += static_cast<long>(pairs.size());
  for (const CandidatePair& candidate : pairs) {
    const int i = activeIndex_[candidate.first], j = activeIndex_[candidate.second];
    if (!bodies[i].movable && !bodies[j].movable) continue;
    // (the search gave this process's pairs only)
    prepareGrown(i);
    prepareGrown(j);
    // body j through its image (a copy only for a shifted image)
    const bool shifted = candidate.image != PeriodicBox::kNoImage;
    const Vec3 shift = shifted ? box_.shift(candidate.image) : Vec3::Zero();
    const ellipsoids::Ellipsoid& e1 = bodies[i].shape;
    const ellipsoids::Ellipsoid e2 = shifted ? bodies[j].shape.translatedBy(shift) : bodies[j].shape;
    // boxes apart (cheap), or the exact test: the grown bodies are apart
    if (((centres_[i] - centres_[j] - shift).cwiseAbs() - halfExtent_[i] - halfExtent_[j]).maxCoeff() > 0) {
      ++statistics_.prefilterRejected;
      ++statistics_.boxRejected;
      continue;
    }
    if (overlap_.test(grown_[i], shifted ? grown_[j].translatedBy(shift) : grown_[j]) ==
        ellipsoids::OverlapStatus::separated) {
      ++statistics_.prefilterRejected;
      continue;
    }
    ellipsoids::DistanceOptions options;
    options.epsD = settings_.distanceAccuracy * std::min(e1.minGaussianRadius(), e2.minGaussianRadius());
    options.stopRule = ellipsoids::StopRule::certified;  // Moving Balls: the bracket, not eps_theta
    const std::uint64_t pairKey = key(i, j, candidate.image);
    const auto warm = direction_.find(pairKey);
    if (warm != direction_.end()) {
      options.useInitialDirection = true;
      options.initialDirection = warm->second;
    }
    ellipsoids::DistanceResult r = distance_->distance(e1, e2, options);
    ++statistics_.distanceQueries;
    statistics_.distanceIterations += r.iterations;
    if (!distance_->isSigned() && (r.status == ellipsoids::DistanceStatus::overlapping || !(r.lower > 0))) {
      // an unsigned method's overlap (distance 0), or a bracket down to 0 (a pair
      // that may overlap by up to eps_d): the sign, depth and direction from the signed dual
      r = dual_.distance(e1, e2, options);
      ++statistics_.distanceQueries;
      statistics_.distanceIterations += r.iterations;
    }
    if (r.status == ellipsoids::DistanceStatus::maxIterations ||
        r.status == ellipsoids::DistanceStatus::failed) {
      ++statistics_.distanceNotConverged;
      // separated pairs: auto's other methods; overlapping ones keep the dual's
      // last iterate (its lower bound is certified)
      const ellipsoids::DistanceResult other = fallback_.distance(e1, e2, options);
      statistics_.distanceIterations += other.iterations;
      if (other.status == ellipsoids::DistanceStatus::converged) r = other;
    }
    if (!std::isfinite(r.distance) || !r.direction.allFinite()) {
      throw std::runtime_error("collision: no finite distance between bodies " +
                               std::to_string(i) + " and " + std::to_string(j));
    }
    nextDirection_[pairKey] = r.direction;
    interact(bodies, i, j, candidate.image, shift, r.distance, r.direction, r.point1, r.point2,
             contactTime, subDt, force, torque);
  }

  for (int i = 0; i < n; ++i) {
    if (!bodies[i].movable || !inSearch(i)) continue;
    for (int w = 0; w < static_cast<int>(walls_.size()); ++w) {
      if (!owns(key(i, -1 - w))) continue;
      const WallDistance d = wallDistance(bodies[i].shape, walls_[w]);
      // (a body that may reach the activation gap within the sub-step too)
      const Scalar lubricationReach =
          wallLubrication.acts()
              ? wallLubrication.activationGap(bodies[i].shape.maxOfMaxCurvatureRadius(), kInf,
                                              bodies[i].cellSize) +
                            2 * subDt *
                                (bodies[i].velocity.norm() +
                                 bodies[i].angularVelocity.norm() * bodies[i].shape.maxSemiAxis())
                      : 0;
      if (d.distance > std::max(lubricationReach, films ? bodies[i].filmGap : Scalar(0))) {
        continue;
      }
      interact(bodies, i, -1 - w, PeriodicBox::kNoImage, Vec3::Zero(), d.distance,
               -walls_[w].normal, d.bodyPoint, d.wallPoint,
               contactTime, subDt, force, torque);
    }
  }

  direction_.swap(nextDirection_);
  contact_.swap(nextContact_);
  // the contact sums of the next call's load rule, with this call's forces
  // in the one collective of the call
  contactSums(n, lastContactForce_);
  // the damping solve sweeps the pairs in the order of their keys, on every
  // process alike: each process sorts its own, combine() merges them
  if (recordDamping) {
    std::sort(damped_.begin(), damped_.end(),
              [](const DampedPair& a, const DampedPair& b) { return a.key < b.key; });
  }
  if (share_) combine(force, torque, lastContactForce_, recordDamping);
  lastContactValid_ = true;
  for (int i = 0; i < n; ++i) {
    if (!force[i].allFinite() || !torque[i].allFinite()) {
      throw std::runtime_error("collision: non-finite collision force on body " + std::to_string(i));
    }
  }
}

void CollisionModel::contactSums(int n, std::vector<Vec3>& sums) const {
  std::vector<std::pair<std::uint64_t, Vec3>> forces;
  forces.reserve(contact_.size());
  for (const auto& [k, c] : contact_) forces.emplace_back(k, c.force);
  sumInKeyOrder(forces, n, sums);
}

namespace {

template <class T>
void put(std::vector<char>& out, const T& value) {
  const char* p = reinterpret_cast<const char*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}

template <class T>
T take(const std::vector<char>& in, std::size_t& at) {
  if (at + sizeof(T) > in.size()) throw std::runtime_error("collision: a process sent a short record");
  T value;
  std::memcpy(reinterpret_cast<char*>(&value), in.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

}  // namespace

void CollisionModel::combine(std::vector<Vec3>& force, std::vector<Vec3>& torque,
                             std::vector<Vec3>& sums, bool withDamped) {
  const int n = static_cast<int>(force.size());
  // this process's block: the bodies it touched (index, force, torque,
  // contact sum), then its damped pairs (numbers only: copied as bytes)
  std::vector<char>& out = sendScratch_;
  out.clear();
  std::int64_t touched = 0;
  for (int i = 0; i < n; ++i) {
    touched += !(force[i].isZero(0) && torque[i].isZero(0) && sums[i].isZero(0));
  }
  put(out, touched);
  put(out, static_cast<std::int64_t>(withDamped ? damped_.size() : 0));
  for (int i = 0; i < n; ++i) {
    if (force[i].isZero(0) && torque[i].isZero(0) && sums[i].isZero(0)) continue;
    put(out, static_cast<std::int32_t>(i));
    for (const Vec3* v : {&force[i], &torque[i], &sums[i]}) {
      for (int c = 0; c < 3; ++c) put(out, (*v)[c]);
    }
  }
  if (withDamped) {
    for (const DampedPair& p : damped_) put(out, p);
  }

  const std::vector<char> all = share_->allGather(out);
  force.assign(n, Vec3::Zero());
  torque.assign(n, Vec3::Zero());
  sums.assign(n, Vec3::Zero());
  if (withDamped) damped_.clear();
  std::size_t at = 0;
  for (int process = 0; process < share_->size(); ++process) {
    const std::int64_t bodies = take<std::int64_t>(all, at);
    const std::int64_t pairs = take<std::int64_t>(all, at);
    for (std::int64_t b = 0; b < bodies; ++b) {
      const int i = take<std::int32_t>(all, at);
      if (i < 0 || i >= n) throw std::runtime_error("collision: a process sent body " + std::to_string(i));
      for (std::vector<Vec3>* v : {&force, &torque, &sums}) {
        for (int c = 0; c < 3; ++c) (*v)[i][c] += take<Scalar>(all, at);
      }
    }
    const auto middle = static_cast<std::ptrdiff_t>(damped_.size());
    for (std::int64_t k = 0; k < pairs; ++k) damped_.push_back(take<DampedPair>(all, at));
    // (each process's pairs came sorted by key)
    std::inplace_merge(damped_.begin(), damped_.begin() + middle, damped_.end(),
                       [](const DampedPair& a, const DampedPair& b) { return a.key < b.key; });
  }
  if (at != all.size()) throw std::runtime_error("collision: the processes' records do not add up");
}

Scalar CollisionModel::sustainedLoad(const std::vector<CollisionBody>& bodies, int i, int j,
                                     const Vec3& n, const Vec3& ownContact,
                                     const Vec3& ownDamping) const {
  // the acceleration of a body from everything but this pair (own: this
  // pair's last contact and damping forces on the second body, minus on the
  // first), and the static force scale the load cannot exceed. A film's force
  // is a load only while a load squeezes the film (a body creeping through
  // it, held by it): it counts at most as much as the body's external and
  // contact forces, so that an impact's film force, many times the weights,
  // never stiffens a spring beyond what the sub-step resolves
  Scalar bound = 0;
  auto acceleration = [&](int b, Scalar sign, Scalar& inverseMass) -> Vec3 {
    if (b < 0 || !bodies[b].movable || !std::isfinite(bodies[b].mass)) {
      inverseMass = 0;
      return Vec3::Zero();
    }
    inverseMass = 1 / bodies[b].mass;
    const Vec3 contacts = lastContactForce_[b] - sign * ownContact;
    const Vec3 films = lastDampingForce_[b] - sign * ownDamping;
    const Scalar scale = bodies[b].externalForce.norm() + contacts.norm();
    bound += scale + std::min(films.norm(), scale);
    return (bodies[b].externalForce + contacts + films) * inverseMass;
  };
  Scalar w1 = 0, w2 = 0;
  const Vec3 a1 = acceleration(i, -1, w1);
  const Vec3 a2 = acceleration(j, 1, w2);
  const Scalar pressing = (a1 - a2).dot(n);  // > 0: body 1 pushed towards body 2
  if (!(pressing > 0) || !(w1 + w2 > 0)) return 0;
  return std::min(pressing / (w1 + w2), bound);
}

void CollisionModel::interact(const std::vector<CollisionBody>& bodies, int i, int j, int image,
                              const Vec3& shift, Scalar gap,
                              const Vec3& n, const Vec3& p1, const Vec3& p2, Scalar contactTime,
                              Scalar subDt, std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  const bool wall = j < 0;
  const InteractionModel& model = wall ? static_cast<const InteractionModel&>(*wall_)
                                       : static_cast<const InteractionModel&>(*pair_);
  const CollisionBody& b1 = bodies[i];
  const Vec3 point = 0.5 * (p1 + p2);
  const ContactSide s1 = sideOf(b1, point);
  ContactSide s2;
  Vec3 v2 = Vec3::Zero();
  Scalar aMin = b1.shape.minSemiAxis();
  if (!wall) {
    // body j is met through its image shifted by shift: its own frame is the point less the shift
    s2 = sideOf(bodies[j], point - shift);
    v2 = pointVelocity(bodies[j], point - shift);
    aMin = std::min(aMin, bodies[j].shape.minSemiAxis());
  }
  const Vec3 relative = v2 - pointVelocity(b1, point);
  const Scalar un = relative.dot(n);
  Vec3 f2 = Vec3::Zero();  // on body 2 (or the wall)

  if (gap < 0) {
    const Scalar overlap = -gap;
    const Scalar cap = settings_.maxOverlap * aMin;
    const std::uint64_t k = key(i, j, image);
    const auto known = contact_.find(k);
    ContactState c = known != contact_.end() ? known->second
                                             : model.contact().firstTouch(contactTime, un, cap);
    const Scalar wInv = inverseEffectiveMass(s1, s2, n);
    if (wInv > 0) {
      // the static load pressing the pair together: the bodies' external
      // forces and the contact and damping forces of their other pairs (the
      // last call's, less this pair's own)
      const auto damping = lastDamping_.find(k);
      const Scalar load =
          sustainedLoad(bodies, i, j, n, known != contact_.end() ? c.force : Vec3::Zero(),
                        damping != lastDamping_.end() ? damping->second : Vec3::Zero());
      ContactLoading loading;
      loading.overlap = overlap;
      loading.normalSpeed = un;
      loading.inverseMass = wInv;
      loading.cap = cap;
      loading.load = load;
      // the contact time the sub-step resolves as the settings ask: a spring
      // stiffened to it needs no more sub-steps in the next step
      loading.shortestContactTime =
          settings_.approachContactTimeScale * settings_.subStepsPerContact * subDt;
      const Scalar fn = model.contact().force(c, loading, statistics_.stiffened);
      Vec3 fContact = fn * n;
      model.friction().addForce(fn, n, relative, s1, s2, subDt, known != contact_.end() ? elapsed_ : 0,
                                c, fContact);
      if (model.rollingFriction() > 0) {
        // R_r: the reduced Gaussian radius at the contact (a wall: the body's)
        const Scalar r1 = b1.shape.curvatureRadii(p1).gaussian;
        const Scalar r2 = wall ? kInf : bodies[j].shape.curvatureRadii(p2 - shift).gaussian;
        const Scalar rollingRadius = wall ? r1 : r1 * r2 / (r1 + r2);
        const Vec3 t2 = rollingResistanceTorque(
            model.rollingFriction(), rollingRadius, fn, n, b1.angularVelocity,
            wall ? Vec3::Zero() : Vec3(bodies[j].angularVelocity), s1, s2, subDt);
        torque[i] -= t2;
        if (!wall) torque[j] += t2;
      }
      c.force = fContact;
      f2 += fContact;
    }
    nextContact_[k] = c;
    ++(wall ? statistics_.wallContacts : statistics_.contacts);
    statistics_.maxOverlapRatio = std::max(statistics_.maxOverlapRatio, overlap / aMin);
  }

  // lubrication and the film correction, both applied
  // implicitly by dampingForces(); the curvature radii only when the gap is
  // below the largest activation gap the radii allow (Gaussian radius <=
  // largest curvature radius) or below the film gap
  const Lubrication& lubrication = model.lubrication();
  const Scalar cellSize = wall ? b1.cellSize : std::max(b1.cellSize, bodies[j].cellSize);
  const Scalar reachBound =
      lubrication.acts()
          ? lubrication.activationGap(b1.shape.maxOfMaxCurvatureRadius(),
                                      wall ? kInf : bodies[j].shape.maxOfMaxCurvatureRadius(),
                                      cellSize)
          : 0;
  // the correction is integrated over the gap path of the sub-step
  // (dampingForces): a pair enters the solve when its gap may cross the range
  // [0, activation) within the sub-step (twice the start speed's travel):
  // approaching from beyond the activation gap, or leaving a contact
  const Scalar travel = 2 * std::abs(un) * subDt;
  const bool lubricating = lubrication.acts() && gap + travel >= 0 &&
                           gap - travel < reachBound && (gap >= 0 || un > 0) &&
                           (gap < reachBound || un < 0);
  const Scalar filmGap =
      film_ ? FilmCorrection::pairFilmGap(b1.filmGap, wall ? Scalar(0) : bodies[j].filmGap) : 0;
  const bool film = filmGap > 0 && gap < filmGap;
  if (lubricating || film) {
    const Scalar r1 = b1.shape.curvatureRadii(p1).gaussian;
    const Scalar r2 = wall ? kInf : bodies[j].shape.curvatureRadii(p2 - shift).gaussian;
    const Mat3 S1 = b1.shape.curvatureTensor(p1);
    const Mat3 S2 = wall ? Mat3::Zero() : Mat3(bodies[j].shape.curvatureTensor(p2 - shift));
    const Scalar squeezeRadius = GapParaboloid::fromCurvatureTensors(S1, S2, n).squeezeRadius();
    DampedPair pair;
    pair.first = i;
    pair.second = j;
    pair.key = key(i, j, image);
    pair.normal = n;
    pair.arm1 = s1.arm;
    pair.arm2 = s2.arm;
    pair.gap = gap;
    // with the radii known, the activation gap itself: a pair whose gap cannot
    // reach it within the sub-step has no lubrication to integrate
    const Scalar activationGap = lubrication.activationGap(r1, r2, cellSize);
    if (lubricating && gap - travel < activationGap) {
      pair.lubricated = true;
      pair.radius1 = r1;
      pair.radius2 = r2;
      pair.law = lubrication.gapLaw(r1, r2, squeezeRadius, cellSize);
      pair.lubrication = pair.law.coefficient(gap);
      pair.startPrimitive = pair.law.primitive(gap);
      if (pair.lubrication > 0) ++statistics_.lubricated;
      if (model.lubrication().tangential()) {
        addTangentialLubrication(bodies, lubrication, i, j, shift, pair.law.logFactor(gap),
                                 S1, S2, n, p1, p2, s1, s2, subDt, force, torque);
      }
    }
    if (film) {
      pair.film = film_->coefficient(squeezeRadius, gap, filmGap);
      ++statistics_.filmPairs;
    }
    if (recordDamping_ && (pair.lubricated || pair.film > 0)) damped_.push_back(pair);
  }

  if (f2.squaredNorm() == 0) return;
  force[i] -= f2;
  torque[i] -= s1.arm.cross(f2);
  if (!wall) {
    force[j] += f2;
    torque[j] += s2.arm.cross(f2);
  }
}

void CollisionModel::addTangentialLubrication(const std::vector<CollisionBody>& bodies,
                                              const Lubrication& lubrication, int i, int j,
                                              const Vec3& shift, Scalar logFactor, const Mat3& S1,
                                              const Mat3& S2, const Vec3& n, const Vec3& p1,
                                              const Vec3& p2, const ContactSide& s1,
                                              const ContactSide& s2, Scalar subDt,
                                              std::vector<Vec3>& force,
                                              std::vector<Vec3>& torque) const {
  if (!(logFactor > 0)) return;
  const bool wall = j < 0;
  const TangentialLubrication law(S1, S2, n, lubrication.viscosity());
  // each body's motion about its closest point (body 2 through its image:
  // its own frame is the point less the shift)
  const CollisionBody& b1 = bodies[i];
  FilmSide side1, side2;
  side1.arm = p1 - b1.shape.centre();
  side1.velocity = b1.velocity;
  side1.angularVelocity = b1.angularVelocity;
  if (!wall) {
    side2.arm = p2 - shift - bodies[j].shape.centre();
    side2.velocity = bodies[j].velocity;
    side2.angularVelocity = bodies[j].angularVelocity;
  }
  FilmLoads l = law.loads(logFactor, side1, side2);
  const FilmMobility mobility(side1.arm, s1.inverseMass, s1.inverseInertia, side2.arm,
                              s2.inverseMass, s2.inverseInertia);
  Scalar rate = law.rate(logFactor, mobility);
  // the coupling of normal and tangential motion from the gap's cubic terms:
  // zero wherever both closest points are vertices, so two spheres and a
  // sphere and a wall skip it
  const bool sphere1 = b1.shape.elongation() == 1;
  const bool sphere2 = wall || bodies[j].shape.elongation() == 1;
  if (!(sphere1 && sphere2)) {
    const Tensor3 zero{Mat3::Zero(), Mat3::Zero(), Mat3::Zero()};
    const CubicGapCoupling coupling(
        S1, S2, sphere1 ? zero : b1.shape.surfaceThirdDerivative(p1),
        sphere2 ? zero : bodies[j].shape.surfaceThirdDerivative(p2 - shift), n,
        lubrication.viscosity());
    const FilmLoads c = coupling.loads(logFactor, side1, side2);
    l.force1 += c.force1;
    l.torque1 += c.torque1;
    l.torque2 += c.torque2;
    const FilmLaw couplingLaw = [&coupling](const FilmSide& one, const FilmSide& two) {
      return coupling.loads(1, one, two);
    };
    rate += logFactor * filmResistanceRate(couplingLaw, mobility);
  }
  // explicit in the sub-step, scaled by the backward-Euler factor of the
  // fastest rate the terms impose (the sum of the two laws' bounds): close to
  // 1 where the rate is small against 1/subDt, and never reversing the
  // relative motion where it is not
  const Scalar relax = 1 / (1 + subDt * rate);
  force[i] += relax * l.force1;
  torque[i] += relax * l.torque1;
  if (!wall) {
    force[j] -= relax * l.force1;
    torque[j] += relax * l.torque2;
  }
}

Scalar CollisionModel::lubricationCoefficientAt(const DampedPair& p, Scalar gap) const {
  return p.law.coefficient(gap);
}

Scalar CollisionModel::lubricationIntegral(const DampedPair& p, Scalar h0, Scalar h1) const {
  return p.law.primitive(h1) - (h0 == p.gap ? p.startPrimitive : p.law.primitive(h0));
}

Scalar CollisionModel::lubricatedEndSpeed(const DampedPair& p, Scalar uFree, Scalar wk, Scalar subDt,
                                          Scalar uRef) {
  // g(u) = (1 + wk dt D) u + wk I(u) - (uFree + wk dt D uRef) = 0: g increases
  // with u (I(u) is the integral of c >= 0 up to gap + u dt) and the root lies
  // between 0 and u0 = rhs/(1 + wk dt D); Newton (g' = 1 + wk dt D +
  // wk dt c(gap + u dt)) kept inside the bracket by bisection
  const Scalar a = 1 + wk * subDt * p.film;
  const Scalar rhs = uFree + wk * subDt * p.film * uRef;
  if (rhs == 0) return 0;
  const Scalar u0 = rhs / a;
  Scalar lo = std::min(Scalar(0), u0), hi = std::max(Scalar(0), u0);
  auto g = [&](Scalar u) { return a * u + wk * lubricationIntegral(p, p.gap, p.gap + u * subDt) - rhs; };
  // first guess: backward Euler with the start gap's coefficient (exact for
  // a path short against the gap, the common case: one or two iterations)
  Scalar u = rhs / (a + wk * subDt * lubricationCoefficientAt(p, p.gap));
  for (int it = 0; it < kMaxLubricationIterations; ++it) {
    const Scalar gu = g(u);
    if (gu == 0) return u;
    if (gu > 0) hi = u; else lo = u;
    const Scalar slope = a + wk * subDt * lubricationCoefficientAt(p, p.gap + u * subDt);
    Scalar next = u - gu / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) <= 1e-14 * std::abs(u0) || hi - lo <= 1e-14 * std::abs(u0)) return next;
    u = next;
  }
  ++statistics_.lubricationNotConverged;
  return u;
}

void CollisionModel::dampingForces(const std::vector<CollisionBody>& bodies,
                                   const std::vector<Vec3>& endVelocity,
                                   const std::vector<Vec3>& endAngularVelocity,
                                   const std::vector<Vec3>& referenceVelocity,
                                   const std::vector<Vec3>& referenceAngularVelocity, Scalar subDt,
                                   std::vector<Vec3>& force, std::vector<Vec3>& torque,
                                   const std::vector<char>* active) {
  const std::size_t n = bodies.size();
  // (each message built only on failure: called once per sub-step)
  if (endVelocity.size() != n || endAngularVelocity.size() != n) {
    require(false, "dampingForces: " + std::to_string(n) + " bodies but " +
                       std::to_string(endVelocity.size()) + " velocities and " +
                       std::to_string(endAngularVelocity.size()) + " angular velocities");
  }
  if (!(std::isfinite(subDt) && subDt > 0)) {
    require(false, "dampingForces: sub-step " + std::to_string(subDt) + " must be > 0");
  }
  force.assign(n, Vec3::Zero());
  torque.assign(n, Vec3::Zero());
  lastDampingValid_ = false;
  if (active) {
    // the damping forces of the pairs that do not take this sub-step stay
    for (auto it = lastDamping_.begin(); it != lastDamping_.end();) {
      it = (*active)[PairKey::first(it->first)] ? lastDamping_.erase(it) : std::next(it);
    }
  } else {
    lastDamping_.clear();
  }
  if (damped_.empty()) return;
  bool films = false;
  for (const DampedPair& p : damped_) {
    if (!(p.first >= 0 && std::size_t(p.first) < n &&
          (p.second < 0 ? -1 - p.second < static_cast<int>(walls_.size())
                        : std::size_t(p.second) < n))) {
      require(false, "dampingForces: the recorded pairs are of other bodies (call forces() first)");
    }
    films = films || p.film > 0;
  }
  if (films && (referenceVelocity.size() != n || referenceAngularVelocity.size() != n)) {
    require(false, "dampingForces: the film correction needs the reference velocities of all " +
                       std::to_string(n) + " bodies");
  }
  ++statistics_.dampingSolves;

  std::vector<Vec3> v = endVelocity, w = endAngularVelocity;
  const std::size_t m = damped_.size();
  impulse_.assign(m, 0);
  auto side = [&](int b, const Vec3& arm) {
    ContactSide s;
    if (b >= 0 && bodies[b].movable) {
      s.movable = true;
      s.inverseMass = 1 / bodies[b].mass;
      s.inverseInertia = bodies[b].inverseInertia;
    }
    s.arm = arm;
    return s;
  };
  // relative normal velocity of a pair (second relative to first) at the
  // velocities vv, ww
  auto normalSpeed = [](const DampedPair& p, const std::vector<Vec3>& vv, const std::vector<Vec3>& ww) {
    Vec3 rel = -(vv[p.first] + ww[p.first].cross(p.arm1));
    if (p.second >= 0) rel += vv[p.second] + ww[p.second].cross(p.arm2);
    return rel.dot(p.normal);
  };
  // does the gap of a pair change with its velocities (a side that moves:
  // free or prescribed; not a wall, a fixed or a frozen body)?
  auto moves = [&](int b) { return b >= 0 && bodies[b].movable && !bodies[b].stationary; };
  auto onPath = [&](const DampedPair& p) { return moves(p.first) || moves(p.second); };
  // per pair: the inverse effective mass along its normal and the reference speed
  std::vector<Scalar>& wk = pairInverseMass_;
  std::vector<Scalar>& uRef = pairReferenceSpeed_;
  wk.resize(m);
  uRef.assign(m, 0);
  Scalar scale = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const DampedPair& p = damped_[k];
    wk[k] = inverseEffectiveMass(side(p.first, p.arm1), side(p.second, p.arm2), p.normal);
    if (p.film > 0) uRef[k] = normalSpeed(p, referenceVelocity, referenceAngularVelocity);
    scale = std::max({scale, std::abs(normalSpeed(p, v, w)), std::abs(uRef[k])});
  }
  if (scale == 0) return;  // no relative normal motion: no force

  int sweeps = 0;
  bool converged = false;
  while (sweeps < kMaxDampingSweeps && !converged) {
    ++sweeps;
    Scalar largestChange = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const DampedPair& p = damped_[k];
      if (!(wk[k] > 0)) {
        // neither side responds to the load (a wall and a prescribed body,
        // two prescribed bodies): the velocities are imposed and the impulse
        // is the law's at them, over the gap path when a side moves and at
        // the gap when none does (a frozen prescribed body); it changes no
        // motion, the bodies report it as their load
        const Scalar u = normalSpeed(p, v, w);
        const Scalar lubrication =
            !p.lubricated ? 0
            : onPath(p) ? lubricationIntegral(p, p.gap, p.gap + u * subDt)
                        : lubricationCoefficientAt(p, p.gap) * u * subDt;
        impulse_[k] = -lubrication - subDt * p.film * (u - uRef[k]);
        continue;
      }
      // the impulse lambda on the second body along n with
      // lambda = -I(u) - subDt D (u - u_ref), u = u_n(end), I(u) the integral
      // of the lubrication coefficient over the gap path from gap to
      // gap + u subDt; the other pairs' impulses held: u_n moves by wk per
      // unit impulse
      const Scalar uFree = normalSpeed(p, v, w) - wk[k] * impulse_[k];
      Scalar target;
      if (p.lubricated) {
        const Scalar u = lubricatedEndSpeed(p, uFree, wk[k], subDt, uRef[k]);
        target = -lubricationIntegral(p, p.gap, p.gap + u * subDt) - subDt * p.film * (u - uRef[k]);
      } else {
        const Scalar h = subDt * p.film;
        target = -(h * uFree - subDt * p.film * uRef[k]) / (1 + h * wk[k]);
      }
      const Scalar change = target - impulse_[k];
      impulse_[k] = target;
      const Vec3 j2 = change * p.normal;  // on the second body; -j2 on the first
      if (bodies[p.first].movable) {
        v[p.first] -= j2 / bodies[p.first].mass;
        w[p.first] -= bodies[p.first].inverseInertia * p.arm1.cross(j2);
      }
      if (p.second >= 0 && bodies[p.second].movable) {
        v[p.second] += j2 / bodies[p.second].mass;
        w[p.second] += bodies[p.second].inverseInertia * p.arm2.cross(j2);
      }
      largestChange = std::max(largestChange, std::abs(change) * wk[k]);
    }
    converged = largestChange <= kDampingTolerance * scale;
  }
  statistics_.dampingSweeps += sweeps;
  if (!converged) ++statistics_.dampingNotConverged;
  // the coefficient each lubricated pair received: the mean over its path
  for (DampedPair& p : damped_) {
    if (!p.lubricated) continue;
    const Scalar dh = onPath(p) ? normalSpeed(p, v, w) * subDt : 0;
    p.lubricationMean = std::abs(dh) > 1e-12 * (std::abs(p.gap) + p.radius1)
                            ? lubricationIntegral(p, p.gap, p.gap + dh) / dh
                            : lubricationCoefficientAt(p, p.gap);
  }

  for (std::size_t k = 0; k < m; ++k) {
    const DampedPair& p = damped_[k];
    const Vec3 f2 = (impulse_[k] / subDt) * p.normal;
    // (Eigen's default constructor leaves a new entry uninitialised)
    if (f2.squaredNorm() > 0) lastDamping_.try_emplace(p.key, Vec3::Zero()).first->second += f2;
    force[p.first] -= f2;
    torque[p.first] -= p.arm1.cross(f2);
    if (p.second >= 0) {
      force[p.second] += f2;
      torque[p.second] += p.arm2.cross(f2);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!force[i].allFinite() || !torque[i].allFinite()) {
      throw std::runtime_error("collision: non-finite damping force on body " + std::to_string(i));
    }
  }
}

std::vector<CollisionModel::Overlap> CollisionModel::overlaps(
    const std::vector<CollisionBody>& bodies, Scalar ratio) {
  std::vector<Overlap> found;
  const int n = static_cast<int>(bodies.size());
  std::vector<Vec3> centres(n);
  std::vector<Scalar> radii(n);
  for (int i = 0; i < n; ++i) {
    centres[i] = bodies[i].shape.centre();
    radii[i] = bodies[i].shape.maxSemiAxis();
  }
  for (const CandidatePair& candidate : search_.find(centres, radii, box_)) {
    const int i = candidate.first, j = candidate.second;
    const ellipsoids::Ellipsoid& e1 = bodies[i].shape;
    const ellipsoids::Ellipsoid e2 = candidate.image == PeriodicBox::kNoImage
                                         ? bodies[j].shape
                                         : bodies[j].shape.translatedBy(box_.shift(candidate.image));
    if (overlap_.test(e1, e2) == ellipsoids::OverlapStatus::separated) continue;
    ellipsoids::DistanceOptions options;
    options.epsD = settings_.distanceAccuracy * std::min(e1.minGaussianRadius(), e2.minGaussianRadius());
    const ellipsoids::DistanceResult r = dual_.distance(e1, e2, options);
    const Scalar aMin = std::min(e1.minSemiAxis(), e2.minSemiAxis());
    if (-r.distance > ratio * aMin) found.push_back(Overlap{i, j, -r.distance / aMin});
  }
  for (int i = 0; i < n; ++i) {
    for (int w = 0; w < static_cast<int>(walls_.size()); ++w) {
      const Scalar gap = wallDistance(bodies[i].shape, walls_[w]).distance;
      const Scalar aMin = bodies[i].shape.minSemiAxis();
      if (-gap > ratio * aMin) found.push_back(Overlap{i, -1 - w, -gap / aMin});
    }
  }
  return found;
}

}  // namespace collision
