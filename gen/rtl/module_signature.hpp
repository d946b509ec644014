// The interface of a building block of rtl_templates/, read from its own declaration: its
// parameters with their defaults and its ports with their directions and widths. The core builder
// (core_builder.hpp) connects instances by it and checks every connection's width, so the
// templates stay the one place that says what a port is.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fpstereo::rtl {

struct PortSignature {
  std::string name;
  bool input = true;
  // The port's width as the Verilog expression of its range [msb:0] plus one; "" for one bit.
  std::string msb;
};

struct ModuleSignature {
  std::string name;
  std::vector<std::pair<std::string, std::string>> parameters;  // name, default expression
  std::vector<PortSignature> ports;
  const PortSignature* port(const std::string& name) const;
};

// Parses `module NAME #(parameter ...) (input wire [..] ..., ...);` (ANSI ports, one a line, as the
// templates write them). Throws std::logic_error naming the module if it cannot.
ModuleSignature parse_module_signature(const std::string& verilog);

// The signature of the embedded template `module` (parsed once).
const ModuleSignature& template_signature(const std::string& module);

// The top-level items of a comma-separated Verilog list (parameters, ports, a concatenation's
// parts), trimmed; commas inside parentheses, brackets and braces do not separate.
std::vector<std::string> verilog_list_items(const std::string& list);

// Integer value of a constant Verilog expression over named values: decimal and sized literals,
// + - * / % ** << >>, comparisons, && || !, ?: and $clog2. nullopt when it names an unknown value
// or is not such an expression.
std::optional<int64_t> evaluate_constant(const std::string& expression, const std::map<std::string, int64_t>& values);

// The port widths of an instance of `signature` with the given parameter values (the others at
// their defaults), by port name; a width is absent where it cannot be evaluated.
std::map<std::string, int64_t> port_widths(const ModuleSignature& signature,
                                           const std::vector<std::pair<std::string, std::string>>& parameters);

}  // namespace fpstereo::rtl
