#include "coulomb/contact/formulation/Formulations.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
std::unique_ptr<Formulation> make(const PairConstants& constants, ContactSystemForm form) {
  const ContactPairSettings& s = *constants.settings;
  // The deck's check (parseContactSettings) keeps the saddle-point form to LMM and ALM frictionless pairs.
  if (s.formulation == ContactFormulation::LMM) {
    COULOMB_CHECK(form == ContactSystemForm::SaddlePoint, "an LMM pair in the condensed form");
    return makeLagrangeNcp<dim>(constants);
  }
  if (form == ContactSystemForm::SaddlePoint) {
    COULOMB_CHECK(s.formulation == ContactFormulation::ALM && !s.frictional(),
                  "the saddle-point form is for ALM frictionless pairs");
    return makeSaddlePoint<dim>(constants);
  }
  if (s.formulation == ContactFormulation::Penalty) return makePenalty<dim>(constants);
  return s.frictional() ? makeAlmFrictional<dim>(constants) : makeAlmFrictionless<dim>(constants);
}

}  // namespace

std::unique_ptr<Formulation> makeFormulation(int dim, const PairConstants& constants, ContactSystemForm form) {
  COULOMB_CHECK(dim == 2 || dim == 3, "contact in dimension " << dim);
  return dim == 2 ? make<2>(constants, form) : make<3>(constants, form);
}

}  // namespace coulomb::contact
