/// @file DeckValueCheck.cpp
/// @brief checkXmlDeckValues (DeckValueCheck.hpp).
#include "coulomb/io/DeckValueCheck.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <Teuchos_XMLObject.hpp>

#include "coulomb/core/Error.hpp"

namespace coulomb::io {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

/// What is wrong with `text` as one value of `scalar` ("" when nothing).
std::string scalarProblem(const std::string& scalar, const std::string& value) {
  const std::string text = trimmed(value);
  if (scalar == "bool") {  // what Teuchos' XMLObject::getRequiredBool takes, in any case
    std::string lower = text;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* word : {"true", "false", "yes", "no", "1", "0"})
      if (lower == word) return "";
    return "is not true or false";
  }
  if (text.empty()) return "is empty, not a number";
  char* end = nullptr;
  errno = 0;
  if (scalar == "int") {
    const long number = std::strtol(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size()) return "is not an integer";
    if (errno == ERANGE || number < INT_MIN || number > INT_MAX) return "is out of the range of an int";
    return "";
  }
  const double number = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return "is not a number";
  if (!std::isfinite(number)) return "is not a finite number";
  return "";
}

/// The scalar type of a Teuchos type name ("double", "Array(double)"), or "" for others (string, ...).
std::string scalarOf(const std::string& type, bool& array) {
  array = type.rfind("Array(", 0) == 0 && type.back() == ')';
  const std::string scalar = array ? type.substr(6, type.size() - 7) : type;
  return scalar == "int" || scalar == "double" || scalar == "float" || scalar == "bool" ? scalar : "";
}

void checkParameter(const Teuchos::XMLObject& parameter, const std::string& where) {
  if (!parameter.hasAttribute("type") || !parameter.hasAttribute("value")) return;  // Teuchos' own error
  const std::string& type = parameter.getAttribute("type");
  const std::string& value = parameter.getAttribute("value");
  bool array = false;
  const std::string scalar = scalarOf(type, array);
  if (scalar.empty()) return;
  std::vector<std::string> items;
  if (array) {
    const std::string text = trimmed(value);
    COULOMB_REQUIRE(text.size() >= 2 && text.front() == '{' && text.back() == '}',
                    "deck: '" << where << "' = '" << value << "' is not an array {a, b, ...} of type " << type);
    const std::string inner = text.substr(1, text.size() - 2);
    if (trimmed(inner).empty()) return;
    std::size_t start = 0;
    for (std::size_t comma; (comma = inner.find(',', start)) != std::string::npos; start = comma + 1)
      items.push_back(inner.substr(start, comma - start));
    items.push_back(inner.substr(start));
  } else {
    items.push_back(value);
  }
  for (const std::string& item : items) {
    const std::string problem = scalarProblem(scalar, item);
    COULOMB_REQUIRE(problem.empty(), "deck: '" << where << "' = '" << trimmed(item) << "' " << problem
                                                << " (type " << type << ")");
  }
}

void checkList(const Teuchos::XMLObject& list, const std::string& path) {
  std::set<std::string> names;
  for (int i = 0; i < list.numChildren(); ++i) {
    const Teuchos::XMLObject& child = list.getChild(i);
    const std::string& tag = child.getTag();
    if (tag != "Parameter" && tag != "ParameterList") continue;
    if (!child.hasAttribute("name")) continue;  // Teuchos' own error
    const std::string& name = child.getAttribute("name");
    const std::string where = path.empty() ? name : path + "/" + name;
    COULOMB_REQUIRE(names.insert(name).second,
                    "deck: '" << where << "' is given twice in '" << (path.empty() ? "top level" : path)
                              << "': keep one");
    if (tag == "Parameter")
      checkParameter(child, where);
    else
      checkList(child, where);
  }
}

}  // namespace

void checkXmlDeckValues(const Teuchos::XMLObject& root) { checkList(root, ""); }

void checkXmlDeckShape(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  // Read in pieces up to one byte past the limit (a 4 MiB buffer for every
  // deck cost more than the rest of the reading).
  std::string text;
  char piece[1 << 16];
  while (text.size() <= kMaxDeckBytes && in.read(piece, sizeof piece).gcount() > 0)
    text.append(piece, static_cast<std::size_t>(in.gcount()));
  COULOMB_REQUIRE(text.size() <= kMaxDeckBytes, "deck file '" << path << "' is larger than " << (kMaxDeckBytes >> 20)
                                                               << " MiB: a deck holds parameters (fields and tables "
                                                                  "belong in the mesh file)");
  int depth = 0, line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') ++line;
    if (text[i] != '<') continue;
    if (text.compare(i, 4, "<!--") == 0) {  // a comment: to its end
      const std::size_t end = text.find("-->", i + 4);
      for (std::size_t k = i; k < std::min(end, text.size()); ++k) line += text[k] == '\n';
      if (end == std::string::npos) break;
      i = end + 2;
      continue;
    }
    const bool closing = i + 1 < text.size() && text[i + 1] == '/';
    const bool special = i + 1 < text.size() && (text[i + 1] == '?' || text[i + 1] == '!');
    // The end of the tag, past quoted attribute values (which may hold '>').
    std::size_t k = i + 1;
    char quote = 0;
    for (; k < text.size(); ++k) {
      if (text[k] == '\n') ++line;
      if (quote) {
        if (text[k] == quote) quote = 0;
      } else if (text[k] == '"' || text[k] == '\'') {
        quote = text[k];
      } else if (text[k] == '>') {
        break;
      }
    }
    if (k >= text.size()) break;  // an unterminated tag: the parser says where
    const bool selfClosing = text[k - 1] == '/';
    if (closing) --depth;
    else if (!special && !selfClosing) ++depth;
    COULOMB_REQUIRE(depth <= kMaxDeckDepth, "deck file '" << path << "': lists nest deeper than " << kMaxDeckDepth
                                                           << " levels at line " << line);
    i = k;
  }
}

}  // namespace coulomb::io
