#pragma once
// JSON configuration files with validation. Every reader call names the key by
// its JSON pointer so an error message can say exactly what is wrong and where:
//   "deploy/config/robot.json: /wheel_radius_m: expected a number in [0.01, 1], got -3"

#include <nlohmann/json.hpp>

#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace refloc {

/// A config or input file that cannot be used; what() names file, key and expectation.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The largest config or map file read [bytes]: a map of 100,000 reflectors written compactly
/// is about 3 MB; anything larger is a mistake (or /dev/zero behind a symlink), not a map.
inline constexpr size_t kMaxConfigFileBytes = 4u << 20;
/// The deepest nesting of objects and arrays accepted; our files need 4 levels. Deeper files
/// are refused while parsing, before any recursive code sees them.
inline constexpr int kMaxConfigNestingDepth = 32;

class JsonConfig {
 public:
  /// Parse a file; throws ConfigError when it cannot be read or is not JSON. Only a regular
  /// file of at most kMaxConfigFileBytes is read (a FIFO, a device or a directory is refused
  /// without blocking), nested at most kMaxConfigNestingDepth deep.
  static JsonConfig load_file(const std::string& path);
  /// The same checks on text already in memory; source names it in messages.
  static JsonConfig parse_text(const std::string& text, const std::string& source);
  /// Wrap a document already in memory; source names it in messages.
  JsonConfig(nlohmann::json document, std::string source);

  const std::string& source() const { return source_; }
  const nlohmann::json& document() const { return document_; }
  bool has(const std::string& pointer) const;

  /// Optional finite number in [min, max]; default when the key is absent.
  double number(const std::string& pointer, double default_value,
                double min = -std::numeric_limits<double>::max(),
                double max = std::numeric_limits<double>::max()) const;
  /// Required finite number in [min, max].
  double required_number(const std::string& pointer, double min = -std::numeric_limits<double>::max(),
                         double max = std::numeric_limits<double>::max()) const;
  /// Optional finite number in (0, max]: for sigmas, tolerances, radii and rates where 0 would
  /// silently disable what the key configures; zero_means says what 0 would do, for the message.
  double positive_number(const std::string& pointer, double default_value, double max,
                         const std::string& zero_means) const;
  long long integer(const std::string& pointer, long long default_value,
                    long long min = std::numeric_limits<long long>::min(),
                    long long max = std::numeric_limits<long long>::max()) const;
  long long required_integer(const std::string& pointer,
                             long long min = std::numeric_limits<long long>::min(),
                             long long max = std::numeric_limits<long long>::max()) const;
  bool boolean(const std::string& pointer, bool default_value) const;
  std::string string(const std::string& pointer, const std::string& default_value) const;
  /// One of the allowed values.
  std::string choice(const std::string& pointer, const std::string& default_value,
                     const std::set<std::string>& allowed) const;
  /// Number of elements of a required array (which may be empty).
  size_t array_size(const std::string& pointer, bool required = true) const;

  /// A sub-document the caller validates itself; it counts as known.
  const nlohmann::json& subtree(const std::string& pointer) const;

  /// Throws for any key in the document that no reader call asked for, so a
  /// misspelt key is an error rather than a silently ignored setting; an unknown key whose
  /// value is {} or [] is as unknown as one holding a number. Iterative: no recursion on
  /// the document's depth.
  void reject_unknown_keys() const;

  /// Throws ConfigError "<source>: <pointer>: <what>".
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;

 private:
  const nlohmann::json* find(const std::string& pointer) const;
  void mark_used(const std::string& pointer) const;
  /// Whether a reader asked for this pointer or for a key below it.
  bool is_known_container(const std::string& pointer) const;
  double checked_number(const std::string& pointer, const nlohmann::json& value, double min,
                        double max) const;
  long long checked_integer(const std::string& pointer, const nlohmann::json& value, long long min,
                            long long max) const;

  nlohmann::json document_;
  std::string source_;
  mutable std::set<std::string> used_;
  mutable std::set<std::string> used_whole_;
};

}  // namespace refloc
