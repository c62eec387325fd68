// Typed, located reading of a scene's YAML tree: every value read knows its dotted path
// and where its text is, so every rejection becomes an InputError pointing at it.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scene_source.h"
#include "scene/quantity.h"

namespace twb::scene_io {

// The values a number may take. Bounds are in the SI unit of the quantity read.
struct Range {
  double low = -std::numeric_limits<double>::infinity();
  bool low_open = false;
  double high = std::numeric_limits<double>::infinity();
  bool high_open = false;
  std::string_view reason = {};  // why, when it is not obvious

  bool contains(double x) const {
    return (low_open ? x > low : x >= low) && (high_open ? x < high : x <= high);
  }
  // "> 0", ">= 3", "in (0, 0.5)", "in [0, 0.1)"
  std::string describe() const;
};
inline constexpr Range positive{.low = 0.0, .low_open = true};
inline constexpr Range non_negative{.low = 0.0};

class Node {
 public:
  Node(YAML::Node yaml, std::string path, const Origin* origin, YAML::Mark mark,
       const Provenance* provenance)
      : yaml_(std::move(yaml)), path_(std::move(path)), origin_(origin), mark_(mark),
        provenance_(provenance) {}

  const YAML::Node& yaml() const { return yaml_; }
  const std::string& path() const { return path_; }
  const Origin* origin() const { return origin_; }
  const Provenance* provenance() const { return provenance_; }
  const YAML::Mark& mark() const { return mark_; }
  // "'geometry.washer'", or "the scene" for the root.
  std::string name() const;
  // "in 'geometry.washer'", or "at the top level" for the root.
  std::string where() const;
  // "a map", "a list", "the value '3 mm'", "no value"
  std::string describe_content() const;

  [[noreturn]] void fail(const std::string& message) const;

  // The scalar text; fails unless this is a scalar. `expected` says what should be here.
  std::string scalar(std::string_view expected) const;
  std::vector<Node> list(std::string_view expected) const;

  double quantity(const SiUnit& unit, const Range& range) const;
  int integer(int minimum, std::string_view reason = {}) const;
  int integer(int minimum, int maximum, std::string_view reason) const;
  bool boolean() const;
  // Index of the scalar in `names`; fails naming the allowed names and the closest one.
  std::size_t choice(std::span<const std::string_view> names) const;

 private:
  YAML::Node yaml_;
  std::string path_;
  const Origin* origin_;
  YAML::Mark mark_;  // of the value, or of its key when the value is empty
  const Provenance* provenance_;
};

// A map read under a fixed set of allowed keys. Construction rejects a value that is
// not a map, duplicate keys and keys outside `allowed`; an absent or empty value is an
// empty map.
class MapReader {
 public:
  MapReader(const Node& node, std::vector<std::string_view> allowed);

  const Node& node() const { return node_; }
  // The keys present, in file order.
  std::vector<std::string> keys() const;
  bool has(std::string_view key) const { return find_entry(key) != nullptr; }
  std::optional<Node> find(std::string_view key) const;
  // Fails with "missing required key" when absent; `expected` describes the value.
  Node get(std::string_view key, std::string_view expected) const;

  // A map of options whose valid keys depend on a choice made in it: rejects present
  // keys outside `valid`, saying `because` (e.g. "with law: empirical").
  void restrict_to(std::vector<std::string_view> valid, std::string_view because) const;

  double quantity(std::string_view key, const SiUnit& unit, const Range& range) const;
  double quantity(std::string_view key, const SiUnit& unit, const Range& range,
                  double fallback) const;
  int integer(std::string_view key, int minimum, int fallback, std::string_view reason = {}) const;
  int integer(std::string_view key, int minimum, int maximum, int fallback, std::string_view reason) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string text(std::string_view key, std::string fallback) const;
  std::size_t choice(std::string_view key, std::span<const std::string_view> names,
                     std::size_t fallback) const;
  MapReader map(std::string_view key, std::vector<std::string_view> allowed) const;

 private:
  struct Entry {
    std::string key;
    YAML::Node key_node;
    YAML::Node value;
  };
  const Entry* find_entry(std::string_view key) const;
  Node child_of(const Entry& entry) const;
  [[noreturn]] void fail_at_key(const Entry& entry, const std::string& message) const;

  Node node_;
  std::vector<std::string_view> allowed_;
  std::vector<Entry> entries_;
};

// An enum's spellings in scene files, in declaration order of the enum.
template <class Enum, std::size_t N>
struct EnumNames {
  std::array<std::string_view, N> names;
  std::array<Enum, N> values;

  std::string_view name(Enum value) const {
    for (std::size_t i = 0; i < N; ++i)
      if (values[i] == value) return names[i];
    return "?";
  }
  std::size_t index(Enum value) const {
    for (std::size_t i = 0; i < N; ++i)
      if (values[i] == value) return i;
    return 0;
  }
};

template <class Enum, std::size_t N>
Enum read_choice(const MapReader& map, std::string_view key, const EnumNames<Enum, N>& names,
                 Enum fallback) {
  return names.values[map.choice(key, names.names, names.index(fallback))];
}

}  // namespace twb::scene_io
