#include "text.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <cstdio>

namespace fpstereo {
namespace {

// Appends `text` with control characters escaped and, if `quote_too`, quotes and backslashes.
void append_escaped(std::string& out, const std::string& text, bool quote_too) {
  for (const char ch : text) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (quote_too && (c == '\\' || c == '\'')) {
      out += '\\';
      out += ch;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += ch;
    }
  }
}

}  // namespace

std::string trim(const std::string& text) {
  static const char* const kBlank = " \t\r\n";
  const size_t first = text.find_first_not_of(kBlank);
  return first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(kBlank) - first + 1);
}

std::string one_line(const std::string& text) {
  std::string out;
  append_escaped(out, text, false);
  return out;
}

std::string quoted(const std::string& value) {
  std::string out = "'";
  append_escaped(out, value, true);
  return out + "'";
}

std::optional<double> parse_decimal(const std::string& text) {
  size_t i = 0;
  const auto digits = [&] {
    const size_t from = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - from;
  };
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  size_t mantissa = digits();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) return std::nullopt;
  }
  if (i != text.size()) return std::nullopt;
  const double v = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(v) || (v != 0 && !std::isnormal(v))) return std::nullopt;
  return v;
}

std::string fill_template(const std::string& text, const std::map<std::string, std::string>& values) {
  const auto is_name_char = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; };
  std::string out;
  size_t at = 0;
  for (size_t open; (open = text.find('@', at)) != std::string::npos;) {
    size_t end = open + 1;
    while (end < text.size() && is_name_char(text[end])) ++end;
    if (end == open + 1 || end == text.size() || text[end] != '@') {  // not a placeholder
      out.append(text, at, open + 1 - at);
      at = open + 1;
      continue;
    }
    const std::string name = text.substr(open + 1, end - open - 1);
    const auto value = values.find(name);
    if (value == values.end()) throw std::logic_error("template placeholder @" + name + "@ has no value");
    out.append(text, at, open - at);
    out += value->second;
    at = end + 1;
  }
  return out.append(text, at, std::string::npos);
}

}  // namespace fpstereo
