#pragma once
/// @file DeckValueCheck.hpp
/// @brief The literal values of a Teuchos XML deck, checked before Teuchos
/// converts them. Teuchos reads a number through an istringstream and keeps
/// 0 for text that is none ("abc" became a Friction Coefficient of 0: a
/// frictionless run without a word), takes "nan" and "inf" as numbers, and
/// of a parameter given twice in one list keeps one silently. Each of these
/// is a one-line coulomb::Error naming the parameter by its path in the deck.
/// Before that, the raw text's shape: Teuchos' reader recurses once per
/// nesting level (10 000 levels: a segmentation fault) and holds ~25 bytes
/// per byte of deck (a 21 MB deck: 470 MB).

#include <cstddef>
#include <string>

namespace Teuchos {
class XMLObject;
}

namespace coulomb::io {

/// @brief Checks every Parameter element below `root` (a ParameterList
/// element): values of type int, double, float, bool and their arrays are
/// finite numbers (or true/false) with nothing left over, and no name occurs
/// twice in one list. Throws coulomb::Error.
void checkXmlDeckValues(const Teuchos::XMLObject& root);

/// A deck holds parameters; data (fields, tables) belong in the mesh file.
inline constexpr std::size_t kMaxDeckBytes = 4u << 20;
inline constexpr int kMaxDeckDepth = 64;

/// @brief The file `path` is at most kMaxDeckBytes long and its elements nest
/// at most kMaxDeckDepth deep (comments and quoted attribute values skipped).
/// Throws coulomb::Error naming the file and the limit.
void checkXmlDeckShape(const std::string& path);

}  // namespace coulomb::io
