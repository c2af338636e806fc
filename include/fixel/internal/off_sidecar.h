#pragma once
// `fixel dump` writes each polytope as a standard OFF file (nothing but the
// header, the counts, the vertices and the faces) and its metadata as a
// sidecar JSON file beside it: X.off and X.json (docs/formats.md).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fixel/cone.h"

namespace fixel::internal {

/// The sidecar's path for an OFF path: the same stem with ".json".
std::string sidecar_path(const std::string& off_path);

/// Writes ∩ halfspaces to `off_path` (write_polytope_off) and `meta`, with
/// "format", "off" (the OFF file's name), "vertices" and "dimension" (of the
/// drawn polytope) added first, to the sidecar. `field` names the caller in
/// errors (e.g. "dump_off(directory)"). Returns {off_path, sidecar path}.
/// Throws InputError if a file cannot be written.
std::vector<std::string> write_off_with_sidecar(const std::string& off_path, const std::vector<Halfspace>& halfspaces,
                                                int dim, const nlohmann::ordered_json& meta, const std::string& field);

}  // namespace fixel::internal
