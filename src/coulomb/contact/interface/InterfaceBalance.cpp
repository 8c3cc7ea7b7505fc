/// @file InterfaceBalance.cpp
/// @brief Slave faces redistributed by their search cost (see the header).
#include "coulomb/contact/interface/InterfaceBalance.hpp"

#include <algorithm>
#include <unordered_map>

#include <Teuchos_CommHelpers.hpp>

#include "coulomb/mesh/Partition.hpp"

namespace coulomb::contact {

std::vector<int> balancedSlaveFaces(const ContactInterface& contact, const std::vector<int>& faces,
                                    const SearchResult& searched) {
  const auto& comm = contact.comm();
  if (comm->getSize() == 1) return faces;
  std::unordered_map<int, std::size_t> candidates;
  for (std::size_t k = 0; k < searched.slaveFaces.size(); ++k)
    candidates[searched.slaveFaces[k]] = searched.candidates[k].size();

  const int dim = contact.dimension();
  const auto& X = contact.referenceCoordinates();
  std::vector<double> centroids(3 * faces.size(), 0.0), weights(faces.size(), 1.0);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const ContactFace& face = contact.slaveFaces()[faces[i]];
    for (int a = 0; a < face.numNodes; ++a)
      for (int c = 0; c < dim; ++c)
        centroids[3 * i + c] += X[static_cast<std::size_t>(face.interfaceIndex[a]) * dim + c] / face.numNodes;
    const auto it = candidates.find(faces[i]);
    if (it != candidates.end()) weights[i] += static_cast<double>(it->second);
  }
  const std::vector<int> parts = mesh::partitionWeightedPoints(dim, centroids, weights, comm);

  // Every rank learns every face's new rank (one int per slave face: the
  // interface is small next to the volume, as in InterfaceGather).
  const int numFaces = static_cast<int>(contact.slaveFaces().size());
  std::vector<int> local(numFaces, -1), rankOf(numFaces, -1);
  for (std::size_t i = 0; i < faces.size(); ++i) local[faces[i]] = parts[i];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, numFaces, local.data(), rankOf.data());
  std::vector<int> mine;
  for (int k = 0; k < numFaces; ++k)
    if (rankOf[k] == comm->getRank()) mine.push_back(k);
  return mine;
}

std::vector<int> slaveNodesOfFaces(const ContactInterface& contact, const std::vector<int>& faces) {
  std::vector<int> nodes;
  for (int k : faces) {
    const ContactFace& face = contact.slaveFaces()[k];
    for (int a = 0; a < face.numNodes; ++a) nodes.push_back(contact.slaveNodeIndex(face.nodes[a]));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace coulomb::contact
