// A candidate plugin library checked before dlopen maps it (reader_host.cpp).
#pragma once

#include <optional>
#include <string>

namespace wrc {

// Why the file at `path` cannot be a loadable shared library of this host, or nothing when its ELF headers hold:
// header, program and section header tables and every segment's and section's file range lie inside the file. A
// segment that reaches past the end of the file would be mapped by dlopen and touched by the dynamic loader:
// SIGBUS (a truncated copy of a plugin), which no error path can catch.
std::optional<std::string> check_library_file(const std::string& path);

}  // namespace wrc
