#include "coulomb/io/NetcdfHeaderCheck.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

namespace coulomb::io {

namespace {

// The header grammar (netCDF's "classic format specification"), big-endian:
//   header   = magic numrecs dim_list gatt_list var_list
//   dim_list = ABSENT | NC_DIMENSION nelems [name dim_length ...]
//   att_list = ABSENT | NC_ATTRIBUTE nelems [name nc_type nelems values ...]
//   var_list = ABSENT | NC_VARIABLE nelems [name ndims [dimid ...] vatt_list nc_type vsize begin ...]
// with counts (NON_NEG) of 4 bytes, 8 in CDF-5; begin 4 bytes in CDF-1, else 8.
constexpr std::uint32_t kDimensionTag = 0x0A, kVariableTag = 0x0B, kAttributeTag = 0x0C;

class HeaderReader {
public:
  HeaderReader(const std::vector<unsigned char>& bytes, std::uint64_t fileSize, int version)
      : bytes_(bytes), fileSize_(fileSize), version_(version) {}

  void header() {
    position_ = 4;  // magic
    count("the record count");
    list(kDimensionTag, "dimension", 8, [this] {
      name("dimension");
      lengths_.push_back(count("a dimension length"));
    });
    attributes("global");
    list(kVariableTag, "variable", 24, [this] {
      const std::string what = "variable '" + name("variable") + "'";
      const std::uint64_t ndims = count("the dimension count of " + what);
      fits(ndims, countSize(), what + " has " + std::to_string(ndims) + " dimensions");
      // netCDF sizes a variable by dividing by the product of its earlier
      // dimensions: the record dimension (length 0) anywhere but first, or
      // a type without a size, made it divide by zero (found by fuzz_exodus).
      for (std::uint64_t d = 0; d < ndims; ++d) {
        const std::uint64_t id = count("a dimension id");
        if (id >= lengths_.size())
          fail(what + " names dimension " + std::to_string(id) + " of " + std::to_string(lengths_.size()));
        if (d > 0 && lengths_[id] == 0) fail(what + " has the record dimension in place " + std::to_string(d + 1));
      }
      attributes(what);
      const std::uint64_t type = word("a type");
      if (type == 0 || type > 11) fail(what + " has the unknown type " + std::to_string(type));
      count("a variable size");
      read(version_ == 1 ? 4 : 8, "a variable offset");
    });
  }

private:
  std::uint64_t remaining() const { return fileSize_ > position_ ? fileSize_ - position_ : 0; }
  int countSize() const { return version_ == 5 ? 8 : 4; }

  [[noreturn]] void fail(const std::string& what) const {
    std::ostringstream message;
    message << "its netCDF header is damaged: " << what << " (byte " << position_ << " of " << fileSize_ << ")";
    throw Damaged{message.str()};
  }
  /// `n` items of at least `itemSize` bytes fit in the rest of the file.
  void fits(std::uint64_t n, std::uint64_t itemSize, const std::string& what) const {
    if (itemSize > 0 && n > remaining() / itemSize) fail(what + ", more than the file holds (damaged or cut short)");
  }
  std::uint64_t read(int size, const std::string& what) {
    if (position_ + static_cast<std::uint64_t>(size) > bytes_.size()) {
      if (position_ + static_cast<std::uint64_t>(size) > fileSize_) fail("the file ends inside " + what);
      throw Incomplete{};
    }
    std::uint64_t value = 0;
    for (int i = 0; i < size; ++i) value = (value << 8) | bytes_[position_ + i];
    position_ += static_cast<std::uint64_t>(size);
    return value;
  }
  std::uint64_t word(const std::string& what) { return read(4, what); }
  std::uint64_t count(const std::string& what) { return read(countSize(), what); }
  void skip(std::uint64_t n, const std::string& what) {
    fits(n, 1, what);
    if (position_ + n > bytes_.size()) throw Incomplete{};
    position_ += n;
  }
  static std::uint64_t padded(std::uint64_t n) { return (n + 3) / 4 * 4; }
  std::string name(const char* kind) {
    const std::uint64_t length = count(std::string("a ") + kind + " name length");
    fits(length, 1, std::string("a ") + kind + " name of " + std::to_string(length) + " bytes");
    const std::uint64_t start = position_;
    skip(padded(length), std::string("a ") + kind + " name");
    return std::string(bytes_.begin() + static_cast<std::ptrdiff_t>(start),
                       bytes_.begin() + static_cast<std::ptrdiff_t>(start + std::min<std::uint64_t>(length, 64)));
  }
  template <class Item>
  void list(std::uint32_t tag, const char* kind, std::uint64_t itemSize, Item&& item) {
    const std::uint64_t found = word(std::string("the ") + kind + " list");
    const std::uint64_t n = count(std::string("the ") + kind + " count");
    if (found == 0 && n == 0) return;  // ABSENT
    if (found != tag) fail(std::string("the ") + kind + " list has the wrong tag");
    fits(n, itemSize, std::to_string(n) + " " + kind + "s");
    for (std::uint64_t i = 0; i < n; ++i) item();
  }
  void attributes(const std::string& owner) {
    list(kAttributeTag, "attribute", 12, [&] {
      const std::string what = name("attribute");
      const std::uint64_t type = word("an attribute type");
      static const int kSizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
      if (type == 0 || type > 11) fail(owner + " attribute '" + what + "' has the unknown type " + std::to_string(type));
      const std::uint64_t n = count("an attribute length");
      fits(n, static_cast<std::uint64_t>(kSizes[type]),
           owner + " attribute '" + what + "' declares " + std::to_string(n) + " values");
      skip(padded(n * static_cast<std::uint64_t>(kSizes[type])), "attribute values");
    });
  }

  const std::vector<unsigned char>& bytes_;
  std::uint64_t fileSize_;
  int version_;
  std::uint64_t position_ = 0;
  std::vector<std::uint64_t> lengths_;  ///< of the dimensions read so far

public:
  struct Incomplete {};  ///< the header goes on past the bytes given
  struct Damaged {
    std::string what;
  };
};

/// "" for a header whose counts fit, the problem, or nothing when `bytes`
/// (a prefix of the file) ends inside the header.
std::optional<std::string> headerProblem(const std::vector<unsigned char>& bytes, std::uint64_t fileSize) {
  if (bytes.size() < 4 || bytes[0] != 'C' || bytes[1] != 'D' || bytes[2] != 'F') return "";
  const int version = bytes[3];
  if (version != 1 && version != 2 && version != 5) return "";  // netCDF names it
  try {
    HeaderReader(bytes, fileSize, version).header();
  } catch (const HeaderReader::Damaged& damaged) {
    return damaged.what;
  } catch (const HeaderReader::Incomplete&) {
    return std::nullopt;
  }
  return "";
}

}  // namespace

std::string classicNetcdfHeaderProblem(const std::vector<unsigned char>& bytes, std::uint64_t fileSize) {
  return headerProblem(bytes, fileSize).value_or("");
}

std::string classicNetcdfHeaderProblem(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const auto size = static_cast<std::uint64_t>(in.tellg());
  // The header is read in growing prefixes; one larger than 64 MiB is left
  // to netCDF (its counts were checked as far as the prefix went).
  for (std::uint64_t prefix = 1 << 16;; prefix *= 4) {
    std::vector<unsigned char> bytes(std::min(prefix, size));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    const auto problem = headerProblem(bytes, size);
    if (problem || bytes.size() == size || prefix >= (std::uint64_t{1} << 26)) return problem.value_or("");
  }
}

}  // namespace coulomb::io
