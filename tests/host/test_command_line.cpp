// The flags of `wrc run` (--shard, --merge, --fresh, --help) and of `wrc merge`, and the shard of a SLURM array task.
#include "wrc/core/error.hpp"
#include "wrc/host/command_line.hpp"

#include <doctest/doctest.h>

#include <map>
#include <string>
#include <vector>

using namespace wrc;
using wrc::host::RunFlags;
using wrc::host::take_run_flags;

namespace {

RunFlags flags(std::vector<std::string>& args, const std::map<std::string, std::string>& env = {}) {
  return take_run_flags(args, [&](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

RunFlags flags_of(std::vector<std::string> args, const std::map<std::string, std::string>& env = {}) {
  return flags(args, env);
}

}  // namespace

TEST_CASE("host flags: --shard K/N, --merge, --fresh, --help are taken out, key=value words stay") {
  std::vector<std::string> args{"step_mm=0.5", "--shard", "2/4", "out=x", "--fresh"};
  const RunFlags f = flags(args);
  CHECK(args == std::vector<std::string>{"step_mm=0.5", "out=x"});
  CHECK(f.shard == 2);
  CHECK(f.shards == 4);
  CHECK(f.shard_from == "--shard 2/4");
  CHECK(f.fresh);
  CHECK_FALSE(f.merge);
  CHECK(flags_of({"--shard=3/8"}).shard == 3);
  CHECK(flags_of({"--merge"}).merge);
  CHECK(flags_of({"-h"}).help);
  const RunFlags none = flags_of({"a=1"});
  CHECK(none.shard == 1);
  CHECK(none.shards == 1);
  CHECK(none.shard_from.empty());
  for (const char* bad : {"0/4", "5/4", "2", "2/0", "a/b", "2/4x", "-1/3"})
    CHECK_THROWS_WITH_AS(flags_of({"--shard", bad}), doctest::Contains("expected K/N with 1 <= K <= N"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"--shard"}), doctest::Contains("--shard needs K/N"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"--shrad", "1/2"}), doctest::Contains("did you mean '--shard'"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"--merge", "--shard", "1/2"}), doctest::Contains("takes no --shard"), Error);
}

TEST_CASE("host flags: a flag or an option given twice, and --fresh with --merge, are refused") {
  CHECK_THROWS_WITH_AS(flags_of({"--shard", "1/2", "--shard", "2/2"}), doctest::Contains("--shard is given twice"),
                       Error);
  CHECK_THROWS_WITH_AS(flags_of({"--shard=1/2", "--shard", "1/2"}), doctest::Contains("--shard is given twice"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"--fresh", "--fresh"}), doctest::Contains("--fresh is given twice"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"cases=10", "x=1", "cases=20"}),
                       doctest::Contains("option cases is given twice (cases=10 and cases=20)"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"--fresh", "--merge"}), doctest::Contains("give one of the two"), Error);
  CHECK(flags_of({"a=1", "b=1", "word", "word"}).shards == 1);  // other words may repeat (a plain script's arg[i])
}

TEST_CASE("host flags: a key=value word needs a key that is a Lua name, and one '='") {
  for (const char* ok : {"y_mm=3", "_x=1", "K2=", "out=a=b", "label=x y"}) CHECK_NOTHROW(flags_of({ok}));
  CHECK(flags_of({"plain", "words"}).shards == 1);  // no '=': positional, arg[1], arg[2]
  CHECK_THROWS_WITH_AS(flags_of({"=3"}), doctest::Contains("argument '=3' has no key before '='"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"="}), doctest::Contains("argument '=' has no key before '='"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"k==v"}), doctest::Contains("argument 'k==v': '=' is doubled"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"k==v"}), doctest::Contains("write k=v"), Error);
  CHECK_THROWS_WITH_AS(flags_of({"k=="}), doctest::Contains("'=' is doubled"), Error);
  for (const char* bad : {"y-mm=3", "1a=2", "a.b=1", " k=1", "k k=1", "\xc3\xa9=1"})
    CHECK_THROWS_WITH_AS(flags_of({bad}), doctest::Contains("is not a name"), Error);
  std::vector<std::string> merge_args{"=3"};
  CHECK_THROWS_WITH_AS(wrc::host::take_merge_flags(merge_args), doctest::Contains("no key before '='"), Error);
}

TEST_CASE("host flags: wrc merge STUDY.lua takes options and --help, no --shard, --merge or --fresh") {
  std::vector<std::string> args{"out=x", "plots=false"};
  const RunFlags f = wrc::host::take_merge_flags(args);
  CHECK(f.merge);
  CHECK(f.from_parts);
  CHECK(args == std::vector<std::string>{"out=x", "plots=false"});
  std::vector<std::string> help{"--help"};
  CHECK(wrc::host::take_merge_flags(help).help);
  std::vector<std::string> fresh{"--fresh"}, merge{"--merge"};
  CHECK_THROWS_WITH_AS(wrc::host::take_merge_flags(fresh), doctest::Contains("--fresh does not apply"), Error);
  CHECK_THROWS_WITH_AS(wrc::host::take_merge_flags(merge), doctest::Contains("--merge does not apply"), Error);
  std::vector<std::string> shard{"--shard", "1/2"};
  CHECK_THROWS_WITH_AS(wrc::host::take_merge_flags(shard), doctest::Contains("--shard does not apply"), Error);
  std::vector<std::string> twice{"out=a", "out=b"};
  CHECK_THROWS_WITH_AS(wrc::host::take_merge_flags(twice), doctest::Contains("option out is given twice"), Error);
}

TEST_CASE("host flags: the shard of a SLURM array task, and --shard winning over it") {
  // --array=1-4, task 3
  RunFlags f = flags_of({}, {{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "4"},
                             {"SLURM_ARRAY_TASK_COUNT", "4"}});
  CHECK(f.shard == 3);
  CHECK(f.shards == 4);
  CHECK(f.shard_from.find("SLURM_ARRAY_TASK_ID=3") != std::string::npos);
  // --array=0-3: ids from 0; the count from MAX when COUNT is missing
  f = flags_of({}, {{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_MAX", "3"}});
  CHECK(f.shard == 1);
  CHECK(f.shards == 4);
  // --array=1-7:2 (ids 1, 3, 5, 7): task 5 is shard 3 of 4
  f = flags_of({}, {{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "7"},
                    {"SLURM_ARRAY_TASK_STEP", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  CHECK(f.shard == 3);
  CHECK(f.shards == 4);
  // --array=1,3,7: ids that do not number the tasks
  CHECK_THROWS_WITH_AS(flags_of({}, {{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_MIN", "1"},
                                     {"SLURM_ARRAY_TASK_MAX", "7"}, {"SLURM_ARRAY_TASK_COUNT", "3"}}),
                       doctest::Contains("a list with gaps"), Error);
  CHECK_THROWS_WITH_AS(flags_of({}, {{"SLURM_ARRAY_TASK_ID", "x"}}), doctest::Contains("not a whole number"), Error);
  CHECK_THROWS_WITH_AS(flags_of({}, {{"SLURM_ARRAY_TASK_ID", "2"}}), doctest::Contains("pass --shard K/N"), Error);
  // --shard wins, with a note; --merge and --help ignore the array
  const std::map<std::string, std::string> task{{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_MIN", "1"},
                                                {"SLURM_ARRAY_TASK_COUNT", "4"}};
  f = flags_of({"--shard", "1/2"}, task);
  CHECK(f.shard == 1);
  CHECK(f.shards == 2);
  REQUIRE(f.notes.size() == 1);
  CHECK(f.notes[0].find("--shard 1/2 wins") != std::string::npos);
  f = flags_of({"--merge"}, task);
  CHECK(f.shards == 1);
  CHECK(f.notes.empty());
  CHECK(flags_of({"--help"}, task).shards == 1);
}
