#include "fixel/internal/file_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>

#include "fixel/error.h"

namespace fixel::internal {

namespace fs = std::filesystem;

namespace {

std::string reason_of(int error) { return std::strerror(error); }

// The file a path names after following its symbolic links by their text,
// for a path whose target does not exist yet (a dangling link: its target
// is made, as a shell redirect would). Bounded like the kernel's chain.
fs::path followed_text(const fs::path& given, const std::string& field, const std::string& shown) {
  fs::path path = given;
  std::error_code ec;
  for (int hops = 0; fs::is_symlink(path, ec); ++hops) {
    if (hops == 40) throw InputError(field, shown, "cannot be written: too many levels of symbolic links");
    const fs::path target = fs::read_symlink(path, ec);
    if (ec) break;
    path = target.is_absolute() ? target : path.parent_path() / target;
  }
  return path;
}

// Whether `st` is the file behind descriptor `fd`.
bool same_file(const struct stat& st, int fd) {
  struct stat other {};
  return ::fstat(fd, &other) == 0 && other.st_dev == st.st_dev && other.st_ino == st.st_ino;
}

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

// Writes `text` into the existing `path` itself (truncating it); the
// errno, or 0, and whether it was opened (then its earlier text is gone).
// Without O_CREAT, which protected_regular refuses for another user's file
// in a sticky folder.
int write_in_place(const std::string& path, const std::string& text, bool* opened = nullptr) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (opened != nullptr) *opened = fd >= 0;
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

// A refusal of permission, as opposed to a full disk or another failure:
// only then is FILE itself written in place, as a shell redirect would.
bool refused(int error) { return error == EACCES || error == EPERM || error == EROFS; }

// Where a write of `path_given` goes, found before anything is computed or
// written; throws the errors that need no writing to find.
struct Target {
  fs::path path;  // the file itself, every symbolic link followed
  fs::path folder;
  bool exists = false;
  struct stat st {};
  std::ostream* stream = nullptr;  // fixel's own standard output or error
  bool special = false;            // a FIFO, device or socket: written into, not renamed over
};

Target target_of(const std::string& path_given, const std::string& field, SpecialFile special) {
  if (path_given.empty()) throw InputError(field, "", "cannot be written: the path is empty");
  // "-" is standard input where fixel reads a scene; as an output it would
  // silently become a file named "-".
  if (path_given == "-")
    throw InputError(field, "-",
                     "is not an output file: give a file name (./- for a file named -, /dev/stdout for "
                     "standard output where it is allowed)");
  Target t;
  // The kernel resolves the path (magic links such as /dev/stdout included).
  if (::stat(path_given.c_str(), &t.st) == 0) {
    t.exists = true;
    if (S_ISDIR(t.st.st_mode)) throw InputError(field, path_given, "cannot be written: it is a folder");
    // Whatever the name (/dev/stdout, /dev/fd/1, a link to either), the file
    // behind fixel's own output is written through its stream: reopened, a
    // redirected log would be truncated or replaced.
    if (same_file(t.st, STDOUT_FILENO)) t.stream = &std::cout;
    if (same_file(t.st, STDERR_FILENO)) t.stream = &std::cerr;
    t.special = t.stream != nullptr || !S_ISREG(t.st.st_mode);
    if (t.special && special == SpecialFile::kRefuse)
      throw InputError(field, path_given,
                       t.stream != nullptr ? "cannot be written: it is fixel's own standard output or error"
                                           : "cannot be written: it is not a regular file (a FIFO or device)");
    if (t.special) return t;
    char resolved[PATH_MAX];
    if (::realpath(path_given.c_str(), resolved) == nullptr)
      throw InputError(field, path_given, "cannot be written: " + reason_of(errno));
    t.path = resolved;
  } else if (errno == ELOOP) {
    throw InputError(field, path_given, "cannot be written: too many levels of symbolic links");
  } else if (errno == EACCES) {
    throw InputError(field, path_given, "cannot be written: a folder on its path cannot be searched");
  } else if (errno == ENAMETOOLONG || errno == ENOTDIR) {
    throw InputError(field, path_given, "cannot be written: " + reason_of(errno));
  } else {
    t.path = followed_text(path_given, field, path_given);
  }
  t.folder = t.path.has_parent_path() ? t.path.parent_path() : fs::path(".");
  std::error_code ec;
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

  // The whole text first: an exception from `write` then leaves no file.
  std::ostringstream buffer;
  write(buffer);
  if (!buffer) throw InputError(field, path_given, "could not be written completely");
  const std::string text = buffer.str();

  if (t.stream != nullptr) {
    // The stream keeps no reason; the failed write(2) leaves it in errno.
    errno = 0;
    *t.stream << text;
    t.stream->flush();
    const int error = errno;
    if (!*t.stream)
      throw InputError(
          field, path_given,
          "could not be written completely" + (error != 0 ? " (" + reason_of(error) + ")" : std::string()));
    return;
  }
  if (t.special) {  // nothing there to keep: written into, by the name given (the kernel resolves it)
    const int error = write_in_place(path_given, text);
    if (error != 0) throw InputError(field, path_given, "could not be written completely (" + reason_of(error) + ")");
    return;
  }
  const std::string path = t.path.string();
  // The folder takes no new file (or, in a sticky folder, FILE may not be
  // replaced) but FILE itself may be written: in place, as a shell redirect
  // would. Then no earlier copy is kept, and a failure says so.
  auto in_place = [&](int why) {
    bool opened = false;
    const int error = write_in_place(path, text, &opened);
    if (error == 0) return;
    if (!opened)  // untouched
      throw InputError(
          field, path_given,
          "cannot be written: " + reason_of(error) + " (and the folder refused a new file: " + reason_of(why) + ")");
    throw InputError(field, path_given,
                     "could not be written completely (" + reason_of(error) +
                         "): written in place, since the folder refused a new file (" + reason_of(why) +
                         "), so the earlier file is lost");
  };
  std::string temporary;
  const int fd = make_temporary(t.folder, temporary);
  if (fd < 0) {
    const int error = errno;
    if (t.exists && refused(error)) return in_place(error);
    throw InputError(field, path_given,
                     "cannot be written: " + reason_of(error) + " (making a file in " + t.folder.string() + ")");
  }
  int error = write_all(fd, text);
  // The replacement keeps the earlier file's permissions and group (a
  // group-shared picture stays so, when the writer is in that group); its
  // owner is the writer, as on any replacement by rename.
  if (error == 0 && t.exists) {
    ::fchmod(fd, t.st.st_mode & 07777);
    if (::fchown(fd, static_cast<uid_t>(-1), t.st.st_gid) != 0) {
      // not in that group: the writer's own, as a new file
    }
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    throw InputError(field, path_given, "could not be written completely (" + reason_of(error) + ")");
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    error = errno;
    ::unlink(temporary.c_str());
    // Refused, or FILE is a mount point (a file bind-mounted into a
    // container): it can still be written in place.
    if (t.exists && (refused(error) || error == EBUSY || error == EXDEV)) return in_place(error);
    throw InputError(field, path_given, "cannot be written: " + reason_of(error));
  }
}

void make_output_folder(const std::string& dir, const std::string& field) {
  if (dir == "-") throw InputError(field, dir, "is not an output folder: give a folder name (./- for one named -)");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(field, dir, "cannot be created: " + ec.message());
}

}  // namespace fixel::internal
