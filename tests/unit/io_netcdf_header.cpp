// The classic netCDF header check before ex_open (io/NetcdfHeaderCheck.hpp):
// a shipped mesh passes; a count corrupted past the file's size, an unknown
// attribute type and a header cut short are named, and readExodus reports
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
