#include "fixel/internal/json_approx.h"

#include <regex>
#include <string>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

namespace {

using json = nlohmann::ordered_json;

bool exact_number(const json& v) {
  static const std::regex number(R"(-?[0-9]+(\.[0-9]+)?(/[0-9]+)?)");
  return v.is_string() && std::regex_match(v.get_ref<const std::string&>(), number);
}

// An exact string, or a non-empty array whose leaves are all exact strings.
bool numeric(const json& v) {
  if (exact_number(v)) return true;
  if (!v.is_array() || v.empty()) return false;
  for (const auto& e : v)
    if (!numeric(e)) return false;
  return true;
}

json approx(const json& v) {
  if (v.is_string()) return to_double(parse_rational(v.get<std::string>()));
  json out = json::array();
  for (const auto& e : v) out.push_back(approx(e));
  return out;
}

}  // namespace

void add_approx(json& doc) {
  if (doc.is_array()) {
    for (auto& e : doc) add_approx(e);
    return;
  }
  if (!doc.is_object()) return;
  std::vector<std::pair<std::string, json>> added;
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string& key = it.key();
    if (numeric(it.value())) {
      const bool named = key == "scene" || key == "name" || key == "description";
      if (!named && !doc.contains(key + "_approx") && !doc.contains("approx")) added.push_back({key, approx(*it)});
    } else {
      add_approx(*it);
    }
  }
  // Insert each "<key>_approx" right after its key.
  if (added.empty()) return;
  json out = json::object();
  std::size_t next = 0;
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    out[it.key()] = *it;
    if (next < added.size() && added[next].first == it.key()) out[it.key() + "_approx"] = added[next++].second;
  }
  doc = std::move(out);
}

}  // namespace fixel::internal
