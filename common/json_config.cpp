#include "common/json_config.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

namespace refloc {
namespace {

std::string describe(const nlohmann::json& value) {
  std::string text = value.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return fmt::format("{} {}", value.type_name(), text);
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
  std::ifstream in(path);
  if (!in) throw ConfigError(fmt::format("{}: cannot open the file", path));
  std::stringstream buffer;
  buffer << in.rdbuf();
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::exception& e) {  // parse errors and number overflow
    throw ConfigError(fmt::format("{}: not valid JSON: {}", path, e.what()));
  }
  if (!document.is_object()) {
    throw ConfigError(fmt::format("{}: /: expected a JSON object, got {}", path, describe(document)));
  }
  return JsonConfig(std::move(document), path);
}

JsonConfig::JsonConfig(nlohmann::json document, std::string source)
    : document_(std::move(document)), source_(std::move(source)) {}

void JsonConfig::fail(const std::string& pointer, const std::string& what) const {
  throw ConfigError(fmt::format("{}: {}: {}", source_, pointer.empty() ? "/" : pointer, what));
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

double JsonConfig::number(const std::string& pointer, double default_value, double min, double max) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  return value ? checked_number(pointer, *value, min, max) : default_value;
}

double JsonConfig::required_number(const std::string& pointer, double min, double max) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) fail(pointer, fmt::format("missing; expected a number{}", range_text(min, max)));
  return checked_number(pointer, *value, min, max);
}

long long JsonConfig::integer(const std::string& pointer, long long default_value, long long min,
                              long long max) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  return value ? checked_integer(pointer, *value, min, max) : default_value;
}

long long JsonConfig::required_integer(const std::string& pointer, long long min, long long max) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) fail(pointer, fmt::format("missing; expected an integer in [{}, {}]", min, max));
  return checked_integer(pointer, *value, min, max);
}

bool JsonConfig::boolean(const std::string& pointer, bool default_value) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) return default_value;
  if (!value->is_boolean()) fail(pointer, fmt::format("expected true or false, got {}", describe(*value)));
  return value->get<bool>();
}

std::string JsonConfig::string(const std::string& pointer, const std::string& default_value) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) return default_value;
  if (!value->is_string()) fail(pointer, fmt::format("expected a string, got {}", describe(*value)));
  return value->get<std::string>();
}

std::string JsonConfig::choice(const std::string& pointer, const std::string& default_value,
                               const std::set<std::string>& allowed) const {
  const std::string v = string(pointer, default_value);
  if (allowed.count(v) == 0) {
    std::string options;
    for (const auto& a : allowed) options += (options.empty() ? "\"" : ", \"") + a + "\"";
    fail(pointer, fmt::format("expected one of {}, got \"{}\"", options, v));
  }
  return v;
}

size_t JsonConfig::array_size(const std::string& pointer, bool required) const {
  mark_used(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) {
    if (required) fail(pointer, "missing; expected an array");
    return 0;
  }
  if (!value->is_array()) fail(pointer, fmt::format("expected an array, got {}", describe(*value)));
  return value->size();
}

const nlohmann::json& JsonConfig::subtree(const std::string& pointer) const {
  used_whole_.insert(pointer);
  const nlohmann::json* value = find(pointer);
  if (!value) fail(pointer, "missing");
  return *value;
}

void JsonConfig::reject_unknown_keys() const {
  std::function<void(const nlohmann::json&, const std::string&)> walk = [&](const nlohmann::json& node,
                                                                            const std::string& pointer) {
    if (used_whole_.count(pointer)) return;
    if (node.is_object()) {
      for (auto it = node.begin(); it != node.end(); ++it) {
        std::string key = it.key();
        // RFC 6901 escaping, so the message names the key as a valid pointer.
        for (size_t pos = 0; (pos = key.find('~', pos)) != std::string::npos; pos += 2)
          key.replace(pos, 1, "~0");
        for (size_t pos = 0; (pos = key.find('/', pos)) != std::string::npos; pos += 2)
          key.replace(pos, 1, "~1");
        walk(it.value(), pointer + "/" + key);
      }
    } else if (node.is_array()) {
      for (size_t i = 0; i < node.size(); ++i) walk(node[i], pointer + "/" + std::to_string(i));
    } else if (!used_.count(pointer)) {
      fail(pointer, "unknown key (misspelt, or not used by this program)");
    }
  };
  walk(document_, "");
}

}  // namespace refloc
