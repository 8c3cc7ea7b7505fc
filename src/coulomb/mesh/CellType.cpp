#include "coulomb/mesh/CellType.hpp"

namespace coulomb::mesh {
std::string toString(CellType t) {
  switch (t) {
    case CellType::Quad4: return "QUAD4";
    case CellType::Tri3: return "TRI3";
    case CellType::Hex8: return "HEX8";
    case CellType::Tet4: return "TET4";
  }
  return "unknown";
}
}  // namespace coulomb::mesh
