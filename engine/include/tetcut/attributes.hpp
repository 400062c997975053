// Per-vertex attribute channels carried by the mesh (rest position, texture coordinates, user
// data), so that edge splits can interpolate them as the paper does for texture and mechanical
// data (paper 3.2), and compaction can move them with their vertex (style: OpenVolumeMesh
// properties).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tetcut {

// Conventional channel names.
inline constexpr std::string_view kRestPositionChannel = "rest_position";  // width 3
inline constexpr std::string_view kTexCoordChannel = "texcoord";           // width 2

class VertexAttributes {
 public:
  struct Channel {
    std::string name;
    std::uint32_t width = 1;
    std::vector<double> values;  // #V by width
  };

  // Adds a channel of `width` doubles per vertex, zero-filled; returns its index. Adding an
  // existing name returns the existing channel if the width matches, nullopt otherwise.
  std::optional<std::uint32_t> add_channel(std::string_view name, std::uint32_t width);
  [[nodiscard]] std::optional<std::uint32_t> find(std::string_view name) const;

  [[nodiscard]] std::size_t channel_count() const { return channels_.size(); }
  [[nodiscard]] const Channel& channel(std::uint32_t c) const { return channels_[c]; }

  std::span<double> value(std::uint32_t c, std::uint32_t vertex);
  [[nodiscard]] std::span<const double> value(std::uint32_t c, std::uint32_t vertex) const;

  // Number of vertices every channel is sized for.
  [[nodiscard]] std::uint32_t size() const { return size_; }
  void resize(std::uint32_t vertex_count);
  void reserve(std::uint32_t vertex_count);

  // dst := (1 - t) * a + t * b on every channel.
  void interpolate(std::uint32_t dst, std::uint32_t a, std::uint32_t b, double t);

  // Keeps vertex old_id at new_to_old position: values[new] = values[new_to_old[new]].
  void permute(std::span<const std::uint32_t> new_to_old);

 private:
  std::vector<Channel> channels_;
  std::uint32_t size_ = 0;
};

}  // namespace tetcut
