// "Did you mean ...?" for misspelt keys and enum values.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace twb::scene_io {

// The candidate closest to `typo` by edit distance (insertions, deletions,
// substitutions and swaps of neighbours), or empty when none is close enough to be a
// plausible misspelling.
std::string closest_match(std::string_view typo, std::span<const std::string_view> candidates);

// "a, b, c" for messages that list what is allowed.
std::string join(std::span<const std::string_view> names);

// The tail of a message rejecting a name: "; did you mean 'x'? Allowed: a, b" or
// "; allowed: a, b" when nothing is close.
std::string allowed_after(const std::string& suggestion, std::span<const std::string_view> names);

}  // namespace twb::scene_io
