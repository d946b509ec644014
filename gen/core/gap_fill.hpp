// The row pass of background interpolation (KITTI development kit): every maximal run of
// invalid pixels is filled with the smaller of the two valid values bounding it, or with the
// one valid neighbour at a row end; an all-invalid row stays as it is. Shared by the golden
// model's gap interpolation stage and by the KITTI-style filling in evaluation.
#pragma once

#include <cstdint>
#include <cstdlib>

namespace fpstereo {

// The linear gap fill's rule (docs/semantics.md, section 7) for a run between valid words `left`
// at `xl` and `right` at `xr = xl + m`: whether the run is filled linearly (its ends differ by at
// most 4 + m / 8 pixels, `unit` words a pixel) and the word at `x` if it is.
inline bool gap_is_linear(int64_t left, int64_t right, int64_t m, int64_t unit) {
  return 8 * std::llabs(right - left) <= (32 + m) * unit;
}
inline int64_t gap_linear_word(int64_t left, int64_t right, int64_t xl, int64_t xr, int64_t x) {
  const int64_t m = xr - xl;
  return (left * (xr - x) + right * (x - xl) + m / 2) / m;
}

// `linear_unit` > 0: runs between two valid words that pass gap_is_linear are filled linearly
// (words of `linear_unit` a pixel); 0: background interpolation alone.
template <class T, class IsValid>
void fill_row_gaps(T* row, int width, IsValid is_valid, int64_t linear_unit = 0) {
  int x = 0;
  while (x < width) {
    if (is_valid(row[x])) {
      ++x;
      continue;
    }
    const int run_start = x;
    while (x < width && !is_valid(row[x])) ++x;
    const bool has_left = run_start > 0, has_right = x < width;
    if (!has_left && !has_right) return;
    if (has_left && has_right && linear_unit > 0 &&
        gap_is_linear(row[run_start - 1], row[x], x - run_start + 1, linear_unit)) {
      for (int i = run_start; i < x; ++i) row[i] = T(gap_linear_word(row[run_start - 1], row[x], run_start - 1, x, i));
      continue;
    }
    T fill;
    if (has_left && has_right)
      fill = row[run_start - 1] < row[x] ? row[run_start - 1] : row[x];
    else
      fill = has_left ? row[run_start - 1] : row[x];
    for (int i = run_start; i < x; ++i) row[i] = fill;
  }
}

}  // namespace fpstereo
