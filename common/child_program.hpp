#pragma once
// Running another program (the matplotlib scripts that draw the tools' pictures) and waiting
// for it, so the C++ tools need no plotting library.

#include <string>
#include <vector>

namespace refloc {

/// Runs argv[0] (a path, not searched in PATH) with argv as its arguments and the caller's
/// environment, and waits for it (EINTR retried). stdout is flushed first so the caller's
/// lines come before the child's. Returns the child's exit status; -1 when it could not be
/// started or did not exit normally.
int run_child_program(const std::vector<std::string>& argv);

}  // namespace refloc
