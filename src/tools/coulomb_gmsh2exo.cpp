/// @file coulomb_gmsh2exo.cpp
/// @brief `coulomb_gmsh2exo in.msh out.e`: converts a gmsh mesh (any .msh
/// version gmsh writes, ASCII or binary) into the Exodus II file the solver
/// reads (no result variables).
///
/// Why a separate tool: gmsh cannot write Exodus, and the solver should read
/// one format only. The conversion rules (physical groups -> blocks, side
/// sets + node sets; orientation; node renumbering) are in
/// coulomb/io/GmshReader.hpp. scripts/make_mesh runs gmsh and then this.
/// Errors: one line on stderr naming the file, exit status 1 (a crash inside
/// gmsh included: the conversion runs in a child process).
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/io/GmshReader.hpp"

namespace {

/// Reads `input` and writes `output`, printing the one-line summary; 1 and
/// one line on stderr on an error.
int convert(const std::string& input, const std::string& output) {
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
    std::cout << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "coulomb_gmsh2exo: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: coulomb_gmsh2exo in.msh out.e   (in.msh: a gmsh mesh file, msh 2.2 or 4.x, ASCII or binary)\n";
    return 1;
  }
  const std::string input = argv[1], output = argv[2];
  // The conversion runs in a child process: gmsh's own reader (libgmsh 4.8.4)
  // crashes on some damaged files (tests/fuzz/gmsh_crashes/), and a crash
  // must still end as one line naming the file, with no output file left.
  std::cout.flush();
  // The child's stderr goes to a pipe: the parent passes on its one error
  // line, and replaces anything else (a sanitizer's crash report, a
  // message gmsh printed while crashing) by one line of its own.
  int errPipe[2];
  if (pipe(errPipe) != 0) return convert(input, output);
  const pid_t child = fork();
  if (child < 0) {  // no process to spare: convert here
    close(errPipe[0]);
    close(errPipe[1]);
    return convert(input, output);
  }
  if (child == 0) {
    close(errPipe[0]);
    dup2(errPipe[1], STDERR_FILENO);
    close(errPipe[1]);
    _exit(convert(input, output));
  }
  close(errPipe[1]);
  std::string childErr;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(errPipe[0], buffer, sizeof buffer);
    if (n > 0) childErr.append(buffer, static_cast<std::size_t>(n));
    else if (n == 0 || errno != EINTR) break;
  }
  close(errPipe[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) {
      std::cerr << "coulomb_gmsh2exo: error: lost the conversion of '" << input << "' (waitpid failed)\n";
      return 1;
    }
  const bool exited = WIFEXITED(status);
  if (exited && WEXITSTATUS(status) == 0) {
    std::cerr << childErr;
    return 0;
  }
  std::remove(output.c_str());  // no output that looks complete after a failure
  const std::string ownPrefix = "coulomb_gmsh2exo: ";
  const std::size_t own = childErr.rfind("\n" + ownPrefix);
  const std::size_t ownStart = childErr.rfind(ownPrefix, 0) == 0 ? 0 : (own == std::string::npos ? own : own + 1);
  if (exited && WEXITSTATUS(status) == 1 && ownStart != std::string::npos) {
    std::cerr << childErr.substr(ownStart, childErr.find('\n', ownStart) - ownStart) << "\n";
    return 1;
  }
  std::cerr << "coulomb_gmsh2exo: error: gmsh crashed (";
  if (exited) std::cerr << "exit status " << WEXITSTATUS(status);
  else std::cerr << "signal " << WTERMSIG(status);
  std::cerr << ") reading '" << input << "': the file is damaged or not a mesh gmsh can read\n";
  return 1;
}
