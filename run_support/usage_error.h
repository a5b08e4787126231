// The one error type of the command lines and input files of specular_tb and the tools.
#pragma once

#include <stdexcept>
#include <string>

namespace specular {
namespace tb {

/// Bad option, bad value, bad input file or unwritable output: the user can fix it.
/// specular_tb reports the message on stderr and exits with status 2.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace tb
}  // namespace specular
