#include "tetcut/attributes.hpp"

#include <algorithm>

namespace tetcut {

std::optional<std::uint32_t> VertexAttributes::add_channel(std::string_view name, std::uint32_t width) {
  if (width == 0) return std::nullopt;
  if (auto existing = find(name)) {
    if (channels_[*existing].width == width) return existing;
    return std::nullopt;
  }
  Channel channel{std::string(name), width, std::vector<double>(std::size_t{size_} * width, 0.0)};
  channels_.push_back(std::move(channel));
  return static_cast<std::uint32_t>(channels_.size() - 1);
}

std::optional<std::uint32_t> VertexAttributes::find(std::string_view name) const {
  for (std::size_t c = 0; c < channels_.size(); ++c)
    if (channels_[c].name == name) return static_cast<std::uint32_t>(c);
  return std::nullopt;
}

std::span<double> VertexAttributes::value(std::uint32_t c, VertId vertex) {
  Channel& ch = channels_[c];
  return {ch.values.data() + std::size_t{vertex.value} * ch.width, ch.width};
}

std::span<const double> VertexAttributes::value(std::uint32_t c, VertId vertex) const {
  const Channel& ch = channels_[c];
  return {ch.values.data() + std::size_t{vertex.value} * ch.width, ch.width};
}

void VertexAttributes::resize(std::uint32_t vertex_count) {
  for (Channel& ch : channels_) ch.values.resize(std::size_t{vertex_count} * ch.width, 0.0);
  size_ = vertex_count;
}

void VertexAttributes::reserve(std::uint32_t vertex_count) {
  for (Channel& ch : channels_) ch.values.reserve(std::size_t{vertex_count} * ch.width);
}

void VertexAttributes::interpolate(VertId dst, VertId a, VertId b, double t) {
  for (Channel& ch : channels_) {
    const std::size_t w = ch.width;
    for (std::size_t k = 0; k < w; ++k) {
      const double va = ch.values[a.value * w + k];
      const double vb = ch.values[b.value * w + k];
      ch.values[dst.value * w + k] = (1.0 - t) * va + t * vb;
    }
  }
}

void VertexAttributes::combine(VertId dst, std::span<const VertId> from, std::span<const double> weight) {
  for (Channel& ch : channels_) {
    const std::size_t w = ch.width;
    for (std::size_t k = 0; k < w; ++k) {
      double sum = 0.0;
      for (std::size_t i = 0; i < from.size(); ++i) sum += weight[i] * ch.values[from[i].value * w + k];
      ch.values[dst.value * w + k] = sum;
    }
  }
}

void VertexAttributes::permute(std::span<const VertId> new_to_old) {
  for (Channel& ch : channels_) {
    std::vector<double> moved(new_to_old.size() * ch.width);
    for (std::size_t n = 0; n < new_to_old.size(); ++n)
      std::copy_n(ch.values.begin() + static_cast<std::ptrdiff_t>(std::size_t{new_to_old[n].value} * ch.width), ch.width,
                  moved.begin() + static_cast<std::ptrdiff_t>(n * ch.width));
    ch.values = std::move(moved);
  }
  size_ = static_cast<std::uint32_t>(new_to_old.size());
}

}  // namespace tetcut
