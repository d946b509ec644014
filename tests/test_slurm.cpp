// --shard auto: a Slurm array task's place in its array, from the variables Slurm sets.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <map>
#include <string>

#include "image_io.hpp"
#include "slurm.hpp"

using namespace fpstereo;

namespace {

const char* const kArrayVariables[] = {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN",
                                       "SLURM_ARRAY_TASK_STEP"};

void unset_array_variables() {
  for (const char* name : kArrayVariables) ::unsetenv(name);
}

// resolve_shard("auto") with the array variables set for the call (an empty value: unset).
std::string shard_in_task(const std::map<std::string, std::string>& variables) {
  unset_array_variables();
  for (const auto& [name, value] : variables)
    if (!value.empty()) ::setenv(name.c_str(), value.c_str(), 1);
  struct Unset {
    ~Unset() { unset_array_variables(); }
  } unset;
  return resolve_shard("auto");
}

std::map<std::string, std::string> task(const std::string& id, const std::string& count, const std::string& min,
                                        const std::string& step = "1") {
  return {{"SLURM_ARRAY_TASK_ID", id},
          {"SLURM_ARRAY_TASK_COUNT", count},
          {"SLURM_ARRAY_TASK_MIN", min},
          {"SLURM_ARRAY_TASK_STEP", step}};
}

}  // namespace

TEST_CASE("shard auto numbers the tasks of a Slurm array from 1", "[slurm]") {
  CHECK(resolve_shard("3/8") == "3/8");  // anything else is passed on as given
  CHECK(shard_in_task(task("1", "4", "1")) == "1/4");  // --array=1-4
  CHECK(shard_in_task(task("4", "4", "1")) == "4/4");
  CHECK(shard_in_task(task("0", "4", "0")) == "1/4");  // --array=0-3
  CHECK(shard_in_task(task("3", "4", "0")) == "4/4");
  CHECK(shard_in_task(task("10", "4", "4", "2")) == "4/4");  // --array=4-10:2
  CHECK(shard_in_task(task("2", "3", "", "")) == "3/3");  // MIN and STEP unset: from 0 in steps of 1
}

TEST_CASE("shard auto outside a Slurm array, or in one with gaps, is an error", "[slurm]") {
  CHECK_THROWS_WITH(shard_in_task({}), Catch::Contains("SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT are not set"));
  CHECK_THROWS_WITH(shard_in_task(task("2", "", "1")), Catch::Contains("not a Slurm array task"));
  CHECK_THROWS_WITH(shard_in_task(task("x", "4", "1")), Catch::Contains("SLURM_ARRAY_TASK_ID=x is not a task number"));
  CHECK_THROWS_WITH(shard_in_task(task("8", "3", "1")), Catch::Contains("task 8 is not one of the 3 tasks"));
  CHECK_THROWS_AS(shard_in_task(task("5", "4", "4", "2")), InputError);  // between two steps
}
