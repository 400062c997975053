#include "tetcut/mechanics/sparse_reference.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

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

SparseStiffness::Eigenvalue SparseStiffness::largest_eigenvalue(const TensorMassModel& model, double tolerance,
                                                                std::uint32_t max_iterations) const {
  const Eigen::Index n = matrix_->k.rows();
  // D = M^-1/2 on the free degrees of freedom, 0 elsewhere: A = D K D is the restriction.
  Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  for (std::uint32_t v = 0; 3 * static_cast<Eigen::Index>(v) < n; ++v)
    if (model.tets_at(VertId{v}) > 0 && !model.is_fixed(VertId{v})) d.segment<3>(3 * v).setConstant(1.0 / std::sqrt(model.mass(VertId{v})));
  Eigenvalue result;
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) q[i] = d[i] != 0 ? std::sin(0.7 + 1.3 * static_cast<double>(i)) : 0.0;
  if (q.norm() == 0) return result;
  q.normalize();
  const Eigen::Index most = std::min<Eigen::Index>(max_iterations, (d.array() != 0).count());
  Eigen::MatrixXd basis(n, std::min<Eigen::Index>(most + 1, 64));  // grown as the iteration goes
  std::vector<double> alpha, beta;
  basis.col(0) = q;
  for (Eigen::Index j = 0; j < most; ++j) {
    Eigen::VectorXd w = d.cwiseProduct(matrix_->k * d.cwiseProduct(basis.col(j)));
    alpha.push_back(basis.col(j).dot(w));
    // Full reorthogonalisation, twice (classical Gram-Schmidt loses what once leaves).
    for (int pass = 0; pass < 2; ++pass) w -= basis.leftCols(j + 1) * (basis.leftCols(j + 1).transpose() * w);
    beta.push_back(w.norm());
    const bool last = j + 1 == most || beta.back() == 0;
    if (j % 8 == 7 || last) {
      const Eigen::Index m = j + 1;
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz;
      ritz.computeFromTridiagonal(Eigen::Map<const Eigen::VectorXd>(alpha.data(), m),
                                  Eigen::Map<const Eigen::VectorXd>(beta.data(), m - 1), Eigen::ComputeEigenvectors);
      const double theta = ritz.eigenvalues()[m - 1];
      const double residual = beta.back() * std::abs(ritz.eigenvectors()(m - 1, m - 1));
      result = {theta, theta > 0 ? residual / theta : 0.0, static_cast<std::uint32_t>(m), false};
      if (result.residual <= tolerance || last) {
        result.converged = result.residual <= tolerance || beta.back() == 0;
        return result;
      }
    }
    if (basis.cols() < j + 2) basis.conservativeResize(Eigen::NoChange, std::min<Eigen::Index>(most + 1, 2 * basis.cols()));
    basis.col(j + 1) = w / beta.back();
  }
  return result;
}

std::size_t SparseStiffness::nonzeros() const { return static_cast<std::size_t>(matrix_->k.nonZeros()); }

}  // namespace tetcut::mechanics
