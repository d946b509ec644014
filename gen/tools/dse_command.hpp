// `fpstereo dse DATASET...`: design-space exploration (gen/dse/dse.hpp), and `fpstereo dse merge`
// to combine the CSVs of a sharded sweep.
#pragma once

#include <CLI/CLI.hpp>

namespace fpstereo {

// Adds the `dse` subcommand (with its `merge` subcommand) to `app`. The callbacks set exit_code:
// 0 on success, kExitBadInput (2) after one line "fpstereo: <message>" on stderr.
void register_dse_command(CLI::App& app, int& exit_code);

}  // namespace fpstereo
