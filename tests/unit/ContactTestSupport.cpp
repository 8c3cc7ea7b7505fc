#include "ContactTestSupport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"

namespace coulomb::test {

std::string deckPath(const std::string& name) { return std::string(COULOMB_SOURCE_DIR) + "/xml/" + name + ".xml"; }

ShippedDeck::ShippedDeck(const std::string& name, const std::string& mesh) {
  std::ifstream in(deckPath(name));
  std::stringstream content;
  content << in.rdbuf();
  text = content.str();
  replace("../exodus_meshes/" + mesh, shippedMesh(mesh));
}

void ShippedDeck::fixLinearTolerance() {
  ASSERT_EQ(text.find("name=\"Newton\""), std::string::npos) << "the deck has a Newton list already";
  const auto end = text.rfind("</ParameterList>");
  ASSERT_NE(end, std::string::npos);
  text.insert(end, "<ParameterList name=\"Newton\"><Parameter name=\"Linear Tolerance\" type=\"string\" "
                   "value=\"Fixed\"/></ParameterList>\n");
}

void ShippedDeck::setNewtonFlag(const std::string& name, bool value) {
  ASSERT_EQ(text.find("name=\"Newton\""), std::string::npos) << "the deck has a Newton list already";
  const auto end = text.rfind("</ParameterList>");
  ASSERT_NE(end, std::string::npos);
  text.insert(end, "<ParameterList name=\"Newton\"><Parameter name=\"" + name + "\" type=\"bool\" value=\"" +
                       (value ? "true" : "false") + "\"/></ParameterList>\n");
}

void ShippedDeck::solveToRoundOff() {
  ASSERT_EQ(text.find("name=\"Newton\""), std::string::npos) << "the deck has a Newton list already";
  const auto end = text.rfind("</ParameterList>");
  ASSERT_NE(end, std::string::npos);
  text.insert(end, "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" "
                   "value=\"1e-12\"/><Parameter name=\"Linear Tolerance\" type=\"string\" value=\"Fixed\"/>"
                   "</ParameterList>\n");
}

void ShippedDeck::replace(const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
}

namespace {
ContactRun runFile(const std::string& deck, const std::string& output) {
  ContactRun run;
  run.simulation = std::make_unique<solver::Simulation>(deck, worldComm(), nullptr, output);
  run.summary = run.simulation->run();
  if (worldComm()->getRank() == 0) run.results = io::readExodusResults(output);
  return run;
}
}  // namespace

ContactRun runDeck(const std::string& name) {
  return runFile(deckPath(name), scratchDirectory("contact_" + name) + "/" + name + ".e");
}

ContactRun runDeckText(const std::string& name, const std::string& text) {
  const std::string dir = scratchDirectory(name);
  writeOnRoot(dir + "/deck.xml", text);
  return runFile(dir + "/deck.xml", dir + "/result.e");
}

namespace {
std::set<long long> punchNodes(const mesh::GlobalMesh& m) {
  std::set<long long> punch;
  for (const auto& block : m.blocks)
    if (block.name == "punch") punch.insert(block.connectivity.begin(), block.connectivity.end());
  return punch;
}
}  // namespace

void writeMovedPatch2d(const std::string& path, const std::array<double, 2>& punchShift,
                       const std::array<double, 2>& allShift, const std::string& title) {
  if (worldComm()->getRank() == 0) {
    mesh::GlobalMesh m = io::readExodus(shippedMesh("contact_patch2d.e"));
    const std::set<long long> punch = punchNodes(m);
    EXPECT_FALSE(punch.empty());
    for (long long n : punch)
      for (int c = 0; c < 2; ++c) m.coordinates[2 * n + c] += punchShift[c];
    for (std::size_t i = 0; i < m.coordinates.size(); ++i) m.coordinates[i] += allShift[i % 2];
    io::ExodusWriter writer(path, m, {}, {}, title);
    writer.close();
  }
  worldComm()->barrier();
}

void writeGradedPatch2d(const std::string& path) {
  if (worldComm()->getRank() == 0) {
    mesh::GlobalMesh m = io::readExodus(shippedMesh("contact_patch2d.e"));
    const std::set<long long> punch = punchNodes(m);
    EXPECT_FALSE(punch.empty());
    for (long long n : punch) m.coordinates[2 * n] *= m.coordinates[2 * n];
    io::ExodusWriter writer(path, m, {}, {}, "2D patch, punch graded x -> x^2");
    writer.close();
  }
  worldComm()->barrier();
}

int writePatch3dWithPunchLeft(const std::string& path) {
  int onInterface = 0;
  if (worldComm()->getRank() == 0) {
    mesh::GlobalMesh m = io::readExodus(shippedMesh("contact_patch3d.e"));
    const std::set<long long> punch = punchNodes(m);
    mesh::NodeSet set;
    set.name = "punch_left";
    set.id = 100;
    for (long long n : punch)
      if (std::abs(m.coordinates[3 * n]) < 1e-12) set.nodes.push_back(n);
    for (long long n : set.nodes) onInterface += std::abs(m.coordinates[3 * n + 2] - 0.5) < 1e-12 ? 1 : 0;
    m.nodeSets.push_back(set);
    io::ExodusWriter writer(path, m, {}, {}, "3D patch with the punch's face x = 0 as a node set");
    writer.close();
  }
  worldComm()->barrier();
  return onInterface;
}

double lastGlobal(const io::ExodusResults& r, const std::string& name) {
  return r.global.back()[r.globalIndex(name)];
}
const std::vector<double>& lastNodal(const io::ExodusResults& r, const std::string& name) {
  return r.nodal.back()[r.nodalIndex(name)];
}

double nodalDifference(const io::ExodusResults& a, const io::ExodusResults& b, const std::string& field) {
  return nodalDifference(a, b, field, {field});
}

double nodalDifference(const io::ExodusResults& a, const io::ExodusResults& b, const std::string& field,
                       const std::vector<std::string>& scaleFields) {
  double scale = 0, d = 0;
  EXPECT_EQ(a.nodal.size(), b.nodal.size()) << field;
  for (std::size_t s = 0; s < std::min(a.nodal.size(), b.nodal.size()); ++s) {
    const auto &x = a.nodal[s][a.nodalIndex(field)], &y = b.nodal[s][b.nodalIndex(field)];
    for (std::size_t i = 0; i < x.size(); ++i) d = std::max(d, std::abs(x[i] - y[i]));
    for (const std::string& name : scaleFields)
      for (double v : a.nodal[s][a.nodalIndex(name)]) scale = std::max(scale, std::abs(v));
  }
  return scale > 0 ? d / scale : d;
}

std::string assemblyDeck(const std::string& mesh, const std::vector<std::string>& blocks,
                         const std::vector<std::pair<std::string, std::string>>& fixed, double delta,
                         const std::vector<AssemblyPair>& pairs, const std::string& axis) {
  std::ostringstream d;
  d << "<ParameterList name=\"Coulomb\"><ParameterList name=\"Mesh\"><Parameter name=\"File\" type=\"string\" value=\""
    << shippedMesh(mesh) << "\"/></ParameterList>"
    << "<ParameterList name=\"Materials\"><ParameterList name=\"steel\">"
       "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"210000\"/>"
       "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.3\"/></ParameterList></ParameterList>"
       "<ParameterList name=\"Element Blocks\">";
  for (const auto& block : blocks)
    d << "<ParameterList name=\"" << block << "\"><Parameter name=\"Material\" type=\"string\" value=\"steel\"/></ParameterList>";
  d << "</ParameterList><ParameterList name=\"Dirichlet Conditions\">" << dirichletXml("bottom", "bottom", axis, 0.0)
    << dirichletXml("top", "top", axis, -delta);
  for (const auto& [set, component] : fixed) d << dirichletXml(set, set, component, 0.0);
  d << "</ParameterList><ParameterList name=\"Contact\"><ParameterList name=\"Pairs\">";
  for (const auto& p : pairs)
    d << "<ParameterList name=\"" << p.name << "\"><Parameter name=\"Slave\" type=\"string\" value=\"" << p.slave
      << "\"/><Parameter name=\"Master\" type=\"string\" value=\"" << p.master << "\"/>" << p.options
      << "</ParameterList>";
  d << "</ParameterList></ParameterList><ParameterList name=\"Load Stepping\">"
       "<Parameter name=\"Number of Steps\" type=\"int\" value=\"2\"/></ParameterList></ParameterList>";
  return d.str();
}

void expectUniformPressure(const ContactRun& run, double current, int active, const std::string& axis, double force) {
  const auto& pressure = lastNodal(run.results, "contact_pressure");
  const auto& state = lastNodal(run.results, "contact_state");
  int found = 0;
  for (std::size_t i = 0; i < state.size(); ++i)
    if (state[i] > 0.5) {
      ++found;
      EXPECT_NEAR(pressure[i], current, 1e-8 * current);
    }
  EXPECT_EQ(found, active);
  EXPECT_NEAR(lastGlobal(run.results, "contact_force_punch_" + axis), force, 1e-8 * force);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_top_" + axis), -force, 1e-8 * force);
}

}  // namespace coulomb::test
