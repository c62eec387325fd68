// Which unknown blocks exist for a scene, and where each starts. An effect that is
// off creates no block (DEVELOPERS' rule: it costs nothing).
#pragma once

#include <string>
#include <vector>

#include "model/sparse_assembly.h"
#include "twb/model/unknown_block.h"

namespace twb {

class UnknownLayout {
 public:
  Index add(std::string name, BlockEffect effect, Index size, bool differential = false);
  Index size() const { return size_; }
  const std::vector<UnknownBlock>& blocks() const { return blocks_; }
  // Block holding unknown k (for messages).
  const UnknownBlock& block_of(Index k) const;

 private:
  std::vector<UnknownBlock> blocks_;
  Index size_ = 0;
};

}  // namespace twb
