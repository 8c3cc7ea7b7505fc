// The mortar pass on partitioned meshes (np = 1, 2, 3): nodal D_j, M_jl and
// weighted gaps of two stacked non-matching bodies against closed forms, the
// cross-rank summation against an all-faces computation on every rank, and the
// derivatives against central differences of the whole pass (normals + pass).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <set>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "TestSupport.hpp"
#include "TwoBodies.hpp"
#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"
#include "coulomb/contact/interface/MortarPass.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {
namespace {

using contact::ContactInterface;
using contact::InterfaceConfiguration;
using contact::NodalMortarEntry;
using contact::NodalMortarQuantities;
using contact::SearchResult;


// ------------------------------------------------------------------ helpers

/// Normals (of the nodes of the searched faces), pass, and optionally the sum to the owners.
NodalMortarQuantities pass(const ContactInterface& c, const InterfaceConfiguration& x, const SearchResult& pairs,
                           bool withDerivatives, bool sum = true) {
  std::vector<int> nodes;
  {
    std::set<int> s;
    for (int f : pairs.slaveFaces)
      for (int a = 0; a < c.slaveFaces()[f].numNodes; ++a) s.insert(c.slaveNodeIndex(c.slaveFaces()[f].nodes[a]));
    nodes.assign(s.begin(), s.end());
  }
  const auto normals = contact::computeNodalNormals(c, x, withDerivatives, &nodes);
  const NodalMortarQuantities local = contact::integrateMortarPass(c, x, normals, pairs, withDerivatives);
  return sum ? contact::sumToOwners(c, local) : local;
}

/// int N_j over the slave faces of a structured flat slave side with 3 cells per
/// edge on [0,1]^(d-1): product of the 1D weights 1/6 (end) and 1/3 (interior).
double exactD(int dim, const double* X) {
  double w = 1.0;
  for (int c = 0; c + 1 < dim; ++c) {
    const bool end = std::abs(X[c]) < 1e-12 || std::abs(X[c] - 1.0) < 1e-12;
    w *= end ? 1.0 / 6.0 : 1.0 / 3.0;
  }
  return w;
}

std::vector<int> allSlaveFaces(const ContactInterface& c) {
  std::vector<int> all(c.slaveFaces().size());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

/// Slave nodes whose slave faces are owned by more than one rank.
std::vector<long long> splitSlaveNodes(const ContactInterface& c) {
  std::vector<long long> out;
  const auto& off = c.slaveNodeFaceOffsets();
  for (std::size_t i = 0; i < c.slaveNodes().size(); ++i) {
    std::set<int> owners;
    for (int k = off[i]; k < off[i + 1]; ++k) owners.insert(c.slaveFaces()[c.slaveNodeFaces()[k]].owner);
    if (owners.size() > 1) out.push_back(c.slaveNodes()[i]);
  }
  return out;
}

/// The interface node nearest to `p` among the slave (or the master-only) nodes, reference coordinates.
long long nearestNode(const ContactInterface& c, bool slave, const std::array<double, 3>& p) {
  long long best = -1;
  double bestDistance = 1e300;
  const int dim = c.dimension();
  for (std::size_t i = 0; i < c.interfaceNodes().size(); ++i) {
    const long long node = c.interfaceNodes()[i];
    if ((c.slaveNodeIndex(node) >= 0) != slave) continue;
    double d = 0.0;
    for (int k = 0; k + 1 < dim; ++k) d += std::pow(c.referenceCoordinates()[i * dim + k] - p[k], 2);
    if (d < bestDistance) bestDistance = d, best = node;
  }
  return best;
}

class MortarPassTwoBodies : public ::testing::TestWithParam<int> {};

// (a) flat, non-matching, gap g: exact D_j, g~_j = g D_j, sum_l M_jl = D_j; the
// summed entries equal the all-faces computation on one rank.
TEST_P(MortarPassTwoBodies, FlatNonMatchingBodies) {
  const int dim = GetParam();
  const double g = 0.01;
  const auto mesh = twoBodies(dim, g, "contact_mortar_pass");
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  const InterfaceConfiguration x = contact::referenceConfiguration(c);
  const SearchResult pairs = contact::searchContactPairs(c, x, 0.05);
  const NodalMortarQuantities q = pass(c, x, pairs, true);

  // one entry per owned slave node (every slave node is covered)
  std::vector<long long> owned;
  for (int i : c.ownedSlaveNodes()) owned.push_back(c.slaveNodes()[i]);
  std::vector<long long> got;
  for (const auto& e : q.entries) got.push_back(e.node);
  EXPECT_EQ(got, owned);

  double sumD = 0.0, sumGap = 0.0;
  for (const NodalMortarEntry& e : q.entries) {
    const double* X = x.point(c.interfaceNodeIndex(e.node));
    EXPECT_NEAR(e.D, exactD(dim, X), 1e-14) << "node " << e.node;
    EXPECT_NEAR(e.gap, g * e.D, 1e-15) << "node " << e.node;
    double sumM = 0.0;
    for (const auto& [l, value] : e.M) {
      sumM += value;
      EXPECT_LT(c.slaveNodeIndex(l), 0);  // master nodes only
    }
    EXPECT_NEAR(sumM, e.D, 1e-14) << "node " << e.node;
    sumD += e.D;
    sumGap += e.gap;
  }
  EXPECT_NEAR(globalSum(sumD), 1.0, 1e-13);  // contact area (3D) / length (2D)
  EXPECT_NEAR(globalSum(sumGap), g, 1e-14);
  const double totalD = globalSum(sumD), totalGap = globalSum(sumGap);
  if (worldComm()->getRank() == 0)
    std::printf("[ MortarPass ] %dD flat: sum D = %.17g, sum gap = %.17g\n", dim, totalD, totalGap);

  // The collective sum against every rank integrating all slave faces itself.
  const SearchResult allPairs = contact::searchContactPairs(c, x, 0.05, allSlaveFaces(c));
  const NodalMortarQuantities reference = pass(c, x, allPairs, true, false);
  double worst = 0.0;
  for (const NodalMortarEntry& e : q.entries) {
    const NodalMortarEntry* r = reference.find(e.node);
    ASSERT_NE(r, nullptr);
    worst = std::max({worst, std::abs(e.D - r->D), std::abs(e.gap - r->gap)});
    EXPECT_EQ(e.M.size(), r->M.size());
    for (const auto& [l, value] : e.M) worst = std::max(worst, std::abs(value - r->M.at(l)));
    for (const auto* rows : {&e.dD, &e.dGap}) {
      const auto& other = rows == &e.dD ? r->dD : r->dGap;
      EXPECT_EQ(rows->size(), other.size()) << "node " << e.node;
      for (const auto& [key, value] : *rows) worst = std::max(worst, std::abs(value - other.at(key)));
    }
  }
  EXPECT_LT(globalMax(worst), 1e-13);
}

// (b) tilted master plane h = s x (+ t y): g~_j = int Phi_j (g - h) dA = (g - h(X_j)) D_j
// (biorthogonality, h linear on each slave face).
TEST_P(MortarPassTwoBodies, TiltedMasterWeightedGap) {
  const int dim = GetParam();
  const double g = 0.1, s = 0.05, t = -0.03;
  const auto mesh = twoBodies(dim, g, "contact_mortar_pass");
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  // The tilt as a displacement of the lower body, gathered like in the solver.
  const fem::DofMap dofs(*mesh);
  const contact::InterfaceGather gather(c, dofs.ownedMap());
  Vector u(dofs.ownedMap());
  for (int i = 0; i < mesh->numOwnedNodes(); ++i) {
    const long long node = mesh->localNodes()[i];
    const double* X = &mesh->global().coordinates[node * dim];
    if (X[dim - 1] > 0.005) continue;  // upper body
    const double w = s * X[0] + (dim == 3 ? t * X[1] : 0.0);
    u.replaceGlobalValue(fem::DofMap::globalDof(node, dim - 1, dim), w);
  }
  const InterfaceConfiguration x = gather.gather(u);
  const SearchResult pairs = contact::searchContactPairs(c, x, 0.2);
  const NodalMortarQuantities q = pass(c, x, pairs, false);
  EXPECT_EQ(q.entries.size(), c.ownedSlaveNodes().size());
  double sumD = 0.0;
  for (const NodalMortarEntry& e : q.entries) {
    const double* X = x.point(c.interfaceNodeIndex(e.node));
    const double h = s * X[0] + (dim == 3 ? t * X[1] : 0.0);
    EXPECT_NEAR(e.D, exactD(dim, X), 1e-14);
    EXPECT_NEAR(e.gap, (g - h) * exactD(dim, X), 1e-14) << "node " << e.node;
    sumD += e.D;
  }
  EXPECT_NEAR(globalSum(sumD), 1.0, 1e-13);
}

// (c) derivatives of D_j, g~_j and M_jl against central differences of the whole
// pass (normals recomputed), curved slave, tilted shifted master.
TEST_P(MortarPassTwoBodies, DerivativesMatchCentralDifferences) {
  const int dim = GetParam();
  const int v = dim - 1;
  const auto mesh = twoBodies(dim, 0.02, "contact_mortar_pass");
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  InterfaceConfiguration x = contact::referenceConfiguration(c);
  for (std::size_t i = 0; i < c.interfaceNodes().size(); ++i) {
    double* p = &x.x[i * dim];
    const double X0 = p[0], X1 = dim == 3 ? p[1] : 0.0;
    if (c.slaveNodeIndex(c.interfaceNodes()[i]) >= 0) {
      p[v] += 0.01 * std::cos(4.0 * X0 + 3.0 * X1);
      p[0] += 0.008 * std::sin(3.0 * X1 + 5.0 * X0 + 1.0);
      if (dim == 3) p[1] += 0.006 * std::cos(2.0 * X0 - X1);
    } else {
      p[0] += 0.03;
      if (dim == 3) p[1] -= 0.02;
      p[v] += 0.03 * X0 - 0.02 * X1 + 0.005 * std::sin(5.0 * X0);
    }
  }
  const SearchResult pairs = contact::searchContactPairs(c, x, 0.1);
  const NodalMortarQuantities q = pass(c, x, pairs, true);
  ASSERT_GT(globalSum(static_cast<double>(q.entries.size())), 0.0);

  std::vector<long long> nodes = {nearestNode(c, true, {1.0 / 3, 1.0 / 3, 0}), nearestNode(c, true, {0, 0, 0}),
                                  nearestNode(c, true, {1, 2.0 / 3, 0}), nearestNode(c, false, {0.5, 0.5, 0})};
  const std::vector<long long> split = splitSlaveNodes(c);
  if (!split.empty()) nodes.push_back(split[split.size() / 2]);
  if (worldComm()->getSize() > 1) EXPECT_FALSE(split.empty()) << "no slave node with faces on two ranks";

  const double h = 1e-6;
  double worst = 0.0;
  long long checked = 0;
  for (long long node : nodes) {
    const int i = c.interfaceNodeIndex(node);
    for (int comp = 0; comp < dim; ++comp) {
      InterfaceConfiguration xp = x, xm = x;
      xp.x[i * dim + comp] += h;
      xm.x[i * dim + comp] -= h;
      const NodalMortarQuantities qp = pass(c, xp, pairs, false), qm = pass(c, xm, pairs, false);
      const contact::DofKey key{node, comp};
      auto analytic = [&key](const contact::DerivativeRow& row) {
        const auto it = row.find(key);
        return it == row.end() ? 0.0 : it->second;
      };
      auto compare = [&](double fd, double an, const std::string& what) {
        const double error = std::abs(fd - an) / std::max(std::abs(an), 1e-2);
        worst = std::max(worst, error);
        ++checked;
        EXPECT_LT(error, 1e-6) << what << " d/dx(" << node << "," << comp << "): fd " << fd << " analytic " << an;
      };
      for (const NodalMortarEntry& e : q.entries) {
        const NodalMortarEntry* p = qp.find(e.node);
        const NodalMortarEntry* m = qm.find(e.node);
        ASSERT_TRUE(p && m);
        const std::string at = "node " + std::to_string(e.node) + ": ";
        compare((p->D - m->D) / (2 * h), analytic(e.dD), at + "D");
        compare((p->gap - m->gap) / (2 * h), analytic(e.dGap), at + "gap");
        for (const auto& [l, row] : e.dM) {
          const double fd = (p->M.at(l) - m->M.at(l)) / (2 * h);
          compare(fd, analytic(row), at + "M[" + std::to_string(l) + "]");
        }
      }
    }
  }
  EXPECT_GT(globalSum(static_cast<double>(checked)), 0.0);
  const double globalWorst = globalMax(worst);
  EXPECT_LT(globalWorst, 1e-6);
  if (worldComm()->getRank() == 0)
    std::printf("[ MortarPass ] %dD: worst relative FD error %.2e over %d nodes\n", dim, globalWorst,
                static_cast<int>(nodes.size()));
}

INSTANTIATE_TEST_SUITE_P(MortarPass, MortarPassTwoBodies, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

}  // namespace
}  // namespace coulomb::test
