#pragma once
/// Private to src/io: an HDF5 identifier that closes itself.
#include <hdf5.h>

#include <utility>

namespace kiln
{
namespace internal
{
/// Owns one HDF5 identifier and closes it with the matching H5?close function.
class H5Handle
{
public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  H5Handle(const hid_t id, const Closer closer) : id_(id), closer_(closer) {}
  ~H5Handle() { reset(); }
  H5Handle(H5Handle &&other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
  H5Handle &operator=(H5Handle &&other) noexcept
  {
    if (this != &other)
    {
      reset();
      std::swap(id_, other.id_);
      closer_ = other.closer_;
    }
    return *this;
  }
  H5Handle(const H5Handle &) = delete;
  H5Handle &operator=(const H5Handle &) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Gives up the identifier without closing it.
  hid_t release()
  {
    const hid_t id = id_;
    id_ = -1;
    return id;
  }
  /// Closes the identifier now; the closer's status (negative: closing failed).
  herr_t close()
  {
    const hid_t id = release();
    return id >= 0 && closer_ != nullptr ? closer_(id) : 0;
  }
  void reset()
  {
    if (id_ >= 0 && closer_ != nullptr)
      closer_(id_);
    id_ = -1;
  }

private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};
} // namespace internal
} // namespace kiln
