// The classic netCDF header check before ex_open (io/NetcdfHeaderCheck.hpp):
// a shipped mesh passes; a count corrupted past the file's size, an unknown
// attribute type, a header cut short, and a variable whose dimensions or
// type would make netCDF divide by zero are named, and readExodus reports
// them as one error instead of netCDF allocating what the count declares.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/NetcdfHeaderCheck.hpp"

namespace {

std::vector<unsigned char> shippedMesh() {
  std::ifstream in(std::string(COULOMB_SOURCE_DIR) + "/exodus_meshes/block2d.e", std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void putWord(std::vector<unsigned char>& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<unsigned char>(value >> (8 * (3 - i)));
}

TEST(NetcdfHeader, ShippedMeshPasses) {
  const auto bytes = shippedMesh();
  ASSERT_GT(bytes.size(), 100u);
  ASSERT_EQ(bytes[3], 2);  // CDF-2: counts of 4 bytes; bytes 8-11 the dimension tag, 12-15 the count
  EXPECT_EQ(coulomb::io::classicNetcdfHeaderProblem(bytes, bytes.size()), "");
  EXPECT_EQ(coulomb::io::classicNetcdfHeaderProblem(std::vector<unsigned char>{'a', 'b', 'c', 'd'}, 4), "");
}

TEST(NetcdfHeader, CountBeyondTheFileIsNamed) {
  auto bytes = shippedMesh();
  putWord(bytes, 12, 0x7fffffff);
  const std::string problem = coulomb::io::classicNetcdfHeaderProblem(bytes, bytes.size());
  EXPECT_NE(problem.find("2147483647 dimensions, more than the file holds"), std::string::npos) << problem;
  // The first dimension's name length.
  bytes = shippedMesh();
  putWord(bytes, 16, 0x10000000);
  EXPECT_NE(coulomb::io::classicNetcdfHeaderProblem(bytes, bytes.size()).find("dimension name of 268435456 bytes"),
            std::string::npos);
}

TEST(NetcdfHeader, CutInsideTheHeaderIsNamed) {
  auto bytes = shippedMesh();
  bytes.resize(40);  // the 21 dimensions declared need more than the 24 bytes left
  std::string problem = coulomb::io::classicNetcdfHeaderProblem(bytes, bytes.size());
  EXPECT_NE(problem.find("21 dimensions, more than the file holds (damaged or cut short)"), std::string::npos)
      << problem;
  bytes.resize(14);  // inside the dimension count
  problem = coulomb::io::classicNetcdfHeaderProblem(bytes, bytes.size());
  EXPECT_NE(problem.find("the file ends inside the dimension count"), std::string::npos) << problem;
}

/// A CDF-1 header: dimensions "t" (the record dimension, length 0) and "n"
/// (3), one variable "v" of type `type` on the dimension ids `dims`.
std::vector<unsigned char> oneVariable(std::vector<std::uint32_t> dims, std::uint32_t type) {
  std::vector<unsigned char> bytes{'C', 'D', 'F', 1};
  auto word = [&bytes](std::uint32_t value) {
    bytes.resize(bytes.size() + 4);
    putWord(bytes, bytes.size() - 4, value);
  };
  auto name = [&](char c) { word(1), bytes.insert(bytes.end(), {static_cast<unsigned char>(c), 0, 0, 0}); };
  word(0);                   // records
  word(0x0A), word(2);       // two dimensions
  name('t'), word(0);
  name('n'), word(3);
  word(0), word(0);          // no global attributes
  word(0x0B), word(1);       // one variable
  name('v'), word(static_cast<std::uint32_t>(dims.size()));
  for (auto d : dims) word(d);
  word(0), word(0);          // no attributes
  word(type), word(24), word(static_cast<std::uint32_t>(bytes.size() + 8));
  bytes.resize(bytes.size() + 24);  // the data
  return bytes;
}

TEST(NetcdfHeader, DimensionsThatWouldDivideByZeroAreNamed) {
  auto problem = [](std::vector<std::uint32_t> dims, std::uint32_t type) {
    const auto bytes = oneVariable(std::move(dims), type);
    return coulomb::io::classicNetcdfHeaderProblem(bytes, bytes.size());
  };
  EXPECT_EQ(problem({0, 1}, 6), "");  // the record dimension first: a record variable
  EXPECT_NE(problem({1, 0}, 6).find("variable 'v' has the record dimension in place 2"), std::string::npos)
      << problem({1, 0}, 6);
  EXPECT_NE(problem({1, 7}, 6).find("variable 'v' names dimension 7 of 2"), std::string::npos);
  EXPECT_NE(problem({1}, 0).find("variable 'v' has the unknown type 0"), std::string::npos);
}

TEST(NetcdfHeader, ReadExodusReportsTheDamage) {
  auto bytes = shippedMesh();
  putWord(bytes, 12, 0x7fffffff);
  const auto dir = std::filesystem::path(COULOMB_BINARY_DIR) / "test_output" / "io_netcdf_header";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "damaged_header.e").string();
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  try {
    coulomb::io::readExodus(path);
    ADD_FAILURE() << "expected coulomb::Error";
  } catch (const coulomb::Error& e) {
    const std::string message = e.what();
    for (const char* part : {"damaged_header.e", "netCDF header is damaged", "more than the file holds"})
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

}  // namespace
