// What a long engine call shows on the terminal, drawn by the front ends (the engine reports, it never prints): a
// progress line redrawn in place from a Progress callback (core/parallel.hpp), and notes such as a capped thread
// count. The Lua binding draws them by default when stderr is a terminal; the C API only when asked.
#pragma once

#include "wrc/core/options.hpp"
#include "wrc/core/parallel.hpp"

#include <cstdio>
#include <functional>
#include <string>

namespace wrc::host {

// True when stderr is a terminal (where a progress line redrawn in place is readable).
bool stderr_is_terminal();

// A progress line for work of `what` ("sweep") counted in `unit` ("cases"), redrawn in place on `out`:
// "\rwrc sweep: 12 / 40 cases, 1 failed, 3.2 s" (", 1 failed" only once a unit failed). Drawn for the first unit,
// then at most every `interval` seconds, and for the last (ended by a newline). Its calls must not overlap
// (ProgressCount serialises them).
Progress progress_line(std::string what, std::string unit, std::FILE* out = stderr, double interval = 0.1);

// The option `progress` (a boolean; `by_default` when not given): a progress_line on stderr when true, else none.
Progress read_progress_line(OptionReader& options, bool by_default, std::string what, std::string unit);

// Prints a note of `what` on stderr: "wrc: sweep: <note>".
std::function<void(const std::string&)> note_printer(std::string what);

}  // namespace wrc::host
