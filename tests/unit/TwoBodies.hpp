#pragma once
// Two stacked structured bodies with non-matching faces on the contact plane,
// for the contact tests (search, mortar pass).
#include <memory>
#include <string>

#include "coulomb/mesh/GlobalMesh.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {

/// A structured box body: n[d] cells between lo[d] and hi[d] (Hex8 in 3D, Quad4 in 2D).
struct Body {
  std::string name;
  int n[3];
  double lo[3], hi[3];
};

/// Appends `body` as a new block, with side sets "<name>_bottom" (lowest
/// z in 3D / y in 2D) and "<name>_top" (highest).
void addBody(mesh::GlobalMesh& m, const Body& body);

/// Lower body [0,1]^(d-1) x [-0.5, 0] with 4 cells per edge of the contact plane
/// (master "lower_top"), upper body [0,1]^(d-1) x [gap, gap + 0.5] with 3
/// (slave "upper_bottom"): non-matching faces on the contact plane.
/// Rank 0 writes the Exodus file into scratchDirectory(scratchName); every
/// rank reads it and partitions.
std::unique_ptr<mesh::Mesh> twoBodies(int dim, double gap, const std::string& scratchName);

}  // namespace coulomb::test
