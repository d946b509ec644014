#include "core_builder.hpp"

#include <fmt/core.h>

#include <optional>
#include <regex>
#include <set>
#include <stdexcept>

#include "module_signature.hpp"
#include "text.hpp"

namespace fpstereo::rtl {
namespace {

// `module #(.P(v), ...) name (.port(signal), ...);`, wrapped at about 110 columns.
std::string instance_text(const std::string& module, const std::string& name, const Connections& parameters,
                          const Connections& ports) {
  auto list = [](const Connections& values, const std::string& indent) {
    std::string text, line = indent;
    for (size_t i = 0; i < values.size(); ++i) {
      const std::string item =
          fmt::format(".{}({}){}", values[i].first, values[i].second, i + 1 < values.size() ? "," : "");
      if (line.size() > indent.size() && line.size() + item.size() + 1 > 110) {
        text += line + "\n";
        line = indent;
      }
      line += (line.size() > indent.size() ? " " : "") + item;
    }
    return text + line;
  };
  std::string text = "  " + module;
  if (!parameters.empty()) text += " #(\n" + list(parameters, "    ") + "\n  )";
  return text + " " + name + " (\n" + list(ports, "    ") + ");\n";
}

std::string range(int64_t bits) { return bits > 1 ? fmt::format("[{}:0] ", bits - 1) : ""; }

// Whether text[0] opens a brace that closes at its last character.
bool one_concatenation(const std::string& text) {
  if (text.size() < 2 || text.front() != '{' || text.back() != '}') return false;
  int depth = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    depth += text[i] == '{' ? 1 : text[i] == '}' ? -1 : 0;
    if (depth == 0 && i + 1 < text.size()) return false;
  }
  return true;
}

// The Verilog of an expression without its comments and literals, for finding the names it reads.
std::string names_only(const std::string& verilog) {
  static const std::regex noise(R"(//[^\n]*|/\*[\s\S]*?\*/|\d+\s*'\s*[sS]?[dDbBhHoO]\s*[0-9a-fA-FxXzZ_]+)");
  return std::regex_replace(verilog, noise, " ");
}

}  // namespace

void CoreBuilder::stage(const std::string& title) { stage_ = title; }

void CoreBuilder::port_text(const std::string& verilog) { port_text_ += verilog; }

void CoreBuilder::input(const std::string& name, int64_t bits, const std::string& comment) {
  port_text_ += comment.empty() ? "" : "  // " + comment + "\n";
  ports_.push_back(Port{NetDeclaration{name, bits, false}, true, port_text_});
  port_text_.clear();
}
void CoreBuilder::output(const std::string& name, int64_t bits, const std::string& comment) {
  port_text_ += comment.empty() ? "" : "  // " + comment + "\n";
  ports_.push_back(Port{NetDeclaration{name, bits, false}, false, port_text_});
  port_text_.clear();
}

CoreBuilder::Item& CoreBuilder::add(Item::Kind kind, const std::string& text) {
  items_.emplace_back();
  Item& item = items_.back();
  item.kind = kind;
  item.stage = stage_;
  item.text = text;
  return item;
}

void CoreBuilder::text(const std::string& verilog) { add(Item::Text, verilog); }

void CoreBuilder::wire(const std::string& name, int64_t bits, bool is_signed) {
  add(Item::Wire, name).regs = {NetDeclaration{name, bits, is_signed}};
}

void CoreBuilder::logic(const std::string& verilog, const std::vector<std::string>& assigns,
                        const std::vector<NetDeclaration>& regs) {
  Item& item = add(Item::Logic, verilog);
  item.assigns = assigns;
  item.regs = regs;
}

void CoreBuilder::instance(const std::string& module, const std::string& name, const Connections& parameters,
                           const Connections& connections) {
  Item& item = add(Item::Instance, "");
  item.module = module;
  item.name = name;
  item.parameters = parameters;
  item.connections = connections;
}

void CoreBuilder::instance(const ModuleSignature& module, const std::string& name, const Connections& parameters,
                           const Connections& connections) {
  instance(module.name, name, parameters, connections);
  items_.back().signature = &module;
}

namespace {

// What the builder knows of a net: its declaration and who drives and reads it.
struct NetUse {
  NetDeclaration declaration;
  std::string declared_by;
  std::vector<std::string> drivers;  // "stage S (instance I, port P)"
  std::string first_reader;
  bool read_whole = false, read_in_part = false;
};

// One part of a connection: a net (whole or a part-select) or a constant, with its width.
struct Reference {
  std::string net;  // empty for a constant
  bool partial = false;
  std::optional<int64_t> bits;
  bool in_expression = false;  // read by an operator, so not something a port can drive
};

class NetTable {
 public:
  void declare(const NetDeclaration& net, const std::string& by) {
    NetUse use;
    use.declaration = net;
    use.declared_by = by;
    const auto [it, fresh] = nets_.emplace(net.name, use);
    if (!fresh)
      throw std::logic_error(fmt::format("net {}: declared twice, by {} and by {}", net.name,
                                         it->second.declared_by, by));
    order_.push_back(net.name);
  }
  bool has(const std::string& name) const { return nets_.count(name) != 0; }
  NetUse& at(const std::string& name, const std::string& who) {
    const auto it = nets_.find(name);
    if (it == nets_.end()) throw std::logic_error(fmt::format("net {}: used by {} but never declared", name, who));
    return it->second;
  }
  const NetUse& at(const std::string& name) const { return nets_.at(name); }
  void drive(const std::string& name, const std::string& who) { at(name, who).drivers.push_back(who); }
  void read(const std::string& name, bool partial, const std::string& who) {
    NetUse& n = at(name, who);
    if (n.first_reader.empty()) n.first_reader = who;
    (partial ? n.read_in_part : n.read_whole) = true;
  }
  // The parts of a connection's expression; a part that is no net, part-select or sized constant
  // is an expression whose names are read whole and whose width is not known.
  std::vector<Reference> references(const std::string& expression, const std::string& who) const {
    static const std::regex identifier(R"(^[A-Za-z_]\w*$)"), select(R"(^([A-Za-z_]\w*)\s*\[\s*(\d+)\s*(?::\s*(\d+)\s*)?\]$)"),
        constant(R"(^(\d+)\s*'\s*[dDbBhHoO]\s*[0-9a-fA-F_]+$)");
    const std::string e = trim(expression);
    if (one_concatenation(e)) {
      std::vector<Reference> out;
      for (const auto& part : verilog_list_items(e.substr(1, e.size() - 2)))
        for (const auto& r : references(part, who)) out.push_back(r);
      return out;
    }
    std::smatch m;
    if (std::regex_match(e, m, identifier) && has(e)) return {{e, false, at(e).declaration.bits}};
    if (std::regex_match(e, m, identifier)) throw std::logic_error(fmt::format("net {}: connected but never declared", e));
    if (std::regex_match(e, m, select)) {
      const int64_t hi = std::stoll(m[2]), lo = m[3].matched ? std::stoll(m[3]) : hi;
      const std::string net = m[1];
      if (has(net) && (hi < lo || hi >= at(net).declaration.bits))
        throw std::logic_error(fmt::format("net {}: {} reads `{}`, outside its {} bits", net, who, e,
                                           at(net).declaration.bits));
      return {{net, true, hi - lo + 1}};
    }
    if (std::regex_match(e, m, constant)) return {{"", false, std::stoll(m[1])}};
    std::vector<Reference> out;
    const std::string names = names_only(e);
    static const std::regex word(R"([A-Za-z_$][\w$]*)");
    for (auto it = std::sregex_iterator(names.begin(), names.end(), word); it != std::sregex_iterator(); ++it)
      if (has(it->str())) out.push_back({it->str(), false, std::nullopt, true});
    if (out.empty()) out.push_back({"", false, std::nullopt, true});
    return out;
  }
  const std::vector<std::string>& order() const { return order_; }

 private:
  std::map<std::string, NetUse> nets_;
  std::vector<std::string> order_;
};

std::optional<int64_t> total_bits(const std::vector<Reference>& refs) {
  int64_t bits = 0;
  for (const auto& r : refs) {
    if (!r.bits) return std::nullopt;
    bits += *r.bits;
  }
  return bits;
}

}  // namespace

std::string CoreBuilder::module_text(const std::string& name) const {
  NetTable nets;
  const std::string outside = "the module's ports";
  for (const auto& p : ports_) {
    nets.declare(p.net, outside);
    if (p.input) nets.drive(p.net.name, outside);
  }
  for (const auto& item : items_)
    for (const auto& r : item.regs) nets.declare(r, "stage " + item.stage);

  // Each instance's connections in its template's port order, the same-named nets filled in.
  std::vector<Connections> resolved(items_.size());
  for (size_t i = 0; i < items_.size(); ++i) {
    const Item& item = items_[i];
    if (item.kind == Item::Logic) {
      const std::string who = "stage " + item.stage;
      for (const auto& a : item.assigns) nets.drive(a, who);
      std::set<std::string> own(item.assigns.begin(), item.assigns.end());
      for (const auto& r : item.regs) {
        nets.drive(r.name, who);
        own.insert(r.name);
      }
      const std::string names = names_only(item.text);
      static const std::regex word(R"(([A-Za-z_]\w*)(\s*\[)?)");
      for (auto it = std::sregex_iterator(names.begin(), names.end(), word); it != std::sregex_iterator(); ++it) {
        const std::string n = (*it)[1];
        if (nets.has(n) && !own.count(n)) nets.read(n, (*it)[2].matched, who);
      }
      continue;
    }
    if (item.kind != Item::Instance) continue;
    const ModuleSignature& signature = item.signature ? *item.signature : template_signature(item.module);
    const auto widths = port_widths(signature, item.parameters);
    for (const auto& [port, expression] : item.connections)
      if (!signature.port(port))
        throw std::logic_error(fmt::format("instance {} (stage {}): {} has no port {}", item.name, item.stage,
                                           item.module, port));
    for (const auto& port : signature.ports) {
      std::string expression;
      for (const auto& [p, e] : item.connections)
        if (p == port.name) expression = e;
      const std::string who = fmt::format("stage {} (instance {}, port {})", item.stage, item.name, port.name);
      if (expression.empty()) {
        if (!nets.has(port.name))
          throw std::logic_error(fmt::format("instance {} (stage {}): port {} is not connected and no net has its name",
                                             item.name, item.stage, port.name));
        expression = port.name;
      }
      resolved[i].push_back({port.name, expression});
      const auto refs = nets.references(expression, who);
      for (const auto& r : refs) {
        if (r.net.empty()) continue;
        if (!port.input && (r.partial || r.in_expression))
          throw std::logic_error(fmt::format("net {}: {} drives `{}`, not the whole net", r.net, who, expression));
        if (port.input) nets.read(r.net, r.partial, who);
        else nets.drive(r.net, who);
      }
      const auto bits = total_bits(refs);
      const auto port_bits = widths.find(port.name);
      if (bits && port_bits != widths.end() && *bits != port_bits->second) {
        const std::string net = refs.size() == 1 && !refs.front().net.empty() ? refs.front().net : expression;
        throw std::logic_error(fmt::format("net {}: {} bits, but {} is {} bits", net, *bits, who, port_bits->second));
      }
    }
  }
  for (const auto& p : ports_)
    if (!p.input) nets.read(p.net.name, false, outside);

  // One driver each; nothing read or declared without one.
  for (const auto& n : nets.order()) {
    const NetUse& use = nets.at(n);
    if (use.drivers.size() > 1)
      throw std::logic_error(fmt::format("net {}: two drivers, {} and {}", n, use.drivers[0], use.drivers[1]));
    if (use.drivers.empty() && !use.first_reader.empty())
      throw std::logic_error(fmt::format("net {}: read by {}, but no stage drives it", n, use.first_reader));
    if (use.drivers.empty())
      throw std::logic_error(fmt::format("net {}: declared by {}, but no stage drives it", n, use.declared_by));
  }
  auto unread = [&](const std::string& n) { return !nets.at(n).read_whole; };
  auto waiver = [](const std::string& declarations, bool in_part) {
    return std::string("  /* verilator lint_off UNUSEDSIGNAL */  // ") +
           (in_part ? "the stages after it read the bits they need\n" : "not read in this configuration\n") +
           declarations + "  /* verilator lint_on UNUSEDSIGNAL */\n";
  };

  std::string text = "module " + name + " (\n";
  for (size_t i = 0; i < ports_.size(); ++i) {
    const Port& p = ports_[i];
    const std::string line = fmt::format("  {} wire {}{}{}\n", p.input ? "input " : "output", range(p.net.bits),
                                         p.net.name, i + 1 < ports_.size() ? "," : "");
    text += p.text;
    text += p.input && unread(p.net.name)
                ? "  /* verilator lint_off UNUSEDSIGNAL */  // read where the configuration uses it\n" + line +
                      "  /* verilator lint_on UNUSEDSIGNAL */\n"
                : line;
  }
  text += ");\n";
  // Consecutive wires under one waiver, the read and the unread apart.
  std::string pending;
  bool pending_part = false;
  auto flush = [&]() {
    if (!pending.empty()) text += waiver(pending, pending_part);
    pending.clear();
  };
  for (size_t i = 0; i < items_.size(); ++i) {
    const Item& item = items_[i];
    if (item.kind == Item::Wire) {
      const NetDeclaration& w = item.regs.front();
      const std::string line = fmt::format("  wire {}{}{};\n", w.is_signed ? "signed " : "", range(w.bits), w.name);
      if (!unread(w.name)) {
        flush();
        text += line;
        continue;
      }
      const bool in_part = nets.at(w.name).read_in_part;
      if (!pending.empty() && in_part != pending_part) flush();
      pending_part = in_part;
      pending += line;
      continue;
    }
    flush();
    if (item.kind == Item::Instance) text += instance_text(item.module, item.name, item.parameters, resolved[i]);
    else text += item.text;
  }
  flush();
  return text + "endmodule\n";
}

}  // namespace fpstereo::rtl
