// numpy arrays over C++ memory (docs/python.md, "Conventions"): a view of memory a result
// object owns, with that object as the array's base (no copy; the object lives as long as the
// array), or an array that takes over a C++ container (no copy either: a capsule frees it).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <complex>
#include <utility>
#include <vector>

namespace railmodal::python {

/// Marks an array read-only (a view of a result that must not change under its owner).
inline pybind11::array read_only(pybind11::array a) {
  pybind11::detail::array_proxy(a.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// A read-only view of a column-major Eigen matrix that `owner` keeps alive.
template <typename Scalar>
pybind11::array matrix_view(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& matrix,
                            pybind11::handle owner) {
  const auto s = static_cast<pybind11::ssize_t>(sizeof(Scalar));
  return read_only(pybind11::array_t<Scalar>({static_cast<pybind11::ssize_t>(matrix.rows()),
                                              static_cast<pybind11::ssize_t>(matrix.cols())},
                                             {s, s * static_cast<pybind11::ssize_t>(matrix.rows())}, matrix.data(),
                                             owner));
}

/// A read-only view of a vector that `owner` keeps alive.
template <typename Scalar>
pybind11::array vector_view(const Scalar* data, std::size_t size, pybind11::handle owner) {
  return read_only(pybind11::array_t<Scalar>({static_cast<pybind11::ssize_t>(size)}, {sizeof(Scalar)}, data, owner));
}
template <typename Scalar>
pybind11::array vector_view(const std::vector<Scalar>& v, pybind11::handle owner) {
  return vector_view(v.data(), v.size(), owner);
}
template <typename Scalar>
pybind11::array vector_view(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& v, pybind11::handle owner) {
  return vector_view(v.data(), static_cast<std::size_t>(v.size()), owner);
}

/// A (writeable) array that takes over `values`: no copy, freed with the array.
template <typename Scalar>
pybind11::array take(std::vector<Scalar>&& values) {
  auto* owned = new std::vector<Scalar>(std::move(values));
  pybind11::capsule free(owned, [](void* p) { delete static_cast<std::vector<Scalar>*>(p); });
  return pybind11::array_t<Scalar>({static_cast<pybind11::ssize_t>(owned->size())}, {sizeof(Scalar)}, owned->data(),
                                   free);
}

/// A (writeable) row-major rows × cols array that takes over `values` (rows·cols of them).
template <typename Scalar>
pybind11::array take(std::vector<Scalar>&& values, std::size_t rows, std::size_t cols) {
  auto* owned = new std::vector<Scalar>(std::move(values));
  pybind11::capsule free(owned, [](void* p) { delete static_cast<std::vector<Scalar>*>(p); });
  const auto s = static_cast<pybind11::ssize_t>(sizeof(Scalar));
  return pybind11::array_t<Scalar>({static_cast<pybind11::ssize_t>(rows), static_cast<pybind11::ssize_t>(cols)},
                                   {s * static_cast<pybind11::ssize_t>(cols), s}, owned->data(), free);
}

/// A (writeable) array that takes over an Eigen matrix (column-major): no copy.
template <typename Scalar>
pybind11::array take(Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>&& matrix) {
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  auto* owned = new Matrix(std::move(matrix));
  pybind11::capsule free(owned, [](void* p) { delete static_cast<Matrix*>(p); });
  const auto s = static_cast<pybind11::ssize_t>(sizeof(Scalar));
  return pybind11::array_t<Scalar>(
      {static_cast<pybind11::ssize_t>(owned->rows()), static_cast<pybind11::ssize_t>(owned->cols())},
      {s, s * static_cast<pybind11::ssize_t>(owned->rows())}, owned->data(), free);
}

/// std::vector<bool> has no contiguous bools: copied into a numpy bool array.
inline pybind11::array bool_array(const std::vector<bool>& flags) {
  pybind11::array_t<bool> out(static_cast<pybind11::ssize_t>(flags.size()));
  auto w = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < flags.size(); ++i) w(static_cast<pybind11::ssize_t>(i)) = flags[i];
  return out;
}

}  // namespace railmodal::python
