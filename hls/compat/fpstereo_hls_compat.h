// Stand-ins for Vitis HLS's ap_int.h, hls_stream.h and ap_axi_sdata.h, so the kernels compile and
// C-simulate with a plain C++17 compiler. fpstereo_hls.hpp includes this header only when the real
// headers are absent; with Vitis installed the real ones win.
//
// Only what the kernels use is here, with the real headers' meaning:
//   ap_uint<W> / ap_int<W>: W-bit values that wrap to W bits on every assignment; up to 64 bits
//     they convert implicitly to (unsigned) long long, so arithmetic happens there and the result
//     is truncated when stored back. Wider values (census codes, packed rows) offer bit and range
//     access, bitwise operators and equality.
//   hls::stream<T>: an unbounded FIFO; reading an empty stream is a C-simulation error (the
//     hardware would deadlock), reported with the stream's name.
//   ap_axiu<D, U, TI, TD>: an AXI4-Stream beat (data, keep, strb, user, last, id, dest).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>
#include <type_traits>

namespace fpstereo_compat {

template <int W, bool Signed>
class ap_bits {
  static_assert(W >= 1, "ap_int widths start at 1");
  static constexpr int kWords = (W + 63) / 64;
  static constexpr int kTopBits = W - 64 * (kWords - 1);
  static constexpr uint64_t kTopMask = kTopBits == 64 ? ~0ull : (1ull << kTopBits) - 1;
  // Values wider than 64 bits convert to nothing usable (no arithmetic on them, as documented).
  struct NoIntegerConversion {};
  using Native = std::conditional_t<(W > 64), NoIntegerConversion,
                                    std::conditional_t<Signed, long long, unsigned long long>>;

 public:
  ap_bits() = default;
  template <class I, class = std::enable_if_t<std::is_integral<I>::value>>
  ap_bits(I v) {
    const uint64_t low = uint64_t(v);
    const uint64_t fill = (std::is_signed<I>::value && v < 0) ? ~0ull : 0;
    words_[0] = low;
    for (int i = 1; i < kWords; ++i) words_[i] = fill;
    wrap();
  }
  template <class R, class = typename R::is_range_ref>
  ap_bits(const R& r) : ap_bits((unsigned long long)r) {}
  template <int W2, bool S2>
  ap_bits(const ap_bits<W2, S2>& o) {
    // Sign-extend a negative source above its width, then cut to this width.
    const uint64_t fill = o.negative() ? ~0ull : 0;
    for (int i = 0; i < kWords; ++i) {
      uint64_t v = i < o.kWordCount ? o.word(i) : fill;
      if (i == (W2 - 1) / 64 && W2 % 64 != 0) v |= fill << (W2 % 64);
      words_[i] = v;
    }
    wrap();
  }

  // Integer value; only up to 64 bits, like the implicit conversion of the real ap_int. Arithmetic
  // and comparisons of narrow values go through it.
  operator Native() const {
    if constexpr (W > 64) {
      return Native();
    } else {
      if (Signed && W < 64 && (words_[0] >> (W - 1) & 1)) return Native(words_[0] | ~kTopMask);
      return Native(words_[0]);
    }
  }
  uint64_t to_uint64() const { return words_[0]; }

  bool operator[](int i) const { return words_[i / 64] >> (i % 64) & 1; }
  void set_bit(int i, bool b) {
    const uint64_t m = 1ull << (i % 64);
    words_[i / 64] = b ? words_[i / 64] | m : words_[i / 64] & ~m;
  }

  // Bits hi..lo (hi - lo < 64) as an unsigned value, and their assignment.
  uint64_t get_range(int hi, int lo) const {
    check_range(hi, lo);
    const int n = hi - lo + 1;
    uint64_t v = words_[lo / 64] >> (lo % 64);
    if (lo % 64 != 0 && lo / 64 + 1 < kWords) v |= words_[lo / 64 + 1] << (64 - lo % 64);
    return n == 64 ? v : v & ((1ull << n) - 1);
  }
  void set_range(int hi, int lo, uint64_t v) {
    check_range(hi, lo);
    for (int i = lo; i <= hi; ++i) set_bit(i, v >> (i - lo) & 1);
  }
  class range_ref {
   public:
    using is_range_ref = void;
    range_ref(ap_bits& bits, int hi, int lo) : bits_(bits), hi_(hi), lo_(lo) {}
    operator unsigned long long() const { return bits_.get_range(hi_, lo_); }
    range_ref& operator=(unsigned long long v) {
      bits_.set_range(hi_, lo_, v);
      return *this;
    }
    range_ref& operator=(const range_ref& o) { return *this = (unsigned long long)(o); }

   private:
    ap_bits& bits_;
    int hi_, lo_;
  };
  range_ref range(int hi, int lo) { return range_ref(*this, hi, lo); }
  unsigned long long range(int hi, int lo) const { return get_range(hi, lo); }

  // Wide values only: narrow ones use the built-in operators through the integer conversion.
  template <int W2 = W, std::enable_if_t<(W2 > 64), int> = 0>
  friend ap_bits operator^(const ap_bits& a, const ap_bits& b) {
    ap_bits r;
    for (int i = 0; i < kWords; ++i) r.words_[i] = a.words_[i] ^ b.words_[i];
    return r;
  }
  template <int W2 = W, std::enable_if_t<(W2 > 64), int> = 0>
  friend bool operator==(const ap_bits& a, const ap_bits& b) {
    for (int i = 0; i < kWords; ++i)
      if (a.words_[i] != b.words_[i]) return false;
    return true;
  }

  static constexpr int kWordCount = kWords;
  uint64_t word(int i) const { return words_[i]; }
  bool negative() const { return Signed && (*this)[W - 1]; }

 private:
  void wrap() { words_[kWords - 1] &= kTopMask; }
  static void check_range(int hi, int lo) {
    if (lo < 0 || hi >= W || hi < lo || hi - lo >= 64) {
      std::fprintf(stderr, "ap_int compat: range(%d, %d) outside a %d-bit value or wider than 64 bits\n", hi,
                   lo, W);
      std::abort();
    }
  }
  uint64_t words_[kWords] = {};
};

}  // namespace fpstereo_compat

template <int W>
using ap_uint = fpstereo_compat::ap_bits<W, false>;
template <int W>
using ap_int = fpstereo_compat::ap_bits<W, true>;

template <int D, int U, int TI, int TD>
struct ap_axiu {
  ap_uint<D> data;
  ap_uint<(D + 7) / 8> keep;
  ap_uint<(D + 7) / 8> strb;
  ap_uint<U> user;
  ap_uint<1> last;
  ap_uint<TI> id;
  ap_uint<TD> dest;
};

namespace hls {

template <class T>
class stream {
 public:
  stream() : name_("unnamed") {}
  explicit stream(const char* name) : name_(name) {}
  stream(const stream&) = delete;
  stream& operator=(const stream&) = delete;

  void write(const T& v) { fifo_.push_back(v); }
  T read() {
    if (fifo_.empty()) {
      std::fprintf(stderr, "hls::stream '%s': read while empty (the hardware would stall forever)\n",
                   name_.c_str());
      std::abort();
    }
    T v = fifo_.front();
    fifo_.pop_front();
    return v;
  }
  void read(T& v) { v = read(); }
  void operator<<(const T& v) { write(v); }
  void operator>>(T& v) { v = read(); }
  bool empty() const { return fifo_.empty(); }
  bool full() const { return false; }
  size_t size() const { return fifo_.size(); }

 private:
  std::string name_;
  std::deque<T> fifo_;
};

}  // namespace hls
