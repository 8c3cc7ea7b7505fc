#include "coulomb/contact/formulation/Formulations.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

std::unique_ptr<Formulation> makeFormulation(int dim, const PairConstants& constants, ContactSystemForm form) {
  COULOMB_CHECK(dim == 2 || dim == 3, "contact in dimension " << dim);
  const ContactPairSettings& s = *constants.settings;
  // The deck's check (parseContactSettings) keeps the saddle-point form to
  // LMM and ALM frictionless pairs, and LMM pairs to it. A frictionless ALM
  // pair with its multipliers as unknowns is the LMM of (4.79) with c_n =
  // eps_n: the active zone of C_n = p - max(0, p - c_n g) is the ALM's
  // (4.73/4.74), and its rows (c_n g, or p) the same conditions.
  if (form == ContactSystemForm::SaddlePoint) {
    COULOMB_CHECK(s.formulation == ContactFormulation::LMM ||
                      (s.formulation == ContactFormulation::ALM && !s.frictional()),
                  "the saddle-point form is for LMM and ALM frictionless pairs");
    return makeLagrangeNcp(dim, constants);
  }
  COULOMB_CHECK(s.formulation != ContactFormulation::LMM, "an LMM pair in the condensed form");
  if (s.formulation == ContactFormulation::Penalty) return makePenalty(dim, constants);
  return makeAlmFrictional(dim, constants);
}

}  // namespace coulomb::contact
