// Progress lines and notes on the terminal (terminal.hpp).
#include "wrc/host/terminal.hpp"

#include <fmt/format.h>

#include <chrono>
#include <memory>

#include <unistd.h>

namespace wrc::host {

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

Progress progress_line(std::string what, std::string unit, std::FILE* out, double interval) {
  using Clock = std::chrono::steady_clock;
  struct Line {
    Clock::time_point start = Clock::now(), drawn;
    bool any = false;
  };
  auto line = std::make_shared<Line>();  // shared by the copies of the callback
  return [=, what = std::move(what), unit = std::move(unit)](int done, int total, int failed) {
    const Clock::time_point now = Clock::now();
    const bool last = done >= total;
    if (line->any && !last && std::chrono::duration<double>(now - line->drawn).count() < interval) return;
    line->any = true;
    line->drawn = now;
    const double s = std::chrono::duration<double>(now - line->start).count();
    const std::string failures = failed > 0 ? fmt::format(", {} failed", failed) : "";
    fmt::print(out, "\rwrc {}: {} / {} {}{}, {:.1f} s{}", what, done, total, unit, failures, s, last ? "\n" : "");
    std::fflush(out);
  };
}

Progress read_progress_line(OptionReader& r, bool by_default, std::string what, std::string unit) {
  if (!r.boolean("progress").value_or(by_default)) return {};
  return progress_line(std::move(what), std::move(unit));
}

std::function<void(const std::string&)> note_printer(std::string what) {
  return [what = std::move(what)](const std::string& note) { fmt::print(stderr, "wrc: {}: {}\n", what, note); };
}

}  // namespace wrc::host
