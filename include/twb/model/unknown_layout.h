// Which unknown blocks exist for a scene, and where each starts. An effect that is
// off creates no block (DEVELOPERS' rule: it costs nothing).
#pragma once

#include <string>
#include <vector>

#include "twb/model/sparse_assembly.h"

namespace twb {

struct UnknownBlock {
  std::string name;         // e.g. "film 1 pressure"
  std::string effect;       // the effect that creates it
  Index offset = 0;
  Index size = 0;
  bool differential = false;  // has a heat capacity in the pseudo-time transient
};

class UnknownLayout {
 public:
  Index add(std::string name, std::string effect, Index size, bool differential = false);
  Index size() const { return size_; }
  const std::vector<UnknownBlock>& blocks() const { return blocks_; }
  // Block holding unknown k (for messages).
  const UnknownBlock& block_of(Index k) const;

 private:
  std::vector<UnknownBlock> blocks_;
  Index size_ = 0;
};

}  // namespace twb
