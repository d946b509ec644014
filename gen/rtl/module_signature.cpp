#include "module_signature.hpp"

#include <cctype>
#include <mutex>
#include <regex>
#include <stdexcept>

#include "rtl_templates.hpp"
#include "text.hpp"

namespace fpstereo::rtl {
namespace {

// A recursive-descent reader of constant expressions, with Verilog's operator precedence.
class ConstantReader {
 public:
  ConstantReader(const std::string& text, const std::map<std::string, int64_t>& values)
      : text_(text), values_(values) {}

  std::optional<int64_t> read() {
    try {
      const int64_t v = conditional();
      skip_space();
      if (at_ != text_.size()) return std::nullopt;
      return v;
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }

 private:
  [[noreturn]] static void fail() { throw std::invalid_argument("not a constant expression"); }

  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool take(const std::string& op) {
    skip_space();
    if (text_.compare(at_, op.size(), op) != 0) return false;
    // "<" is not "<<" or "<=", "*" is not "**", "|" is not "||", "&" not "&&", "=" needs "==".
    const char next = at_ + op.size() < text_.size() ? text_[at_ + op.size()] : '\0';
    if ((op == "<" || op == ">") && (next == op[0] || next == '=')) return false;
    if ((op == "*" || op == "&" || op == "|") && next == op[0]) return false;
    at_ += op.size();
    return true;
  }

  int64_t conditional() {
    const int64_t c = logical_or();
    if (!take("?")) return c;
    const int64_t a = conditional();
    if (!take(":")) fail();
    const int64_t b = conditional();
    return c ? a : b;
  }
  int64_t logical_or() {
    int64_t v = logical_and();
    while (take("||")) v = (logical_and() != 0) || v;
    return v;
  }
  int64_t logical_and() {
    int64_t v = equality();
    while (take("&&")) v = (equality() != 0) && v;
    return v;
  }
  int64_t equality() {
    int64_t v = relation();
    for (;;) {
      if (take("==")) v = v == relation();
      else if (take("!=")) v = v != relation();
      else return v;
    }
  }
  int64_t relation() {
    int64_t v = shift();
    for (;;) {
      if (take("<=")) v = v <= shift();
      else if (take(">=")) v = v >= shift();
      else if (take("<")) v = v < shift();
      else if (take(">")) v = v > shift();
      else return v;
    }
  }
  int64_t shift() {
    int64_t v = sum();
    for (;;) {
      if (take("<<")) v <<= sum();
      else if (take(">>")) v >>= sum();
      else return v;
    }
  }
  int64_t sum() {
    int64_t v = product();
    for (;;) {
      if (take("+")) v += product();
      else if (take("-")) v -= product();
      else return v;
    }
  }
  int64_t product() {
    int64_t v = power();
    for (;;) {
      if (take("*")) {
        v *= power();
      } else if (take("/") || take("%")) {
        const bool divide = text_[at_ - 1] == '/';
        const int64_t d = power();
        if (d == 0) fail();
        v = divide ? v / d : v % d;
      } else {
        return v;
      }
    }
  }
  int64_t power() {
    const int64_t base = unary();
    if (!take("**")) return base;
    int64_t e = power(), v = 1;
    if (e < 0 || e > 62) fail();
    while (e-- > 0) v *= base;
    return v;
  }
  int64_t unary() {
    if (take("!")) return !unary();
    if (take("-")) return -unary();
    if (take("+")) return unary();
    return primary();
  }
  int64_t primary() {
    skip_space();
    if (take("(")) {
      const int64_t v = conditional();
      if (!take(")")) fail();
      return v;
    }
    if (take("$clog2")) {
      if (!take("(")) fail();
      const int64_t v = conditional();
      if (!take(")")) fail();
      int64_t bits = 0;
      while (bits < 63 && (int64_t(1) << bits) < v) ++bits;
      return bits;
    }
    if (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_]))) return literal();
    if (at_ < text_.size() && (std::isalpha(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_')) {
      const size_t start = at_;
      while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_')) ++at_;
      const auto it = values_.find(text_.substr(start, at_ - start));
      if (it == values_.end()) fail();
      return it->second;
    }
    fail();
  }
  // 42, or a sized literal 8'd42, 1'b0, 32'h1f.
  int64_t literal() {
    size_t used = 0;
    int64_t v = std::stoll(text_.substr(at_), &used, 10);
    at_ += used;
    if (at_ + 1 < text_.size() && text_[at_] == '\'') {
      const char base = static_cast<char>(std::tolower(static_cast<unsigned char>(text_[at_ + 1])));
      const int radix = base == 'd' ? 10 : base == 'h' ? 16 : base == 'b' ? 2 : base == 'o' ? 8 : 0;
      if (radix == 0) fail();
      at_ += 2;
      size_t digits = 0;
      v = std::stoll(text_.substr(at_), &digits, radix);
      at_ += digits;
    }
    return v;
  }

  const std::string& text_;
  const std::map<std::string, int64_t>& values_;
  size_t at_ = 0;
};

std::string strip_comments(const std::string& text) {
  static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
  return std::regex_replace(text, comments, "");
}

}  // namespace

std::vector<std::string> verilog_list_items(const std::string& list) {
  std::vector<std::string> out;
  int depth = 0;
  std::string item;
  for (char ch : list) {
    depth += (ch == '(' || ch == '[' || ch == '{') ? 1 : (ch == ')' || ch == ']' || ch == '}') ? -1 : 0;
    if (ch == ',' && depth == 0) {
      out.push_back(trim(item));
      item.clear();
    } else {
      item += ch;
    }
  }
  if (!trim(item).empty()) out.push_back(trim(item));
  return out;
}

const PortSignature* ModuleSignature::port(const std::string& port_name) const {
  for (const auto& p : ports)
    if (p.name == port_name) return &p;
  return nullptr;
}

std::optional<int64_t> evaluate_constant(const std::string& expression, const std::map<std::string, int64_t>& values) {
  return ConstantReader(expression, values).read();
}

ModuleSignature parse_module_signature(const std::string& verilog) {
  const std::string text = strip_comments(verilog);
  static const std::regex header(R"(\bmodule\s+(\w+)\s*(#\s*\()?)");
  std::smatch m;
  if (!std::regex_search(text, m, header)) throw std::logic_error("no module declaration");
  ModuleSignature s;
  s.name = m[1];
  size_t at = size_t(m.position(0) + m.length(0));
  auto fail = [&](const std::string& what) { throw std::logic_error("module " + s.name + ": " + what); };
  // The text up to the parenthesis that closes the one opened just before `at`.
  auto enclosed = [&]() {
    int depth = 1;
    const size_t start = at;
    for (; at < text.size() && depth > 0; ++at) depth += text[at] == '(' ? 1 : text[at] == ')' ? -1 : 0;
    if (depth != 0) fail("unbalanced parentheses");
    return text.substr(start, at - 1 - start);
  };
  if (m[2].matched) {
    static const std::regex parameter(R"(^parameter\s+(?:integer\s+|\[[^\]]*\]\s*)?(\w+)\s*=\s*([\s\S]+)$)");
    for (const auto& item : verilog_list_items(enclosed())) {
      std::smatch p;
      if (!std::regex_match(item, p, parameter)) fail("cannot read parameter `" + item + "`");
      s.parameters.push_back({p[1], trim(p[2])});
    }
  }
  while (at < text.size() && text[at] != '(') ++at;
  if (at++ == text.size()) fail("no port list");
  static const std::regex port(R"(^(input|output)\s+(?:wire\s+|reg\s+)?(?:signed\s+)?(?:\[([\s\S]*):\s*0\s*\]\s*)?(\w+)$)");
  for (const auto& item : verilog_list_items(enclosed())) {
    std::smatch p;
    if (!std::regex_match(item, p, port)) fail("cannot read port `" + item + "`");
    s.ports.push_back({p[3], p[1] == "input", p[2].matched ? trim(p[2]) : ""});
  }
  return s;
}

const ModuleSignature& template_signature(const std::string& module) {
  static std::mutex lock;
  static std::map<std::string, ModuleSignature> parsed;
  const std::lock_guard<std::mutex> guard(lock);
  auto it = parsed.find(module);
  if (it != parsed.end()) return it->second;
  const auto& files = templates();
  const auto file = files.find(module);
  if (file == files.end()) throw std::logic_error("no template " + module);
  return parsed.emplace(module, parse_module_signature(file->second)).first->second;
}

std::map<std::string, int64_t> port_widths(const ModuleSignature& signature,
                                           const std::vector<std::pair<std::string, std::string>>& parameters) {
  // Given values first; defaults in declaration order, each over the values before it.
  // A given value that is no constant (a concatenation) leaves the parameter unknown.
  std::map<std::string, int64_t> values;
  std::map<std::string, std::optional<int64_t>> given;
  for (const auto& [name, value] : parameters) given[name] = evaluate_constant(value, {});
  for (const auto& [name, default_value] : signature.parameters) {
    const auto it = given.find(name);
    const auto v = it != given.end() ? it->second : evaluate_constant(default_value, values);
    if (v) values[name] = *v;
  }
  std::map<std::string, int64_t> widths;
  for (const auto& p : signature.ports) {
    if (p.msb.empty()) widths[p.name] = 1;
    else if (const auto v = evaluate_constant(p.msb, values)) widths[p.name] = *v + 1;
  }
  return widths;
}

}  // namespace fpstereo::rtl
