#include "coulomb/contact/formulation/RowSink.hpp"

#include "coulomb/contact/interface/ContactInterface.hpp"

namespace coulomb::contact {

RowSink::RowSink(ContactContributions& contributions, const ContactInterface& contact,
                 const std::vector<std::array<bool, 3>>& prescribed, GlobalOrdinal multiplierOffset)
    : out(contributions),
      contact_(contact),
      prescribed_(prescribed),
      dim_(contact.dimension()),
      multiplierOffset_(multiplierOffset) {}

bool isPrescribedDof(const ContactInterface& contact, const std::vector<std::array<bool, 3>>& prescribed,
                     long long node, int c) {
  const int i = contact.interfaceNodeIndex(node);
  return i >= 0 && prescribed[i][c];
}

bool RowSink::prescribed(long long node, int c) const { return isPrescribedDof(contact_, prescribed_, node, c); }

void RowSink::add(std::vector<linalg::MatrixTriplet>& to, GlobalOrdinal target, const DerivativeRow& d,
                  double scale) const {
  for (const auto& [key, value] : d)
    if (value != 0.0 && !prescribed(key.first, key.second)) to.push_back({target, row(key.first, key.second), scale * value});
}

}  // namespace coulomb::contact
