// Which unknown blocks exist for a scene, where each starts, and the scale of each
// row (the system is square: row k is the balance of unknown k's block). An effect
// that is off creates no block (DEVELOPERS' rule: it costs nothing).
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
  // The factor a row's physical balance is multiplied by so that it reads in its
  // unknown's units (bearing_model.h); 1 until its owner sets it. Every effect adding to
  // a row scales its terms by it.
  double row_scale(Index k) const { return row_scale_[std::size_t(k)]; }
  void set_row_scale(Index k, double scale) { row_scale_[std::size_t(k)] = scale; }
  const std::vector<UnknownBlock>& blocks() const { return blocks_; }
  // Block holding unknown k (for messages).
  const UnknownBlock& block_of(Index k) const;

 private:
  std::vector<UnknownBlock> blocks_;
  std::vector<double> row_scale_;
  Index size_ = 0;
};

}  // namespace twb
