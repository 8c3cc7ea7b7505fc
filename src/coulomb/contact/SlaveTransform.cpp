/// @file SlaveTransform.cpp
/// @brief Transformed slave rows of Quad8 / Tri6 faces (see the header).
#include "coulomb/contact/SlaveTransform.hpp"

#include <set>
#include <unordered_set>

#include "coulomb/contact/mortar/DualBasis.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

SlaveTransform::SlaveTransform(const ContactInterface& contact, const std::vector<std::array<bool, 3>>& prescribed,
                               const std::string& what)
    : contact_(contact), prescribed_(prescribed), dim_(contact.dimension()) {
  bool quad9 = false;
  for (const ContactFace& f : contact.slaveFaces()) quad9 = quad9 || f.type == mesh::FaceType::Quad9;
  // The checks cover every face of the surface, so that useSlaveFaces (any
  // subset of them, a self-contact surface's slave roles) cannot fail later.
  for (const ContactFace& f : contact.slaveFaces()) {
    const int (*edges)[3] = nullptr;
    const int count = transformedEdges(f.type, &edges);
    if (count == 0) continue;
    COULOMB_REQUIRE(!quad9, what << ": the slave surface has QUAD9 faces and " << mesh::toString(f.type)
                                 << " faces (element " << f.element + 1
                                 << "); contact on quadratic faces takes one kind per surface");
    active_ = true;
    for (int k = 0; k < count; ++k) {
      const int e = contact.slaveNodeIndex(f.nodes[edges[k][0]]);
      for (int c = 0; c < dim_; ++c)
        for (int corner : {edges[k][1], edges[k][2]}) {
          const int j = contact.slaveNodeIndex(f.nodes[corner]);
          COULOMB_REQUIRE(!prescribedSlave(e, c) || prescribedSlave(j, c),
                          what << ": node " << contact.slaveNodes()[e] + 1 << " (the mid-side node of an edge of "
                               << mesh::toString(f.type) << " slave faces) is prescribed in component " << "xyz"[c]
                               << " but the edge's corner node " << contact.slaveNodes()[j] + 1
                               << " is not; the transformed basis of these faces needs both (prescribe the whole "
                                  "edge, e.g. a node set of a surface)");
        }
    }
  }
  useSlaveFaces(std::vector<char>(contact.slaveFaces().size(), 1));
}

void SlaveTransform::useSlaveFaces(const std::vector<char>& inUse) {
  const std::size_t n = contact_.slaveNodes().size();
  rowTerms_.assign(n, {});
  forceTerms_.assign(n, {});
  transformed_.assign(n, 0);
  edgeCorners_.assign(n, {-1, -1});
  for (std::size_t j = 0; j < n; ++j) rowTerms_[j] = forceTerms_[j] = {Term{static_cast<int>(j), 1.0}};
  const double a = kTransformedBasisAlpha;
  std::set<int> done;
  const auto& faces = contact_.slaveFaces();
  for (std::size_t face = 0; face < faces.size(); ++face) {
    if (!inUse[face]) continue;
    const ContactFace& f = faces[face];
    const int (*edges)[3] = nullptr;
    const int count = transformedEdges(f.type, &edges);
    for (int k = 0; k < count; ++k) {
      const int e = contact_.slaveNodeIndex(f.nodes[edges[k][0]]);
      if (!done.insert(e).second) continue;
      const int c0 = contact_.slaveNodeIndex(f.nodes[edges[k][1]]);
      const int c1 = contact_.slaveNodeIndex(f.nodes[edges[k][2]]);
      edgeCorners_[e] = {c0, c1};
      rowTerms_[e] = {Term{e, 1.0 - 2.0 * a}};
      rowTerms_[c0].push_back(Term{e, a});
      rowTerms_[c1].push_back(Term{e, a});
      forceTerms_[e] = {Term{e, 1.0 / (1.0 - 2.0 * a)}, Term{c0, -a / (1.0 - 2.0 * a)}, Term{c1, -a / (1.0 - 2.0 * a)}};
      transformed_[e] = transformed_[c0] = transformed_[c1] = 1;
    }
  }
}

bool SlaveTransform::prescribedSlave(int slave, int c) const {
  return prescribed_[contact_.interfaceNodeIndex(contact_.slaveNodes()[slave])][c];
}

void SlaveTransform::toSystemRows(ContactContributions& out, const Marks& from, bool condensed,
                                  const std::vector<int>& owned,
                                  const std::function<double(long long, int)>& residual) const {
  if (!active_) return;
  const auto& nodes = contact_.slaveNodes();
  // The transformed slave node of a DoF, or -1.
  auto slaveOf = [&](GlobalOrdinal dof) {
    const int j = contact_.slaveNodeIndex(static_cast<long long>(dof / dim_));
    return j >= 0 && transformed_[j] ? j : -1;
  };
  auto dof = [&](int slave, int c) { return static_cast<GlobalOrdinal>(dim_) * nodes[slave] + c; };

  // K rows combined by a derivative with respect to r~_j: rowTerms.
  {
    auto& list = out.tangentTransform;
    std::vector<linalg::MatrixTriplet> kept(list.begin(), list.begin() + from.tangentTransform);
    for (std::size_t i = from.tangentTransform; i < list.size(); ++i) {
      const auto& t = list[i];
      const int j = slaveOf(t.column);
      if (j < 0) {
        kept.push_back(t);
        continue;
      }
      const int c = static_cast<int>(t.column % dim_);
      for (const Term& term : rowTerms_[j])
        if (!prescribedSlave(term.slave, c)) kept.push_back({t.row, dof(term.slave, c), t.value * term.coefficient});
    }
    list.swap(kept);
  }

  // Forces on transformed nodes act on the physical ones: forceTerms.
  auto forces = [&](auto& list, std::size_t start, auto&& onPrescribed) {
    using Entry = typename std::decay_t<decltype(list)>::value_type;
    std::vector<Entry> kept(list.begin(), list.begin() + start);
    for (std::size_t i = start; i < list.size(); ++i) {
      const Entry& entry = list[i];
      const int j = slaveOf(entry.row);
      if (j < 0) {
        kept.push_back(entry);
        continue;
      }
      const int c = static_cast<int>(entry.row % dim_);
      for (const Term& term : forceTerms_[j]) {
        Entry moved = entry;
        moved.row = dof(term.slave, c);
        moved.value *= term.coefficient;
        if (prescribedSlave(term.slave, c) && !prescribedSlave(j, c))
          onPrescribed(moved);
        else
          kept.push_back(moved);
      }
    }
    list.swap(kept);
  };
  std::vector<linalg::VectorEntry> toSupport;
  forces(out.contactResidual, from.contactResidual, [&](linalg::VectorEntry e) {
    e.value = -e.value;  // -f_c in the residual, +f_c on the support
    toSupport.push_back(e);
  });
  forces(out.contactStiffness, from.contactStiffness, [](const linalg::MatrixTriplet&) {});
  forces(out.multipliers.columns, from.multiplierColumns, [](const linalg::MatrixTriplet&) {});
  forces(out.prescribedForce, from.prescribedForce, [&](const linalg::VectorEntry& e) { toSupport.push_back(e); });
  out.prescribedForce.insert(out.prescribedForce.end(), toSupport.begin(), toSupport.end());

  if (!condensed) return;
  // Rows the pair did not replace become r~ (T - I += rowTerms - identity).
  std::unordered_set<GlobalOrdinal> replaced;
  for (std::size_t i = from.transform; i < out.transform.size(); ++i)
    if (out.transform[i].row == out.transform[i].column) replaced.insert(out.transform[i].row);
  for (int j : owned) {
    if (!transformed_[j]) continue;
    for (int c = 0; c < dim_; ++c) {
      const GlobalOrdinal row = dof(j, c);
      if (prescribedSlave(j, c)) continue;
      // The force of a free mid-side node on a prescribed corner: -alpha r_e.
      for (int corner : edgeCorners_[j])
        if (corner >= 0 && prescribedSlave(corner, c))
          out.prescribedForce.push_back({dof(corner, c), -kTransformedBasisAlpha * residual(nodes[j], c)});
      if (replaced.count(row)) continue;
      for (const Term& term : rowTerms_[j]) {
        const double value = term.coefficient - (term.slave == j ? 1.0 : 0.0);
        if (value != 0.0) out.transform.push_back({row, dof(term.slave, c), value});
      }
    }
  }
}

}  // namespace coulomb::contact
