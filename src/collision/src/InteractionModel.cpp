#include "collision/InteractionModel.hpp"
#include "collision/CoulombFriction.hpp"
#include "collision/SpringCoulombFriction.hpp"

#include <cmath>
#include <stdexcept>

namespace collision {

std::unique_ptr<Friction> makeFriction(const ContactParameters& contact) {
  contact.validate();
  if (contact.frictionModel == "coulombSliding") {
    return std::make_unique<CoulombFriction>(contact.friction);
  }
  return std::make_unique<SpringCoulombFriction>(contact.friction, contact.restitution);
}

void InteractionParameters::validate() const {
  contact.validate();
  lubrication.validate();
  if (!(std::isfinite(viscosity) && viscosity >= 0)) {
    throw std::invalid_argument("collision: viscosity = " + Range::number(viscosity) +
                                " must be >= 0");
  }
}

InteractionModel::InteractionModel(std::string name, const SpringDashpotContact& contact,
                                   std::unique_ptr<Friction> friction,
                                   std::unique_ptr<Lubrication> lubrication,
                                   Scalar rollingFriction)
    : name_(std::move(name)),
      contact_(contact),
      friction_(std::move(friction)),
      lubrication_(std::move(lubrication)),
      rollingFriction_(rollingFriction) {
  if (!friction_ || !lubrication_) {
    throw std::invalid_argument("collision: model " + name_ +
                                " needs a friction and a lubrication law");
  }
}

std::string InteractionModel::list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace collision
