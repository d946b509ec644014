#include "text.hpp"

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

}  // namespace fpstereo
