// Runner of the per-module benches: modules_tb <test> [--seed N] [--cycles N], or --list.
// The seed may also come from FPSTEREO_MODTB_SEED.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tb_common.hpp"

int main(int argc, char** argv) {
  modtb::Options o;
  if (const char* s = std::getenv("FPSTEREO_MODTB_SEED")) o.seed = std::strtoull(s, nullptr, 0);
  std::string test;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--list") {
      for (const auto& [name, fn] : modtb::registry()) std::printf("%s\n", name.c_str());
      return 0;
    } else if (a == "--seed" && i + 1 < argc) {
      o.seed = std::strtoull(argv[++i], nullptr, 0);
    } else if (a == "--cycles" && i + 1 < argc) {
      o.cycles = std::strtol(argv[++i], nullptr, 0);
    } else if (test.empty() && a[0] != '-') {
      test = a;
    } else {
      std::fprintf(stderr, "usage: %s <test> [--seed N] [--cycles N] | --list\n", argv[0]);
      return 2;
    }
  }
  const auto it = modtb::registry().find(test);
  if (it == modtb::registry().end()) {
    std::fprintf(stderr, "unknown test '%s' (--list shows them)\n", test.c_str());
    return 2;
  }
  std::printf("%s: seed %llu\n", test.c_str(), static_cast<unsigned long long>(o.seed));
  return it->second(o);
}
