#pragma once
// Every exact number of a report gets a double beside it: for a key whose
// value is an exact string "p/q" (or an array, or nested arrays, of them),
// adds "<key>_approx" with the nearest doubles. Display only.

#include <nlohmann/json.hpp>

namespace fixel::internal {

void add_approx(nlohmann::ordered_json& doc);

}  // namespace fixel::internal
