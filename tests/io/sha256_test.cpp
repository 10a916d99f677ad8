// SHA-256 against FIPS 180-4's published examples and against sha256sum's answer for a file.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "fabform/error.hpp"
#include "fabform/io/sha256.hpp"
#include "support/temp_dir.hpp"

namespace fabform::sha256_test {
namespace {

TEST(Sha256, MatchesThePublishedExamples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

// A file larger than the reading buffer (1 MiB) hashes as its bytes do.
TEST(Sha256, OfAFileIsOfItsBytes) {
  test::TempDir dir;
  std::string bytes(3 * (1 << 20) + 17, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7919 % 251);
  const std::string path = dir.write("big.bin", bytes);
  EXPECT_EQ(sha256_of_file(path), sha256_hex(bytes));
  const std::string command = "sha256sum '" + path + "'";
  if (std::FILE* pipe = popen(command.c_str(), "r")) {  // coreutils is in every Debian base
    char line[128] = {};
    const bool read = std::fgets(line, sizeof line, pipe) != nullptr;
    pclose(pipe);
    if (read) {
      EXPECT_EQ(std::string(line).substr(0, 64), sha256_of_file(path));
    }
  }
}

TEST(Sha256, MissingFileIsAnInputErrorNamingIt) {
  try {
    sha256_of_file("/nonexistent/scene.toml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace fabform::sha256_test
