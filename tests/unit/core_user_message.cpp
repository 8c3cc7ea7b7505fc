/// Unit tests of coulomb::userMessage (core/UserMessage.hpp): Teuchos'
/// throw banner (a Trilinos source path, the throw number and the tested
/// expression) is removed, the user's text kept on one line.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <Teuchos_TestForException.hpp>

#include "coulomb/core/UserMessage.hpp"

namespace {

std::string teuchosMessage() {
  try {
    const bool empty = true;
    TEUCHOS_TEST_FOR_EXCEPTION(empty, std::runtime_error, "Error, An empty XML std::string or file was specified!");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(UserMessage, TeuchosThrowBannerIsRemoved) {
  const std::string raw = teuchosMessage();
  ASSERT_NE(raw.find("Throw test that evaluated to true"), std::string::npos) << raw;  // the banner is there
  const std::string plain = coulomb::userMessage("deck file 'a.xml' is wrong: " + raw);
  EXPECT_EQ(plain, "deck file 'a.xml' is wrong: Error, An empty XML std::string or file was specified!");
}

TEST(UserMessage, OneLineAndOtherTextUnchanged) {
  EXPECT_EQ(coulomb::userMessage("mesh 'a.e':\n  node 3\tis   missing \n"), "mesh 'a.e': node 3 is missing");
  EXPECT_EQ(coulomb::userMessage("t = 1: 2 steps"), "t = 1: 2 steps");
}

TEST(UserMessage, EveryBannerRemovedAndLookalikesKept) {
  const std::string raw = teuchosMessage();
  // Two banners (an error wrapped in another), each removed.
  EXPECT_EQ(coulomb::userMessage("deck: " + raw + " and " + raw),
            "deck: Error, An empty XML std::string or file was specified! and Error, An empty XML std::string or "
            "file was specified!");
  // Text that only starts like a banner is the user's: kept.
  EXPECT_EQ(coulomb::userMessage("a.xml:12: Throw number = 3 was not thrown"), "a.xml:12: Throw number = 3 was not thrown");
  EXPECT_EQ(coulomb::userMessage("Throw number = 3"), "Throw number = 3");
}

TEST(UserMessage, LongMessageWithManyLocationsIsLinear) {
  // 'file:1:' a hundred thousand times: the banner search must not backtrack
  // (std::regex took seconds on a 4 kB fuzzed deck quoted in an error).
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "f:1: ";
  const std::string plain = coulomb::userMessage(text + teuchosMessage());
  EXPECT_EQ(plain.size(), text.size() - 1 + std::string(" Error, An empty XML std::string or file was specified!").size());
}
