// The one hash of the tools: cache keys, cache file names and dataset identities.
#pragma once

#include <cstdint>
#include <string_view>

namespace fpstereo {

// 64-bit FNV-1a: stable across runs, platforms and versions, which std::hash is not.
constexpr uint64_t fnv1a64(std::string_view text) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (char ch : text) h = (h ^ uint8_t(ch)) * 0x100000001b3ull;
  return h;
}

}  // namespace fpstereo
