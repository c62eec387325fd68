#include "key_suggestion.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace twb::scene_io {
namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// Optimal string alignment distance: a swapped pair of letters ("thcikness") is one
// typing slip, so it costs one edit rather than two. Case is ignored: 'ra' means 'Ra'.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t substitution = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

}  // namespace

std::string closest_match(std::string_view typo, std::span<const std::string_view> candidates) {
  // Beyond a third of the word the "suggestion" is usually a different word altogether.
  const std::size_t plausible = std::max<std::size_t>(2, typo.size() / 3);
  std::string_view best;
  std::size_t best_distance = plausible + 1;
  for (std::string_view candidate : candidates) {
    const std::size_t distance = edit_distance(typo, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return std::string(best);
}

std::string join(std::span<const std::string_view> names) {
  std::string out;
  for (std::string_view name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

std::string allowed_after(const std::string& suggestion, std::span<const std::string_view> names) {
  return suggestion.empty() ? "; allowed: " + join(names)
                            : "; did you mean '" + suggestion + "'? Allowed: " + join(names);
}

}  // namespace twb::scene_io
