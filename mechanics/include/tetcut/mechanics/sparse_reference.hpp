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

  // The largest eigenvalue of M^-1 K over the model's free vertices (live and not fixed), in
  // 1/s2: omega_max^2, whose 2 / sqrt is the explicit step's critical time step. Lanczos on the
  // symmetric M^-1/2 K M^-1/2 with full reorthogonalisation, run until the largest Ritz value's
  // residual |A y - theta y| is below `tolerance` theta: the converged reference that
  // StableStepEstimator's few power iterations are checked against. O(iterations^2 #V) time,
  // O(iterations #V) memory.
  struct Eigenvalue {
    double lambda = 0;
    double residual = 0;  // relative, at the end
    std::uint32_t iterations = 0;
    bool converged = false;
  };
  [[nodiscard]] Eigenvalue largest_eigenvalue(const TensorMassModel& model, double tolerance = 1e-9,
                                              std::uint32_t max_iterations = 3000) const;
  [[nodiscard]] std::size_t nonzeros() const;

 private:
  struct Matrix;  // Eigen stays out of this header
  std::unique_ptr<Matrix> matrix_;
};

}  // namespace tetcut::mechanics
