#include "scene_node.h"

#include <charconv>
#include <climits>

#include <fmt/format.h>

#include "key_suggestion.h"

namespace twb::scene_io {
namespace {

std::string child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : fmt::format("{}.{}", parent, key);
}

bool has_mark(const YAML::Mark& mark) { return mark.line >= 0 && mark.column >= 0; }

std::string with_reason(std::string_view reason) {
  return reason.empty() ? std::string() : fmt::format(" ({})", reason);
}

}  // namespace

std::string Range::describe() const {
  const bool bounded_below = low > -std::numeric_limits<double>::infinity();
  const bool bounded_above = high < std::numeric_limits<double>::infinity();
  if (bounded_below && bounded_above)
    return fmt::format("in {}{:.12g}, {:.12g}{}", low_open ? '(' : '[', low, high, high_open ? ')' : ']');
  if (bounded_below) return fmt::format("{} {:.12g}", low_open ? ">" : ">=", low);
  if (bounded_above) return fmt::format("{} {:.12g}", high_open ? "<" : "<=", high);
  return "finite";
}

std::string Node::name() const { return path_.empty() ? "the scene" : fmt::format("'{}'", path_); }

std::string Node::where() const {
  return path_.empty() ? "at the top level" : fmt::format("in '{}'", path_);
}

std::string Node::describe_content() const {
  switch (yaml_.Type()) {
    case YAML::NodeType::Scalar: return fmt::format("the value '{}'", yaml_.Scalar());
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    default: return "no value";
  }
}

void Node::fail(const std::string& message) const { fail_at(*origin_, mark_, false, message); }

std::string Node::scalar(std::string_view expected) const {
  if (yaml_.IsScalar()) return yaml_.Scalar();
  fail(fmt::format("{}: expected {}; got {}", path_, expected, describe_content()));
}

std::vector<Node> Node::list(std::string_view expected) const {
  if (!yaml_.IsSequence())
    fail(fmt::format("{}: expected a list of {}; got {}", path_, expected, describe_content()));
  std::vector<Node> items;
  std::size_t index = 0;
  for (const YAML::Node& item : yaml_) {
    const YAML::Mark mark = has_mark(item.Mark()) && !item.IsNull() ? item.Mark() : mark_;
    items.emplace_back(item, fmt::format("{}[{}]", path_, index++), origin_, mark, provenance_);
  }
  return items;
}

double Node::quantity(const SiUnit& unit, const Range& range) const {
  const std::string text = scalar(fmt::format("{}, e.g. '{}'", unit.kind, unit.example));
  double value = 0.0;
  try {
    value = to_si(text, unit);
  } catch (const QuantityError& error) {
    fail(fmt::format("{}: {}", path_, error.what()));
  }
  if (!range.contains(value)) {
    const bool has_unit = unit.symbol != "1";
    // Show the SI value the range applies to, unless that is what was written.
    const std::string si_text = has_unit ? fmt::format("{:.12g} {}", value, unit.symbol)
                                         : fmt::format("{:.12g}", value);
    const bool converted = text.find_first_of(" \t") != std::string::npos && si_text != text;
    fail(fmt::format("{}: '{}'{} is out of range; must be {}{}{}", path_, text,
                     converted ? fmt::format(" (= {})", si_text) : std::string(),
                     range.describe(), has_unit ? fmt::format(" {}", unit.symbol) : std::string(),
                     with_reason(range.reason)));
  }
  if (provenance_) provenance_->note_quantity(path_, value, unit.symbol);
  return value;
}

int Node::integer(int minimum, std::string_view reason) const { return integer(minimum, INT_MAX, reason); }

int Node::integer(int minimum, int maximum, std::string_view reason) const {
  const std::string allowed = maximum == INT_MAX ? fmt::format(">= {}", minimum)
                                                 : fmt::format("in [{}, {}]", minimum, maximum);
  const std::string text = scalar(fmt::format("a whole number {}", allowed));
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error == std::errc::invalid_argument || end != digits.data() + digits.size())
    fail(fmt::format("{}: '{}' is not a whole number; expected a whole number {}", path_, text, allowed));
  if (error == std::errc::result_out_of_range || value < minimum || value > maximum)
    fail(fmt::format("{}: {} is out of range; must be {}{}", path_, text, allowed, with_reason(reason)));
  return static_cast<int>(value);
}

bool Node::boolean() const {
  const std::string text = scalar("true or false");
  // YAML 1.2 core schema spellings only: 'yes' and 'on' are YAML 1.1 and surprise people.
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  fail(fmt::format("{}: '{}' is not a boolean; allowed: true, false", path_, text));
}

std::size_t Node::choice(std::span<const std::string_view> names) const {
  const std::string text = scalar(fmt::format("one of: {}", join(names)));
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == text) return i;
  const std::string suggestion = closest_match(text, names);
  fail(fmt::format("{}: unknown value '{}'{}", path_, text, allowed_after(suggestion, names)));
}

MapReader::MapReader(const Node& node, std::vector<std::string_view> allowed)
    : node_(node), allowed_(std::move(allowed)) {
  const YAML::Node& yaml = node_.yaml();
  if (!yaml.IsDefined() || yaml.IsNull()) return;
  if (!yaml.IsMap())
    node_.fail(fmt::format("{} must be a map (allowed keys: {}); got {}", node_.name(),
                           join(allowed_), node_.describe_content()));
  for (auto it = yaml.begin(); it != yaml.end(); ++it) {
    Entry entry{std::string(), it->first, it->second};
    if (!entry.key_node.IsScalar())
      fail_at_key(entry, fmt::format("keys {} must be plain names; allowed: {}", node_.where(),
                                     join(allowed_)));
    entry.key = entry.key_node.Scalar();
    // yaml-cpp keeps both entries of a repeated key but lookups see only the first,
    // so a repeated key would silently ignore one of the user's values.
    if (const Entry* first = find_entry(entry.key)) {
      const YAML::Mark first_mark = first->key_node.Mark();
      fail_at_key(entry, fmt::format("duplicate key '{}' {}{}; each key may appear once", entry.key,
                                     node_.where(),
                                     has_mark(first_mark) && node_.origin()->is_file
                                         ? fmt::format(" (first given on line {})", first_mark.line + 1)
                                         : std::string()));
    }
    bool known = false;
    for (std::string_view name : allowed_) known = known || name == entry.key;
    if (!known) {
      const std::string suggestion = closest_match(entry.key, allowed_);
      if (allowed_.empty())
        fail_at_key(entry, fmt::format("unknown key '{}' {}: {} takes no options", entry.key,
                                       node_.where(), node_.name()));
      fail_at_key(entry, fmt::format("unknown key '{}' {}{} Allowed: {}", entry.key, node_.where(),
                                     suggestion.empty() ? std::string(".")
                                                        : fmt::format("; did you mean '{}'?", suggestion),
                                     join(allowed_)));
    }
    entries_.push_back(std::move(entry));
  }
}

const MapReader::Entry* MapReader::find_entry(std::string_view key) const {
  for (const Entry& entry : entries_)
    if (entry.key == key) return &entry;
  return nullptr;
}

Node MapReader::child_of(const Entry& entry) const {
  const std::string path = child_path(node_.path(), entry.key);
  const Origin* origin = node_.provenance()->origin_of(path, node_.origin());
  const YAML::Mark value_mark = entry.value.Mark();
  const bool point_at_value = !entry.value.IsNull() && has_mark(value_mark);
  return Node(entry.value, path, origin, point_at_value ? value_mark : entry.key_node.Mark(),
              node_.provenance());
}

void MapReader::fail_at_key(const Entry& entry, const std::string& message) const {
  const std::string path = child_path(node_.path(), entry.key_node.IsScalar() ? entry.key_node.Scalar() : "?");
  const Origin* origin = node_.provenance()->origin_of(path, node_.origin());
  fail_at(*origin, entry.key_node.Mark(), true, message);
}

std::optional<Node> MapReader::find(std::string_view key) const {
  const Entry* entry = find_entry(key);
  if (entry == nullptr) return std::nullopt;
  return child_of(*entry);
}

Node MapReader::get(std::string_view key, std::string_view expected) const {
  if (const Entry* entry = find_entry(key)) return child_of(*entry);
  node_.fail(fmt::format("missing required key '{}' {} ({}); allowed: {}", key, node_.where(),
                         expected, join(allowed_)));
}

std::vector<std::string> MapReader::keys() const {
  std::vector<std::string> keys;
  for (const Entry& entry : entries_) keys.push_back(entry.key);
  return keys;
}

void MapReader::restrict_to(std::vector<std::string_view> valid, std::string_view because) const {
  for (const Entry& entry : entries_) {
    bool ok = false;
    for (std::string_view name : valid) ok = ok || name == entry.key;
    if (!ok)
      fail_at_key(entry, fmt::format("key '{}' {} does not apply {}; allowed {}: {}", entry.key,
                                     node_.where(), because, because, join(valid)));
  }
}

double MapReader::quantity(std::string_view key, const SiUnit& unit, const Range& range) const {
  return get(key, fmt::format("{}, e.g. '{}'", unit.kind, unit.example)).quantity(unit, range);
}

double MapReader::quantity(std::string_view key, const SiUnit& unit, const Range& range,
                           double fallback) const {
  const auto found = find(key);
  return found ? found->quantity(unit, range) : fallback;
}

int MapReader::integer(std::string_view key, int minimum, int fallback, std::string_view reason) const {
  return integer(key, minimum, INT_MAX, fallback, reason);
}

int MapReader::integer(std::string_view key, int minimum, int maximum, int fallback, std::string_view reason) const {
  const auto found = find(key);
  return found ? found->integer(minimum, maximum, reason) : fallback;
}

bool MapReader::boolean(std::string_view key, bool fallback) const {
  const auto found = find(key);
  return found ? found->boolean() : fallback;
}

std::string MapReader::text(std::string_view key, std::string fallback) const {
  const auto found = find(key);
  if (!found) return fallback;
  std::string value = found->scalar("a text");
  if (value.empty()) found->fail(fmt::format("{}: must not be empty", found->path()));
  return value;
}

std::size_t MapReader::choice(std::string_view key, std::span<const std::string_view> names,
                              std::size_t fallback) const {
  const auto found = find(key);
  return found ? found->choice(names) : fallback;
}

MapReader MapReader::map(std::string_view key, std::vector<std::string_view> allowed) const {
  if (const auto found = find(key)) return MapReader(*found, std::move(allowed));
  // An absent optional section reads as an empty map; errors about it point at its parent.
  const std::string path = child_path(node_.path(), key);
  return MapReader(Node(YAML::Node(), path, node_.provenance()->origin_of(path, node_.origin()),
                        node_.mark(), node_.provenance()),
                   std::move(allowed));
}

}  // namespace twb::scene_io
