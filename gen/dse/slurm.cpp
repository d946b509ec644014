#include "slurm.hpp"

#include <fmt/core.h>

#include <cstdlib>
#include <optional>

#include "image_io.hpp"

namespace fpstereo {
namespace {

// An array variable's value; nullopt when unset, InputError when it is not a number.
std::optional<long> array_variable(const char* name) {
  const char* text = std::getenv(name);
  if (!text) return std::nullopt;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*text == '\0' || *end != '\0' || value < 0)
    throw InputError(fmt::format("--shard auto: {}={} is not a task number", name, text));
  return value;
}

}  // namespace

std::string resolve_shard(const std::string& text) {
  if (text != "auto") return text;
  const auto id = array_variable("SLURM_ARRAY_TASK_ID");
  const auto count = array_variable("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count)
    throw InputError(
        "--shard auto: SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT are not set (not a Slurm array task; "
        "give --shard i/N)");
  // --array=0-3 and --array=1-4 are both four shards; --array=0-6:2 too (steps of 2).
  const long min = array_variable("SLURM_ARRAY_TASK_MIN").value_or(0);
  const long step = array_variable("SLURM_ARRAY_TASK_STEP").value_or(1);
  const long index = step > 0 && *id >= min && (*id - min) % step == 0 ? (*id - min) / step + 1 : 0;
  if (index < 1 || index > *count)
    throw InputError(fmt::format(
        "--shard auto: task {} is not one of the {} tasks from {} in steps of {} (an array with gaps, such as "
        "--array=1,3,8, cannot be shards; give a range)",
        *id, *count, min, step));
  return fmt::format("{}/{}", index, *count);
}

}  // namespace fpstereo
