#pragma once
/// @file FuzzInput.hpp
/// @brief What every fuzz harness shares: the input bytes as a file (the
/// readers under test take a path, as users give them one) and the rule
/// that decides what counts as a finding.
///
/// Finding = anything but a coulomb::Error: a crash, a sanitizer report, a
/// hang, memory beyond libFuzzer's -rss_limit_mb, or any other exception
/// escaping (main() would answer it with "unexpected error" and MPI_Abort,
/// not with the one-line message bad input must get).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "coulomb/core/Error.hpp"

namespace coulomb::fuzz {

/// A file of this process (in $TMPDIR, /dev/shm when it exists) holding
/// the bytes given; rewritten for every input, removed at exit.
inline std::string writeInputFile(const uint8_t* data, std::size_t size, const char* suffix) {
  static const std::string path = [suffix] {
    const char* tmp = std::getenv("TMPDIR");
    std::string folder = tmp ? tmp : (access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp");
    std::string p = folder + "/coulomb_fuzz_" + std::to_string(getpid()) + suffix;
    static std::string removeAtExit;
    removeAtExit = p;
    std::atexit([] { std::remove(removeAtExit.c_str()); });
    return p;
  }();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
  std::fclose(file);
  return path;
}

/// Runs @p body; a coulomb::Error (the answer to bad input) is expected,
/// everything else propagates to libFuzzer as a finding.
template <typename Body>
int runExpectingOnlyUserErrors(Body&& body) {
  try {
    body();
  } catch (const coulomb::Error&) {
  }
  return 0;
}

}  // namespace coulomb::fuzz
