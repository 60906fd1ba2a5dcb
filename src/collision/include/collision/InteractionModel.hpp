/**
 * @file InteractionModel.hpp
 * @brief One normal contact, one friction law and one lubrication law: what
 *        a PairModel (body-body) and a WallModel (body-wall) combine.
 *
 * Usage (InteractionParameters; the defaults and ranges are those of
 * ContactParameters and LubricationParameters):
 * | parameter   | used by                        | default | range |
 * |-------------|--------------------------------|---------|-------|
 * | contact     | SpringDashpotContact (restitution), the friction law of frictionModel (friction) | 0.97, coulombSpring, 0 | (0, 1], coulombSpring or coulombSliding, [0, 100] |
 * | lubrication | StokesLubrication              | LubricationParameters |   |
 * | viscosity   | StokesLubrication, from the caller | 0   | > 0 when lubricated |
 *
 * See also: PairModel, WallModel, CollisionModel.
 */
#ifndef COLLISION_INTERACTIONMODEL_HPP
#define COLLISION_INTERACTIONMODEL_HPP

#include "collision/Friction.hpp"
#include "collision/Lubrication.hpp"
#include "collision/SpringDashpotContact.hpp"

#include <memory>
#include <string>
#include <vector>

namespace collision {

/// The constants of the laws a model is built from (its factory reads the ones it needs).
struct InteractionParameters {
  ContactParameters contact;
  LubricationParameters lubrication;
  /// dynamic viscosity mu of the fluid [Pa s], passed in by the caller (lubricated models: > 0)
  Scalar viscosity = 0;

  /// @throws std::invalid_argument naming the parameter and its allowed range
  void validate() const;
};

/// The friction law ContactParameters::frictionModel names, with its coefficient (and restitution).
std::unique_ptr<Friction> makeFriction(const ContactParameters& contact);

class InteractionModel {
 public:
  /// @throws std::invalid_argument if a law is missing
  InteractionModel(std::string name, const SpringDashpotContact& contact,
                   std::unique_ptr<Friction> friction, std::unique_ptr<Lubrication> lubrication,
                   Scalar rollingFriction = 0);
  virtual ~InteractionModel() = default;

  InteractionModel(const InteractionModel&) = delete;
  InteractionModel& operator=(const InteractionModel&) = delete;

  /// the name it was built by
  const std::string& name() const { return name_; }
  const SpringDashpotContact& contact() const { return contact_; }
  const Friction& friction() const { return *friction_; }
  const Lubrication& lubrication() const { return *lubrication_; }
  /// mu_r of the rolling resistance (RollingResistance.hpp; 0: none)
  Scalar rollingFriction() const { return rollingFriction_; }

 protected:
  /// "a, b": the allowed names of a factory, for its error message
  static std::string list(const std::vector<std::string>& names);

 private:
  std::string name_;
  SpringDashpotContact contact_;
  std::unique_ptr<Friction> friction_;
  std::unique_ptr<Lubrication> lubrication_;
  Scalar rollingFriction_ = 0;
};

}  // namespace collision

#endif
