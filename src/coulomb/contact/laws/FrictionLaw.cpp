#include "coulomb/contact/laws/FrictionLaw.hpp"

namespace coulomb::contact {

const char* toString(FrictionLawType type) {
  switch (type) {
    case FrictionLawType::None:
      return "None";
    case FrictionLawType::Coulomb:
      return "Coulomb";
    case FrictionLawType::Tresca:
      return "Tresca";
  }
  return "Unknown";
}

}  // namespace coulomb::contact
