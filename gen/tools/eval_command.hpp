// `fpstereo eval DATASET_DIR`: accuracy of the pipeline (golden model) and optionally of OpenCV's
// StereoSGBM on every pair of a dataset with ground truth (pairs.csv, see gen/io/dataset.hpp).
#pragma once

#include <CLI/CLI.hpp>

namespace fpstereo {

// Adds the `eval` subcommand to `app`. Its callback runs the evaluation during app.parse() and
// sets exit_code: 0 on success, kExitBadInput (2) on bad input, after printing one line
// "fpstereo: <message>" to stderr.
void register_eval_command(CLI::App& app, int& exit_code);

}  // namespace fpstereo
