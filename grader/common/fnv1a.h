// FNV-1a, 64 bits: a quick hash that notices a changed text, and names a file by one. Not a
// defence against forgery: a caller that must not be fooled compares the bytes themselves
// (build/build.cpp's known objects), or hashes only what the TA owns (batch/layouts.cpp's
// fingerprints).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace a6::grader {

struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;

  void addBytes(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * kPrime;
  }
  /// `bytes`, then a separator, so that "ab" + "c" differs from "a" + "bc".
  void add(const std::string& bytes) {
    addBytes(bytes.data(), bytes.size());
    h = (h ^ 0xffu) * kPrime;
  }
  /// Sixteen hex digits.
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
  }

 private:
  static constexpr std::uint64_t kPrime = 1099511628211ull;
};

}  // namespace a6::grader
