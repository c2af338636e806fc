#include "fixel/error.h"

#include <utility>

namespace fixel {

namespace {
std::string compose(const std::string& field, const std::string& value, const std::string& reason) {
  std::string out = field + ":";
  if (!value.empty()) out += " " + value;
  if (!reason.empty()) out += " " + reason;
  return out;
}
}  // namespace

InputError::InputError(std::string field, std::string value, const std::string& reason)
    : Error(compose(field, value, reason)), field_(std::move(field)), value_(std::move(value)) {}

}  // namespace fixel
