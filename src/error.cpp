#include "fixel/error.h"

#include <utility>

namespace fixel {

namespace {
// A message stays readable whatever the input: an exact value of 10,000
// digits is shown by its ends (InputError::value() keeps all of it). Only
// past 864 bytes: a long file path is shown whole.
// Cuts fall between UTF-8 characters (a continuation byte is 10xxxxxx).
bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

std::string shortened(const std::string& text, std::size_t head, std::size_t tail) {
  if (text.size() <= head + tail + 64) return text;
  std::size_t end = head, start = text.size() - tail;
  while (end > 0 && continuation(text[end])) --end;
  while (start < text.size() && continuation(text[start])) ++start;
  return text.substr(0, end) + "…[" + std::to_string(start - end) + " bytes]…" + text.substr(start);
}

}  // namespace

// Control characters (a newline in a file name) are shown escaped, so a
// message is one line and cannot pass for another.
std::string escape_control(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7F) {
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      static const char digits[] = "0123456789abcdef";
      out += "\\x";
      out += digits[byte >> 4];
      out += digits[byte & 0xF];
    }
  }
  return out;
}

namespace {

std::string compose(const std::string& field, const std::string& value, const std::string& reason) {
  std::string out = escape_control(shortened(field, 200, 40)) + ":";
  if (!value.empty()) out += " " + escape_control(shortened(value, 600, 200));
  if (!reason.empty()) out += " " + escape_control(shortened(reason, 600, 200));
  return out;
}
}  // namespace

InputError::InputError(std::string field, std::string value, const std::string& reason)
    : Error(compose(field, value, reason)), field_(std::move(field)), value_(std::move(value)) {}

}  // namespace fixel
