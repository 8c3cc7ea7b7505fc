#include "TestSupport.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/fem/DofMap.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {

Teuchos::RCP<const Teuchos::Comm<int>> worldComm() { return Tpetra::getDefaultComm(); }

std::string scratchDirectory(const std::string& name) {
  const auto comm = worldComm();
  const std::string dir = std::string(COULOMB_BINARY_DIR) + "/tests/scratch/" + name + "_np" +
                          std::to_string(comm->getSize());
  if (comm->getRank() == 0) std::filesystem::create_directories(dir);
  comm->barrier();
  return dir;
}

void writeOnRoot(const std::string& path, const std::string& text) {
  const auto comm = worldComm();
  if (comm->getRank() == 0) std::ofstream(path) << text;
  comm->barrier();
}

std::string shippedMesh(const std::string& file) { return std::string(COULOMB_SOURCE_DIR) + "/exodus_meshes/" + file; }

void writeDistortedCopy(const std::string& source, const std::string& target, double amplitude, bool straightEdges) {
  const auto comm = worldComm();
  if (comm->getRank() == 0) {
    mesh::GlobalMesh m = io::readExodus(source);
    std::vector<char> onBoundary(m.numNodes(), 0);
    for (const auto& set : m.nodeSets)
      for (long long n : set.nodes) onBoundary[n] = 1;
    // local size: shortest edge at each node, from the cells around it
    std::vector<double> size(m.numNodes(), 1e300);
    const int dim = m.dimension;
    for (const auto& block : m.blocks) {
      const int k = mesh::numNodes(block.cellType);
      for (long long e = 0; e < block.numElements(); ++e)
        for (int a = 0; a < k; ++a)
          for (int b = 0; b < k; ++b) {
            if (a == b) continue;
            const long long na = block.connectivity[e * k + a], nb = block.connectivity[e * k + b];
            double d2 = 0;
            for (int d = 0; d < dim; ++d) d2 += std::pow(m.coordinates[na * dim + d] - m.coordinates[nb * dim + d], 2);
            size[na] = std::min(size[na], std::sqrt(d2));
          }
    }
    unsigned state = 12345u;
    auto random = [&] {
      state = state * 1103515245u + 12345u;
      return ((state >> 8) & 0xffff) / 65535.0 * 2.0 - 1.0;
    };
    for (long long n = 0; n < m.numNodes(); ++n)
      for (int d = 0; d < dim; ++d) {
        const double shift = amplitude * size[n] * random();
        if (!onBoundary[n]) m.coordinates[n * dim + d] += shift;
      }
    for (const auto& block : m.blocks) {
      const int k = mesh::numNodes(block.cellType);
      for (long long e = 0; e < block.numElements() && straightEdges; ++e)
        for (int a = mesh::numCorners(block.cellType); a < k; ++a) {
          const mesh::NodeCorners c = mesh::nodeCorners(block.cellType, a);
          const long long node = block.connectivity[e * k + a];
          for (int d = 0; d < dim; ++d) {
            double mean = 0;
            for (int j = 0; j < c.count; ++j) mean += m.coordinates[block.connectivity[e * k + c.corners[j]] * dim + d];
            m.coordinates[node * dim + d] = mean / c.count;
          }
        }
    }
    io::ExodusWriter writer(target, m, {}, {}, "distorted copy of " + source);
    writer.close();
  }
  comm->barrier();
}

std::string deckXml(const std::string& meshFile, const std::string& material, const std::string& body) {
  std::ostringstream out;
  out << "<ParameterList name=\"Coulomb\">\n"
      << "  <ParameterList name=\"Mesh\"><Parameter name=\"File\" type=\"string\" value=\"" << meshFile
      << "\"/></ParameterList>\n"
      << "  <ParameterList name=\"Materials\"><ParameterList name=\"m\">" << material << "</ParameterList></ParameterList>\n"
      << "  <ParameterList name=\"Element Blocks\"><ParameterList name=\"body\">"
      << "<Parameter name=\"Material\" type=\"string\" value=\"m\"/></ParameterList></ParameterList>\n"
      << body << "</ParameterList>\n";
  return out.str();
}

std::string neoHookeanXml(double youngsModulus, double poissonsRatio) {
  std::ostringstream out;
  out.precision(17);
  out << "<Parameter name=\"Model\" type=\"string\" value=\"Neo-Hookean\"/>"
      << "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"" << youngsModulus << "\"/>"
      << "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"" << poissonsRatio << "\"/>";
  return out.str();
}

std::string dirichletXml(const std::string& name, const std::string& nodeSet, const std::string& component,
                         double value, const std::vector<double>& coefficients, const std::string& function) {
  std::ostringstream out;
  out.precision(17);
  out << "<ParameterList name=\"" << name << "\"><Parameter name=\"Node Set\" type=\"string\" value=\"" << nodeSet
      << "\"/><Parameter name=\"Component\" type=\"string\" value=\"" << component
      << "\"/><Parameter name=\"Value\" type=\"double\" value=\"" << value << "\"/>"
      << "<Parameter name=\"Function\" type=\"string\" value=\"" << function << "\"/>";
  if (!coefficients.empty()) {
    out << "<Parameter name=\"Linear Coefficients\" type=\"Array(double)\" value=\"{";
    for (std::size_t i = 0; i < coefficients.size(); ++i) out << (i ? ", " : "") << coefficients[i];
    out << "}\"/>";
  }
  out << "</ParameterList>\n";
  return out.str();
}

void forOwnedNodes(const solver::Simulation& simulation,
                   const std::function<void(long long, const double*, const double*)>& f) {
  const auto& mesh = simulation.mesh();
  const int dim = mesh.dimension();
  auto u = simulation.displacement().getData(0);
  for (int i = 0; i < mesh.numOwnedNodes(); ++i) {
    const long long node = mesh.localNodes()[i];
    f(node, &mesh.global().coordinates[node * dim], &u[i * dim]);
  }
}

LinearFieldError linearFieldError(const solver::Simulation& simulation, const double (&A)[3][3], const double (&b)[3]) {
  const int dim = simulation.mesh().dimension();
  LinearFieldError out;
  forOwnedNodes(simulation, [&](long long, const double* X, const double* u) {
    for (int i = 0; i < dim; ++i) {
      double exact = b[i];
      for (int j = 0; j < dim; ++j) exact += A[i][j] * X[j];
      out.error = std::max(out.error, std::abs(u[i] - exact));
      out.value = std::max(out.value, std::abs(exact));
    }
  });
  return {globalMax(out.error), globalMax(out.value)};
}

double globalMax(double local) {
  double result = 0;
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_MAX, local, Teuchos::outArg(result));
  return result;
}
double globalSum(double local) {
  double result = 0;
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(result));
  return result;
}

}  // namespace coulomb::test
