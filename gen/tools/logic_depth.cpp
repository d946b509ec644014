#include "logic_depth.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

namespace fpstereo {
namespace {

using json = nlohmann::json;

constexpr int kConstant = -1;  // a connection to "0", "1", "x" or "z"
// Yosys numbers net bits densely from 2 and the analysis indexes arrays by them; far above a
// large design's million, so only a damaged file reaches it.
constexpr int64_t kMaxBitId = int64_t(1) << 26;

// ---- the netlist -----------------------------------------------------------------------------

struct Port {
  std::string name;
  bool output = false;
  std::vector<int> bits;  // net bit ids, kConstant for a constant
};

enum class CellKind { Lut, Mux, Carry, Buffer, LutRam, Sequential };

struct Cell {
  std::string name, type;
  bool public_name = false;
  CellKind kind = CellKind::Sequential;
  std::vector<std::string> src;  // the "|"-separated locations of its src attribute
  std::vector<Port> ports;
};

struct NetName {
  std::string name;
  bool public_name = false;
  std::vector<int> bits;
  int offset = 0;
  bool upto = false;
  std::vector<std::string> src;
};

struct Netlist {
  std::vector<Cell> cells;
  std::vector<NetName> netnames;
  std::vector<Port> ports;  // the top module's
  int bit_count = 0;        // one more than the largest bit id
};

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

CellKind kind_of(const std::string& type) {
  static const std::set<std::string> luts = {"LUT1", "LUT2", "LUT3", "LUT4", "LUT5", "LUT6", "INV"};
  static const std::set<std::string> muxes = {"MUXF7", "MUXF8", "MUXF9"};
  static const std::set<std::string> carries = {"CARRY4", "CARRY8"};
  static const std::set<std::string> buffers = {"IBUF", "IBUFG", "OBUF", "BUFG", "BUF"};
  if (luts.count(type)) return CellKind::Lut;
  if (muxes.count(type)) return CellKind::Mux;
  if (carries.count(type)) return CellKind::Carry;
  if (buffers.count(type)) return CellKind::Buffer;
  // Distributed RAM and shift registers; RAMB* is block RAM, sequential.
  if (starts_with(type, "SRL") || (starts_with(type, "RAM") && !starts_with(type, "RAMB"))) return CellKind::LutRam;
  return CellKind::Sequential;
}

std::vector<std::string> split_src(const std::string& src) {
  std::vector<std::string> parts;
  size_t begin = 0;
  while (begin <= src.size()) {
    const size_t bar = std::min(src.find('|', begin), src.size());
    if (bar > begin) parts.push_back(src.substr(begin, bar - begin));
    begin = bar + 1;
  }
  return parts;
}

std::string src_of(const json& object) {
  const auto attributes = object.find("attributes");
  if (attributes == object.end() || !attributes->is_object()) return "";
  const auto src = attributes->find("src");
  return src != attributes->end() && src->is_string() ? src->get<std::string>() : "";
}

// Yosys writes flags as numbers, or as binary strings when they do not fit.
bool flag(const json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end()) return false;
  if (it->is_number()) return it->get<double>() != 0;
  if (it->is_string()) return it->get<std::string>().find('1') != std::string::npos;
  return false;
}

// object[key], or null when absent (operator[] on a const json must not miss).
const json& member(const json& object, const char* key) {
  static const json null;
  if (!object.is_object()) return null;
  const auto it = object.find(key);
  return it == object.end() ? null : *it;
}

std::vector<int> bits_of(const json& bits, const std::string& where, int& bit_count) {
  if (!bits.is_array()) throw LogicDepthError(fmt::format("netlist: {} has no bit list", where));
  std::vector<int> out;
  out.reserve(bits.size());
  for (const auto& b : bits) {
    if (b.is_number_integer() && b.get<int64_t>() >= 0 && b.get<int64_t>() < kMaxBitId) {
      out.push_back(b.get<int>());
      bit_count = std::max(bit_count, out.back() + 1);
    } else if (b.is_string()) {
      out.push_back(kConstant);
    } else {
      throw LogicDepthError(fmt::format("netlist: {} has a malformed bit {}", where, b.dump()));
    }
  }
  return out;
}

const json& top_module(const json& doc) {
  const auto modules = doc.find("modules");
  if (modules == doc.end() || !modules->is_object()) throw LogicDepthError("netlist: no \"modules\" object");
  const json* with_cells = nullptr;
  size_t count_with_cells = 0;
  for (const auto& [name, module] : modules->items()) {
    if (!module.is_object()) continue;
    const auto attributes = module.find("attributes");
    if (attributes != module.end() && attributes->is_object() && flag(*attributes, "top")) return module;
    const auto cells = module.find("cells");
    if (cells != module.end() && cells->is_object() && !cells->empty()) {
      with_cells = &module;
      ++count_with_cells;
    }
  }
  if (count_with_cells != 1) throw LogicDepthError("netlist: no module marked top");
  return *with_cells;
}

Netlist read_module(const json& top) {
  Netlist n;
  for (const auto& [name, port] : member(top, "ports").items()) {
    const std::string direction = port.value("direction", "");
    if (direction != "input" && direction != "output") continue;  // inout: neither starts nor ends
    n.ports.push_back({name, direction == "output", bits_of(member(port, "bits"), "port " + name, n.bit_count)});
  }
  for (const auto& [name, cell] : member(top, "cells").items()) {
    Cell c;
    c.name = name;
    c.type = cell.value("type", "");
    c.public_name = !flag(cell, "hide_name") && !name.empty() && name[0] != '$';
    c.kind = kind_of(c.type);
    c.src = split_src(src_of(cell));
    const auto directions = cell.find("port_directions");
    const auto connections = cell.find("connections");
    if (directions == cell.end() || connections == cell.end())
      throw LogicDepthError(fmt::format("netlist: cell {} lacks port_directions or connections", name));
    for (const auto& [pin, bits] : connections->items()) {
      const auto direction = directions->find(pin);
      if (direction == directions->end())
        throw LogicDepthError(fmt::format("netlist: cell {} has no direction for port {}", name, pin));
      if (*direction == "inout") continue;
      c.ports.push_back({pin, *direction == "output", bits_of(bits, "cell " + name, n.bit_count)});
    }
    n.cells.push_back(std::move(c));
  }
  for (const auto& [name, net] : member(top, "netnames").items()) {
    NetName w;
    w.name = name;
    w.public_name = !flag(net, "hide_name") && !name.empty() && name[0] != '$';
    w.bits = bits_of(member(net, "bits"), "net " + name, n.bit_count);
    w.offset = net.value("offset", 0);
    w.upto = flag(net, "upto");
    w.src = split_src(src_of(net));
    n.netnames.push_back(std::move(w));
  }
  return n;
}

Netlist read_netlist(const std::string& text) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw LogicDepthError(fmt::format("netlist: not JSON: {}", e.what()));
  }
  try {
    return read_module(top_module(doc));
  } catch (const json::exception& e) {  // a member of the wrong type
    throw LogicDepthError(fmt::format("netlist: unexpected structure: {}", e.what()));
  }
}

// ---- the timing graph ------------------------------------------------------------------------

// Depth in (first, second) order: (LUT levels, with carry) or (with carry, LUT levels). Pairs
// compare lexicographically, which addition preserves, so the longest path stays well defined.
struct Depth {
  int first = 0, second = 0;
  int start = -1;  // the bit the path starts from
  bool operator<(const Depth& o) const { return std::tie(first, second) < std::tie(o.first, o.second); }
};

// Where a bit comes from: a cell's output pin, an input port, or nothing (undriven).
struct Source {
  int cell = -1, port = -1, index = 0;  // port: index into the cell's ports, or into the top ports
  bool top_port = false;
};

// The combinational arcs into one bit: its input bits and what the driving cell adds.
struct Arcs {
  uint32_t begin = 0, end = 0;  // range in Graph::inputs
  int luts = 0, others = 0;     // LUT levels, carry/MUXF cells the driver adds
};

struct Endpoint {
  int bit = -1;
  Source sink;  // the cell input pin or output port the path ends at
};

struct Graph {
  std::vector<Source> source;  // per bit
  std::vector<Arcs> arcs;      // per bit
  std::vector<int> inputs;
  std::vector<Endpoint> endpoints;
};

bool is_clock(const std::string& pin) { return pin == "C" || pin.find("CLK") != std::string::npos; }

bool is_address_of_output(const std::string& out, const std::string& in) {
  // RAM32M16/RAM64M8/RAM64M: DOx reads at ADDRx. RAMnX1D: DPO at DPRA. SRLs and single ports: A.
  if (out.size() > 2 && starts_with(out, "DO")) return in == "ADDR" + out.substr(2);
  if (out == "DPO") return starts_with(in, "DPRA");
  if (out == "O" || out == "SPO" || out == "Q")
    return in == "A" || (in.size() > 1 && in[0] == 'A' && std::isdigit(uint8_t(in[1])));
  return false;  // e.g. an SRL's cascade output Q31
}

const Port* find_port(const Cell& c, const char* name) {
  for (const auto& p : c.ports)
    if (p.name == name) return &p;
  return nullptr;
}

// The input bits bit `index` of output port `out` of cell `c` depends on.
std::vector<int> fanin(const Cell& c, const Port& out, size_t index) {
  std::vector<int> bits;
  auto add = [&bits](const Port& p, size_t count) {
    for (size_t i = 0; i < std::min(count, p.bits.size()); ++i) bits.push_back(p.bits[i]);
  };
  for (const auto& in : c.ports) {
    if (in.output) continue;
    switch (c.kind) {
      case CellKind::Carry:
        // Bit j of the sum and carry out depends on the selects and data of bits 0..j; CI_TOP
        // enters CARRY8's upper half.
        if (in.name == "S" || in.name == "DI") add(in, index + 1);
        else if (in.name == "CI" || in.name == "CYINIT" || (in.name == "CI_TOP" && index >= 4)) add(in, in.bits.size());
        break;
      case CellKind::Buffer:
        if (in.name == "I") add(in, in.bits.size());
        break;
      case CellKind::LutRam:
        if (is_address_of_output(out.name, in.name)) add(in, in.bits.size());
        break;
      default:
        add(in, in.bits.size());
    }
  }
  bits.erase(std::remove(bits.begin(), bits.end(), kConstant), bits.end());
  return bits;
}

Graph build_graph(const Netlist& n) {
  Graph g;
  g.source.resize(n.bit_count);
  g.arcs.resize(n.bit_count);
  for (size_t p = 0; p < n.ports.size(); ++p) {
    const Port& port = n.ports[p];
    for (size_t i = 0; i < port.bits.size(); ++i) {
      if (port.bits[i] == kConstant) continue;
      if (port.output) g.endpoints.push_back({port.bits[i], {-1, int(p), int(i), true}});
      else g.source[port.bits[i]] = {-1, int(p), int(i), true};
    }
  }
  for (size_t c = 0; c < n.cells.size(); ++c) {
    const Cell& cell = n.cells[c];
    const bool combinational = cell.kind != CellKind::Sequential;
    for (size_t p = 0; p < cell.ports.size(); ++p) {
      const Port& port = cell.ports[p];
      for (size_t i = 0; i < port.bits.size(); ++i) {
        const int bit = port.bits[i];
        if (bit == kConstant) continue;
        const Source here{int(c), int(p), int(i), false};
        if (!port.output) {
          // A register's or memory's input ends paths; a LUTRAM's too (its data, write enable and
          // write address are stored; a read address also continues through the data out).
          if ((cell.kind == CellKind::Sequential || cell.kind == CellKind::LutRam) && !is_clock(port.name))
            g.endpoints.push_back({bit, here});
          continue;
        }
        if (g.source[bit].cell >= 0 || g.source[bit].top_port)
          throw LogicDepthError(fmt::format("netlist: net bit {} has two drivers (cell {})", bit, cell.name));
        g.source[bit] = here;
        if (!combinational) continue;
        Arcs& a = g.arcs[bit];
        const std::vector<int> in = fanin(cell, port, i);
        a.begin = uint32_t(g.inputs.size());
        g.inputs.insert(g.inputs.end(), in.begin(), in.end());
        a.end = uint32_t(g.inputs.size());
        a.luts = cell.kind == CellKind::Lut || cell.kind == CellKind::LutRam ? 1 : 0;
        a.others = cell.kind == CellKind::Mux || cell.kind == CellKind::Carry ? 1 : 0;
      }
    }
  }
  return g;
}

// Longest paths into every bit, by iterative depth-first search (a deep carry chain would overflow
// the stack of a recursive one). A bit met again while on the stack closes a combinational loop.
class LongestPaths {
 public:
  LongestPaths(const Graph& g, bool luts_first, const Netlist& n)
      : g_(g), n_(n), luts_first_(luts_first), depth_(g.arcs.size()), state_(g.arcs.size(), kNew) {}

  const Depth& operator()(int bit) {
    if (state_[bit] != kDone) visit(bit);
    return depth_[bit];
  }

 private:
  enum State : uint8_t { kNew, kOnStack, kDone };

  void visit(int root) {
    std::vector<std::pair<int, uint32_t>> stack = {{root, g_.arcs[root].begin}};
    state_[root] = kOnStack;
    while (!stack.empty()) {
      auto& [bit, next] = stack.back();
      const Arcs& a = g_.arcs[bit];
      if (next < a.end) {
        const int in = g_.inputs[next++];
        if (state_[in] == kOnStack) throw LogicDepthError(loop_message(stack, in));
        if (state_[in] == kNew) {
          state_[in] = kOnStack;
          stack.push_back({in, g_.arcs[in].begin});
        }
        continue;
      }
      finish(bit);
      state_[bit] = kDone;
      stack.pop_back();
    }
  }

  void finish(int bit) {
    const Arcs& a = g_.arcs[bit];
    const int first = luts_first_ ? a.luts : a.luts + a.others;
    const int second = luts_first_ ? a.luts + a.others : a.luts;
    // A bit no logic drives starts paths: a register's output, a port, a LUTRAM word not read
    // through an address.
    Depth best{0, 0, bit};
    for (uint32_t k = a.begin; k < a.end; ++k) {
      const Depth& d = depth_[g_.inputs[k]];
      const Depth through{d.first + first, d.second + second, d.start};
      if (k == a.begin || best < through) best = through;
    }
    depth_[bit] = best;
  }

  std::string loop_message(const std::vector<std::pair<int, uint32_t>>& stack, int again) const {
    std::vector<std::string> cells;  // in loop order, each once (a carry cell drives several bits)
    bool on_loop = false;
    for (const auto& [bit, next] : stack) {
      on_loop = on_loop || bit == again;
      if (!on_loop || g_.source[bit].cell < 0) continue;
      const std::string& name = n_.cells[g_.source[bit].cell].name;
      if (std::find(cells.begin(), cells.end(), name) == cells.end()) cells.push_back(name);
    }
    const size_t shown = std::min<size_t>(cells.size(), 4);
    std::string list;
    for (size_t i = 0; i < shown; ++i) list += (i ? ", " : "") + cells[i];
    return fmt::format("combinational loop through {} cells: {}{}", cells.size(), list,
                       cells.size() > shown ? ", ..." : "");
  }

  const Graph& g_;
  const Netlist& n_;
  const bool luts_first_;
  std::vector<Depth> depth_;
  std::vector<State> state_;
};

// ---- names -----------------------------------------------------------------------------------

std::string bit_name(const std::string& name, size_t width, size_t index, int offset, bool upto) {
  if (width == 1 && offset == 0) return name;
  return fmt::format("{}[{}]", name, offset + int(upto ? width - 1 - index : index));
}

std::string file_of(const std::string& location) { return location.substr(0, location.rfind(':')); }
int line_of(const std::string& location) {
  const size_t colon = location.rfind(':');
  return colon == std::string::npos ? 0 : std::atoi(location.c_str() + colon + 1);
}

class Names {
 public:
  Names(const Netlist& n, const Graph& g) : n_(n), g_(g), aliases_(n.bit_count) {
    for (size_t w = 0; w < n.netnames.size(); ++w)
      for (size_t i = 0; i < n.netnames[w].bits.size(); ++i)
        if (n.netnames[w].bits[i] != kConstant) aliases_[n.netnames[w].bits[i]].push_back({int(w), int(i)});
  }

  // The start of a path: the register, pin or port that drives `bit`.
  std::string start(int bit) const {
    const Source& s = g_.source[bit];
    if (s.top_port) return port_name(s);
    if (s.cell < 0) return net_name(bit);  // undriven
    const Cell& c = n_.cells[s.cell];
    if (is_register(c)) return register_name(c);
    return pin_name(c, s);
  }

  // The end of a path: the register and pin (or the cell pin, or the port) it enters.
  std::string end(const Source& sink) const {
    if (sink.top_port) return port_name(sink);
    const Cell& c = n_.cells[sink.cell];
    if (is_register(c)) return register_name(c) + "/" + c.ports[sink.port].name;
    return pin_name(c, sink);
  }

  // What one entry of the worst-path list stands for: a register or port without its bit index, or
  // a cell.
  std::string end_group(const Source& sink) const {
    if (sink.top_port) return n_.ports[sink.port].name;
    const Cell& c = n_.cells[sink.cell];
    if (!is_register(c)) return c.name;
    std::string name = register_name(c);
    if (!name.empty() && name.back() == ']') name.erase(name.rfind('['));
    return name;
  }

 private:
  struct Alias {
    int netname, index;
  };

  static bool is_register(const Cell& c) {
    return (starts_with(c.type, "FD") || starts_with(c.type, "LD")) && find_port(c, "Q") &&
           find_port(c, "Q")->bits.size() == 1;
  }

  std::string alias_name(const Alias& a) const {
    const NetName& w = n_.netnames[a.netname];
    return bit_name(w.name, w.bits.size(), a.index, w.offset, w.upto);
  }

  std::string port_name(const Source& s) const {
    const Port& p = n_.ports[s.port];
    for (const auto& w : n_.netnames)
      if (w.name == p.name) return bit_name(p.name, p.bits.size(), s.index, w.offset, w.upto);
    return bit_name(p.name, p.bits.size(), s.index, 0, false);
  }

  std::string pin_name(const Cell& c, const Source& s) const {
    const Port& p = c.ports[s.port];
    const std::string pin = bit_name(p.name, p.bits.size(), s.index, 0, false);
    if (c.public_name) return c.name + "/" + pin;
    return net_name(p.bits[s.index]) + "/" + pin;  // Yosys' own cell names say nothing
  }

  // Without a register's src to go by (an SRL, a memory's output): public names first, then the
  // generator's register names (*_q), then the shortest, then the first in order.
  std::string net_name(int bit) const {
    const auto rank = [this](const Alias& a) {
      const NetName& w = n_.netnames[a.netname];
      const bool register_like = w.name.size() > 2 && w.name.compare(w.name.size() - 2, 2, "_q") == 0;
      return std::make_tuple(!w.public_name, !register_like, alias_name(a).size());
    };
    const Alias* best = nullptr;
    for (const auto& a : aliases_[bit])
      if (!best || rank(a) < rank(*best)) best = &a;
    return best ? alias_name(*best) : fmt::format("net_bit_{}", bit);
  }

  // A flip-flop's Q net has one name per module it passes through, and more where wires are
  // slices or concatenations of it. The register is declared in the module of the always block
  // the flip-flop came from: flatten gives both the instance chain's locations, then the
  // flip-flop the always block's (and a techmap file's), the net its declaration, in the same
  // file. Of several there (a port, the reg, wires made of it), the one declared nearest above
  // the block: Verilog declares before use, and wires derived from the reg follow it.
  std::string register_name(const Cell& c) const {
    const int q = find_port(c, "Q")->bits[0];
    if (q == kConstant) return c.name;
    const std::multiset<std::string> cell_src(c.src.begin(), c.src.end());
    const Alias* best = nullptr;
    std::pair<bool, int> best_distance;  // (declared below the block, lines between)
    for (const auto& a : aliases_[q]) {
      const NetName& w = n_.netnames[a.netname];
      if (!w.public_name) continue;
      std::multiset<std::string> only_cell = cell_src;
      std::vector<std::string> only_net;
      for (const auto& loc : w.src) {
        const auto it = only_cell.find(loc);
        if (it != only_cell.end()) only_cell.erase(it);
        else only_net.push_back(loc);
      }
      if (only_net.size() != 1 || only_cell.size() > 2) continue;
      const std::string& declaration = only_net[0];
      const auto block = std::find_if(only_cell.begin(), only_cell.end(), [&](const std::string& loc) {
        return file_of(loc) == file_of(declaration);
      });
      if (block == only_cell.end()) continue;
      const int lines = line_of(*block) - line_of(declaration);
      const std::pair<bool, int> distance{lines < 0, std::abs(lines)};
      if (!best || distance < best_distance) {
        best = &a;
        best_distance = distance;
      }
    }
    return best ? alias_name(*best) : net_name(q);
  }

  const Netlist& n_;
  const Graph& g_;
  std::vector<std::vector<Alias>> aliases_;
};

}  // namespace

LogicDepth analyse_logic_depth(const std::string& yosys_json, size_t max_paths) {
  const Netlist netlist = read_netlist(yosys_json);
  const Graph graph = build_graph(netlist);
  LongestPaths by_levels(graph, true, netlist);
  LongestPaths by_carry(graph, false, netlist);
  const Names names(netlist, graph);

  LogicDepth result;
  std::vector<std::pair<Depth, const Endpoint*>> ends;
  std::optional<std::pair<Depth, const Endpoint*>> carry_end;
  for (const auto& e : graph.endpoints) {
    ends.push_back({by_levels(e.bit), &e});
    const Depth& c = by_carry(e.bit);
    if (!carry_end || carry_end->first < c) carry_end = {c, &e};
  }
  if (!carry_end) return result;  // nothing ends a path
  // Deepest first; equal depths in netlist order, so the report is the same on every run.
  std::stable_sort(ends.begin(), ends.end(), [](const auto& a, const auto& b) { return b.first < a.first; });
  result.levels = ends.front().first.first;
  result.levels_with_carry = carry_end->first.first;
  result.worst_with_carry = {carry_end->first.second, carry_end->first.first, names.start(carry_end->first.start),
                             names.end(carry_end->second->sink)};
  std::set<std::string> groups;
  for (const auto& [depth, end] : ends) {
    if (result.worst.size() >= max_paths) break;
    if (!groups.insert(names.end_group(end->sink)).second) continue;
    result.worst.push_back({depth.first, depth.second, names.start(depth.start), names.end(end->sink)});
  }
  return result;
}

}  // namespace fpstereo
