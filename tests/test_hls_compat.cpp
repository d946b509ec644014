// The compatibility header that stands in for the Vitis HLS headers in C-simulation: the
// behaviour the kernels rely on, as the real ap_int.h and hls_stream.h have it.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "fpstereo_hls_compat.h"

TEST_CASE("ap_uint and ap_int wrap to their width on assignment") {
  ap_uint<5> u = 31;
  u = u + 1;
  CHECK(u == 0);
  u = -1;
  CHECK(u == 31);
  ap_int<5> s = 15;
  s = s + 1;
  CHECK(s == -16);
  ap_int<5> n = -3;
  CHECK(int(n) == -3);
  CHECK(int(ap_uint<8>(n)) == 253);  // sign-extended, then cut to 8 bits
  ap_uint<64> full = ~0ull;
  CHECK(full == ~0ull);
}

TEST_CASE("ap_uint range and bit access, within one word and across words") {
  ap_uint<12> w = 0;
  w.range(7, 4) = 0xA;
  CHECK(int(w) == 0xA0);
  CHECK(w.range(7, 4) == 0xA);
  w.range(11, 8) = 0x1F;  // cut to the 4-bit field
  CHECK(int(w) == 0xFA0);

  ap_uint<200> wide = 0;
  wide.range(70, 60) = 0x5A5;  // straddles the 64-bit word boundary
  CHECK(wide.range(70, 60) == 0x5A5);
  CHECK(wide.range(59, 0) == 0);
  CHECK(wide.range(127, 71) == 0);
  CHECK(wide[60]);
  CHECK(!wide[61]);
  wide.range(199, 199) = 1;
  CHECK(wide[199]);
  ap_uint<200> copy = wide;
  CHECK(copy == wide);
  CHECK((copy ^ wide) == ap_uint<200>(0));
  ap_uint<16> from_range = wide.range(75, 60);
  CHECK(int(from_range) == 0x5A5);
}

TEST_CASE("hls::stream is a FIFO") {
  hls::stream<int> s("s");
  CHECK(s.empty());
  s.write(1);
  s << 2;
  CHECK(s.size() == 2);
  CHECK(s.read() == 1);
  int v = 0;
  s >> v;
  CHECK(v == 2);
  CHECK(s.empty());
  CHECK(!s.full());
}
