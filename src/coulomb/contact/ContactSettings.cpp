#include "coulomb/contact/ContactSettings.hpp"

#include <algorithm>
#include <limits>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/Choices.hpp"
#include "coulomb/io/ExodusResults.hpp"
#include "coulomb/io/ParameterValidation.hpp"
#include "coulomb/io/RangeValidator.hpp"

namespace coulomb::contact {

using Teuchos::ParameterList;

namespace {

// The deck's enumerations, each declared once (names, values; the validator,
// the parse and the messages come from these tables).
const io::Choices<ContactFormulation> kFormulations{
    {"ALM", ContactFormulation::ALM},
    {"Penalty", ContactFormulation::Penalty},
    {"MPC", ContactFormulation::MPC},
    {"LMM", ContactFormulation::LMM}};
const io::Choices<SemiSmoothNewton> kSemiSmooth{{"Full", SemiSmoothNewton::Full},
                                                {"Simplified", SemiSmoothNewton::Simplified}};
const io::Choices<FrictionLawType> kFrictionLaws{
    {"None", FrictionLawType::None}, {"Coulomb", FrictionLawType::Coulomb}, {"Tresca", FrictionLawType::Tresca}};
const io::Choices<SlipMeasure> kSlipMeasures{{"Objective", SlipMeasure::Objective},
                                             {"Non-Objective", SlipMeasure::NonObjective}};
const io::Choices<InterfaceDistribution> kDistributions{{"Element Owners", InterfaceDistribution::ElementOwners},
                                                         {"Balanced", InterfaceDistribution::Balanced}};
const io::Choices<ConvergenceCriterion> kCriteria{{"Residual", ConvergenceCriterion::Residual},
                                                  {"Increment", ConvergenceCriterion::Increment},
                                                  {"Mixed", ConvergenceCriterion::Mixed}};
const io::Choices<ContactSystemForm> kSystemForms{{"Condensed", ContactSystemForm::Condensed},
                                                  {"Saddle Point", ContactSystemForm::SaddlePoint}};

/// Measured friction coefficients stay below 10 (rubber on clean glass
/// reaches about 4): a larger mu is a unit or typing error. At mu = 10 a
/// node already sticks wherever its tangential traction is below ten times
/// its pressure.
constexpr double kLargestFrictionCoefficient = 10.0;

}  // namespace

const char* toString(ContactFormulation formulation) { return kFormulations.name(formulation); }

void addValidContactParameters(ParameterList& valid) {
  ParameterList& contact =
      valid.sublist("Contact", false, "Dual mortar contact, frictionless or with friction (docs/deck.md, 'Contact')");
  const ContactSettings defaults;
  contact.set("Normal Relative Tolerance", defaults.normalRelativeTolerance,
              "converged when ||eps_n g~|| (active nodes) <= this x ||contact forces|| + the absolute tolerance",
              io::positive());
  contact.set("Normal Absolute Tolerance", defaults.normalAbsoluteTolerance,
              "absolute part of the normal-constraint test [force]", io::positive());
  contact.set("Stick Relative Tolerance", defaults.stickRelativeTolerance,
              "converged when the stick rows eps_n t |w_tau| <= this x ||contact forces|| + the absolute tolerance",
              io::positive());
  contact.set("Stick Absolute Tolerance", defaults.stickAbsoluteTolerance, "absolute part of the stick test [force]",
              io::positive());
  contact.set("Slip Relative Tolerance", defaults.slipRelativeTolerance,
              "converged when the slip rows |f_tau - t D Θ d| <= this x ||contact forces|| + the absolute tolerance",
              io::positive());
  contact.set("Slip Absolute Tolerance", defaults.slipAbsoluteTolerance, "absolute part of the slip test [force]",
              io::positive());
  contact.set("Tangential Normal Ratio", defaults.tangentNormalRatio,
              "the stick and slip tests count as met while ||tangential contact forces|| <= this x ||contact forces|| "
              "(negligible friction; the rows stay in the residual test)",
              io::nonNegative());
  contact.set("Convergence Criterion", std::string(kCriteria.name(defaults.criterion)),
              "besides an unchanged active set - Residual: ||f|| (Newton tolerances) and the contact rows by group "
              "(normal, stick, slip: the tolerances above); Increment: the displacement increment (the increment "
              "tolerances) and the change of the nodal contact forces by group since the last iterate (the tolerances "
              "above); Mixed: ||f|| and the contact force changes by group",
              kCriteria.validator());
  contact.set("Increment Relative Tolerance", defaults.incrementRelativeTolerance,
              "Convergence Criterion = Increment: the RMS of |du_i| / (this x |u_i| + the absolute one) <= 1",
              io::positive());
  contact.set("Increment Absolute Tolerance", defaults.incrementAbsoluteTolerance,
              "Convergence Criterion = Increment: absolute part [length]", io::positive());
  contact.set("System Form", std::string(kSystemForms.name(defaults.systemForm)),
              "Condensed: multipliers eliminated, displacement-only Newton system (default; LMM pairs: Saddle "
              "Point); Saddle Point: the multipliers are Newton unknowns, solved by the direct solver (Amesos2) - "
              "for LMM pairs, and a check of the condensation with ALM frictionless pairs",
              kSystemForms.validator());
  ParameterList& pairs = contact.sublist("Pairs", false, "One sublist per contact pair, named freely");
  ParameterList& pair = pairs.sublist("*", false, "a slave/master pair of side sets");
  const ContactPairSettings d;
  pair.set("Slave", "", std::string(io::kRequired) + "slave side set (the finer or curved surface)");
  pair.set("Master", "", std::string(io::kRequired) + "master side set (the same list as Slave: a surface that may touch itself)");
  pair.set("Formulation", std::string(kFormulations.name(d.formulation)),
           "ALM: Lagrange multipliers (condensed), no penetration at convergence; Penalty: pressure eps_n <-gap>; "
           "MPC: multipoint constraints (slave tied to master: stick all directions, slip normal only + Coulomb "
           "force), states from reactions and gaps; LMM: Lagrange multipliers as Newton unknowns with the "
           "complementarity functions of the thesis (4.79), frictionless or frictional (System Form = Saddle Point, "
           "the default with it; a direct solver)",
           kFormulations.validator());
  pair.set("Penalty", d.penalty,
           "normal penalty eps_n [force/length^3]; 0 = automatic: Penalty Factor x E / h (E = min(E_s, E_m), E_s and "
           "E_m the largest Young's moduli on the slave and the master side; h mean slave face size)",
           io::nonNegative());
  pair.set("Penalty Factor", d.penaltyFactor, "factor of the automatic penalty", io::positive());
  pair.set("Scale Factor", d.scaleFactor, "ALM scale factor k (contact traction = k lambda)", io::positive());
  pair.set("Semi-Smooth Newton", std::string(kSemiSmooth.name(d.semiSmooth)),
           "Full: active set updated every iteration; Simplified: only at the first two evaluations of a step "
           "(and again after an iterate where the frozen set violates the contact conditions)",
           kSemiSmooth.validator());
  pair.set("Search Every Iteration", d.searchEveryIteration, "search candidates every Newton iteration (else per step)");
  pair.set("Search Radius Factor", d.searchRadiusFactor,
           "search radius = this x the largest slave face diameter: should exceed the gap closed in one step; an active node found deeper than the radius widens it to twice its depth for the rest of the run (the step is retried)",
           io::positive());
  pair.set("Feature Angle", d.featureAngle,
           "[degrees] slave faces around a node whose normals differ by more than this are across a sharp edge "
           "(a block's bottom and sides in one slave set): the node's normal is the average over the side that "
           "faces the master, not over all its faces; 180 averages all faces everywhere",
           Teuchos::rcp(new io::RangeValidator(0.0, true, 180.0, false)));
  pair.set("Interface Distribution", std::string(kDistributions.name(d.distribution)),
           "which rank integrates a slave face: Element Owners, the rank of its element; Balanced, the faces "
           "redistributed over all ranks by their candidate master faces at every search",
           kDistributions.validator());
  pair.set("Friction Law", std::string(kFrictionLaws.name(d.friction.type)),
           "None: frictionless; Coulomb: |t_tau| <= mu p; Tresca: |t_tau| <= Tresca Threshold",
           kFrictionLaws.validator());
  pair.set("Friction Coefficient", d.friction.coefficient, "Coulomb's mu (0: pure slip)", io::nonNegative());
  pair.set("Friction Coefficient Field", "",
           "Coulomb's mu per node: the name of a nodal variable of the mesh file (its last time step), instead of "
           "Friction Coefficient");
  pair.set("Tresca Threshold", d.friction.threshold,
           "Tresca's limit of the tangential traction [pressure], required (> 0) with Friction Law = Tresca",
           io::nonNegative());
  pair.set("Tangent Factor", d.tangentFactor,
           "kappa: tangential penalty eps_tau = kappa eps_n (ALM: stick/slip test and slip direction; Penalty: the "
           "tangential stiffness of a sticking contact)",
           io::positive());
  pair.set("Slip Threshold", d.slipThreshold,
           "hysteresis: a slipping node sticks again only below (1 - this) x the friction threshold", io::nonNegative());
  pair.set("Slip Augmentation Coefficient", d.slipAugmentation,
           "alpha: weight of the slip in the augmented tangential multiplier of slipping nodes (> 0: the slip "
           "direction is a Newton unknown)",
           io::positive());
  pair.set("Slip Reset Frequency", d.slipResetFrequency,
           "slipping nodes restart each n-th load step as stick (the thesis' choice, n = 1; MPC default 0); 0: never "
           "reset; < 0: never reset, and slipping nodes keep the direction of their slip in the last step",
           Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(-1000000, 1000000)));
  pair.set("Slip Measure", std::string(kSlipMeasures.name(d.slipMeasure)),
           "Objective: weighted slip from the change of the mortar operators (4.69b, frame indifferent); "
           "Non-Objective: from the displacement increments (4.65a)",
           kSlipMeasures.validator());
  pair.set("Operator Threshold", d.operatorThreshold,
           "objective slip only where the mortar operators changed by more than this (relative) over the step, "
           "else the non-objective one; 0: objective whenever possible",
           io::nonNegative());
  pair.set("Ensure Contact", d.ensureContact,
           "a converged step in which no slave node of this pair is in contact is an error (the bodies were meant "
           "to touch: a wrong set, sign or load), instead of a result without contact");
  pair.set("Pure Slip", d.pureSlip,
           "every active node slides, with the law's threshold against its slip (never sticks); every mu = 0 is "
           "frictionless");
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
  settings.stickRelativeTolerance = io::valueOrDefault<double>(user, validContact, "Stick Relative Tolerance");
  settings.stickAbsoluteTolerance = io::valueOrDefault<double>(user, validContact, "Stick Absolute Tolerance");
  settings.slipRelativeTolerance = io::valueOrDefault<double>(user, validContact, "Slip Relative Tolerance");
  settings.slipAbsoluteTolerance = io::valueOrDefault<double>(user, validContact, "Slip Absolute Tolerance");
  settings.tangentNormalRatio = io::valueOrDefault<double>(user, validContact, "Tangential Normal Ratio");
  settings.systemForm = kSystemForms.value(io::valueOrDefault<std::string>(user, validContact, "System Form"));
  settings.criterion =
      kCriteria.value(io::valueOrDefault<std::string>(user, validContact, "Convergence Criterion"));
  settings.incrementRelativeTolerance =
      io::valueOrDefault<double>(user, validContact, "Increment Relative Tolerance");
  settings.incrementAbsoluteTolerance =
      io::valueOrDefault<double>(user, validContact, "Increment Absolute Tolerance");
  if (!user.isSublist("Pairs")) return settings;
  // LMM pairs keep their multipliers: the saddle-point form unless the deck says otherwise (an error below).
  for (auto it = user.sublist("Pairs").begin(); it != user.sublist("Pairs").end(); ++it) {
    const ParameterList& p = user.sublist("Pairs").sublist(user.sublist("Pairs").name(it));
    if (!user.isParameter("System Form") && p.isParameter("Formulation") &&
        p.get<std::string>("Formulation") == kFormulations.name(ContactFormulation::LMM))
      settings.systemForm = ContactSystemForm::SaddlePoint;
  }
  const ParameterList& pairs = user.sublist("Pairs");
  const ParameterList& v = validContact.sublist("Pairs").sublist("*");
  for (auto it = pairs.begin(); it != pairs.end(); ++it) {
    const std::string& name = pairs.name(it);
    const ParameterList& p = pairs.sublist(name);
    ContactPairSettings s;
    s.name = name;
    s.slave = p.get<std::string>("Slave");
    s.master = p.get<std::string>("Master");
    s.formulation = kFormulations.value(io::valueOrDefault<std::string>(p, v, "Formulation"));
    s.penalty = io::valueOrDefault<double>(p, v, "Penalty");
    s.penaltyFactor = io::valueOrDefault<double>(p, v, "Penalty Factor");
    s.scaleFactor = io::valueOrDefault<double>(p, v, "Scale Factor");
    s.semiSmooth = kSemiSmooth.value(io::valueOrDefault<std::string>(p, v, "Semi-Smooth Newton"));
    s.searchEveryIteration = io::valueOrDefault<bool>(p, v, "Search Every Iteration");
    s.searchRadiusFactor = io::valueOrDefault<double>(p, v, "Search Radius Factor");
    s.featureAngle = io::valueOrDefault<double>(p, v, "Feature Angle");
    s.distribution = kDistributions.value(io::valueOrDefault<std::string>(p, v, "Interface Distribution"));
    s.friction.type = kFrictionLaws.value(io::valueOrDefault<std::string>(p, v, "Friction Law"));
    s.friction.coefficient = io::valueOrDefault<double>(p, v, "Friction Coefficient");
    s.friction.threshold = io::valueOrDefault<double>(p, v, "Tresca Threshold");
    s.tangentFactor = io::valueOrDefault<double>(p, v, "Tangent Factor");
    s.slipThreshold = io::valueOrDefault<double>(p, v, "Slip Threshold");
    s.slipAugmentation = io::valueOrDefault<double>(p, v, "Slip Augmentation Coefficient");
    s.slipResetFrequency = io::valueOrDefault<int>(p, v, "Slip Reset Frequency");
    // MPC pairs never reset unless asked (docs/deck.md: a reset costs MPC
    // two Newton iterations per step in gross slip).
    if (s.formulation == ContactFormulation::MPC && !p.isParameter("Slip Reset Frequency")) s.slipResetFrequency = 0;
    s.slipMeasure = kSlipMeasures.value(io::valueOrDefault<std::string>(p, v, "Slip Measure"));
    s.pureSlip = io::valueOrDefault<bool>(p, v, "Pure Slip");
    s.ensureContact = io::valueOrDefault<bool>(p, v, "Ensure Contact");
    s.frictionCoefficientField = io::valueOrDefault<std::string>(p, v, "Friction Coefficient Field");
    s.operatorThreshold = io::valueOrDefault<double>(p, v, "Operator Threshold");
    const std::string where = "deck: 'Contact/Pairs/" + name + "/";
    COULOMB_REQUIRE(s.friction.type != FrictionLawType::Tresca || s.friction.threshold > 0.0,
                    where << "Tresca Threshold' must be > 0 with Friction Law = Tresca, got " << s.friction.threshold);
    COULOMB_REQUIRE(s.frictionCoefficientField.empty() || s.friction.type == FrictionLawType::Coulomb,
                    where << "Friction Coefficient Field' is given but 'Friction Law' is not Coulomb");
    COULOMB_REQUIRE(s.frictionCoefficientField.empty() || !p.isParameter("Friction Coefficient"),
                    where << "Friction Coefficient' and 'Friction Coefficient Field' are both given: keep one");
    COULOMB_REQUIRE(s.friction.type == FrictionLawType::Coulomb || !p.isParameter("Friction Coefficient"),
                    where << "Friction Coefficient' is given but 'Friction Law' is not Coulomb");
    COULOMB_REQUIRE(s.friction.type == FrictionLawType::Tresca || !p.isParameter("Tresca Threshold"),
                    where << "Tresca Threshold' is given but 'Friction Law' is not Tresca");
    COULOMB_REQUIRE(s.friction.coefficient <= kLargestFrictionCoefficient,
                    where << "Friction Coefficient' = " << s.friction.coefficient
                          << " is not a friction coefficient (measured ones stay below "
                          << kLargestFrictionCoefficient << "); a contact that must not slide sticks with mu = "
                          << kLargestFrictionCoefficient << " already");
    COULOMB_REQUIRE(s.slipThreshold < 1.0, where << "Slip Threshold' must be < 1, got " << s.slipThreshold);
    COULOMB_REQUIRE(s.slipResetFrequency >= 0 || s.formulation != ContactFormulation::Penalty,
                    where << "Slip Reset Frequency' < 0 (slip direction from the last step's slip) is for ALM and "
                             "MPC pairs; the penalty traction takes its direction from its return map");
    const bool lmm = s.formulation == ContactFormulation::LMM;
    COULOMB_REQUIRE(settings.systemForm == ContactSystemForm::Condensed || lmm ||
                        (s.formulation == ContactFormulation::ALM && !s.frictional()),
                    "deck: 'Contact/System Form' = Saddle Point is for LMM and ALM frictionless pairs; 'Contact/Pairs/"
                        << name << "' is " << (s.frictional() ? "frictional " : "") << toString(s.formulation));
    COULOMB_REQUIRE(!lmm || settings.systemForm == ContactSystemForm::SaddlePoint,
                    where << "Formulation' = LMM keeps the multipliers as unknowns: 'Contact/System Form' must be "
                             "Saddle Point (its default with LMM pairs), not Condensed");
    COULOMB_REQUIRE(!lmm || (!s.pureSlip && s.slipResetFrequency >= 0),
                    where << "Formulation' = LMM has no 'Pure Slip' and no 'Slip Reset Frequency' < 0 (ALM options)");
    settings.pairs.push_back(std::move(s));
  }
  return settings;
}

void loadFrictionFields(ContactSettings& settings, const std::string& meshFile) {
  for (auto& pair : settings.pairs) {
    if (pair.frictionCoefficientField.empty()) continue;
    const std::string where = "deck: 'Contact/Pairs/" + pair.name + "/Friction Coefficient Field': ";
    const io::ExodusResults results = io::readExodusResults(meshFile);
    const auto& names = results.nodalNames;
    const auto it = std::find(names.begin(), names.end(), pair.frictionCoefficientField);
    COULOMB_REQUIRE(it != names.end() && !results.nodal.empty(),
                    where << "the mesh '" << meshFile << "' has no nodal variable '" << pair.frictionCoefficientField
                          << "'");
    pair.nodalFrictionCoefficients = results.nodal.back()[static_cast<std::size_t>(it - names.begin())];
    for (std::size_t i = 0; i < pair.nodalFrictionCoefficients.size(); ++i)
      COULOMB_REQUIRE(pair.nodalFrictionCoefficients[i] >= 0.0 &&
                          pair.nodalFrictionCoefficients[i] <= kLargestFrictionCoefficient,
                      where << "'" << pair.frictionCoefficientField << "' is " << pair.nodalFrictionCoefficients[i]
                            << " at node " << i + 1 << ", outside [0, " << kLargestFrictionCoefficient
                            << "] (a friction coefficient)");
  }
}

}  // namespace coulomb::contact
