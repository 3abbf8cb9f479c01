#include "friction/support/checked_input.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>

namespace frictionlab::support {
namespace checked_input_test {

std::filesystem::path temp(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("frictionlab_checked_input_" + name + "_" + std::to_string(::getpid()));
}

TEST(SupportCheckedInput, ReadsEveryByte) {
  const auto p = temp("bytes");
  std::string bytes(200000, 'x');  // more than one read(2) chunk
  bytes[7] = '\0';
  bytes.back() = '\n';
  { std::ofstream(p, std::ios::binary) << bytes; }
  EXPECT_EQ(read_file(p, "file"), bytes);
  { std::ofstream(p, std::ios::binary | std::ios::trunc); }
  EXPECT_EQ(read_file(p, "file"), "");  // empty is empty, not an error
  std::filesystem::remove(p);
}

// A read that fails after the open (EIO) was taken for the end of an empty file.
TEST(SupportCheckedInput, AReadThatFailsIsAnErrorNotTheEndOfTheFile) {
  if (!std::filesystem::exists("/proc/self/mem")) GTEST_SKIP() << "no /proc/self/mem on this system";
  try {
    (void)read_file("/proc/self/mem", "scenario file");
    ADD_FAILURE() << "reading /proc/self/mem at offset 0 succeeded";
  } catch (const InputError& e) {
    EXPECT_EQ(e.error_number(), EIO);
    EXPECT_STREQ(e.what(), "reading scenario file '/proc/self/mem' failed: Input/output error");
  }
}

TEST(SupportCheckedInput, AMissingFileOrAFolderNamesTheFileAndTheReason) {
  try {
    (void)read_file("/no/such/file.toml", "study file");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.error_number(), ENOENT);
    EXPECT_STREQ(e.what(), "cannot read study file '/no/such/file.toml': No such file or directory");
  }
  try {
    (void)read_file("/", "study file");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.error_number(), EISDIR);
    EXPECT_STREQ(e.what(), "study file '/' is a folder: give the path of a file");
  }
  // An InputError is bad input: a std::invalid_argument, as the command line and Python expect.
  EXPECT_THROW((void)read_file("/no/such/file.toml", "file"), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::support
