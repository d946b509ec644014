// Image and disparity files: loading stereo inputs, writing results (KITTI PNG, PFM, colour
// preview) and reading ground truth. Disparity maps are cv::Mat1f in pixels with NaN marking
// "no value", the one invalid marker used by evaluation.
#pragma once

#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "config.hpp"
#include "image.hpp"

namespace fpstereo {

// A missing, unreadable or unsuitable input or output file. what() is one line naming the file.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads any image OpenCV decodes and returns it as 8-bit gray (colour and alpha images are
// converted with cv::cvtColor). `role` names the image in messages, e.g. "left image".
GrayImage load_gray(const std::string& path, const std::string& role);

// Builds OpenCV's image codec registry now. It is built on first use, and registering its GDAL
// decoder aborts the process when memory runs out: a program that decodes images calls this as
// it starts, so that the registry is part of what it needs to start, not an abort mid-run.
void start_image_codecs();
// A decoded image (8-bit, 1, 3 or 4 channels) converted as load_gray converts a file; `what`
// names it in messages. Throws InputError.
GrayImage to_gray_image(const cv::Mat& decoded, const std::string& what);

// The image enlarged `factor` times in each direction (bilinear): large test frames (1080p, 4K)
// from the real pairs at hand.
GrayImage upscale(const GrayImage& image, int factor);

// Throws InputError if the two images differ in size or exceed cfg.width x cfg.height.
void check_pair(const GrayImage& left, const GrayImage& right, const StereoConfig& cfg);

// Output words (docs/semantics.md, "Output word") to disparities in pixels, NaN where invalid.
cv::Mat1f to_float_disparity(const DisparityImage& words, const StereoConfig& cfg);

// The files below as bytes, so that a command can compute every output before writing any.
std::vector<uchar> encode_pgm(const GrayImage& image);
// 8-bit values 0 .. 255 as a gray PNG.
std::vector<uchar> encode_gray_png(const DisparityImage& values);
std::vector<uchar> encode_kitti_png(const cv::Mat1f& disp);
std::vector<uchar> encode_pfm(const cv::Mat1f& disp);
std::vector<uchar> encode_colour_png(const cv::Mat1f& disp, float min_disp, float max_disp);
// PFM if `path` ends in .pfm, else a KITTI PNG: what a disparity output's name asks for.
std::vector<uchar> encode_disparity_file(const std::string& path, const cv::Mat1f& disp);

// The write_* functions write atomically too; they throw InputError naming the path.
// Binary 8-bit PGM (P5): the input format of the generated HLS test bench and host program.
void write_pgm(const GrayImage& image, const std::string& path);

// KITTI format: 16-bit PNG holding round(d * 256), 0 = invalid; a valid 0 is written as 1. A
// disparity it cannot hold (negative, or 256 and more) is an InputError, never clamped.
void write_kitti_png(const cv::Mat1f& disp, const std::string& path);
// Single-channel little-endian PFM (scale -1), rows bottom to top, +inf where invalid.
void write_pfm(const cv::Mat1f& disp, const std::string& path);
// TURBO colour map over min_disp .. max_disp, invalid pixels black, with a legend on the right.
void write_colour_png(const cv::Mat1f& disp, float min_disp, float max_disp, const std::string& path);

// Reads a ground-truth disparity map: 8/16-bit PNG or PGM, or PFM (either byte order, 1 or 3
// channels, the first one used). Stored values are divided by `scale`. `invalid_spec` says
// which stored value means "no ground truth": "0", "inf" (any non-finite value) or "none".
// Non-finite values are never disparities, so they are NaN whatever the spec.
cv::Mat1f read_disparity(const std::string& path, double scale, const std::string& invalid_spec);

}  // namespace fpstereo
