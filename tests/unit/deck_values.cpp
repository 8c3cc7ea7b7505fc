/// Unit tests of the deck reader's checks of literal values and of what is
/// given as a deck (io::readXmlDeck, io/DeckValueCheck.hpp): Teuchos alone
/// reads "abc" as 0, takes nan and inf, keeps one of a parameter given
/// twice, and calls a directory an empty XML file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/DeckValueCheck.hpp"
#include "coulomb/io/ParameterValidation.hpp"

namespace {

/// A file of this test's own folder: ctest runs the tests of this file in
/// parallel processes (gtest_discover_tests), which shared deck.xml before
/// (DeckValues.* then failed at random under ctest -j2).
std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::path(COULOMB_BINARY_DIR) / "tests" / "deck_values" /
                   ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = scratch(name);
  std::ofstream(path) << text;
  return path;
}

/// A deck with one parameter `name` of `type` = `value` in the list Materials/steel.
std::string deck(const std::string& type, const std::string& value, const std::string& extra = "") {
  return "<ParameterList name=\"Coulomb\"><ParameterList name=\"Materials\"><ParameterList name=\"steel\">"
         "<Parameter name=\"Young's Modulus\" type=\"" + type + "\" value=\"" + value + "\"/>" + extra +
         "</ParameterList></ParameterList></ParameterList>";
}

/// The message of the coulomb::Error readXmlDeck throws for `text` ("" if none).
std::string errorOf(const std::string& text) {
  try {
    coulomb::io::readXmlDeck(write("deck.xml", text));
  } catch (const coulomb::Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DeckValues, NumbersAreReadWhole) {
  const auto list = coulomb::io::readXmlDeck(write("good.xml", deck("double", " 2.1e5 ")));
  EXPECT_EQ(list->sublist("Materials").sublist("steel").get<double>("Young's Modulus"), 2.1e5);
  const auto arrays = coulomb::io::readXmlDeck(write("arrays.xml", deck("Array(double)", "{0, 5.5, 1e3}")));
  EXPECT_EQ(arrays->sublist("Materials").sublist("steel").get<Teuchos::Array<double>>("Young's Modulus").size(), 3u);
  EXPECT_EQ(errorOf(deck("bool", "TRUE")), "");
  EXPECT_EQ(errorOf(deck("Array(int)", "{}")), "");
}

TEST(DeckValues, TextThatIsNoNumberIsAnError) {
  for (const std::string value : {"abc", "", "1.5x", "1,5", "0x"}) {
    const std::string message = errorOf(deck("double", value));
    EXPECT_NE(message.find("'Materials/steel/Young's Modulus' = '" + value + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(value.empty() ? "is empty" : "is not a number"), std::string::npos) << message;
  }
  EXPECT_NE(errorOf(deck("int", "2.5")).find("'2.5' is not an integer"), std::string::npos);
  EXPECT_NE(errorOf(deck("int", "99999999999")).find("out of the range"), std::string::npos);
  EXPECT_NE(errorOf(deck("bool", "ture")).find("is not true or false"), std::string::npos);
  EXPECT_NE(errorOf(deck("Array(double)", "{0, x, 2}")).find("'x' is not a number"), std::string::npos);
  EXPECT_NE(errorOf(deck("Array(double)", "0, 1")).find("is not an array"), std::string::npos);
}

TEST(DeckValues, NanAndInfinityAreErrors) {
  for (const std::string value : {"nan", "NaN", "inf", "-inf", "1e999"})
    EXPECT_NE(errorOf(deck("double", value)).find("is not a finite number"), std::string::npos) << value;
  EXPECT_NE(errorOf(deck("Array(double)", "{1, nan}")).find("is not a finite number"), std::string::npos);
}

TEST(DeckValues, AParameterGivenTwiceIsAnError) {
  const std::string twice = errorOf(deck("double", "1", "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"2\"/>"));
  EXPECT_NE(twice.find("'Materials/steel/Young's Modulus' is given twice in 'Materials/steel'"), std::string::npos)
      << twice;
  const std::string lists = errorOf(
      "<ParameterList name=\"Coulomb\"><ParameterList name=\"Mesh\"/><ParameterList name=\"Mesh\"/></ParameterList>");
  EXPECT_NE(lists.find("'Mesh' is given twice in 'top level'"), std::string::npos) << lists;
}

TEST(DeckValues, WhatIsGivenAsADeckIsNamed) {
  const std::string dir = scratch("a_directory");
  std::filesystem::create_directories(dir);
  auto message = [](const std::string& path) {
    try {
      coulomb::io::readXmlDeck(path);
    } catch (const coulomb::Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(dir).find("is a directory"), std::string::npos) << message(dir);
  EXPECT_NE(message(write("empty.xml", "")).find("is empty"), std::string::npos);
  EXPECT_NE(message(write("blank.xml", " \n\t\n")).find("is empty"), std::string::npos);
  EXPECT_NE(message(write("deck.json", "{\"Coulomb\": {}}")).find("looks like JSON"), std::string::npos);
  EXPECT_NE(message(write("other.xml", "<Deck/>")).find("root element is <Deck>"), std::string::npos);
  EXPECT_NE(message(scratch("missing.xml")).find("cannot be opened"), std::string::npos);
  // Teuchos' source paths never reach the user.
  for (const std::string& m : {message(dir), message(write("empty2.xml", "")), message(write("bad.xml", "<a"))})
    EXPECT_EQ(m.find("packages/teuchos"), std::string::npos) << m;
}

// Teuchos' reader recurses per nesting level (10 000 levels crashed it) and
// holds ~25 bytes per deck byte: the raw text is checked first.
TEST(DeckValues, DeepOrHugeDecksAreRefusedBeforeParsing) {
  auto nested = [](int levels) {
    std::string text;
    for (int k = 0; k < levels; ++k) text += "<ParameterList name=\"l" + std::to_string(k) + "\">";
    for (int k = 0; k < levels; ++k) text += "</ParameterList>";
    return text;
  };
  EXPECT_EQ(errorOf(nested(coulomb::io::kMaxDeckDepth)), "");
  EXPECT_NE(errorOf(nested(coulomb::io::kMaxDeckDepth + 1)).find("nest deeper than 64 levels"), std::string::npos);
  EXPECT_NE(errorOf(nested(10000)).find("nest deeper than 64 levels"), std::string::npos);
  // Comments, declarations and quoted '>' do not count as levels.
  EXPECT_EQ(errorOf("<?xml version=\"1.0\"?><!-- <a><b><c> -->" +
                    deck("string", "a > b", "<Parameter name=\"x\" type=\"string\" value='>'/>")),
            "");
  std::string huge = "<ParameterList name=\"Coulomb\">";
  while (huge.size() <= coulomb::io::kMaxDeckBytes) huge += "<!-- padding padding padding padding padding -->\n";
  huge += "</ParameterList>";
  EXPECT_NE(errorOf(huge).find("larger than 4 MiB"), std::string::npos);
}
