#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::mesh {

long long GlobalMesh::numElements() const {
  long long n = 0;
  for (const auto& block : blocks) n += block.numElements();
  return n;
}

std::string displayName(const std::string& name, const char* kind, int id) {
  return name.empty() ? std::string(kind) + "_" + std::to_string(id) : name;
}

}  // namespace coulomb::mesh
