#include "catena/io/sha256.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace catena::io {
namespace {

TEST(Sha256, Fips180Vectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, AgreesWithSha256sumAcrossBlockBoundaries) {
  // Independent implementation: coreutils' sha256sum, for lengths around the padding limits.
  std::mt19937 rng(5);
  const auto path = std::filesystem::temp_directory_path() / "catena_sha256_probe.bin";
  for (std::size_t n : {1u, 54u, 55u, 56u, 57u, 63u, 64u, 65u, 119u, 120u, 127u, 128u, 1000u}) {
    std::string data(n, '\0');
    for (char& c : data) c = static_cast<char>(rng() & 0xff);
    std::ofstream(path, std::ios::binary).write(data.data(), static_cast<std::streamsize>(n));
    FILE* pipe = ::popen(("sha256sum " + path.string()).c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char digest[65] = {0};
    ASSERT_EQ(std::fread(digest, 1, 64, pipe), 64u);
    ::pclose(pipe);
    EXPECT_EQ(sha256_hex(data), std::string(digest)) << n << " bytes";
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace catena::io
