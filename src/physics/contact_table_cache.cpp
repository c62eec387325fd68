#include "physics/contact_table_cache.h"

#include <algorithm>
#include <mutex>
#include <utility>
#include <vector>

namespace twb {

namespace {

// A fold curve in roughness visits three populations per corrector iteration, a family
// of curves a few more: sixteen covers both, at ~100 kB a table.
constexpr std::size_t kept_tables = 16;

}  // namespace

std::shared_ptr<const StatisticalContact> shared_contact_table(const ContactTableKey& key) {
  static std::mutex guard;
  static std::vector<std::pair<ContactTableKey, std::shared_ptr<const StatisticalContact>>> tables;
  {
    const std::lock_guard lock(guard);
    const auto found = std::find_if(tables.begin(), tables.end(), [&](const auto& t) { return t.first == key; });
    if (found != tables.end()) return found->second;
  }
  // Built outside the lock: two threads asking at once build the same table twice, and
  // both are the same numbers.
  auto table = std::make_shared<const StatisticalContact>(
      JacksonGreenAsperity(key.effective_modulus, key.yield_strength, key.poisson_ratio, key.summit_radius),
      key.summit_density, key.summit_sigma);
  const std::lock_guard lock(guard);
  if (tables.size() == kept_tables) tables.erase(tables.begin());
  tables.emplace_back(key, table);
  return table;
}

}  // namespace twb
