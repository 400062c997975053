// The only CGAL translation unit of the generators (a CGAL TU takes about a minute to compile).
#include "tetcut/generators/liver.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <system_error>
#include <utility>

#include "tetcut/generators/repair.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::generators {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
// Sequential: the parallel mesher is not deterministic.
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

// Calibration on Debian's liver.inr.gz: tets ~ kTetsAtUnitCellSize / size^3 (8,232 tets at
// size 10, 4,098 at 12.7, 15,748 at 8).
constexpr double kTetsAtUnitCellSize = 8.2e6;

// A temporary directory removed when it goes out of scope.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "tetcut-liver-XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

RawMesh complex_to_raw(const Complex& c3t3) {
  RawMesh raw;
  std::map<Triangulation::Vertex_handle, std::uint32_t> index;  // lookup only, never iterated
  for (auto cell = c3t3.cells_in_complex_begin(); cell != c3t3.cells_in_complex_end(); ++cell) {
    std::array<std::uint32_t, 4> tet{};
    for (int k = 0; k < 4; ++k) {
      const auto v = cell->vertex(k);
      auto [it, inserted] = index.emplace(v, static_cast<std::uint32_t>(raw.positions.size()));
      if (inserted) {
        const auto& p = v->point();
        raw.positions.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                 CGAL::to_double(p.z())});
      }
      tet[k] = it->second;
    }
    const auto& P = raw.positions;
    if (orientation(P[tet[0]], P[tet[1]], P[tet[2]], P[tet[3]]) < 0) std::swap(tet[2], tet[3]);
    raw.tets.push_back(tet);
  }
  return raw;
}

}  // namespace

double liver_cell_size_for_tets(std::uint32_t target_tets) {
  if (target_tets == 0) return 0.0;
  return std::cbrt(kTetsAtUnitCellSize / static_cast<double>(target_tets));
}

GenResult generate_liver(const LiverOptions& options, RepairReport* repair) {
  if (!(options.cell_size > 0.0) || !std::isfinite(options.cell_size))
    return GenResult::failure("liver: the cell size must be a positive number");

  TempDir temp;
  std::string image_path = options.image_path;
  if (image_path.empty()) {
    if (!std::filesystem::exists(kCgalDataTarball))
      return GenResult::failure(std::string("liver: ") + kCgalDataTarball +
                                " not found (install Debian's libcgal-demo / libcgal-dev)");
    if (temp.path().empty()) return GenResult::failure("liver: cannot create a temporary directory");
    const std::string command = std::string("tar -xzf '") + kCgalDataTarball + "' -C '" +
                                temp.path() + "' " + kLiverImageMember;
    if (std::system(command.c_str()) != 0)
      return GenResult::failure(std::string("liver: cannot extract ") + kLiverImageMember +
                                " from " + kCgalDataTarball);
    image_path = temp.path() + "/" + kLiverImageMember;
  }

  CGAL::Image_3 image;
  if (!image.read(image_path.c_str()))
    return GenResult::failure("liver: cannot read the image " + image_path);

  // Mesh_3 draws initial points and perturbations from CGAL's default generator and the domain's
  // own: seed both, so that the same options give the same mesh on every run.
  CGAL::get_default_random() = CGAL::Random(options.seed);
  CGAL::Random domain_rng(options.seed);
  namespace p = CGAL::parameters;
  Domain domain = Domain::create_labeled_image_mesh_domain(image, p::p_rng = &domain_rng);

  const double s = options.cell_size;
  Criteria criteria(p::facet_angle = 30, p::facet_size = s, p::facet_distance = s / 3.0,
                    p::cell_radius_edge_ratio = 2.5, p::cell_size = s);
  Complex c3t3 = CGAL::make_mesh_3<Complex>(domain, criteria, p::no_lloyd(), p::no_odt(),
                                            p::perturb(p::time_limit = 0, p::sliver_bound = 10),
                                            p::exude(p::time_limit = 0, p::sliver_bound = 10));
  RawMesh raw = complex_to_raw(c3t3);
  if (raw.tets.empty()) return GenResult::failure("liver: Mesh_3 produced no tetrahedra");

  if (!options.repair) return GenResult::success(std::move(raw));
  RepairResult repaired = repair_mesh(raw);
  if (repair != nullptr) *repair = repaired.report;
  if (!repaired.ok()) return GenResult::failure("liver: " + repaired.error);
  return GenResult::success(std::move(*repaired.mesh));
}

}  // namespace tetcut::generators
