#pragma once
// One exception type for everything a user can get wrong: a file, a field,
// a value. It is caught once in main and printed as one line.
#include <stdexcept>
#include <string>

namespace planet {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A failure of the machine rather than of the input: no GL device, a
// shader that does not compile, a file that cannot be written.
class SystemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace planet
