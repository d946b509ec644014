// A Verilog module built from typed nets (docs/contributing.md, "The core builder"): each stage
// declares the nets it drives, with their widths, and instantiates templates whose ports the
// builder reads from the templates themselves (module_signature.hpp). A port without a connection
// of its own connects to the net of its name. When the module is written the builder checks that
// every net has one driver, that nothing reads a net no one drives, and that every connection's
// width is the port's, and fails with one line naming the net and the stages; it writes the wire
// declarations and the lint waivers for nets the configuration leaves unread.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fpstereo::rtl {

struct ModuleSignature;

// Named values: an instance's parameters or its port connections (port, Verilog expression).
using Connections = std::vector<std::pair<std::string, std::string>>;
inline Connections operator+(Connections a, const Connections& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
// A parameter's value.
inline std::string num(int64_t v) { return std::to_string(v); }

struct NetDeclaration {
  std::string name;
  int64_t bits = 1;
  bool is_signed = false;
};

class CoreBuilder {
 public:
  // The stage whose nets, logic and instances follow; errors name it.
  void stage(const std::string& title);
  // The module's ports, which are nets too: an input is driven from outside, an output is read.
  // A comment given goes on the line above.
  void input(const std::string& name, int64_t bits, const std::string& comment = "");
  void output(const std::string& name, int64_t bits, const std::string& comment = "");
  // Lines written as they are above the next port (comments, attributes).
  void port_text(const std::string& verilog);
  // Text between the items: comments, localparams.
  void text(const std::string& verilog);
  // A wire declared here; an instance's output or logic() drives it.
  void wire(const std::string& name, int64_t bits, bool is_signed = false);
  // Hand-written logic that assigns the declared nets `assigns` and declares and drives `regs`;
  // the nets it reads are found by name in its text.
  void logic(const std::string& verilog, const std::vector<std::string>& assigns,
             const std::vector<NetDeclaration>& regs = {});
  // An instance of a template; every port not in `connections` connects to the net of its name.
  void instance(const std::string& module, const std::string& name, const Connections& parameters,
                const Connections& connections = {});
  // The same for a module of the design's own, by its signature (the top's core).
  void instance(const ModuleSignature& module, const std::string& name, const Connections& parameters,
                const Connections& connections = {});

  // Checks the nets (throws std::logic_error, one line) and writes the module: its header, the
  // port list, then the items in the order they were added.
  std::string module_text(const std::string& name) const;

 private:
  struct Item {
    enum Kind { Text, Wire, Logic, Instance } kind = Text;
    std::string stage, text;  // Text and Logic: the Verilog; Wire: the net's name
    std::vector<std::string> assigns;
    std::vector<NetDeclaration> regs;
    std::string module, name;
    Connections parameters, connections;
    const ModuleSignature* signature = nullptr;  // a module not among the templates
  };
  struct Port {
    NetDeclaration net;
    bool input;
    std::string text;  // written above the port
  };
  Item& add(Item::Kind kind, const std::string& text);
  std::string stage_ = "core", port_text_;
  std::vector<Port> ports_;
  std::vector<Item> items_;
};

}  // namespace fpstereo::rtl
