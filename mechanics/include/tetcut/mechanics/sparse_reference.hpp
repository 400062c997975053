// The stiffness of a TensorMassModel assembled as a global sparse matrix (Eigen's
// SparseMatrix, compressed rows), and the elastic forces -K u as its product: the textbook way
// the tensor loop of TensorMassModel::elastic_forces() replaces, kept as the reference that the
// tests check it against and the benchmark times it against. Assembly is O(#V + #E), once.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

class SparseStiffness {
 public:
  explicit SparseStiffness(const TensorMassModel& model);
  ~SparseStiffness();
  SparseStiffness(SparseStiffness&&) noexcept;
  SparseStiffness& operator=(SparseStiffness&&) noexcept;

  // -K u at every vertex id of the model (out: #vertex capacity).
  void elastic_forces(const TensorMassModel& model, std::vector<Vec3>& out) const;
  [[nodiscard]] std::size_t nonzeros() const;

 private:
  struct Matrix;  // Eigen stays out of this header
  std::unique_ptr<Matrix> matrix_;
};

}  // namespace tetcut::mechanics
