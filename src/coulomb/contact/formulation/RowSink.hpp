#pragma once
/// @file RowSink.hpp
/// @brief Where a formulation puts a node's contributions
/// (ContactContributions), with the global row numbering and the one rule
/// for derivatives: prescribed columns are left out (the bulk tangent zeroes
/// those columns too, and their rows are u - u_bar).
#include <array>
#include <vector>

#include "coulomb/contact/ContactContributions.hpp"
#include "coulomb/contact/interface/MortarPass.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"

namespace coulomb::contact {

class ContactInterface;

/// Component c of global node `node` is a Dirichlet DoF (`prescribed` by
/// interface node index; a node off the interface is not).
bool isPrescribedDof(const ContactInterface& contact, const std::vector<std::array<bool, 3>>& prescribed,
                     long long node, int c);

class RowSink {
public:
  /// `prescribed[i][c]`: component c of interface node i is a Dirichlet DoF.
  /// `multiplierOffset`: the first global index of the pair's multiplier
  /// unknowns (saddle-point form).
  RowSink(ContactContributions& out, const ContactInterface& contact, const std::vector<std::array<bool, 3>>& prescribed,
          GlobalOrdinal multiplierOffset);

  ContactContributions& out;
  /// Which part of a node's contributions emit() writes: the residual part
  /// (residual entries, T - I, supports' forces, the summary figures) and
  /// the tangent part (derivative rows). A condensed update writes the
  /// residual part alone and the tangent part when the tangent is asked for
  /// (ContactPair::emitTangent): the last residual of a step needs no
  /// derivatives. Both by default (the saddle-point form, chained pairs).
  bool residualPart = true;
  bool tangentPart = true;

  int dimension() const { return dim_; }
  GlobalOrdinal row(long long node, int c) const { return static_cast<GlobalOrdinal>(dim_ * node + c); }
  bool prescribed(long long node, int c) const;
  /// Saddle-point form: the unknown z_c of slave node `slave` (slaveNodes() index).
  GlobalOrdinal multiplierDof(int slave, int c) const {
    return multiplierOffset_ + static_cast<GlobalOrdinal>(dim_ * slave + c);
  }
  /// to += scale × the derivative row `d` in row `target` (prescribed columns left out).
  void add(std::vector<linalg::MatrixTriplet>& to, GlobalOrdinal target, const DerivativeRow& d,
           double scale = 1.0) const;

private:
  const ContactInterface& contact_;
  const std::vector<std::array<bool, 3>>& prescribed_;
  int dim_;
  GlobalOrdinal multiplierOffset_;
};

/// to += scale × from.
inline void addScaled(DerivativeRow& to, const DerivativeRow& from, double scale) {
  if (scale == 0.0) return;
  for (const auto& [key, value] : from) to[key] += scale * value;
}

/// to += sum_m coefficient[m] d n_m / dx  (the chain through the nodal normal).
template <std::size_t N>
void addNormalDerivative(DerivativeRow& to, const NodalNormal& normal, const std::array<double, N>& coefficient) {
  for (const auto& d : normal.derivative)
    for (std::size_t m = 0; m < N; ++m)
      if (coefficient[m] != 0.0) to[{d.node, d.component}] += coefficient[m] * d.dn[m];
}

}  // namespace coulomb::contact
