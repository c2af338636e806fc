// internal::write_file: output files are written through a temporary file,
// so that a failed write keeps the earlier file whole.
#include "fixel/internal/file_write.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

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
      EXPECT_EQ(std::string(e.what()), "svg(path): /dev/full could not be written completely");
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

}  // namespace
}  // namespace fixel
