#pragma once
// What each of a technique's passes was last computed from, so that a
// frame runs a pass only when one of its inputs changed: the model, the
// camera's altitude, the sun, the view. The inputs are compared exactly,
// as the bytes the pass reads; a pass that tolerates a small change of a
// continuous input quantises that input first and reads the quantised
// value, so that what it computes depends on the current frame alone, never
// on the frames before it (a capture's slices stay byte-identical to the
// whole run).
#include <map>
#include <string>
#include <type_traits>

namespace planet {

// The bytes of a pass's inputs, appended one value at a time.
class PassKey {
 public:
  template <typename T>
  PassKey& add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "a pass's inputs are compared as bytes");
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class PassInputs {
 public:
  // True when `pass` never ran or its inputs differ from those it last ran
  // with; `key` is kept as the pass's inputs from now on.
  bool changed(const std::string& pass, const PassKey& key) {
    auto [it, inserted] = last_.try_emplace(pass, key.bytes());
    if (inserted) return true;
    if (it->second == key.bytes()) return false;
    it->second = key.bytes();
    return true;
  }
  // Every pass runs in the next frame.
  void forget() { last_.clear(); }

 private:
  std::map<std::string, std::string> last_;
};

}  // namespace planet
