// internal::write_file: output files are written through a temporary file,
// so that a failed write keeps the earlier file whole.
#include "fixel/internal/file_write.h"

#include <grp.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "fixel/error.h"

namespace fixel {
namespace {

namespace fs = std::filesystem;
using internal::check_writable;
using internal::SpecialFile;
using internal::write_file;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string folder(const std::string& name) {
  const std::string dir = testing::TempDir() + "fixel_file_write_" + name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void text(std::ostream& out) { out << "new\n"; }

GTEST_TEST(WriteFile, WritesTheTextAndLeavesNoTemporaryFile) {
  const std::string dir = folder("plain");
  write_file(dir + "/a.svg", "svg(path)", text);
  EXPECT_EQ(read(dir + "/a.svg"), "new\n");
  EXPECT_FALSE(fs::exists(dir + "/a.svg.fixel-partial"));
}

// The writer fails half-way (as a full disk or an exception does): the
// earlier file is still there, whole, and the half-written one is gone.
GTEST_TEST(WriteFile, AWriteThatFailsHalfWayKeepsTheEarlierFileWhole) {
  const std::string dir = folder("fails");
  const std::string path = dir + "/a.svg";
  std::ofstream(path) << "earlier\n";
  EXPECT_THROW(write_file(path, "svg(path)",
                          [](std::ostream& out) {
                            out << "half";
                            throw std::runtime_error("the writer failed");
                          }),
               std::runtime_error);
  EXPECT_EQ(read(path), "earlier\n");
  EXPECT_FALSE(fs::exists(path + ".fixel-partial"));
  EXPECT_THROW(write_file(path, "svg(path)", [](std::ostream& out) { out.setstate(std::ios::badbit); }), InputError);
  EXPECT_EQ(read(path), "earlier\n");
  EXPECT_FALSE(fs::exists(path + ".fixel-partial"));
}

GTEST_TEST(WriteFile, ARewrittenFileKeepsItsEarlierPermissions) {
  const std::string dir = folder("mode");
  const std::string path = dir + "/a.svg";
  std::ofstream(path) << "earlier\n";
  const auto mode = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::group_write;
  fs::permissions(path, mode);
  write_file(path, "svg(path)", text);
  EXPECT_EQ(read(path), "new\n");
  EXPECT_EQ(fs::status(path).permissions(), mode);
}

GTEST_TEST(WriteFile, ASymbolicLinkIsWrittenThroughAndStaysALink) {
  const std::string dir = folder("link");
  std::ofstream(dir + "/target.svg") << "earlier\n";
  fs::create_symlink(dir + "/target.svg", dir + "/link.svg");
  write_file(dir + "/link.svg", "svg(path)", text);
  EXPECT_TRUE(fs::is_symlink(dir + "/link.svg"));
  EXPECT_EQ(read(dir + "/target.svg"), "new\n");
}

GTEST_TEST(WriteFile, AFolderIsAnInputErrorNamingTheFieldAndThePath) {
  const std::string dir = folder("folder");
  try {
    write_file(dir, "svg(path)", text);
    ADD_FAILURE() << "a folder was written";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "svg(path)");
    EXPECT_EQ(std::string(e.what()), "svg(path): " + dir + " cannot be written: it is a folder");
  }
  EXPECT_THROW(write_file(dir + "/no such folder/a.svg", "svg(path)", text), InputError);
}

// A device or FIFO has nothing to keep: written into directly (a full
// device is then reported), unless the caller refuses them (a scene file,
// which is read back).
GTEST_TEST(WriteFile, ADeviceOrFifoIsWrittenDirectlyOrRefused) {
  if (fs::exists("/dev/full")) {
    try {
      write_file("/dev/full", "svg(path)", text);
      ADD_FAILURE() << "/dev/full took the text";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "svg(path): /dev/full could not be written completely (No space left on device)");
    }
  }
  const std::string fifo = folder("fifo") + "/pipe";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(write_file(fifo, "save_scene(path)", text, SpecialFile::kRefuse), InputError);
  std::string got;
  std::thread reader([&] { got = read(fifo); });
  write_file(fifo, "svg(path)", text);
  reader.join();
  EXPECT_EQ(got, "new\n");
  EXPECT_TRUE(fs::is_fifo(fifo));  // not replaced by a regular file
}

// No file other than the one named is touched: the temporary file has a
// fresh name made with O_EXCL, so a link planted under the old fixed name
// (FILE.fixel-partial) or any predictable one redirects nothing.
GTEST_TEST(WriteFile, APlantedLinkBesideTheFileRedirectsNothingAndNoTemporaryIsLeft) {
  const std::string dir = folder("planted");
  std::ofstream(dir + "/victim") << "victim\n";
  fs::create_symlink(dir + "/victim", dir + "/a.svg.fixel-partial");
  write_file(dir + "/a.svg", "svg(path)", text);
  EXPECT_EQ(read(dir + "/a.svg"), "new\n");
  EXPECT_FALSE(fs::is_symlink(dir + "/a.svg"));
  EXPECT_EQ(read(dir + "/victim"), "victim\n");
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename().string().rfind(".fixel-", 0) == 0;
  EXPECT_EQ(entries, 0);
}

GTEST_TEST(WriteFile, ANameOfTheLongestLegalLengthIsWrittenAndALongerOneRefusedBeforeWriting) {
  const std::string dir = folder("long");
  const std::string name = dir + "/" + std::string(250, 'b');  // NAME_MAX is 255
  write_file(name, "svg(path)", text);
  EXPECT_EQ(read(name), "new\n");
  const std::string too_long = dir + "/" + std::string(300, 'b');
  for (int early = 0; early < 2; ++early) {
    try {
      bool written = false;
      if (early)
        check_writable(too_long, "svg(path)");  // the command line's check before computing
      else
        write_file(too_long, "svg(path)", [&](std::ostream& out) {
          written = true;
          out << "new\n";
        });
      ADD_FAILURE() << "a 300-byte name was accepted" << (written ? " and written" : "");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot be written: File name too long"), std::string::npos) << e.what();
    }
  }
}

// As a shell redirect does: the link's target is created, the link kept.
GTEST_TEST(WriteFile, ADanglingLinkIsWrittenThroughToItsNewTarget) {
  const std::string dir = folder("dangling");
  fs::create_symlink("target.svg", dir + "/link.svg");  // relative to the link's folder
  write_file(dir + "/link.svg", "svg(path)", text);
  EXPECT_TRUE(fs::is_symlink(dir + "/link.svg"));
  EXPECT_EQ(read(dir + "/target.svg"), "new\n");
  fs::create_symlink("nowhere/t.svg", dir + "/lost.svg");
  try {
    write_file(dir + "/lost.svg", "svg(path)", text);
    ADD_FAILURE() << "a link into a missing folder was written";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "svg(path): " + dir + "/lost.svg cannot be written: no such folder " + dir + "/nowhere");
  }
}

// /dev/stdout is this process's standard output, whatever it is redirected
// to: written into the stream, never reopened (which would truncate a log
// that `>>` appends to, or replace the file `>` made).
GTEST_TEST(WriteFile, StandardOutputIsWrittenIntoTheStreamItself) {
  testing::internal::CaptureStdout();
  std::cout << "before\n";
  write_file("/dev/stdout", "svg(path)", text);
  std::cout << "after\n";
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "before\nnew\nafter\n");
  EXPECT_THROW(write_file("/dev/stdout", "save_scene(path)", text, SpecialFile::kRefuse), InputError);
}

// Runs `f` as an unprivileged user when this is root (root may write any
// file); its exit status, or kCannotRun when that user cannot be taken or
// cannot reach `dir` (a private TMPDIR, an unmapped uid).
constexpr int kCannotRun = 77;
template <typename F>
int as_unprivileged(const std::string& dir, F f) {
  const pid_t pid = fork();
  if (pid < 0) return kCannotRun;
  if (pid == 0) {
    if (geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(65534) != 0 || setuid(65534) != 0)) _exit(kCannotRun);
    if (access(dir.c_str(), X_OK) != 0) _exit(kCannotRun);
    _exit(f());
  }
  int status = -1;
  if (waitpid(pid, &status, 0) != pid) return kCannotRun;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 101;
}

// A read-only file is refused, as the command line's early check refuses
// it; a writable file in a folder that takes no new file is written in
// place, as a shell redirect would write it.
GTEST_TEST(WriteFile, AReadOnlyFileIsRefusedAndAWritableOneInAReadOnlyFolderIsWrittenInPlace) {
  const std::string dir = folder("modes");
  fs::permissions(dir, fs::perms::all);
  const std::string read_only = dir + "/ro.svg";
  std::ofstream(read_only) << "keep\n";
  fs::permissions(read_only, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const int refused = as_unprivileged(dir, [&] {
    try {
      write_file(read_only, "svg(path)", text);
      return 1;
    } catch (const InputError& e) {
      return std::string(e.what()) == "svg(path): " + read_only + " cannot be written: it is read-only" ? 0 : 2;
    }
  });
  if (refused == kCannotRun) GTEST_SKIP() << "cannot run as another user that reaches " << dir;
  EXPECT_EQ(refused, 0);
  EXPECT_EQ(read(read_only), "keep\n");

  const std::string locked = dir + "/locked";
  fs::create_directories(locked);
  const std::string writable = locked + "/w.svg";
  std::ofstream(writable) << "earlier\n";
  fs::permissions(writable, fs::perms::all);
  // No one may make a file in it, its owner included (so the in-place path
  // runs also when this test is not root).
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  const int written = as_unprivileged(dir, [&] {
    try {
      write_file(writable, "svg(path)", text);
      return 0;
    } catch (const InputError&) {
      return 1;
    }
  });
  EXPECT_EQ(written, 0);
  EXPECT_EQ(read(writable), "new\n");
  int temporaries = 0;
  for (const auto& e : fs::directory_iterator(locked)) temporaries += e.path().filename().string() != "w.svg";
  EXPECT_EQ(temporaries, 0);
  fs::permissions(locked, fs::perms::all);
}

// In a sticky folder (as /tmp) another user's writable file may be written
// but not replaced: the rename is refused, so it is written in place, as a
// shell redirect writes it (it was an error after the whole computation).
GTEST_TEST(WriteFile, AnotherUsersWritableFileInAStickyFolderIsWrittenInPlace) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root, to own a file another user then writes";
  const std::string dir = folder("sticky");
  fs::permissions(dir, fs::perms::all | fs::perms::sticky_bit);
  const std::string shared = dir + "/shared.svg";
  std::ofstream(shared) << "earlier\n";
  fs::permissions(shared, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                              fs::perms::group_write | fs::perms::others_read | fs::perms::others_write);
  const int written = as_unprivileged(dir, [&] {
    try {
      check_writable(shared, "svg(path)");    // the early check lets it through ...
      write_file(shared, "svg(path)", text);  // ... and the write succeeds
      return 0;
    } catch (const InputError&) {
      return 1;
    }
  });
  if (written == kCannotRun) GTEST_SKIP() << "cannot run as another user that reaches " << dir;
  EXPECT_EQ(written, 0);
  EXPECT_EQ(read(shared), "new\n");
}

// /dev/stdout under any name (a link to it, /dev//stdout) is fixel's own
// output: written into its stream, never reopened or replaced.
GTEST_TEST(WriteFile, StandardOutputUnderAnyNameIsWrittenIntoTheStream) {
  const std::string dir = folder("stdout_names");
  fs::create_symlink("/dev/stdout", dir + "/to_stdout");
  for (const std::string& name : {dir + "/to_stdout", std::string("/dev//stdout"), std::string("/dev/fd/1")}) {
    testing::internal::CaptureStdout();
    std::cout << "before\n";
    write_file(name, "svg(path)", text);
    std::cout << "after\n";
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "before\nnew\nafter\n") << name;
  }
  EXPECT_TRUE(fs::is_symlink(dir + "/to_stdout"));  // not replaced by a file
}

// As a shell says: a loop of links is an error, not replaced by a file.
GTEST_TEST(WriteFile, ALoopOfSymbolicLinksIsAnErrorAndStaysALoop) {
  const std::string dir = folder("loop");
  fs::create_symlink(dir + "/b", dir + "/a");
  fs::create_symlink(dir + "/a", dir + "/b");
  try {
    write_file(dir + "/a", "svg(path)", text);
    ADD_FAILURE() << "a loop of links was written";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "svg(path): " + dir + "/a cannot be written: too many levels of symbolic links");
  }
  EXPECT_TRUE(fs::is_symlink(dir + "/a") && fs::is_symlink(dir + "/b"));
}

// A regular file is written by rename wherever it lives, /dev/shm included
// (only a path that is not a regular file is written into directly).
GTEST_TEST(WriteFile, ARegularFileUnderDevIsARegularFile) {
  if (!fs::is_directory("/dev/shm") || access("/dev/shm", W_OK) != 0) GTEST_SKIP() << "no writable /dev/shm";
  const std::string path = "/dev/shm/fixel_file_write_test_" + std::to_string(getpid()) + ".json";
  write_file(path, "save_scene(path)", text, SpecialFile::kRefuse);
  EXPECT_EQ(read(path), "new\n");
  fs::remove(path);
}

}  // namespace
}  // namespace fixel
