/// @file coulomb_gmsh2exo.cpp
/// @brief `coulomb_gmsh2exo in.msh out.e`: converts a gmsh 2.2 ASCII mesh into
/// the Exodus II file the solver reads (no result variables).
///
/// Why a separate tool: gmsh cannot write Exodus, and the solver should read
/// one format only. The conversion rules (physical groups -> blocks, side
/// sets + node sets; orientation; node renumbering) are in
/// coulomb/io/GmshReader.hpp. scripts/make_mesh runs gmsh and then this.
/// Errors: one line on stderr naming the file, exit status 1.
#include <exception>
#include <iostream>
#include <string>

#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/io/GmshReader.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: coulomb_gmsh2exo in.msh out.e   (in.msh: gmsh format 2.2 ASCII, gmsh -format msh22)\n";
    return 1;
  }
  const std::string input = argv[1], output = argv[2];
  try {
    const auto mesh = coulomb::io::readGmsh(input);
    std::string title = "converted from " + input + " by coulomb_gmsh2exo";
    coulomb::io::ExodusWriter writer(output, mesh, {}, {}, title);
    writer.close();
    std::cout << output << ": " << mesh.dimension << "D, " << mesh.numNodes() << " nodes, " << mesh.numElements()
              << " elements; blocks:";
    for (const auto& b : mesh.blocks)
      std::cout << " " << coulomb::mesh::displayName(b.name, "block", b.id) << "(" << coulomb::mesh::toString(b.cellType)
                << " x" << b.numElements() << ")";
    std::cout << "; side sets:";
    for (const auto& s : mesh.sideSets)
      std::cout << " " << coulomb::mesh::displayName(s.name, "sideset", s.id) << "(" << s.elements.size() << ")";
    std::cout << "; node sets:";
    for (const auto& s : mesh.nodeSets)
      std::cout << " " << coulomb::mesh::displayName(s.name, "nodeset", s.id) << "(" << s.nodes.size() << ")";
    std::cout << "\n";
  } catch (const std::exception& e) {
    std::cerr << "coulomb_gmsh2exo: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
