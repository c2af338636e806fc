#pragma once
// Exact JSON: reading keeps every number's decimal text; writing gives
// exact rationals as "p/q" strings.

#include <nlohmann/json.hpp>
#include <string>

#include "fixel/rational.h"

namespace fixel::internal {

// Parses JSON text into a DOM in which every number is replaced by a string
// holding its exact source text (so "0.1" and 0.1 read the same). Duplicate
// object keys and malformed text throw ParseError with the position.
nlohmann::json parse_json_exact(const std::string& text, const std::string& source);

// The exact text of every entry, as a JSON array of strings.
nlohmann::ordered_json exact_json(const VectorQ& v);

}  // namespace fixel::internal
