// The fuzzer's bytes as a stream of small values, for targets that decode structured
// input. Reading past the end yields zeros instead of failing, so every byte string is a
// valid input and libFuzzer's truncations and insertions keep producing meaningful cases.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace curvebench::fuzz {

class Fuzz_input {
 public:
  Fuzz_input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool exhausted() const { return position_ == size_; }

  std::uint8_t byte() { return raw<std::uint8_t>(); }

  // The next sizeof(T) bytes reinterpreted as a T (zero-padded at the end): any bit
  // pattern, NaNs, infinities and subnormals included.
  template <class T>
    requires std::is_trivially_copyable_v<T>
  T raw() {
    unsigned char bytes[sizeof(T)] = {};
    const std::size_t n = std::min(sizeof(T), size_ - position_);
    if (n > 0) std::memcpy(bytes, data_ + position_, n);
    position_ += n;
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

}  // namespace curvebench::fuzz
