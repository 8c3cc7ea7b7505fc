#include "coulomb/io/ParameterValidation.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/UserMessage.hpp"
#include "coulomb/io/DeckValueCheck.hpp"
#include "coulomb/io/RangeValidator.hpp"

namespace coulomb::io {

namespace {

bool startsWith(const std::string& text, const char* prefix) {
  return text.rfind(prefix, 0) == 0;
}

std::string validNames(const Teuchos::ParameterList& valid) {
  std::string names;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    if (valid.name(it) == "*") continue;
    names += (names.empty() ? "'" : ", '") + valid.name(it) + "'";
  }
  return names;
}

std::string typeName(const Teuchos::ParameterEntry& entry) {
  return entry.isList() ? "ParameterList" : entry.getAny(false).typeName();
}

std::string valueText(const Teuchos::ParameterEntry& entry) {
  std::ostringstream value;
  entry.leftshift(value, false);
  return "'" + value.str() + "'";
}

/// What a validator accepts, in words; Teuchos' own message is a multi-line
/// banner, so it is used only for validators this function does not know.
std::string describeValidator(const Teuchos::ParameterEntryValidator& validator, const std::string& teuchosMessage) {
  if (auto v = dynamic_cast<const RangeValidator*>(&validator)) return v->requirement();
  if (auto v = dynamic_cast<const Teuchos::EnhancedNumberValidator<double>*>(&validator)) {
    std::ostringstream out;
    out << "must be in [" << v->getMin() << ", " << v->getMax() << "]";
    return out.str();
  }
  if (auto v = dynamic_cast<const Teuchos::EnhancedNumberValidator<int>*>(&validator)) {
    std::ostringstream out;
    out << "must be in [" << v->getMin() << ", " << v->getMax() << "]";
    return out.str();
  }
  if (auto strings = validator.validStringValues(); strings != Teuchos::null) {
    std::string list;
    for (const auto& s : *strings) list += (list.empty() ? "'" : ", '") + s + "'";
    return "must be one of " + list;
  }
  return userMessage(teuchosMessage);
}

}  // namespace

std::string joinPath(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "/" + name;
}

Teuchos::RCP<Teuchos::ParameterList> readXmlDeck(const std::string& path) {
  std::error_code ignored;
  COULOMB_REQUIRE(!std::filesystem::is_directory(path, ignored),
                  "deck file '" << path << "' is a directory, not an XML deck");
  std::ifstream probe(path);
  COULOMB_REQUIRE(probe.good(), "deck file '" << path << "' cannot be opened");
  char first = ' ';
  while (probe.get(first) && std::isspace(static_cast<unsigned char>(first))) {
  }
  COULOMB_REQUIRE(probe.good(), "deck file '" << path << "' is empty");
  checkXmlDeckShape(path);
  Teuchos::XMLObject xml;
  try {
    xml = Teuchos::FileInputSource(path).getObject();
  } catch (const std::exception& e) {
    // Keep the parser's own sentence ("XML parse error at line 47: ..."), not Teuchos' throw banner.
    std::string reason = userMessage(e.what());
    if (const auto pos = reason.find("XML parse error"); pos != std::string::npos) reason = reason.substr(pos);
    if (first == '{' || first == '[') reason += " (it looks like JSON; Coulomb reads Teuchos XML decks)";
    throw Error("deck file '" + path + "' is not a valid Teuchos XML parameter list: " + reason);
  }
  COULOMB_REQUIRE(xml.getTag() == "ParameterList", "deck file '" << path << "' is XML, but its root element is <"
                                                                  << xml.getTag() << ">, not <ParameterList>");
  checkXmlDeckValues(xml);
  try {
    return Teuchos::rcp(new Teuchos::ParameterList(Teuchos::XMLParameterListReader().toParameterList(xml)));
  } catch (const std::exception& e) {
    throw Error("deck file '" + path + "' is not a valid Teuchos XML parameter list: " + userMessage(e.what()));
  }
}

void validateParameters(const Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                        const std::string& path) {
  const bool hasTemplate = valid.isSublist("*");
  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string& name = user.name(it);
    const Teuchos::ParameterEntry& entry = user.entry(it);
    const std::string where = joinPath(path, name);
    const Teuchos::ParameterEntry* validEntry = valid.getEntryPtr(name);
    if (validEntry == nullptr && hasTemplate && entry.isList()) validEntry = valid.getEntryPtr("*");
    COULOMB_REQUIRE(validEntry != nullptr,
                    "deck: unknown parameter '" << where << "'"
                        << (hasTemplate ? " (expected a sublist here)"
                                        : "; valid names in '" + (path.empty() ? std::string("top level") : path) +
                                              "': " + validNames(valid)));
    if (validEntry->isList()) {
      COULOMB_REQUIRE(entry.isList(), "deck: '" << where << "' must be a ParameterList, got a parameter of type "
                                                << typeName(entry));
      if (startsWith(validEntry->docString(), kPassthrough)) continue;
      validateParameters(Teuchos::getValue<Teuchos::ParameterList>(entry),
                         Teuchos::getValue<Teuchos::ParameterList>(*validEntry), where);
      continue;
    }
    COULOMB_REQUIRE(!entry.isList(), "deck: '" << where << "' must be a parameter of type "
                                               << typeName(*validEntry) << ", got a ParameterList");
    COULOMB_REQUIRE(entry.getAny(false).type() == validEntry->getAny(false).type(),
                    "deck: '" << where << "' must have type \"" << typeName(*validEntry) << "\", got \""
                              << typeName(entry) << "\"");
    if (auto validator = validEntry->validator(); validator != Teuchos::null) {
      try {
        validator->validate(entry, name, path.empty() ? "top level" : path);
      } catch (const std::exception& e) {
        throw Error("deck: invalid value " + valueText(entry) + " for '" + where + "': " +
                    describeValidator(*validator, e.what()));
      }
    }
  }
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (name == "*" || !startsWith(valid.entry(it).docString(), kRequired)) continue;
    COULOMB_REQUIRE(user.isParameter(name), "deck: required parameter '" << joinPath(path, name) << "' is missing");
  }
}

}  // namespace coulomb::io
