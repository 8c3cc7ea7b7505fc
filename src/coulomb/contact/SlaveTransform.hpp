#pragma once
/// @file SlaveTransform.hpp
/// @brief The transformed slave displacements of Quad8 and Tri6 faces
/// (issue 18, item 2) and what they do to a pair's rows.
///
/// The multipliers of a Quad8 / Tri6 slave face are dual to the transformed
/// basis N~ (DualBasis.hpp, faceTrialValues), which interpolates transformed
/// nodal values d~ with d = T d~: d_c = d~_c at a corner, d_e = (1 - 2 alpha)
/// d~_e + alpha (d~_a + d~_b) at the mid-side node e of the edge a-b (alpha
/// = kTransformedBasisAlpha). T belongs to the edge, so it is one global
/// matrix, the same from either face of an edge. In the variables d~, D is
/// diagonal and positive; the system stays in d, and the pair's rows are
/// those of T^T applied to it:
///  - the slave rows of the condensed forms (ALM, MPC) are the rows of
///    T^T (r - f_c): the transformed residual r~_j = sum_k T_kj r_k gives the
///    node's multiplier (as r_j does for a linear face), the row is replaced
///    by the node's conditions when active and is r~_j when not (T - I gains
///    T^T - I there), and a derivative with respect to r~_j combines the K
///    rows k with T_kj (rowTerms);
///  - a force on the transformed slave node j (penalty, the saddle-point
///    form, the supports) acts on the physical nodes as T^-T: on j alone at
///    a corner, 1 / (1 - 2 alpha) on an edge node e and -alpha / (1 - 2
///    alpha) on its corners (forceTerms).
/// A node of a transformed edge prescribed in a component where the edge's
/// mid-side node is free is fine (its row is u - u_bar); a prescribed
/// mid-side node with a free corner has no transformed equivalent and is
/// refused.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "coulomb/contact/ContactContributions.hpp"
#include "coulomb/contact/interface/ContactInterface.hpp"

namespace coulomb::contact {

class SlaveTransform {
public:
  /// `prescribed[i][c]` by interface node index. Throws coulomb::Error
  /// naming `what` and the nodes for a prescribed mid-side node with a free
  /// corner, and for a surface that mixes Quad8 / Tri6 with Quad9 faces.
  SlaveTransform(const ContactInterface& contact, const std::vector<std::array<bool, 3>>& prescribed,
                 const std::string& what);

  /// Whether the pair has transformed faces at all.
  bool active() const { return active_; }

  /// Transforms the edges of the slave faces with inUse[f] (indices of
  /// ContactInterface::slaveFaces()) alone; the constructor takes them all.
  /// A self-contact surface (issue 18, item 5) lists every face as slave
  /// and master, and its faces' roles change with each search
  /// (SelfContactRoles.hpp): only the faces of the slave role carry the
  /// transformed multipliers; a node of a master face gets master forces in
  /// the physical basis, as on an ordinary master surface. The roles never
  /// put a node on a slave and a master face, so no edge is transformed
  /// from one side and not from the other. T may change between Newton
  /// iterations: the equations T^T r = 0 are the same for every invertible T.
  void useSlaveFaces(const std::vector<char>& inUse);

  struct Term {
    int slave = -1;  ///< slave node index (ContactInterface::slaveNodes())
    double coefficient = 0.0;
  };
  /// Transformed row j = sum over rowTerms(j) of coefficient × row `slave` (T_kj).
  const std::vector<Term>& rowTerms(int slave) const { return rowTerms_[slave]; }
  /// A force on transformed node j acts on the physical nodes as these terms (T^-T).
  const std::vector<Term>& forceTerms(int slave) const { return forceTerms_[slave]; }

  /// How long each list of a ContactContributions is: where a pair's own
  /// entries begin.
  struct Marks {
    std::size_t transform = 0, tangentTransform = 0, contactResidual = 0, contactStiffness = 0,
                prescribedForce = 0, multiplierColumns = 0;
    explicit Marks(const ContactContributions& c)
        : transform(c.transform.size()), tangentTransform(c.tangentTransform.size()),
          contactResidual(c.contactResidual.size()), contactStiffness(c.contactStiffness.size()),
          prescribedForce(c.prescribedForce.size()), multiplierColumns(c.multipliers.columns.size()) {}
  };

  /// Converts what a pair appended to `out` since `from` (Marks of out
  /// before the pair's update) from transformed slave rows to the system's:
  ///  - tangentTransform columns at transformed slave nodes combine the K
  ///    rows of rowTerms;
  ///  - `condensed` (ALM, MPC): the free rows of the owned slave nodes
  ///    `owned` that the pair did not replace become r~ (T - I gains
  ///    rowTerms - identity), and the force of each owned mid-side node on
  ///    its prescribed corners, -alpha r_e (the support carries it), is
  ///    listed in prescribedForce; `residual(node, c)` is the bulk residual;
  ///  - contactResidual, contactStiffness, prescribedForce and the
  ///    multiplier columns at slave rows act as forceTerms; what lands on a
  ///    prescribed row goes to prescribedForce (residual) or is dropped
  ///    (stiffness: those rows are u - u_bar).
  void toSystemRows(ContactContributions& out, const Marks& from, bool condensed, const std::vector<int>& owned,
                    const std::function<double(long long, int)>& residual) const;

private:
  bool prescribedSlave(int slave, int c) const;

  const ContactInterface& contact_;
  const std::vector<std::array<bool, 3>>& prescribed_;
  int dim_;
  bool active_ = false;
  std::vector<std::vector<Term>> rowTerms_, forceTerms_;
  std::vector<char> transformed_;  ///< per slave node: rowTerms or forceTerms is not the identity
  /// Per slave mid-side node e: its two corners (slave indices), else -1.
  std::vector<std::array<int, 2>> edgeCorners_;
};

}  // namespace coulomb::contact
