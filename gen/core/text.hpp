// Quoting user input in messages: every error is one line, whatever the input holds.
#pragma once

#include <string>

namespace fpstereo {

// 'value' with control characters, quotes and backslashes escaped (\n, \t, \x01, ...), so a
// value or path holding a newline cannot break the one-line rule of error messages.
std::string quoted(const std::string& value);

}  // namespace fpstereo
