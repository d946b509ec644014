// The helpers every tool shares: the hash of cache keys.
#include <catch2/catch.hpp>
#include <string>

#include "hash.hpp"

using namespace fpstereo;

TEST_CASE("fnv1a64 is the standard 64-bit FNV-1a", "[tools]") {
  // The reference vectors of the FNV specification.
  CHECK(fnv1a64("") == 0xcbf29ce484222325ull);
  CHECK(fnv1a64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a64("foobar") == 0x85944171f73967e8ull);
  CHECK(fnv1a64(std::string("a\0b", 3)) != fnv1a64("ab"));
}
