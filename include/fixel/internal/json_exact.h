#pragma once
// Exact JSON: reading keeps every number's decimal text; writing gives
// exact rationals as "p/q" strings.

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "fixel/rational.h"

namespace fixel::internal {

// Parses JSON text into a DOM in which every number is replaced by a string
// holding its exact source text (so "0.1" and 0.1 read the same). Duplicate
// object keys and malformed text throw ParseError with the position. A
// number given to one of the top-level object's `text_keys` throws
// SceneError naming that key: those fields take text only.
nlohmann::json parse_json_exact(const std::string& text, const std::string& source,
                                const std::set<std::string>& text_keys = {});

// The exact text of every entry, as a JSON array of strings.
nlohmann::ordered_json exact_json(const VectorQ& v);

}  // namespace fixel::internal
