#pragma once
// A C++17 stand-in for std::span: a non-owning view of contiguous elements. Use it instead of a raw
// pointer and a length.

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace ifar::common {

template <typename T>
class Span {
 public:
  using element_type = T;
  using value_type = std::remove_cv_t<T>;

  constexpr Span() = default;
  constexpr Span(T* data, std::size_t size) : data_(data), size_(size) {}
  template <typename Container,
            typename = decltype(std::declval<Container&>().data() + std::declval<Container&>().size())>
  constexpr Span(Container& container)  // NOLINT(google-explicit-constructor): views convert implicitly
      : data_(container.data()), size_(container.size())
  {
  }
  template <std::size_t N>
  constexpr Span(T (&array)[N]) : data_(array), size_(N)  // NOLINT(google-explicit-constructor)
  {
  }

  constexpr T* data() const { return data_; }
  constexpr std::size_t size() const { return size_; }
  constexpr bool empty() const { return size_ == 0; }
  constexpr T* begin() const { return data_; }
  constexpr T* end() const { return data_ + size_; }
  constexpr T& operator[](std::size_t index) const { return data_[index]; }

  /// Elements [offset, offset + count); throws std::out_of_range when that leaves the view.
  Span subspan(std::size_t offset, std::size_t count) const
  {
    if (offset > size_ || count > size_ - offset) {
      throw std::out_of_range("Span::subspan out of range");
    }
    return Span(data_ + offset, count);
  }
  Span subspan(std::size_t offset) const
  {
    return subspan(offset, size_ - (offset <= size_ ? offset : size_));
  }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

using ByteView = Span<const std::uint8_t>;

}  // namespace ifar::common
