#include "friction/support/checked_output.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

namespace frictionlab::support {
namespace checked_output_test {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path fresh_dir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_support_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs `body` in a child process whose files may not grow beyond `limit` bytes (RLIMIT_FSIZE;
// SIGXFSZ ignored so that writes fail with EFBIG instead of killing it). Returns its exit code.
int in_child_with_file_limit(rlim_t limit, const std::function<int()>& body) {
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit r{limit, limit};
    if (::setrlimit(RLIMIT_FSIZE, &r) != 0) ::_exit(90);
    int code = 91;
    try {
      code = body();
    } catch (...) {
      code = 92;
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A 30-byte record whose number can be checked when read back.
std::string record(int i) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "record %08d of the sequence\n", i);
  return buf;
}

TEST(SupportCheckedOutput, RecordFileWritesEveryRecord) {
  const fs::path dir = fresh_dir("records");
  std::string expected;
  {
    RecordFile f(dir / "r.csv", 64);  // a small buffer: many writes
    for (int i = 0; i < 100; ++i) {
      f.append(record(i));
      expected += record(i);
    }
    f.close();
    EXPECT_EQ(f.bytes_written(), expected.size());
    EXPECT_FALSE(f.failed());
  }
  EXPECT_EQ(slurp(dir / "r.csv"), expected);
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, ASizeLimitRefusesTheRecordThatWouldPassItAndKeepsTheFileValid) {
  const fs::path dir = fresh_dir("size_limit");
  const std::size_t r = record(0).size();  // 30 bytes
  const std::uint64_t limit = 3 * r + r / 2;  // room for three records and half of a fourth
  std::string expected;
  {
    RecordFile f(dir / "r.csv", 64);
    f.set_size_limit(limit);
    for (int i = 0; i < 3; ++i) {
      f.append(record(i));
      expected += record(i);
    }
    EXPECT_EQ(f.size(), 3 * r);
    try {
      f.append(record(3));
      ADD_FAILURE() << "the fourth record was taken past the limit";
    } catch (const SizeLimitReached& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(limit) + " bytes"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(f.failed());  // a refusal, not a failure: the file closes cleanly
    EXPECT_EQ(f.size(), 3 * r);
    EXPECT_NO_THROW(f.close());
  }
  EXPECT_EQ(slurp(dir / "r.csv"), expected);
  EXPECT_LE(fs::file_size(dir / "r.csv"), limit);
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, DestructorKeepsBufferedRecords) {
  const fs::path dir = fresh_dir("dtor");
  {
    RecordFile f(dir / "r.csv");
    f.append(record(1));
  }
  EXPECT_EQ(slurp(dir / "r.csv"), record(1));
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, AFullDeviceIsAnErrorNamingFileAndReason) {
  RecordFile f("/dev/full");
  f.append(record(0));
  try {
    f.flush();
    FAIL() << "no error writing to /dev/full";
  } catch (const OutputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/dev/full"), std::string::npos) << what;
    EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
  }
  EXPECT_TRUE(f.failed());
  EXPECT_THROW(f.append(record(1)), OutputError);  // it stays failed
  EXPECT_THROW(f.close(), OutputError);
}

TEST(SupportCheckedOutput, AnUnwritablePathIsAnError) {
  EXPECT_THROW(RecordFile("/no/such/folder/r.csv"), OutputError);
}

TEST(SupportCheckedOutput, AFileSizeLimitLeavesOnlyWholeRecords) {
  const fs::path dir = fresh_dir("limit");
  const fs::path file = dir / "r.csv";
  constexpr rlim_t kLimit = 1000;  // not a multiple of the 30-byte record; below the 4096-byte buffer
  const int code = in_child_with_file_limit(kLimit, [&] {
    RecordFile f(file, 4096);
    try {
      for (int i = 0; i < 1000; ++i) f.append(record(i));
      f.close();
    } catch (const OutputError&) {
      return 0;  // the expected end
    }
    return 1;
  });
  ASSERT_EQ(code, 0) << "the limit did not stop the writes";
  const std::string text = slurp(file);
  EXPECT_LE(text.size(), kLimit);
  EXPECT_GT(text.size() + record(0).size(), kLimit) << "whole records that fitted were dropped";
  ASSERT_EQ(text.size() % record(0).size(), 0u) << "a record was cut: " << text.size() << " bytes";
  for (std::size_t i = 0; i < text.size() / record(0).size(); ++i)
    EXPECT_EQ(text.substr(i * record(0).size(), record(0).size()), record(static_cast<int>(i)));
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, AppendModeKeepsWhatTheFileHeld) {
  const fs::path dir = fresh_dir("append");
  {
    RecordFile f(dir / "r.csv");
    f.append(record(0));
  }
  {
    RecordFile f(dir / "r.csv", RecordFile::OpenMode::append);
    f.append(record(1));
    f.close();
    EXPECT_EQ(f.bytes_written(), record(1).size()) << "counts what this object wrote";
  }
  EXPECT_EQ(slurp(dir / "r.csv"), record(0) + record(1));
  {
    RecordFile f(dir / "new.csv", RecordFile::OpenMode::append);  // creates a missing file
    f.append(record(2));
  }
  EXPECT_EQ(slurp(dir / "new.csv"), record(2));
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, AppendModeUnderAFileSizeLimitKeepsTheOldRecordsAndWholeNewOnes) {
  const fs::path dir = fresh_dir("append_limit");
  const fs::path file = dir / "r.csv";
  std::string old;
  for (int i = 0; i < 10; ++i) old += record(i);  // 300 bytes before the limit bites
  {
    std::ofstream(file, std::ios::binary) << old;
  }
  constexpr rlim_t kLimit = 1000;
  const int code = in_child_with_file_limit(kLimit, [&] {
    RecordFile f(file, RecordFile::OpenMode::append, 4096);
    try {
      for (int i = 10; i < 1000; ++i) f.append(record(i));
      f.close();
    } catch (const OutputError&) {
      return 0;
    }
    return 1;
  });
  ASSERT_EQ(code, 0) << "the limit did not stop the writes";
  const std::string text = slurp(file);
  EXPECT_LE(text.size(), kLimit);
  ASSERT_EQ(text.size() % record(0).size(), 0u) << "a record was cut, or the old ones: " << text.size() << " bytes";
  EXPECT_GT(text.size() + record(0).size(), kLimit) << "whole records that fitted were dropped";
  for (std::size_t i = 0; i < text.size() / record(0).size(); ++i)
    EXPECT_EQ(text.substr(i * record(0).size(), record(0).size()), record(static_cast<int>(i)));
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, AtomicWriteReplacesTheFile) {
  const fs::path dir = fresh_dir("atomic");
  write_file_atomically(dir / "summary.json", "old\n");
  write_file_atomically(dir / "summary.json", "new\n");
  EXPECT_EQ(slurp(dir / "summary.json"), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);  // no temporary left
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, AFailedAtomicWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path dir = fresh_dir("atomic_fail");
  write_file_atomically(dir / "summary.json", "old\n");
  const int code = in_child_with_file_limit(100, [&] {
    try {
      write_file_atomically(dir / "summary.json", std::string(1000, 'x'));
    } catch (const OutputError& e) {
      return std::string(e.what()).find("summary.json") != std::string::npos ? 0 : 2;
    }
    return 1;
  });
  EXPECT_EQ(code, 0);
  EXPECT_EQ(slurp(dir / "summary.json"), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  EXPECT_THROW(write_file_atomically(dir / "no-such-folder" / "x.json", "x"), OutputError);
  fs::remove_all(dir);
}

TEST(SupportCheckedOutput, StandardOutputToAFullDeviceIsAnError) {
  const int code = in_child_with_file_limit(RLIM_INFINITY, [] {
    if (!std::freopen("/dev/full", "w", stdout)) return 3;
    std::cout << "a line that cannot be written\n";
    try {
      finish_standard_output();
    } catch (const OutputError& e) {
      return std::string(e.what()) == "writing to standard output failed: No space left on device" ? 0 : 2;
    }
    return 1;
  });
  EXPECT_EQ(code, 0);
}

TEST(SupportCheckedOutput, StandardOutputThatWorksIsNoError) {
  const fs::path dir = fresh_dir("stdout");
  const int code = in_child_with_file_limit(RLIM_INFINITY, [&] {
    if (!std::freopen((dir / "out.txt").c_str(), "w", stdout)) return 3;
    std::cout << "fine\n";
    std::printf("also fine\n");
    finish_standard_output();
    return 0;
  });
  EXPECT_EQ(code, 0);
  EXPECT_EQ(slurp(dir / "out.txt"), "fine\nalso fine\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::support
