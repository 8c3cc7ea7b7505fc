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

void addMultiplierForces(RowSink& sink, int slave, long long node, const std::array<bool, 3>& prescribed,
                         const NodalMortarEntry& entry, const std::array<double, 3>& lambda, double toLambda, double kt,
                         bool withDerivatives, bool active, const std::array<double, 3>& normal,
                         PairIterationSummary& summary) {
  const int dim = sink.dimension();
  const double D = entry.D;
  auto& out = sink.out;
  std::array<double, 3> force{}, normalPart{};
  double fn = 0;
  for (int c = 0; c < dim; ++c) fn += kt * D * lambda[c] * normal[c];
  for (int c = 0; c < dim; ++c) {
    force[c] = kt * D * lambda[c];
    normalPart[c] = fn * normal[c];
    const GlobalOrdinal z = sink.multiplierDof(slave, c);
    if (!prescribed[c]) {
      const GlobalOrdinal row = sink.row(node, c);
      out.contactResidual.push_back({row, -force[c]});
      out.multipliers.columns.push_back({row, z, -kt * D * toLambda});
      if (withDerivatives) sink.add(out.contactStiffness, row, entry.dD, -kt * lambda[c]);
    }
    for (const auto& [master, Mjl] : entry.M) {
      if (sink.prescribed(master, c)) continue;
      const GlobalOrdinal row = sink.row(master, c);
      out.contactResidual.push_back({row, kt * Mjl * lambda[c]});
      out.multipliers.columns.push_back({row, z, kt * Mjl * toLambda});
      if (!withDerivatives) continue;
      const auto dM = entry.dM.find(master);
      if (dM != entry.dM.end()) sink.add(out.contactStiffness, row, dM->second, kt * lambda[c]);
    }
  }
  if (active) summary.addSlaveForce(force, normalPart);
}

void addVanishingMultiplier(RowSink& sink, int slave, const std::array<double, 3>& z, int dim, double scale) {
  auto& out = sink.out.multipliers;
  for (int c = 0; c < dim; ++c) {
    out.rows.push_back({sink.multiplierDof(slave, c), sink.multiplierDof(slave, c), scale});
    out.residual.push_back({sink.multiplierDof(slave, c), scale * z[c]});
  }
}

}  // namespace coulomb::contact
