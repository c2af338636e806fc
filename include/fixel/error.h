#pragma once
/// @file
/// Typed exceptions. The library never aborts on bad input: it throws one of
/// these, and the message names the offending field and value.

#include <stdexcept>
#include <string>

namespace fixel {

/// Base of every exception fixel throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `text` with its control characters escaped as error messages show them
/// (\n, \t, \r, \xNN; UTF-8 kept), so that a message stays one line.
std::string escape_control(const std::string& text);

/// Bad input: `field` is the JSON path or option name (for example
/// `fixels[1].normal`), `value` the offending value as text, and `what()` is
/// "field: value reason".
class InputError : public Error {
 public:
  InputError(std::string field, std::string value, const std::string& reason);
  const std::string& field() const { return field_; }
  const std::string& value() const { return value_; }

 private:
  std::string field_;
  std::string value_;
};

/// Text that is not an exact number, or malformed JSON.
class ParseError : public InputError {
 public:
  using InputError::InputError;
};

/// A scene that is well formed but physically invalid or degenerate
/// (for example a singular W_n).
class SceneError : public InputError {
 public:
  using InputError::InputError;
};

/// Input that is valid but needs a case fixel does not handle yet.
class UnsupportedError : public InputError {
 public:
  using InputError::InputError;
};

/// A broken internal invariant: a bug in fixel, not a problem with the
/// input. Deliberately not an InputError; the CLI exits 3 on it and asks the
/// user to report it.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace fixel
