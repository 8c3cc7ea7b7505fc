// Frictional contact at slave nodes with a prescribed tangential DoF, and the
// stick/slip 2-cycle of a stiff indenter (FrictionalNode.cpp: driven
// directions, slipReversed). Every run happens at np = 1, 2, 3 (ctest
// MpiTests.np*); the decks are the shipped ones, edited.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "ContactTestSupport.hpp"
#include "FrictionDeckSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/fem/Assembler.hpp"

namespace coulomb::test {
namespace {

/// The support forces of a finished run on the union of `sets` (their nodes
/// of element block `block` only, unless empty): the bulk
/// reaction f_int - f_ext of the last state (assembled again here) with the
/// contact forces on prescribed DoFs taken out
/// (ContactModel::subtractPrescribedForces), or left in (`subtract` false).
std::vector<double> supportForce(ContactRun& run, const std::vector<std::string>& sets, bool subtract,
                                 const std::string& block = "") {
  auto& simulation = *run.simulation;
  const auto& mesh = simulation.mesh();
  const int dim = mesh.dimension();
  Vector reactions(simulation.dofMap().ownedMap());
  simulation.assembler().assemble(simulation.settings().finalTime, simulation.displacement(), nullptr, nullptr,
                                  &reactions);
  if (subtract) simulation.contact()->subtractPrescribedForces(reactions);
  std::set<long long> nodes, ofBlock;
  for (const auto& b : mesh.global().blocks)
    if (b.name == block) ofBlock.insert(b.connectivity.begin(), b.connectivity.end());
  for (const auto& name : sets)
    for (long long n : mesh.global().nodeSets[mesh.nodeSetIndex(name, "test")].nodes)
      if (block.empty() || ofBlock.count(n)) nodes.insert(n);
  const auto r = reactions.getData(0);
  std::vector<double> local(dim, 0.0), total(dim, 0.0);
  for (long long node : nodes) {
    const int i = mesh.localNode(node);
    if (i < 0 || i >= mesh.numOwnedNodes()) continue;
    for (int c = 0; c < dim; ++c) local[c] += r[i * dim + c];
  }
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_SUM, dim, local.data(), total.data());
  return total;
}

/// The deck's "top y" condition preceded by u_x on node set punch_left as
/// on the top: the slip s = 0.002 plus the homogeneous field's `coefficients`.
std::string punchLeftX(const std::string& coefficients) {
  return "<ParameterList name=\"punch left x\"><Parameter name=\"Node Set\" type=\"string\" value=\"punch_left\"/>"
         "<Parameter name=\"Component\" type=\"string\" value=\"x\"/><Parameter name=\"Value\" type=\"double\" "
         "value=\"0.002\"/><Parameter name=\"Linear Coefficients\" type=\"Array(double)\" value=\"" +
         coefficients + "\"/></ParameterList><ParameterList name=\"top y\">";
}

/// xml/friction_patch_2d.xml with the punch's left edge x = 0 prescribed in
/// x like its top (u_x = s + eps_xx x + gamma y): its slave node (0, 0.5) has
/// a prescribed tangential DoF that moves it over the base, whose left edge
/// stays free (the component is driven, FrictionalNodeInput::driven).
std::string prescribedEdgeDeck2d() {
  ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
  deck.replace("<ParameterList name=\"top y\">", punchLeftX("{0.004285714285714286, 0.008571428571428572}"));
  return deck.text;
}

/// The checks of a gross-slip patch whose slave edge node is prescribed in
/// x: every active slave node (the edge nodes too) slips with mu p against
/// the slip, so the tangential contact force is mu times the normal one (up
/// to the tilt of the normals at the deformed punch ends, 1e-3: see
/// FrictionPatch.ImposedSlipCarriesMuTimesPressure; the edge nodes carry
/// about h/2 of the width, 1/14 of it in 2D), and the punch's supports (top
/// and left edge) carry exactly the contact force once the friction of the
/// prescribed DoFs is counted as theirs.
void expectEdgeFrictionCarried(ContactRun& run, int dim, int slaveNodes, double tolerance, bool penalty) {
  const auto with = supportForce(run, {"top", "punch_left"}, true);
  const auto without = supportForce(run, {"top", "punch_left"}, false);
  if (worldComm()->getRank() != 0) return;
  const auto& r = run.results;
  const double P = kE * 0.01 / (dim == 2 ? (1 - kNu * kNu) : 1.0);
  const auto nodes = checkTractions(r, [](double p) { return -kMu * p; }, tolerance * P, dim);
  EXPECT_EQ(nodes.slip, slaveNodes);
  EXPECT_EQ(nodes.stick, 0);
  const double Q = lastGlobal(r, "contact_force_punch_x");
  const double N = lastGlobal(r, dim == 2 ? "contact_force_punch_y" : "contact_force_punch_z");
  // (Not for the penalty: its normals tilt more at the punch ends, where it
  // penetrates: Q/N = 0.3012 on the unedited 3D penalty patch already.)
  if (!penalty) EXPECT_NEAR(Q / N, -kMu, 1e-3 * kMu);
  // Momentum balance of the punch along x (its side tractions act along the normal only).
  EXPECT_NEAR(with[0], -Q, 1e-8 * P);
  std::printf("%dD prescribed edge: Q/N %.6f, supports %.6f, -Q %.6f (bulk reaction alone %.6f)\n", dim, Q / N,
              with[0], -Q, without[0]);
  // The bulk reaction alone misses the edge node's friction, mu p D_j.
  EXPECT_GT(std::abs(without[0] + Q), 1e-3 * std::abs(Q));
  // The base's support carries the whole tangential force (the master rows got the edge node's too).
  EXPECT_NEAR(lastGlobal(r, "reaction_bottom_x"), Q, 1e-8 * P);
}

/// xml/friction_patch_3d.xml with the punch's face x = 0 prescribed in x like
/// its top (a node set made here), formulation `formulation`; the base's face
/// x = 0 stays free. The 5 slave nodes on that edge have one driven
/// direction (x) and one tangent slot (y).
ContactRun runPrescribedEdge3d(const std::string& name, const std::string& formulation) {
  const std::string dir = scratchDirectory(name + "_mesh");
  const std::string meshCopy = dir + "/patch3d_punch_left.e";
  const int onInterface = writePatch3dWithPunchLeft(meshCopy);
  if (worldComm()->getRank() == 0) EXPECT_EQ(onInterface, 5);  // the punch's slave nodes on x = 0 (4 x 4 faces in plan)
  ShippedDeck deck("friction_patch_3d", "contact_patch3d.e");
  deck.replace(shippedMesh("contact_patch3d.e"), meshCopy);
  deck.replace("<ParameterList name=\"top y\">", punchLeftX("{0.003, 0.0, 0.0078000000000000005}"));
  if (formulation != "ALM")
    deck.replace(kCoulombLaw, "<Parameter name=\"Formulation\" type=\"string\" value=\"" + formulation + "\"/>" +
                                  kCoulombLaw);
  return runDeckText(name, deck.text);
}

}  // namespace

// 2D, ALM: the slave node on the prescribed edge carries mu p like the others.
TEST(FrictionPrescribedDof, SlaveEdgeNodeCarriesItsFriction2D) {
  const std::string name = "friction_prescribed_edge_2d";
  auto run = runDeckText(name, prescribedEdgeDeck2d());
  EXPECT_EQ(run.summary.cutbacks, 0);
  expectEdgeFrictionCarried(run, 2, 8, 1e-8, false);
}

// 2D, penalty: its force already reached the master rows; the support now
// carries it too, and the edge node's traction is mu p.
TEST(FrictionPrescribedDof, SlaveEdgeNodeCarriesItsFrictionPenalty2D) {
  const std::string name = "friction_prescribed_edge_penalty_2d";
  std::string text = prescribedEdgeDeck2d();
  text.replace(text.find(kCoulombLaw), kCoulombLaw.size(),
               "<Parameter name=\"Formulation\" type=\"string\" value=\"Penalty\"/>" + kCoulombLaw);
  auto run = runDeckText(name, text);
  EXPECT_EQ(run.summary.cutbacks, 0);
  expectEdgeFrictionCarried(run, 2, 8, 1e-6, true);
}

// 3D, ALM: the slave nodes on the prescribed face carry mu p along x.
TEST(FrictionPrescribedDof, SlaveEdgeNodesCarryTheirFriction3D) {
  auto run = runPrescribedEdge3d("friction_prescribed_edge_3d", "ALM");
  EXPECT_EQ(run.summary.cutbacks, 0);
  expectEdgeFrictionCarried(run, 3, 25, 1e-8, false);
}

// 3D, penalty.
TEST(FrictionPrescribedDof, SlaveEdgeNodesCarryTheirFrictionPenalty3D) {
  auto run = runPrescribedEdge3d("friction_prescribed_edge_penalty_3d", "Penalty");
  EXPECT_EQ(run.summary.cutbacks, 0);
  expectEdgeFrictionCarried(run, 3, 25, 1e-6, true);
}

// Frictionless (ALM): the quarter Hertz model's slave nodes on the symmetry
// planes carry normal forces with a small component across the plane (their
// nodal normals average the faces on one side), on the prescribed DoF: the
// plane's support takes it. The indenter's supports (top, its part of the
// planes) then balance the contact force exactly in x and y.
TEST(ContactPrescribedDof, SymmetryPlaneForcesGoToTheSupport) {
  const std::string name = "contact_prescribed_hertz3d_quarter";
  ShippedDeck deck("hertz3d_quarter", "hertz3d_quarter.e");
  auto run = runDeckText(name, deck.text);
  const std::vector<std::string> supports = {"top", "symmetry_x", "symmetry_y"};
  const auto with = supportForce(run, supports, true, "indenter");
  const auto without = supportForce(run, supports, false, "indenter");
  if (worldComm()->getRank() != 0) return;
  const auto& r = run.results;
  const double P = lastGlobal(r, "contact_force_sphere_z");
  EXPECT_GT(P, 0.0);
  for (int c = 0; c < 2; ++c) {
    const double F = lastGlobal(r, std::string("contact_force_sphere_") + "xy"[c]);
    EXPECT_NEAR(with[c], -F, 1e-7 * P) << "xy"[c];
    EXPECT_GT(std::abs(without[c] + F), 1e-5 * P) << "xy"[c];  // the bulk reaction alone misses the plane nodes' share
    std::printf("quarter Hertz %c: contact force %.6f, supports %.6f (bulk reaction alone %.6f)\n", "xy"[c], F, with[c],
                without[c]);
  }
  EXPECT_NEAR(with[2], -P, 1e-7 * P);
}

// A cylinder 10 x stiffer than the block, pressed in one step (xml/hertz2d.xml
// edited, mu = 0.3): partial slip (Spence: stick in the middle, inward slip
// at the edges). Slipping nodes near the middle used to slide against the
// direction of their rows and flip it at every iterate, the sets unchanged,
// until the step failed (the 2-cycle of tests/zoo/sharp_punch_2d and the
// pressing of sliding_cylinder_2d); full Newton steps as in the defaults.
TEST(FrictionStiffIndenter, PressingConvergesWithoutCutbacks) {
  ShippedDeck deck("hertz2d", "hertz2d.e");
  deck.replace("<ParameterList name=\"foundation\"><Parameter name=\"Material\" type=\"string\" value=\"steel\"/>",
               "<ParameterList name=\"foundation\"><Parameter name=\"Material\" type=\"string\" value=\"soft\"/>");
  deck.replace("<ParameterList name=\"Materials\">",
               "<ParameterList name=\"Materials\"><ParameterList name=\"soft\"><Parameter name=\"Young's Modulus\" "
               "type=\"double\" value=\"21000\"/><Parameter name=\"Poisson's Ratio\" type=\"double\" "
               "value=\"0.3\"/></ParameterList>");
  deck.replace("value=\"-0.14\"", "value=\"-0.03\"");
  deck.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>",
               "<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>" + kCoulombLaw +
                   "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>");
  deck.replace("<Parameter name=\"Number of Steps\" type=\"int\" value=\"5\"/>",
               "<Parameter name=\"Number of Steps\" type=\"int\" value=\"1\"/><Parameter name=\"Maximum Cutbacks\" "
               "type=\"int\" value=\"0\"/>");
  deck.replace("</ParameterList>\n</ParameterList>",
               "</ParameterList>\n<ParameterList name=\"Nonlinear Solver\"><ParameterList name=\"Line Search\">"
               "<Parameter name=\"Method\" type=\"string\" value=\"Full Step\"/></ParameterList></ParameterList>\n"
               "</ParameterList>");
  ContactRun run;
  ASSERT_NO_THROW(run = runDeckText("friction_stiff_indenter", deck.text));
  EXPECT_EQ(run.summary.cutbacks, 0);
  ASSERT_EQ(run.summary.stepNewtonIterations.size(), 1u);
  EXPECT_LE(run.summary.stepNewtonIterations[0], 10);
  if (worldComm()->getRank() != 0) return;
  const auto& r = run.results;
  // Momentum balance to the Newton residual, and Coulomb's law per node:
  // slip on the cone against the slip, stick inside it. The reaction minus
  // the contact force is the sum of the residual over the free rows, at most
  // sqrt(DoFs) ||f|| (Cauchy-Schwarz; ||f|| = 3e-6 = 1.1e-8 P, the sum
  // 1.4e-7 P at np = 2).
  const double P = -lastGlobal(r, "reaction_top_y");
  EXPECT_GT(P, 0.0);
  const double balance = std::sqrt(double(run.summary.dofs)) * run.summary.stepResidualNorms.back().back();
  EXPECT_NEAR(lastGlobal(r, "contact_force_cylinder_y"), P, balance);
  EXPECT_NEAR(lastGlobal(r, "contact_force_cylinder_x"), -lastGlobal(r, "reaction_top_x"), balance);
  EXPECT_LT(balance, 1e-5 * P);
  const auto& state = lastNodal(r, "contact_state");
  const auto& pressure = lastNodal(r, "contact_pressure");
  const auto &tx = lastNodal(r, "contact_tangential_traction_x"), &ty = lastNodal(r, "contact_tangential_traction_y");
  const auto &sx = lastNodal(r, "contact_slip_x"), &sy = lastNodal(r, "contact_slip_y");
  double peak = 0;
  for (double p : pressure) peak = std::max(peak, p);
  int stick = 0, slip = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    const double t = std::hypot(tx[i], ty[i]);
    if (state[i] > 1.5) {
      ++stick;
      EXPECT_LE(t, 0.3 * pressure[i] * (1 + 1e-8)) << "node " << i + 1;
    } else {
      ++slip;
      EXPECT_NEAR(t, 0.3 * pressure[i], 1e-8 * peak) << "node " << i + 1;
      EXPECT_LT(tx[i] * sx[i] + ty[i] * sy[i], 0.0) << "node " << i + 1;  // the traction opposes the slip
    }
  }
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
}

}  // namespace coulomb::test
