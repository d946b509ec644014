// The row pass of background interpolation (KITTI development kit): every maximal run of
// invalid pixels is filled with the smaller of the two valid values bounding it, or with the
// one valid neighbour at a row end; an all-invalid row stays as it is. Shared by the golden
// model's gap interpolation stage and by the KITTI-style filling in evaluation.
#pragma once

namespace fpstereo {

template <class T, class IsValid>
void fill_row_gaps(T* row, int width, IsValid is_valid) {
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
    T fill;
    if (has_left && has_right)
      fill = row[run_start - 1] < row[x] ? row[run_start - 1] : row[x];
    else
      fill = has_left ? row[run_start - 1] : row[x];
    for (int i = run_start; i < x; ++i) row[i] = fill;
  }
}

}  // namespace fpstereo
