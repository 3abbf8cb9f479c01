#include "friction/support/folder_lock.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <optional>
#include <string>

namespace frictionlab::support {
namespace folder_lock_test {

std::filesystem::path fresh(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("frictionlab_folder_lock_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// The error of a second claim on `dir`, or "" if it succeeded.
std::string second_claim(const std::filesystem::path& dir, long* holder = nullptr) {
  try {
    const FolderLock again(dir);
  } catch (const FolderInUse& e) {
    if (holder) *holder = e.holder();
    return e.what();
  }
  return "";
}

TEST(SupportFolderLock, ASecondClaimIsRefusedNamingTheFolderAndTheHolder) {
  const auto dir = fresh("second");
  const FolderLock lock(dir);
  EXPECT_TRUE(std::filesystem::is_directory(dir)) << "the folder is created";
  long holder = 0;
  const std::string error = second_claim(dir, &holder);
  EXPECT_EQ(holder, ::getpid());
  EXPECT_EQ(error, "--out " + dir.string() + " is in use by another frictionlab job (pid " + std::to_string(::getpid()) +
                       "; " + (dir / ".frictionlab.lock").string() + "): wait for it to end, or choose another --out");
  std::filesystem::remove_all(dir);
}

TEST(SupportFolderLock, TheClaimEndsWithTheLockAndLeavesNoFile) {
  const auto dir = fresh("release");
  { const FolderLock lock(dir); }
  EXPECT_FALSE(std::filesystem::exists(dir / FolderLock::kFileName));
  EXPECT_EQ(second_claim(dir), "");
  std::filesystem::remove_all(dir);
}

// A job killed with SIGKILL leaves its lock file behind; the system has released its claim, and
// the next job takes the folder without anyone removing the file.
TEST(SupportFolderLock, TheFolderOfAKilledJobIsTakenOver) {
  const auto dir = fresh("killed");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const FolderLock lock(dir);
    const char byte = 1;
    (void)!::write(ready[1], &byte, 1);
    for (;;) ::pause();
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  long holder = 0;
  EXPECT_NE(second_claim(dir, &holder), "");
  EXPECT_EQ(holder, child);
  ::kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(std::filesystem::exists(dir / FolderLock::kFileName)) << "the dead job's file is still there";
  EXPECT_EQ(second_claim(dir), "");
  ::close(ready[0]);
  ::close(ready[1]);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::support
