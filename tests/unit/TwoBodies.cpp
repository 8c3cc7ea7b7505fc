#include "TwoBodies.hpp"

#include <algorithm>

#include "TestSupport.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"

namespace coulomb::test {

void addBody(mesh::GlobalMesh& m, const Body& body) {
  const int dim = m.dimension;
  const long long firstNode = m.numNodes();
  const int nx = body.n[0], ny = body.n[1], nz = dim == 3 ? body.n[2] : 0;
  auto coordinate = [&](int d, int i) { return body.lo[d] + (body.hi[d] - body.lo[d]) * i / body.n[d]; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        m.coordinates.push_back(coordinate(0, i));
        m.coordinates.push_back(coordinate(1, j));
        if (dim == 3) m.coordinates.push_back(coordinate(2, k));
      }
  auto node = [&](int i, int j, int k) { return firstNode + i + (nx + 1) * (j + (ny + 1) * static_cast<long long>(k)); };
  mesh::ElementBlock block;
  block.name = body.name;
  block.id = static_cast<int>(m.blocks.size()) + 1;
  block.cellType = dim == 3 ? mesh::CellType::Hex8 : mesh::CellType::Quad4;
  block.firstElement = m.numElements();
  mesh::SideSet bottom, top;
  bottom.name = body.name + "_bottom";
  top.name = body.name + "_top";
  bottom.id = static_cast<int>(m.sideSets.size()) + 1;
  top.id = bottom.id + 1;
  const int layers = dim == 3 ? nz : ny;
  long long element = block.firstElement;
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, ++element) {
        if (dim == 3) {
          for (int kk : {k, k + 1})
            for (long long v : {node(i, j, kk), node(i + 1, j, kk), node(i + 1, j + 1, kk), node(i, j + 1, kk)})
              block.connectivity.push_back(v);
        } else {
          for (long long v : {node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)})
            block.connectivity.push_back(v);
        }
        const int layer = dim == 3 ? k : j;
        // Hex8: side 5 (1,4,3,2) is z-min, side 6 (5,6,7,8) z-max; Quad4: side 1 (1,2) y-min, side 3 (3,4) y-max.
        if (layer == 0) bottom.elements.push_back(element), bottom.sides.push_back(dim == 3 ? 4 : 0);
        if (layer == layers - 1) top.elements.push_back(element), top.sides.push_back(dim == 3 ? 5 : 2);
      }
  m.blocks.push_back(block);
  m.sideSets.push_back(bottom);
  m.sideSets.push_back(top);
}

std::unique_ptr<mesh::Mesh> twoBodies(int dim, double gap, const std::string& scratchName) {
  const std::string dir = scratchDirectory(scratchName);
  const std::string path = dir + "/two_bodies_" + std::to_string(dim) + "d_" + std::to_string(gap) + ".e";
  if (worldComm()->getRank() == 0) {
    mesh::GlobalMesh m;
    m.dimension = dim;
    const int v = dim - 1;  // vertical axis
    Body lower{"lower", {4, 4, 4}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    Body upper{"upper", {3, 3, 3}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    lower.n[v] = 2, lower.lo[v] = -0.5, lower.hi[v] = 0.0;
    upper.n[v] = 2, upper.lo[v] = gap, upper.hi[v] = gap + 0.5;
    addBody(m, lower);
    addBody(m, upper);
    io::ExodusWriter writer(path, m, {}, {}, "two stacked bodies");
    writer.close();
  }
  worldComm()->barrier();
  auto global = std::make_shared<const mesh::GlobalMesh>(io::readExodus(path));
  return std::make_unique<mesh::Mesh>(global, worldComm());
}

}  // namespace coulomb::test
