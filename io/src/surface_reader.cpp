#include "surface_reader.hpp"

namespace tetcut::io_detail {

bool SurfaceReaderState::add_point(std::uint64_t line, const std::string_view* xyz) {
  Vec3 p;
  if (!parse_point(sink, line, xyz, p)) return false;
  surface.positions.push_back(p);
  return true;
}

void SurfaceReaderState::emit_notices(std::vector<std::string>& notices) const {
  polygon_notice(polygons_split, notices);
  if (strips_split > 0) notices.push_back("split " + std::to_string(strips_split) + " triangle strips into triangles");
  ignored.emit(notices);
}

SurfaceReadResult SurfaceReaderState::result(std::vector<std::string>&& notices) {
  return make_surface_result(sink, std::move(surface), std::move(notices));
}

}  // namespace tetcut::io_detail
