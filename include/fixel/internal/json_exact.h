#pragma once
// Exact JSON reading: numbers keep their decimal text.

#include <nlohmann/json.hpp>
#include <string>

namespace fixel::internal {

// Parses JSON text into a DOM in which every number is replaced by a string
// holding its exact source text (so "0.1" and 0.1 read the same). Duplicate
// object keys and malformed text throw ParseError with the position.
nlohmann::json parse_json_exact(const std::string& text, const std::string& source);

}  // namespace fixel::internal
