// Running on a Slurm cluster: a job array's task as a shard of a sweep (docs/cluster.md).
#pragma once

#include <string>

namespace fpstereo {

// "--shard auto" is this task's place in its Slurm job array, "i/N" with i counted from 1 in
// array order (SLURM_ARRAY_TASK_ID, _MIN, _STEP, _COUNT); any other text is returned as given.
// Throws InputError (one line) when auto is asked for outside a job array.
std::string resolve_shard(const std::string& text);

}  // namespace fpstereo
