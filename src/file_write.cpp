#include "fixel/internal/file_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include "fixel/error.h"

namespace fixel::internal {

namespace fs = std::filesystem;

namespace {

std::string reason_of(int error) { return std::strerror(error); }

// The file a path names after following its symbolic links, also when the
// last link dangles (its target is then created, as a shell redirect
// would). Bounded like the kernel's own limit on a chain of links.
fs::path followed(const fs::path& given) {
  fs::path path = given;
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(path, ec); ++hops) {
    const fs::path target = fs::read_symlink(path, ec);
    if (ec) break;
    path = target.is_absolute() ? target : path.parent_path() / target;
  }
  return path;
}

// A path that opens one of this process's standard streams: written into
// that stream. Reopening it would truncate a redirected log, or write at
// offsets the shell's descriptor does not know.
std::ostream* standard_stream(const std::string& path) {
  if (path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1") return &std::cout;
  if (path == "/dev/stderr" || path == "/dev/fd/2" || path == "/proc/self/fd/2") return &std::cerr;
  return nullptr;
}

bool in_special_tree(const std::string& path) { return path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0; }

// Writes all of `text` to `fd`; the errno of the failure, or 0.
int write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// Writes `text` into `path` itself (truncating it); the errno, or 0.
int write_in_place(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  int error = write_all(fd, text);
  if (::close(fd) != 0 && error == 0) error = errno;
  return error;
}

// A new file in `folder` with a name no one else holds (O_EXCL, never a
// planted link); its descriptor, or -1 with errno set.
int make_temporary(const fs::path& folder, std::string& name) {
  thread_local std::mt19937_64 random{std::random_device{}()};
  for (int attempt = 0; attempt < 64; ++attempt) {
    char suffix[17];
    std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(random()));
    name = (folder / (".fixel-" + std::string(suffix) + ".partial")).string();
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

}  // namespace

namespace {

// Where a write of `path_given` goes, checked before anything is computed
// or written: throws the errors that need no writing to find.
struct Target {
  fs::path path;  // after following symbolic links
  fs::path folder;
  fs::file_status status;
  bool exists = false;
  bool special = false;  // a FIFO, device or stream: written into, not renamed over
};

Target target_of(const std::string& path_given, const std::string& field, SpecialFile special) {
  if (path_given.empty()) throw InputError(field, "", "cannot be written: the path is empty");
  std::error_code ec;
  if (fs::is_directory(path_given, ec)) throw InputError(field, path_given, "cannot be written: it is a folder");
  Target t;
  t.path = followed(path_given);
  t.status = fs::status(t.path, ec);
  t.exists = fs::exists(t.status);
  t.special = (t.exists && !fs::is_regular_file(t.status)) || in_special_tree(path_given) ||
              in_special_tree(t.path.string()) || standard_stream(path_given) != nullptr;
  if (t.special && special == SpecialFile::kRefuse)
    throw InputError(field, path_given, "cannot be written: it is not a regular file (a FIFO, device or stream)");
  if (t.special) return t;
  t.folder = t.path.has_parent_path() ? t.path.parent_path() : fs::path(".");
  if (!fs::is_directory(t.folder, ec))
    throw InputError(field, path_given, "cannot be written: no such folder " + t.folder.string());
  if (t.exists && ::access(t.path.c_str(), W_OK) != 0)
    throw InputError(field, path_given, "cannot be written: it is read-only");
  return t;
}

}  // namespace

void check_writable(const std::string& path_given, const std::string& field, SpecialFile special) {
  const Target t = target_of(path_given, field, special);
  if (!t.special && !t.exists && ::access(t.folder.c_str(), W_OK) != 0)
    throw InputError(field, path_given, "cannot be written: no permission to make a file in " + t.folder.string());
}

void write_file(const std::string& path_given, const std::string& field,
                const std::function<void(std::ostream&)>& write, SpecialFile special) {
  const Target t = target_of(path_given, field, special);
  const fs::path& path = t.path;
  const bool exists = t.exists;
  const auto& status = t.status;

  // The whole text first: an exception from `write` then leaves no file.
  std::ostringstream buffer;
  write(buffer);
  if (!buffer) throw InputError(field, path_given, "could not be written completely");
  const std::string text = buffer.str();

  if (std::ostream* stream = standard_stream(path_given)) {
    *stream << text;
    stream->flush();
    if (!*stream) throw InputError(field, path_given, "could not be written completely");
    return;
  }
  if (t.special) {  // nothing there to keep: written into
    const int error = write_in_place(path.string(), text);
    if (error != 0) throw InputError(field, path_given, "could not be written completely (" + reason_of(error) + ")");
    return;
  }
  const fs::path& folder = t.folder;
  std::string temporary;
  const int fd = make_temporary(folder, temporary);
  if (fd < 0) {
    const int error = errno;
    // The folder takes no new file, but the file itself may be written:
    // in place, as a shell redirect would (no earlier copy is kept then).
    if (exists && write_in_place(path.string(), text) == 0) return;
    throw InputError(field, path_given,
                     "cannot be written: " + reason_of(error) + " (in folder " + folder.string() + ")");
  }
  int error = write_all(fd, text);
  // The replacement keeps the earlier file's permissions (a group-shared
  // picture stays so); its owner is the writer, as on any rename.
  if (error == 0 && exists) ::fchmod(fd, static_cast<mode_t>(status.permissions()) & 07777);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    throw InputError(field, path_given, "could not be written completely (" + reason_of(error) + ")");
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    error = errno;
    ::unlink(temporary.c_str());
    throw InputError(field, path_given, "cannot be written: " + reason_of(error));
  }
}

}  // namespace fixel::internal
