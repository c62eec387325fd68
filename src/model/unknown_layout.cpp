#include "model/unknown_layout.h"

#include <stdexcept>

namespace twb {

Index UnknownLayout::add(std::string name, BlockEffect effect, Index size, bool differential) {
  const Index offset = size_;
  blocks_.push_back({std::move(name), effect, offset, size, differential});
  size_ += size;
  row_scale_.resize(std::size_t(size_), 1.0);
  return offset;
}

const UnknownBlock& UnknownLayout::block_of(Index k) const {
  for (const auto& b : blocks_)
    if (k >= b.offset && k < b.offset + b.size) return b;
  throw std::out_of_range("unknown index outside every block");
}

}  // namespace twb
