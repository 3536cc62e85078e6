#pragma once
/// A view of contiguous elements (std::span is C++20): what Mesh::cell_nodes returns.
#include <cstddef>
#include <type_traits>
#include <utility>

namespace kiln
{
template <typename T> class Span
{
public:
  Span(T *data, const int size) : data_(data), size_(size) {}
  /// A view of a container with data() and size() (std::array, std::vector, a Span).
  template <typename C, typename = decltype(std::declval<const C &>().data())>
  Span(const C &c) : data_(c.data()), size_(static_cast<int>(c.size()))
  {
  }
  int size() const { return size_; }
  T &operator[](const int i) const { return data_[i]; }
  T *begin() const { return data_; }
  T *end() const { return data_ + size_; }
  T *data() const { return data_; }

private:
  T *data_;
  int size_;
};
} // namespace kiln
