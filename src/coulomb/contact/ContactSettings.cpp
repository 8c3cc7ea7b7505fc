#include "coulomb/contact/ContactSettings.hpp"

#include <limits>

#include <Teuchos_ParameterList.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ParameterValidation.hpp"
#include "coulomb/io/RangeValidator.hpp"

namespace coulomb::contact {

using Teuchos::ParameterList;

const char* toString(ContactFormulation formulation) {
  return formulation == ContactFormulation::ALM ? "ALM" : "Penalty";
}

void addValidContactParameters(ParameterList& valid) {
  ParameterList& contact = valid.sublist("Contact", false, "Frictionless mortar contact (docs/deck.md, 'Contact')");
  const ContactSettings defaults;
  contact.set("Normal Relative Tolerance", defaults.normalRelativeTolerance,
              "converged when ||eps_n g~|| (active nodes) <= this x ||contact forces|| + the absolute tolerance",
              io::positive());
  contact.set("Normal Absolute Tolerance", defaults.normalAbsoluteTolerance,
              "absolute part of the normal-constraint test [force]", io::positive());
  ParameterList& pairs = contact.sublist("Pairs", false, "One sublist per contact pair, named freely");
  ParameterList& pair = pairs.sublist("*", false, "a slave/master pair of side sets");
  const ContactPairSettings d;
  pair.set("Slave", "", std::string(io::kRequired) + "slave side set (the finer or curved surface)");
  pair.set("Master", "", std::string(io::kRequired) + "master side set");
  pair.set("Formulation", "ALM",
           "ALM: Lagrange multipliers (condensed), no penetration at convergence; Penalty: pressure eps_n <-gap>",
           io::oneOf({"ALM", "Penalty"}));
  pair.set("Penalty", d.penalty,
           "normal penalty eps_n [force/length^3]; 0 = automatic: Penalty Factor x E / h (E largest Young's modulus "
           "of the two bodies, h mean slave face size)",
           io::nonNegative());
  pair.set("Penalty Factor", d.penaltyFactor, "factor of the automatic penalty", io::positive());
  pair.set("Scale Factor", d.scaleFactor, "ALM scale factor k (contact traction = k lambda)", io::positive());
  pair.set("Semi-Smooth Newton", "Full",
           "Full: active set updated every iteration; Simplified: only at the first two evaluations of a step "
           "(and again after an iterate where the frozen set violates the contact conditions)",
           io::oneOf({"Full", "Simplified"}));
  pair.set("Search Every Iteration", d.searchEveryIteration, "search candidates every Newton iteration (else per step)");
  pair.set("Search Radius Factor", d.searchRadiusFactor,
           "search radius = this x the largest slave face diameter: must exceed the gap closed in one step",
           io::positive());
}

ContactSettings parseContactSettings(const ParameterList& deck) {
  ContactSettings settings;
  if (!deck.isSublist("Contact")) return settings;
  ParameterList valid;
  addValidContactParameters(valid);
  const ParameterList& user = deck.sublist("Contact");
  const ParameterList& validContact = valid.sublist("Contact");
  settings.normalRelativeTolerance = io::valueOrDefault<double>(user, validContact, "Normal Relative Tolerance");
  settings.normalAbsoluteTolerance = io::valueOrDefault<double>(user, validContact, "Normal Absolute Tolerance");
  if (!user.isSublist("Pairs")) return settings;
  const ParameterList& pairs = user.sublist("Pairs");
  const ParameterList& v = validContact.sublist("Pairs").sublist("*");
  for (auto it = pairs.begin(); it != pairs.end(); ++it) {
    const std::string& name = pairs.name(it);
    const ParameterList& p = pairs.sublist(name);
    ContactPairSettings s;
    s.name = name;
    s.slave = p.get<std::string>("Slave");
    s.master = p.get<std::string>("Master");
    s.formulation = io::valueOrDefault<std::string>(p, v, "Formulation") == "ALM" ? ContactFormulation::ALM
                                                                                   : ContactFormulation::Penalty;
    s.penalty = io::valueOrDefault<double>(p, v, "Penalty");
    s.penaltyFactor = io::valueOrDefault<double>(p, v, "Penalty Factor");
    s.scaleFactor = io::valueOrDefault<double>(p, v, "Scale Factor");
    s.semiSmooth = io::valueOrDefault<std::string>(p, v, "Semi-Smooth Newton") == "Full" ? SemiSmoothNewton::Full
                                                                                         : SemiSmoothNewton::Simplified;
    s.searchEveryIteration = io::valueOrDefault<bool>(p, v, "Search Every Iteration");
    s.searchRadiusFactor = io::valueOrDefault<double>(p, v, "Search Radius Factor");
    COULOMB_REQUIRE(s.slave != s.master, "deck: 'Contact/Pairs/" << name << "' names side set '" << s.slave
                                                                  << "' as both Slave and Master");
    settings.pairs.push_back(std::move(s));
  }
  return settings;
}

}  // namespace coulomb::contact
