// KHR_debug: driver messages of high severity and GL errors are collected
// and raised as exceptions at the next checkpoint (throwing from inside the
// driver's callback would unwind through C frames). In release builds only
// glGetError is consulted.
#pragma once

#include <string>

namespace eikon::gl {

void installDebugCallback();

// Throws std::runtime_error naming `where` if the driver reported an error
// since the last checkpoint.
void checkpoint(const std::string& where);

}  // namespace eikon::gl
