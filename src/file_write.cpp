#include "fixel/internal/file_write.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "fixel/error.h"

namespace fixel::internal {

namespace {

// Writes `path` itself; false if it cannot be opened.
bool write_directly(const std::string& path, const std::string& field, const std::string& shown,
                    const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return false;
  write(out);
  out.flush();  // a full disk shows here, not silently at the stream's end
  if (!out) throw InputError(field, shown, "could not be written completely");
  return true;
}

}  // namespace

void write_file(const std::string& path_given, const std::string& field,
                const std::function<void(std::ostream&)>& write, SpecialFile special) {
  std::error_code ec;
  if (std::filesystem::is_directory(path_given, ec))
    throw InputError(field, path_given, "cannot be written: it is a folder");
  std::string path = path_given;
  if (std::filesystem::is_symlink(path_given, ec)) {
    const auto target = std::filesystem::weakly_canonical(path_given, ec);
    if (!ec) path = target.string();
  }
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    if (special == SpecialFile::kRefuse)
      throw InputError(field, path_given, "cannot be written: it exists and is not a regular file (a FIFO or device)");
    if (!write_directly(path, field, path_given, write)) throw InputError(field, path_given, "cannot be written");
    return;
  }
  const std::string temporary = path + ".fixel-partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(field, path_given, "cannot be written (" + temporary + " cannot be created)");
    try {
      write(out);
      out.flush();
    } catch (...) {
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw InputError(field, path_given, "could not be written completely");
    }
  }
  // The replacement keeps the earlier file's permissions (a read-only or
  // group-shared picture stays so); its owner is the writer's, as on any
  // replacement by rename.
  if (std::filesystem::exists(status)) std::filesystem::permissions(temporary, status.permissions(), ec);
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(field, path_given, "cannot be written: " + ec.message());
  }
}

}  // namespace fixel::internal
