#include "tetcut/mechanics/sparse_reference.hpp"

#include <Eigen/SparseCore>

namespace tetcut::mechanics {

struct SparseStiffness::Matrix {
  Eigen::SparseMatrix<double, Eigen::RowMajor> k;
  mutable Eigen::VectorXd u, f;
};

SparseStiffness::SparseStiffness(const TensorMassModel& model) : matrix_(std::make_unique<Matrix>()) {
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(model.vertex_capacity());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * (model.vertex_capacity() + 2 * std::size_t{model.edge_count()}));
  auto put = [&](std::uint32_t row, std::uint32_t col, const Tensor3& k, bool transpose) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        entries.emplace_back(3 * row + r, 3 * col + c, transpose ? k[3 * c + r] : k[3 * r + c]);
  };
  for (std::uint32_t v = 0; v < model.vertex_capacity(); ++v)
    if (model.tets_at(VertId{v}) > 0) put(v, v, model.vertex_stiffness(VertId{v}), false);
  for (const TensorMassModel::Edge& e : model.edge_slots()) {
    if (e.tets == 0) continue;
    put(e.a.value, e.b.value, e.k, false);
    put(e.b.value, e.a.value, e.k, true);
  }
  matrix_->k.resize(n, n);
  matrix_->k.setFromTriplets(entries.begin(), entries.end());
  matrix_->u.resize(n);
  matrix_->f.resize(n);
}

SparseStiffness::~SparseStiffness() = default;
SparseStiffness::SparseStiffness(SparseStiffness&&) noexcept = default;
SparseStiffness& SparseStiffness::operator=(SparseStiffness&&) noexcept = default;

void SparseStiffness::elastic_forces(const TensorMassModel& model, std::vector<Vec3>& out) const {
  const std::uint32_t n = model.vertex_capacity();
  for (std::uint32_t v = 0; v < n; ++v) {
    const Vec3& u = model.displacement(VertId{v});
    matrix_->u.segment<3>(3 * v) << u.x, u.y, u.z;
  }
  matrix_->f.noalias() = matrix_->k * matrix_->u;
  out.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) out[v] = {-matrix_->f[3 * v], -matrix_->f[3 * v + 1], -matrix_->f[3 * v + 2]};
}

std::size_t SparseStiffness::nonzeros() const { return static_cast<std::size_t>(matrix_->k.nonZeros()); }

}  // namespace tetcut::mechanics
