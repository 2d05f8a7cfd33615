#pragma once
/// \file mappable_array.h
/// A read-only array that either owns its elements or views elements kept
/// elsewhere: the pages of a prepared scene file mapped into memory
/// (hullcover/covering/staged_decomposition.h). The decomposer's search
/// trees and per-face tables are built into owned arrays; a bake's worker
/// maps them from the file instead, and then holds in memory only the pages
/// its cells read.

#include <cstddef>
#include <utility>
#include <vector>

namespace hullcover {

/// Owned (a std::vector) or a view (pointer and count); read through one
/// interface. A view's elements must outlive every copy of it.
template <class T>
class MappableArray {
public:
  MappableArray() = default;
  /// Owns `elements`. Implicit, so that a vector just built is assigned as
  /// it is.
  MappableArray(std::vector<T> elements) : owned_(std::move(elements)) {} // NOLINT(google-explicit-constructor)
  /// Views `count` elements at `first` (not owned).
  static MappableArray view(const T* first, std::size_t count) {
    MappableArray a;
    a.view_ = first;
    a.view_count_ = count;
    return a;
  }

  /// The first element (the vector's, or the viewed ones').
  const T* data() const { return view_ ? view_ : owned_.data(); }
  /// How many elements.
  std::size_t size() const { return view_ ? view_count_ : owned_.size(); }
  /// Whether it has none.
  bool empty() const { return size() == 0; }
  /// Element i (i < size(), not checked).
  const T& operator[](std::size_t i) const { return data()[i]; }
  /// The elements, for range loops and algorithms.
  const T* begin() const { return data(); }
  /// Past the last element.
  const T* end() const { return data() + size(); }
  /// The first element (not empty).
  const T& front() const { return data()[0]; }
  /// The last element (not empty).
  const T& back() const { return data()[size() - 1]; }
  /// Whether the elements live elsewhere (a mapped file).
  bool is_view() const { return view_ != nullptr; }

private:
  std::vector<T> owned_;
  const T* view_ = nullptr;
  std::size_t view_count_ = 0;
};

} // namespace hullcover
