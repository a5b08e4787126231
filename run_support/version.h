// The project's version (CMake's PROJECT_VERSION), for --version and the reports. Apart
// from cli.h so that a file that only prints it does not compile CLI11, whose header
// alone is about 6 CPU-seconds of every file that includes it (docs/testing/ci_budget.md).
#pragma once

namespace specular {
namespace cli {

/// The project's version (CMake's PROJECT_VERSION).
const char* version();

}  // namespace cli
}  // namespace specular
