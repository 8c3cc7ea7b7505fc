#include "coulomb/solver/ResultWriter.hpp"

#include <cstdio>

#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"
#include "coulomb/io/ExodusWriter.hpp"

namespace coulomb::solver {

ResultWriter::ResultWriter(const std::string& path, const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedNodeMap,
                           std::vector<std::string> nodalNames, std::vector<std::string> globalNames)
    : path_(path), mesh_(mesh) {
  const auto comm = mesh.comm();
  const bool root = comm->getRank() == 0;
  const long long numNodes = mesh.global().numNodes();
  std::vector<GlobalOrdinal> all;
  if (root) {
    all.resize(numNodes);
    for (long long i = 0; i < numNodes; ++i) all[i] = i;
  }
  rootNodeMap_ = Teuchos::rcp(new Map(numNodes, Teuchos::ArrayView<const GlobalOrdinal>(all), 0, comm));
  gather_ = Teuchos::rcp(new Import(ownedNodeMap, rootNodeMap_));
  std::string failure;
  if (root) {
    try {
      std::remove(path_.c_str());  // an older complete result must not survive a failed run either
      writer_ = std::make_unique<io::ExodusWriter>(partialPath(path_), mesh.global(), std::move(nodalNames),
                                                   std::move(globalNames));
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  throwIfAnyRankFailed(*comm, failure);
}

ResultWriter::~ResultWriter() = default;

void ResultWriter::writeStep(double time, const std::vector<NodalField>& fields, const std::vector<double>& globals) {
  std::vector<std::vector<double>> nodal;
  for (const auto& field : fields) {
    MultiVector gathered(rootNodeMap_, field.values->getNumVectors());
    gathered.doImport(*field.values, *gather_, Tpetra::INSERT);
    if (writer_) {
      auto view = gathered.get2dView();
      for (std::size_t c = 0; c < field.names.size(); ++c) nodal.emplace_back(view[c].begin(), view[c].end());
    }
  }
  std::string failure;
  if (writer_) {
    try {
      writer_->writeStep(time, nodal, globals);
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  throwIfAnyRankFailed(*mesh_.comm(), failure);
}

void ResultWriter::finish() { close(true); }

void ResultWriter::abandon() { close(false); }

void ResultWriter::close(bool complete) {
  std::string failure;
  if (writer_) {
    try {
      writer_->close();
      COULOMB_REQUIRE(!complete || std::rename(partialPath(path_).c_str(), path_.c_str()) == 0,
                      "output: cannot rename '" << partialPath(path_) << "' to '" << path_ << "'");
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  throwIfAnyRankFailed(*mesh_.comm(), failure);
}

}  // namespace coulomb::solver
