// fpstereo HLS kernels: the semi-global matching pipeline as Vitis HLS streaming stages, bit-exact
// with the golden model (docs/semantics.md). Every stage is a function template on a configuration
// struct C (the generated <prefix>_config.hpp: constants from StereoConfig and derive_widths), reads
// hls::streams and writes hls::streams in raster order (the aggregation works in chain order
// inside), and is meant to run under DATAFLOW with its main loop pipelined at II = 1. The generated
// top's <top>_pipeline chains them: each stage of the plan (gen/pipeline/stages/, hls_calls) emits
// its calls and the streams between them, only those the configuration needs. Stages, in
// data-flow order:
//
//   read_pair ─ window (N) ─ transform ─ window (cost window) ─ cost
//     ─ aggregate ([right_to_left ─] to_chain_order ─ aggregate_chains ─ from_chain_order) ─ select
//     ─ [LR check] ─ [window (median) ─ median] ─ [gap fill] ─ write_words
//   LR1: select also finds the match-side disparities from the base side's sums.
//   LR2: match_costs (the base costs regrouped per match pixel) ─ aggregate ─ select_match.
//   Right view: the LR check passes Dm on ─ write_words (its own stream).
//
// Time base: one pixel takes G = dmax / uf loop iterations ("groups"), each handling uf disparities
// packed into one word, so a frame takes about W * H * dmax / uf cycles plus the fill latency.
#pragma once

#include <type_traits>

#if __has_include(<ap_int.h>) && __has_include(<hls_stream.h>) && __has_include(<ap_axi_sdata.h>)
#ifndef AP_INT_MAX_W
#define AP_INT_MAX_W 8192  // packed words of uf path costs or sums can exceed the default 1024 bits
#endif
#include <ap_axi_sdata.h>
#include <ap_int.h>
#include <hls_stream.h>
#else
#include "fpstereo_hls_compat.h"
#endif

namespace fpstereo_hls {

enum class Cost { Census, Rank, Sad, Zsad, Shd };
enum class Lr { None, Lr1, Lr2 };

using Pixel = ap_uint<8>;
using VideoIn = ap_axiu<8, 1, 1, 1>;

// Runtime sizes and parameters (AXI4-Lite registers), clamped to what the hardware was built for:
// the path-cost widths hold P2 up to the configured value, the line buffers the configured width.
struct Frame {
  int width, height;
};
template <class C>
Frame clamp_frame(int width, int height) {
  const int w = width < C::kMinWidth ? C::kMinWidth : width > C::kMaxWidth ? C::kMaxWidth : width;
  const int h = height < 1 ? 1 : height > C::kMaxHeight ? C::kMaxHeight : height;
  return Frame{w, h};
}
inline int clamp_int(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

// ---------------------------------------------------------------------------------------------
// Feature and word types of a configuration.

template <int N>
struct CensusCodeOf {
  using type = ap_uint<N * N - 1>;
};
// ZSAD compares pixels after subtracting their window means, so each pixel carries its mean.
struct ZsadPixel {
  Pixel pixel;
  Pixel mean;
};

template <class C>
using CensusCode = typename CensusCodeOf<C::kWindow>::type;
// The code a census, SHD or rank cost compares: a census code or a rank value.
template <class C>
using Code = std::conditional_t<C::kCost == Cost::Census || C::kCost == Cost::Shd, CensusCode<C>,
                                ap_uint<C::kCodeBits>>;
// What the cost window slides over: codes (census, SHD, rank), with the fused cost the pixel's
// feature above the code (C::kFusedFeatureBits, fused_feature), pixels (SAD) or pixels with
// their means (ZSAD).
template <class C>
using Feature = std::conditional_t<C::kCost == Cost::Census || C::kCost == Cost::Shd || C::kCost == Cost::Rank,
                                   ap_uint<C::kCodeBits + C::kFusedFeatureBits>,
                                   std::conditional_t<C::kCost == Cost::Zsad, ZsadPixel, Pixel>>;
// With adaptive P2 a cost word carries, above its uf costs, the pixel's P2 for each of the four
// paths, C::kPenaltyBits (penalty_stage, attach_penalties; the aggregation's base instance reads them).
template <class C>
using Penalties = ap_uint<4 * C::kPathCostBits>;  // a pixel's P2 on the 0, 45, 90, 135 degree paths
template <class C>
using CostWord = ap_uint<C::kUf * C::kCostBits + C::kPenaltyBits>;  // uf costs, disparity g * uf + lane
template <class C>
using PathWord = ap_uint<C::kUf * C::kPathCostBits>;
// With the 180-degree path (C::kPaths bit 4) the aggregation's chains read each cost word with the
// pixel's 180-degree path costs beside it (right_to_left); without it, the cost word alone.
template <class C>
constexpr bool kRightToLeft = (C::kPaths & 16u) != 0;
template <class C>
struct CostWithPath {
  CostWord<C> cost;
  PathWord<C> path;  // L_180 of the word's uf disparities
};
template <class C>
using ChainWord = std::conditional_t<kRightToLeft<C>, CostWithPath<C>, CostWord<C>>;
template <class C>
const CostWord<C>& cost_of(const CostWord<C>& word) {
  return word;
}
template <class C>
const CostWord<C>& cost_of(const CostWithPath<C>& word) {
  return word.cost;
}
template <class C>
using SumWord = ap_uint<C::kUf * C::kSumBits>;
template <class C>
using Word = ap_uint<C::kWordBits>;  // the output word: disparity, invalid flag on top
// The winner-take-all's word: with sub-pixel output and a left-right check, the whole D above the
// word, C::kWholeBits (the check compares whole disparities, semantics section 5).
template <class C>
using BaseWord = ap_uint<C::kWordBits + C::kWholeBits>;
template <class C>
using VideoOut = ap_axiu<C::kOutBits, 1, 1, 1>;

template <class T, int N>
struct Window {
  T v[N][N];  // v[row][column], row 0 on top
};

// The value of a window position outside the image (section 1: zero extension).
template <class T>
T zero_value() {
  return T(0);
}
template <>
inline ZsadPixel zero_value<ZsadPixel>() {
  ZsadPixel p;
  p.pixel = 0;
  p.mean = 0;
  return p;
}

// ---------------------------------------------------------------------------------------------
// Input: the left and right AXI4-Stream pixels, one of each per pixel (tuser/tlast not
// interpreted: the frame size comes from the registers).
template <class C>
void read_pair(hls::stream<VideoIn>& left_in, hls::stream<VideoIn>& right_in, hls::stream<Pixel>& left,
               hls::stream<Pixel>& right, int width, int height) {
  const Frame f = clamp_frame<C>(width, height);
read_pair_pixels:
  for (int i = 0; i < f.width * f.height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    left.write(left_in.read().data);
    right.write(right_in.read().data);
  }
}

// Adaptive P2 reads the left pixels beside the cost's windows.
template <class C>
void fork_pixels(hls::stream<Pixel>& in, hls::stream<Pixel>& a, hls::stream<Pixel>& b, int width, int height) {
fork_pixels_loop:
  for (int i = 0; i < width * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    const Pixel p = in.read();
    a.write(p);
    b.write(p);
  }
}

// ---------------------------------------------------------------------------------------------
// Section 1: an N x N window around every pixel, in raster order, positions outside the image
// replaced by `fill` (0 for the cost stages, the invalid word for the median). N - 1 line buffers
// and a register window shifted by one column per pixel; the centre lags the input by r rows and
// r pixels, so the loop runs r extra rows and columns with fill as input. Positions outside the
// image are masked by comparing with the centre, so stale line-buffer contents never matter.
template <class T, int N, int kMaxWidth>
void window_stage(hls::stream<T>& in, hls::stream<Window<T, N>>& out, int width, int height, T fill) {
  constexpr int r = N / 2;
  constexpr int kLines = N > 1 ? N - 1 : 1;
  T lines[kLines][kMaxWidth];
#pragma HLS ARRAY_PARTITION variable = lines complete dim = 1
#pragma HLS DEPENDENCE variable = lines inter false
  Window<T, N> win;
#pragma HLS ARRAY_PARTITION variable = win.v complete dim = 0
  int x = 0, y = 0;
window_pixels:
  for (int i = 0; i < (width + r) * (height + r); ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (kMaxWidth + r) * (1 + r)
    T column[N];
#pragma HLS ARRAY_PARTITION variable = column complete
    const T pixel = (x < width && y < height) ? in.read() : fill;
    if (x < width) {
      for (int k = 0; k < N - 1; ++k) column[k] = lines[k][x];
      column[N - 1] = pixel;
      for (int k = 0; k + 1 < N - 1; ++k) lines[k][x] = column[k + 1];
      if (N > 1) lines[kLines - 1][x] = pixel;
    } else {
      for (int k = 0; k < N; ++k) column[k] = fill;
    }
    for (int row = 0; row < N; ++row) {
      for (int col = 0; col + 1 < N; ++col) win.v[row][col] = win.v[row][col + 1];
      win.v[row][N - 1] = column[row];
    }
    if (x >= r && y >= r) {
      const int xc = x - r, yc = y - r;
      Window<T, N> masked;
      for (int row = 0; row < N; ++row)
        for (int col = 0; col < N; ++col) {
          const int xi = xc + col - r, yi = yc + row - r;
          const bool inside = xi >= 0 && xi < width && yi >= 0 && yi < height;
          masked.v[row][col] = inside ? win.v[row][col] : fill;
        }
      out.write(masked);
    }
    if (++x == width + r) {
      x = 0;
      ++y;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Section 2: transforms. Census: one bit per neighbour, 1 iff centre > neighbour, the first window
// position in the most significant bit. Rank: neighbours below the centre. ZSAD: the pixel and
// floor(window sum / N^2). The fused cost's feature (semantics section 2, "Fused cost"): the
// centre pixel, or I(x+1) - I(x-1) on the centre row (the window reads 0 outside the image) in
// two's complement.
template <class C>
Feature<C> with_fused_feature(const Code<C>& code, const Window<Pixel, C::kWindow>& w) {
  Feature<C> f = code;
  if constexpr (C::kFusedFeatureBits != 0) {
    constexpr int r = C::kWindow / 2, mask = (1 << C::kFusedFeatureBits) - 1;
    const int feature = C::kFusedGradient ? int(w.v[r][r + 1]) - int(w.v[r][r - 1]) : int(w.v[r][r]);
    f.range(C::kCodeBits + C::kFusedFeatureBits - 1, C::kCodeBits) = feature & mask;
  }
  return f;
}

template <class C>
Feature<C> transform_window(const Window<Pixel, C::kWindow>& w) {
  constexpr int N = C::kWindow, r = N / 2;
  const int centre = w.v[r][r];
  if constexpr (C::kCost == Cost::Census || C::kCost == Cost::Shd) {
    CensusCode<C> code = 0;
    int bit = N * N - 2;
    for (int row = 0; row < N; ++row)
      for (int col = 0; col < N; ++col) {
        if (row == r && col == r) continue;
        code.range(bit, bit) = centre > int(w.v[row][col]) ? 1 : 0;
        --bit;
      }
    return with_fused_feature<C>(code, w);
  } else if constexpr (C::kCost == Cost::Rank) {
    int rank = 0;
    for (int row = 0; row < N; ++row)
      for (int col = 0; col < N; ++col)
        if (!(row == r && col == r)) rank += int(w.v[row][col]) < centre;
    return with_fused_feature<C>(Code<C>(rank), w);
  } else {
    int sum = 0;
    for (int row = 0; row < N; ++row)
      for (int col = 0; col < N; ++col) sum += int(w.v[row][col]);
    ZsadPixel p;
    p.pixel = centre;
    p.mean = sum / (N * N);
    return p;
  }
}

template <class C>
void transform_stage(hls::stream<Window<Pixel, C::kWindow>>& in, hls::stream<Feature<C>>& out, int width,
                     int height) {
transform_pixels:
  for (int i = 0; i < width * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    out.write(transform_window<C>(in.read()));
  }
}

// Point costs between a base and a match feature.
template <int W>
int hamming(const ap_uint<W>& a, const ap_uint<W>& b) {
  int distance = 0;
  for (int i = 0; i < W; ++i) distance += bool(a[i]) != bool(b[i]);
  return distance;
}
inline int abs_diff(int a, int b) { return a > b ? a - b : b - a; }

// The fused cost's pixel-wise term of two window centres (semantics section 2, "Fused cost"):
// floor(k * min(|F_B - F_M|, T) / 8), 0 without the fused cost.
template <class C>
int fused_feature_value(const Feature<C>& f) {
  const int v = int(f.range(C::kCodeBits + C::kFusedFeatureBits - 1, C::kCodeBits));
  return C::kFusedGradient && v >= 256 ? v - 512 : v;  // the gradient's two's complement
}
template <class C>
int fused_term(const Feature<C>& base, const Feature<C>& match) {
  if constexpr (C::kFusedFeatureBits == 0) {
    return 0;
  } else {
    const int diff = abs_diff(fused_feature_value<C>(base), fused_feature_value<C>(match));
    return C::kFusedWeight * (diff < C::kFusedTrunc ? diff : C::kFusedTrunc) / 8;
  }
}

// The cost of the current pixel against the match window that spans history[at .. at + 2r]
// (history[j] is a match column of the cost window, r its radius, the newest at j = 0), with the
// fused cost's term of the two windows' centres.
template <class C>
int window_cost(const Window<Feature<C>, C::kCostWindow>& base,
                const Feature<C> history[][C::kCostWindow], int at) {
  constexpr int K = C::kCostWindow, r = K / 2;
  int sum = 0;
  for (int row = 0; row < K; ++row)
    for (int col = 0; col < K; ++col) {
      const Feature<C>& b = base.v[row][col];
      const Feature<C>& m = history[at + 2 * r - col][row];
      if constexpr (C::kCost == Cost::Census || C::kCost == Cost::Shd) {
        sum += hamming(Code<C>(b), Code<C>(m));
      } else if constexpr (C::kCost == Cost::Zsad) {
        const int base_mean = base.v[r][r].mean, match_mean = history[at + r][r].mean;
        sum += abs_diff(int(b.pixel) - base_mean, int(m.pixel) - match_mean);
      } else if constexpr (C::kCost == Cost::Rank) {
        sum += abs_diff(int(Code<C>(b)), int(Code<C>(m)));
      } else {
        sum += abs_diff(int(b), int(m));
      }
    }
  return sum + fused_term<C>(base.v[r][r], history[at + r][r]);
}

// min-disp m (semantics section 2): index d pairs base pixel x with match pixel x - m - d. With
// m > 0 the match pixels lie m further left, with m < 0 up to -m right of x: the match side then
// runs match_lead = -m pixels ahead of the base side (cost_stage, lr_check).
template <class C>
constexpr int match_lead() {
  return C::kMinDisp < 0 ? -C::kMinDisp : 0;
}

// C(x, y, d) for every pixel, G words of uf costs each; Cmax where the match pixel x - m - d leaves
// the row. The match columns live in a register history shifted once per match window, newest
// first; at a row's start it is refilled from the first window (columns left of the image are
// zero). The newest column is x + r + lead (lead = match_lead), so the match window of x - m - d
// starts at history[d + max(m, 0)]: dmax + K - 1 + max(m, 0) columns. With m < 0 each row opens
// with lead iterations that only shift match windows in (W * G + lead iterations per row), and
// past the row's last match window zero columns enter (outside the image). With LR2 the costs also
// go to the match side.
template <class C>
void cost_stage(hls::stream<Window<Feature<C>, C::kCostWindow>>& base_in,
                hls::stream<Window<Feature<C>, C::kCostWindow>>& match_in, hls::stream<CostWord<C>>& out,
                hls::stream<CostWord<C>>& match_side_out, int width, int height) {
  constexpr int K = C::kCostWindow, G = C::kGroups, kLead = match_lead<C>();
  constexpr int kShift = C::kMinDisp > 0 ? C::kMinDisp : 0, kHistory = C::kDmax + K - 1 + kShift;
  Feature<C> history[kHistory][K];
#pragma HLS ARRAY_PARTITION variable = history complete dim = 0
  Window<Feature<C>, K> base;
  int u = 0, g = 0;  // u: the newest match window in the row; base pixel x = u - lead
cost_groups:
  for (int i = 0; i < height * (width * G + kLead); ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxHeight * (C::kMaxWidth * C::kGroups + kLead)
    const bool ahead = u < kLead;  // a match window before the row's first base pixel
    if (ahead || g == 0) {
      if (!ahead) base = base_in.read();
      Window<Feature<C>, K> match;
      for (int row = 0; row < K; ++row)
        for (int col = 0; col < K; ++col) match.v[row][col] = zero_value<Feature<C>>();
      if (u < width) match = match_in.read();
      for (int j = kHistory - 1; j >= 0; --j)
        for (int row = 0; row < K; ++row) {
          if (u == 0)
            history[j][row] = j < K ? match.v[row][K - 1 - j] : zero_value<Feature<C>>();
          else
            history[j][row] = j == 0 ? match.v[row][K - 1] : history[j - 1][row];
        }
    }
    if (ahead) {
      ++u;
    } else {
      const int x = u - kLead;
      CostWord<C> word = 0;
      for (int lane = 0; lane < C::kUf; ++lane) {
#pragma HLS UNROLL
        const int d = g * C::kUf + lane, xm = x - C::kMinDisp - d;
        const int cost = xm < 0 || xm >= width ? C::kCostMax : window_cost<C>(base, history, d + kShift);
        word.range((lane + 1) * C::kCostBits - 1, lane * C::kCostBits) = cost;
      }
      out.write(word);
      if (C::kLr == Lr::Lr2) match_side_out.write(word);
      if (++g == G) {
        g = 0;
        if (++u == width + kLead) u = 0;
      }
    }
  }
}

// Section 3, adaptive P2: each pixel's P2 on the four paths, max(P1, P2 - k * |I(p) - I(p-r)| / 4),
// from the left pixels in raster order (the row above in a line buffer); where p - r lies outside
// the image the aggregation does not use it. P1 and P2 are clamped as the aggregation clamps them.
template <class C>
void penalty_stage(hls::stream<Pixel>& pixels, hls::stream<Penalties<C>>& out, int width,
                   int height, int p1, int p2) {
  p2 = clamp_int(p2, 0, C::kP2);
  p1 = clamp_int(p1, 0, p2);
  Pixel above[C::kMaxWidth] = {};  // at pixel x: row y - 1 from x on, row y before x
  Pixel left = 0, above_left = 0;
  int x = 0;
penalty_pixels:
  for (int i = 0; i < width * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    const Pixel centre = pixels.read();
    const Pixel up = above[x], up_right = above[x + 1 < width ? x + 1 : x];
    const Pixel before[4] = {left, above_left, up, up_right};  // 0, 45, 90, 135 degrees
    Penalties<C> word = 0;
    for (int r = 0; r < 4; ++r) {
      const int step = int(centre) > int(before[r]) ? int(centre) - int(before[r]) : int(before[r]) - int(centre);
      const int lowered = p2 - ((C::kP2Adapt * step) >> 2);
      word.range((r + 1) * C::kPathCostBits - 1, r * C::kPathCostBits) = lowered > p1 ? lowered : p1;
    }
    out.write(word);
    above[x] = centre;
    above_left = up;
    left = centre;
    if (++x == width) x = 0;
  }
}

// The pixel's penalties above each of its G cost words.
template <class C>
void attach_penalties(hls::stream<CostWord<C>>& costs, hls::stream<Penalties<C>>& penalties,
                      hls::stream<CostWord<C>>& out, int width, int height) {
  constexpr int kCostsBits = C::kUf * C::kCostBits;
  Penalties<C> penalty = 0;
  int g = 0;
attach_groups:
  for (int i = 0; i < width * height * C::kGroups; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight * C::kGroups
    if (g == 0) penalty = penalties.read();
    CostWord<C> word = costs.read();
    word.range(kCostsBits + C::kPenaltyBits - 1, kCostsBits) = penalty;
    out.write(word);
    if (++g == C::kGroups) g = 0;
  }
}

// Section 5, LR2: the match side's cost of match pixel x' at index d is the base cost
// C(x' + m + d, d) (Cmax outside the row). Lane l of base word (x, g) goes to bank l at slot
// x mod dmax, so every lane of match word (x', g) is one read in its own bank. Match pixel x' is
// complete once base pixel x' + lag has arrived (lag = m + dmax - 1; its base pixels are the dmax
// up to that one, still in the banks): it leaves at pixel time t = x' + lag, while base pixel t
// arrives. A row runs t from min(lag, 0) to max(W, W + lag) - 1, W + |lag| pixel times: with
// lag < 0 the first -lag match pixels have no base pixel in the row (all Cmax).
template <class C>
void match_costs(hls::stream<CostWord<C>>& base_costs, hls::stream<CostWord<C>>& out, int width, int height) {
  constexpr int G = C::kGroups, D = C::kDmax, kLag = C::kMinDisp + C::kDmax - 1;
  constexpr int kExtra = kLag < 0 ? -kLag : kLag;
  ap_uint<C::kCostBits> banks[C::kUf][D][G];
#pragma HLS ARRAY_PARTITION variable = banks complete dim = 1
#pragma HLS DEPENDENCE variable = banks inter false
match_cost_rows:
  for (int y = 0; y < height; ++y) {
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxHeight
    int t = kLag < 0 ? kLag : 0, g = 0;
  match_cost_groups:
    for (int i = 0; i < (width + kExtra) * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (C::kMaxWidth + kExtra) * C::kGroups
      if (t >= 0 && t < width) {
        const CostWord<C> word = base_costs.read();
        for (int lane = 0; lane < C::kUf; ++lane)
          banks[lane][t % D][g] = word.range((lane + 1) * C::kCostBits - 1, lane * C::kCostBits);
      }
      const int xm = t - kLag;
      if (xm >= 0 && xm < width) {
        CostWord<C> word = 0;
        for (int lane = 0; lane < C::kUf; ++lane) {
          const int xb = xm + C::kMinDisp + g * C::kUf + lane;
          const bool inside = xb >= 0 && xb < width;
          const int cost = inside ? int(banks[lane][(inside ? xb : 0) % D][g]) : C::kCostMax;
          word.range((lane + 1) * C::kCostBits - 1, lane * C::kCostBits) = cost;
        }
        out.write(word);
      }
      if (++g == G) {
        g = 0;
        ++t;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Section 3: path costs and their sum.
//
// L(p, d) = C(p, d) + min(L(p-r, d), L(p-r, d-1) + P1, L(p-r, d+1) + P1, m + P2) - m, written as
// C + (t - m) so no intermediate exceeds the path-cost width.
inline int path_step(int cost, int pred, bool has_lower, int lower, bool has_upper, int upper, int pred_min,
                     int p1, int p2) {
  int t = pred < pred_min + p2 ? pred : pred_min + p2;
  if (has_lower && lower + p1 < t) t = lower + p1;
  if (has_upper && upper + p1 < t) t = upper + p1;
  return cost + (t - pred_min);
}

template <class C>
int lane_of(const PathWord<C>& w, int lane) {
  return int(w.range((lane + 1) * C::kPathCostBits - 1, lane * C::kPathCostBits));
}

// One word of a path: L for the uf disparities of group g, from the predecessor's words of groups
// g - 1, g and g + 1 (the d +- 1 neighbours across the group borders) and its minimum; L = C at a
// path start. Adds L to the sums and returns the word's minimum in word_min.
template <class C>
PathWord<C> path_word(const CostWord<C>& costs, int g, bool has_pred, const PathWord<C>& lower_word,
                      const PathWord<C>& centre, const PathWord<C>& upper_word, int pred_min, int p1, int p2,
                      int sum[C::kUf], int& word_min) {
  constexpr int U = C::kUf;
  PathWord<C> word = 0;
  for (int lane = 0; lane < U; ++lane) {
    const int d = g * U + lane;
    const int cost = int(costs.range((lane + 1) * C::kCostBits - 1, lane * C::kCostBits));
    int l = cost;
    if (has_pred) {
      const int lower = lane > 0 ? lane_of<C>(centre, lane - 1) : lane_of<C>(lower_word, U - 1);
      const int upper = lane < U - 1 ? lane_of<C>(centre, lane + 1) : lane_of<C>(upper_word, 0);
      l = path_step(cost, lane_of<C>(centre, lane), d > 0, lower, d < C::kDmax - 1, upper, pred_min, p1, p2);
    }
    word.range((lane + 1) * C::kPathCostBits - 1, lane * C::kPathCostBits) = l;
    sum[lane] += l;
    if (lane == 0 || l < word_min) word_min = l;
  }
  return word;
}

// The 0-degree loop: pixel x needs all of L(x-1, .) and their minimum, so in raster order the
// minimum tree of one pixel would feed the next pixel's first group in the next cycle. As in the
// paper (interleaving and reordering) and the RTL (docs/architecture.md, with K = 2 here), each
// row is cut into two halves of h = ceil(W / 2) pixels processed by two interleaved chains: in
// row-time t, slot j, chain k = j mod 2 processes pixel x = k * h + j / 2 of row t - k. Consecutive
// slots belong to different chains, so a chain's next pixel starts G + 1 iterations after its
// previous pixel's last group. Every predecessor is finished in time: (x-1, row) is the chain's
// previous pixel, or for the second half's first pixel the first chain's last one, a row-time
// earlier; the row above was finished a row-time earlier, or at the halves' border by the other
// chain earlier in the same row-time.
struct Chains {
  int half, slots;  // h, and the slots of a row-time (2h: the last is a bubble when W is odd)
  explicit Chains(int width) : half((width + 1) / 2), slots(2 * ((width + 1) / 2)) {}
  int chain(int slot) const { return slot & 1; }
  int x(int slot) const { return chain(slot) * half + slot / 2; }
  // The same slots from the row's end (right_to_left): chain 0 on the right half, from x = 2h - 1
  // (a bubble when W is odd) down, chain 1 on the left half.
  int mirrored_x(int slot) const { return slots - 1 - x(slot); }
  // Steps a chain-order loop to its next iteration: group g of slot `slot` in row-time t.
  void advance(int groups, int& g, int& slot, int& t) const {
    if (++g == groups) {
      g = 0;
      if (++slot == slots) {
        slot = 0;
        ++t;
      }
    }
  }
};

// Costs from raster order to chain order, one row-time behind: row t's pixels are kept (bank
// t mod 2) for the first chain now and the second chain in the next row-time.
template <class C, class T>
void to_chain_order(hls::stream<T>& in, hls::stream<T>& out, int width, int height) {
  constexpr int G = C::kGroups;
  const Chains chains(width);
  T banks[2][C::kMaxWidth * G];
#pragma HLS ARRAY_PARTITION variable = banks complete dim = 1
#pragma HLS DEPENDENCE variable = banks inter false
  int t = 0, slot = 0, g = 0;
to_chain_groups:
  for (int i = 0; i < (height + 1) * chains.slots * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (C::kMaxHeight + 1) * (C::kMaxWidth + 1) * C::kGroups
    if (t < height && slot < width) banks[t & 1][slot * G + g] = in.read();
    const int x = chains.x(slot), row = t - chains.chain(slot);
    if (row >= 0 && row < height && x < width) out.write(banks[row & 1][x * G + g]);
    chains.advance(G, g, slot, t);
  }
}

// Sums from chain order back to raster order: row t - 1 leaves during row-time t, its first half
// from the bank written a row-time earlier, its second half just after the second chain wrote it.
template <class C>
void from_chain_order(hls::stream<SumWord<C>>& in, hls::stream<SumWord<C>>& out, int width, int height) {
  constexpr int G = C::kGroups;
  const Chains chains(width);
  SumWord<C> banks[2][C::kMaxWidth * G];
#pragma HLS ARRAY_PARTITION variable = banks complete dim = 1
#pragma HLS DEPENDENCE variable = banks inter false
  int t = 0, slot = 0, g = 0;
from_chain_groups:
  for (int i = 0; i < (height + 1) * chains.slots * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (C::kMaxHeight + 1) * (C::kMaxWidth + 1) * C::kGroups
    const int x = chains.x(slot), row = t - chains.chain(slot);
    if (row >= 0 && row < height && x < width) banks[row & 1][x * G + g] = in.read();
    if (t >= 1 && slot < width) out.write(banks[(t - 1) & 1][slot * G + g]);
    chains.advance(G, g, slot, t);
  }
}

// One word of a path whose predecessor is the chain's previous pixel (0 and 180 degrees), from
// that pixel's last G + 1 words (own, newest first; pushed) and minimum (pred_min; replaced by
// this pixel's after its last group, running_min collecting it over the groups).
template <class C>
PathWord<C> chain_path_word(const CostWord<C>& cost_word, int g, bool has_pred, PathWord<C> own[C::kGroups + 1],
                            int& pred_min, int& running_min, int p1, int p2, int sum[C::kUf]) {
  constexpr int G = C::kGroups;
  int word_min = 0;
  const PathWord<C> word = path_word<C>(cost_word, g, has_pred, own[G], own[G - 1], own[G >= 2 ? G - 2 : 0],
                                        pred_min, p1, p2, sum, word_min);
  running_min = g == 0 || word_min < running_min ? word_min : running_min;
  for (int k = G; k > 0; --k) own[k] = own[k - 1];
  own[0] = word;
  if (g == G - 1) pred_min = running_min;
  return word;
}

// The path costs in chain order. The rows above (45, 90, 135 degrees: dx = -1, 0, +1) are packed
// rows in block RAM, W * G words of uf path costs per path, ping-pong by row parity (the two chains
// work on two rows), with the per-pixel minima beside them; a read never meets a write of the same
// word closer than half a row (DEPENDENCE inter false). The 0-degree state (the previous pixel's
// last G + 1 words and its minimum) belongs to the row, so it is kept per row parity: the second
// chain takes over the row where the first one stopped a row-time earlier.
template <class C, int kInstance>
void aggregate_chains(hls::stream<ChainWord<C>>& costs, hls::stream<SumWord<C>>& sums, int width, int height,
                      int p1, int p2) {
  constexpr int G = C::kGroups, U = C::kUf;
  constexpr int kUpperDx[3] = {-1, 0, 1};
  constexpr unsigned kUpperMask[3] = {2u, 4u, 8u};  // 45, 90, 135 (config.hpp's PathMask)
  constexpr bool kPath0 = C::kPaths & 1u;
  p2 = clamp_int(p2, 0, C::kP2);
  p1 = clamp_int(p1, 0, p2);
  const Chains chains(width);

  PathWord<C> rows[3][2][C::kMaxWidth * G];
#pragma HLS ARRAY_PARTITION variable = rows complete dim = 1
#pragma HLS ARRAY_PARTITION variable = rows complete dim = 2
#pragma HLS ARRAY_PARTITION variable = rows cyclic factor = 3 dim = 3
#pragma HLS BIND_STORAGE variable = rows type = ram_2p impl = bram
#pragma HLS DEPENDENCE variable = rows inter false
  ap_uint<C::kPathCostBits> minima[3][2][C::kMaxWidth];
#pragma HLS ARRAY_PARTITION variable = minima complete dim = 1
#pragma HLS ARRAY_PARTITION variable = minima complete dim = 2
#pragma HLS DEPENDENCE variable = minima inter false
  PathWord<C> left_words[2][G + 1];  // per row parity: the 0-degree path's last G + 1 words, newest first
  int left_min[2] = {};
#pragma HLS ARRAY_PARTITION variable = left_words complete dim = 0
#pragma HLS ARRAY_PARTITION variable = left_min complete
  // The two chains alternate pixel by pixel: a chain's 0-degree state is read again at least
  // G + 1 iterations after it was written.
#pragma HLS DEPENDENCE variable = left_words inter true distance = G + 1
#pragma HLS DEPENDENCE variable = left_min inter true distance = G + 1
  int running_min[4] = {};  // over the groups of the current pixel: 0 degrees, then 45, 90, 135

  int t = 0, slot = 0, g = 0;
aggregate_groups:
  for (int i = 0; i < (height + 1) * chains.slots * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (C::kMaxHeight + 1) * (C::kMaxWidth + 1) * C::kGroups
    const int x = chains.x(slot), row = t - chains.chain(slot);
    if (row >= 0 && row < height && x < width) {
      const int parity = row & 1;
      const ChainWord<C> chain_word = costs.read();
      const CostWord<C>& cost_word = cost_of<C>(chain_word);
      // P2 on the four paths: the base instance's adaptive penalties, or the register.
      int path_p2[4];
      for (int p = 0; p < 4; ++p)
        path_p2[p] = kInstance == 0 && C::kP2Adapt != 0
                         ? int(cost_word.range(U * C::kCostBits + (p + 1) * C::kPathCostBits - 1,
                                               U * C::kCostBits + p * C::kPathCostBits))
                         : p2;
      int sum[U];
      for (int lane = 0; lane < U; ++lane) sum[lane] = 0;
      if constexpr (kRightToLeft<C>)  // the sums start from L_180
        for (int lane = 0; lane < U; ++lane) sum[lane] = lane_of<C>(chain_word.path, lane);

      if (kPath0)
        chain_path_word<C>(cost_word, g, x > 0, left_words[parity], left_min[parity], running_min[0], p1,
                           path_p2[0], sum);

      for (int p = 0; p < 3; ++p) {
        if (!(C::kPaths & kUpperMask[p])) continue;
        const int px = x + kUpperDx[p];
        const bool has_pred = row > 0 && px >= 0 && px < width;
        const PathWord<C>* above = rows[p][1 - parity];
        const int at = (has_pred ? px : 0) * G + g;
        int word_min = 0;
        const PathWord<C> word = path_word<C>(
            cost_word, g, has_pred, above[g > 0 ? at - 1 : at], above[at], above[g < G - 1 ? at + 1 : at],
            int(minima[p][1 - parity][has_pred ? px : 0]), p1, path_p2[p + 1], sum, word_min);
        rows[p][parity][x * G + g] = word;
        running_min[p + 1] = g == 0 || word_min < running_min[p + 1] ? word_min : running_min[p + 1];
        if (g == G - 1) minima[p][parity][x] = running_min[p + 1];
      }

      SumWord<C> sum_word = 0;
      for (int lane = 0; lane < U; ++lane)
        sum_word.range((lane + 1) * C::kSumBits - 1, lane * C::kSumBits) = sum[lane];
      sums.write(sum_word);
    }
    chains.advance(G, g, slot, t);
  }
}

// Section 3, the 180-degree path: L(x, y) against (x + 1, y), from each row's last pixel to its
// first once the row's costs are all in. P2 of the pair (x, x + 1) is the 0-degree P2 of x + 1
// (the same two intensities), which the chain's previous pixel carried. The chains of
// aggregate_chains, mirrored (Chains::mirrored_x): in row-time t, chain k works on row t - 1 - k,
// chain 1 taking the row over where chain 0 stopped a row-time earlier, so a pixel's predecessor
// is finished G + 1 iterations before it. Row t is kept (cost bank t mod 4) as it arrives; row
// t - 3, which chain 1 finished in row-time t - 1, leaves in raster order, each cost word with its
// L_180 (path bank (t - 3) mod 3). Three row-times of delay, four rows of cost words and three of
// path words.
template <class C, int kInstance>
void right_to_left(hls::stream<CostWord<C>>& in, hls::stream<CostWithPath<C>>& out, int width, int height,
                   int p1, int p2) {
  constexpr int G = C::kGroups, U = C::kUf, kCostsBits = U * C::kCostBits;
  constexpr int kCostRows = 4, kPathRows = 3, kDelay = 3;
  p2 = clamp_int(p2, 0, C::kP2);
  p1 = clamp_int(p1, 0, p2);
  const Chains chains(width);
  CostWord<C> costs[kCostRows][C::kMaxWidth * G];
#pragma HLS ARRAY_PARTITION variable = costs complete dim = 1
#pragma HLS DEPENDENCE variable = costs inter false
  PathWord<C> paths[kPathRows][C::kMaxWidth * G];
#pragma HLS ARRAY_PARTITION variable = paths complete dim = 1
#pragma HLS DEPENDENCE variable = paths inter false
  // Per row parity, as aggregate_chains' 0-degree state: the previous pixel's last G + 1 words
  // (newest first), its minimum and its 0-degree P2.
  PathWord<C> right_words[2][G + 1];
  int right_min[2] = {}, right_p2[2] = {};
#pragma HLS ARRAY_PARTITION variable = right_words complete dim = 0
#pragma HLS ARRAY_PARTITION variable = right_min complete
#pragma HLS ARRAY_PARTITION variable = right_p2 complete
#pragma HLS DEPENDENCE variable = right_words inter true distance = G + 1
#pragma HLS DEPENDENCE variable = right_min inter true distance = G + 1
#pragma HLS DEPENDENCE variable = right_p2 inter true distance = G + 1
  int running_min = 0;

  int t = 0, slot = 0, g = 0;
right_to_left_groups:
  for (int i = 0; i < (height + kDelay) * chains.slots * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (C::kMaxHeight + 3) * (C::kMaxWidth + 1) * C::kGroups
    if (t < height && slot < width) costs[t % kCostRows][slot * G + g] = in.read();
    const int x = chains.mirrored_x(slot), row = t - 1 - chains.chain(slot);
    if (row >= 0 && row < height && x < width) {
      const int parity = row & 1;
      const CostWord<C> cost_word = costs[row % kCostRows][x * G + g];
      const int pair_p2 = kInstance == 0 && C::kP2Adapt != 0 ? right_p2[parity] : p2;
      int sum[U];  // not used: the forward chains add L_180 to their sums
      for (int lane = 0; lane < U; ++lane) sum[lane] = 0;
      paths[row % kPathRows][x * G + g] = chain_path_word<C>(cost_word, g, x < width - 1, right_words[parity],
                                                            right_min[parity], running_min, p1, pair_p2, sum);
      if constexpr (kInstance == 0 && C::kP2Adapt != 0)
        if (g == G - 1) right_p2[parity] = int(cost_word.range(kCostsBits + C::kPathCostBits - 1, kCostsBits));
    }
    const int out_row = t - kDelay;
    if (out_row >= 0 && slot < width) {
      CostWithPath<C> word;
      word.cost = costs[out_row % kCostRows][slot * G + g];
      word.path = paths[out_row % kPathRows][slot * G + g];
      out.write(word);
    }
    chains.advance(G, g, slot, t);
  }
}

// Section 3 as one block for the pipeline: raster costs in, raster sums out.
template <class C, int kInstance>
void aggregate(hls::stream<CostWord<C>>& costs, hls::stream<SumWord<C>>& sums, int width, int height, int p1,
               int p2) {
#pragma HLS INLINE
  hls::stream<ChainWord<C>> chain_costs("chain_costs");
  hls::stream<SumWord<C>> chain_sums("chain_sums");
  if constexpr (kRightToLeft<C>) {
    hls::stream<CostWithPath<C>> with_paths("with_paths");
    right_to_left<C, kInstance>(costs, with_paths, width, height, p1, p2);
    to_chain_order<C>(with_paths, chain_costs, width, height);
  } else {
    to_chain_order<C>(costs, chain_costs, width, height);
  }
  aggregate_chains<C, kInstance>(chain_costs, chain_sums, width, height, p1, p2);
  from_chain_order<C>(chain_sums, sums, width, height);
}

// ---------------------------------------------------------------------------------------------
// Section 4: winner-take-all (smallest d among equal sums) and uniqueness. For uniqueness the
// four smallest (sum, d) pairs seen so far are kept in order: at most three of them (D-1, D, D+1)
// are excluded, so S2 is always among them.
template <class C>
struct Winner {
  int best_sum = 0, best_d = 0;
  int top_sum[4], top_d[4];
  int count = 0;

  // Sub-pixel (section 4): the sums offered just before and just after the winner's, which are
  // S(D - 1) and S(D + 1) since disparities come in ascending order.
  int left_sum = 0, right_sum = 0, last_sum = 0;
  bool right_due = false;

  void offer(int s, int d) {
    if (right_due) {
      right_sum = s;
      right_due = false;
    }
    if (count == 0 || s < best_sum) {
      best_sum = s;
      best_d = d;
      left_sum = last_sum;
      right_due = true;
    }
    last_sum = s;
    if (C::kUniqueness == 0 && !C::kConfidence) {
      ++count;
      return;
    }
    // Insert after every entry with a smaller or equal sum (they have smaller d).
    int at = count < 4 ? count : 4;
    for (int k = 3; k >= 0; --k)
      if (k < count && s < top_sum[k]) at = k;
    for (int k = 3; k > 0; --k)
      if (k > at) {
        top_sum[k] = top_sum[k - 1];
        top_d[k] = top_d[k - 1];
      }
    if (at < 4) {
      top_sum[at] = s;
      top_d[at] = d;
    }
    ++count;
  }
  // The winner in units of 2^-kSubpixelBits: the fit's offset rounded half away from zero, none at
  // the ends of the range.
  int refined() const {
    constexpr int k = C::kSubpixelBits;
    if (k == 0 || best_d == 0 || best_d == C::kDmax - 1) return best_d << k;
    const int num = left_sum - right_sum;
    const int half = C::kSubpixelEquiangular ? (left_sum > right_sum ? left_sum : right_sum) - best_sum
                                             : left_sum + right_sum - 2 * best_sum;
    const int offset = (((num < 0 ? -num : num) << k) + half) / (2 * half);
    return (best_d << k) + (num < 0 ? -offset : offset);
  }
  // S2: the smallest sum two or more disparities from the winner, among the four smallest (one
  // of them is once dmax >= 4 sums were offered: at most three lie within one of the winner);
  // -1 if none.
  int second() const {
    for (int k = 0; k < 4 && k < count; ++k) {
      const int distance = top_d[k] > best_d ? top_d[k] - best_d : best_d - top_d[k];
      if (distance >= 2) return top_sum[k];
    }
    return -1;
  }
  // S2 * (100 - u) < S1 * 100 makes the pixel invalid.
  bool unique(int ratio) const {
    const int s2 = second();
    if (s2 < 0) return true;
    const ap_uint<C::kUniquenessBits> second_scaled = ap_uint<C::kUniquenessBits>(s2) * (100 - ratio);
    const ap_uint<C::kUniquenessBits> first_scaled = ap_uint<C::kUniquenessBits>(best_sum) * 100;
    return !(second_scaled < first_scaled);
  }
  // Section 4: 255 (S2 - S1) / S2, 0 where S2 is 0.
  int confidence() const {
    const int s2 = second();
    return s2 <= 0 ? 0 : int((ap_uint<C::kSumBits + 8>(s2 - best_sum) * 255) / s2);
  }
};

// The base side: disparity words after uniqueness. With LR1 also Dm(x') = the smallest d
// minimising S(x' + m + d, d) over the d with x' + m + d in the row (0 if none), built up in a row
// RAM as the sums pass and sent out in order of x' as soon as final: after base pixel x' + lag
// (lag = m + dmax - 1), at the row's start where that lies left of the row (no candidates), the
// rest at the row's end (0 where x' + m >= W). A row takes W * G + min(|lag|, W) iterations.
template <class C>
void select_base(hls::stream<SumWord<C>>& sums, hls::stream<BaseWord<C>>& disparity,
                 hls::stream<Word<C>>& match_disparity, hls::stream<ap_uint<8>>& confidences, int width,
                 int height, int uniqueness) {
  constexpr int G = C::kGroups, U = C::kUf, kLag = C::kMinDisp + C::kDmax - 1;
  constexpr int kStart = kLag < 0 ? -kLag : 1, kEnd = kLag > 0 ? kLag : 1;  // trip counts
  uniqueness = clamp_int(uniqueness, 0, 99);
  int dm_sum[C::kMaxWidth];
  int dm_d[C::kMaxWidth];
#pragma HLS ARRAY_PARTITION variable = dm_sum cyclic factor = U
#pragma HLS ARRAY_PARTITION variable = dm_d cyclic factor = U
#pragma HLS DEPENDENCE variable = dm_sum inter true distance = G
#pragma HLS DEPENDENCE variable = dm_d inter true distance = G
select_rows:
  for (int y = 0; y < height; ++y) {
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxHeight
    Winner<C> winner;
    int x = 0, g = 0;
    if (C::kLr == Lr::Lr1) {
    select_lr1_row_start:
      for (int xm = 0; xm < -kLag && xm < width; ++xm) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = kStart
        match_disparity.write(0);
      }
    }
  select_groups:
    for (int i = 0; i < width * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kGroups
      const SumWord<C> word = sums.read();
      if (g == 0) winner = Winner<C>();
      for (int lane = 0; lane < U; ++lane) {
        const int d = g * U + lane;
        const int s = int(word.range((lane + 1) * C::kSumBits - 1, lane * C::kSumBits));
        winner.offer(s, d);
        // x' = x - m - d; the first candidate of x' is d = 0 or, left of the row's start, x = 0.
        const int xm = x - C::kMinDisp - d;
        if (C::kLr == Lr::Lr1 && xm >= 0 && xm < width && (d == 0 || x == 0 || s < dm_sum[xm])) {
          dm_sum[xm] = s;
          dm_d[xm] = d;
        }
      }
      if (++g == G) {
        const bool valid = C::kUniqueness == 0 || uniqueness == 0 || winner.unique(uniqueness);
        const BaseWord<C> whole = C::kWholeBits != 0 ? BaseWord<C>(winner.best_d) : BaseWord<C>(0);
        disparity.write(BaseWord<C>((whole << C::kWordBits) |
                                    BaseWord<C>(valid ? winner.refined() : C::kInvalidWord)));
        if (C::kConfidence) confidences.write(winner.confidence());
        if (C::kLr == Lr::Lr1 && x - kLag >= 0 && x - kLag < width) match_disparity.write(dm_d[x - kLag]);
        g = 0;
        ++x;
      }
    }
    if (C::kLr == Lr::Lr1) {
    select_lr1_row_end:
      for (int xm = width - kLag < 0 ? 0 : width - kLag; xm < width; ++xm) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = kEnd
        match_disparity.write(xm < width - C::kMinDisp ? int(dm_d[xm]) : 0);
      }
    }
  }
}

// LR2's match side: winner-take-all without uniqueness.
template <class C>
void select_match(hls::stream<SumWord<C>>& sums, hls::stream<Word<C>>& match_disparity, int width,
                  int height) {
  constexpr int G = C::kGroups, U = C::kUf;
  Winner<C> winner;
  int g = 0;
select_match_groups:
  for (int i = 0; i < width * height * G; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight * C::kGroups
    const SumWord<C> word = sums.read();
    if (g == 0) winner = Winner<C>();
    for (int lane = 0; lane < U; ++lane)
      winner.offer(int(word.range((lane + 1) * C::kSumBits - 1, lane * C::kSumBits)), g * U + lane);
    if (++g == G) {
      match_disparity.write(winner.best_d);
      g = 0;
    }
  }
}

// Section 5: the check of D(x) against Dm(x') at x' = x - m - D, invalid where x' leaves the row.
// Both come in raster order and Dm is kept for the row; D(x) is checked once Dm up to x + lead has
// arrived (lead = match_lead, capped at W: with m < 0, x' may lie right of x), so each row reads
// lead Dm before its first D (W + lead iterations a row). With the right view, Dm also goes to
// right_view as it arrives.
template <class C>
void lr_check(hls::stream<BaseWord<C>>& disparity, hls::stream<Word<C>>& match_disparity,
              hls::stream<Word<C>>& out, hls::stream<Word<C>>& right_view, int width, int height, int threshold) {
  constexpr int kLead = match_lead<C>();
  threshold = clamp_int(threshold, 0, 15);
  const int lead = kLead < width ? kLead : width;
  ap_uint<C::kDisparityBits> dm_row[C::kMaxWidth];
  int u = 0;  // in the row: Dm(u) arrives, D(u - lead) is checked
lr_check_pixels:
  for (int i = 0; i < (width + lead) * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = (C::kMaxWidth + kLead) * C::kMaxHeight
    if (u < width) {
      dm_row[u] = match_disparity.read();
      if (C::kRightView) right_view.write(Word<C>(dm_row[u]));
    }
    if (u >= lead) {
      const int x = u - lead;
      const BaseWord<C> in = disparity.read();
      Word<C> w = Word<C>(in.range(C::kWordBits - 1, 0));
      if (int(w) != C::kInvalidWord) {
        const int d = C::kWholeBits != 0 ? int(in >> C::kWordBits) : int(w), xm = x - C::kMinDisp - d;
        const bool inside = xm >= 0 && xm < width;
        if (!inside || abs_diff(d, int(dm_row[inside ? xm : 0])) > threshold) w = C::kInvalidWord;
      }
      out.write(w);
    }
    if (++u == width + lead) u = 0;
  }
}

// ---------------------------------------------------------------------------------------------
// Section 5a: the speckle filter. Each row's runs (valid neighbours within the range) get labels,
// which union-find joins with the labels above them; a region's pixel count, saturated at S + 1,
// lives at its root, always a label of the newest row the region reaches, so no label in use
// points into a row that has left the ring of S + 1 rows. Row y leaves once row y + S has been
// labelled: a region that still reaches row y + S spans S + 1 rows and stays, any other is closed
// and its count final. The root search is a walk of unbounded length, so this kernel does not
// reach II = 1 (the RTL's stage avoids the walk, docs/speckle-hardware.md).
template <class C>
bool speckle_connected(int a, int b) {
  const int step = a > b ? a - b : b - a;
  return a != C::kInvalidWord && b != C::kInvalidWord && step <= C::kSpeckleRange;
}

// The root of a label, halving the path on the way (a parent is never in an older row).
inline int speckle_root(int* parent, int label) {
speckle_find:
  while (parent[label] != label) {
    parent[label] = parent[parent[label]];
    label = parent[label];
  }
  return label;
}

template <class C>
void speckle_filter(hls::stream<Word<C>>& in, hls::stream<Word<C>>& out, int width, int height) {
  constexpr int kSize = C::kSpeckleSize, kRows = kSize + 1, kNoLabel = -1;
  constexpr int kBig = kSize + 1;  // a count that has passed S
  static int words[kRows][C::kMaxWidth];
  static int labels[kRows][C::kMaxWidth];  // a run's label: its row's slot * kMaxWidth + its first x
  static int parent[kRows * C::kMaxWidth], count[kRows * C::kMaxWidth];
speckle_rows:
  for (int y = 0; y < height + kSize; ++y) {
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxHeight + C::kSpeckleSize
    if (y < height) {
      const int slot = y % kRows, above = (y + kSize) % kRows;
    speckle_label:
      for (int x = 0; x < width; ++x) {
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth
        const int v = int(in.read());
        words[slot][x] = v;
        int label = kNoLabel;
        if (v != C::kInvalidWord) {
          if (x > 0 && speckle_connected<C>(words[slot][x - 1], v)) {
            label = labels[slot][x - 1];
            const int root = speckle_root(parent, label);
            count[root] = count[root] < kBig ? count[root] + 1 : kBig;
          } else {
            label = slot * C::kMaxWidth + x;
            parent[label] = label;
            count[label] = 1;
          }
          if (y > 0 && speckle_connected<C>(words[above][x], v)) {
            const int root = speckle_root(parent, label), other = speckle_root(parent, labels[above][x]);
            if (root != other) {
              parent[other] = root;
              count[root] = count[root] + count[other] < kBig ? count[root] + count[other] : kBig;
            }
          }
        }
        labels[slot][x] = label;
      }
    }
    if (y >= kSize) {
      const int slot = (y - kSize) % kRows;
    speckle_decide:
      for (int x = 0; x < width; ++x) {
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth
        const int v = words[slot][x];
        const bool speckle = v != C::kInvalidWord && count[speckle_root(parent, labels[slot][x])] <= kSize;
        out.write(Word<C>(speckle ? int(C::kInvalidWord) : v));
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Section 6: the lower median of the valid values in the window (positions outside the image
// arrive as invalid); an invalid centre stays invalid. Radix selection, as the Verilog's
// fpstereo_median_select: the median's bits from the most significant one, each decided by
// counting the values that agree with the bits found so far and have a 0 next (in sorted order
// they come first). One count over the window a bit instead of one a pair of values: M^2 (W - 1)
// narrow compares for W-bit words, where comparing every pair takes 2 M^4 full-width ones.
template <class C>
Word<C> median_of(const Window<Word<C>, C::kMedian>& w) {
  constexpr int M = C::kMedian, n = M * M, kValueBits = C::kWordBits - 1;  // below the invalid flag
  const Word<C> centre = w.v[M / 2][M / 2];
  if (int(centre) == C::kInvalidWord) return centre;
  int values[n];
  bool valid[n];
  int count = 0;
  for (int k = 0; k < n; ++k) {
    values[k] = int(w.v[k / M][k % M]);
    valid[k] = values[k] != C::kInvalidWord;
    count += valid[k];
  }
  int rank = (count - 1) / 2;  // the rank sought among the values that agree with `median` so far
  int median = 0;
  for (int b = kValueBits - 1; b >= 0; --b) {
    int zeros = 0;
    for (int k = 0; k < n; ++k)
      zeros += valid[k] && (values[k] >> (b + 1)) == (median >> (b + 1)) && ((values[k] >> b) & 1) == 0;
    if (rank >= zeros) {
      rank -= zeros;
      median |= 1 << b;
    }
  }
  return Word<C>(median);
}

template <class C>
void median_stage(hls::stream<Window<Word<C>, C::kMedian>>& in, hls::stream<Word<C>>& out, int width,
                  int height) {
median_pixels:
  for (int i = 0; i < width * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    out.write(median_of<C>(in.read()));
  }
}

// ---------------------------------------------------------------------------------------------
// Section 7: gap interpolation, one row behind. While row y arrives, each invalid run's start
// records the value that ends it and its x (the invalid word at the row's end); meanwhile row
// y - 1 is sent, runs filled from the last valid value on the left and the recorded right
// neighbour: the smaller of the two, or (kGapLinear) where they are close, the value on the line
// between them. Two row RAMs each, ping-pong by row parity.
template <class C>
void gap_fill(hls::stream<Word<C>>& in, hls::stream<Word<C>>& out, int width, int height) {
  constexpr int kInvalid = C::kInvalidWord;
  constexpr int kUnit = 1 << C::kSubpixelBits;  // words a pixel
  Word<C> rows[2][C::kMaxWidth];
  Word<C> run_end[2][C::kMaxWidth];  // at a run's start: the valid value right of the run
  int run_end_x[2][C::kMaxWidth];    // and its x
#pragma HLS ARRAY_PARTITION variable = rows complete dim = 1
#pragma HLS ARRAY_PARTITION variable = run_end complete dim = 1
#pragma HLS ARRAY_PARTITION variable = run_end_x complete dim = 1
gap_rows:
  for (int y = 0; y <= height; ++y) {
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxHeight + 1
    const int in_bank = y & 1, out_bank = 1 - in_bank;
    bool in_run = false;
    int in_run_start = 0;
    int left = kInvalid, right = kInvalid, left_x = 0, right_x = 0;
  gap_pixels:
    for (int x = 0; x < width; ++x) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth
      if (y < height) {
        const Word<C> v = in.read();
        rows[in_bank][x] = v;
        if (int(v) == kInvalid && !in_run) {
          in_run = true;
          in_run_start = x;
        } else if (int(v) != kInvalid && in_run) {
          run_end[in_bank][in_run_start] = v;
          run_end_x[in_bank][in_run_start] = x;
          in_run = false;
        }
        if (x == width - 1 && in_run) run_end[in_bank][in_run_start] = kInvalid;
      }
      if (y > 0) {
        const int v = int(rows[out_bank][x]);
        if (v != kInvalid) {
          left = v;
          left_x = x;
          right = kInvalid;
          out.write(v);
        } else {
          if (x == 0 || int(rows[out_bank][x - 1]) != kInvalid) {
            right = int(run_end[out_bank][x]);
            right_x = run_end_x[out_bank][x];
          }
          int fill = kInvalid;
          const int span = right_x - left_x, step = x - left_x;
          const int diff = left < right ? right - left : left - right;
          if (left != kInvalid && right != kInvalid && C::kGapLinear && 8 * diff <= (32 + span) * kUnit)
            fill = (left * (span - step) + right * step + span / 2) / span;
          else if (left != kInvalid && right != kInvalid)
            fill = left < right ? left : right;
          else if (left != kInvalid)
            fill = left;
          else if (right != kInvalid)
            fill = right;
          out.write(fill);
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Output: words zero-extended to the byte-aligned tdata; tuser on a frame's first pixel, tlast on
// a row's last, to any of the output streams (the disparity words' is VideoOut).
template <class Beat>
Beat video_beat(decltype(Beat::data) data, bool first, bool row_end) {
  Beat beat;
  beat.data = data;
  beat.keep = -1;
  beat.strb = -1;
  beat.user = first ? 1 : 0;
  beat.last = row_end ? 1 : 0;
  beat.id = 0;
  beat.dest = 0;
  return beat;
}

template <class C, class Beat>
void write_words(hls::stream<Word<C>>& in, hls::stream<Beat>& out, int width, int height) {
  int x = 0;
write_pixels:
  for (int i = 0; i < width * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    out.write(video_beat<Beat>(decltype(Beat::data)(in.read()), i == 0, x == width - 1));
    if (++x == width) x = 0;
  }
}

// With confidence: each word in its lane, its pixel's confidence in the 8 bits above.
template <class C>
void write_confident_words(hls::stream<Word<C>>& in, hls::stream<ap_uint<8>>& confidences,
                           hls::stream<VideoOut<C>>& out, int width, int height) {
  int x = 0;
write_confident_pixels:
  for (int i = 0; i < width * height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    const ap_uint<C::kOutBits> data =
        (ap_uint<C::kOutBits>(confidences.read()) << C::kLaneBits) | ap_uint<C::kOutBits>(in.read());
    out.write(video_beat<VideoOut<C>>(data, i == 0, x == width - 1));
    if (++x == width) x = 0;
  }
}

// ---------------------------------------------------------------------------------------------
// Memory-mapped frames for the Vitis kernel flow (XRT): a frame in memory becomes a video stream
// (the output streams' stores to memory are generated with the top, one per output stream).
template <class C>
void load_frame(const unsigned char* frame, hls::stream<VideoIn>& out, int width, int height) {
  const Frame f = clamp_frame<C>(width, height);
load_pixels:
  for (int i = 0; i < f.width * f.height; ++i) {
#pragma HLS PIPELINE II = 1
#pragma HLS LOOP_TRIPCOUNT max = C::kMaxWidth * C::kMaxHeight
    out.write(video_beat<VideoIn>(frame[i], i == 0, (i + 1) % f.width == 0));
  }
}

}  // namespace fpstereo_hls
