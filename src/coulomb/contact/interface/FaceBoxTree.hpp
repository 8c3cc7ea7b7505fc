#pragma once
/// @file FaceBoxTree.hpp
/// @brief The Boost.Geometry R-tree of face bounding boxes that the contact
/// search (ContactSearch.cpp) and the sharp-edge choice (SharpEdges.cpp)
/// query: 3D boxes (2D: z = 0) labelled with a face index.
#include <utility>

#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/geometry/strategies/strategies.hpp>

namespace coulomb::contact::facebox {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Point = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Entry = std::pair<Box, int>;  ///< a face's box and its index
/// R*-tree, bulk-loaded by packing when built from a range of entries.
using Tree = bgi::rtree<Entry, bgi::rstar<16>>;

}  // namespace coulomb::contact::facebox
