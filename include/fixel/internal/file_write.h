#pragma once
// Writing an output file so that a failed write loses nothing: the text
// goes to a temporary file beside it, renamed over the path when complete.

#include <functional>
#include <ostream>
#include <string>

namespace fixel::internal {

/// What to do with a path that is not a regular file (a FIFO, a
/// device such as /dev/stdout): write into it directly (nothing there to
/// keep), or refuse it (a file the caller will read back, as a scene).
enum class SpecialFile { kWriteDirectly, kRefuse };

/// Writes `path` with `write`. The whole text is made first, then written
/// to a new file of a fresh name in the same folder (`.fixel-<random>.partial`,
/// created exclusively, so no planted link is followed) and renamed over
/// `path`: an error (a full disk, an exception from `write`) leaves an
/// earlier file at `path` whole and no temporary file. The replacement keeps
/// the earlier file's permissions (and group, when allowed). A symbolic
/// link is written through (its target made or replaced, also when it
/// dangles); a loop is an error. A read-only file is refused. When the
/// folder refuses a new file (or the rename) for lack of permission but the
/// file itself is writable, it is written in place (as a shell redirect
/// would). A path that is not a regular file (a FIFO, a device) is written
/// into directly (or refused); one that is this process's standard output
/// or error, by any name, is written into std::cout or std::cerr. Throws
/// InputError(field, path, reason): "cannot be written: ..." or "could not
/// be written completely (...)".
void write_file(const std::string& path, const std::string& field, const std::function<void(std::ostream&)>& write,
                SpecialFile special = SpecialFile::kWriteDirectly);

/// The checks of write_file that need no writing, and that a new file can
/// be made in the folder: run before a long computation, so that a bad
/// output path is refused first. Throws as write_file does.
void check_writable(const std::string& path, const std::string& field,
                    SpecialFile special = SpecialFile::kWriteDirectly);

/// Makes the folder `dir` (and its parents) for a dump. Throws
/// InputError(field, dir, reason) for "-" (standard input where fixel reads
/// a scene: as a folder it would silently be one named "-") or when the
/// folder cannot be made.
void make_output_folder(const std::string& dir, const std::string& field);

}  // namespace fixel::internal
