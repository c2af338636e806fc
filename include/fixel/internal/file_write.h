#pragma once
// Writing an output file so that a failed write loses nothing: the text
// goes to a temporary file beside it, renamed over the path when complete.

#include <functional>
#include <ostream>
#include <string>

namespace fixel::internal {

/// What to do with a path that exists and is not a regular file (a FIFO, a
/// device such as /dev/stdout): write into it directly (nothing there to
/// keep), or refuse it (a file the caller will read back, as a scene).
enum class SpecialFile { kWriteDirectly, kRefuse };

/// Writes `path` with `write`: into `path.fixel-partial`, renamed over
/// `path` once written and flushed, so that an error (a full disk, an
/// exception from `write`) leaves an earlier file at `path` whole. A
/// symbolic link is written through (its target replaced). Throws
/// InputError(field, path, reason) when it cannot be written: "cannot be
/// written" (a folder; no such folder; the temporary file cannot be
/// created, and then the earlier file is not touched) or "could not be
/// written completely".
void write_file(const std::string& path, const std::string& field, const std::function<void(std::ostream&)>& write,
                SpecialFile special = SpecialFile::kWriteDirectly);

}  // namespace fixel::internal
