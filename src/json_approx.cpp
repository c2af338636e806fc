#include "fixel/internal/json_approx.h"

#include <string>
#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

namespace {

using json = nlohmann::ordered_json;

// -?digits(.digits)?(/digits)? : the exact number strings fixel writes.
bool exact_number(const json& v) {
  if (!v.is_string()) return false;
  const std::string& t = v.get_ref<const std::string&>();
  std::size_t k = t.size() > 0 && t[0] == '-' ? 1 : 0;
  auto digits = [&] {
    const std::size_t start = k;
    while (k < t.size() && t[k] >= '0' && t[k] <= '9') ++k;
    return k > start;
  };
  if (!digits()) return false;
  if (k < t.size() && t[k] == '.' && (++k, !digits())) return false;
  if (k < t.size() && t[k] == '/' && (++k, !digits())) return false;
  return k == t.size();
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
