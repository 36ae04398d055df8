#include "common/json_config.hpp"

#include "common/bounded_file_read.hpp"
#include "common/json_config_nesting.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

namespace refloc {
namespace {
using json_config_detail::escape_key;
using json_config_detail::NestingLimitedDom;
using json_config_detail::printable;
using json_config_detail::read_bounded_file;

// Containers are described by their size: dump() would recurse over the whole subtree.
std::string describe(const nlohmann::json& value) {
  if (value.is_object()) return fmt::format("object with {} keys", value.size());
  if (value.is_array()) return fmt::format("array of {} elements", value.size());
  return fmt::format("{} {}", value.type_name(), printable(value.dump(), 60));
}

std::string integer_range_text(long long min, long long max) {
  const bool has_min = min > std::numeric_limits<long long>::min();
  const bool has_max = max < std::numeric_limits<long long>::max();
  if (has_min && has_max) return fmt::format(" in [{}, {}]", min, max);
  if (has_min) return fmt::format(" >= {}", min);
  if (has_max) return fmt::format(" <= {}", max);
  return "";
}

std::string range_text(double min, double max) {
  const bool has_min = min > -std::numeric_limits<double>::max();
  const bool has_max = max < std::numeric_limits<double>::max();
  if (has_min && has_max) return fmt::format(" in [{}, {}]", min, max);
  if (has_min) return fmt::format(" >= {}", min);
  if (has_max) return fmt::format(" <= {}", max);
  return "";
}

}  // namespace

JsonConfig JsonConfig::load_file(const std::string& path) {
  return parse_text(read_bounded_file(path), path);
}

JsonConfig JsonConfig::parse_text(const std::string& text, const std::string& source) {
  const std::string name = printable(source, 400);
  nlohmann::json document;
  NestingLimitedDom builder(document);
  // Comments (// and /* */) are allowed: the shipped files explain their keys in place.
  if (!nlohmann::json::sax_parse(text, &builder, nlohmann::json::input_format_t::json, /*strict=*/true,
                                 /*ignore_comments=*/true) ||
      !builder.error().empty()) {
    throw ConfigError(
        fmt::format("{}: {}", name, builder.error().empty() ? "not valid JSON" : builder.error()));
  }
  if (!document.is_object()) {
    throw ConfigError(fmt::format("{}: /: expected a JSON object, got {}", name, describe(document)));
  }
  return JsonConfig(std::move(document), source);
}

JsonConfig::JsonConfig(nlohmann::json document, std::string source)
    : document_(std::move(document)), source_(std::move(source)) {}

void JsonConfig::fail(const std::string& pointer, const std::string& what) const {
  throw ConfigError(
      fmt::format("{}: {}: {}", printable(source_, 400), pointer.empty() ? "/" : printable(pointer), what));
}

const nlohmann::json* JsonConfig::find(const std::string& pointer) const {
  try {
    const nlohmann::json::json_pointer ptr(pointer);
    if (!document_.contains(ptr)) return nullptr;
    return &document_.at(ptr);
  } catch (const nlohmann::json::exception&) {
    return nullptr;  // a path through a non-object counts as absent
  }
}

bool JsonConfig::has(const std::string& pointer) const { return find(pointer) != nullptr; }

void JsonConfig::mark_used(const std::string& pointer) const { used_.insert(pointer); }

bool JsonConfig::is_known_container(const std::string& pointer) const {
  if (pointer.empty() || used_.count(pointer) || used_whole_.count(pointer)) return true;
  const std::string prefix = pointer + "/";
  const auto below = used_.lower_bound(prefix);
  return below != used_.end() && below->compare(0, prefix.size(), prefix) == 0;
}

double JsonConfig::checked_number(const std::string& pointer, const nlohmann::json& value, double min,
                                  double max) const {
  if (!value.is_number()) {
    fail(pointer, fmt::format("expected a number{}, got {}", range_text(min, max), describe(value)));
  }
  const double v = value.get<double>();
  if (!std::isfinite(v) || v < min || v > max) {
    fail(pointer, fmt::format("expected a finite number{}, got {}", range_text(min, max), value.dump()));
  }
  return v;
}

long long JsonConfig::checked_integer(const std::string& pointer, const nlohmann::json& value, long long min,
                                      long long max) const {
  if (!value.is_number_integer()) {
    fail(pointer, fmt::format("expected an integer in [{}, {}], got {}", min, max, describe(value)));
  }
  const long long v = value.get<long long>();
  if (v < min || v > max) {
    fail(pointer, fmt::format("expected an integer in [{}, {}], got {}", min, max, v));
  }
  return v;
}

void JsonConfig::record(const ConfigKey& key, const char* type, std::string range, bool required,
                        nlohmann::json default_value, nlohmann::json value) const {
  // Array elements share one record (/reflectors/*/x): a map of 100,000 reflectors documents
  // three keys, not 300,000, and the value shown is the first element's.
  std::string pointer;
  for (size_t begin = 0; begin < key.pointer.size();) {
    const size_t end = std::min(key.pointer.find('/', begin + 1), key.pointer.size());
    const std::string segment = key.pointer.substr(begin + 1, end - begin - 1);
    const bool index = !segment.empty() && segment.find_first_not_of("0123456789") == std::string::npos;
    pointer += "/" + (index ? std::string("*") : segment);
    begin = end;
  }
  pointer = record_prefix_ + pointer;
  const auto [it, inserted] = records_->index.emplace(pointer, records_->keys.size());
  if (!inserted) {
    // The first call documents the key; a later one may only add documentation it lacked.
    ConfigKeyRecord& r = records_->keys[it->second];
    if (r.meaning.empty()) r.meaning = key.meaning;
    if (r.unit.empty()) r.unit = key.unit;
    return;
  }
  records_->keys.push_back(ConfigKeyRecord{pointer, key.unit, key.meaning, type, std::move(range), required,
                                           std::move(default_value), std::move(value)});
}

double JsonConfig::number(const ConfigKey& key, double default_value, double min, double max) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  const double v = value ? checked_number(pointer, *value, min, max) : default_value;
  record(key, "number", range_text(min, max), false, default_value, v);
  return v;
}

double JsonConfig::positive_number(const ConfigKey& key, double default_value, double max,
                                   const std::string& zero_means) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  const double v =
      value ? checked_number(pointer, *value, -std::numeric_limits<double>::max(), max) : default_value;
  if (!(v > 0.0)) {
    fail(pointer, fmt::format("expected a finite number in (0, {}], got {} ({})", max, v, zero_means));
  }
  record(key, "number", fmt::format(" in (0, {}]", max), false, default_value, v);
  return v;
}

double JsonConfig::required_number(const ConfigKey& key, double min, double max) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) fail(pointer, fmt::format("missing; expected a number{}", range_text(min, max)));
  const double v = checked_number(pointer, *value, min, max);
  record(key, "number", range_text(min, max), true, nullptr, v);
  return v;
}

long long JsonConfig::integer(const ConfigKey& key, long long default_value, long long min,
                              long long max) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  const long long v = value ? checked_integer(pointer, *value, min, max) : default_value;
  record(key, "integer", integer_range_text(min, max), false, default_value, v);
  return v;
}

long long JsonConfig::required_integer(const ConfigKey& key, long long min, long long max) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) fail(pointer, fmt::format("missing; expected an integer in [{}, {}]", min, max));
  const long long v = checked_integer(pointer, *value, min, max);
  record(key, "integer", integer_range_text(min, max), true, nullptr, v);
  return v;
}

bool JsonConfig::boolean(const ConfigKey& key, bool default_value) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (value && !value->is_boolean())
    fail(pointer, fmt::format("expected true or false, got {}", describe(*value)));
  const bool v = value ? value->get<bool>() : default_value;
  record(key, "boolean", "", false, default_value, v);
  return v;
}

std::string JsonConfig::checked_string(const std::string& pointer, const std::string& default_value) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) return default_value;
  if (!value->is_string()) fail(pointer, fmt::format("expected a string, got {}", describe(*value)));
  return value->get<std::string>();
}

std::string JsonConfig::string(const ConfigKey& key, const std::string& default_value) const {
  const std::string v = checked_string(key.pointer, default_value);
  record(key, "string", "", false, default_value, v);
  return v;
}

std::string JsonConfig::choice(const ConfigKey& key, const std::string& default_value,
                               const std::set<std::string>& allowed) const {
  const std::string v = checked_string(key.pointer, default_value);
  std::string options;
  for (const auto& a : allowed) options += (options.empty() ? "\"" : ", \"") + a + "\"";
  if (allowed.count(v) == 0) fail(key.pointer, fmt::format("expected one of {}, got \"{}\"", options, v));
  record(key, "choice", "one of " + options, false, default_value, v);
  return v;
}

size_t JsonConfig::array_size(const ConfigKey& key, bool required) const {
  const std::string& pointer = key.pointer;
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) {
    if (required) fail(pointer, "missing; expected an array");
    record(key, "array", "", false, nlohmann::json::array(), nlohmann::json::array());
    return 0;
  }
  if (!value->is_array()) fail(pointer, fmt::format("expected an array, got {}", describe(*value)));
  record(key, "array", "", required, required ? nlohmann::json() : nlohmann::json::array(), *value);
  return value->size();
}

JsonConfig JsonConfig::child(const std::string& pointer) const {
  used_whole_.insert(pointer);
  const nlohmann::json* value = find(pointer);
  if (value && !value->is_object())
    fail(pointer, fmt::format("expected an object, got {}", describe(*value)));
  JsonConfig sub(value ? *value : nlohmann::json::object(), source_ + " " + pointer);
  sub.records_ = records_;
  sub.record_prefix_ = record_prefix_ + pointer;
  return sub;
}

const nlohmann::json& JsonConfig::subtree(const std::string& pointer) const {
  used_whole_.insert(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) fail(pointer, "missing");
  return *value;
}

void JsonConfig::reject_unknown_keys() const {
  // An explicit stack: a document built in memory (not by parse_text) may be of any depth.
  std::vector<std::pair<const nlohmann::json*, std::string>> pending{{&document_, ""}};
  while (!pending.empty()) {
    auto [node, pointer] = std::move(pending.back());
    pending.pop_back();
    if (used_whole_.count(pointer)) continue;
    if (node->is_object() || node->is_array()) {
      if (node->empty() && !is_known_container(pointer))
        fail(pointer, "unknown key (misspelt, or not used by this program)");
      // Children pushed last-first, so the first unknown key in file order is the one named.
      if (node->is_object()) {
        for (auto it = node->rbegin(); it != node->rend(); ++it)
          pending.emplace_back(&it.value(), pointer + "/" + escape_key(it.key()));
      } else {
        for (size_t i = node->size(); i-- > 0;)
          pending.emplace_back(&(*node)[i], pointer + "/" + std::to_string(i));
      }
    } else if (!used_.count(pointer)) {
      fail(pointer, "unknown key (misspelt, or not used by this program)");
    }
  }
}

}  // namespace refloc
