#include "fixel/internal/json_exact.h"

#include <exception>
#include <set>
#include <vector>

#include "fixel/error.h"

namespace fixel::internal {

namespace {

using json = nlohmann::json;

// A SAX consumer that builds the DOM itself, so that number_float's raw text
// is kept (the DOM parser would round it to a double) and duplicate keys are
// caught (the DOM parser silently keeps the last one).
class ExactDomBuilder {
 public:
  ExactDomBuilder(std::string source, const std::set<std::string>& text_keys)
      : source_(std::move(source)), text_keys_(text_keys) {}

  bool null() { return put(json(nullptr)); }
  bool boolean(bool v) { return put(json(v)); }
  bool number_integer(json::number_integer_t v) { return number(std::to_string(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return number(std::to_string(v)); }
  bool number_float(json::number_float_t, const json::string_t& raw) { return number(raw); }
  bool string(json::string_t& v) { return put(json(v)); }
  bool binary(json::binary_t&) { return put(json(nullptr)); }
  bool start_object(std::size_t) { return open(json::object()); }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_array() { return close(); }
  bool key(json::string_t& k) {
    auto& keys = keys_.back();
    if (!keys.insert(k).second) defer(ParseError(source_, "key \"" + k + "\"", "appears twice in one object"));
    pending_key_ = k;
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    throw ParseError(source_, "at byte " + std::to_string(position),
                     std::string("is not valid JSON (") + ex.what() + ")");
  }

  // The document, once parsed whole: a syntax error anywhere is reported
  // before the first error of content, which was kept until now.
  json result() {
    if (deferred_) std::rethrow_exception(deferred_);
    return std::move(root_);
  }

 private:
  // A number becomes its text, so a text field must refuse it here: after
  // this "name": 5 and "name": "5" look the same.
  bool number(const std::string& raw) {
    if (stack_.size() == 1 && stack_.back()->is_object() && text_keys_.count(pending_key_) != 0)
      defer(SceneError(pending_key_, raw, "must be a string, not a number"));
    return put(json(raw));
  }
  template <class E>
  void defer(const E& error) {
    if (!deferred_) deferred_ = std::make_exception_ptr(error);
  }
  bool put(json value) {
    if (stack_.empty()) {
      root_ = std::move(value);
    } else if (stack_.back()->is_array()) {
      stack_.back()->push_back(std::move(value));
    } else {
      (*stack_.back())[pending_key_] = std::move(value);
    }
    return true;
  }
  bool open(json container) {
    // Scenes nest at most 5 levels; a deeper document would make the DOM's
    // recursive copy and destruction overflow the stack.
    if (stack_.size() >= kMaxDepth)
      throw ParseError(source_, "depth " + std::to_string(stack_.size() + 1),
                       "nests deeper than " + std::to_string(kMaxDepth) + " levels");
    json* slot;
    if (stack_.empty()) {
      root_ = std::move(container);
      slot = &root_;
    } else if (stack_.back()->is_array()) {
      stack_.back()->push_back(std::move(container));
      slot = &stack_.back()->back();
    } else {
      slot = &((*stack_.back())[pending_key_] = std::move(container));
    }
    stack_.push_back(slot);
    keys_.emplace_back();
    return true;
  }
  bool close() {
    stack_.pop_back();
    keys_.pop_back();
    return true;
  }

  static constexpr std::size_t kMaxDepth = 64;
  std::string source_;
  const std::set<std::string>& text_keys_;
  json root_;
  std::vector<json*> stack_;
  std::vector<std::set<std::string>> keys_;
  std::string pending_key_;
  std::exception_ptr deferred_;
};

}  // namespace

nlohmann::json parse_json_exact(const std::string& text, const std::string& source,
                                const std::set<std::string>& text_keys) {
  ExactDomBuilder builder(source, text_keys);
  // nlohmann's SAX parser keeps its own stack; the builder bounds the depth.
  json::sax_parse(text, &builder, json::input_format_t::json, true, false);
  return builder.result();
}

nlohmann::ordered_json exact_json(const VectorQ& v) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (int k = 0; k < v.size(); ++k) out.push_back(to_string(v[k]));
  return out;
}

}  // namespace fixel::internal
