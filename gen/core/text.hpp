// Quoting user input in messages: every error is one line, whatever the input holds; and the
// small text tests the tools share.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>

namespace fpstereo {

// `text` with control characters escaped (\n, \r, \t, \x01, ...) and nothing else changed: the
// last guard of the one-line rule, applied to every message printed on stderr.
std::string one_line(const std::string& text);

// 'value' escaped as one_line does, plus quotes and backslashes, so a value or path stays readable
// and unambiguous whatever it holds.
std::string quoted(const std::string& value);
// For a non-const std::string, argument-dependent lookup would otherwise pick std::quoted (a
// better match), which escapes no control characters.
inline std::string quoted(std::string& value) { return quoted(std::as_const(value)); }

// `text` without the spaces, tabs and line ends around it.
std::string trim(const std::string& text);

// Whether `text` ends with `suffix` (a file name's extension, say).
inline bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A decimal number as people write it, [+-]digits[.digits][(e|E)[+-]digits], finite and not
// subnormal; nullopt for anything else (hex, inf, nan, surrounding spaces, 1e-310, 1e999).
std::optional<double> parse_decimal(const std::string& text);

// An embedded template (hls/templates, constraints/templates) filled in: each @NAME@ (capitals,
// digits, underscores) replaced by values.at(NAME) in one pass, so a value's own text is never
// searched again. Throws std::logic_error naming a @NAME@ without a value: a template and its
// emitter disagree. Any other '@' is copied as it is.
std::string fill_template(const std::string& text, const std::map<std::string, std::string>& values);

}  // namespace fpstereo
