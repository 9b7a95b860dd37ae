// The command line of the wrc executable (command_line.hpp).
#include "wrc/host/command_line.hpp"

#include "wrc/core/error.hpp"
#include "wrc/core/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

namespace wrc::host {

namespace {

// K/N with 1 <= K <= N.
void parse_shard(const std::string& text, RunFlags& f) {
  int k = 0, n = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 1 || k > n || n > 1000000)
    fail("--shard {}: expected K/N with 1 <= K <= N (e.g. --shard 2/4)", text);
  f.shard = k;
  f.shards = n;
}

// An integer environment variable, nullopt when unset; an error when set to anything else.
std::optional<long> env_integer(const std::function<const char*(const char*)>& env, const char* name) {
  const char* v = env(name);
  if (v == nullptr || *v == 0) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(v, &end, 10);
  if (errno != 0 || *end != 0) fail("{}={} is not a whole number", name, v);
  return x;
}

// The shard of a SLURM array task: ids MIN, MIN + STEP, ..., MAX number the shards 1..N.
void shard_from_slurm(const std::function<const char*(const char*)>& env, RunFlags& f) {
  const long id = *env_integer(env, "SLURM_ARRAY_TASK_ID");
  const auto count = env_integer(env, "SLURM_ARRAY_TASK_COUNT"), max = env_integer(env, "SLURM_ARRAY_TASK_MAX");
  const long step = env_integer(env, "SLURM_ARRAY_TASK_STEP").value_or(1);
  auto min = env_integer(env, "SLURM_ARRAY_TASK_MIN");
  if (step < 1) fail("SLURM_ARRAY_TASK_STEP={} must be >= 1", step);
  if (!min && count && max) min = *max - (*count - 1) * step;
  if (!min || (!count && !max))
    fail("SLURM_ARRAY_TASK_ID={} is set without SLURM_ARRAY_TASK_MIN and SLURM_ARRAY_TASK_COUNT or _MAX: pass --shard K/N",
         id);
  const long n = count ? *count : (*max - *min) / step + 1;
  if (max && (*max - *min) / step + 1 != n)
    fail("the SLURM array's task ids {}..{} (step {}) do not number its {} tasks 1..N (a list with gaps?): submit "
         "--array=1-N or pass --shard K/N", *min, *max, step, n);
  if (id < *min || (id - *min) % step != 0 || (id - *min) / step + 1 > n)
    fail("SLURM_ARRAY_TASK_ID={} is not one of the array's ids {}, {}, ... ({} tasks)", id, *min, *min + step, n);
  f.shard = static_cast<int>((id - *min) / step + 1);
  f.shards = static_cast<int>(n);
  f.shard_from = fmt::format("SLURM_ARRAY_TASK_ID={} of the array {}-{} ({} tasks)", id, *min, *min + (n - 1) * step, n);
}

// A word with '=' is an option key=value, read by the script as arg.key: the key must be a Lua name (a letter or '_',
// then letters, digits, '_'), and a value that starts with '=' is a doubled '=' ("k==v"), not a value.
void check_option_word(const std::string& word, std::size_t eq) {
  const std::string key = word.substr(0, eq);
  if (key.empty())
    fail("argument '{}' has no key before '=': options are key=value (e.g. y_mm=3), read by the script as arg.key",
         word);
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  const bool name = letter(key[0]) && std::all_of(key.begin(), key.end(), [&](char c) {
                      return letter(c) || (c >= '0' && c <= '9');
                    });
  if (!name)
    fail("argument '{}': the key '{}' is not a name (a letter or '_', then letters, digits and '_'): options are "
         "key=value, read by the script as arg.key", word, key);
  if (eq + 1 < word.size() && word[eq + 1] == '=')
    fail("argument '{}': '=' is doubled (the value would start with '='): write {}={}", word, key,
         word.substr(std::min(word.find_first_not_of('=', eq), word.size())));
}

// The flags of a command line taken out of `args`; each flag and each key=value key at most once.
RunFlags parse_flags(std::vector<std::string>& args) {
  RunFlags f;
  std::vector<std::string> rest, seen;
  std::map<std::string, std::string> keys;
  auto once = [&](const std::string& flag) {
    if (std::find(seen.begin(), seen.end(), flag) != seen.end()) fail("{} is given twice: give it once", flag);
    seen.push_back(flag);
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 && a != "-h") {
      const auto eq = a.find('=');
      if (eq != std::string::npos) {
        check_option_word(a, eq);
        const auto [it, fresh] = keys.emplace(a.substr(0, eq), a);
        if (!fresh) fail("option {} is given twice ({} and {}): give it once", it->first, it->second, a);
      }
      rest.push_back(a);
    } else if (a == "--help" || a == "-h") {
      once("--help");
      f.help = true;
    } else if (a == "--merge") {
      once("--merge");
      f.merge = true;
    } else if (a == "--fresh") {
      once("--fresh");
      f.fresh = true;
    } else if (a == "--shard" || a.rfind("--shard=", 0) == 0) {
      once("--shard");
      if (a == "--shard" && i + 1 >= args.size()) fail("--shard needs K/N (e.g. --shard 2/4)");
      const std::string v = a == "--shard" ? args[++i] : a.substr(8);
      parse_shard(v, f);
      f.shard_from = "--shard " + v;
    } else {
      const std::string best = closest_name(a, {"--shard", "--merge", "--fresh", "--help"});
      fail("unknown flag '{}'{} (flags: --shard K/N, --merge, --fresh, --help)", a,
           best.empty() ? std::string() : " (did you mean '" + best + "'?)");
    }
  }
  args = std::move(rest);
  return f;
}

}  // namespace

RunFlags take_run_flags(std::vector<std::string>& args, const std::function<const char*(const char*)>& env) {
  RunFlags f = parse_flags(args);
  const bool shard_given = !f.shard_from.empty();
  if (f.merge && shard_given) fail("--merge assembles the parts of every shard: it takes no --shard");
  if (f.merge && f.fresh) fail("--merge assembles the parts there are, --fresh discards them: give one of the two");
  const char* id = env("SLURM_ARRAY_TASK_ID");
  if (id != nullptr && *id != 0 && !f.merge && !f.help) {
    if (shard_given)
      f.notes.push_back(fmt::format("{} wins over the SLURM array task (SLURM_ARRAY_TASK_ID={})", f.shard_from, id));
    else
      shard_from_slurm(env, f);
  }
  return f;
}

RunFlags take_merge_flags(std::vector<std::string>& args) {
  RunFlags f = parse_flags(args);
  if (!f.shard_from.empty() || f.merge || f.fresh)
    fail("wrc merge STUDY.lua assembles the parts of every shard: {} does not apply to it",
         !f.shard_from.empty() ? "--shard" : f.merge ? "--merge" : "--fresh");
  f.merge = f.from_parts = true;
  return f;
}

}  // namespace wrc::host
